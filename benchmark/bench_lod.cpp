// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// bench_lod: levels of detail from one run (entropy_simplification_ranks).
//
//   bench_lod --data DIR [--out DIR] [--smoke]
//
// 1. Cost: the whole order, without a level and with its exact level at
//    1%, against one direct call of entropy_simplify_point_set to 1%, in
//    the same process, run after run, with Parallel_tag on the machine's
//    threads: the default mode on lion samples of 100k and 1M points, the
//    paper's mode on 100k. Each run's ratios, of the orders' times to the
//    direct call's just before, their medians and ranges: 11 runs at 100k,
//    where a default-mode call takes a quarter of a second, and the medians
//    of 21 runs of the same code moved by up to 0.07 from one process to the
//    next; 5 at 1M. Then the default mode again with Sequential_tag, 5 runs
//    at 100k and 3 at 1M: on this shared machine of two threads, one
//    thread's ratios at 1M ranged from 1.034 to 1.058 over 7 runs in a
//    scratch driver, where the two threads' ranged over up to 0.4, more
//    than the bound's margin.
// 2. Quality: the first m points by rank against a direct call to m, at 1,
//    5, 10, 20 and 50%, without a level and with the level at 1%: the mean
//    distance and the point-to-plane error (measure_simplification_quality)
//    of each, on the benchmark's inputs.
// Invariants checked on every run (the program fails otherwise): the ranks
// are a permutation, and a level's prefix is the direct call's kept set.
// Prints the tables of RESULTS.md's "Levels of detail" and writes lod.csv.

#include "bench_arguments.h"
#include "bench_common.h"
#include "bench_inputs.h"
#include "bench_machine.h"

#include <CGAL/Entropy_simplification/entropy_simplification_ranks.h>
#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>
#include <CGAL/Entropy_simplification/measure_simplification_quality.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace ES = CGAL::Entropy_simplification;
using bench::Point;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The points a direct call asking for m keeps.
template <typename ConcurrencyTag = CGAL::Parallel_tag>
std::vector<Point> direct_call(const std::vector<Point>& points, std::size_t m, const ES::Options& options)
{
  std::vector<Point> copy = points;
  const auto kept = CGAL::entropy_simplify_point_set<ConcurrencyTag>(
    copy, 10, CGAL::parameters::number_of_output_points(m), options);
  copy.erase(kept, copy.end());
  return copy;
}

// The input positions by rank, checked to be a permutation: the level
// `level`, or none when 0.
template <typename ConcurrencyTag = CGAL::Parallel_tag>
std::vector<std::size_t> order_by_rank(const std::vector<Point>& points, std::size_t level, const ES::Options& options)
{
  std::vector<std::size_t> ranks;
  if (level == 0)
    CGAL::entropy_simplification_ranks<ConcurrencyTag>(points, 10, std::back_inserter(ranks),
                                                       CGAL::parameters::default_values(), options);
  else
    CGAL::entropy_simplification_ranks<ConcurrencyTag>(
      points, 10, std::back_inserter(ranks), CGAL::parameters::number_of_output_points(level), options);
  const std::size_t n = points.size();
  if (ranks.size() != n)
    throw std::logic_error("not one rank per point");
  std::vector<std::size_t> order(n, n);
  for (std::size_t i = 0; i < n; ++i)
  {
    if (ranks[i] >= n || order[ranks[i]] != n)
      throw std::logic_error("the ranks are not a permutation");
    order[ranks[i]] = i;
  }
  return order;
}

std::vector<Point> first_by_rank(const std::vector<Point>& points, const std::vector<std::size_t>& order,
                                 std::size_t m)
{
  std::vector<Point> prefix;
  for (std::size_t r = 0; r < m; ++r)
    prefix.push_back(points[order[r]]);
  return prefix;
}

void require_same_set(std::vector<Point> a, std::vector<Point> b)
{
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  if (a != b)
    throw std::logic_error("the level's prefix is not the direct call's result");
}

struct Ratios
{
  double median, least, greatest;
};

struct Cost
{
  std::string mode, input;
  std::size_t n;
  bool parallel; // Parallel_tag, or Sequential_tag
  int runs;
  double direct, without_level, with_level; // median times
  Ratios without_level_ratio, with_level_ratio; // of each run

  // the threads column of the table and of lod.csv
  const char* threads() const { return parallel ? "all" : "1"; }
};

