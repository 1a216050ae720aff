// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// PCL's simplifiers as peers of the benchmark (built with ES_BENCH_WITH_PCL,
// when CMake finds PCL 1.13): VoxelGrid, UniformSampling, and
// NormalSpaceSampling on normals from NormalEstimation. Each is brought to
// exactly m points like CGAL's simplifiers (bench_methods.h).

#ifndef ENTROPY_SIMPLIFICATION_BENCH_PEERS_PCL_H
#define ENTROPY_SIMPLIFICATION_BENCH_PEERS_PCL_H

#include "bench_methods.h"

#include <pcl/common/common.h>
#include <pcl/features/normal_3d.h>
#include <pcl/filters/normal_space.h>
#include <pcl/filters/uniform_sampling.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/pcl_config.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>

#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace bench {
namespace pcl_peers {

using Pcl_points = pcl::PointCloud<pcl::PointXYZ>;

inline std::string description()
{
  return std::string("PCL ") + PCL_VERSION_PRETTY + " (VoxelGrid, UniformSampling, NormalSpaceSampling)";
}

// The input in PCL's single-precision points. The cloud is first translated
// so that its bounding box is centred on the origin, as a PCL user would do
// with georeferenced data: b9_training's coordinates are near 600,000 m,
// where a float's step is 6 cm, which VoxelGrid's centroids (accumulated in
// float) would add to every distance. Converted once per input, not timed:
// a PCL user's cloud is already in this form.
struct Input
{
  explicit Input(const Cloud& cloud) : points(new Pcl_points)
  {
    const CGAL::Bbox_3 box = CGAL::bbox_3(cloud.points.begin(), cloud.points.end());
    offset = Vector((box.xmin() + box.xmax()) / 2., (box.ymin() + box.ymax()) / 2., (box.zmin() + box.zmax()) / 2.);
    points->reserve(cloud.points.size());
    for (const Point& p : cloud.points)
      points->push_back(pcl::PointXYZ(float(p.x() - offset.x()), float(p.y() - offset.y()), float(p.z() - offset.z())));
  }

  Point original(const pcl::PointXYZ& p) const
  {
    return Point(double(p.x) + offset.x(), double(p.y) + offset.y(), double(p.z) + offset.z());
  }

