// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The normal of one neighbourhood (Eq. 1-2), by PCA or by jet fitting.

#ifndef CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_LOCAL_NORMAL_H
#define CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_LOCAL_NORMAL_H

#include <CGAL/Entropy_simplification/Options.h>
#include <CGAL/Entropy_simplification/internal/Array.h>
#include <CGAL/Entropy_simplification/internal/Indexed_points.h>

#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Eigen_svd.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Entropy_simplification {
namespace internal {

using Working_vector = Working_kernel::Vector_3;

// The centroid of the `m` points `point(0)`, ..., `point(m-1)`, summed in
// that order.
template <typename PointAt>
Working_point centroid_of(std::size_t m, PointAt point)
{
  double x = 0., y = 0., z = 0.;
  for (std::size_t i = 0; i < m; ++i)
  {
    const Working_point& p = point(i);
    x += p.x(); y += p.y(); z += p.z();
  }
  return Working_point(x / double(m), y / double(m), z / double(m));
}

// The unit normal of the plane fitted by least squares to the `m` points
// `point(0)`, ..., `point(m-1)`: the eigenvector of the smallest eigenvalue of
// their covariance matrix, as `CGAL::pca_estimate_normals()` computes it.
// The closed-form 3x3 solver re-estimates a normal in a fraction of the time
// of an iterative one, which matters because every removal re-estimates about
// k normals. Points that all coincide have no plane: the result is then the
// null vector.
template <typename PointAt>
Working_vector pca_normal(std::size_t m, PointAt point)
{
  const Working_point c = centroid_of(m, point);
  const double cx = c.x(), cy = c.y(), cz = c.z();

  double xx = 0., xy = 0., xz = 0., yy = 0., yz = 0., zz = 0.;
  for (std::size_t i = 0; i < m; ++i)
  {
    const Working_point& p = point(i);
    const double dx = p.x() - cx, dy = p.y() - cy, dz = p.z() - cz;
    xx += dx * dx; xy += dx * dy; xz += dx * dz;
    yy += dy * dy; yz += dy * dz; zz += dz * dz;
  }
  if (xx + yy + zz == 0.)
    return CGAL::NULL_VECTOR;

  Eigen::Matrix3d covariance;
  covariance << xx, xy, xz,
                xy, yy, yz,
                xz, yz, zz;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(covariance);
  const Eigen::Vector3d normal = solver.eigenvectors().col(0);
  return Working_vector(normal(0), normal(1), normal(2));
}

// The unit normal of a jet of degree 2 fitted to the `m >= 6` points, the
// first being the point where the normal is wanted, as
// `CGAL::jet_estimate_normals()` computes it. A fit that degenerates (for
// instance on coincident points) gives the null vector, as PCA does. So does
// a neighbourhood narrower than smallest_extent, the least the package
// accepts for a cloud: the fit's scaling underflows there, and its SVD then
// reads out of bounds.
template <typename PointAt>
Working_vector jet_normal(std::size_t m, PointAt point)
{
  using Fitting = CGAL::Monge_via_jet_fitting<Working_kernel, Working_kernel, CGAL::Eigen_svd>;
  thread_local Array<Working_point> points;
  points.clear();
  double extent = 0.;
  for (std::size_t i = 0; i < m; ++i)
  {
    points.push_back(point(i));
    extent = (std::max)(extent, squared_distance(points.front(), points.back()));
  }
  if (extent < smallest_extent * smallest_extent)
    return CGAL::NULL_VECTOR;
  Fitting fitting;
  const Working_vector normal = fitting(points.begin(), points.end(), 2, 1).normal_direction();
  if (!(std::isfinite(normal.x()) && std::isfinite(normal.y()) && std::isfinite(normal.z())))
    return CGAL::NULL_VECTOR;
  return normal;
}

template <typename PointAt>
Working_vector estimate_normal(Normal_estimation method, std::size_t m, PointAt point)
{
  return method == Normal_estimation::jet ? jet_normal(m, point) : pca_normal(m, point);
}

// The normal of point `i` estimated on it and `near`, its k nearest
// neighbours, `estimation` choosing the method.
inline Working_vector neighborhood_normal(const Indexed_points& points, Index i, const Index* near, unsigned int k,
                                          Normal_estimation estimation)
{
  return estimate_normal(estimation, k + 1, [&](std::size_t j) -> const Working_point& {
    return points.points[j == 0 ? i : near[j - 1]];
  });
}

// The smallest k each estimator accepts: a plane needs 3 points, a jet of
// degree 2 needs 6.
inline unsigned int minimum_k(Normal_estimation method)
{
  return method == Normal_estimation::jet ? 5u : 2u;
}

} // namespace internal
} // namespace Entropy_simplification
} // namespace CGAL

#endif // CGAL_ENTROPY_SIMPLIFICATION_INTERNAL_LOCAL_NORMAL_H