template <typename ConcurrencyTag = CGAL::Parallel_tag>
Cost measure_cost(const std::string& input, const std::vector<Point>& points, const ES::Options& options, int runs)
{
  const std::size_t level = ES::internal::kept_count_from_percentage(points.size(), 1.);
  std::vector<double> direct, without_level, with_level;
  for (int r = 0; r < runs; ++r)
  {
    auto start = std::chrono::steady_clock::now();
    const std::vector<Point> kept = direct_call<ConcurrencyTag>(points, level, options);
    direct.push_back(seconds_since(start));
    start = std::chrono::steady_clock::now();
    order_by_rank<ConcurrencyTag>(points, 0, options);
    without_level.push_back(seconds_since(start));
    start = std::chrono::steady_clock::now();
    const std::vector<std::size_t> order = order_by_rank<ConcurrencyTag>(points, level, options);
    with_level.push_back(seconds_since(start));
    require_same_set(first_by_rank(points, order, level), kept);
  }
  const auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  const auto ratios = [&](const std::vector<double>& order) {
    std::vector<double> r;
    for (std::size_t i = 0; i < order.size(); ++i)
      r.push_back(order[i] / direct[i]);
    return Ratios{ median(r), *std::min_element(r.begin(), r.end()), *std::max_element(r.begin(), r.end()) };
  };
  return { options.mode == ES::Mode::paper ? "paper" : "default",
           input,
           points.size(),
           std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value,
           runs,
           median(direct),
           median(without_level),
           median(with_level),
           ratios(without_level),
           ratios(with_level) };
}

struct Prefix_quality
{
  std::string input;
  bool with_level;
  double percentage, mean_ratio, plane_ratio;
};

// The percentages of the prefixes measured: issue 11's, and two below the
// level of 1%, where the kept points stand for the input points.
constexpr double prefix_percentages[] = { 0.1, 0.5, 1., 5., 10., 20., 50. };
constexpr std::size_t prefix_count = sizeof(prefix_percentages) / sizeof(prefix_percentages[0]);

// The prefixes' ratios at each percentage, without a level, then with the
// level at 1%.
std::vector<Prefix_quality> measure_quality(const bench::Cloud& cloud)
{
  const std::vector<Point>& points = cloud.points;
  const std::size_t level = ES::internal::kept_count_from_percentage(points.size(), 1.);
  const std::vector<std::size_t> orders[2] = { order_by_rank(points, 0, ES::Options()),
                                               order_by_rank(points, level, ES::Options()) };
  std::vector<Prefix_quality> rows;
  for (int with_level = 0; with_level < 2; ++with_level)
    for (double percentage : prefix_percentages)
    {
      const std::size_t m = ES::internal::kept_count_from_percentage(points.size(), percentage);
      const std::vector<Point> direct = direct_call(points, m, ES::Options()),
                               prefix = first_by_rank(points, orders[with_level], m);
      if (with_level && m == level)
        require_same_set(prefix, direct);
      const ES::Quality_report d = CGAL::measure_simplification_quality<CGAL::Parallel_tag>(points, direct);
      const ES::Quality_report p = CGAL::measure_simplification_quality<CGAL::Parallel_tag>(points, prefix);
      rows.push_back({ cloud.name, with_level == 1, percentage, p.mean_distance / d.mean_distance,
                       p.point_to_plane / d.point_to_plane });
    }
  return rows;
}

} // namespace

