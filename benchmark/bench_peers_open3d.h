// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Open3D's simplifiers as peers of the benchmark (built with
// ES_BENCH_WITH_OPEN3D, when CMake finds Open3D): VoxelDownSample and
// FarthestPointDownSample of the legacy geometry::PointCloud. Each is brought
// to exactly m points like CGAL's simplifiers (bench_methods.h).

#ifndef ENTROPY_SIMPLIFICATION_BENCH_PEERS_OPEN3D_H
#define ENTROPY_SIMPLIFICATION_BENCH_PEERS_OPEN3D_H

#include "bench_methods.h"

#include <open3d/Open3DConfig.h>
#include <open3d/geometry/PointCloud.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace bench {
namespace open3d_peers {

inline std::string description()
{
  return std::string("Open3D ") + OPEN3D_VERSION + " (VoxelDownSample, FarthestPointDownSample)";
}

// The input as Open3D's cloud (double precision, no translation needed).
// Converted once per input, not timed: an Open3D user's cloud is already in
// this form.
inline std::shared_ptr<const open3d::geometry::PointCloud> to_open3d(const Cloud& cloud)
{
  auto result = std::make_shared<open3d::geometry::PointCloud>();
  result->points_.reserve(cloud.points.size());
  for (const Point& p : cloud.points)
    result->points_.emplace_back(p.x(), p.y(), p.z());
  return result;
}

// VoxelDownSample: the centroid of the points in each voxel of edge `edge`
// (the grid starts half an edge below the bounding box), new points like
// WLOP's. Open3D refuses an edge below the extent / INT_MAX; the searches
// start at 1e-7 times the diagonal, far above it.
inline std::vector<Point> voxel_down_sample(const open3d::geometry::PointCloud& input, double edge)
{
  const std::shared_ptr<open3d::geometry::PointCloud> out = input.VoxelDownSample(edge);
  std::vector<Point> result;
  result.reserve(out->points_.size());
  for (const Eigen::Vector3d& p : out->points_)
    result.emplace_back(p.x(), p.y(), p.z());
  return result;
}

// FarthestPointDownSample: from the first input point, repeatedly the point
// farthest from those already chosen; exactly m input points, deterministic.
// It costs O(n m) (one sequential pass over the input per point chosen).
inline std::shared_ptr<open3d::geometry::PointCloud> farthest_points(const open3d::geometry::PointCloud& input,
                                                                     std::size_t m)
{
  return input.FarthestPointDownSample(m);
}

// Open3D returns the chosen points, not their indices. For the quality runs,
// a copy of the input carries each point's index in its colour, which the
// method ignores and copies to its output (PointCloud::SelectByIndex).
inline std::vector<Index> farthest_point_indices(const open3d::geometry::PointCloud& input, std::size_t m)
{
  open3d::geometry::PointCloud tagged = input;
  tagged.colors_.resize(input.points_.size());
  for (std::size_t i = 0; i < input.points_.size(); ++i)
    tagged.colors_[i] = Eigen::Vector3d(double(i), 0., 0.);
  const std::shared_ptr<open3d::geometry::PointCloud> out = farthest_points(tagged, m);
  if (out->colors_.size() != out->points_.size())
    throw std::runtime_error("Open3D's FarthestPointDownSample did not copy the colours");
  std::vector<Index> kept;
  for (std::size_t i = 0; i < out->points_.size(); ++i)
  {
    const Index index = Index(out->colors_[i].x());
    if (input.points_[index] != out->points_[i])
      throw std::runtime_error("Open3D's FarthestPointDownSample: a colour does not match its point");
    kept.push_back(index);
  }
  std::sort(kept.begin(), kept.end());
  return kept;
}

// The two methods, in that order, for the cloud of `context`.
inline std::vector<Method> methods(Method_context& context)
{
  const Cloud& cloud = context.cloud;
  const std::shared_ptr<const open3d::geometry::PointCloud> input = to_open3d(cloud);
  const std::size_t n = cloud.points.size();
  const double small = cloud.diagonal * 1e-7, large = cloud.diagonal;
  std::vector<Method> result;
  {
    Method voxel;
    voxel.name = "Open3D voxel down-sample";
    voxel.family = "Open3D";
    voxel.select = [&context, input, small, large](std::size_t m) {
      return reach_count_new_points(context, m, small, large,
                                    [&](double edge) { return voxel_down_sample(*input, edge); });
    };
    voxel.timed_run = [input](std::size_t, const std::vector<double>& edge) {
      return timed([&] { voxel_down_sample(*input, edge[0]); });
    };
    result.push_back(voxel);
  }
  {
    Method farthest;
    farthest.name = "Open3D farthest point";
    farthest.family = "Open3D";
    farthest.select = [&cloud, input](std::size_t m) { return subset(cloud, farthest_point_indices(*input, m)); };
    farthest.timed_run = [input](std::size_t m, const std::vector<double>&) {
      return timed([&] { farthest_points(*input, m); });
    };
    // n m distance updates at about 8.5e-10 s each on the machine of the
    // RESULTS (measured by --quick runs on the replica, the lion and
    // timing_1M, 8.1e-10 to 8.5e-10): cells predicted above the limit are
    // skipped, like WLOP's
    farthest.predicted_seconds = [n](std::size_t m) { return 8.5e-10 * double(n) * double(m); };
    farthest.searches_parameters = false;
    result.push_back(farthest);
  }
  return result;
}

} // namespace open3d_peers
} // namespace bench

#endif // ENTROPY_SIMPLIFICATION_BENCH_PEERS_OPEN3D_H
