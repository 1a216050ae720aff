// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// bench_noise: on noisy inputs, what the point-to-plane error rewards.
//
//   bench_noise --data DIR [--out DIR] [--smoke]
//
// On the benchmark's noisy inputs (the two replicas of Experiment I, whose
// surface is known, and the real scans) at 10, 20 and 50% kept, runs the
// default mode and every peer library's simplifier that was built, as
// run_benchmark does, and measures for each:
// - the point-to-plane error (bench::measure, as in quality.csv);
// - the kept noise: the RMS distance of the kept points to the input's own
//   surface there, the PCA plane of their 30 nearest input points, over the
//   same RMS for every input point. Above 1, a method keeps the points
//   farthest from the surface; below 1, those nearest it (or, moving
//   points, it smooths them);
// - on the replicas, the same ratio against the true surface (the board's
//   plane and the ball's sphere), and the noise floor: the input points' RMS
//   distance to the true surface over the diagonal, the point-to-plane
//   error of a simplification whose planes were the true surface.
// Prints the section "Point-to-plane error and noise" of RESULTS.md and
// writes every cell to noise.csv. With --smoke: the replicas divided in size
// by 16, CGAL's peers only.
// Invariants checked (the program fails otherwise): each method keeps
// exactly the count asked for, or what its parameter search reached; the
// replica's input noise against the true surface lies between 0.8 and 1.0
// times its range noise, which runs along the scanner's rays.

#include "bench_arguments.h"
#include "bench_common.h"
#include "bench_inputs.h"
#include "bench_machine.h"
#include "bench_methods.h"
#include "bench_metrics.h"
#include "bench_peers.h"

#include <CGAL/Entropy_simplification/experiment_I_replica.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace ES = CGAL::Entropy_simplification;
using bench::Cloud;
using bench::Point;

namespace {

const double ratios[] = { 10., 20., 50. };

// The input points that span the surface around a point: enough that the
// plane averages the noise of many, few enough that it stays local.
constexpr unsigned int surface_points = 30;

// Methods predicted to take longer are skipped, as run_benchmark skips them.
constexpr double skip_seconds = 100.;

// The default mode and every peer library's simplifier that was built.
std::vector<bench::Method> methods_for(bench::Method_context& context, bool smoke)
{
  std::vector<bench::Method> methods;
  for (bench::Method& m : bench::all_methods(context))
    if (m.name == "package default" || m.family == "CGAL")
      methods.push_back(std::move(m));
  if (smoke)
    return methods;
  const std::vector<bench::Method> peers = bench::optional_peer_methods(context);
  methods.insert(methods.end(), peers.begin(), peers.end());
  return methods;
}

// The RMS distance of `points` to the input's surface near each: the PCA
// plane of its nearest input points.
double rms_to_input_surface(const bench::Method_context& context, const std::vector<Point>& points)
{
  std::vector<double> squared(points.size());
  tbb::parallel_for(std::size_t(0), points.size(), [&](std::size_t i) {
    thread_local std::vector<bench::Index> near;
    context.tree.nearest(points[i], surface_points, near);
    const auto [normal, centroid] = bench::pca_plane(context.cloud.points, near);
    const Point& p = points[i];
    squared[i] = CGAL::square(normal.dot(Eigen::Vector3d(p.x(), p.y(), p.z()) - centroid));
  });
  double sum = 0.;
  for (double s : squared)
    sum += s;
  return std::sqrt(sum / double(points.size()));
}

// The RMS distance of `points` to the replica's true surface: the nearer of
// the board's plane and the ball's sphere.
double rms_to_replica_surface(const std::vector<Point>& points)
{
  const ES::Experiment_I_setup setup;
  const Point centre(setup.sphere_x, setup.sphere_y, setup.board_distance - setup.sphere_gap);
  double sum = 0.;
  for (const Point& p : points)
  {
    const double to_board = p.z() - setup.board_distance;
    const double to_ball = std::sqrt(CGAL::squared_distance(p, centre)) - setup.sphere_radius;
    sum += (std::min)(to_board * to_board, to_ball * to_ball);
  }
  return std::sqrt(sum / double(points.size()));
}

struct Cell
{
  std::string input, method;
  double ratio;
  std::size_t count;
  double point_to_plane, kept_noise, true_kept_noise, floor; // the last two NaN but on the replicas
};

// Spearman's rank correlation of two equally long series (no ties expected
// among measured distances; ties take the order they come in).
double rank_correlation(const std::vector<double>& a, const std::vector<double>& b)
{
  const auto ranks = [](const std::vector<double>& v) {
    std::vector<std::size_t> order(v.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return v[i] < v[j]; });
    std::vector<double> rank(v.size());
    for (std::size_t r = 0; r < order.size(); ++r)
      rank[order[r]] = double(r);
    return rank;
  };
  const std::vector<double> ra = ranks(a), rb = ranks(b);
  const double n = double(a.size());
  double d2 = 0.;
  for (std::size_t i = 0; i < a.size(); ++i)
    d2 += (ra[i] - rb[i]) * (ra[i] - rb[i]);
  return 1. - 6. * d2 / (n * (n * n - 1.));
}

