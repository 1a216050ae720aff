// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Scale: the time and peak memory of the package from 100,000 to 10,000,000
// points, against one sequential CGAL::pca_estimate_normals pass (k = 10) on
// the same points in the same run.
//
//   bench_scale --data DIR --work DIR [--program PATH] [--sizes N1,N2,...]
//               [--runs R] [--out DIR] [--smoke]
//
// The inputs are area-uniform samples of `meshes/lion.off` (DIR is CGAL's
// demo data), the benchmark's sampler with seed 2018, coordinates rounded to
// float and written once to WORK/lion_N.ply (binary, float x y z). For each
// size, each case runs in a process of its own:
//   - pca: CGAL::IO::read_PLY, then pca_estimate_normals<Sequential_tag>;
//   - the library, default mode with 2 threads (Parallel_tag) and with 1
//     (Sequential_tag), and the paper's mode with 2 threads: the call
//     entropy_simplify_point_set(points, 10, select_percentage(10)) on a
//     std::vector of Epick points, normal estimation included;
//   - the program, when --program is given: `entropy_simplify lion_N.ply
//     OUT.ply --ratio 0.1 --binary -q`, read and write included.
// Times are medians of R runs (3 by default) up to 1,000,000 points, one run
// above; the runs of one size go in rounds, each case once per round.
// Peak: the process's maximum resident set size, input included.
// Invariants, checked after the peak is taken: exactly the count kept, the
// range a permutation of the input, the same kept points with 1 and 2
// threads, the program's output holding the count. The exit status is
// nonzero when one fails.
//
// With --out: OUT/RESULTS.md gets the section "## Scale", OUT/results gets
// scale.csv, and scale.dat and scale.gp (gnuplot) for the chart scale.png.
// --smoke: 20,000 and 50,000 points, one run, for the test suite.

#include "bench_inputs.h"
#include "bench_machine.h"
#include "bench_process.h"

#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>

#include <CGAL/IO/PLY.h>
#include <CGAL/pca_estimate_normals.h>
#include <CGAL/property_map.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using bench::fixed;
using bench::Point;
using bench::thousands;
using bench::Vector;
namespace ES = CGAL::Entropy_simplification;

constexpr unsigned int k = 10;
constexpr double percentage = 10.;

enum class Kind { pca, default_2, default_1, paper_2, program };
const Kind all_kinds[] = { Kind::pca, Kind::default_2, Kind::default_1, Kind::paper_2, Kind::program };

const char* kind_name(Kind kind)
{
  switch (kind)
  {
  case Kind::pca: return "read + pca pass";
  case Kind::default_2: return "default, 2 threads";
  case Kind::default_1: return "default, 1 thread";
  case Kind::paper_2: return "paper, 2 threads";
  case Kind::program: return "program, 2 threads";
  }
  return "";
}

const char* kind_key(Kind kind)
{
  switch (kind)
  {
  case Kind::pca: return "pca";
  case Kind::default_2: return "default_2";
  case Kind::default_1: return "default_1";
  case Kind::paper_2: return "paper_2";
  case Kind::program: return "program";
  }
  return "";
}

// What a child measures, sent to its parent through a pipe.
struct Result
{
  double seconds = 0.;      // the call, or the program; for pca, the pass alone
  double read_seconds = 0.; // pca: CGAL::IO::read_PLY
  std::size_t kept = 0;
  std::uint64_t kept_hash = 0; // of the kept points' coordinates, in input order
  long peak_kib = 0;
  char failures[512] = "";
};

struct Case
{
  std::size_t n = 0;
  Kind kind = Kind::pca;
  Result result;
  long peak_kib = 0;
  std::string verdict;
  // the time of each round, and the read's for the pca pass
  std::vector<double> rounds, read_rounds;
};

std::string input_file(const std::string& work, std::size_t n)
{
  return work + "/lion_" + std::to_string(n) + ".ply";
}

