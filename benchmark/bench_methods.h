// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The simplification methods compared by the benchmark, behind one interface.

#ifndef ENTROPY_SIMPLIFICATION_BENCH_METHODS_H
#define ENTROPY_SIMPLIFICATION_BENCH_METHODS_H

#include "bench_baselines.h"
#include "bench_common.h"

#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>

#include <CGAL/grid_simplify_point_set.h>
#include <CGAL/hierarchy_simplify_point_set.h>
#include <CGAL/random_simplify_point_set.h>
#include <CGAL/wlop_simplify_and_regularize_point_set.h>

#include <functional>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

namespace bench {

namespace ES = CGAL::Entropy_simplification;
using Indexed_point = std::pair<Point, Index>;
using Point_of = CGAL::First_of_pair_property_map<Indexed_point>;

struct Timing
{
  double seconds = 0.;
  double normal_seconds = 0.; // of which normal estimation (or the package's initialisation)
};

struct Method
{
  std::string name;
  std::string family; // "package", "paper baseline", or a peer library: "CGAL", "PCL", "Open3D"
  // the method's result with exactly m points
  std::function<Selection(std::size_t m)> select;
  // for a progressive method: all points, ordered so that every prefix of at
  // least m_min points is the result for that count; one run serves every ratio
  std::function<std::vector<Index>(std::size_t m_min)> progressive_order;
  // one run for m points with the parameters `select` found, timed
  std::function<Timing(std::size_t m, const std::vector<double>& parameters)> timed_run;
  // a rough prediction of one run's seconds, to skip what would not fit
  std::function<double(std::size_t m)> predicted_seconds;
  // false when `select` finds no parameter for `timed_run`: a ratio that is
  // timed but not measured (timing_1M) then needs no `select` run (the
  // package's methods keep the run they always had)
  bool searches_parameters = true;
};

// A run of `f`, timed as a whole (no normal-estimation part).
inline Timing timed(const std::function<void()>& f)
{
  CGAL::Real_timer timer;
  timer.start();
  f();
  return Timing{ timer.time(), 0. };
}

inline std::vector<Indexed_point> indexed(const Cloud& cloud)
{
  std::vector<Indexed_point> v;
  for (Index i = 0; i < Index(cloud.points.size()); ++i)
    v.emplace_back(cloud.points[i], i);
  return v;
}

inline std::vector<Index> first_indices(const std::vector<Indexed_point>& v, std::size_t count)
{
  std::vector<Index> kept;
  for (std::size_t i = 0; i < count; ++i)
    kept.push_back(v[i].second);
  std::sort(kept.begin(), kept.end());
  return kept;
}

// The package with the given options. The paper's mode is progressive: one
// run serves every ratio. The default mode's radius depends on the target, so
// it runs for each ratio, as a user would call it.
inline Method package_method(const Cloud& cloud, const ES::Options& options, const std::string& name)
{
  auto run = [&cloud, options](std::size_t m, Timing* timing) {
    std::vector<Indexed_point> v = indexed(cloud);
    CGAL::Real_timer timer;
    double initialised = -1.;
    const std::function<bool(double)> watch = [&](double done) {
      if (done >= 0.25 && initialised < 0.)
        initialised = timer.time();
      return true;
    };
    timer.start();
    CGAL::entropy_simplify_point_set<CGAL::Parallel_if_available_tag>(
      v, 10, CGAL::parameters::number_of_output_points(m).point_map(Point_of()).callback(watch), options);
    if (timing)
      *timing = Timing{ timer.time(), initialised < 0. ? timer.time() : initialised };
    return v;
  };
  Method method;
  method.name = name;
  method.family = "package";
  if (options.mode == ES::Mode::paper)
    method.progressive_order = [run](std::size_t m_min) {
      const std::vector<Indexed_point> v = run(m_min, nullptr);
      std::vector<Index> order;
      for (const Indexed_point& e : v)
        order.push_back(e.second);
      return order;
    };
  else
    method.select = [run, &cloud](std::size_t m) { return subset(cloud, first_indices(run(m, nullptr), m)); };
  method.timed_run = [run](std::size_t m, const std::vector<double>&) {
    Timing t;
    run(m, &t);
    return t;
  };
  return method;
}

// Everything a cloud's methods share, built once.
struct Method_context
{
  explicit Method_context(const Cloud& c) : cloud(c), tree(c.points) {}

  const std::vector<double>& sigma()
  {
    if (m_sigma.empty())
    {
      m_sigma = surface_variation(cloud.points, tree, 10);
      m_by_decreasing_sigma.resize(cloud.points.size());
      std::iota(m_by_decreasing_sigma.begin(), m_by_decreasing_sigma.end(), Index(0));
      std::stable_sort(m_by_decreasing_sigma.begin(), m_by_decreasing_sigma.end(),
                       [&](Index a, Index b) { return m_sigma[a] > m_sigma[b]; });
    }
    return m_sigma;
  }
  const std::vector<Index>& by_decreasing_sigma()
  {
    sigma();
    return m_by_decreasing_sigma;
  }

