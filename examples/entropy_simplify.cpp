// entropy_simplify: the command-line front end of the package.
//
//   entropy_simplify INPUT OUTPUT (--ratio R | --count N) [options]
//
// Reads any point set format CGAL::IO reads (XYZ, PLY, OFF, ...), keeps the
// extra PLY properties of the kept points, writes the format of OUTPUT's
// extension. Exits with 0 on success, 1 on a failure to read, simplify or
// write, 2 on bad options.

#include <CGAL/Entropy_simplification/entropy_simplify_point_set.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>
#include <CGAL/Real_timer.h>

#include <cstdlib>
#include <exception>
#include <iomanip>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_set = CGAL::Point_set_3<Kernel::Point_3, Kernel::Vector_3>;
namespace ES = CGAL::Entropy_simplification;

namespace {

const char* const usage =
  "usage: entropy_simplify INPUT OUTPUT (--ratio R | --count N) [options]\n"
  "\n"
  "Simplifies the point set INPUT to exactly N points, or to the fraction R of\n"
  "its points (rounded up), guided by the local entropy of normals, and writes\n"
  "the kept points, with all their properties, to OUTPUT. The formats are\n"
  "those CGAL::IO reads and writes for point sets (.xyz, .ply, .off, ...),\n"
  "chosen by file extension.\n"
  "\n"
  "options:\n"
  "  --ratio R          keep the fraction R of the points, 0 < R <= 1\n"
  "  --count N          keep N points (all of them if N exceeds the input)\n"
  "  -k K               neighbours per point (default 10)\n"
  "  --mode M           default | paper: weighted elimination with denser\n"
  "                     features (default), or the paper's method\n"
  "  --feature-weight W default mode: features keep up to 1 + W times the\n"
  "                     density of flat regions (default 3; 0: no entropy term)\n"
  "  --order O          paper mode: lowest | highest, which entropy is removed\n"
  "                     first (default lowest, the paper's text)\n"
  "  --normals E        pca | jet: normal estimation (default pca)\n"
  "  --write-normals    store the final normals of the kept points in OUTPUT\n"
  "                     (replacing the input's normals, if any)\n"
  "  --quiet            print nothing but errors\n"
  "  -h, --help         print this help\n";

struct Command_line
{
  std::string input, output;
  std::optional<double> ratio;
  std::optional<long long> count;
  unsigned int k = 10;
  ES::Options options;
  bool write_normals = false;
  bool quiet = false;
};

struct Bad_option : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

double parse_number(const std::string& option, const std::string& text)
{
  std::size_t used = 0;
  double value = 0.;
  try
  {
    value = std::stod(text, &used);
  }
  catch (const std::exception&)
  {
    used = 0;
  }
  if (used != text.size() || text.empty())
    throw Bad_option(option + " expects a number, got '" + text + "'");
  return value;
}

long long parse_integer(const std::string& option, const std::string& text)
{
  const double value = parse_number(option, text);
  if (value != double((long long)value))
    throw Bad_option(option + " expects an integer, got '" + text + "'");
  return (long long)value;
}

// One of the named choices of an option, e.g. `--order lowest`.
template <typename Value>
Value parse_choice(const std::string& option, const std::string& text,
                   const std::vector<std::pair<std::string, Value> >& choices)
{
  std::string names;
  for (const auto& choice : choices)
  {
    if (choice.first == text)
      return choice.second;
    names += (names.empty() ? "" : " or ") + choice.first;
  }
  throw Bad_option(option + " expects " + names + ", got '" + text + "'");
}

Command_line parse(int argc, char** argv)
{
  Command_line c;
  std::vector<std::string> positional;
  bool order_given = false, feature_weight_given = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc)
        throw Bad_option(a + " expects a value");
      return argv[++i];
    };
    if (a == "-h" || a == "--help")
    {
      std::cout << usage;
      std::exit(EXIT_SUCCESS);
    }
    else if (a == "--ratio")
    {
      c.ratio = parse_number(a, value());
      if (!(*c.ratio > 0. && *c.ratio <= 1.))
        throw Bad_option("--ratio must lie in (0, 1]");
    }
    else if (a == "--count")
    {
      c.count = parse_integer(a, value());
      if (*c.count <= 0)
        throw Bad_option("--count must be positive");
    }
    else if (a == "-k")
    {
      const long long k = parse_integer(a, value());
      if (k < 1 || k > 1000)
        throw Bad_option("-k must lie in [1, 1000]");
      c.k = unsigned(k);
    }
    else if (a == "--mode")
      c.options.mode = parse_choice<ES::Mode>(
        a, value(), { { "default", ES::Mode::weighted_elimination }, { "paper", ES::Mode::paper } });
    else if (a == "--feature-weight")
    {
      c.options.feature_weight = parse_number(a, value());
      if (!(c.options.feature_weight >= 0.))
        throw Bad_option("--feature-weight must be non-negative");
      feature_weight_given = true;
    }
    else if (a == "--order")
    {
      order_given = true;
      c.options.removal_order = parse_choice<ES::Removal_order>(
        a, value(), { { "lowest", ES::Removal_order::lowest_entropy_first },
                      { "highest", ES::Removal_order::highest_entropy_first } });
    }
    else if (a == "--normals")
      c.options.normal_estimation = parse_choice<ES::Normal_estimation>(
        a, value(), { { "pca", ES::Normal_estimation::pca }, { "jet", ES::Normal_estimation::jet } });
    else if (a == "--write-normals")
      c.write_normals = true;
    else if (a == "--quiet")
      c.quiet = true;
    else if (a.size() > 1 && a[0] == '-')
      throw Bad_option("unknown option '" + a + "'");
    else
      positional.push_back(a);
  }
  if (positional.size() != 2)
    throw Bad_option("expected INPUT and OUTPUT, got " + std::to_string(positional.size()) + " file names");
  if (c.ratio.has_value() == c.count.has_value())
    throw Bad_option("give exactly one of --ratio and --count");
  if (order_given && c.options.mode != ES::Mode::paper)
    throw Bad_option("--order applies to --mode paper only");
  if (feature_weight_given && c.options.mode == ES::Mode::paper)
    throw Bad_option("--feature-weight applies to the default mode only");
  c.input = positional[0];
  c.output = positional[1];
  return c;
}

