// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The default mode (Mode::weighted_elimination) computed from the user
// manual's definitions with code of its own: an independent reference for the
// package. Neighbours come from linear scans; every point's nearest and next
// present points, and every cost, are found from scratch in every round of
// the greedy coverage elimination, and every weight before every removal
// of weighted sample elimination (the ablation's alternative); every nearest
// point of the relocation is found by a scan. Of the package it uses only the public Options; of CGAL,
// the kernel and the jet fitting.
//
// Every formula runs its floating-point operations in the package's order, so
// that the fields agree to the last bits and the removal orders exactly: a
// last-bit difference in a scale can move a pair weight by one unit, and a
// removal order compares sums of such weights or costs.

#ifndef ENTROPY_SIMPLIFICATION_TEST_REFERENCE_ELIMINATION_H
#define ENTROPY_SIMPLIFICATION_TEST_REFERENCE_ELIMINATION_H

#include <CGAL/Entropy_simplification/Options.h>

#include <CGAL/Eigen_svd.h>
#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Simple_cartesian.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace reference {

namespace ES = CGAL::Entropy_simplification;
using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;

// The terms of the default mode, each of which the ablation switches off:
// the manual's "What each term contributes".
struct Terms
{
  bool coverage_elimination = true; // the greedy coverage elimination, not Yuksel's
  bool coarse_scale = true;   // the strength is the greater of the two scales'
  bool feature_budget = true; // the weight is lowered where features cover much
  bool strong_features_first = true; // above 35% present, the square of the strength
  bool relocation = true;     // the kept points are relocated
  bool medians = true;        // each cell keeps its median
  bool radius_bound = true;   // within the radius bound
  bool coverage_swaps = true; // the farthest points swapped in for crowded ones
};

// Every point is named by its input position; ties in distance go to the
// lowest one, as the manual defines every order of the package.
using Neighbor = std::pair<double, std::size_t>; // (squared distance, input position)

// Whether a point may be another's nearest present point: among all of
// them, or (at a ranking's level boundary) among those of nonzero weight.
using Adjacency = std::function<bool(std::size_t, std::size_t)>;
inline const Adjacency everywhere = [](std::size_t, std::size_t) { return true; };

inline double squared_distance(const Point& a, const Point& b)
{
  const double dx = a.x() - b.x(), dy = a.y() - b.y(), dz = a.z() - b.z();
  return dx * dx + dy * dy + dz * dz;
}

// ----------------------------------------------------------------------------
// Neighbourhoods and normals
// ----------------------------------------------------------------------------

// N(p): the k members nearest `points[p]`, `p` excluded, nearest first.
inline std::vector<std::size_t> nearest_members(const std::vector<Point>& points,
                                                const std::vector<std::size_t>& members, std::size_t p,
                                                unsigned int k)
{
  std::vector<Neighbor> candidates;
  for (std::size_t q : members)
    if (q != p)
      candidates.emplace_back(squared_distance(points[p], points[q]), q);
  std::partial_sort(candidates.begin(), candidates.begin() + k, candidates.end());
  std::vector<std::size_t> nearest;
  for (unsigned int j = 0; j < k; ++j)
    nearest.push_back(candidates[j].second);
  return nearest;
}

// The normal of the plane fitted by least squares (Eq. 1-2): the eigenvector
// of the least eigenvalue of the points' covariance, or the null vector when
// the points all coincide. Eigen's closed-form 3x3 solver, which the package
// documents as its own; CGAL's pca_estimate_normals() uses an iterative one,
// which agrees within 1e-9 (test_feature_field.cpp).
inline Vector least_squares_normal(const std::vector<Point>& points)
{
  const double m = double(points.size());
  double cx = 0., cy = 0., cz = 0.;
  for (const Point& p : points)
  {
    cx += p.x();
    cy += p.y();
    cz += p.z();
  }
  cx /= m;
  cy /= m;
  cz /= m;
  double xx = 0., xy = 0., xz = 0., yy = 0., yz = 0., zz = 0.;
  for (const Point& p : points)
  {
    const double dx = p.x() - cx, dy = p.y() - cy, dz = p.z() - cz;
    xx += dx * dx;
    xy += dx * dy;
    xz += dx * dz;
    yy += dy * dy;
    yz += dy * dz;
    zz += dz * dz;
  }
  if (xx + yy + zz == 0.)
    return CGAL::NULL_VECTOR;
  Eigen::Matrix3d covariance;
  covariance << xx, xy, xz, xy, yy, yz, xz, yz, zz;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(covariance);
  const Eigen::Vector3d normal = solver.eigenvectors().col(0); // eigenvalues in increasing order
  return Vector(normal(0), normal(1), normal(2));
}

// The normal of a jet of degree 2 fitted at the first point, as
// CGAL::jet_estimate_normals() computes it; the null vector when the fit
// degenerates.
inline Vector jet_normal(const std::vector<Point>& points)
{
  CGAL::Monge_via_jet_fitting<Kernel, Kernel, CGAL::Eigen_svd> fitting;
  const Vector normal = fitting(points.begin(), points.end(), 2, 1).normal_direction();
  if (!(std::isfinite(normal.x()) && std::isfinite(normal.y()) && std::isfinite(normal.z())))
    return CGAL::NULL_VECTOR;
  return normal;
}

// The normal of `p`, estimated on `p` then N(p) nearest first: k + 1 points.
inline Vector normal_at(const std::vector<Point>& points, std::size_t p, const std::vector<std::size_t>& neighbors,
                        ES::Normal_estimation method)
{
  std::vector<Point> neighborhood{ points[p] };
  for (std::size_t q : neighbors)
    neighborhood.push_back(points[q]);
  return method == ES::Normal_estimation::jet ? jet_normal(neighborhood) : least_squares_normal(neighborhood);
}

// ----------------------------------------------------------------------------
// The feature signal
// ----------------------------------------------------------------------------