  const Cloud& cloud;
  const Index_tree tree;

private:
  std::vector<double> m_sigma;
  std::vector<Index> m_by_decreasing_sigma;
};

// A result made of new points (WLOP's, voxel centroids): each labelled like
// its nearest input point.
inline Selection labelled_new_points(const Method_context& context, std::vector<Point> points)
{
  Selection s;
  s.points = std::move(points);
  s.count_before_trim = s.points.size();
  std::vector<Index> near;
  for (const Point& p : s.points)
  {
    context.tree.nearest(p, 1, near); // on unlabelled inputs too, as WLOP's timing always included it
    if (!context.cloud.labels.empty())
      s.labels.push_back(context.cloud.labels[near[0]]);
  }
  return s;
}

// reach_count for a method whose output is new points (at most one per input
// point) and whose count decreases as its size parameter grows: the same
// search, and the same trim applied to the positions of the output points;
// then one more run at the parameter found gives the points.
inline Selection reach_count_new_points(const Method_context& context, std::size_t m, double low, double high,
                                        const std::function<std::vector<Point>(double)>& run)
{
  const Selection positions = reach_count(context.cloud, m, low, high, [&](double p) {
    std::vector<Index> all(run(p).size());
    std::iota(all.begin(), all.end(), Index(0));
    return all;
  });
  const std::vector<Point> out = run(positions.parameters[0]);
  std::vector<Point> kept;
  for (Index i : positions.indices)
    kept.push_back(out[i]);
  Selection s = labelled_new_points(context, std::move(kept));
  s.count_before_trim = positions.count_before_trim;
  s.parameters = positions.parameters;
  return s;
}

inline std::vector<Method> all_methods(Method_context& context)
{
  const Cloud& cloud = context.cloud;
  const std::size_t n = cloud.points.size();
  const double small = cloud.diagonal * 1e-7, large = cloud.diagonal;
  std::vector<Method> methods;

  ES::Options default_mode, without_entropy, lowest, highest;
  without_entropy.feature_weight = 0.;
  lowest.mode = highest.mode = ES::Mode::paper;
  lowest.removal_order = ES::Removal_order::lowest_entropy_first;
  highest.removal_order = ES::Removal_order::highest_entropy_first;
  methods.push_back(package_method(cloud, default_mode, "package default"));
  methods.push_back(package_method(cloud, without_entropy, "default without entropy term"));
  methods.push_back(package_method(cloud, lowest, "entropy, lowest first"));
  methods.push_back(package_method(cloud, highest, "entropy, highest first"));

  auto timed = [](const std::function<void()>& f) {
    CGAL::Real_timer timer;
    timer.start();
    f();
    return Timing{ timer.time(), 0. };
  };

  // E1: exact by construction
  {
    Method e1;
    e1.name = "equidistant E1 (every i-th)";
    e1.family = "paper baseline";
    e1.select = [&cloud, n](std::size_t m) { return subset(cloud, every_ith(n, m)); };
    e1.timed_run = [timed, n](std::size_t m, const std::vector<double>&) { return timed([&] { every_ith(n, m); }); };
    methods.push_back(e1);
  }
  {
    Method e2;
    e2.name = "equidistant E2 (spacing)";
    e2.family = "paper baseline";
    e2.select = [&cloud, small, large](std::size_t m) {
      return reach_count(cloud, m, small, large, [&](double d) { return minimum_spacing(cloud.points, d); });
    };
    e2.timed_run = [timed, &cloud](std::size_t, const std::vector<double>& d) {
      return timed([&] { minimum_spacing(cloud.points, d[0]); });
    };
    methods.push_back(e2);
  }
  {
    Method sphere;
    sphere.name = "bounding sphere";
    sphere.family = "paper baseline";
    sphere.select = [&context, small, large](std::size_t m) {
      return reach_count(context.cloud, m, small, large,
                         [&](double r) { return ball_cover(context.cloud.points, context.tree, r); });
    };
    sphere.timed_run = [timed, &cloud](std::size_t, const std::vector<double>& r) {
      return timed([&] {
        const Index_tree tree(cloud.points);
        ball_cover(cloud.points, tree, r[0]);
      });
    };
    methods.push_back(sphere);
  }
  {
    Method curvature;
    curvature.name = "curvature";
    curvature.family = "paper baseline";
    curvature.select = [&context, small, large](std::size_t m) {
      return reach_count(context.cloud, m, small, large, [&](double d0) {
        return curvature_modulated(context.cloud.points, context.sigma(), context.by_decreasing_sigma(), m, d0);
      });
    };
    curvature.timed_run = [&cloud](std::size_t m, const std::vector<double>& d0) {
      CGAL::Real_timer timer;
      timer.start();
      const Index_tree tree(cloud.points);
      const std::vector<double> sigma = surface_variation(cloud.points, tree, 10);
      const double normals = timer.time();
      std::vector<Index> order(cloud.points.size());
      std::iota(order.begin(), order.end(), Index(0));
      std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) { return sigma[a] > sigma[b]; });
      curvature_modulated(cloud.points, sigma, order, m, d0[0]);
      return Timing{ timer.time(), normals };
    };
    methods.push_back(curvature);
  }
  {
    Method grid;
    grid.name = "CGAL grid";
    grid.family = "CGAL";
    auto run = [&cloud](double epsilon) {
      std::vector<Indexed_point> v = indexed(cloud);
      const auto it = CGAL::grid_simplify_point_set(v, epsilon, CGAL::parameters::point_map(Point_of()));
      return first_indices(v, std::size_t(it - v.begin()));
    };
    grid.select = [&cloud, small, large, run](std::size_t m) { return reach_count(cloud, m, small, large, run); };
    grid.timed_run = [timed, run](std::size_t, const std::vector<double>& epsilon) {
      return timed([&] { run(epsilon[0]); });
    };
    methods.push_back(grid);
  }
  {
    Method hierarchy;
    hierarchy.name = "CGAL hierarchy";
    hierarchy.family = "CGAL";
    auto run = [&cloud](double size, double variation) {
      std::vector<Indexed_point> v = indexed(cloud);
      const auto it = CGAL::hierarchy_simplify_point_set(
        v, CGAL::parameters::size((unsigned int)(size)).maximum_variation(variation).point_map(Point_of()));
      return first_indices(v, std::size_t(it - v.begin()));
    };
    // The cluster size is an integer: the count between two sizes is reached
    // by lowering the maximum variation (default 1/3) at the larger size.
    hierarchy.select = [&cloud, n, run](std::size_t m) {
      const double default_variation = 1. / 3.;
      Selection s = reach_count(cloud, m, 1., double(n), [&](double size) { return run(size, default_variation); },
                                true);
      if (s.count_before_trim > m + m / 1000)
      {
        const double size = s.parameters[0] + 1.;
        s = reach_count(cloud, m, 1e-4, default_variation, [&](double v) { return run(size, v); });
        s.parameters.insert(s.parameters.begin(), size);
      }
      else
        s.parameters.push_back(default_variation);
      return s;
    };
    hierarchy.timed_run = [timed, run](std::size_t, const std::vector<double>& p) {
      return timed([&] { run(p[0], p[1]); });
    };
    methods.push_back(hierarchy);
  }
  {
    Method wlop;
    wlop.name = "CGAL WLOP";
    wlop.family = "CGAL";
    // WLOP keeps floor(n p / 100) new points: p is chosen for exactly m.
    auto run = [&cloud, n](std::size_t m) {
      std::vector<Point> copy = cloud.points, out; // WLOP shuffles its input
      CGAL::wlop_simplify_and_regularize_point_set<CGAL::Parallel_if_available_tag>(
        copy, std::back_inserter(out), CGAL::parameters::select_percentage(100. * (double(m) + 0.5) / double(n)));
      return out;
    };
    wlop.select = [&context, run](std::size_t m) { return labelled_new_points(context, run(m)); };
    wlop.timed_run = [timed, run](std::size_t m, const std::vector<double>&) { return timed([&] { run(m); }); };
    // about 2.9e-8 s per input point and output point on the machine of the
    // RESULTS, measured on b9_training at 10%
    wlop.predicted_seconds = [n](std::size_t m) { return 2.9e-8 * double(n) * double(m); };
    methods.push_back(wlop);
  }
  {
    Method random;
    random.name = "CGAL random";
    random.family = "CGAL";
    auto run = [&cloud, n](std::size_t m) {
      std::vector<Indexed_point> v = indexed(cloud);
      const auto it = CGAL::random_simplify_point_set(v, 100. * (1. - (double(m) + 0.5) / double(n)));
      return first_indices(v, std::size_t(it - v.begin()));
    };
    random.select = [&cloud, run](std::size_t m) { return subset(cloud, run(m)); };
    random.timed_run = [timed, run](std::size_t m, const std::vector<double>&) { return timed([&] { run(m); }); };
    methods.push_back(random);
  }
  return methods;
}

} // namespace bench

#endif // ENTROPY_SIMPLIFICATION_BENCH_METHODS_H
