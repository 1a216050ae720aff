// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The paper's three baselines, which it does not define. The definitions
// chosen here are those of benchmark/README.md.

#ifndef ENTROPY_SIMPLIFICATION_BENCH_BASELINES_H
#define ENTROPY_SIMPLIFICATION_BENCH_BASELINES_H

#include "bench_common.h"

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>

#include <Eigen/Eigenvalues>

#include <boost/iterator/counting_iterator.hpp>

#include <array>
#include <numeric>
#include <unordered_map>
#include <vector>

namespace bench {

// A Kd tree over the indices of a point vector.
struct Index_tree
{
  using Point_map = CGAL::Pointer_property_map<Point>::const_type;
  using Traits = CGAL::Search_traits_adapter<Index, Point_map, CGAL::Search_traits_3<Kernel> >;
  using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;
  using Tree = Search::Tree;
  using Distance = Search::Distance;
  using Sphere = CGAL::Fuzzy_sphere<Traits>;

  explicit Index_tree(const std::vector<Point>& points)
    : map(CGAL::make_property_map(points)),
      tree(boost::counting_iterator<Index>(0), boost::counting_iterator<Index>(Index(points.size())),
           Tree::Splitter(), Traits(map))
  {
    tree.build();
  }

  // the k nearest points of `query`, nearest first
  void nearest(const Point& query, unsigned int k, std::vector<Index>& out) const
  {
    out.clear();
    Search search(tree, query, k, 0., true, Distance(map));
    for (auto it = search.begin(); it != search.end(); ++it)
      out.push_back(it->first);
  }

  void within(const Point& center, double radius, std::vector<Index>& out) const
  {
    out.clear();
    tree.search(std::back_inserter(out), Sphere(center, radius, 0., Traits(map)));
  }

  Point_map map;
  Tree tree;
};

// Kept points in a hash grid, for "is there a kept point within d of p"
// with d at most the cell size.
class Spacing_grid
{
public:
  Spacing_grid(const std::vector<Point>& points, double cell) : m_points(points), m_cell(cell) {}

  bool has_point_within(const Point& p, double d) const
  {
    const std::array<long, 3> c = cell_of(p);
    for (long x = c[0] - 1; x <= c[0] + 1; ++x)
      for (long y = c[1] - 1; y <= c[1] + 1; ++y)
        for (long z = c[2] - 1; z <= c[2] + 1; ++z)
        {
          const auto found = m_cells.find(key(x, y, z));
          if (found == m_cells.end())
            continue;
          for (Index i : found->second)
            if (CGAL::squared_distance(p, m_points[i]) < d * d)
              return true;
        }
    return false;
  }

  void insert(Index i)
  {
    const std::array<long, 3> c = cell_of(m_points[i]);
    m_cells[key(c[0], c[1], c[2])].push_back(i);
  }

private:
  std::array<long, 3> cell_of(const Point& p) const
  {
    return { long(std::floor(p.x() / m_cell)), long(std::floor(p.y() / m_cell)), long(std::floor(p.z() / m_cell)) };
  }
  static std::uint64_t key(long x, long y, long z)
  {
    return (std::uint64_t(x) * 73856093u) ^ (std::uint64_t(y) * 19349663u) ^ (std::uint64_t(z) * 83492791u);
  }