// Simplifies `points` in place and returns the number kept.
std::size_t simplify(Point_set& points, const Command_line& c)
{
  int last_percent = -1;
  const std::function<bool(double)> progress = [&](double done) {
    const int percent = int(done * 100.);
    if (!c.quiet && percent != last_percent)
    {
      std::cerr << "\r" << percent << "% " << std::flush;
      last_percent = percent;
    }
    return true;
  };
  if (c.write_normals)
    points.add_normal_map();

  auto simplify_with = [&](const auto& target) {
    if (c.write_normals)
      return CGAL::entropy_simplify_point_set<CGAL::Parallel_if_available_tag>(
        points, c.k, target.callback(progress).normal_map(points.normal_map()), c.options);
    return CGAL::entropy_simplify_point_set<CGAL::Parallel_if_available_tag>(
      points, c.k, target.callback(progress), c.options);
  };
  const auto first_removed =
    c.ratio ? simplify_with(CGAL::parameters::select_percentage(*c.ratio * 100.))
            : simplify_with(CGAL::parameters::number_of_output_points(std::size_t(*c.count)));
  if (!c.quiet)
    std::cerr << "\r";
  points.remove(first_removed, points.end());
  points.collect_garbage();
  return points.size();
}

} // namespace

int main(int argc, char** argv)
{
  Command_line c;
  try
  {
    c = parse(argc, argv);
  }
  catch (const Bad_option& e)
  {
    std::cerr << "entropy_simplify: " << e.what() << "\n\n" << usage;
    return 2;
  }

  Point_set points;
  if (!CGAL::IO::read_point_set(c.input, points))
  {
    std::cerr << "entropy_simplify: cannot read a point set from '" << c.input << "'\n";
    return 1;
  }
  const std::size_t read = points.size();

  CGAL::Real_timer timer;
  timer.start();
  std::size_t kept = 0;
  try
  {
    kept = simplify(points, c);
  }
  catch (const std::exception& e)
  {
    std::cerr << "entropy_simplify: " << e.what() << "\n";
    return 1;
  }
  timer.stop();

  if (!CGAL::IO::write_point_set(c.output, points, CGAL::parameters::stream_precision(17)))
  {
    std::cerr << "entropy_simplify: cannot write '" << c.output << "'\n";
    return 1;
  }
  if (!c.quiet)
    std::cout << "read " << read << " points from " << c.input << "\n"
              << "kept " << kept << " points (" << std::setprecision(4) << 100. * double(kept) / double(read)
              << "%) in " << std::setprecision(3) << timer.time() << " s\n"
              << "wrote " << c.output << "\n";
  return 0;
}