// The entropy (nats) of the eigenvalues of the orientation tensor of some
// normals, the mean of n n^T over the m defined unit normals; its eigenvalues
// sum to 1. Null normals are left out. Eigen's closed-form solver, as the
// package: near a double zero eigenvalue its rounding (about 1e-9) puts about
// 1e-8 into the entropy of parallel normals, where the iterative solver gives
// 1e-16, and the field could not agree to 1e-12.
inline double tensor_entropy(const std::vector<Vector>& normals)
{
  Eigen::Matrix3d tensor = Eigen::Matrix3d::Zero();
  int defined = 0;
  for (const Vector& n : normals)
    if (n.squared_length() > 0.)
    {
      const Eigen::Vector3d u = Eigen::Vector3d(n.x(), n.y(), n.z()).normalized();
      tensor += u * u.transpose();
      ++defined;
    }
  if (defined == 0)
    return 0.;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(tensor / defined, Eigen::EigenvaluesOnly);
  const Eigen::Vector3d mu = solver.eigenvalues();
  double entropy = 0.;
  for (int i = 0; i < 3; ++i)
    if (mu(i) > 0.) // 0 log 0 = 0, and rounding may leave a tiny negative
      entropy -= mu(i) * std::log(mu(i));
  return entropy;
}

// The median, for an even count the upper of the two middle values (the
// package's convention: the median is always one of the values).
inline double median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

// The noise floor: the median entropy, at least that of normals spread by
// one degree (0.0175 rad), taken as two tensor eigenvalues of a^2/2 whose
// terms -mu log mu are counted, the third's left out.
inline double noise_floor(const std::vector<double>& entropy)
{
  const double a = 0.0175;
  const double one_degree_spread = -2. * (a * a / 2.) * std::log(a * a / 2.);
  return (std::max)(one_degree_spread, median(entropy));
}

// 0 up to twice the floor, 1 from ten times the floor, linear in between.
inline double feature_strength(double entropy, double floor)
{
  return (std::min)(1., (std::max)(0., (entropy - 2. * floor) / (8. * floor)));
}

// The normals and entropies of one scale, by input position: each member's
// neighbourhood is taken among the members only.
struct Scale
{
  std::vector<Vector> normals;
  std::vector<double> entropy;
  std::vector<std::vector<std::size_t> > neighbors;
};

inline Scale scale_among(const std::vector<Point>& points, const std::vector<std::size_t>& members, unsigned int k,
                         ES::Normal_estimation method)
{
  Scale scale;
  scale.normals.assign(points.size(), CGAL::NULL_VECTOR);
  scale.entropy.assign(points.size(), 0.);
  scale.neighbors.resize(points.size());
  for (std::size_t p : members)
  {
    scale.neighbors[p] = nearest_members(points, members, p, k);
    scale.normals[p] = normal_at(points, p, scale.neighbors[p], method);
  }
  // the normals of p and N(p), in that order
  for (std::size_t p : members)
  {
    std::vector<Vector> normals{ scale.normals[p] };
    for (std::size_t q : scale.neighbors[p])
      normals.push_back(scale.normals[q]);
    scale.entropy[p] = tensor_entropy(normals);
  }
  return scale;
}

// The input positions in kd order, from the manual's definition: the
// points are split into halves, the lower half first, along the widest
// side of their bounding box (the first of equal sides), a point below
// another when its coordinate there is smaller, or equal with a smaller input
// position; each half is ordered so in turn, down to single points. Here
// each range is fully sorted, not partitioned, to pick its lower half.
inline void kd_sort(const std::vector<Point>& points, std::size_t* first, std::size_t* beyond)
{
  if (beyond - first < 2)
    return;
  double extent[3];
  for (int d = 0; d < 3; ++d)
  {
    const auto [low, high] = std::minmax_element(first, beyond, [&](std::size_t a, std::size_t b) {
      return points[a].cartesian(d) < points[b].cartesian(d);
    });
    extent[d] = points[*high].cartesian(d) - points[*low].cartesian(d);
  }
  int side = 0;
  for (int d = 1; d < 3; ++d)
    if (extent[d] > extent[side])
      side = d;
  std::sort(first, beyond, [&](std::size_t a, std::size_t b) {
    const double ca = points[a].cartesian(side), cb = points[b].cartesian(side);
    return ca < cb || (ca == cb && a < b);
  });
  std::size_t* middle = first + (beyond - first) / 2;
  kd_sort(points, first, middle);
  kd_sort(points, middle, beyond);
}

inline std::vector<std::size_t> kd_order(const std::vector<Point>& points)
{
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  kd_sort(points, order.data(), order.data() + order.size());
  return order;
}

// The manual's scrambling of input positions, a fixed 32-bit hash.
inline std::uint32_t scramble(std::uint32_t x)
{
  x = (x ^ (x >> 16)) * 0x7feb352dU;
  x = (x ^ (x >> 15)) * 0x846ca68bU;
  return x ^ (x >> 16);
}

// The coarse scale: one point from each run of 64 in the kd order, the one
// whose input position scrambles lowest, so that their spacing is sqrt(64)
// = 8 times the input's. Its neighbourhoods need k + 1 points.
inline std::vector<std::size_t> coarse_points(const std::vector<std::size_t>& kd, unsigned int k)
{
  std::vector<std::size_t> coarse;
  for (std::size_t r = 0; r < kd.size(); r += 64)
  {
    const auto block_end = kd.begin() + std::ptrdiff_t((std::min)(kd.size(), r + 64));
    coarse.push_back(*std::min_element(kd.begin() + std::ptrdiff_t(r), block_end, [](std::size_t a, std::size_t b) {
      return scramble(std::uint32_t(a)) < scramble(std::uint32_t(b));
    }));
  }
  if (coarse.size() < std::size_t(k) + 1)
    coarse.clear();
  return coarse;
}

