// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The command line of the programs that print a section of RESULTS.md after
// run_benchmark: --data DIR (CGAL's demo data), --out DIR, --smoke, and
// --quality FILE (run_benchmark's quality.csv) for those that read it; and
// how such a program ends.

#ifndef ENTROPY_SIMPLIFICATION_BENCH_ARGUMENTS_H
#define ENTROPY_SIMPLIFICATION_BENCH_ARGUMENTS_H

#include <exception>
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

// Runs `section(arguments)` on `program`'s command line (see
// section_arguments): exit status 2 after a bad command line, 1 after
// printing what `section` threw, 0 otherwise.
template <typename Section>
int run_section(int argc, char** argv, const std::string& program, bool needs_quality, const Section& section)
{
  const std::optional<Section_arguments> arguments = section_arguments(argc, argv, program, needs_quality);
  if (!arguments)
    return 2;
  try
  {
    section(*arguments);
  }
  catch (const std::exception& e)
  {
    std::cerr << program << ": " << e.what() << '\n';
    return 1;
  }
  return 0;
}

} // namespace bench

#endif // ENTROPY_SIMPLIFICATION_BENCH_ARGUMENTS_H
