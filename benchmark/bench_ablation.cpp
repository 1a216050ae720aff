// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// bench_ablation: what each term of the default mode contributes (issue 12).
//
//   bench_ablation --data DIR --quality FILE [--out DIR] [--smoke]
//
// Runs the default mode on the benchmark's inputs of issue 12's targets at
// 10, 20 and 50% kept, with all its terms, then with each switched off in
// turn (Default_mode_terms; the entropy term is Options::feature_weight = 0),
// and measures each run as run_benchmark does (bench::measure). Prints the
// section "What each term contributes" of RESULTS.md: the ratios to the
// whole mode, geometric means over the cells of each group of inputs; the
// targets met against the peers of FILE, run_benchmark's quality.csv; and
// the labelled shares. Writes every cell to ablation.csv.
// Invariants checked on every cell (the program fails otherwise): each run
// keeps exactly the count asked for, distinct input points; with all the
// terms, the kept set is entropy_simplify_point_set's, and its mean distance
// that of FILE's row of the default mode in the same cell.

#include "bench_arguments.h"
#include "bench_csv.h"
#include "bench_common.h"
#include "bench_inputs.h"
#include "bench_metrics.h"
#include "bench_report.h"
#include "bench_targets_ahead.h"

#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>
#include <CGAL/Entropy_simplification/internal/simplify_points.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace ES = CGAL::Entropy_simplification;
namespace ESI = CGAL::Entropy_simplification::internal;
using bench::Cloud;
using bench::Input_role;
using bench::Point;

namespace {

const double ratios[] = { 10., 20., 50. };

// The mode with one term switched off (none for the first).
struct Variant
{
  std::string term;
  ES::Options options;
  ESI::Default_mode_terms terms;
};

std::vector<Variant> variants()
{
  std::vector<Variant> v(2);
  v[0].term = "none (the default mode)";
  v[1].term = "entropy term (`feature_weight` 0)";
  v[1].options.feature_weight = 0.;
  for (const ESI::Term_switched_off& off : ESI::each_term_switched_off())
    v.push_back({ off.term, ES::Options(), off.terms });
  return v;
}

// The inputs of run_benchmark's issue-12 section, in its order and roles;
// with `smoke`, its samples of meshes only, divided in size by 16.
std::vector<bench::Benchmark_input> inputs(const std::string& data, bool smoke)
{
  std::vector<bench::Benchmark_input> in = bench::benchmark_inputs(data, smoke ? 16 : 1);
  if (smoke)
    in.erase(std::remove_if(in.begin(), in.end(), [](const bench::Benchmark_input& i) { return i.is_scan; }),
             in.end());
  return in;
}

// The points a variant keeps, checked to be `m` distinct input points.
bench::Selection kept_by(const Cloud& cloud, std::size_t m, const Variant& v)
{
  ESI::Array<ESI::Working_point> input;
  for (const Point& p : cloud.points)
    input.emplace_back(p.x(), p.y(), p.z());
  const ESI::Array<ESI::Index> removed = ESI::removal_order_with_terms<CGAL::Parallel_tag>(input, 10, m, v.options, v.terms);
  std::vector<char> present(cloud.points.size(), 1);
  for (ESI::Index i : removed)
  {
    if (i >= present.size() || !present[i])
      throw std::logic_error(v.term + ": a removal is not an input point, or is removed twice");
    present[i] = 0;
  }
  bench::Selection s;
  for (std::size_t i = 0; i < present.size(); ++i)
    if (present[i])
    {
      s.points.push_back(cloud.points[i]);
      s.indices.push_back(bench::Index(i));
      if (!cloud.labels.empty())
        s.labels.push_back(cloud.labels[i]);
    }
  if (s.points.size() != m)
    throw std::logic_error(v.term + ": kept " + std::to_string(s.points.size()) + " points, not " + std::to_string(m));
  return s;
}

// The input positions entropy_simplify_point_set keeps, sorted.
std::vector<bench::Index> kept_by_the_public_call(const Cloud& cloud, std::size_t m)
{
  std::vector<bench::Index> idx(cloud.points.size());
  std::iota(idx.begin(), idx.end(), bench::Index(0));
  const auto end = CGAL::entropy_simplify_point_set<CGAL::Parallel_tag>(
    idx, 10, CGAL::parameters::number_of_output_points(m).point_map(CGAL::make_property_map(cloud.points)));
  std::vector<bench::Index> kept(idx.begin(), end);
  std::sort(kept.begin(), kept.end());
  return kept;
}

struct Cell
{
  std::string input;
  Input_role role;
  double ratio;
  std::size_t variant;
  bench::Quality quality;
  double share = 0.; // labelled share over the input's; 0 without labels
};

// The peers' figures of run_benchmark's quality.csv, by (input, ratio); NaN
// where the file has no such row.
struct Peer_figures
{
  double best_mean = std::numeric_limits<double>::infinity();
  double best_plane = std::numeric_limits<double>::infinity();
  double grid_hausdorff = std::numeric_limits<double>::quiet_NaN();
  double default_mean = std::numeric_limits<double>::quiet_NaN();

