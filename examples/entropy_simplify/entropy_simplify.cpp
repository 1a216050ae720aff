// entropy_simplify: the command-line program of the package.
//
//   entropy_simplify INPUT OUTPUT (--ratio R | --count N) [options]
//
// Checks everything it can before computing (options, formats, the output's
// folder, the input), then reads, simplifies and writes, never over the
// input and never leaving a partial file (safe_output.h). `--help` gives the
// options, an example for each format and the exit codes.

#include "command_line.h"
#include "input_file.h"
#include "point_files.h"
#include "progress.h"
#include "quality_report.h"
#include "safe_output.h"
#include "simplify_cloud.h"
#include "thread_limit.h"

#include <CGAL/Real_timer.h>

#include <cstdio>
#include <exception>
#include <iostream>
#include <new>
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
}

void print_notes(const Settings& s, const Cloud& cloud, const Point_table& written, Format out)
{
  if (s.quiet)
    return;
  for (const std::string& note : cloud.notes)
    std::cerr << "entropy_simplify: note: " << note << "\n";
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
    return exit_done;
  const Settings& s = *settings;
  const Thread_limit thread_limit(s.threads);
  const Format in = format_of(s.input), out = format_of(s.output);
  check_formats(s, in, out);

  remove_output_on_signals();
  const Input_file input = reading(s.input, [&] { return Input_file(s.input); });
  Safe_output output(s.output, s.input);

  CGAL::Real_timer timer;
  timer.start();
  const Cloud cloud = reading(s.input, [&] { return read_cloud(input.bytes(), in); });

  Progress_bar progress(!s.quiet);
  std::vector<std::array<double, 3> > normals;
  const std::vector<std::size_t> kept =
    simplify_cloud<CGAL::Parallel_if_available_tag>(cloud, s, std::ref(progress), normals);
  progress.finish();

  if (out == Format::las)
    write_las(output.sink(), *cloud.las, kept);
  else
  {
    const Point_table table = output_table(cloud, kept, s.write_normals ? &normals : nullptr);
    print_notes(s, cloud, table, out);
    write_table(output.sink(), table, out, s.binary.value_or(in != Format::ply || cloud.binary_ply), cloud.comments);
  }
  output.commit();
  timer.stop();

  if (!s.quiet)
    std::printf("entropy_simplify: kept %zu of %zu points (%.4g%%) in %.3g s, peak memory %.0f MiB; wrote %s\n",
                kept.size(), cloud.size(), 100. * double(kept.size()) / double(cloud.size()), timer.time(),
                peak_memory_mib(), s.output.c_str());
  // measured once the output is safe, so that it never delays the file
  if (s.report)
    print_quality_report(quality_of<CGAL::Parallel_if_available_tag>(cloud, kept));
  return exit_done;
}

} // namespace
} // namespace entropy_simplify

int main(int argc, char** argv)
{
  using namespace entropy_simplify;
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
