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
//   farthest from the surface (or, on a scan, near edges and corners);
//   below 1, those nearest it (or, moving points, it smooths them);
// - on the replicas, the same ratio against the true surface (the board's
//   plane and the ball's sphere); the surface error, the input points' RMS
//   distance to the true surface over the diagonal, the point-to-plane error
//   of planes on it; and the point-to-plane error and the mean distance
//   once the kept points are moved onto it, their layout unchanged.
// Prints the section "Point-to-plane error and noise" of RESULTS.md and
// writes every cell to noise.csv. With --smoke: the replicas divided in size
// by 16, CGAL's peers only.
// Invariants checked (the program fails otherwise): each method keeps
// exactly the count asked for, or what its parameter search reached below
// it, at least 3 points; its measures are finite; the replica's input noise
// against the true surface lies between 0.8 and 1.0 times its range noise,
// which runs along the scanner's rays.

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

// `p` moved onto the replica's true surface, the nearer of the board's
// plane and the ball's sphere (13 cm apart).
Point onto_replica_surface(const Point& p)
{
  const ES::Experiment_I_setup setup;
  const Point centre(setup.sphere_x, setup.sphere_y, setup.board_distance - setup.sphere_gap);
  const double to_centre = std::sqrt(CGAL::squared_distance(p, centre));
  if (std::abs(p.z() - setup.board_distance) <= std::abs(to_centre - setup.sphere_radius))
    return Point(p.x(), p.y(), setup.board_distance);
  return centre + (p - centre) * (setup.sphere_radius / to_centre);
}

double rms_to_replica_surface(const std::vector<Point>& points)
{
  double sum = 0.;
  for (const Point& p : points)
    sum += CGAL::squared_distance(p, onto_replica_surface(p));
  return std::sqrt(sum / double(points.size()));
}

// The quality of the kept points once moved onto the replica's true
// surface: their layout unchanged, their offsets from it removed.
bench::Quality quality_on_surface(const Cloud& cloud, bench::Selection kept)
{
  for (Point& p : kept.points)
    p = onto_replica_surface(p);
  return bench::measure(cloud, kept, true, ES::Options());
}

struct Cell
{
  std::string input, method;
  double ratio;
  std::size_t count;
  double point_to_plane, mean, kept_noise;
  // on the replicas, NaN elsewhere: the kept noise against the true surface; the error and the mean
  // distance with the kept points on it; the error of planes on it (the input points' RMS distance to it)
  double true_kept_noise, point_to_plane_on_surface, mean_on_surface, surface_error;
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
  const Cloud cloud = in.make();
  const bool replica = cloud.range_noise > 0.;
  bench::Method_context context(cloud);
  const double input_noise = rms_to_input_surface(context, cloud.points);
  double true_input_noise = std::numeric_limits<double>::quiet_NaN();
  if (replica)
  {
    true_input_noise = rms_to_replica_surface(cloud.points);
    if (!(true_input_noise > 0.8 * cloud.range_noise && true_input_noise <= cloud.range_noise))
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
      const std::size_t kept = s.points.size();
      if (kept != m && !(kept == s.count_before_trim && kept > 2 && kept < m))
        throw std::logic_error(in.name + ", " + method.name + ": kept " + std::to_string(kept) + " points for " +
                               std::to_string(m));
      const double nan = std::numeric_limits<double>::quiet_NaN();
      const bench::Quality q = bench::measure(cloud, s, replica, ES::Options());
      Cell c{ in.name, method.name, ratio, kept, q.point_to_plane, q.mean,
              rms_to_input_surface(context, s.points) / input_noise, nan, nan, nan, nan };
      if (replica)
      {
        c.true_kept_noise = rms_to_replica_surface(s.points) / true_input_noise;
        const bench::Quality on_surface = quality_on_surface(cloud, s);
        c.point_to_plane_on_surface = on_surface.point_to_plane;
        c.mean_on_surface = on_surface.mean;
        c.surface_error = true_input_noise / cloud.diagonal;
      }
      for (double v : { c.point_to_plane, c.mean, c.kept_noise, replica ? c.true_kept_noise : 0.,
                        replica ? c.point_to_plane_on_surface : 0., replica ? c.mean_on_surface : 0. })
        if (!std::isfinite(v))
          throw std::logic_error(in.name + ", " + method.name + ": a measure is not finite");
      cells.push_back(c);
      log << in.name << ' ' << ratio << "% " << method.name << ": point-to-plane " << c.point_to_plane
          << ", kept noise " << c.kept_noise << '\n';
    }
  return cells;
}

