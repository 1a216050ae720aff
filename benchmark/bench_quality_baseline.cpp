// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Issue 10's quality target: the default mode's mean distance and
// point-to-plane error in every cell (input and percentage) of a run's
// quality.csv, divided by the same cell at the commit where the work on
// speed started; each must stay at most 1.01.
//
//   bench_quality_baseline --baseline FILE --current FILE
//
// Both files are run_benchmark's quality.csv (or its default-mode rows).
// Prints the section "## Quality against the start of the speed work" of
// RESULTS.md. Exits with 1 when a file cannot be read or a cell of the
// baseline is missing from the current run.

#include "bench_csv.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

constexpr double bound = 1.01;
const char* const default_mode = "package default";

struct Cell_quality
{
  double mean = 0.;
  double point_to_plane = 0.;
};

// (input, percent) -> quality of the default mode, in file order.
using Cells = std::vector<std::pair<std::pair<std::string, double>, Cell_quality> >;

Cells read_default_mode(const std::string& file)
{
  std::ifstream in(file);
  std::string line;
  if (!std::getline(in, line))
    throw std::runtime_error("cannot read " + file);
  const std::vector<std::string> header = bench::fields_of(line);
  auto column = [&](const std::string& name) {
    const auto at = std::find(header.begin(), header.end(), name);
    if (at == header.end())
      throw std::runtime_error(file + " has no column " + name);
    return std::size_t(at - header.begin());
  };
  const std::size_t input = column("input"), method = column("method"), percent = column("percent"),
                    mean = column("mean"), plane = column("point_to_plane");
  Cells cells;
  while (std::getline(in, line))
  {
    const std::vector<std::string> f = bench::fields_of(line);
    if (f.size() == header.size() && f[method] == default_mode)
      cells.push_back({ { f[input], std::stod(f[percent]) }, { std::stod(f[mean]), std::stod(f[plane]) } });
  }
  if (cells.empty())
    throw std::runtime_error(file + " has no row of the " + default_mode + " method");
  return cells;
}

std::string fixed(double value, int digits)
{
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(digits);
  s << value;
  return s.str();
}

std::string verdict(double ratio) { return fixed(ratio, 4) + (ratio <= bound ? "" : " **over**"); }

} // namespace

int main(int argc, char** argv)
{
  std::string baseline_file, current_file;
  for (int a = 1; a + 1 < argc; a += 2)
  {
    const std::string flag = argv[a];
    if (flag == "--baseline")
      baseline_file = argv[a + 1];
    else if (flag == "--current")
      current_file = argv[a + 1];
  }
  if (baseline_file.empty() || current_file.empty())
  {
    std::cerr << "usage: bench_quality_baseline --baseline FILE --current FILE\n";
    return 2;
  }
  try
  {
    const Cells baseline = read_default_mode(baseline_file);
    std::map<std::pair<std::string, double>, Cell_quality> current;
    for (const auto& [cell, quality] : read_default_mode(current_file))
      current[cell] = quality;

    std::ostringstream table;
    std::size_t over = 0;
    double log_mean = 0., log_plane = 0.;
    double low_mean = HUGE_VAL, high_mean = 0., low_plane = HUGE_VAL, high_plane = 0.;
    for (const auto& [cell, before] : baseline)
    {
      const auto now = current.find(cell);
      if (now == current.end())
        throw std::runtime_error("the cell " + cell.first + " at " + fixed(cell.second, 0) + "% is not in " +
                                 current_file);
      const double mean = now->second.mean / before.mean;
      const double plane = now->second.point_to_plane / before.point_to_plane;
      over += (mean > bound || plane > bound) ? 1 : 0;
      log_mean += std::log(mean);
      log_plane += std::log(plane);
      low_mean = (std::min)(low_mean, mean);
      high_mean = (std::max)(high_mean, mean);
      low_plane = (std::min)(low_plane, plane);
      high_plane = (std::max)(high_plane, plane);
      table << "| " << cell.first << " | " << fixed(cell.second, 0) << "% | " << verdict(mean) << " | "
            << verdict(plane) << " |\n";
    }
    const double cells = double(baseline.size());
    std::cout << "## Quality against the start of the speed work\n\n"
              << "Produced by `bench_quality_baseline --baseline " << baseline_file << " --current " << current_file
              << "` (`bash benchmark/run.sh` runs it after `run_benchmark`). Issue 10 asks that the default "
                 "mode's mean distance and point-to-plane error stay within 1% of their values at the commit "
                 "where its work started, or improve, in every cell. The baseline is the default mode's rows of "
                 "the full run at 8df8f32, whose kept points were those of c85d6e2, the start of that work "
                 "(`results/quality_baseline.csv`); each figure below is this run's value over the baseline's.\n\n"
              << "- " << baseline.size() - over << " of " << baseline.size() << " cells within 1%; "
              << over << " over.\n"
              << "- Mean distance: " << fixed(low_mean, 4) << " to " << fixed(high_mean, 4)
              << ", geometric mean " << fixed(std::exp(log_mean / cells), 4) << ".\n"
              << "- Point-to-plane error: " << fixed(low_plane, 4) << " to " << fixed(high_plane, 4)
              << ", geometric mean " << fixed(std::exp(log_plane / cells), 4) << ".\n\n"
              << "| input | kept | mean distance / baseline | point-to-plane / baseline |\n|---|---:|---:|---:|\n"
              << table.str() << "\n";
    return 0;
  }
  catch (const std::exception& e)
  {
    std::cerr << "bench_quality_baseline: " << e.what() << "\n";
    return 1;
  }
}