// The coarse strength of every point: 0.7 times that of its nearest
// coarse point (a coarse point is its own), against the coarse points' own
// noise floor.
inline std::vector<double> coarse_strength(const std::vector<Point>& points, const std::vector<std::size_t>& coarse,
                                           unsigned int k, ES::Normal_estimation method)
{
  std::vector<double> strength(points.size(), 0.);
  if (coarse.empty())
    return strength;
  const Scale scale = scale_among(points, coarse, k, method);
  std::vector<double> entropy;
  for (std::size_t c : coarse)
    entropy.push_back(scale.entropy[c]);
  const double floor = noise_floor(entropy);
  for (std::size_t p = 0; p < points.size(); ++p)
  {
    Neighbor nearest{ std::numeric_limits<double>::infinity(), points.size() };
    for (std::size_t c : coarse)
      nearest = (std::min)(nearest, Neighbor{ squared_distance(points[p], points[c]), c });
    strength[p] = 0.7 * feature_strength(scale.entropy[nearest.second], floor);
  }
  return strength;
}

// ----------------------------------------------------------------------------
// The field of the elimination
// ----------------------------------------------------------------------------

// Features may take at most 0.45 * w / 3 more points than the flat regions
// would (45% at the default w = 3): the requested weight w becomes the
// largest w' <= w with w' * (sum of area * strength) <= 0.45 * (w / 3) * area.
inline double budgeted_weight(double feature_weight, double feature_area, double total_area)
{
  const double extra_points = 0.45 * (feature_weight / 3.);
  return feature_area > 0. ? (std::min)(feature_weight, extra_points * total_area / feature_area) : feature_weight;
}

// The radius factor of a point: 1 / sqrt(1 + w s), so that the kept density
// grows by up to 1 + w on features, times the cube root of its share of the
// area over the median share, within a factor 2, so that the kept density
// follows the input's to the power 2/3 (unless `with_density` is false).
inline double radius_factor(double strength, double weight, double area, double typical_area, bool with_density)
{
  const double density = with_density && typical_area > 0.
                           ? (std::min)(2., (std::max)(0.5, std::cbrt(area / typical_area)))
                           : 1.;
  return 1. / std::sqrt(1. + weight * strength) * density;
}

// Everything by input position; the pieces after `effective_area` are there
// for the tests to check what the field is made of.
struct Field
{
  std::vector<Vector> normals;
  std::vector<double> scale;
  double effective_area = 0.; // the area, each point's share divided by its scale squared
  std::vector<double> fine_strength, coarse_strength;
  std::size_t coarse_count = 0; // 0 when the cloud is too small for the coarse scale
  double floor = 0.;            // the noise floor of the fine scale
  double weight = 0.;           // the feature weight after the budget
  bool strong_features_first = true; // see coverage_weights
};

inline Field feature_field(const std::vector<Point>& points, unsigned int k, const ES::Options& options,
                           const Terms& terms = Terms())
{
  const std::size_t n = points.size();
  std::vector<std::size_t> all(n);
  std::iota(all.begin(), all.end(), std::size_t(0));
  const Scale fine = scale_among(points, all, k, options.normal_estimation);
  const std::vector<std::size_t> kd = kd_order(points);
  const std::vector<std::size_t> coarse = coarse_points(kd, k);

  Field field;
  field.normals = fine.normals;
  field.coarse_count = coarse.size();
  field.coarse_strength = coarse_strength(points, coarse, k, options.normal_estimation);
  field.floor = noise_floor(fine.entropy);
  std::vector<double> area(n), strength(n);
  for (std::size_t p = 0; p < n; ++p)
  {
    // p's share of the area: k points in the disc reaching its k-th neighbour
    area[p] = CGAL_PI * squared_distance(points[p], points[fine.neighbors[p][k - 1]]) / double(k);
    field.fine_strength.push_back(feature_strength(fine.entropy[p], field.floor));
    strength[p] = terms.coarse_scale ? (std::max)(field.fine_strength[p], field.coarse_strength[p])
                                     : field.fine_strength[p];
  }
  // No point counts for more than 1000 times the median area: a stray point
  // far from the rest would otherwise make every radius, hence every
  // neighbourhood, as wide as its distance.
  const double largest_area = 1000. * median(area);
  for (double& a : area)
    a = (std::min)(a, largest_area);
  // Summed in the package's internal order, the kd order, so that the
  // rounding of the sums, hence the budget, is the same.
  double total_area = 0., feature_area = 0.;
  for (std::size_t p : kd)
  {
    total_area += area[p];
    feature_area += area[p] * strength[p];
  }
  field.weight = terms.feature_budget ? budgeted_weight(options.feature_weight, feature_area, total_area)
                                      : options.feature_weight;
  field.strong_features_first = terms.strong_features_first;
  const double typical_area = median(area);
  for (std::size_t p = 0; p < n; ++p)
  {
    // rounded to 30 significant bits, as the manual says
    int exponent = 0;
    const double significand =
      std::frexp(radius_factor(strength[p], field.weight, area[p], typical_area,
                               !terms.coverage_elimination),
                 &exponent);
    field.scale.push_back(std::ldexp(std::round(significand * 1073741824.), exponent - 30));
    field.effective_area += area[p] / (field.scale[p] * field.scale[p]);
  }
  return field;
}

// ----------------------------------------------------------------------------
// Weighted sample elimination (Yuksel 2015), in stages
// ----------------------------------------------------------------------------

struct Stage
{
  std::size_t target;
  double radius; // of a hexagonal packing of `target` points on the effective area
  double limit;  // Yuksel's weight limiting
  int exponent = 2; // of the pair weight
};

// Yuksel's eighth power in the stages that keep more than 55% of the `n`
// input points, the square in the others.
inline int weight_exponent(std::size_t stage_target, std::size_t n)
{
  return 100 * stage_target > 55 * n ? 8 : 2;
}

// The stage from `present` points down to `stage_target`.
inline Stage stage_to(std::size_t present, std::size_t stage_target, double effective_area)
{
  Stage stage;
  stage.target = stage_target;
  stage.radius = std::sqrt(effective_area / (2. * std::sqrt(3.) * double(stage.target)));
  stage.limit = stage.radius * 0.65 * (1. - std::pow(double(stage.target) / double(present), 1.5));
  return stage;
}