void write_csv(const std::string& file, const std::vector<Cell>& cells)
{
  std::ofstream out(file);
  out.precision(10);
  out << "input,method,percent,count,point_to_plane,mean,kept_noise,true_kept_noise,point_to_plane_on_surface,"
         "mean_on_surface,surface_error\n";
  for (const Cell& c : cells)
    out << c.input << ",\"" << c.method << "\"," << c.ratio << ',' << c.count << ',' << c.point_to_plane << ','
        << c.mean << ',' << c.kept_noise << ',' << c.true_kept_noise << ',' << c.point_to_plane_on_surface << ','
        << c.mean_on_surface << ',' << c.surface_error << '\n';
  if (!out)
    throw std::runtime_error("cannot write " + file);
}

// A cell's rows: the default mode and the peers, by method.
struct Cell_rows
{
  const Cell* ours = nullptr;
  std::vector<const Cell*> peers;

  // the peer of least `measure`
  const Cell* least(double Cell::*measure) const
  {
    return *std::min_element(peers.begin(), peers.end(),
                             [measure](const Cell* a, const Cell* b) { return a->*measure < b->*measure; });
  }
  const Cell* peer(const std::string& method) const
  {
    for (const Cell* p : peers)
      if (p->method == method)
        return p;
    return nullptr;
  }
  // Spearman's, across the default mode and the peers, of the error and the kept noise
  double correlation() const
  {
    std::vector<double> errors{ ours->point_to_plane }, noises{ ours->kept_noise };
    for (const Cell* p : peers)
    {
      errors.push_back(p->point_to_plane);
      noises.push_back(p->kept_noise);
    }
    return rank_correlation(errors, noises);
  }
};

// The cells with a default-mode row and at least one peer, in input and ratio order.
std::vector<Cell_rows> cell_rows(const std::vector<Cell>& cells)
{
  std::vector<Cell_rows> rows;
  for (std::size_t first = 0; first < cells.size();)
  {
    std::size_t last = first;
    while (last < cells.size() && cells[last].input == cells[first].input)
      ++last;
    for (double ratio : ratios)
    {
      Cell_rows r;
      for (std::size_t i = first; i < last; ++i)
        if (cells[i].ratio == ratio && cells[i].method == "package default")
          r.ours = &cells[i];
        else if (cells[i].ratio == ratio)
          r.peers.push_back(&cells[i]);
      if (r.ours && !r.peers.empty())
        rows.push_back(r);
    }
    first = last;
  }
  return rows;
}

std::string range(const std::vector<double>& v, int digits)
{
  const auto [low, high] = std::minmax_element(v.begin(), v.end());
  return bench::fixed(*low, digits) + " to " + bench::fixed(*high, digits);
}

// On a replica: the error over the surface error, then with the kept points
// moved onto the true surface, and the kept noise against it.
std::string against_the_surface(const Cell* c, bool named = true)
{
  if (!c)
    return "";
  return (named ? c->method + ": " : std::string()) + bench::fixed(c->point_to_plane / c->surface_error, 3) + " → " +
         bench::fixed(c->point_to_plane_on_surface / c->surface_error, 3) + ", " + bench::fixed(c->true_kept_noise, 2);
}

