// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Number formatting and the description of the machine, shared by
// run_benchmark (through bench_report.h) and bench_duplicates, which needs
// neither TBB nor the rest of the benchmark.

#ifndef ENTROPY_SIMPLIFICATION_BENCH_MACHINE_H
#define ENTROPY_SIMPLIFICATION_BENCH_MACHINE_H

#include <CGAL/version.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <thread>

namespace bench {

inline std::string fixed(double v, int digits)
{
  if (std::isnan(v))
    return "n/a";
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

inline std::string thousands(std::size_t v)
{
  std::string s = std::to_string(v);
  for (int i = int(s.size()) - 3; i > 0; i -= 3)
    s.insert(std::size_t(i), ",");
  return s;
}

// The CPU, its hardware threads, the memory, the compiler and CGAL's version.
inline std::string machine_description()
{
  std::string cpu = "unknown CPU";
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);)
    if (line.rfind("model name", 0) == 0)
    {
      cpu = line.substr(line.find(':') + 2);
      break;
    }
  double memory = 0.;
  std::ifstream meminfo("/proc/meminfo");
  for (std::string line; std::getline(meminfo, line);)
    if (line.rfind("MemTotal", 0) == 0)
      memory = std::stod(line.substr(line.find(':') + 1)) / 1024. / 1024.;
  std::ostringstream s;
  s << cpu << ", " << std::thread::hardware_concurrency() << " hardware threads, " << fixed(memory, 0) << " GiB; "
#ifdef __clang__
    << "clang++ "
#else
    << "g++ "
#endif
    << __VERSION__ << ", -O3 -DNDEBUG; CGAL " << CGAL_VERSION_STR;
  return s.str();
}

} // namespace bench

#endif // ENTROPY_SIMPLIFICATION_BENCH_MACHINE_H