std::vector<Cell> measure_input(const bench::Benchmark_input& in, bool smoke, std::ostream& log)
{
  const bool replica = !in.is_scan;
  const Cloud cloud = in.make();
  bench::Method_context context(cloud);
  const double input_noise = rms_to_input_surface(context, cloud.points);
  double true_input_noise = std::numeric_limits<double>::quiet_NaN();
  if (replica)
  {
    true_input_noise = rms_to_replica_surface(cloud.points);
    const double range_noise = in.name == "replica_2mm" ? 0.002 : 0.0012;
    if (!(true_input_noise > 0.8 * range_noise && true_input_noise <= range_noise))
      throw std::logic_error(in.name + ": the input's noise against the true surface, " +
                             std::to_string(true_input_noise) + ", is not within 0.8 to 1 times the range noise");
  }
  std::vector<Cell> cells;
  for (bench::Method& method : methods_for(context, smoke))
    for (double ratio : ratios)
    {
      const std::size_t m = ES::internal::kept_count_from_percentage(cloud.points.size(), ratio);
      if (method.predicted_seconds && method.predicted_seconds(m) > skip_seconds)
        continue;
      const bench::Selection s = method.select(m);
      if (s.points.size() != m && s.points.size() != s.count_before_trim)
        throw std::logic_error(in.name + ", " + method.name + ": kept " + std::to_string(s.points.size()) +
                               " points for " + std::to_string(m));
      const bench::Quality q = bench::measure(cloud, s, replica, ES::Options());
      Cell c{ in.name, method.name, ratio, s.points.size(), q.point_to_plane,
              rms_to_input_surface(context, s.points) / input_noise, std::numeric_limits<double>::quiet_NaN(),
              true_input_noise / cloud.diagonal };
      if (replica)
        c.true_kept_noise = rms_to_replica_surface(s.points) / true_input_noise;
      cells.push_back(c);
      log << in.name << ' ' << ratio << "% " << method.name << ": point-to-plane " << q.point_to_plane
          << ", kept noise " << c.kept_noise << '\n';
    }
  return cells;
}

void write_csv(const std::string& file, const std::vector<Cell>& cells)
{
  std::ofstream out(file);
  out.precision(10);
  out << "input,method,percent,count,point_to_plane,kept_noise,true_kept_noise,noise_floor\n";
  for (const Cell& c : cells)
    out << c.input << ",\"" << c.method << "\"," << c.ratio << ',' << c.count << ',' << c.point_to_plane << ','
        << c.kept_noise << ',' << c.true_kept_noise << ',' << c.floor << '\n';
  if (!out)
    throw std::runtime_error("cannot write " + file);
}