  const std::vector<Point>& m_points;
  double m_cell;
  // cells colliding in the hash share a list, which only costs distance tests
  std::unordered_map<std::uint64_t, std::vector<Index> > m_cells;
};

// E1, every i-th point in acquisition (input) order: indices floor(i N / m).
inline std::vector<Index> every_ith(std::size_t n, std::size_t m)
{
  std::vector<Index> kept;
  for (std::size_t i = 0; i < m; ++i)
    kept.push_back(Index(double(i) * double(n) / double(m)));
  return kept;
}

// E2, minimum-spacing thinning: points visited in input order, each kept
// when no kept point lies within d.
inline std::vector<Index> minimum_spacing(const std::vector<Point>& points, double d)
{
  Spacing_grid grid(points, d);
  std::vector<Index> kept;
  for (Index i = 0; i < Index(points.size()); ++i)
    if (!grid.has_point_within(points[i], d))
    {
      grid.insert(i);
      kept.push_back(i);
    }
  return kept;
}

// Bounding sphere, read as ball-cover clustering: seeds in input order; the
// points not yet assigned within r of a seed form its cluster; the member
// nearest the cluster's centroid is kept.
inline std::vector<Index> ball_cover(const std::vector<Point>& points, const Index_tree& tree, double r)
{
  std::vector<char> assigned(points.size(), 0);
  std::vector<Index> kept, inside, cluster;
  for (Index seed = 0; seed < Index(points.size()); ++seed)
  {
    if (assigned[seed])
      continue;
    tree.within(points[seed], r, inside);
    cluster.clear();
    for (Index i : inside)
      if (!assigned[i])
      {
        assigned[i] = 1;
        cluster.push_back(i);
      }
    if (!assigned[seed])
    {
      assigned[seed] = 1;
      cluster.push_back(seed);
    }
    double x = 0., y = 0., z = 0.;
    for (Index i : cluster)
    {
      x += points[i].x();
      y += points[i].y();
      z += points[i].z();
    }
    const Point centroid(x / double(cluster.size()), y / double(cluster.size()), z / double(cluster.size()));
    kept.push_back(*std::min_element(cluster.begin(), cluster.end(), [&](Index a, Index b) {
      return CGAL::squared_distance(points[a], centroid) < CGAL::squared_distance(points[b], centroid);
    }));
  }
  std::sort(kept.begin(), kept.end());
  return kept;
}

// Surface variation sigma = l0 / (l0 + l1 + l2) of each point and its k
// nearest neighbours (Pauly, Gross and Kobbelt 2002).
inline std::vector<double> surface_variation(const std::vector<Point>& points, const Index_tree& tree, unsigned int k)
{
  std::vector<double> sigma(points.size());
  std::vector<Index> neighbors;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    tree.nearest(points[i], k + 1, neighbors);
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (Index j : neighbors)
      mean += Eigen::Vector3d(points[j].x(), points[j].y(), points[j].z());
    mean /= double(neighbors.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (Index j : neighbors)
    {
      const Eigen::Vector3d d = Eigen::Vector3d(points[j].x(), points[j].y(), points[j].z()) - mean;
      covariance += d * d.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(covariance, Eigen::EigenvaluesOnly);
    const Eigen::Vector3d l = solver.eigenvalues().cwiseMax(0.);
    sigma[i] = l.sum() > 0. ? l(0) / l.sum() : 0.;
  }
  return sigma;
}

// Curvature-based, with spacing modulated by curvature (as CloudCompare's
// subsampling modulated by a scalar field): the ceil(m / 4) points of highest
// surface variation are kept; the others, visited by decreasing variation,
// are kept when no kept point lies within d0 (1 - sigma / tau), tau being the
// variation of the last point kept unconditionally.
inline std::vector<Index> curvature_modulated(const std::vector<Point>& points, const std::vector<double>& sigma,
                                              const std::vector<Index>& by_decreasing_sigma, std::size_t m, double d0)
{
  const std::size_t unconditional = (std::min)(points.size(), (m + 3) / 4);
  const double tau = sigma[by_decreasing_sigma[unconditional - 1]];
  Spacing_grid grid(points, d0);
  std::vector<Index> kept;
  for (std::size_t rank = 0; rank < points.size(); ++rank)
  {
    const Index i = by_decreasing_sigma[rank];
    const double spacing = rank < unconditional || tau <= 0. ? 0. : d0 * (1. - (std::min)(1., sigma[i] / tau));
    if (rank < unconditional || !grid.has_point_within(points[i], spacing))
    {
      grid.insert(i);
      kept.push_back(i);
    }
  }
  std::sort(kept.begin(), kept.end());
  return kept;
}

} // namespace bench

#endif // ENTROPY_SIMPLIFICATION_BENCH_BASELINES_H