void write_replica_table(std::ostream& md, const std::vector<Cell_rows>& rows)
{
  md << "### On the replicas, against the true surface\n\n"
     << "Each entry: the method's point-to-plane error over the *surface error* (the error of planes on the true "
        "surface: the input points' RMS distance to it over the diagonal), then (→) the same with its kept "
        "points moved onto the true surface, their layout unchanged, and the kept points' RMS distance to the "
        "true surface over the input points'.\n\n"
     << "| input | kept | surface error | peer of least error | default mode | CGAL random |\n"
        "|---|---:|---:|---|---|---|\n";
  std::vector<double> errors, on_surface, random_errors, random_noise, best_errors, best_noise;
  for (const Cell_rows& r : rows)
  {
    if (std::isnan(r.ours->surface_error))
      continue;
    const Cell* best = r.least(&Cell::point_to_plane);
    const Cell* random = r.peer("CGAL random");
    md << "| " << r.ours->input << " | " << r.ours->ratio << "% | " << bench::fixed(r.ours->surface_error, 6)
       << " | " << against_the_surface(best) << " | " << against_the_surface(r.ours, false) << " | "
       << against_the_surface(random, false) << " |\n";
    for (const Cell* c : r.peers)
    {
      errors.push_back(c->point_to_plane / c->surface_error);
      on_surface.push_back(c->point_to_plane_on_surface / c->surface_error);
    }
    errors.push_back(r.ours->point_to_plane / r.ours->surface_error);
    on_surface.push_back(r.ours->point_to_plane_on_surface / r.ours->surface_error);
    if (random)
    {
      random_errors.push_back(random->point_to_plane / random->surface_error);
      random_noise.push_back(random->true_kept_noise);
    }
    if (best->true_kept_noise > 1.)
    {
      best_errors.push_back(best->point_to_plane / best->surface_error);
      best_noise.push_back(best->true_kept_noise);
    }
  }
  if (errors.empty())
    return;
  md << "\nOver every method and cell, the error is " << range(errors, 3)
     << " times the surface error, and with the kept points on the true surface " << range(on_surface, 3) << ".";
  if (!random_errors.empty())
    md << " CGAL's random simplification, whose kept points lie as far from the surface as the input's ("
       << range(random_noise, 2) << " times), is " << range(random_errors, 3) << " times it.";
  if (!best_errors.empty())
    md << " In " << best_errors.size()
       << " cells the peer of least error keeps points farther from the surface than the input's ("
       << range(best_noise, 2) << " times), and is " << range(best_errors, 3) << " times it.";
  md << "\n\n";
}

// The mean distance on the replicas, as it is and with every method's kept
// points on the true surface: what their layout gives, without the noise.
void write_replica_mean_table(std::ostream& md, const std::vector<Cell_rows>& rows)
{
  md << "### The mean distance on the replicas\n\n"
     << "The default mode's mean distance over the best peer's, as in the quality tables, then with every "
        "method's kept points moved onto the true surface, their layout unchanged (the input unchanged).\n\n"
     << "| input | kept | peer of least mean distance | default mode / that peer | on the surface: peer of least "
        "mean distance | default mode / that peer |\n|---|---:|---|---:|---|---:|\n";
  int cells = 0, ahead = 0, ahead_on_surface = 0;
  for (const Cell_rows& r : rows)
  {
    if (std::isnan(r.ours->surface_error))
      continue;
    const Cell* best = r.least(&Cell::mean);
    const Cell* best_on_surface = r.least(&Cell::mean_on_surface);
    const double ratio = r.ours->mean / best->mean;
    const double on_surface = r.ours->mean_on_surface / best_on_surface->mean_on_surface;
    ++cells;
    ahead += ratio <= 1.;
    ahead_on_surface += on_surface <= 1.;
    md << "| " << r.ours->input << " | " << r.ours->ratio << "% | " << best->method << " | " << bench::fixed(ratio, 3)
       << " | " << best_on_surface->method << " | " << bench::fixed(on_surface, 3) << " |\n";
  }
  if (cells > 0)
    md << "\nThe default mode's mean distance is at most the best peer's in " << ahead << " of " << cells
       << " cells, and in " << ahead_on_surface << " with the kept points on the true surface.\n\n";
}