  Pcl_points::Ptr points;
  Vector offset;
};

// VoxelGrid and UniformSampling index voxels with 32-bit integers. Below
// this edge the grid over the bounding box has more than 2^31 - 1 voxels:
// VoxelGrid then warns and returns its input unchanged, or, when its own
// check's 64-bit product of the three divisions overflows too (at 1e-7 times
// the diagonal on the lion), goes on with overflowed indices, as
// UniformSampling, which has no check, always does. The searches start here.
// The divisions are VoxelGrid's, in float, plus one for the floors of the
// bounds (which the grids' indices use, not the check); their product in
// double, which does not overflow (bisection in log space).
inline double smallest_voxel(const Pcl_points& points, double diagonal)
{
  Eigen::Vector4f lo, hi;
  pcl::getMinMax3D(points, lo, hi);
  auto accepted = [&](double edge) {
    const float inverse = 1.f / float(edge);
    double voxels = 1.;
    for (int axis = 0; axis < 3; ++axis)
      voxels *= double(std::int64_t((hi[axis] - lo[axis]) * inverse) + 2);
    return voxels <= double(std::numeric_limits<std::int32_t>::max());
  };
  double low = diagonal * 1e-7, high = diagonal;
  if (accepted(low))
    return low;
  for (int i = 0; i < 60; ++i)
  {
    const double mid = std::sqrt(low * high);
    (accepted(mid) ? high : low) = mid;
  }
  return high;
}

// VoxelGrid: the centroid of the input points in each voxel of edge `edge`,
// new points (like WLOP's).
inline std::vector<Point> voxel_grid(const Input& input, double edge)
{
  pcl::VoxelGrid<pcl::PointXYZ> grid;
  grid.setInputCloud(input.points);
  grid.setLeafSize(float(edge), float(edge), float(edge));
  Pcl_points out;
  grid.filter(out);
  std::vector<Point> result;
  result.reserve(out.size());
  for (const pcl::PointXYZ& p : out)
    result.push_back(input.original(p));
  return result;
}

// UniformSampling keeps, in each voxel, the input point nearest the voxel's
// centre: a subset of the input. PCL 1.13 returns the points, not their
// indices; every other input point is reported removed exactly once, so the
// kept indices are the complement of the removed ones.
inline std::vector<Index> uniform_sampling(const Input& input, double edge)
{
  pcl::UniformSampling<pcl::PointXYZ> sampling(true); // true: report the removed indices
  sampling.setInputCloud(input.points);
  sampling.setRadiusSearch(edge); // the voxel's edge, despite the name
  Pcl_points out;
  sampling.filter(out);
  std::vector<char> removed(input.points->size(), 0);
  for (const auto i : *sampling.getRemovedIndices())
    removed[std::size_t(i)] = 1;
  std::vector<Index> kept;
  for (Index i = 0; i < Index(removed.size()); ++i)
    if (!removed[i])
      kept.push_back(i);
  return kept;
}

// What a user calls for the timing: the same filter, returning its points.
inline void uniform_sampling_points(const Input& input, double edge)
{
  pcl::UniformSampling<pcl::PointXYZ> sampling;
  sampling.setInputCloud(input.points);
  sampling.setRadiusSearch(edge);
  Pcl_points out;
  sampling.filter(out);
}

// Normals as PCL estimates them: NormalEstimation (sequential) on the 10
// nearest neighbours from its kd-tree, oriented towards its default viewpoint,
// the origin (the centre of the bounding box after the translation).
// NormalSpaceSampling's bin lookup reads past its histogram on a NaN normal
// (NormalEstimation gives one for a degenerate neighbourhood): such a point
// gets +z, and a message says how many there were.
inline pcl::PointCloud<pcl::Normal>::Ptr normals(const Input& input, bool report = false)
{
  pcl::NormalEstimation<pcl::PointXYZ, pcl::Normal> estimation;
  estimation.setInputCloud(input.points);
  estimation.setSearchMethod(pcl::search::KdTree<pcl::PointXYZ>::Ptr(new pcl::search::KdTree<pcl::PointXYZ>));
  estimation.setKSearch(10);
  pcl::PointCloud<pcl::Normal>::Ptr result(new pcl::PointCloud<pcl::Normal>);
  estimation.compute(*result);
  std::size_t invalid = 0;
  for (pcl::Normal& n : *result)
    if (!std::isfinite(n.normal_x) || !std::isfinite(n.normal_y) || !std::isfinite(n.normal_z))
    {
      n.normal_x = n.normal_y = 0.f;
      n.normal_z = 1.f;
      ++invalid;
    }
  if (report && invalid > 0)
    std::cerr << " [PCL NormalEstimation: " << invalid << " NaN normals set to +z]" << std::flush;
  return result;
}

// NormalSpaceSampling (Rusinkiewicz and Levoy 2001): normals binned on a
// 4 x 4 x 4 grid of their coordinates (as in PCL's own test), then one point
// drawn at random from each non-empty bin in turn until m are drawn: exactly
// m input points. Seed 1, like the benchmark's other random choices.
inline std::vector<Index> normal_space_sampling(const Input& input, const pcl::PointCloud<pcl::Normal>::Ptr& normals,
                                                std::size_t m)
{
  pcl::NormalSpaceSampling<pcl::PointXYZ, pcl::Normal> sampling;
  sampling.setInputCloud(input.points);
  sampling.setNormals(normals);
  sampling.setBins(4, 4, 4);
  sampling.setSeed(1);
  sampling.setSample((unsigned int)(m));
  pcl::Indices indices;
  sampling.filter(indices);
  std::vector<Index> kept(indices.begin(), indices.end());
  std::sort(kept.begin(), kept.end());
  return kept;
}

// The three methods, in that order, for the cloud of `context`.
inline std::vector<Method> methods(Method_context& context)
{
  const Cloud& cloud = context.cloud;
  const auto input = std::make_shared<const Input>(cloud);
  const double small = smallest_voxel(*input->points, cloud.diagonal), large = cloud.diagonal;
  std::vector<Method> result;
  {
    Method grid;
    grid.name = "PCL voxel grid";
    grid.family = "PCL";
    grid.select = [&context, input, small, large](std::size_t m) {
      return reach_count_new_points(context, m, small, large, [&](double edge) { return voxel_grid(*input, edge); });
    };
    grid.timed_run = [input](std::size_t, const std::vector<double>& edge) {
      return timed([&] { voxel_grid(*input, edge[0]); });
    };
    result.push_back(grid);
  }
  {
    Method uniform;
    uniform.name = "PCL uniform sampling";
    uniform.family = "PCL";
    uniform.select = [&cloud, input, small, large](std::size_t m) {
      return reach_count(cloud, m, small, large, [&](double edge) { return uniform_sampling(*input, edge); });
    };
    uniform.timed_run = [input](std::size_t, const std::vector<double>& edge) {
      return timed([&] { uniform_sampling_points(*input, edge[0]); });
    };
    result.push_back(uniform);
  }
  {
    Method normal_space;
    normal_space.name = "PCL normal space sampling";
    normal_space.family = "PCL";
    // the normals serve every ratio of the quality runs; the timed runs
    // estimate them again, and count them, as the package counts its own
    auto cached = std::make_shared<pcl::PointCloud<pcl::Normal>::Ptr>();
    normal_space.select = [&cloud, input, cached](std::size_t m) {
      if (!*cached)
        *cached = normals(*input, true);
      return subset(cloud, normal_space_sampling(*input, *cached, m));
    };
    normal_space.timed_run = [input](std::size_t m, const std::vector<double>&) {
      CGAL::Real_timer timer;
      timer.start();
      const pcl::PointCloud<pcl::Normal>::Ptr n = normals(*input);
      const double normal_seconds = timer.time();
      normal_space_sampling(*input, n, m);
      return Timing{ timer.time(), normal_seconds };
    };
    normal_space.searches_parameters = false;
    result.push_back(normal_space);
  }
  return result;
}

} // namespace pcl_peers
} // namespace bench

#endif // ENTROPY_SIMPLIFICATION_BENCH_PEERS_PCL_H
