// The command line of entropy_simplify, parsed with CLI11 and checked whole
// before anything is read: a usage error never costs a computation.

#ifndef ENTROPY_SIMPLIFY_COMMAND_LINE_H
#define ENTROPY_SIMPLIFY_COMMAND_LINE_H

#include "text_numbers.h"

#include <CGAL/Entropy_simplification/Options.h>
#include <CGAL/Entropy_simplification/internal/Decremental_knn.h>
#include <CGAL/Entropy_simplification/internal/local_normal.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iostream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace entropy_simplify {

namespace ES = CGAL::Entropy_simplification;

// Exit codes, as --help documents them.
constexpr int exit_done = 0, exit_failure = 1, exit_usage = 2;

struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

struct Settings
{
  std::string input, output;
  std::optional<double> ratio;
  std::optional<std::size_t> count;
  unsigned int k = 10;
  ES::Options options;
  bool write_normals = false;
  bool lod = false;        // --lod: every point, by rank
  bool importance = false; // --importance: a scalar property
  std::string indices;     // --indices FILE: the input indices written, by rank
  std::string render;      // --render FILE.png: the input beside the result
  bool report = false;
  std::optional<std::size_t> threads; // --threads; all the hardware threads otherwise
  bool quiet = false;
  std::optional<bool> binary; // --binary or --ascii; otherwise the input's PLY encoding
};

inline const char* examples_text()
{
  return "Examples, one per format (the output's extension sets its format):\n"
         "  entropy_simplify scan.ply out.ply --ratio 0.1    PLY: every vertex property kept,\n"
         "                                                   in the input's encoding\n"
         "  entropy_simplify scan.las out.las --ratio 0.1    LAS 1.0-1.4: kept records copied byte\n"
         "                                                   for byte, VLRs and EVLRs kept\n"
         "  entropy_simplify scan.las out.ply --count 100000 LAS to PLY: x y z as doubles, the LAS\n"
         "                                                   attributes as properties\n"
         "  entropy_simplify scan.xyz out.xyz --ratio 0.2    XYZ (and .pwn): x y z [nx ny nz]\n"
         "  entropy_simplify mesh.off out.off --count 5000   OFF in: the vertices; OFF out: plain OFF\n"
         "                                                   (Open3D reads no points-only OFF: use PLY)\n"
         "  entropy_simplify scan.ply out.ply --ratio 0.1 --mode paper --order highest -k 12\n"
         "                                                   the paper's method, greatest entropy first\n"
         "  entropy_simplify scan.ply out.ply --count 5000 --normals jet --feature-weight 5 --write-normals\n"
         "                                                   jet normals, denser features, normals written\n"
         "  entropy_simplify scan.ply out.ply --ratio 0.1 --ascii --quiet\n"
         "                                                   text PLY, and nothing printed\n"
         "  entropy_simplify scan.ply lod.ply --lod --ratio 0.01\n"
         "                                                   every point, by rank, with its rank: any\n"
         "                                                   first m points are a simplification, the\n"
         "                                                   first 1% exactly the --ratio 0.01 result\n"
         "  entropy_simplify scan.las lod.las --lod          LAS: the records by rank, the order alone\n"
         "                                                   carries it\n"
         "  entropy_simplify scan.ply out.ply --ratio 0.1 --importance\n"
         "                                                   and each point's importance as a scalar\n"
         "                                                   property (in LAS, an extra-bytes attribute)\n"
         "  entropy_simplify scan.xyz out.xyz --ratio 0.1 --indices kept.txt\n"
         "                                                   and the kept points' 0-based input indices,\n"
         "                                                   one per line, by rank\n"
         "  entropy_simplify scan.ply out.ply --ratio 0.1 --render view.png\n"
         "                                                   and a picture of the input beside the result\n"
         "  entropy_simplify scan.ply out.ply --ratio 0.05 --report\n"
         "                                                   and how far the input lies from the result\n"
         "  entropy_simplify scan.ply lod.ply --lod --report\n"
         "                                                   every point by rank, and the quality of its\n"
         "                                                   first 50, 20, 10, 5, 2 and 1%: a ratio chosen\n"
         "  entropy_simplify scan.ply out.ply --ratio 0.1 --threads 4\n"
         "                                                   on at most 4 threads, the same result\n"
         "LAZ is not supported (no LAZ library in Debian 12): decompress it first, e.g.\n"
         "  laszip -i scan.laz -o scan.las   or   pdal translate scan.laz scan.las\n"
         "\n"
         "Exit codes: 0 done; 1 failure (the output is left untouched); 2 usage error;\n"
         "130 interrupted by SIGINT, SIGTERM, SIGHUP, SIGQUIT or another stopping signal\n"
         "(the output is left untouched).";
}

