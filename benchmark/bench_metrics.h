// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The metrics of the benchmark (defined in benchmark/README.md).

#ifndef ENTROPY_SIMPLIFICATION_BENCH_METRICS_H
#define ENTROPY_SIMPLIFICATION_BENCH_METRICS_H

#include "bench_baselines.h"
#include "bench_common.h"

#include <CGAL/Entropy_simplification/compute_mean_normal_angle_entropy.h>

#include <CGAL/linear_least_squares_fitting_3.h>

#include <tbb/parallel_for.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace bench {

struct Quality
{
  // distance from each input point to the nearest kept point, / diagonal
  double mean = 0., p95 = 0., p99 = 0., max = 0.;
  // RMS distance of each input point to the PCA plane of its nearest kept
  // point's 10 nearest kept points, / diagonal
  double point_to_plane = 0.;
  // coefficient of variation of the kept points' nearest-neighbour distances
  double uniformity = 0.;
  // the paper's indicator (Eq. 7), in bits, k = 10, the input's reference plane
  double mean_entropy = 0.;
  // kept points labelled 1 (ball, or near a sharp edge)
  std::size_t labelled = 0;
  // replica only: radius of the sphere fitted to the kept ball points, RMSE of
  // the plane fitted to the kept board points (Table 3)
  double sphere_radius = 0., plane_rmse = 0.;
};

// PCA plane (unit normal, centroid) of points given by index.
inline std::pair<Eigen::Vector3d, Eigen::Vector3d> pca_plane(const std::vector<Point>& points,
                                                             const std::vector<Index>& which)
{
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (Index j : which)
    mean += Eigen::Vector3d(points[j].x(), points[j].y(), points[j].z());
  mean /= double(which.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (Index j : which)
  {
    const Eigen::Vector3d d = Eigen::Vector3d(points[j].x(), points[j].y(), points[j].z()) - mean;
    covariance += d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  return { solver.eigenvectors().col(0), mean };
}

// Radius of the sphere fitted by least squares to the points: an algebraic
// fit, refined by Gauss-Newton on the geometric distances.
inline double fitted_sphere_radius(const std::vector<Point>& points)
{
  if (points.size() < 4)
    return std::numeric_limits<double>::quiet_NaN();
  Eigen::MatrixXd a(points.size(), 4);
  Eigen::VectorXd b(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const Point& p = points[i];
    a.row(i) << 2. * p.x(), 2. * p.y(), 2. * p.z(), 1.;
    b(i) = p.x() * p.x() + p.y() * p.y() + p.z() * p.z();
  }
  const Eigen::Vector4d s = a.colPivHouseholderQr().solve(b);
  Eigen::Vector3d c(s(0), s(1), s(2));
  double r = std::sqrt(s(3) + c.squaredNorm());
  for (int iteration = 0; iteration < 20; ++iteration)
  {
    Eigen::MatrixXd j(points.size(), 4);
    Eigen::VectorXd residual(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      const Eigen::Vector3d d = Eigen::Vector3d(points[i].x(), points[i].y(), points[i].z()) - c;
      const double distance = d.norm();
      residual(i) = distance - r;
      j.row(i) << -d.transpose() / distance, -1.;
    }
    const Eigen::Vector4d step = j.colPivHouseholderQr().solve(-residual);
    c += step.head<3>();
    r += step(3);
    if (step.norm() < 1e-12)
      break;
  }
  return r;
}

inline double fitted_plane_rmse(const std::vector<Point>& points)
{
  if (points.size() < 3)
    return std::numeric_limits<double>::quiet_NaN();
  Kernel::Plane_3 plane;
  CGAL::linear_least_squares_fitting_3(points.begin(), points.end(), plane, CGAL::Dimension_tag<0>());
  double sum = 0.;
  for (const Point& p : points)
    sum += CGAL::squared_distance(p, plane);
  return std::sqrt(sum / double(points.size()));
}

// Per point, over the input's diagonal: each input point's distance to its
// nearest kept point and to that point's PCA plane of its 10 nearest kept
// points (itself included); each kept point's distance to its nearest other
// kept point. And each input point's nearest kept point.
struct Point_distances
{
  std::vector<double> to_nearest, to_plane, spacing;
  std::vector<Index> nearest;
};

inline Point_distances point_distances(const Cloud& input, const std::vector<Point>& kept)
{
  const Index_tree tree(kept);
  const std::size_t m = kept.size();
  std::vector<Eigen::Vector3d> normal(m), centroid(m);
  Point_distances d{ std::vector<double>(input.points.size()), std::vector<double>(input.points.size()),
                     std::vector<double>(m), std::vector<Index>(input.points.size()) };
  tbb::parallel_for(std::size_t(0), m, [&](std::size_t i) {
    thread_local std::vector<Index> near;
    tree.nearest(kept[i], 10, near);
    std::tie(normal[i], centroid[i]) = pca_plane(kept, near);
    d.spacing[i] = std::sqrt(CGAL::squared_distance(kept[i], kept[near[1]])) / input.diagonal;
  });
  tbb::parallel_for(std::size_t(0), input.points.size(), [&](std::size_t i) {
    thread_local std::vector<Index> near;
    tree.nearest(input.points[i], 1, near);
    const Point& p = input.points[i];
    d.nearest[i] = near[0];
    d.to_nearest[i] = std::sqrt(CGAL::squared_distance(p, kept[near[0]])) / input.diagonal;
    d.to_plane[i] =
      std::abs(normal[near[0]].dot(Eigen::Vector3d(p.x(), p.y(), p.z()) - centroid[near[0]])) / input.diagonal;
  });
  return d;
}

inline Quality measure(const Cloud& input, const Selection& kept, bool is_replica,
                       const CGAL::Entropy_simplification::Options& indicator_options)
{
  Quality q;
  const std::size_t n = input.points.size(), m = kept.points.size();
  Point_distances d = point_distances(input, kept.points);
  std::vector<double>& distance = d.to_nearest;
  const std::vector<double>& plane_distance = d.to_plane;

  double sum = 0., squares = 0.;
  for (std::size_t i = 0; i < n; ++i)
  {
    sum += distance[i];
    squares += plane_distance[i] * plane_distance[i];
  }
  q.mean = sum / double(n);
  q.point_to_plane = std::sqrt(squares / double(n));
  std::sort(distance.begin(), distance.end());
  q.p95 = distance[std::size_t(0.95 * double(n - 1))];
  q.p99 = distance[std::size_t(0.99 * double(n - 1))];
  q.max = distance.back();

  double s = 0., ss = 0.;
  for (double x : d.spacing)
  {
    s += x;
    ss += x * x;
  }
  const double mean_spacing = s / double(m);
  q.uniformity = std::sqrt((std::max)(0., ss / double(m) - mean_spacing * mean_spacing)) / mean_spacing;

  q.mean_entropy = CGAL::compute_mean_normal_angle_entropy<CGAL::Parallel_if_available_tag>(
    kept.points, 10, CGAL::parameters::default_values(), indicator_options);

  std::vector<Point> ball, board;
  for (std::size_t i = 0; i < kept.labels.size(); ++i)
  {
    q.labelled += kept.labels[i] == 1;
    (kept.labels[i] == 1 ? ball : board).push_back(kept.points[i]);
  }
  if (is_replica)
  {
    q.sphere_radius = fitted_sphere_radius(ball);
    q.plane_rmse = fitted_plane_rmse(board);
  }
  return q;
}

} // namespace bench

#endif // ENTROPY_SIMPLIFICATION_BENCH_METRICS_H