  bool complete() const
  {
    return best_mean < std::numeric_limits<double>::infinity() &&
           best_plane < std::numeric_limits<double>::infinity() && grid_hausdorff == grid_hausdorff &&
           default_mean == default_mean;
  }
};

std::map<std::pair<std::string, double>, Peer_figures> read_peers(const std::string& file)
{
  std::ifstream in(file);
  std::string line;
  if (!std::getline(in, line))
    throw std::runtime_error("cannot read run_benchmark's quality.csv from " + file);
  const std::vector<std::string> header = bench::fields_of(line);
  const auto column = [&](const std::string& name) {
    const auto at = std::find(header.begin(), header.end(), name);
    if (at == header.end())
      throw std::runtime_error(file + " has no column " + name);
    return std::size_t(at - header.begin());
  };
  const std::size_t input = column("input"), method = column("method"), family = column("family"),
                    percent = column("percent"), mean = column("mean"), hausdorff = column("max"),
                    plane = column("point_to_plane"), skipped = column("skipped");
  std::map<std::pair<std::string, double>, Peer_figures> peers;
  while (std::getline(in, line))
  {
    const std::vector<std::string> f = bench::fields_of(line);
    if (f.size() != header.size() || f[skipped] == "1")
      continue;
    Peer_figures& p = peers[{ f[input], std::stod(f[percent]) }];
    if (f[method] == "package default")
      p.default_mean = std::stod(f[mean]);
    if (f[method] == "CGAL grid")
      p.grid_hausdorff = std::stod(f[hausdorff]);
    if (bench::is_library_family(f[family]))
    {
      p.best_mean = (std::min)(p.best_mean, std::stod(f[mean]));
      p.best_plane = (std::min)(p.best_plane, std::stod(f[plane]));
    }
  }
  return peers;
}

const char* const role_names[] = { "tuned", "held out", "held out anew", "held out for the next term" };
constexpr int roles = 4;

// The geometric mean over a group's cells of a variant's metric over the
// whole mode's.
double geometric_ratio(const std::vector<Cell>& cells, std::size_t variant, Input_role role,
                       double (*metric)(const bench::Quality&))
{
  double log_sum = 0.;
  int count = 0;
  for (const Cell& c : cells)
    if (c.variant == variant && c.role == role)
      for (const Cell& whole : cells)
        if (whole.variant == 0 && whole.input == c.input && whole.ratio == c.ratio)
        {
          log_sum += std::log(metric(c.quality) / metric(whole.quality));
          ++count;
        }
  return count > 0 ? std::exp(log_sum / count) : 0.;
}

// The measures of the ratios, in the order of the tables and the chart.
using Metric = double (*)(const bench::Quality&);
const Metric metrics[3] = { [](const bench::Quality& q) { return q.mean; },
                            [](const bench::Quality& q) { return q.point_to_plane; },
                            [](const bench::Quality& q) { return q.max; } };
const char* const metric_names[3] = { "mean distance", "point-to-plane error", "Hausdorff distance" };

int cells_in_group(const std::vector<Cell>& cells, Input_role role)
{
  return int(std::count_if(cells.begin(), cells.end(), [&](const Cell& c) { return c.variant == 0 && c.role == role; }));
}

// The chart of the ratios (chart_ablation.png, which run.sh draws with
// gnuplot): per measure, each term's change without it, group by group.
void write_chart(const std::vector<Cell>& cells, const std::vector<Variant>& v, const std::string& dir)
{
  std::ofstream data(dir + "/ablation.dat");
  data << "# term, then (ratio - 1) in % for each measure: tuned, held out, held out anew, held out for the next term\n";
  for (std::size_t i = 1; i < v.size(); ++i)
  {
    data << '"' << v[i].term << '"';
    for (Metric metric : metrics)
      for (int role = 0; role < roles; ++role)
      {
        const double ratio = geometric_ratio(cells, i, Input_role(role), metric);
        data << ' ' << (ratio > 0. ? bench::fixed(100. * (ratio - 1.), 2) : std::string("NaN"));
      }
    data << '\n';
  }
  std::ofstream gp(dir + "/ablation.gp");
  gp << "set terminal pngcairo noenhanced size 1500,640 font 'sans,10'\nset output 'chart_ablation.png'\n"
        "set multiplot layout 1,3 title 'the default mode with one term switched off: the change against the "
        "whole mode, geometric mean over the cells (above 0: the term helps)'\n"
        "set style data histograms\nset style histogram clustered gap 1\nset style fill solid 0.8 border -1\n"
        "set grid ytics\nset xtics rotate by -40 scale 0 font 'sans,9'\nset bmargin 15\nset key outside bottom center horizontal\n"
        "set ylabel 'without the term / with it - 1 (%)'\n";
  // a group without cells (the smoke run's held-out scans) has no bars
  for (int m = 0; m < 3; ++m)
  {
    gp << "set title '" << metric_names[m] << "'\nplot ";
    bool first = true;
    for (int role = 0; role < roles; ++role)
      if (cells_in_group(cells, Input_role(role)) > 0)
      {
        gp << (first ? "'ablation.dat'" : ", ''") << " using " << 2 + roles * m + role << (first ? ":xtic(1)" : "")
           << " title '" << role_names[role] << "'";
        first = false;
      }
    gp << "\n";
  }
  gp << "unset multiplot\n";
  if (!data || !gp)
    throw std::runtime_error("cannot write the chart's files in " + dir);
}

void write_section(const std::vector<Cell>& cells, const std::vector<Variant>& v,
                   const std::map<std::pair<std::string, double>, Peer_figures>& peers, bool smoke)
{
  std::ostringstream md;
  // after the section before, whose last table has no blank line after it
  md << "\n## What each term contributes\n\n"
     << "Produced by `bench_ablation --data DIR --quality benchmark/results/quality.csv --out DIR`"
     << (smoke ? " --smoke (smaller inputs)" : "")
     << " (`bash benchmark/run.sh` runs it; every cell in `results/ablation.csv`). The default mode on the inputs "
        "of issue 12's targets at 10, 20 and 50% kept, with each of its terms switched off in turn, the others "
        "on: the entropy term, the greedy coverage elimination (switched off: weighted sample elimination), and the "
        "rest of the mode (see the manual). The "
        "program checks, in every cell, the count and that the kept points are distinct input points; with every "
        "term, it keeps what `entropy_simplify_point_set` keeps. Below 1 is better than the whole mode.\n\n"
     << "### Ratios to the whole mode\n\nGeometric mean over the cells of each group (tuned / held out / held out "
        "anew / held out for the next term) of the run without the term over the whole mode, drawn in `results/chart_ablation.png`.\n\n"
        "![ablation](results/chart_ablation.png)\n\n"
     << "| term switched off | mean distance | point-to-plane error | Hausdorff distance |\n|---|---|---|---|\n";
  for (std::size_t i = 1; i < v.size(); ++i)
  {
    md << "| " << v[i].term << " |";
    for (auto metric : metrics)
    {
      md << ' ';
      for (int role = 0; role < roles; ++role)
      {
        const double ratio = geometric_ratio(cells, i, Input_role(role), metric);
        md << (role ? " / " : "") << (ratio > 0. ? bench::fixed(ratio, 3) : "-");
      }
      md << " |";
    }
    md << "\n";
  }
  md << "\n### Issue 12's targets met\n\n";
  if (peers.empty())
    md << "Not counted: the smoke run's inputs are not those of `quality.csv`.\n";
  else
    md << "Cells (tuned / held out / held out anew / held out for the next term; "
       << cells_in_group(cells, Input_role::tuned) << " / " << cells_in_group(cells, Input_role::held_out) << " / "
       << cells_in_group(cells, Input_role::held_out_anew) << " / " << cells_in_group(cells, Input_role::held_out_next)
       << " in all) where the run keeps a mean distance at most " << bench::fixed(bench::ahead_mean, 1)
       << " times the best library peer's, a point-to-plane error at most "
       << bench::fixed(bench::ahead_point_to_plane, 1) << " times the best peer's, a Hausdorff distance at most "
       << bench::fixed(bench::ahead_hausdorff, 1)
       << " times grid's, the peers' figures taken from `quality.csv`.\n\n| term switched off | mean distance | "
          "point-to-plane error | Hausdorff distance |\n|---|---|---|---|\n";
  for (std::size_t i = 0; i < v.size() && !peers.empty(); ++i)
  {
    int met[3][roles] = {};
    for (const Cell& c : cells)
      if (c.variant == i)
      {
        const Peer_figures& p = peers.at({ c.input, c.ratio });
        const int r = int(c.role);
        met[0][r] += c.quality.mean <= bench::ahead_mean * p.best_mean;
        met[1][r] += c.quality.point_to_plane <= bench::ahead_point_to_plane * p.best_plane;
        met[2][r] += c.quality.max <= bench::ahead_hausdorff * p.grid_hausdorff;
      }
    md << "| " << v[i].term << " |";
    for (auto& metric : met)
    {
      md << ' ';
      for (int role = 0; role < roles; ++role)
        md << (role ? " / " : "") << metric[role];
      md << " |";
    }
    md << "\n";
  }
  md << "\n### Labelled shares\n\nThe share of kept points near fandisk's sharp edges, and on the replicas' ball, "
        "over the input's, with issue 12's targets.\n\n| term switched off |";
  const std::vector<std::pair<std::string, double> > shares = { { "fandisk", 10. },       { "fandisk", 20. },
                                                               { "fandisk", 50. },       { "replica_1.2mm", 10. },
                                                               { "replica_2mm", 10. } };
  for (const auto& s : shares)
  {
    const double bound = bench::share_bound(s.first, s.second);
    md << ' ' << s.first << ' ' << s.second << '%'
       << (bound > 0. ? " (≥ " + bench::fixed(bound, 1) + ")" : std::string(" (no target)")) << " |";
  }
  md << "\n|---|";
  for (std::size_t s = 0; s < shares.size(); ++s)
    md << "---|";
  md << "\n";
  for (std::size_t i = 0; i < v.size(); ++i)
  {
    md << "| " << v[i].term << " |";
    for (const auto& s : shares)
    {
      const auto c = std::find_if(cells.begin(), cells.end(), [&](const Cell& c) {
        return c.variant == i && c.input == s.first && c.ratio == s.second;
      });
      md << ' ' << (c == cells.end() ? std::string("-") : bench::fixed(c->share, 3)) << " |";
    }
    md << "\n";
  }
  std::cout << md.str() << "\n";
}

} // namespace

