// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The normal angle (Eq. 4) and the entropy of a neighbourhood's angles (Eq. 5).

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_NORMAL_ANGLE_ENTROPY_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_NORMAL_ANGLE_ENTROPY_H

#include <CGAL/Entropy_simplification/internal/local_normal.h>

#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// Eq. 4: the angle between a normal and the reference PLANE, in [0, pi/2].
// atan2 keeps full precision at both ends, where arcsin or pi/2 - arccos lose
// about 1e-8 rad, enough to reorder near-ties in flat regions. A null normal
// (undefined) gets the angle 0.
inline double normal_angle(const Working_vector& normal, const Working_vector& reference)
{
  const double along = std::abs(normal * reference);
  const double across = std::sqrt(CGAL::cross_product(normal, reference).squared_length());
  return std::atan2(along, across);
}

// A normal angle with the term theta * log(theta) that Eq. 5 sums, computed
// once per point rather than once per neighbourhood the point belongs to.
struct Angle_term
{
  double theta = 0.;
  double theta_log_theta = 0.;
};

inline Angle_term make_angle_term(double theta)
{
  return Angle_term{ theta, theta > 0. ? theta * std::log(theta) : 0. };
}

// Eq. 5, the entropy (natural log) of the angles theta_0..theta_{m-1} of a
// point and its neighbours, each normalised by their sum S:
//   H = -sum (theta_i / S) log(theta_i / S) = log S - (1 / S) sum theta_i log theta_i.
// Conventions the paper leaves open: 0 log 0 = 0, and H = 0 when every angle
// is 0 (no angle to distribute). H lies in [0, log m]. `term(i)` returns the
// Angle_term of the i-th angle; the sums run in index order.
template <typename TermAt>
double angle_entropy(std::size_t m, TermAt term)
{
  double sum = 0., sum_log = 0.;
  for (std::size_t i = 0; i < m; ++i)
  {
    const Angle_term& t = term(i);
    sum += t.theta;
    sum_log += t.theta_log_theta;
  }
  if (sum == 0.)
    return 0.;
  return std::log(sum) - sum_log / sum;
}

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_NORMAL_ANGLE_ENTROPY_H