void write_all_inputs_table(std::ostream& md, const std::vector<Cell_rows>& rows)
{
  md << "### On every noisy input, against the input's own surface\n\n"
     << "*Kept noise*: the RMS distance of the kept points to the PCA plane of their " << surface_points
     << " nearest input points, over the same for every input point; on a scan, edges and corners can raise it "
        "too. *ρ*: Spearman's correlation, across the cell's methods (the default mode and the peers that ran), of "
        "the point-to-plane error and the kept noise.\n\n"
     << "| input | kept | peer of least error: kept noise | default mode: error / that peer's, kept noise | "
        "peer of least kept noise: error / least, kept noise | ρ |\n|---|---:|---|---|---|---:|\n";
  int noisier = 0, negative = 0;
  for (const Cell_rows& r : rows)
  {
    const Cell* best = r.least(&Cell::point_to_plane);
    const Cell* quietest = r.least(&Cell::kept_noise);
    const double rho = r.correlation();
    noisier += best->kept_noise > 1.;
    negative += rho < 0.;
    md << "| " << r.ours->input << " | " << r.ours->ratio << "% | " << best->method << ": "
       << bench::fixed(best->kept_noise, 2) << " | " << bench::fixed(r.ours->point_to_plane / best->point_to_plane, 3)
       << ", " << bench::fixed(r.ours->kept_noise, 2) << " | " << quietest->method << ": "
       << bench::fixed(quietest->point_to_plane / best->point_to_plane, 3) << ", "
       << bench::fixed(quietest->kept_noise, 2) << " | " << bench::fixed(rho, 2) << " |\n";
  }
  md << "\nThe peer of least error has a kept noise above 1 in " << noisier << " of " << rows.size()
     << " cells; ρ is below 0 in " << negative << " of " << rows.size() << ".\n\n";
}

void write_section(std::ostream& md, const std::vector<Cell>& cells)
{
  md << "## Point-to-plane error and noise\n\n"
     << "Produced by `bench_noise --data DIR --out DIR` (`bash benchmark/run.sh` runs it; every cell in "
        "`results/noise.csv`). On the noisy inputs, the default mode and every peer library's simplifier at 10, "
        "20 and 50% kept (WLOP where predicted to take at most 100 s, as in the quality tables; CGAL's hierarchy "
        "keeps fewer points than asked at 50%, as there). On a noisy input, the point-to-plane error can fall "
        "below that of planes on the true surface; a likely mechanism, not measured directly: planes through kept "
        "points near an input point follow the noise there. These tables measure how much, and how it goes "
        "with the noise the kept points keep.\n\n";
  const std::vector<Cell_rows> rows = cell_rows(cells);
  write_replica_table(md, rows);
  write_replica_mean_table(md, rows);
  write_all_inputs_table(md, rows);
}

} // namespace

int main(int argc, char** argv)
{
  return bench::run_section(argc, argv, "bench_noise", false, [](const bench::Section_arguments& arguments) {
    const auto& [data, out, quality, smoke] = arguments;
    std::vector<Cell> cells;
    for (const bench::Benchmark_input& in : bench::benchmark_inputs(data, smoke ? 16 : 1))
      if (bench::open_to_diagnosis(in) && (in.is_scan ? !smoke : in.name.rfind("replica", 0) == 0))
      {
        const std::vector<Cell> c = measure_input(in, smoke, std::cerr);
        cells.insert(cells.end(), c.begin(), c.end());
      }
    write_csv(out + "/noise.csv", cells);
    write_section(std::cout, cells);
  });
}