int main(int argc, char** argv)
{
  return bench::run_section(argc, argv, "bench_ablation", true, [](const bench::Section_arguments& arguments) {
    const auto& [data, out, quality_file, smoke] = arguments;
    // the smoke run's smaller inputs are not those of quality.csv: its peers
    // are read, not compared with
    const auto read = read_peers(quality_file);
    const auto peers = smoke ? std::map<std::pair<std::string, double>, Peer_figures>() : read;
    const std::vector<Variant> v = variants();
    std::vector<Cell> cells;
    std::ofstream csv(out + "/ablation.csv");
    if (!csv)
      throw std::runtime_error("cannot write " + out + "/ablation.csv");
    csv << "input,role,percent,term_off,count,mean,point_to_plane,max,share\n";
    csv.precision(10);
    for (const bench::Benchmark_input& input : inputs(data, smoke))
    {
      const Cloud cloud = input.make();
      const double labelled_share =
        double(std::count(cloud.labels.begin(), cloud.labels.end(), 1)) / double(cloud.points.size());
      for (double ratio : ratios)
      {
        const std::size_t m = ESI::kept_count_from_percentage(cloud.points.size(), ratio);
        for (std::size_t i = 0; i < v.size(); ++i)
        {
          const bench::Selection kept = kept_by(cloud, m, v[i]);
          if (i == 0)
          {
            std::vector<bench::Index> sorted = kept.indices;
            if (sorted != kept_by_the_public_call(cloud, m))
              throw std::logic_error(cloud.name + ": with every term, not what entropy_simplify_point_set keeps");
          }
          Cell c{ cloud.name, input.role, ratio, i, bench::measure(cloud, kept, false, ES::Options()), 0. };
          if (labelled_share > 0.)
            c.share = double(c.quality.labelled) / double(m) / labelled_share;
          if (i == 0 && !smoke)
          {
            const auto p = peers.find({ cloud.name, ratio });
            if (p == peers.end() || !p->second.complete())
              throw std::runtime_error(quality_file + " lacks the default mode, grid or a library peer for " +
                                       cloud.name + " at " + std::to_string(ratio) + "%");
            if (std::abs(c.quality.mean - p->second.default_mean) > 1e-9 * p->second.default_mean)
              throw std::logic_error(cloud.name + ": the whole mode's mean distance is not quality.csv's");
          }
          csv << cloud.name << ',' << role_names[int(input.role)] << ',' << ratio << ",\"" << v[i].term << "\","
              << m << ',' << c.quality.mean << ',' << c.quality.point_to_plane << ',' << c.quality.max << ','
              << c.share << "\n";
          if (!csv)
            throw std::runtime_error("cannot write " + out + "/ablation.csv");
          cells.push_back(c);
        }
        std::cerr << "bench_ablation: " << cloud.name << " at " << ratio << "%\n";
      }
    }
    write_section(cells, v, peers, smoke);
    write_chart(cells, v, out);
  });
}