namespace command_line_detail {

inline double finite_number(const std::string& option, const std::string& text)
{
  double value;
  if (!parse_number(text, value))
    throw Usage_error(option + " expects a number, got '" + text + "'");
  if (!std::isfinite(value))
    throw Usage_error(option + " must be finite, got '" + text + "'");
  return value;
}

inline unsigned long long whole_number(const std::string& option, const std::string& text)
{
  unsigned long long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error == std::errc::result_out_of_range)
    throw Usage_error(option + " " + text + " is out of range: at most " +
                      std::to_string(std::numeric_limits<unsigned long long>::max()));
  if (error != std::errc() || end != text.data() + text.size())
    throw Usage_error(option + " expects a whole number, got '" + text + "'");
  return value;
}

// The named choices of an option, e.g. `--order lowest`, to their values.
template <typename Value>
Value choice(const std::string& option, const std::string& text,
             const std::vector<std::pair<std::string, Value> >& choices)
{
  std::string names;
  for (const auto& c : choices)
  {
    if (c.first == text)
      return c.second;
    names += (names.empty() ? "" : " or ") + c.first;
  }
  throw Usage_error(option + " expects " + names + ", got '" + text + "'");
}

// The options' values, checked, and the rules between options.
inline void check(Settings& s, const std::string& ratio, const std::string& count, const std::string& k,
                  const std::string& feature_weight, const std::string& order)
{
  if (!ratio.empty() && !count.empty())
    throw Usage_error("give only one of --ratio and --count");
  if (ratio.empty() && count.empty() && !s.lod)
    throw Usage_error("give one of --ratio and --count (with --lod, they are optional: the level made exact)");
  if (s.write_normals && (s.lod || !s.indices.empty()))
    throw Usage_error(std::string("--write-normals does not combine with ") + (s.lod ? "--lod" : "--indices") +
                      ": the ranks are computed without the final normals");
  if (!ratio.empty())
  {
    s.ratio = finite_number("--ratio", ratio);
    if (!(*s.ratio > 0. && *s.ratio <= 1.))
      throw Usage_error("--ratio must lie in (0, 1], got " + ratio);
  }
  if (!count.empty())
  {
    const unsigned long long n = whole_number("--count", count);
    if (n == 0)
      throw Usage_error("--count must be at least 1");
    s.count = std::size_t((std::min)(n, (unsigned long long)(std::numeric_limits<std::size_t>::max)()));
  }
  const unsigned long long smallest_k = ES::internal::minimum_k(s.options.normal_estimation);
  const unsigned long long largest_k = ES::internal::Decremental_knn::largest_k;
  const unsigned long long kk = whole_number("-k", k);
  if (kk < smallest_k || kk > largest_k)
    throw Usage_error("-k must lie in [" + std::to_string(smallest_k) + ", " + std::to_string(largest_k) + "]" +
                      (smallest_k > 2 ? " with --normals jet" : "") + ", got " + k);
  s.k = unsigned(kk);
  if (!feature_weight.empty())
  {
    if (s.options.mode == ES::Mode::paper)
      throw Usage_error("--feature-weight applies to the default mode only");
    s.options.feature_weight = finite_number("--feature-weight", feature_weight);
    if (!(s.options.feature_weight >= 0. && s.options.feature_weight <= ES::Options::largest_feature_weight))
      throw Usage_error("--feature-weight must lie in [0, 100], got " + feature_weight);
  }
  if (!order.empty())
  {
    if (s.options.mode != ES::Mode::paper)
      throw Usage_error("--order applies to --mode paper only");
    s.options.removal_order =
      choice<ES::Removal_order>("--order", order, { { "lowest", ES::Removal_order::lowest_entropy_first },
                                                    { "highest", ES::Removal_order::highest_entropy_first } });
  }
}

} // namespace command_line_detail

