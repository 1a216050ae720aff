// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Coincident points: the time and peak memory of
// CGAL::entropy_simplify_point_set, k = 10, Sequential_tag, in both modes, and
// of the two measures (CGAL::compute_mean_normal_angle_entropy, and
// CGAL::measure_simplification_quality of a cloud against itself), on
// a plane of 20,000 points plus 0, 2,000, 20,000 and 200,000 copies of one of
// its points, against a plane of 220,000 points without copies; and on a
// plane of 200,000 points plus 200,000 copies against one of 400,000 points.
// Every case keeps 10% of its distinct points (`number_of_output_points`):
// 2,000 on the 20,000-point plane whatever its copies, 22,000 on the
// reference of 220,000 points, 20,000 and 40,000 in the second comparison.
// Fewer points are asked for than there are distinct points, so every case
// runs the full simplification once the copies are removed.
//
//   bench_duplicates                      every case, 5 runs each (median time)
//   bench_duplicates --smoke              20,000 points plus 0, 2,000 and 20,000 copies, 1 run each
//   bench_duplicates --copies 0,500       20,000 points plus these numbers of copies
//                    [--reference]        and the plane of 220,000 points
//   bench_duplicates --runs R             R runs per case
//   bench_duplicates --append FILE        also writes the section "Coincident points" of FILE
//
// Markdown on the standard output; a line per case on the standard error.
// Each case runs in a child process of its own (fork), so that the peak
// memory, the child's maximum resident set size, is that of the case. The
// exit status is nonzero when an invariant fails in any case:
//   - exactly the target is kept, and it is below the number of distinct
//     input points;
//   - the range is a permutation of the input, so that the kept points are a
//     subset of it, unaltered;
//   - no point is kept twice; in particular at most one copy of the
//     duplicated point is kept;
//   - for the measures, a mean entropy in [0, log2(k + 1)] and a cloud at
//     distance 0 from itself.

#include "bench_common.h"
#include "bench_machine.h"
#include "bench_process.h"

#include <CGAL/Entropy_simplification/compute_mean_normal_angle_entropy.h>
#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>
#include <CGAL/Entropy_simplification/measure_simplification_quality.h>

#include <sys/resource.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using bench::fixed;
using bench::Point;
using bench::thousands;
using CGAL::Entropy_simplification::Mode;

constexpr unsigned int k = 10;
constexpr std::size_t plane_points = 20000, reference_points = 220000;
constexpr std::uint64_t seed = 2026;
constexpr double allowed_ratio = 1.5;

// A plane z = 0.3 x - 0.2 y over the unit square, sampled uniformly, with a
// Gaussian noise of 5% of the mean spacing along z; then `copies` copies of
// the plane point nearest the centre of the square, appended.
std::vector<Point> make_input(std::size_t n, std::size_t copies, Point* duplicated = nullptr)
{
  bench::Random random(seed);
  const double noise = 0.05 / std::sqrt(double(n));
  std::vector<Point> points;
  points.reserve(n + copies);
  std::size_t centre = 0;
  double best = 1.;
  for (std::size_t i = 0; i < n; ++i)
  {
    const double x = random.uniform(), y = random.uniform();
    points.emplace_back(x, y, 0.3 * x - 0.2 * y + noise * random.gaussian());
    const double d = CGAL::square(x - 0.5) + CGAL::square(y - 0.5);
    if (d < best)
    {
      best = d;
      centre = i;
    }
  }
  points.insert(points.end(), copies, points[centre]);
  if (duplicated)
    *duplicated = points[centre];
  return points;
}

