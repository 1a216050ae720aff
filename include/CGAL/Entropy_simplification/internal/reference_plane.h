// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The reference plane of the normal angles (Eq. 3).

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_REFERENCE_PLANE_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_REFERENCE_PLANE_H

#include <CGAL/Entropy_simplification/Options.h>
#include <CGAL/Entropy_simplification/internal/local_normal.h>

#include <CGAL/linear_least_squares_fitting_3.h>

#include <cmath>
#include <stdexcept>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

// The unit normal of the reference plane: the user's, or else the normal of
// the plane fitted by orthogonal total least squares to all the points (Eq. 3),
// i.e. the eigenvector of the smallest eigenvalue of their covariance. The
// points come in input order so that the fit does not depend on how the
// package reorders them internally: any range of Working_point.
template <typename WorkingPoints>
Working_vector reference_normal(const Options& options, const WorkingPoints& points_in_input_order)
{
  Working_vector normal;
  if (options.reference_normal)
  {
    const auto& n = *options.reference_normal;
    normal = Working_vector(n[0], n[1], n[2]);
    if (!(std::isfinite(normal.squared_length()) && normal.squared_length() > 0.))
      throw std::invalid_argument("Options::reference_normal must be finite and not null");
  }
  else
  {
    Working_kernel::Plane_3 plane;
    CGAL::linear_least_squares_fitting_3(points_in_input_order.begin(), points_in_input_order.end(),
                                         plane, CGAL::Dimension_tag<0>());
    normal = plane.orthogonal_vector();
  }
  return normal / std::sqrt(normal.squared_length());
}

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_REFERENCE_PLANE_H
