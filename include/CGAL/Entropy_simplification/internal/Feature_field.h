// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The feature field of the default mode: how strongly the normals vary around
// each point, measured by an entropy of normals, against the cloud's own noise.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_FEATURE_FIELD_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_FEATURE_FIELD_H

#include <CGAL/Entropy_simplification/Options.h>
#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>
#include <CGAL/Entropy_simplification/internal/local_normal.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// The entropy (nats) of the normals of a neighbourhood, independent of their
// orientation and of any reference plane: the entropy of the eigenvalues of
// their orientation tensor (1/m) sum n n^T, which sum to 1. It is 0 when the
// normals are parallel, log 2 on a right-angled edge with equal sides, log 3
// at a cube corner; noise and curvature raise it smoothly from 0. Null
// normals (undefined) are left out.
template <typename NormalAt>
double normal_tensor_entropy(std::size_t m, NormalAt normal)
{
  Eigen::Matrix3d tensor = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < m; ++i)
  {
    const Working_vector& n = normal(i);
    const double length = n.squared_length();
    if (length == 0.)
      continue;
    const Eigen::Vector3d u = Eigen::Vector3d(n.x(), n.y(), n.z()) / std::sqrt(length);
    tensor += u * u.transpose();
  }
  const double trace = tensor.trace();
  if (trace == 0.)
    return 0.;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(tensor / trace, Eigen::EigenvaluesOnly);
  double entropy = 0.;
  for (int i = 0; i < 3; ++i)
  {
    const double mu = solver.eigenvalues()(i);
    if (mu > 0.)
      entropy -= mu * std::log(mu);
  }
  return entropy;
}

// The median of some values (not empty).
inline double median(Array<double> values)
{
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(values.size() / 2), values.end());
  return values[values.size() / 2];
}

// The noise floor of a cloud's normal entropies: their median, but not below
// the entropy of normals spread by about one degree, so that a noise-free
// sample of flat faces does not make every slight curvature a feature.
inline double entropy_noise_floor(const Array<double>& entropy)
{
  const double one_degree = 0.0175;
  const double smallest = -2. * (one_degree * one_degree / 2.) * std::log(one_degree * one_degree / 2.);
  return entropy.empty() ? smallest : (std::max)(smallest, median(entropy));
}

// Feature strength in [0, 1]: 0 up to twice the noise floor, 1 from ten
// times the floor, linear in between.
inline double feature_strength(double entropy, double noise_floor)
{
  return (std::min)(1., (std::max)(0., (entropy - 2. * noise_floor) / (8. * noise_floor)));
}

// Each block of `coarse_stride` points of the kd order (see sort_spatially)
// gives one point to the coarse scale, whose neighbourhoods are then 8
// times wider: there, the smooth curvature of a ball of 12 cm under 1.2 mm of
// range noise (the paper's Experiment I) rises clear of the noise, which it
// does not at k = 10 on all the points.
constexpr std::size_t coarse_stride = 64;

// What the coarse scale's strength counts for against the fine scale's. Its
// strength is that of the nearest coarse point, each standing for a block of
// 64 points, so it marks a band wider than the curvature it sees, whose
// points it asks to be kept dense in full. Chosen on the 1.2 mm replica,
// whose ball issue 12 asks to keep at least 1.6 times the input's share at
// 10%: with the weights of coverage_weight_exponent, 0.7 keeps 1.63 there
// and brings its mean distance at 10% within the best peer's (0.998 times
// it), which three quarters did not (1.001; design notes: the coarse scale).
constexpr double coarse_strength_share = 0.7;

// A bijection of 32-bit integers that scrambles their order, by which each
// block draws its coarse point from its input positions as if at random:
// a block's first point, always at the same end of the kd order's splits,
// makes a more regular sample, and on that replica at 1.2 mm of noise cost
// 1.5 to 2.1% in mean distance (measured in the user manual).
inline std::uint32_t scrambled(std::uint32_t x)
{
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

// The extra points the features may take, as a fraction of the points the
// flat regions would have: 45% at the default weight 3, and in proportion to
// the weight, so that a greater weight always keeps more on features. The
// weight is lowered so that the sum of `weight * strength` over the area
// stays below it, that is, where more than 15% of the area, counted by
// strength, is marked. On noisy scans, where a third of the area has high
// entropy, an unbounded weight thins everything else (measured in the design
// notes).
constexpr double feature_budget_at_default_weight = 0.45;

inline double budgeted_feature_weight(double feature_weight, double feature_area, double total_area)
{
  // (w / 3) is exactly 1 at the default weight, whose budget is then 0.45
  const double budget = feature_budget_at_default_weight * (feature_weight / 3.);
  return feature_area > 0. ? (std::min)(feature_weight, budget * total_area / feature_area) : feature_weight;
}

// The factor applied to the interaction radius of the elimination around a
// point: 1 without features, down to 1 / sqrt(1 + feature_weight), so that
// the kept density grows by up to 1 + feature_weight on features.
inline double interaction_scale(double strength, double feature_weight)
{
  return 1. / std::sqrt(1. + feature_weight * strength);
}

// The factor applied to the interaction radius where each input point takes
// `area` instead of the `typical_area`: the kept density then goes as the
// input density to the power 2/3, which minimises the mean distance from the
// input points to the kept ones, within a factor 2 of the radius either way.
inline double density_scale(double area, double typical_area)
{
  if (!(typical_area > 0.))
    return 1.;
  return (std::min)(2., (std::max)(0.5, std::cbrt(area / typical_area)));
}

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_FEATURE_FIELD_H