// Each stage halves the count, the last one reaching the target.
inline Stage stage_from(std::size_t present, std::size_t target, double effective_area)
{
  return stage_to(present, (std::max)(target, (present + 1) / 2), effective_area);
}

// (1 - d / 2r s)^e within 2 r s, e the stage's exponent, s the mean of the
// two scales, d not below the limit times s; in units of 2^-40, so that sums
// are exact in any order.
inline std::int64_t pair_weight(const Point& a, const Point& b, double scale_a, double scale_b, const Stage& stage)
{
  const double reach = stage.radius * (scale_a + scale_b);
  const double d = std::sqrt(squared_distance(a, b));
  if (d >= reach)
    return 0;
  const double floor = stage.limit * (scale_a + scale_b) / 2.;
  double w = 1. - (std::max)(d, floor) / reach;
  for (int power = 1; power < stage.exponent; power *= 2)
    w *= w;
  return std::llround(w * std::ldexp(1., 40));
}

// The weight of every pair of distinct points in a stage, row by row: the
// weights do not change within a stage.
inline std::vector<std::int64_t> pair_weights(const std::vector<Point>& points, const std::vector<double>& scale,
                                              const Stage& stage)
{
  const std::size_t n = points.size();
  std::vector<std::int64_t> weights(n * n, 0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      if (j != i)
        weights[i * n + j] = pair_weight(points[i], points[j], scale[i], scale[j], stage);
  return weights;
}

// The present point of greatest weight, ties to the lowest input position,
// every point's weight summed from scratch over the present points.
inline std::size_t most_crowded(const std::vector<std::int64_t>& weights, const std::vector<bool>& present)
{
  const std::size_t n = present.size();
  std::vector<std::size_t> members;
  for (std::size_t i = 0; i < n; ++i)
    if (present[i])
      members.push_back(i);
  std::size_t best = n;
  std::int64_t best_weight = 0;
  for (std::size_t i : members)
  {
    std::int64_t weight = 0;
    for (std::size_t j : members)
      weight += weights[i * n + j];
    if (best == n || weight > best_weight)
    {
      best = i;
      best_weight = weight;
    }
  }
  return best;
}

// The input positions of the removed points, first removed first, from
// the `present` points (all of them when empty), by weighted sample
// elimination in stages that halve the count.
inline std::vector<std::size_t> eliminate(const std::vector<Point>& points, const Field& field, std::size_t target,
                                          std::vector<bool> present = {})
{
  if (present.empty())
    present.assign(points.size(), true);
  std::size_t count = std::size_t(std::count(present.begin(), present.end(), true));
  std::vector<std::size_t> removed;
  while (count > target)
  {
    Stage stage = stage_from(count, target, field.effective_area);
    stage.exponent = weight_exponent(stage.target, points.size());
    const std::vector<std::int64_t> weights = pair_weights(points, field.scale, stage);
    for (; count > stage.target; --count)
    {
      const std::size_t p = most_crowded(weights, present);
      present[p] = false;
      removed.push_back(p);
    }
  }
  return removed;
}

// ----------------------------------------------------------------------------
// The greedy coverage elimination
// ----------------------------------------------------------------------------

// The present points nearest `points[p]` and next, in the neighbour order,
// `p` itself first when present, by a scan: (squared distance, input
// position).
inline std::vector<std::pair<double, std::size_t> > nearest_two_present(const std::vector<Point>& points,
                                                                         const std::vector<bool>& present,
                                                                         std::size_t p)
{
  std::vector<Neighbor> all;
  for (std::size_t q = 0; q < points.size(); ++q)
    if (present[q] && q != p)
      all.emplace_back(squared_distance(points[p], points[q]), q);
  std::sort(all.begin(), all.end());
  if (present[p])
    all.insert(all.begin(), Neighbor{ 0., p });
  std::vector<std::pair<double, std::size_t> > two;
  for (std::size_t j = 0; j < (std::min)(std::size_t(2), all.size()); ++j)
    two.push_back(all[j]);
  return two;
}

// The exponent e of the weights while `count` of `n` points are present:
// 1.1 above 35% of them, 1.35 above 20%, 1.6 otherwise.
inline double coverage_exponent(std::size_t count, std::size_t n)
{
  const double fraction = double(count) / double(n);
  return fraction > 0.35 ? 1.1 : fraction > 0.2 ? 1.35 : 1.6;
}

// The weight of each point in the greedy coverage elimination while `count`
// of the points are present: (smallest scale / its scale)^(2e), that is
// (1 + w s)^e over the greatest; while more than 35% are present (and the
// weight is not 0), (1 + w s^2)^e over the greatest instead, w s being
// 1 / scale^2 - 1, as the scales agree with the library's to the bit where
// the strengths may not.
inline std::vector<double> coverage_weights(const Field& field, std::size_t count)
{
  const double e = coverage_exponent(count, field.scale.size());
  std::vector<double> weight;
  if (field.strong_features_first && field.weight > 0. && double(count) / double(field.scale.size()) > 0.35)
  {
    double greatest = 0.;
    for (double s : field.scale)
    {
      const double w_s = 1. / (s * s) - 1.;
      weight.push_back(1. + w_s * w_s / field.weight);
      greatest = (std::max)(greatest, weight.back());
    }
    for (double& w : weight)
      w = std::pow(w / greatest, e);
    return weight;
  }
  const double smallest = *std::min_element(field.scale.begin(), field.scale.end());
  for (double s : field.scale)
    weight.push_back(std::pow(smallest / s, 2. * e));
  return weight;
}

// The points whose distances count in a greedy coverage elimination: every
// point with its weight (empty), or the points of nonzero weight, each as
// far from a point at distance d as sqrt(d^2 + spread^2).
struct Followers
{
  std::vector<double> weight, spread;
};

// The removal order from the `present` points (all when empty) down to
// `target`, the `followers` being the points whose distances count. By
// default, every point counts and weighs as coverage_weights() gives at
// the start of each round;
// what removing its nearest present point costs it is its weight times the
// distance to its next one less the distance to the nearest (each distance
// d being sqrt(d^2 + spread^2) for a follower of some spread), in units of
// 2^-20 of the typical spacing (the side of the effective area over n, the
// clouds here having no coincident points), truncated, at most 2^40 and at
// most the largest 64-bit integer over the number of points that count. A
// present point's cost sums those of the
// points it is nearest of. Each round, from the costs of its start: a
// present point is a candidate when it comes (lowest cost, then lowest
// scrambled input position) before every present point with which it is
// some point's nearest and next, and not after the tenth present point (at
// least the first); the candidates are removed in that order, at most down
// to `target`.
inline std::vector<std::size_t> coverage_eliminate(const std::vector<Point>& points, const Field& field,
                                                   std::size_t target, std::vector<bool> present = {},
                                                   const Followers& followers = {})
{
  const std::size_t n = points.size();
  if (present.empty())
    present.assign(n, true);
  const std::vector<double> spread = followers.spread.empty() ? std::vector<double>(n, 0.) : followers.spread;
  const auto counts = [&](std::size_t p) { return followers.weight.empty() || followers.weight[p] != 0.; };
  std::int64_t counted = 0;
  for (std::size_t p = 0; p < n; ++p)
    counted += counts(p) ? 1 : 0;
  const double unit = std::sqrt(field.effective_area / double(n)) / 1048576.;
  const std::int64_t largest =
    (std::min)(std::int64_t(1099511627776), std::numeric_limits<std::int64_t>::max() / counted);
  std::size_t count = std::size_t(std::count(present.begin(), present.end(), true));
  std::vector<std::size_t> removed;
  while (count > target)
  {
    const std::vector<double> weight = followers.weight.empty() ? coverage_weights(field, count) : followers.weight;
    std::vector<std::int64_t> cost(n, 0);
    std::vector<std::pair<std::size_t, std::size_t> > nearest_and_next;
    for (std::size_t p = 0; p < n; ++p)
    {
      if (!counts(p))
        continue;
      const auto two = nearest_two_present(points, present, p);
      const auto to = [&](double squared) { return std::sqrt(squared + spread[p] * spread[p]); };
      const double share = weight[p] * (to(two[1].first) - to(two[0].first)) / unit;
      cost[two[0].second] += share < double(largest) ? std::int64_t(share) : largest;
      nearest_and_next.emplace_back(two[0].second, two[1].second);
    }
    const auto key = [&](std::size_t s) { return std::make_pair(cost[s], scramble(std::uint32_t(s))); };
    std::vector<bool> candidate = present;
    for (const auto& [a, b] : nearest_and_next)
      candidate[key(a) < key(b) ? b : a] = false;
    std::vector<std::pair<std::int64_t, std::uint32_t> > keys;
    for (std::size_t s = 0; s < n; ++s)
      if (present[s])
        keys.push_back(key(s));
    std::sort(keys.begin(), keys.end());
    const auto tenth = keys[(std::max)(std::size_t(1), count / 10) - 1];
    std::vector<std::pair<std::pair<std::int64_t, std::uint32_t>, std::size_t> > round; // (key, point)
    for (std::size_t s = 0; s < n; ++s)
      if (candidate[s] && !(tenth < key(s)))
        round.emplace_back(key(s), s);
    std::sort(round.begin(), round.end());
    for (std::size_t j = 0; j < round.size() && count > target; ++j, --count)
    {
      present[round[j].second] = false;
      removed.push_back(round[j].second);
    }
  }
  return removed;
}

// ----------------------------------------------------------------------------
// The relocation: a relaxation in Lloyd's manner restricted to the input
// points, each cell keeping its median
// ----------------------------------------------------------------------------

// The present point nearest `points[p]`, itself when present.
inline std::size_t nearest_present(const std::vector<Point>& points, const std::vector<bool>& present, std::size_t p,
                                   const Adjacency& adjacent = everywhere)
{
  if (present[p])
    return p;
  Neighbor nearest{ std::numeric_limits<double>::infinity(), points.size() };
  for (std::size_t q = 0; q < points.size(); ++q)
    if (present[q] && adjacent(p, q))
      nearest = (std::min)(nearest, Neighbor{ squared_distance(points[p], points[q]), q });
  return nearest.second;
}

// A member of a cell as its representative: the sum of its distances to the
// members, in input order, and its squared distance to the farthest.
struct Merits
{
  std::size_t member;
  double distance_sum;
  double squared_radius;
};

inline Merits merits_in_cell(const std::vector<Point>& points, const std::vector<std::size_t>& members,
                             std::size_t member)
{
  Merits m{ member, 0., 0. };
  for (std::size_t q : members)
  {
    m.distance_sum += std::sqrt(squared_distance(points[q], points[member]));
    m.squared_radius = (std::max)(m.squared_radius, squared_distance(points[q], points[member]));
  }
  return m;
}

// The `wanted` members of a cell nearest its centroid (summed in input
// order), nearest first, with their merits.
inline std::vector<Merits> candidates_of_cell(const std::vector<Point>& points, const std::vector<std::size_t>& members,
                                              std::size_t wanted)
{
  double x = 0., y = 0., z = 0.;
  for (std::size_t q : members)
  {
    x += points[q].x();
    y += points[q].y();
    z += points[q].z();
  }
  const double count = double(members.size());
  const Point centroid(x / count, y / count, z / count);
  std::vector<Neighbor> by_distance;
  for (std::size_t q : members)
    by_distance.emplace_back(squared_distance(points[q], centroid), q);
  std::sort(by_distance.begin(), by_distance.end());
  std::vector<Merits> candidates;
  for (std::size_t j = 0; j < (std::min)(wanted, by_distance.size()); ++j)
    candidates.push_back(merits_in_cell(points, members, by_distance[j].second));
  return candidates;
}

// One iteration: every input point joins the cell of its nearest present
// point. Each cell keeps, among its four members nearest its centroid, the
// one whose distances to the members sum least (ties: the lowest position),
// leaving out those whose farthest member is farther than the farthest member
// of any cell from that cell's member nearest its centroid. Without
// `terms.medians`, each cell keeps its member nearest its centroid; without
// `terms.radius_bound`, no candidate is left out.
inline std::vector<bool> relocation_step(const std::vector<Point>& points, const std::vector<bool>& present,
                                         const Terms& terms)
{
  const std::size_t n = points.size();
  std::vector<std::vector<std::size_t> > members(n);
  for (std::size_t p = 0; p < n; ++p)
    members[nearest_present(points, present, p)].push_back(p);
  std::vector<std::vector<Merits> > candidates(n);
  double bound = 0.;
  for (std::size_t c = 0; c < n; ++c)
    if (present[c])
    {
      candidates[c] = candidates_of_cell(points, members[c], terms.medians ? 4 : 1);
      bound = (std::max)(bound, candidates[c].front().squared_radius);
    }
  std::vector<bool> relocated(n, false);
  for (std::size_t c = 0; c < n; ++c)
    if (present[c])
    {
      Merits best = candidates[c].front();
      for (const Merits& m : candidates[c])
        if ((m.squared_radius <= bound || !terms.radius_bound) && std::make_pair(m.distance_sum, m.member) < std::make_pair(best.distance_sum, best.member))
          best = m;
      relocated[best.member] = true;
    }
  return relocated;
}

// The present point nearest `points[p]` other than `p` and `excluded`, at
// an infinite distance when there is none.
inline Neighbor nearest_present_but(const std::vector<Point>& points, const std::vector<bool>& present, std::size_t p,
                                    std::size_t excluded, const Adjacency& adjacent)
{
  Neighbor nearest{ std::numeric_limits<double>::infinity(), points.size() };
  for (std::size_t q = 0; q < points.size(); ++q)
    if (present[q] && q != p && q != excluded && adjacent(p, q))
      nearest = (std::min)(nearest, Neighbor{ squared_distance(points[p], points[q]), q });
  return nearest;
}

inline double squared_distance_to_present(const std::vector<Point>& points, const std::vector<bool>& present,
                                          std::size_t p, const Adjacency& adjacent = everywhere)
{
  const std::size_t nearest = nearest_present(points, present, p, adjacent);
  return nearest == points.size() ? std::numeric_limits<double>::infinity()
                                  : squared_distance(points[p], points[nearest]);
}

// How crowded present point `p` is: the squared distance to its nearest
// other present point divided by the square of its scale.
inline double crowding_of(const std::vector<Point>& points, const std::vector<bool>& present,
                          const std::vector<double>& scale, std::size_t p, const Adjacency& adjacent)
{
  return nearest_present_but(points, present, p, p, adjacent).first / (scale[p] * scale[p]);
}

// The coverage swaps, up to `swaps` times: the point farthest from the
// present points (ties: the lowest position) becomes present. Then the
// present points of the start are tried in the order of their crowding at
// the start (ties: the lowest position), each once over all the swaps: the
// first one still present, no less crowded than at the start, and such that
// each point whose nearest present point it is would be nearer its nearest
// present point other than it than the farthest point now is from its own,
// is no longer present. When none is, the farthest point is not present
// either, and the swaps end. A point's present points are those `adjacent`
// to it; one with none is at an infinite distance from them.
inline void swap_farthest_for_crowded(const std::vector<Point>& points, std::vector<bool>& present, std::size_t swaps,
                                      const std::vector<double>& scale, const Adjacency& adjacent = everywhere)
{
  const std::size_t n = points.size();
  std::vector<Neighbor> crowded;
  for (std::size_t p = 0; p < n; ++p)
    if (present[p])
      crowded.emplace_back(crowding_of(points, present, scale, p, adjacent), p);
  if (crowded.size() < 2 || crowded.size() == n)
    return;
  std::sort(crowded.begin(), crowded.end());
  std::size_t tried = 0;
  for (std::size_t swap = 0; swap < swaps; ++swap)
  {
    std::size_t farthest = n;
    double farthest_distance = -1.;
    for (std::size_t p = 0; p < n; ++p)
      if (!present[p] && squared_distance_to_present(points, present, p, adjacent) > farthest_distance)
      {
        farthest = p;
        farthest_distance = squared_distance_to_present(points, present, p, adjacent);
      }
    if (farthest == n)
      return;
    present[farthest] = true;
    double greatest = 0.;
    for (std::size_t p = 0; p < n; ++p)
      greatest = (std::max)(greatest, squared_distance_to_present(points, present, p, adjacent));
    bool left = false;
    while (tried < crowded.size() && !left)
    {
      const auto [crowding, y] = crowded[tried++];
      if (!present[y] || crowding_of(points, present, scale, y, adjacent) > crowding)
        continue;
      bool stays_near = true;
      for (std::size_t p = 0; p < n; ++p)
        if (nearest_present(points, present, p, adjacent) == y &&
            !(nearest_present_but(points, present, p, y, adjacent).first < greatest))
          stays_near = false;
      present[y] = !stays_near;
      left = stays_near;
    }
    if (!left)
    {
      present[farthest] = false;
      return;
    }
  }
}

// ----------------------------------------------------------------------------
// The default mode
// ----------------------------------------------------------------------------

// `rate` per hundred of `kept` points, rounded up.
inline std::size_t per_hundred(std::size_t rate, std::size_t kept) { return (rate * kept + 99) / 100; }

// The coverage swaps of a run that keeps `kept` of `n` points: three per
// hundred, rounded up, when it keeps at most a quarter of them, else one.
inline std::size_t coverage_swaps_keeping(std::size_t kept, std::size_t n)
{
  return per_hundred(4 * kept <= n ? 3 : 1, kept);
}

// The removal order of the default mode down to `target` points, on the
// `field` of the points: the elimination's, then two iterations of
// relocation and the coverage swaps (see coverage_swaps_keeping); the j-th
// point the relocation drops takes the place, in the
// removal order, of the j-th point it brings in, both in input order. The
// `terms` switched off are left out.
inline std::vector<std::size_t> removal_order(const std::vector<Point>& points, const Field& field,
                                              std::size_t target, const Terms& terms = Terms())
{
  std::vector<std::size_t> removed = terms.coverage_elimination
                                       ? coverage_eliminate(points, field, target)
                                       : eliminate(points, field, target);
  if ((!terms.relocation && !terms.coverage_swaps) || removed.empty())
    return removed;
  std::vector<bool> eliminated(points.size(), true);
  for (std::size_t p : removed)
    eliminated[p] = false;
  std::vector<bool> relocated = eliminated;
  for (int iteration = 0; iteration < (terms.relocation ? 2 : 0); ++iteration)
    relocated = relocation_step(points, relocated, terms);
  if (terms.coverage_swaps)
    swap_farthest_for_crowded(points, relocated, coverage_swaps_keeping(target, points.size()), field.scale);
  std::vector<std::size_t> gone, come;
  for (std::size_t p = 0; p < points.size(); ++p)
  {
    if (eliminated[p] && !relocated[p])
      gone.push_back(p);
    if (!eliminated[p] && relocated[p])
      come.push_back(p);
  }
  for (std::size_t j = 0; j < gone.size(); ++j)
    *std::find(removed.begin(), removed.end(), come[j]) = gone[j];
  return removed;
}

// ----------------------------------------------------------------------------
// The ranks of the default mode
// ----------------------------------------------------------------------------

// The level boundaries of n points: 50, 20, 10, 5, 2, 1, 0.5, ...% of them,
// rounded up, from the largest.
inline std::vector<std::size_t> level_boundaries(std::size_t n)
{
  std::vector<std::size_t> boundaries;
  for (double denominator = 10.; denominator <= 10. * double(n); denominator *= 10.)
    for (double numerator : { 5., 2., 1. })
      boundaries.push_back(std::size_t(std::ceil(double(n) * numerator / denominator - 1e-9)));
  return boundaries;
}

// Where a stage of the ranking below its level ends, from `present` points:
// the first boundary below `present`, or 1.
inline std::size_t stage_end(std::size_t present, std::size_t n)
{
  for (std::size_t boundary : level_boundaries(n))
    if (boundary < present)
      return (std::max)(boundary, std::size_t(1));
  return 1;
}

// The cells of the points, each in that of its nearest present point: a
// label per point (equal labels, one cell).
inline std::vector<std::size_t> cells_of_present(const std::vector<Point>& points, const std::vector<bool>& present)
{
  std::vector<std::size_t> label(points.size());
  for (std::size_t p = 0; p < points.size(); ++p)
    label[p] = nearest_present(points, present, p);
  return label;
}

// At a boundary, first: the coverage swaps on a cloud of the present points
// and those the stage removed alone, three per hundred present points
// rounded up, a point's present points being those of nonzero weight in
// the stage; the j-th point that leaves takes the place, in
// `stage_removed`, of the j-th point that comes, both in input order.
inline void swap_at_boundary(const std::vector<Point>& points, const std::vector<double>& scale,
                             const std::vector<std::int64_t>& weights, std::vector<bool>& present,
                             std::vector<std::size_t>& stage_removed)
{
  const std::size_t n = points.size();
  std::vector<bool> in_level_above = present;
  for (std::size_t r : stage_removed)
    in_level_above[r] = true;
  std::vector<std::size_t> position;
  std::vector<Point> cloud;
  std::vector<bool> cloud_present;
  std::vector<double> cloud_scale;
  for (std::size_t p = 0; p < n; ++p)
    if (in_level_above[p])
    {
      position.push_back(p);
      cloud.push_back(points[p]);
      cloud_present.push_back(present[p]);
      cloud_scale.push_back(scale[p]);
    }
  const std::size_t kept = std::size_t(std::count(present.begin(), present.end(), true));
  swap_farthest_for_crowded(cloud, cloud_present, per_hundred(3, kept), cloud_scale,
                            [&](std::size_t a, std::size_t b) { return weights[position[a] * n + position[b]] != 0; });
  std::vector<std::size_t> gone, come;
  for (std::size_t c = 0; c < cloud.size(); ++c)
  {
    if (present[position[c]] && !cloud_present[c])
      gone.push_back(position[c]);
    if (!present[position[c]] && cloud_present[c])
      come.push_back(position[c]);
  }
  for (std::size_t j = 0; j < gone.size(); ++j)
  {
    present[gone[j]] = false;
    present[come[j]] = true;
    *std::find(stage_removed.begin(), stage_removed.end(), come[j]) = gone[j];
  }
}

// Each cell with a present point keeps, among that point and the stage's
// removed points of the cell, the one whose distances to the cell's points,
// summed in input order, sum least (ties: the lowest position), which takes
// the other's place in `stage_removed`.
inline void keep_cell_medians(const std::vector<Point>& points, std::vector<bool>& present,
                              const std::vector<std::size_t>& label, std::vector<std::size_t>& stage_removed)
{
  const std::size_t n = points.size();
  const auto distance_sum = [&](std::size_t candidate, std::size_t cell) {
    double sum = 0.;
    for (std::size_t q = 0; q < n; ++q)
      if (label[q] == cell)
        sum += std::sqrt(squared_distance(points[q], points[candidate]));
    return sum;
  };
  const std::vector<bool> sites = present;
  for (std::size_t site = 0; site < n; ++site)
  {
    if (!sites[site])
      continue;
    std::pair<double, std::size_t> best{ distance_sum(site, label[site]), site };
    for (std::size_t r : stage_removed)
      if (label[r] == label[site])
        best = (std::min)(best, std::make_pair(distance_sum(r, label[site]), r));
    if (best.second == site)
      continue;
    present[site] = false;
    present[best.second] = true;
    *std::find(stage_removed.begin(), stage_removed.end(), best.second) = site;
  }
}

// At a boundary, then: each point the stage removed (in removal order) brings its
// cell into that of the present point nearest it among those `adjacent` to
// it, if any; then each cell keeps its median (keep_cell_medians).
inline void relocate_boundary(const std::vector<Point>& points, const Adjacency& adjacent,
                              std::vector<bool>& present, std::vector<std::size_t>& label,
                              std::vector<std::size_t>& stage_removed)
{
  const std::size_t n = points.size();
  for (std::size_t r : stage_removed)
  {
    const std::size_t nearest = nearest_present(points, present, r, adjacent);
    if (nearest == n)
      continue;
    const std::size_t from = label[r], to = label[nearest];
    for (std::size_t& l : label)
      if (l == from)
        l = to;
  }
  keep_cell_medians(points, present, label, stage_removed);
}

// The removal order of the `present` points down to one, in stages that end
// at the level boundaries, each swapped and relocated.
inline std::vector<std::size_t> eliminate_by_boundaries(const std::vector<Point>& points, const Field& field,
                                                        std::vector<bool> present)
{
  const std::size_t n = points.size();
  std::vector<std::size_t> label = cells_of_present(points, present);
  std::size_t count = std::size_t(std::count(present.begin(), present.end(), true));
  std::vector<std::size_t> removed;
  while (count > 1)
  {
    Stage stage = stage_to(count, stage_end(count, n), field.effective_area);
    stage.exponent = weight_exponent(stage.target, n);
    const std::vector<std::int64_t> weights = pair_weights(points, field.scale, stage);
    std::vector<std::size_t> stage_removed;
    for (; count > stage.target; --count)
    {
      const std::size_t p = most_crowded(weights, present);
      present[p] = false;
      stage_removed.push_back(p);
    }
    if (stage.target > 1)
    {
      swap_at_boundary(points, field.scale, weights, present, stage_removed);
      relocate_boundary(
        points, [&](std::size_t a, std::size_t b) { return weights[a * n + b] != 0; }, present, label, stage_removed);
    }
    removed.insert(removed.end(), stage_removed.begin(), stage_removed.end());
  }
  return removed;
}

// The removal order of the `present` points down to one by the greedy
// coverage elimination, in stages that end at the level boundaries, each
// relocated, every present point adjacent to every removed one, and
// relocated a second time, each point in the cell of its nearest present
// point, while every point counts. Once at
// most 1% of the points (rounded up) are present, at the start or after a
// relocation, the present points alone count from then on, each weighing
// the sum of the weights of the points nearest it, its spread their mean
// distance to it, weighted, both summed in input order.
inline std::vector<std::size_t> coverage_eliminate_by_boundaries(const std::vector<Point>& points,
                                                                 const Field& field, std::vector<bool> present)
{
  const std::size_t n = points.size();
  std::vector<std::size_t> label = cells_of_present(points, present);
  std::size_t count = std::size_t(std::count(present.begin(), present.end(), true));
  Followers followers; // every point with its own weight, until the switch
  const auto represent_when_few = [&] {
    if (!followers.weight.empty() || count > (n + 99) / 100)
      return;
    const std::vector<double> weight = coverage_weights(field, count);
    followers.weight.assign(n, 0.);
    followers.spread.assign(n, 0.);
    for (std::size_t p = 0; p < n; ++p)
    {
      const std::size_t r = nearest_present(points, present, p);
      followers.weight[r] += weight[p];
      followers.spread[r] += weight[p] * std::sqrt(squared_distance(points[p], points[r]));
    }
    for (std::size_t r = 0; r < n; ++r)
      if (present[r])
        followers.spread[r] /= followers.weight[r];
  };
  represent_when_few();
  std::vector<std::size_t> removed;
  while (count > 1)
  {
    const std::size_t end = stage_end(count, n);
    std::vector<std::size_t> stage_removed = coverage_eliminate(points, field, end, present, followers);
    for (std::size_t r : stage_removed)
      present[r] = false;
    count = end;
    if (end > 1)
    {
      relocate_boundary(points, everywhere, present, label, stage_removed);
      if (followers.weight.empty())
      {
        // every point still counts: its cell becomes that of its nearest
        // present point, and each cell keeps its median once more
        label = cells_of_present(points, present);
        keep_cell_medians(points, present, label, stage_removed);
      }
      represent_when_few();
    }
    removed.insert(removed.end(), stage_removed.begin(), stage_removed.end());
  }
  return removed;
}

// The ranks of the default mode with the level `level` exact: the points
// kept by the default mode down to `level` are ordered by eliminating among
// them by boundaries, or by the greedy coverage elimination going on when
// the `terms` say so; rank 0 is the last point present, and the points
// removed after it come before those removed earlier.
inline std::vector<std::size_t> ranks(const std::vector<Point>& points, const Field& field, std::size_t level,
                                      const Terms& terms = Terms())
{
  const std::size_t n = points.size();
  std::vector<std::size_t> removed =
    level < n ? removal_order(points, field, level, terms) : std::vector<std::size_t>();
  std::vector<bool> kept(n, true);
  for (std::size_t p : removed)
    kept[p] = false;
  for (std::size_t p : terms.coverage_elimination ? coverage_eliminate_by_boundaries(points, field, kept)
                                                  : eliminate_by_boundaries(points, field, kept))
    removed.push_back(p);
  std::vector<std::size_t> rank(n, 0); // the one point never removed keeps 0
  for (std::size_t j = 0; j < removed.size(); ++j)
    rank[removed[j]] = n - 1 - j;
  return rank;
}

} // namespace reference

#endif // ENTROPY_SIMPLIFICATION_TEST_REFERENCE_ELIMINATION_H
