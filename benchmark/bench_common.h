// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Types and helpers shared by the benchmark: clouds, selections, timing, and
// the rule that brings a method with a size parameter to an exact count.

#ifndef ENTROPY_SIMPLIFICATION_BENCH_COMMON_H
#define ENTROPY_SIMPLIFICATION_BENCH_COMMON_H

#include <CGAL/Entropy_simplification/experiment_I_replica.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace bench {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Index = std::uint32_t;
using Random = CGAL::Entropy_simplification::internal::Portable_random;

// An input of the benchmark. `labels` is empty, or holds one label per point:
// board 0 / ball 1 on the replica, 1 near a sharp edge on fandisk.
struct Cloud
{
  std::string name;
  std::string description;
  std::vector<Point> points;
  std::vector<int> labels;
  double diagonal = 0.;
  double range_noise = 0.; // a replica's: the standard deviation of its range noise
};

// What a method keeps: new points for WLOP, otherwise a subset of the input
// (`indices` then lists the kept input points). `labels` are those of the
// kept points, or of the nearest input point for new points.
struct Selection
{
  std::vector<Point> points;
  std::vector<int> labels;
  std::vector<Index> indices;
  std::size_t count_before_trim = 0; // what the method's parameters reached
  std::vector<double> parameters;    // the values the search found, if any
};

inline double bounding_box_diagonal(const std::vector<Point>& points)
{
  const CGAL::Bbox_3 box = CGAL::bbox_3(points.begin(), points.end());
  return std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                   CGAL::square(box.zmax() - box.zmin()));
}

inline Selection subset(const Cloud& cloud, std::vector<Index> indices)
{
  Selection s;
  s.count_before_trim = indices.size();
  for (Index i : indices)
  {
    s.points.push_back(cloud.points[i]);
    if (!cloud.labels.empty())
      s.labels.push_back(cloud.labels[i]);
  }
  s.indices = std::move(indices);
  return s;
}

// The documented rule for a method that overshoots: the surplus is removed
// uniformly at random (partial Fisher-Yates, portable generator, seed 1), the
// others keep their order.
inline std::vector<Index> trim_to(std::vector<Index> kept, std::size_t m)
{
  if (kept.size() <= m)
    return kept;
  Random random(1);
  std::vector<std::size_t> order(kept.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  const std::size_t surplus = kept.size() - m;
  std::vector<char> dropped(kept.size(), 0);
  for (std::size_t i = 0; i < surplus; ++i)
  {
    std::swap(order[i], order[i + random.below(order.size() - i)]);
    dropped[order[i]] = 1;
  }
  std::vector<Index> result;
  for (std::size_t i = 0; i < kept.size(); ++i)
    if (!dropped[i])
      result.push_back(kept[i]);
  return result;
}

// For a method whose number of kept points decreases as its size parameter
// grows: searches the parameter in [low, high] for a count in [m, 1.001 m],
// by interpolation in log-log space safeguarded by bisection, then trims the
// surplus. `run(parameter)` returns the kept indices.
inline Selection reach_count(const Cloud& cloud, std::size_t m, double low, double high,
                             const std::function<std::vector<Index>(double)>& run, bool integer = false)
{
  auto evaluate = [&](double p) { return run(integer ? std::round(p) : p); };
  std::vector<Index> best = evaluate(low); // the largest count, >= m by the caller's choice of low
  double best_parameter = low;
  std::size_t low_count = best.size(), high_count = evaluate(high).size();
  for (int iteration = 0; iteration < 30 && best.size() > m + m / 1000; ++iteration)
  {
    if (integer && high - low <= 1.)
      break;
    double p;
    if (high_count > 0 && low_count > m && high_count < m)
    {
      // counts scale like a power of the parameter: interpolate in log-log
      const double t = (std::log(double(low_count)) - std::log(double(m))) /
                       (std::log(double(low_count)) - std::log(double(high_count)));
      p = std::exp(std::log(low) + t * (std::log(high) - std::log(low)));
      if (!(p > low && p < high) || iteration % 3 == 2)
        p = std::sqrt(low * high);
    }
    else
      p = std::sqrt(low * high);
    if (integer)
      p = std::round(p);
    if (p <= low || p >= high)
      p = integer ? std::floor((low + high) / 2.) : std::sqrt(low * high);
    if (p <= low || p >= high)
      break;
    std::vector<Index> kept = evaluate(p);
    if (kept.size() >= m)
    {
      low = p;
      low_count = kept.size();
      best = std::move(kept);
      best_parameter = p;
    }
    else
    {
      high = p;
      high_count = kept.size();
    }
  }
  Selection s = subset(cloud, trim_to(best, m));
  s.count_before_trim = best.size();
  s.parameters = { integer ? std::round(best_parameter) : best_parameter };
  return s;
}

// The median of `repeats` timings of `f`, in seconds.
inline double median_seconds(int repeats, const std::function<void()>& f)
{
  std::vector<double> times;
  for (int r = 0; r < repeats; ++r)
  {
    CGAL::Real_timer timer;
    timer.start();
    f();
    times.push_back(timer.time());
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

} // namespace bench

#endif // ENTROPY_SIMPLIFICATION_BENCH_COMMON_H
