// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The command line of the programs that print a section of RESULTS.md after
// run_benchmark: --data DIR (CGAL's demo data), --out DIR, --smoke, and
// --quality FILE (run_benchmark's quality.csv) for those that read it.

#ifndef ENTROPY_SIMPLIFICATION_BENCH_ARGUMENTS_H
#define ENTROPY_SIMPLIFICATION_BENCH_ARGUMENTS_H

#include <iostream>
#include <optional>
#include <string>

namespace bench {

struct Section_arguments
{
  std::string data, out = ".", quality;
  bool smoke = false;
};

// The arguments of `program`, or nothing after printing what is wrong: an
// unknown option, a missing --data, or a missing --quality when
// `needs_quality`.
inline std::optional<Section_arguments> section_arguments(int argc, char** argv, const std::string& program,
                                                          bool needs_quality = false)
{
  const std::string usage = "usage: " + program + " --data DIR" + (needs_quality ? " --quality FILE" : "") +
                            " [--out DIR] [--smoke]\n";
  Section_arguments a;
  for (int i = 1; i < argc; ++i)
  {
    const std::string option = argv[i];
    if (option == "--data" && i + 1 < argc)
      a.data = argv[++i];
    else if (option == "--quality" && needs_quality && i + 1 < argc)
      a.quality = argv[++i];
    else if (option == "--out" && i + 1 < argc)
      a.out = argv[++i];
    else if (option == "--smoke")
      a.smoke = true;
    else
    {
      std::cerr << usage;
      return std::nullopt;
    }
  }
  if (a.data.empty() || (needs_quality && a.quality.empty()))
  {
    std::cerr << program << ": give --data, the folder of CGAL's demo data"
              << (needs_quality ? ", and --quality, run_benchmark's quality.csv" : "") << '\n'
              << usage;
    return std::nullopt;
  }
  return a;
}

} // namespace bench

#endif // ENTROPY_SIMPLIFICATION_BENCH_ARGUMENTS_H