std::size_t count_distinct(std::vector<Point> points)
{
  std::sort(points.begin(), points.end());
  return std::size_t(std::unique(points.begin(), points.end()) - points.begin());
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double process_cpu_seconds()
{
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

const char* mode_name(Mode mode) { return mode == Mode::paper ? "paper" : "default"; }

std::string short_count(std::size_t v)
{
  return v % 1000 == 0 && v > 0 ? std::to_string(v / 1000) + "k" : std::to_string(v);
}

// What a child process measures, sent to its parent through a pipe.
struct Result
{
  std::size_t distinct_input = 0, kept = 0, distinct_kept = 0, kept_copies = 0;
  double seconds = 0., cpu_seconds = 0.;
  double entropy_seconds = 0., quality_seconds = 0.; // of the measures
  long peak_kib = 0;
  char failures[512] = ""; // empty when every invariant holds
};

struct Case
{
  std::size_t group = 0, plane = 0, copies = 0;
  std::size_t target = 0; // 10% of the plane's points, which are its distinct points
  Mode mode = Mode::weighted_elimination;
  bool measures = false; // the two measures rather than a simplification
  Result result;
  std::string verdict; // "ok", or what failed
  std::string name() const
  {
    return "plane " + short_count(plane) + (copies > 0 ? " + " + short_count(copies) + " copies" : "");
  }
};

// In the child: `runs` calls on fresh copies of the input, then the peak
// memory, then the invariants on the range of the last call.
Result measure(const Case& c, int runs)
{
  Result r;
  CGAL::Entropy_simplification::Options options;
  options.mode = c.mode;
  std::vector<double> seconds, cpu_seconds;
  std::vector<Point> points;
  for (int i = 0; i < runs; ++i)
  {
    std::vector<Point>().swap(points); // never two inputs at once
    points = make_input(c.plane, c.copies);
    const double cpu_start = process_cpu_seconds();
    const auto start = std::chrono::steady_clock::now();
    const auto first_removed = CGAL::entropy_simplify_point_set<CGAL::Sequential_tag>(
      points, k, CGAL::parameters::number_of_output_points(c.target), options);
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    cpu_seconds.push_back(process_cpu_seconds() - cpu_start);
    r.kept = std::size_t(first_removed - points.begin());
  }
  r.seconds = median(seconds);
  r.cpu_seconds = median(cpu_seconds);
  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage); // the peak of the runs, before the checks allocate
  r.peak_kib = usage.ru_maxrss;   // in KiB on Linux

  Point duplicated;
  std::vector<Point> input = make_input(c.plane, c.copies, &duplicated);
  const std::vector<Point> kept(points.begin(), points.begin() + std::ptrdiff_t(r.kept));
  r.distinct_input = count_distinct(input);
  r.distinct_kept = count_distinct(kept);
  r.kept_copies = std::size_t(std::count(kept.begin(), kept.end(), duplicated));
  std::string failures;
  auto fail = [&failures](const std::string& what) { failures += (failures.empty() ? "" : "; ") + what; };
  if (r.kept != c.target)
    fail(thousands(r.kept) + " kept instead of " + thousands(c.target));
  if (c.target >= r.distinct_input)
    fail("the target is not below the " + thousands(r.distinct_input) + " distinct points");
  std::sort(points.begin(), points.end());
  std::sort(input.begin(), input.end());
  if (points != input)
    fail("the range is not a permutation of the input");
  if (r.distinct_kept != r.kept)
    fail(thousands(r.kept - r.distinct_kept) + " points kept twice");
  if (r.kept_copies > 1)
    fail(thousands(r.kept_copies) + " copies of the duplicated point kept");
  std::snprintf(r.failures, sizeof r.failures, "%s", failures.c_str());
  return r;
}

// In the child: `runs` calls of each measure on the input, which is also the
// simplification measured, copies included, then the peak memory, then the
// invariants.
Result measure_copies(const Case& c, int runs)
{
  Result r;
  const std::vector<Point> points = make_input(c.plane, c.copies);
  std::vector<double> entropy_seconds, quality_seconds;
  double bits = 0.;
  CGAL::Entropy_simplification::Quality_report report;
  for (int i = 0; i < runs; ++i)
  {
    auto start = std::chrono::steady_clock::now();
    bits = CGAL::compute_mean_normal_angle_entropy<CGAL::Sequential_tag>(points, k);
    entropy_seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    start = std::chrono::steady_clock::now();
    report = CGAL::measure_simplification_quality<CGAL::Sequential_tag>(points, points);
    quality_seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  r.entropy_seconds = median(entropy_seconds);
  r.quality_seconds = median(quality_seconds);
  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  r.peak_kib = usage.ru_maxrss;
  r.distinct_input = count_distinct(points);
  r.kept = report.kept_size;
  std::string failures;
  if (!(bits >= 0. && bits <= std::log2(double(k + 1)) + 1e-12))
    failures += "a mean entropy of " + std::to_string(bits) + " bits";
  if (report.mean_distance != 0. || report.max_distance != 0. || report.kept_size != points.size())
    failures += std::string(failures.empty() ? "" : "; ") + "the cloud is not at distance 0 from itself";
  std::snprintf(r.failures, sizeof r.failures, "%s", failures.c_str());
  return r;
}

// Runs `measure` or `measure_copies` in a child process.
void run_case(Case& c, int runs)
{
  const bench::Child_outcome<Result> outcome =
    bench::run_in_child<Result>([&] { return c.measures ? measure_copies(c, runs) : measure(c, runs); });
  c.result = outcome.result;
  c.verdict = outcome.verdict;
}

// --- the report ------------------------------------------------------------

// Planes of `plane` points plus each number of `copies`, compared with a
// plane of `reference` points without copies (none when 0).
struct Group
{
  std::size_t plane = 0;
  std::vector<std::size_t> copies;
  std::size_t reference = 0;
};

const Case* find_case(const std::vector<Case>& cases, std::size_t group, std::size_t plane, std::size_t copies,
                      Mode mode)
{
  for (const Case& c : cases)
    if (c.group == group && c.plane == plane && c.copies == copies && c.mode == mode && !c.measures &&
        c.verdict == "ok")
      return &c;
  return nullptr;
}

// "1.23x the time (1.23x the CPU time) and 0.45x the peak memory"
std::string ratios(const Case& c, const Case& to)
{
  return fixed(c.result.seconds / to.result.seconds, 2) + "x the time (" +
         fixed(c.result.cpu_seconds / to.result.cpu_seconds, 2) + "x the CPU time) and " +
         fixed(double(c.result.peak_kib) / double(to.result.peak_kib), 2) + "x the peak memory";
}

// One table per group, then, per mode, its largest number of copies against
// the reference and against the same plane without copies.
void write_group(std::ostream& s, const std::vector<Case>& cases, const Group& g, std::size_t group,
                 bool titled)
{
  if (titled)
    s << "### " << thousands(g.plane) << " points plus copies"
      << (g.reference ? ", against " + thousands(g.reference) + " points without copies" : std::string()) << "\n\n";
  const std::string per = g.reference ? short_count(g.reference) : std::string("reference");
  s << "| case | points | distinct | mode | kept | time (s) | CPU time (s) | peak (MiB) | time / " << per
    << " | memory / " << per << " | copies kept | invariants |\n"
    << "|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---|\n";
  for (const Case& c : cases)
    if (c.group == group && !c.measures)
    {
      const Case* r = g.reference ? find_case(cases, group, g.reference, 0, c.mode) : nullptr;
      const Result& m = c.result;
      s << "| " << c.name() << " | " << thousands(c.plane + c.copies) << " | " << thousands(m.distinct_input)
        << " | " << mode_name(c.mode) << " | " << thousands(m.kept) << " | " << fixed(m.seconds, 3) << " | "
        << fixed(m.cpu_seconds, 3) << " | " << fixed(double(m.peak_kib) / 1024., 1) << " | "
        << (r ? fixed(m.seconds / r->result.seconds, 2) : "-") << " | "
        << (r ? fixed(double(m.peak_kib) / double(r->result.peak_kib), 2) : "-") << " | "
        << thousands(m.kept_copies) << " | " << c.verdict << " |\n";
    }
  const std::size_t most = g.copies.empty() ? 0 : *std::max_element(g.copies.begin(), g.copies.end());
  std::vector<std::string> compared, within; // the modes compared with the reference, and those within the ratio
  for (Mode mode : { Mode::weighted_elimination, Mode::paper })
  {
    const std::string phrase = mode == Mode::paper ? "the paper's mode" : "the default mode";
    const Case* big = find_case(cases, group, g.plane, most, mode);
    const Case* ref = g.reference ? find_case(cases, group, g.reference, 0, mode) : nullptr;
    const Case* alone = find_case(cases, group, g.plane, 0, mode);
    if (most == 0 || !big || (!ref && !alone))
      continue;
    s << "\nIn " << phrase << ", with " << thousands(most) << " copies of one point added to the "
      << thousands(g.plane) << "-point plane (" << thousands(big->target) << " points kept), the call takes ";
    if (ref)
    {
      const bool time_ok = big->result.seconds <= allowed_ratio * ref->result.seconds;
      const bool memory_ok = double(big->result.peak_kib) <= allowed_ratio * double(ref->result.peak_kib);
      compared.push_back(phrase);
      if (time_ok && memory_ok)
        within.push_back(phrase);
      s << ratios(*big, *ref) << " of the " << thousands(g.reference) << "-point plane without copies ("
        << thousands(ref->target) << " kept): "
        << (time_ok && memory_ok ? "within " : "**not within** ") << fixed(allowed_ratio, 1) << "x"
        << (time_ok && memory_ok ? "" : time_ok ? " in memory" : memory_ok ? " in time" : " in time and memory")
        << "." << (alone ? " Against the same plane without copies, it takes " : "");
    }
    if (alone)
      s << ratios(*big, *alone) << (ref ? "." : " of the same plane without copies.");
    s << "\n";
  }
  if (compared.size() == 2)
    s << "\n**" << thousands(most) << " copies added to " << thousands(g.plane) << " points: within "
      << fixed(allowed_ratio, 1) << "x the time and peak memory of " << thousands(g.reference)
      << " points without copies "
      << (within.size() == 2 ? std::string("in both modes")
          : within.empty()   ? std::string("in neither mode")
                             : "in " + within[0] + " only")
      << ".**\n";
  s << "\n";
}

// The measures' table of a group, and its largest number of copies against
// the reference.
void write_measures(std::ostream& s, const std::vector<Case>& cases, const Group& g, std::size_t group)
{
  const Case* ref = nullptr;
  const Case* big = nullptr;
  const std::size_t most = g.copies.empty() ? 0 : *std::max_element(g.copies.begin(), g.copies.end());
  for (const Case& c : cases)
    if (c.group == group && c.measures && c.verdict == "ok")
    {
      if (c.plane == g.reference && c.copies == 0)
        ref = &c;
      if (c.plane == g.plane && c.copies == most)
        big = &c;
    }
  const std::string per = g.reference ? short_count(g.reference) : std::string("reference");
  s << "The measures, on the same clouds: `compute_mean_normal_angle_entropy` (k = " << k
    << ") and `measure_simplification_quality` of the cloud against itself, copies included.\n\n"
    << "| case | points | distinct | mean entropy (s) | time / " << per << " | quality (s) | time / " << per
    << " | peak (MiB) | invariants |\n|---|---:|---:|---:|---:|---:|---:|---:|---|\n";
  for (const Case& c : cases)
    if (c.group == group && c.measures)
    {
      const Result& m = c.result;
      s << "| " << c.name() << " | " << thousands(c.plane + c.copies) << " | " << thousands(m.distinct_input) << " | "
        << fixed(m.entropy_seconds, 3) << " | "
        << (ref ? fixed(m.entropy_seconds / ref->result.entropy_seconds, 2) : "-") << " | "
        << fixed(m.quality_seconds, 3) << " | "
        << (ref ? fixed(m.quality_seconds / ref->result.quality_seconds, 2) : "-") << " | "
        << fixed(double(m.peak_kib) / 1024., 1) << " | " << c.verdict << " |\n";
    }
  if (ref && big && most > 0)
    s << "\nWith " << thousands(most) << " copies of one point added to the " << thousands(g.plane)
      << "-point plane, the mean entropy takes " << fixed(big->result.entropy_seconds / ref->result.entropy_seconds, 2)
      << "x and the quality " << fixed(big->result.quality_seconds / ref->result.quality_seconds, 2) << "x the time of the "
      << thousands(g.reference) << "-point plane without copies.\n";
  s << "\n";
}

std::string markdown(const std::vector<Case>& cases, const std::vector<Group>& groups, int runs,
                     const std::string& command, double minutes, const std::string& load)
{
  std::ostringstream s;
  s << "## Coincident points\n\n"
    << bench::produced_by(command, minutes,
                          ": the target `bench_duplicates` of a build with `ENTROPY_SIMPLIFICATION_BUILD_BENCHMARKS` "
                          "or `ENTROPY_SIMPLIFICATION_BUILD_TESTS` on; `bash benchmark/run.sh` runs it after the rest",
                          load)
    << "`CGAL::entropy_simplify_point_set` with k = " << k
    << ", `Sequential_tag`, in each mode, on planes (uniform over the unit square, Gaussian noise of 5% of the mean "
       "spacing along z, seed "
    << seed
    << ") followed by copies of their point nearest the centre, against planes without copies. Every case keeps "
       "10% of its distinct points (`number_of_output_points`, the plane's points; *distinct* in the table): "
       "fewer points than there are distinct ones, so that the copies are removed and the distinct points then "
       "simplified in full. A plane with copies and its reference hold as many points, but the reference keeps "
       "more, all of its points being distinct: the ratio to the reference says whether copies cost more than "
       "as many distinct points; the ratio to the same plane without copies, what the copies add. Each case "
       "runs in a process of its own. Time: that of the call, "
    << (runs > 1 ? "the median of " + std::to_string(runs) + " runs" : "one run")
    << "; the CPU time of the process during the call is given too, for when the machine is shared. Peak: the "
       "process's maximum resident set size after the runs, its input and code included. Invariants: exactly the target "
       "kept, the range a permutation of the input (the kept points are a subset of it), and no point kept "
       "twice; *copies kept* counts the duplicated point among the kept points, the original included (at most "
       "1).\n\n";
  for (std::size_t i = 0; i < groups.size(); ++i)
  {
    write_group(s, cases, groups[i], i, groups.size() > 1);
    write_measures(s, cases, groups[i], i);
  }
  std::string text = s.str();
  text.pop_back(); // one newline at the end
  return text;
}

int usage()
{
  std::cerr << "usage: bench_duplicates [--smoke | --copies C1,C2,... [--reference]] [--runs R] [--append FILE]\n";
  return 2;
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    const std::vector<std::string> args(argv + 1, argv + argc);
    std::string command = argv[0];
    for (const std::string& a : args)
      command += " " + a;
    // The plane of 20,000 points plus copies against 220,000 points, then a
    // larger plane with as many copies as points against 400,000 points.
    std::vector<Group> groups = { { plane_points, { 0, 2000, 20000, 200000 }, reference_points },
                                  { 200000, { 200000 }, 400000 } };
    bool smoke = false, reference = false;
    int runs = 0;
    std::string append;
    for (std::size_t i = 0; i < args.size(); ++i)
    {
      const bool has_value = i + 1 < args.size();
      if (args[i] == "--smoke")
      {
        smoke = true;
        groups = { { plane_points, { 0, 2000, 20000 }, 0 } };
      }
      else if (args[i] == "--copies" && has_value)
      {
        groups = { { plane_points, {}, 0 } };
        std::istringstream list(args[++i]);
        for (std::string item; std::getline(list, item, ',');)
          groups[0].copies.push_back(std::size_t(std::stoull(item)));
      }
      else if (args[i] == "--reference")
        reference = true;
      else if (args[i] == "--runs" && has_value)
        runs = std::stoi(args[++i]);
      else if (args[i] == "--append" && has_value)
        append = args[++i];
      else
        return usage();
    }
    if (reference && groups.size() == 1)
      groups[0].reference = reference_points;
    if (runs <= 0)
      runs = smoke ? 1 : 5;

    std::vector<Case> cases;
    for (std::size_t i = 0; i < groups.size(); ++i)
      for (Mode mode : { Mode::weighted_elimination, Mode::paper })
      {
        auto add = [&](std::size_t plane, std::size_t copies) {
          Case c;
          c.group = i;
          c.plane = plane;
          c.copies = copies;
          c.target = (plane + 9) / 10;
          c.mode = mode;
          cases.push_back(c);
        };
        for (std::size_t copies : groups[i].copies)
          add(groups[i].plane, copies);
        if (groups[i].reference)
          add(groups[i].reference, 0);
      }
    // the measures, once per cloud, after the simplifications
    for (std::size_t i = 0, simplifications = cases.size(); i < simplifications; ++i)
      if (cases[i].mode == Mode::weighted_elimination)
      {
        cases.push_back(cases[i]);
        cases.back().measures = true;
      }

    const std::string load = bench::load_average();
    const auto start = std::chrono::steady_clock::now();
    bool failed = false;
    for (Case& c : cases)
    {
      run_case(c, runs);
      if (c.measures)
        std::cerr << "bench_duplicates: " << c.name() << ", measures: " << fixed(c.result.entropy_seconds, 3)
                  << " s and " << fixed(c.result.quality_seconds, 3) << " s, "
                  << fixed(double(c.result.peak_kib) / 1024., 1) << " MiB: " << c.verdict << std::endl;
      else
        std::cerr << "bench_duplicates: " << c.name() << ", " << mode_name(c.mode) << ": "
                  << fixed(c.result.seconds, 3) << " s, " << fixed(double(c.result.peak_kib) / 1024., 1) << " MiB, "
                  << c.result.kept << " kept, of which " << c.result.kept_copies << " the duplicated point: "
                  << c.verdict << std::endl;
      failed = failed || c.verdict != "ok";
    }
    const double minutes = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / 60.;
    const std::string section = markdown(cases, groups, runs, command, minutes, load);
    std::cout << section;
    if (!append.empty())
      bench::write_section(append, "## Coincident points", section);
    if (failed)
      std::cerr << "bench_duplicates: an invariant failed" << std::endl;
    return failed ? EXIT_FAILURE : EXIT_SUCCESS;
  }
  catch (const std::exception& e)
  {
    std::cerr << "bench_duplicates: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
}