// Writes the sample as a binary little-endian PLY of float x y z.
void write_input(const std::string& data, const std::string& file, std::size_t n)
{
  const std::vector<Point> points = bench::sample_mesh(bench::read_mesh(data + "/meshes/lion.off"), n, 2018);
  const std::string temporary = file + ".tmp";
  std::ofstream out(temporary, std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\nelement vertex " << n
      << "\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
  std::vector<float> row(3 * n);
  for (std::size_t i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d)
      row[3 * i + std::size_t(d)] = float(points[i].cartesian(d));
  out.write(reinterpret_cast<const char*>(row.data()), std::streamsize(row.size() * sizeof(float)));
  if (!out.flush())
    throw std::runtime_error("cannot write " + temporary);
  out.close();
  std::filesystem::rename(temporary, file);
}

// Reads a file written by write_input, untimed.
std::vector<Point> read_input(const std::string& file)
{
  std::ifstream in(file, std::ios::binary);
  std::string line;
  std::size_t n = 0;
  while (std::getline(in, line) && line != "end_header")
    if (line.rfind("element vertex ", 0) == 0)
      n = std::stoull(line.substr(15));
  std::vector<float> row(3 * n);
  if (!in.read(reinterpret_cast<char*>(row.data()), std::streamsize(row.size() * sizeof(float))))
    throw std::runtime_error("cannot read " + file);
  std::vector<Point> points;
  points.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    points.emplace_back(row[3 * i], row[3 * i + 1], row[3 * i + 2]);
  return points;
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

long own_peak_kib()
{
  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

// FNV-1a over the kept points, taken in input order.
std::uint64_t hash_of(std::vector<Point> kept)
{
  std::sort(kept.begin(), kept.end());
  std::uint64_t h = 1469598103934665603ull;
  for (const Point& p : kept)
    for (int d = 0; d < 3; ++d)
    {
      const double c = p.cartesian(d);
      unsigned char bytes[sizeof c];
      std::memcpy(bytes, &c, sizeof c);
      for (unsigned char b : bytes)
        h = (h ^ b) * 1099511628211ull;
    }
  return h;
}

Result measure_pca(const std::string& file)
{
  using Pair = std::pair<Point, Vector>;
  Result r;
  std::vector<Pair> points;
  const auto read_start = std::chrono::steady_clock::now();
  std::ifstream in(file, std::ios::binary);
  if (!CGAL::IO::read_PLY(in, std::back_inserter(points),
                          CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Pair>())
                            .normal_map(CGAL::Second_of_pair_property_map<Pair>())))
    throw std::runtime_error("CGAL::IO::read_PLY cannot read " + file);
  r.read_seconds = seconds_since(read_start);
  const auto start = std::chrono::steady_clock::now();
  CGAL::pca_estimate_normals<CGAL::Sequential_tag>(
    points, k,
    CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Pair>())
      .normal_map(CGAL::Second_of_pair_property_map<Pair>()));
  r.seconds = seconds_since(start);
  r.peak_kib = own_peak_kib();
  return r;
}

Result measure_library(const std::string& file, Kind kind)
{
  Result r;
  std::vector<Point> points = read_input(file);
  const std::vector<Point> input = points;
  ES::Options options;
  options.mode = kind == Kind::paper_2 ? ES::Mode::paper : ES::Mode::weighted_elimination;
  const auto np = CGAL::parameters::select_percentage(percentage);
  const auto start = std::chrono::steady_clock::now();
  const auto first_removed = kind == Kind::default_1
                               ? CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(points, k, np, options)
                               : CGAL::entropy_simplify_point_set<CGAL::Parallel_tag>(points, k, np, options);
  r.seconds = seconds_since(start);
  // the copy of the input counts in the peak: subtract it
  r.peak_kib = own_peak_kib() - long(input.size() * sizeof(Point) / 1024);
  r.kept = std::size_t(first_removed - points.begin());
  r.kept_hash = hash_of(std::vector<Point>(points.begin(), first_removed));
  std::vector<Point> sorted_input = input, sorted_range = points;
  std::sort(sorted_input.begin(), sorted_input.end());
  std::sort(sorted_range.begin(), sorted_range.end());
  if (sorted_input != sorted_range)
    std::snprintf(r.failures, sizeof r.failures, "the range is not a permutation of the input");
  return r;
}

// The number of points a PLY file says it holds.
std::size_t ply_vertex_count(const std::string& file)
{
  std::ifstream in(file, std::ios::binary);
  for (std::string line; std::getline(in, line) && line != "end_header";)
    if (line.rfind("element vertex ", 0) == 0)
      return std::stoull(line.substr(15));
  return 0;
}

// Runs the program in a grandchild, whose peak is the program's own.
Result measure_program(const std::string& program, const std::string& file, const std::string& output)
{
  Result r;
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid < 0)
    throw std::runtime_error("fork failed");
  if (pid == 0)
  {
    execl(program.c_str(), program.c_str(), file.c_str(), output.c_str(), "--ratio", "0.1", "--binary", "-q",
          static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  struct rusage usage;
  while (wait4(pid, &status, 0, &usage) < 0)
    if (errno != EINTR)
      throw std::runtime_error("wait4 failed");
  r.seconds = seconds_since(start);
  r.peak_kib = usage.ru_maxrss;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(program + " failed (status " + std::to_string(status) + ")");
  r.kept = ply_vertex_count(output);
  std::filesystem::remove(output);
  return r;
}

// The middle value, or the mean of the two middle ones.
double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  const std::size_t middle = v.size() / 2;
  return v.size() % 2 == 1 ? v[middle] : (v[middle - 1] + v[middle]) / 2.;
}

// Runs a case once, in a process of its own, adding its time to `seconds`
// and `read_seconds` and keeping the largest peak, unless it failed (its
// verdict then says why).
void run_once(Case& c, const std::string& work, const std::string& program, std::vector<double>& seconds,
              std::vector<double>& read_seconds)
{
  const std::string file = input_file(work, c.n);
  const auto outcome = bench::run_in_child<Result>([&]() -> Result {
    if (c.kind == Kind::pca)
      return measure_pca(file);
    if (c.kind == Kind::program)
      return measure_program(program, file, work + "/out_" + std::to_string(c.n) + ".ply");
    return measure_library(file, c.kind);
  });
  c.verdict = outcome.verdict;
  if (c.verdict != "ok")
    return;
  seconds.push_back(outcome.result.seconds);
  read_seconds.push_back(outcome.result.read_seconds);
  c.result = outcome.result;
  c.peak_kib = (std::max)(c.peak_kib, outcome.result.peak_kib);
}

// Runs the cases of one size `runs` times in rounds, every case once per
// round, so that a slow spell of this shared machine falls on all of them
// rather than on one: each case's median time, its largest peak.
void run_cases(std::vector<Case>& cases, int runs, const std::string& work, const std::string& program)
{
  std::vector<std::vector<double> > seconds(cases.size()), read_seconds(cases.size());
  for (int run = 0; run < runs; ++run)
    for (std::size_t c = 0; c < cases.size(); ++c)
      if (run == 0 || cases[c].verdict == "ok")
        run_once(cases[c], work, program, seconds[c], read_seconds[c]);
  for (std::size_t c = 0; c < cases.size(); ++c)
  {
    if (cases[c].verdict != "ok")
      continue;
    cases[c].result.seconds = median(seconds[c]);
    cases[c].result.read_seconds = median(read_seconds[c]);
    cases[c].rounds = seconds[c];
    cases[c].read_rounds = read_seconds[c];
    const std::size_t expected = ES::internal::kept_count_from_percentage(cases[c].n, percentage);
    if (cases[c].kind != Kind::pca && cases[c].result.kept != expected)
      cases[c].verdict = thousands(cases[c].result.kept) + " kept instead of " + thousands(expected);
  }
}

const Case* find(const std::vector<Case>& cases, std::size_t n, Kind kind)
{
  for (const Case& c : cases)
    if (c.n == n && c.kind == kind && c.verdict == "ok")
      return &c;
  return nullptr;
}

// The pca pass, read included, as the program's reference.
double read_and_pca(const Case& pca) { return pca.result.read_seconds + pca.result.seconds; }

// The ratio of a case's time to the pca pass's (read included for the
// program) in each round: the pass varies more than the package on this
// shared machine, so a ratio is taken between runs of the same round. The
// one ratio of their medians when they did not run in the same rounds.

std::vector<double> ratios_by_round(const Case& c, const Case& pca, bool with_read)
{
  std::vector<double> ratios;
  if (c.rounds.size() == pca.rounds.size())
    for (std::size_t r = 0; r < c.rounds.size(); ++r)
      ratios.push_back(c.rounds[r] / (pca.rounds[r] + (with_read ? pca.read_rounds[r] : 0.)));
  else
    ratios.push_back(c.result.seconds / (with_read ? read_and_pca(pca) : pca.result.seconds));
  return ratios;
}

// --- the report ------------------------------------------------------------

std::string bytes_per_point(long kib, std::size_t n) { return fixed(double(kib) * 1024. / double(n), 0); }

std::string times_table(const std::vector<Case>& cases, const std::vector<std::size_t>& sizes)
{
  std::ostringstream s;
  s << "| points | default, 2 threads | default, 1 thread | paper, 2 threads | pca pass | read (CGAL) | program, "
       "2 threads | default / pca, 2 threads | default / pca, 1 thread | paper / pca | program / (read + pca) |\n"
    << "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (std::size_t n : sizes)
  {
    const Case* pca = find(cases, n, Kind::pca);
    auto seconds = [&](Kind kind) {
      const Case* c = find(cases, n, kind);
      return c ? fixed(c->result.seconds, 2) + " s" : std::string("-");
    };
    auto ratio = [&](Kind kind, bool with_read) {
      const Case* c = find(cases, n, kind);
      return c && pca ? fixed(median(ratios_by_round(*c, *pca, with_read)), 2) + "x" : std::string("-");
    };
    s << "| " << thousands(n) << " | " << seconds(Kind::default_2) << " | " << seconds(Kind::default_1) << " | "
      << seconds(Kind::paper_2) << " | " << seconds(Kind::pca) << " | "
      << (pca ? fixed(pca->result.read_seconds, 2) + " s" : "-") << " | " << seconds(Kind::program) << " | "
      << ratio(Kind::default_2, false) << " | " << ratio(Kind::default_1, false) << " | "
      << ratio(Kind::paper_2, false) << " | " << ratio(Kind::program, true) << " |\n";
  }
  return s.str();
}

std::string memory_table(const std::vector<Case>& cases, const std::vector<std::size_t>& sizes)
{
  std::ostringstream s;
  s << "| points | default, 2 threads | default, 1 thread | paper, 2 threads | read + pca pass | program, 2 threads "
       "|\n|---:|---:|---:|---:|---:|---:|\n";
  for (std::size_t n : sizes)
  {
    s << "| " << thousands(n);
    for (Kind kind : { Kind::default_2, Kind::default_1, Kind::paper_2, Kind::pca, Kind::program })
    {
      const Case* c = find(cases, n, kind);
      s << " | "
        << (c ? fixed(double(c->peak_kib) / 1024., 0) + " MiB (" + bytes_per_point(c->peak_kib, n) + " B/point)"
              : std::string("-"));
    }
    s << " |\n";
  }
  return s.str();
}

// "**met**" or "**missed**", and the measured figure against the target,
// to three decimals so that a figure just over its bound does not print as
// equal to it.
std::string verdict(double measured, double bound, const std::string& unit)
{
  return fixed(measured, 3) + unit + " (target ≤ " + fixed(bound, 2) + unit + "): " +
         (measured <= bound ? "**met**" : "**missed**");
}

// The verdict on the median of the ratios of the rounds, with their range
// and the number of rounds within the target when there are several: a
// median near the bound may be met in one run and missed in the next.
std::string verdict_by_round(const std::vector<double>& ratios, double bound)
{
  if (ratios.size() < 2)
    return verdict(ratios.front(), bound, "x");
  const auto [low, high] = std::minmax_element(ratios.begin(), ratios.end());
  const long within = std::count_if(ratios.begin(), ratios.end(), [bound](double r) { return r <= bound; });
  return verdict(median(ratios), bound, "x") + "; rounds " + fixed(*low, 3) + "x to " + fixed(*high, 3) +
         "x, within the target in " + std::to_string(within) + " of " + std::to_string(ratios.size());
}

std::string targets(const std::vector<Case>& cases, const std::vector<std::size_t>& sizes)
{
  std::ostringstream s;
  auto ratio_to_pca = [&](std::size_t n, Kind kind, bool with_read, double bound) {
    const Case* c = find(cases, n, kind);
    const Case* pca = find(cases, n, Kind::pca);
    return c && pca ? verdict_by_round(ratios_by_round(*c, *pca, with_read), bound) : std::string("not measured");
  };
  const std::size_t million = 1000000, ten_million = 10000000;
  if (find(cases, million, Kind::default_2))
  {
    s << "- 1,000,000 points to 10%, the library, 2 threads, against the pca pass: "
      << ratio_to_pca(million, Kind::default_2, false, 0.4) << ".\n"
      << "- The same, 1 thread (stretch: 0.7x): " << ratio_to_pca(million, Kind::default_1, false, 1.0) << ".\n"
      << "- The paper's mode, 1,000,000 points, 2 threads, against the pca pass: "
      << ratio_to_pca(million, Kind::paper_2, false, 1.5) << "; peak ";
    if (const Case* paper = find(cases, million, Kind::paper_2))
      s << verdict(double(paper->peak_kib) * 1024. / double(million), 150., " B/point") << ".\n";
    else
      s << "not measured.\n";
  }
  if (const Case* program = find(cases, ten_million, Kind::program))
    s << "- 10,000,000 points to 10%, the program from a binary PLY to a binary PLY, 2 threads, against the read "
         "+ pca pass: "
      << ratio_to_pca(ten_million, Kind::program, true, 0.4) << "; peak "
      << verdict(double(program->peak_kib) * 1024. / double(ten_million), 150., " B/point") << ".\n";
  const Case* first = find(cases, sizes.front(), Kind::default_2);
  const Case* last = find(cases, sizes.back(), Kind::default_2);
  if (first && last && sizes.back() > sizes.front())
    s << "- Scaling, the library with 2 threads, time per point from " << thousands(sizes.front()) << " to "
      << thousands(sizes.back()) << " points: "
      << verdict((last->result.seconds / double(last->n)) / (first->result.seconds / double(first->n)), 1.2, "x")
      << ".\n";
  return s.str();
}

std::string markdown(const std::vector<Case>& cases, const std::vector<std::size_t>& sizes, int runs,
                     const std::string& command, double minutes, const std::string& load)
{
  std::ostringstream s;
  s << "## Scale\n\n"
    << bench::produced_by(command, minutes, " (`bash benchmark/run.sh` runs it after the rest)", load)
    << "Inputs: `meshes/lion.off` sampled uniformly in area (seed 2018), coordinates rounded to float, in a binary "
       "PLY of float `x y z`. Each case runs in a process of its own. *Library*: "
       "`CGAL::entropy_simplify_point_set(points, 10, select_percentage(10))` on a `std::vector` of Epick points, "
       "normal estimation included; 2 threads is `Parallel_tag` on this machine's two hardware threads, 1 thread "
       "`Sequential_tag`. *pca pass*: one `CGAL::pca_estimate_normals<Sequential_tag>` pass, k = 10, on the same "
       "points, after `CGAL::IO::read_PLY` (*read*). *Program*: `entropy_simplify lion_N.ply out.ply --ratio 0.1 "
       "--binary -q`, read and write included, against the read + pca pass. Times: "
    << (runs > 1 ? "the median of " + std::to_string(runs) +
                     " runs up to 1,000,000 points, in rounds that run every case of a size once, one run above"
                 : std::string("one run"))
    << ". Ratios: in each round, a case's time over the pca pass's, the median of those ratios (on this shared "
       "machine the pass varies more than the package from one run to the next); the targets give their range "
       "too. Peak: the maximum resident set size of the process (as `/usr/bin/time -v` reports it); for the library, "
       "less the copy of the input the check keeps, so the input range itself is counted.\n\n"
    << "### Targets (issue 10)\n\n"
    << targets(cases, sizes) << "\n### Time\n\n"
    << times_table(cases, sizes) << "\n![time per point](results/scale.png)\n\n### Peak memory\n\n"
    << memory_table(cases, sizes) << "\n### Invariants\n\n";
  bool all_ok = true;
  for (const Case& c : cases)
    if (c.verdict != "ok")
    {
      all_ok = false;
      s << "- " << thousands(c.n) << " points, " << kind_name(c.kind) << ": " << c.verdict << "\n";
    }
  if (all_ok)
    s << "Every case kept exactly its count; the library's range was a permutation of its input; 1 and 2 threads "
         "kept the same points at every size.\n";
  std::string text = s.str();
  return text;
}

void write_chart(const std::string& results, const std::vector<Case>& cases, const std::vector<std::size_t>& sizes)
{
  std::ofstream dat(results + "/scale.dat");
  dat << "# points";
  for (Kind kind : all_kinds)
    dat << ' ' << kind_key(kind) << "_us_per_point";
  dat << '\n';
  for (std::size_t n : sizes)
  {
    dat << n;
    for (Kind kind : all_kinds)
    {
      const Case* c = find(cases, n, kind);
      const double seconds = !c ? 0. : kind == Kind::pca ? read_and_pca(*c) : c->result.seconds;
      dat << ' ' << (c ? fixed(1e6 * seconds / double(n), 4) : std::string("NaN"));
    }
    dat << '\n';
  }
  std::ofstream gp(results + "/scale.gp");
  gp << "set terminal pngcairo size 900,540\nset output 'scale.png'\nset logscale x\nset key outside right\n"
        "set xlabel 'input points'\nset ylabel 'microseconds per input point'\nset yrange [0:*]\nset grid\n"
        "set title 'lion samples to 10%, 2 hardware threads'\n"
        "plot 'scale.dat' using 1:3 with linespoints title 'default, 2 threads', \\\n"
        "     '' using 1:4 with linespoints title 'default, 1 thread', \\\n"
        "     '' using 1:5 with linespoints title 'paper, 2 threads', \\\n"
        "     '' using 1:6 with linespoints title 'program, 2 threads', \\\n"
        "     '' using 1:2 with linespoints dashtype 2 title 'read + pca pass'\n";
  std::ofstream csv(results + "/scale.csv");
  // the times of the rounds too, from which the ratios are taken
  auto joined = [](const std::vector<double>& values) {
    std::string text;
    for (double v : values)
      text += (text.empty() ? "" : " ") + fixed(v, 4);
    return text;
  };
  csv << "points,case,seconds,read_seconds,peak_kib,kept,verdict,round_seconds,round_read_seconds\n";
  for (const Case& c : cases)
    csv << c.n << ',' << kind_key(c.kind) << ',' << fixed(c.result.seconds, 4) << ','
        << fixed(c.result.read_seconds, 4) << ',' << c.peak_kib << ',' << c.result.kept << ",\"" << c.verdict
        << "\"," << joined(c.rounds) << ',' << joined(c.read_rounds) << "\n";
}

int usage()
{
  std::cerr << "usage: bench_scale --data DIR --work DIR [--program PATH] [--sizes N1,N2,...] [--runs R] "
               "[--out DIR] [--smoke]\n";
  return 2;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    const std::vector<std::string> args(argv + 1, argv + argc);
    std::string command = "bench_scale";
    for (const std::string& a : args)
      command += " " + a;
    std::string data, work, program, out;
    std::vector<std::size_t> sizes = { 100000, 300000, 1000000, 3000000, 10000000 };
    int runs = 3;
    for (std::size_t i = 0; i < args.size(); ++i)
    {
      const bool has_value = i + 1 < args.size();
      if (args[i] == "--data" && has_value)
        data = args[++i];
      else if (args[i] == "--work" && has_value)
        work = args[++i];
      else if (args[i] == "--program" && has_value)
        program = args[++i];
      else if (args[i] == "--out" && has_value)
        out = args[++i];
      else if (args[i] == "--runs" && has_value)
        runs = std::stoi(args[++i]);
      else if (args[i] == "--smoke")
      {
        sizes = { 20000, 50000 };
        runs = 1;
      }
      else if (args[i] == "--sizes" && has_value)
      {
        sizes.clear();
        std::istringstream list(args[++i]);
        for (std::string item; std::getline(list, item, ',');)
          sizes.push_back(std::size_t(std::stoull(item)));
      }
      else
        return usage();
    }
    if (data.empty() || work.empty() || sizes.empty() || runs < 1)
      return usage();
    std::filesystem::create_directories(work);

    const std::string load = bench::load_average();
    const auto start = std::chrono::steady_clock::now();
    std::vector<Case> cases;
    bool failed = false;
    for (std::size_t n : sizes)
    {
      const std::string file = input_file(work, n);
      if (!std::filesystem::exists(file))
      {
        const auto written = bench::run_in_child<Result>([&] {
          write_input(data, file, n);
          return Result();
        });
        if (written.verdict != "ok")
          throw std::runtime_error("cannot write " + file + ": " + written.verdict);
      }
      std::vector<Case> of_size;
      for (Kind kind : all_kinds)
        if (kind != Kind::program || !program.empty())
          of_size.push_back(Case{ n, kind, Result(), 0, "" });
      run_cases(of_size, n <= 1000000 ? runs : 1, work, program);
      for (const Case& c : of_size)
      {
        std::cerr << "bench_scale: " << thousands(n) << " points, " << kind_name(c.kind) << ": "
                  << fixed(c.result.seconds, 3) << " s"
                  << (c.kind == Kind::pca ? " (read " + fixed(c.result.read_seconds, 3) + " s)" : std::string())
                  << ", peak " << fixed(double(c.peak_kib) / 1024., 0) << " MiB: " << c.verdict << std::endl;
        cases.push_back(c);
      }
      const Case* two = find(cases, n, Kind::default_2);
      const Case* one = find(cases, n, Kind::default_1);
      if (two && one && two->result.kept_hash != one->result.kept_hash)
        cases.push_back(Case{ n, Kind::default_1, one->result, one->peak_kib, "kept other points than with 2 threads" });
    }
    for (const Case& c : cases)
      failed = failed || c.verdict != "ok";
    const double minutes = seconds_since(start) / 60.;
    const std::string section = markdown(cases, sizes, runs, command, minutes, load);
    std::cout << section;
    if (!out.empty())
    {
      std::filesystem::create_directories(out + "/results");
      write_chart(out + "/results", cases, sizes);
      bench::write_section(out + "/RESULTS.md", "## Scale", section);
    }
    if (failed)
      std::cerr << "bench_scale: an invariant failed" << std::endl;
    return failed ? EXIT_FAILURE : EXIT_SUCCESS;
  }
  catch (const std::exception& e)
  {
    std::cerr << "bench_scale: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
}
