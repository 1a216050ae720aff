// entropy_simplify: the command-line program of the package.
//
//   entropy_simplify INPUT OUTPUT (--ratio R | --count N) [options]
//
// Checks everything it can before computing (options, formats, the output's
// folder, the input), then reads, simplifies and writes, never over the
// input and never leaving a partial file (safe_output.h). `--help` gives the
// options, an example for each format and the exit codes.

#include "command_line.h"
#include "indices_file.h"
#include "input_file.h"
#include "las_extra_bytes.h"
#include "point_files.h"
#include "progress.h"
#include "render_png.h"
#include "quality_report.h"
#include "safe_output.h"
#include "simplify_cloud.h"
#include "thread_limit.h"

#include <CGAL/Real_timer.h>

#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <limits>
#include <new>
#include <optional>
#include <system_error>
#include <tuple>
#include <vector>

namespace entropy_simplify {
namespace {

// Checks what can be checked from the names alone: a usage error.
void check_formats(const Settings& s, Format in, Format out)
{
  if (out == Format::las && in != Format::las)
    throw Usage_error("LAS output needs LAS input: a LAS file's scale and offset, which its integer coordinates "
                      "need, come from the input's header; write .ply to keep the coordinates as doubles");
  if (s.binary && out != Format::ply)
    throw Usage_error(std::string(*s.binary ? "--binary" : "--ascii") + " applies to PLY output only");
  if (s.write_normals && (out == Format::las || out == Format::off))
    throw Usage_error(std::string("--write-normals needs an output that stores normals (PLY or XYZ); ") +
                      (out == Format::las ? "LAS" : "plain OFF") + " does not");
  if (s.importance && (out == Format::xyz || out == Format::off))
    throw Usage_error("--importance needs an output that stores a scalar property (PLY or LAS); XYZ and OFF do not");
  namespace fs = std::filesystem;
  // a link to what is no path, as /dev/stdout to a pipe, is compared as named
  // (writing there is refused later, with the reason)
  const auto resolved = [](const std::string& name) {
    std::error_code error;
    const fs::path path = fs::weakly_canonical(fs::absolute(name), error);
    return error ? fs::absolute(name).lexically_normal() : path;
  };
  const auto same_file = [&](const std::string& a, const std::string& b) {
    return !a.empty() && !b.empty() && resolved(a) == resolved(b);
  };
  if (same_file(s.indices, s.output) || same_file(s.render, s.output) || same_file(s.render, s.indices))
    throw Usage_error("--indices, --render and OUTPUT must name different files");
  if (!s.render.empty() && fs::path(s.render).extension() != ".png" && fs::path(s.render).extension() != ".PNG")
    throw Usage_error("--render writes PNG: give a file name ending in .png, got '" + s.render + "'");
}

// What --importance says it is, in the file.
const char* importance_description(const Settings& s)
{
  return s.options.mode == ES::Mode::paper ? "entropy of normal angles, nats" : "feature strength, 0 to 1";
}

// The points written, as a table, with --lod's ranks (PLY only: elsewhere
// the order alone carries them) and --importance's values. Their names take
// CloudCompare's prefix for scalar fields, which it opens as such (as
// 'rank' and 'importance'), and ignores without it.
Point_table table_to_write(const Settings& s, const Cloud& cloud, const std::vector<std::size_t>& rows, Format out,
                           const std::vector<std::array<double, 3> >& normals, const std::vector<double>& importance)
{
  Point_table table = output_table(cloud, rows, s.write_normals ? &normals : nullptr);
  if (s.lod && out == Format::ply)
    set_column(table, "scalar_rank",
               rows.size() <= std::numeric_limits<std::uint32_t>::max() ? Scalar_type::uint32 : Scalar_type::float64,
               [](std::size_t r) { return double(r); });
  if (s.importance)
    set_column(table, "scalar_importance", Scalar_type::float64, [&](std::size_t r) { return importance[rows[r]]; });
  return table;
}

// Throws Read_error when a PLY output would replace a property of the input
// with --lod's ranks or --importance's values, without a word.
void check_added_properties(const Settings& s, const Cloud& cloud, Format out)
{
  if (out != Format::ply)
    return;
  for (const auto& [added, name, option] : { std::tuple{ s.lod, "scalar_rank", "--lod" },
                                             std::tuple{ s.importance, "scalar_importance", "--importance" } })
    if (added && cloud.table.find(name))
      throw Read_error(std::string("it already has a property '") + name + "', which " + option +
                       " would replace: rename it first, or write without " + option);
}

// What the input holds that is not kept, or that disagrees with its header:
// said before the computation, so that a run on the wrong data can be
// stopped.
void print_input_notes(const Settings& s, const Cloud& cloud)
{
  if (s.quiet)
    return;
  for (const std::string& note : cloud.notes)
    std::cerr << "entropy_simplify: note: " << note << "\n";
}

// What the output's format does not store.
void print_output_notes(const Settings& s, const Cloud& cloud, const Point_table& written, Format out)
{
  if (s.quiet)
    return;
  if (cloud.las && out != Format::las && las_has_unconverted_bytes(*cloud.las))
    std::cerr << "entropy_simplify: note: the LAS records' waveform packets and extra bytes are not converted; "
                 "write .las to keep them\n";
  const std::vector<std::string> dropped = columns_not_stored(written, out);
  if (!dropped.empty())
  {
    std::cerr << "entropy_simplify: note: " << s.output << " stores no";
    for (const std::string& name : dropped)
      std::cerr << " " << name;
    std::cerr << "; write .ply to keep every property\n";
  }
}

// What `read` returns; a Read_error it throws names the input.
template <typename Read>
auto reading(const std::string& path, const Read& read)
{
  try
  {
    return read();
  }
  catch (const Read_error& e)
  {
    throw Read_error("cannot read '" + path + "': " + e.what());
  }
}

int run(int argc, char** argv)
{
  const std::optional<Settings> settings = parse_command_line(argc, argv);
  if (!settings)
  {
    flush_standard_output("");
    return exit_done;
  }
  const Settings& s = *settings;
  const Thread_limit thread_limit(s.threads);
  const Format in = format_of(s.input), out = format_of(s.output);
  check_formats(s, in, out);

  remove_output_on_signals();
  const Input_file input = reading(s.input, [&] { return Input_file(s.input); });
  Safe_output output(s.output, s.input);
  std::optional<Safe_output> indices, picture;
  if (!s.indices.empty())
    indices.emplace(s.indices, s.input);
  if (!s.render.empty())
    picture.emplace(s.render, s.input);

  CGAL::Real_timer timer;
  timer.start();
  const Cloud cloud = reading(s.input, [&] { return read_cloud(input.bytes(), in); });
  print_input_notes(s, cloud);
  if (s.importance && out == Format::las)
    reading(s.input, [&] { return check_room_for_attribute(*cloud.las, "importance"); });
  reading(s.input, [&] { return check_added_properties(s, cloud, out); });

  // one bar for both passes: the importance takes about a third of a run
  Progress_bar progress(!s.quiet);
  const bool with_importance = s.importance || picture;
  const double importance_share = with_importance ? 0.3 : 0.;
  const std::vector<double> importance =
    with_importance ? importance_of_rows<CGAL::Parallel_if_available_tag>(
                        cloud, s, [&](double f) { return progress(importance_share * f); })
                    : std::vector<double>();
  std::vector<std::array<double, 3> > normals;
  const Selection selection = simplify_cloud<CGAL::Parallel_if_available_tag>(
    cloud, s, [&](double f) { return progress(importance_share + (1. - importance_share) * f); }, normals);
  progress.finish();

  const std::vector<std::size_t>& written = s.lod ? selection.by_rank : selection.kept;
  if (out == Format::las && s.importance)
    write_las_with_attribute(output.sink(), *cloud.las, written, "importance", importance_description(s), importance);
  else if (out == Format::las)
    write_las(output.sink(), *cloud.las, written);
  else
  {
    const Point_table table = table_to_write(s, cloud, written, out, normals, importance);
    print_output_notes(s, cloud, table, out);
    write_table(output.sink(), table, out, s.binary.value_or(in != Format::ply || cloud.binary_ply), cloud.comments);
  }
  if (indices)
    write_indices(indices->sink(), selection.by_rank);
  if (picture)
    write_png(picture->sink(), render_side_by_side(cloud, selection.kept, importance));
  // all complete before any replaces its target
  commit_together({ &output, indices ? &*indices : nullptr, picture ? &*picture : nullptr });
  timer.stop();

  const std::vector<std::size_t>& kept = selection.kept;
  const std::string targets =
    s.output + (s.indices.empty() ? "" : ", " + s.indices) + (s.render.empty() ? "" : ", " + s.render);
  const bool level_asked = s.ratio || s.count;
  if (!s.quiet && s.lod && level_asked)
    std::printf("entropy_simplify: wrote the %zu points by rank, the first %zu exactly the simplification asked "
                "for, in %.3g s, peak memory %.0f MiB; wrote %s\n",
                cloud.size(), kept.size(), timer.time(), peak_memory_mib(), targets.c_str());
  else if (!s.quiet && s.lod)
    std::printf("entropy_simplify: wrote the %zu points by rank, in %.3g s, peak memory %.0f MiB; wrote %s\n",
                cloud.size(), timer.time(), peak_memory_mib(), targets.c_str());
  else if (!s.quiet)
    std::printf("entropy_simplify: kept %zu of %zu points (%.4g%%) in %.3g s, peak memory %.0f MiB; wrote %s\n",
                kept.size(), cloud.size(), 100. * double(kept.size()) / double(cloud.size()), timer.time(),
                peak_memory_mib(), targets.c_str());
  const std::string files_written =
    "; " + targets + (s.indices.empty() && s.render.empty() ? " is" : " are") + " written";
  flush_standard_output(files_written);
  // measured once the output is safe, so that it never delays the file
  if (s.report && s.lod)
    print_prefix_reports(prefix_reports<CGAL::Parallel_if_available_tag>(
      cloud, selection.by_rank, level_asked ? std::optional<std::size_t>(kept.size()) : std::nullopt));
  else if (s.report)
    print_quality_report(quality_of<CGAL::Parallel_if_available_tag>(cloud, kept));
  flush_standard_output(files_written);
  return exit_done;
}

} // namespace
} // namespace entropy_simplify

int main(int argc, char** argv)
{
  using namespace entropy_simplify;
  keep_standard_descriptors_taken();
  buffer_standard_output();
  try
  {
    return run(argc, argv);
  }
  catch (const Usage_error& e)
  {
    std::cerr << "entropy_simplify: " << e.what() << "\nRun 'entropy_simplify --help' for the options.\n";
    return exit_usage;
  }
  catch (const std::bad_alloc&)
  {
    std::cerr << "entropy_simplify: out of memory; nothing was written\n";
    return exit_failure;
  }
  catch (const std::exception& e)
  {
    std::cerr << "entropy_simplify: " << e.what() << "\n";
    return exit_failure;
  }
  catch (...)
  {
    std::cerr << "entropy_simplify: unexpected error; nothing was written\n";
    return exit_failure;
  }
}