// One row per cell: the peer of least point-to-plane error, the default
// mode, the peer that keeps the least noise, and the rank correlation.
void write_section(std::ostream& md, const std::vector<Cell>& cells)
{
  md << "## Point-to-plane error and noise\n\n"
     << "Produced by `bench_noise --data DIR --out DIR` (`bash benchmark/run.sh` runs it; every cell in "
        "`results/noise.csv`). On the noisy inputs, the default mode and every peer library's simplifier at 10, "
        "20 and 50% kept (WLOP where predicted to take at most 100 s, as in the quality tables). *Kept noise*: "
        "the RMS distance of the kept points to the input's surface around them (the PCA plane of their "
        << surface_points
        << " nearest input points), over the same for all input points: above 1, a method keeps the points "
           "farthest from the surface (or, on a scan, near its edges and corners, which also lie off such "
           "planes); below 1, those nearest it, or, moving points, it smooths them. On the replicas, the true "
           "surface is known: *truth* is the same ratio against it, and the *floor* is the input points' RMS "
           "distance to it over the diagonal, the point-to-plane error a simplification would have if its "
           "planes were the true surface. A likely cause of errors below the floor, not tested: an input point "
           "is measured against a plane through kept points near it, which, when they lie off the surface, "
           "tend to lie on its side. *Correlation*: Spearman's, across the methods of "
           "the cell, between the point-to-plane error and the kept noise (-1: the noisier the kept points, the "
           "lower the error).\n\n"
     << "| input | kept | floor | best peer on point-to-plane: error / floor, kept noise (truth) | default mode: "
        "error / best peer's, kept noise (truth) | least kept noise among peers: error / best peer's, kept noise "
        "(truth) | correlation |\n|---|---:|---:|---|---|---|---:|\n";
  const auto noise = [](const Cell& c) {
    return bench::fixed(c.kept_noise, 2) + (std::isnan(c.true_kept_noise) ? "" : " (" + bench::fixed(c.true_kept_noise, 2) + ")");
  };
  int cells_shown = 0, best_noisier = 0, negative = 0, replica_cells = 0;
  // on the replicas, the best peers below the floor that keep noisier points than the input's: their
  // errors over the floor and their kept noise against the true surface
  std::vector<double> below_floor_errors, below_floor_noises;
  for (std::size_t first = 0; first < cells.size();)
  {
    std::size_t last = first;
    while (last < cells.size() && cells[last].input == cells[first].input)
      ++last;
    for (double ratio : ratios)
    {
      std::vector<const Cell*> peers;
      const Cell* ours = nullptr;
      for (std::size_t i = first; i < last; ++i)
        if (cells[i].ratio == ratio && cells[i].method == "package default")
          ours = &cells[i];
        else if (cells[i].ratio == ratio)
          peers.push_back(&cells[i]);
      if (!ours || peers.empty())
        continue;
      const Cell* best = *std::min_element(peers.begin(), peers.end(), [](const Cell* a, const Cell* b) {
        return a->point_to_plane < b->point_to_plane;
      });
      const Cell* quietest = *std::min_element(peers.begin(), peers.end(), [](const Cell* a, const Cell* b) {
        return a->kept_noise < b->kept_noise;
      });
      std::vector<double> errors{ ours->point_to_plane }, noises{ ours->kept_noise };
      for (const Cell* p : peers)
      {
        errors.push_back(p->point_to_plane);
        noises.push_back(p->kept_noise);
      }
      const double correlation = rank_correlation(errors, noises);
      ++cells_shown;
      best_noisier += best->kept_noise > 1.;
      negative += correlation < 0.;
      replica_cells += !std::isnan(best->floor);
      if (best->point_to_plane < best->floor && best->true_kept_noise > 1.)
      {
        below_floor_errors.push_back(best->point_to_plane / best->floor);
        below_floor_noises.push_back(best->true_kept_noise);
      }
      md << "| " << ours->input << " | " << ratio << "% | "
         << (std::isnan(ours->floor) ? std::string("") : bench::fixed(ours->floor, 6)) << " | " << best->method
         << ": " << (std::isnan(best->floor) ? std::string("") : bench::fixed(best->point_to_plane / best->floor, 3) + ", ")
         << noise(*best) << " | " << bench::fixed(ours->point_to_plane / best->point_to_plane, 3) << ", "
         << noise(*ours) << " | " << quietest->method << ": "
         << bench::fixed(quietest->point_to_plane / best->point_to_plane, 3) << ", " << noise(*quietest) << " | "
         << bench::fixed(correlation, 2) << " |\n";
    }
    first = last;
  }
  md << "\nIn " << best_noisier << " of " << cells_shown
     << " cells the peer of least point-to-plane error keeps more noise than the input has (kept noise above 1); "
        "the correlation is negative in "
     << negative << " of " << cells_shown << ".";
  const auto range = [](const std::vector<double>& v, int digits) {
    const auto [low, high] = std::minmax_element(v.begin(), v.end());
    return bench::fixed(*low, digits) + " to " + bench::fixed(*high, digits);
  };
  if (!below_floor_errors.empty())
    md << " On the replicas, the peer of least error is below the noise floor with kept points noisier than the "
          "input in "
       << below_floor_errors.size() << " of " << replica_cells << " cells: " << range(below_floor_errors, 3)
       << " times the floor, its kept points " << range(below_floor_noises, 2)
       << " times as far from the true surface as the input points.";
  md << "\n\n";
}

} // namespace

int main(int argc, char** argv)
{
  const std::optional<bench::Section_arguments> arguments = bench::section_arguments(argc, argv, "bench_noise");
  if (!arguments)
    return 2;
  const auto& [data, out, quality, smoke] = *arguments;
  try
  {
    std::vector<Cell> cells;
    for (const bench::Benchmark_input& in : bench::benchmark_inputs(data, smoke ? 16 : 1))
      if (in.is_scan ? !smoke : in.name.rfind("replica", 0) == 0)
      {
        const std::vector<Cell> c = measure_input(in, smoke, std::cerr);
        cells.insert(cells.end(), c.begin(), c.end());
      }
    write_csv(out + "/noise.csv", cells);
    write_section(std::cout, cells);
  }
  catch (const std::exception& e)
  {
    std::cerr << "bench_noise: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