// The settings of a run; std::nullopt when --help was asked for (and
// printed). Throws Usage_error.
inline std::optional<Settings> parse_command_line(int argc, const char* const* argv)
{
  Settings s;
  std::string ratio, count, k = "10", feature_weight, order, mode = "default", normals = "pca", threads;
  bool ascii = false, binary = false;
  CLI::App app("Simplifies the point set INPUT to exactly N points, or to the fraction R of its points "
               "(rounded up), keeping more points where the normals vary, and writes the kept points, "
               "with their properties, to OUTPUT.",
               "entropy_simplify");
  app.add_option("INPUT", s.input, "the point file to read (.ply .xyz .pwn .off .las)")->required();
  app.add_option("OUTPUT", s.output, "the file to write (.ply .xyz .pwn .off .las); never the input")->required();
  app.add_option("--ratio", ratio, "keep the fraction R of the points, 0 < R <= 1")->type_name("R");
  app.add_option("--count", count, "keep N points (all of them if N exceeds the input)")->type_name("N");
  app.add_flag("--lod", s.lod, "write every point, ordered by rank, so that any first m points are a "
                               "simplification to m points; PLY gets a 'scalar_rank' property (CloudCompare's "
                               "scalar field 'rank'). --ratio or --count gives the level whose points are "
                               "exactly those a run without --lod keeps, the longer prefixes unrelocated (default: no level, and the "
                               "prefixes at 50, 20, 10, 5, 2, 1, 0.5, ...% relocated)");
  app.add_flag("--importance", s.importance, "add each point's importance, the value its mode orders by, "
                                             "computed on the input: a PLY property 'scalar_importance' (double; "
                                             "CloudCompare's scalar field 'importance'), or a LAS extra-bytes "
                                             "attribute 'importance' after the record's own bytes");
  app.add_option("--render", s.render, "draw the input beside the result, coloured by importance, to the PNG "
                                       "file FILE.png (no display needed)")->type_name("FILE.png");
  app.add_option("--indices", s.indices, "write the 0-based input index of each point kept (with --lod, of "
                                         "every point) to FILE, one per line, by rank: without --lod, not in "
                                         "the output's order, which is the input's")->type_name("FILE");
  app.add_option("-k", k, "neighbours per point (default 10; 2-1000, 5-1000 with --normals jet)")->type_name("K");
  app.add_option("--mode", mode, "default | paper: weighted elimination with denser features (default), "
                                 "or the paper's method, which keeps at least k + 1 points")->type_name("M");
  app.add_option("--feature-weight", feature_weight, "default mode: features keep up to 1 + W times the "
                                                     "density of flat regions (default 3; 0: no entropy term; at most 100)")
    ->type_name("W");
  app.add_option("--order", order, "paper mode: lowest | highest, which entropy is removed first "
                                   "(default lowest, the paper's text)")->type_name("O");
  app.add_option("--normals", normals, "pca | jet: normal estimation (default pca)")->type_name("E");
  app.add_flag("--write-normals", s.write_normals, "store the final normals of the kept points in OUTPUT "
                                                   "(PLY, XYZ), replacing the input's normals, if any");
  CLI::Option* ascii_flag = app.add_flag("--ascii", ascii, "write PLY as text");
  CLI::Option* binary_flag = app.add_flag("--binary", binary, "write PLY as binary (little-endian)");
  ascii_flag->excludes(binary_flag);
  app.add_option("--threads", threads, "use at most N worker threads (default, and at most: every hardware "
                                     "thread); the result does not depend on N")->type_name("N");
  app.add_flag("--report", s.report, "print the quality of the result: the mean and greatest distance from "
                                     "the input points to the kept ones, and the point-to-plane error, over "
                                     "the input's bounding-box diagonal (printed even with --quiet); with "
                                     "--lod, that of the first points by rank at 50, 20, 10, 5, 2 and 1% and "
                                     "at the level asked for");
  app.add_flag("-q,--quiet", s.quiet, "print nothing but errors (and the report, if asked for)");
  app.footer(examples_text());
  try
  {
    app.parse(argc, argv);
  }
  catch (const CLI::CallForHelp&)
  {
    std::cout << app.help();
    return std::nullopt;
  }
  catch (const CLI::ParseError& e)
  {
    throw Usage_error(e.what());
  }
  using command_line_detail::choice;
  s.options.mode = choice<ES::Mode>("--mode", mode, { { "default", ES::Mode::weighted_elimination },
                                                      { "paper", ES::Mode::paper } });
  s.options.normal_estimation = choice<ES::Normal_estimation>(
    "--normals", normals, { { "pca", ES::Normal_estimation::pca }, { "jet", ES::Normal_estimation::jet } });
  command_line_detail::check(s, ratio, count, k, feature_weight, order);
  if (!threads.empty())
  {
    const unsigned long long n = command_line_detail::whole_number("--threads", threads);
    if (n == 0)
      throw Usage_error("--threads must be at least 1");
    s.threads = std::size_t((std::min)(n, (unsigned long long)(std::numeric_limits<int>::max)()));
  }
  if (ascii || binary)
    s.binary = binary;
  return s;
}

} // namespace entropy_simplify

#endif // ENTROPY_SIMPLIFY_COMMAND_LINE_H