int main(int argc, char** argv)
{
  return bench::run_section(argc, argv, "bench_lod", false, [](const bench::Section_arguments& arguments) {
    const std::string &data = arguments.data, &out = arguments.out;
    const bool smoke = arguments.smoke;
    const std::string lion = data + "/meshes/lion.off";
    ES::Options paper;
    paper.mode = ES::Mode::paper;
    const std::size_t small = smoke ? 20000 : 100000, large = smoke ? 50000 : 1000000;
    const int small_runs = smoke ? 1 : 11, large_runs = smoke ? 1 : 5;
    const std::vector<Point> small_sample = bench::mesh_sample("lion", lion, small, false).points,
                             large_sample = bench::mesh_sample("lion", lion, large, false).points;
    std::vector<Cost> costs;
    costs.push_back(measure_cost("lion", small_sample, ES::Options(), small_runs));
    costs.push_back(measure_cost("lion", large_sample, ES::Options(), large_runs));
    costs.push_back(measure_cost("lion", small_sample, paper, small_runs));
    costs.push_back(measure_cost<CGAL::Sequential_tag>("lion", small_sample, ES::Options(), smoke ? 1 : 5));
    costs.push_back(measure_cost<CGAL::Sequential_tag>("lion", large_sample, ES::Options(), smoke ? 1 : 3));

    std::vector<bench::Cloud> clouds;
    clouds.push_back(bench::mesh_sample("lion", lion, smoke ? 30000 : 457124, false));
    clouds.push_back(bench::mesh_sample("fandisk", data + "/meshes/fandisk.off", smoke ? 20000 : 200000, false));
    for (const char* name : { "b9_training.ply", "hippo1.ply", "radar.xyz" })
      clouds.push_back(bench::scan(std::string(name).substr(0, std::string(name).find('.')),
                                   data + "/points_3/" + name));
    std::vector<Prefix_quality> quality;
    for (const bench::Cloud& cloud : clouds)
      for (const Prefix_quality& q : measure_quality(cloud))
        quality.push_back(q);

    std::ofstream csv(out + "/lod.csv");
    csv << "table,mode,input,points,level,percentage,direct_s,ranks_s,ratio,threads\n";
    std::printf("## Levels of detail\n\nProduced by `bench_lod --data DIR --out DIR`%s (`bash benchmark/run.sh` "
                "runs it after \"Scale\"); the figures are also in `results/lod.csv`.\n\nMachine: %s.\n\n"
                "### Cost of the whole order\n\n`CGAL::entropy_simplification_ranks(points, 10, ranks)`, "
                "without a level, and with `number_of_output_points(L)`, against one "
                "`CGAL::entropy_simplify_point_set(points, 10, number_of_output_points(L))`, L = 1%% of the "
                "points, run after run in one process, on `meshes/lion.off` sampled uniformly in area (seed "
                "2018), with `Parallel_tag` on the machine's threads, then with `Sequential_tag`. Times: "
                "medians; ratios: the median, and the range, of each run's ratio to the direct call just before "
                "it (*runs* runs: on 100,000 points a direct call of the default mode takes a quarter of a "
                "second, and the medians of 21 runs of the same code moved by up to 0.07 from one process to "
                "the next). On this shared machine, one thread's ratios vary far less from run to run (their "
                "ranges below). Issue 11's target: at most 1.1x.\n\n"
                "| mode | input | points | threads | runs | direct call to 1%% | whole order, no level | ratio | "
                "whole order, level 1%% | ratio |\n|---|---|---:|---|---:|---:|---:|---:|---:|---:|\n",
                smoke ? " --smoke" : "", bench::machine_description().c_str());
    for (const Cost& c : costs)
    {
      std::printf("| %s | %s | %zu | %s | %d | %.3f s | %.3f s | %.3f (%.3f to %.3f) | %.3f s | %.3f (%.3f to "
                  "%.3f) |\n",
                  c.mode.c_str(), c.input.c_str(), c.n, c.threads(), c.runs, c.direct, c.without_level,
                  c.without_level_ratio.median, c.without_level_ratio.least, c.without_level_ratio.greatest,
                  c.with_level, c.with_level_ratio.median, c.with_level_ratio.least, c.with_level_ratio.greatest);
      csv << "cost," << c.mode << "," << c.input << "," << c.n << ",none,1," << c.direct << "," << c.without_level
          << "," << c.without_level_ratio.median << "," << c.threads() << "\n";
      csv << "cost," << c.mode << "," << c.input << "," << c.n << ",1,1," << c.direct << "," << c.with_level << ","
          << c.with_level_ratio.median << "," << c.threads() << "\n";
    }
    std::printf("\n### Prefixes against direct calls\n\nThe first m points by rank, without a level (every "
                "level boundary relocated) and with the level at 1%%, against `CGAL::entropy_simplify_point_set` "
                "asking for m, in the default mode: the ratio of their mean distance and of their point-to-plane "
                "error (`CGAL::measure_simplification_quality`). With the level at 1%%, the prefix at 1%% is the "
                "direct call's result, and the longer ones are not relocated. lion (457,124 points), fandisk "
                "(200,000) and b9_training were tuned on, hippo1 and radar held out (see [Inputs](#inputs)). "
                "Issue 11's target: at most 1.05 at 1, 5, 10, 20 and 50%%. Below the level of 1%%, each kept "
                "point stands for the input points nearest it (see `CGAL::entropy_simplification_ranks`): 0.1 and "
                "0.5%% show what that costs, without a target.\n\n| input | level | ratio |");
    for (double percentage : prefix_percentages)
      std::printf(" %g%% |", percentage);
    std::printf("\n|---|---|---|");
    for (std::size_t j = 0; j < prefix_count; ++j)
      std::printf("---:|");
    std::printf("\n");
    for (std::size_t i = 0; i < quality.size(); i += prefix_count)
      for (int which = 0; which < 2; ++which)
      {
        const bool first_of_input = which == 0 && !quality[i].with_level;
        std::printf("| %s | %s | %s |", first_of_input ? quality[i].input.c_str() : "",
                    which == 0 ? (quality[i].with_level ? "1%" : "none") : "",
                    which == 0 ? "mean distance" : "point-to-plane");
        for (std::size_t j = i; j < i + prefix_count; ++j)
        {
          const double r = which == 0 ? quality[j].mean_ratio : quality[j].plane_ratio;
          std::printf(" %.3f |", r);
          csv << "quality," << (which == 0 ? "mean_distance" : "point_to_plane") << "," << quality[j].input << ",,"
              << (quality[j].with_level ? "1" : "none") << "," << quality[j].percentage << ",,," << r << ",all\n";
        }
        std::printf("\n");
      }
  });
}
