// Tests of the program's parts other than PLY and LAS (which have their own
// files): the XYZ and OFF formats, the safe output, the choice of format, and
// the simplification of a read cloud, georeferenced LAS included.

#include <catch2/catch.hpp>

#include "indices_file.h"
#include "input_file.h"
#include "las_extra_bytes.h"
#include "point_files.h"
#include "quality_report.h"
#include "render_png.h"
#include "require_tbb.h"
#include "safe_output.h"
#include "thread_limit.h"
#include "simplify_cloud.h"

#include <sys/stat.h>

#include <stb_image.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace es = entropy_simplify;

namespace {

std::string cli_input(const std::string& name) { return std::string(ES_CLI_INPUTS_DIR) + "/" + name; }

std::string file_text(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_text(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// A fresh, empty folder for one test.
std::string fresh_folder(const std::string& name)
{
  const std::string folder = "program_test_" + name;
  std::system(("rm -rf '" + folder + "' && mkdir -p '" + folder + "'").c_str());
  return folder;
}

std::size_t hidden_files_in(const std::string& folder)
{
  const std::string listing = folder + "/listing";
  std::system(("ls -A '" + folder + "' | grep -c '^\\.' > '" + listing + "'").c_str());
  return std::stoul(file_text(listing));
}

es::Settings count_settings(std::size_t count, CGAL::Entropy_simplification::Mode mode)
{
  es::Settings s;
  s.count = count;
  s.options.mode = mode;
  return s;
}

// What the program selects, without progress or normals.
template <typename ConcurrencyTag>
es::Selection selection_of(const es::Cloud& cloud, const es::Settings& s)
{
  std::vector<std::array<double, 3> > normals;
  return es::simplify_cloud<ConcurrencyTag>(cloud, s, std::function<bool(double)>(), normals);
}

template <typename ConcurrencyTag>
std::vector<std::size_t> kept_rows(const es::Cloud& cloud, const es::Settings& s)
{
  return selection_of<ConcurrencyTag>(cloud, s).kept;
}

} // namespace

TEST_CASE("XYZ: 3 or 6 numbers a line, comments and blank lines skipped, exact round trip", "[program][xyz]")
{
  const es::Point_table t = es::read_xyz("# a comment\n1 2 3 0 0 1\n\n  -4.5\t5e-300 +6 0 1 0\r\n");
  REQUIRE(t.size() == 2);
  REQUIRE(t.columns.size() == 6);
  CHECK(t.columns[0].values == std::vector<double>{ 1., -4.5 });
  CHECK(t.columns[1].values == std::vector<double>{ 2., 5e-300 });
  CHECK(t.find("nz")->values == std::vector<double>{ 1., 0. });

  es::Point_table extremes;
  for (const char* name : { "x", "y", "z" })
    extremes.column(name, es::Scalar_type::float64).values = {
      0.1, -0.0, 1e308, 4.9e-324, 123456789.123456789, -2.2250738585072014e-308 };
  es::String_sink out;
  es::write_xyz(out, extremes);
  const es::Point_table back = es::read_xyz(out.bytes);
  for (std::size_t c = 0; c < 3; ++c)
    CHECK(back.columns[c].values == extremes.columns[c].values);
  CHECK(out.bytes.find("0.1 0.1 0.1\n") == 0);
}

TEST_CASE("XYZ: a line of another length is an error naming the line", "[program][xyz]")
{
  // CR alone ends a line too (old Mac files): never two points read as one with a normal
  CHECK(es::read_xyz("1 2 3\r4 5 6\n").size() == 2);
  CHECK(es::read_xyz("1 2 3\r\n4 5 6\r7 8 9").size() == 3);
  // what the file holds is shown, but not its unprintable bytes
  CHECK_THROWS_WITH(es::read_xyz(std::string("1 2 \0\x01\n", 7)), Catch::Contains("got '1 2 ?" "?'"));
  CHECK_THROWS_WITH(es::read_xyz("1 2 3\n4 5\n"), Catch::Contains("line 2 holds 2 numbers"));
  CHECK_THROWS_WITH(es::read_xyz("1 2 3 4\n"), Catch::Contains("line 1 holds 4 numbers; XYZ lines hold 3 or 6"));
  CHECK_THROWS_WITH(es::read_xyz("1 2 3 4 5 6 7\n"), Catch::Contains("line 1: an XYZ line holds 3 or 6 numbers"));
  CHECK_THROWS_WITH(es::read_xyz("1 2 x\n"), Catch::Contains("line 1: an XYZ line holds 3 or 6"));
  CHECK_THROWS_WITH(es::read_xyz("1 2 3\n1 2 3 # no comments after numbers\n"), Catch::Contains("line 2"));
  CHECK(es::read_xyz("\n# nothing\n").size() == 0);
}

TEST_CASE("OFF: OFF and NOFF vertices, faces dropped with a note, counts checked", "[program][off]")
{
  const es::Off_cloud off = es::read_off("OFF # a mesh\n# comment\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  CHECK(off.table.size() == 3);
  CHECK(off.table.find("x")->values == std::vector<double>{ 0., 1., 0. });
  REQUIRE(off.notes.size() == 1);
  CHECK(off.notes[0] == "1 face dropped: a simplified point set has no faces");

  // a header that counts fewer vertices than the file holds: noted, with
  // no faces declared or where a face should follow
  const std::string undercount = "line 5, after the 2 vertices that the header declares, is not ";
  CHECK(es::read_off("OFF\n2 0 0\n0 0 0\n1 1 1\n0.5 0.5 0.5\n").notes ==
        std::vector<std::string>{ undercount + "read, as the header declares no faces: if more vertices are there, "
                                               "the header's count is wrong" });
  CHECK(es::read_off("OFF\n2 1 0\n0 0 0\n1 1 1\n0.5 0.5 0.5\n3 0 1 2\n").notes ==
        std::vector<std::string>{ "1 face dropped: a simplified point set has no faces",
                                  undercount + "a face: if more vertices are there, the header's count is wrong" });
  CHECK(es::read_off("OFF\n2 0 0\n0 0 0\n1 1 1\n# a comment, then blank lines\n\n \n").notes.empty());

  const es::Off_cloud noff = es::read_off("NOFF 2 0 0\n0 0 0 0 0 1\n1 1 1 0 1 0\n");
  CHECK(noff.table.find("ny")->values == std::vector<double>{ 0., 1. });

  CHECK_THROWS_WITH(es::read_off("OFF\n4000000000 0 0\n0 0 0\n"), Catch::Contains("claims 4000000000 vertices"));
  CHECK_THROWS_WITH(es::read_off("OFF\n3 0 0\n0 0 0\n1 1 1\n# room for a third vertex\n"),
                    Catch::Contains("the file is truncated: it ends after 2 of 3 vertices"));
  CHECK_THROWS_WITH(es::read_off("OFF\n3 0 0\n0 0 0\n1 1 1\n"), Catch::Contains("claims 3 vertices"));
  CHECK(es::read_off("OFF\n2 0 0\n0 0 0\n1 1 1").table.size() == 2);
  CHECK_THROWS_WITH(es::read_off("OFF\n-3 0 0\n"), Catch::Contains("vertex count is not a count"));
  CHECK_THROWS_WITH(es::read_off("OFF\n99999999999999999999999 0 0\n"), Catch::Contains("not a count"));
  CHECK_THROWS_WITH(es::read_off("OFF\n1 0\n"), Catch::Contains("needs 3 counts"));
  CHECK_THROWS_WITH(es::read_off("OFF\n1 0 0\n0 0\n# padding\n"), Catch::Contains("line 3 holds 2 values"));
  CHECK_THROWS_WITH(es::read_off("4OFF\n"), Catch::Contains("other OFF variants"));

  es::String_sink out;
  es::write_off(out, noff.table);
  CHECK(out.bytes == "OFF\n2 0 0\n0 0 0\n1 1 1\n");
}

TEST_CASE("The format is the extension's, in any case, and LAZ says how to convert", "[program]")
{
  CHECK(es::format_of("a/b.PLY") == es::Format::ply);
  CHECK(es::format_of("scan.pwn") == es::Format::xyz);
  CHECK(es::format_of("x.Las") == es::Format::las);
  CHECK_THROWS_WITH(es::format_of("scan.laz"), Catch::Contains("laszip"));
  CHECK_THROWS_AS(es::format_of("folder.ply/scan"), es::Usage_error);
  CHECK_THROWS_AS(es::format_of("scan.txt"), es::Usage_error);
}

TEST_CASE("Safe output: the target changes only on commit, and never partly", "[program][safe output]")
{
  const std::string folder = fresh_folder("safe_output");
  const std::string target = folder + "/out.xyz", input = folder + "/in.xyz";
  write_text(target, "old\n");
  write_text(input, "1 2 3\n");
  ::chmod(target.c_str(), 0640);

  SECTION("committed: the new content, the old permissions, no temporary file")
  {
    es::Safe_output output(target, input);
    CHECK(hidden_files_in(folder) == 1); // the temporary file, from the start
    output.sink().write("new\n");
    CHECK(file_text(target) == "old\n");
    output.commit();
    CHECK(file_text(target) == "new\n");
    struct stat status;
    ::stat(target.c_str(), &status);
    CHECK((status.st_mode & 0777) == 0640);
    CHECK(hidden_files_in(folder) == 0);
  }
  SECTION("abandoned (an exception, a failure): the target untouched, no temporary file")
  {
    {
      es::Safe_output output(target, input);
      output.sink().write(std::string(3 << 20, 'x'));
    }
    CHECK(file_text(target) == "old\n");
    CHECK(hidden_files_in(folder) == 0);
  }
  SECTION("a full disk: the write fails, with the reason")
  {
    ::setenv("ENTROPY_SIMPLIFY_TEST_FREE_BYTES", "100", 1);
    {
      es::Safe_output output(target, input);
      ::unsetenv("ENTROPY_SIMPLIFY_TEST_FREE_BYTES");
      output.sink().write(std::string(99, 'x'));
      output.sink().write("y\n");
      CHECK_THROWS_WITH(output.commit(), Catch::Contains("out.xyz': No space left on device"));
    }
    CHECK(file_text(target) == "old\n");
    CHECK(hidden_files_in(folder) == 0);
  }
  SECTION("the input, a folder or a missing folder are refused before anything is written")
  {
    CHECK_THROWS_WITH(es::Safe_output(input, input), Catch::Contains("is the input file"));
    CHECK_THROWS_WITH(es::Safe_output(folder, input), Catch::Contains("is a folder"));
    CHECK_THROWS_WITH(es::Safe_output(folder + "/none/x.ply", input), Catch::Contains("No such file or directory"));
    CHECK(file_text(input) == "1 2 3\n");
    CHECK(hidden_files_in(folder) == 0);
  }
}

TEST_CASE("The program's simplification: exact count, kept rows in order, sequential = parallel",
          "[program][simplify]")
{
  test_parallel::require_tbb();
  es::Input_file file(cli_input("grid.xyz"));
  const es::Cloud cloud = es::read_cloud(file.bytes(), es::Format::xyz);
  REQUIRE(cloud.size() == 144);
  for (auto mode : { CGAL::Entropy_simplification::Mode::weighted_elimination,
                     CGAL::Entropy_simplification::Mode::paper })
  {
    const es::Settings s = count_settings(37, mode);
    const std::vector<std::size_t> sequential = kept_rows<CGAL::Sequential_tag>(cloud, s);
    const std::vector<std::size_t> parallel =
      test_parallel::on_two_threads_or_more([&] { return kept_rows<test_parallel::Parallel_tag>(cloud, s); });
    CHECK(sequential.size() == 37);
    CHECK(std::is_sorted(sequential.begin(), sequential.end()));
    CHECK(std::adjacent_find(sequential.begin(), sequential.end()) == sequential.end());
    CHECK(sequential.back() < 144);
    CHECK(sequential == parallel);
  }
}

TEST_CASE("Ranked runs (--lod, --indices): the level's rows are the plain run's, the first by rank",
          "[program][simplify][lod]")
{
  test_parallel::require_tbb();
  es::Input_file file(cli_input("grid.xyz"));
  const es::Cloud cloud = es::read_cloud(file.bytes(), es::Format::xyz);
  for (auto mode : { CGAL::Entropy_simplification::Mode::weighted_elimination,
                     CGAL::Entropy_simplification::Mode::paper })
  {
    const es::Settings plain = count_settings(37, mode);
    es::Settings lod = plain, indices = plain;
    lod.lod = true;
    indices.indices = "kept.txt";
    const std::vector<std::size_t> expected = kept_rows<CGAL::Sequential_tag>(cloud, plain);
    const es::Selection all = selection_of<CGAL::Sequential_tag>(cloud, lod);
    const es::Selection parallel =
      test_parallel::on_two_threads_or_more([&] { return selection_of<test_parallel::Parallel_tag>(cloud, lod); });
    const es::Selection kept = selection_of<CGAL::Sequential_tag>(cloud, indices);
    CHECK(all.kept == expected);
    CHECK(kept.kept == expected);
    std::vector<std::size_t> sorted = all.by_rank;
    std::sort(sorted.begin(), sorted.end());
    CHECK(sorted == es::all_rows<std::size_t>(cloud.size()));
    std::vector<std::size_t> first(all.by_rank.begin(), all.by_rank.begin() + 37);
    std::sort(first.begin(), first.end());
    CHECK(first == expected);
    CHECK(kept.by_rank == std::vector<std::size_t>(all.by_rank.begin(), all.by_rank.begin() + 37));
    CHECK(parallel.by_rank == all.by_rank);
  }
  // --lod alone: the level is the points the mode never removes
  es::Settings alone;
  alone.lod = true;
  CHECK(selection_of<CGAL::Sequential_tag>(cloud, alone).kept.size() == 1);
  alone.options.mode = CGAL::Entropy_simplification::Mode::paper;
  CHECK(selection_of<CGAL::Sequential_tag>(cloud, alone).kept.size() == 11);
}

TEST_CASE("The file of --indices: one 0-based index a line, in the order given", "[program][lod]")
{
  es::String_sink sink;
  es::write_indices(sink, { 7, 0, 123456789012, 3 });
  CHECK(sink.bytes == "7\n0\n123456789012\n3\n");
  es::String_sink empty;
  es::write_indices(empty, {});
  CHECK(empty.bytes.empty());
}

TEST_CASE("The importance in LAS: the records' bytes, then the attribute, declared in the Extra Bytes VLR",
          "[program][las][importance]")
{
  for (const std::string name : { "grid.las", "grid_1_4_format_10.las", "grid_undocumented_extra_bytes.las",
                                  "grid_declared_extra_bytes.las" })
  {
    INFO(name);
    es::Input_file file(cli_input(name));
    const es::Las_file las = es::read_las(file.bytes());
    const std::vector<std::size_t> rows = { 5, 0, 143, 77 };
    std::vector<double> value_of_row(las.point_count);
    for (std::size_t r = 0; r < value_of_row.size(); ++r)
      value_of_row[r] = 0.25 * double(r);
    es::String_sink sink;
    es::write_las_with_attribute(sink, las, rows, "importance", "a test", value_of_row);
    const std::string written = sink.bytes;
    const es::Las_file again = es::read_las(written);
    REQUIRE(again.point_count == rows.size());
    CHECK(again.record_length == las.record_length + 8);
    CHECK(again.version_minor == las.version_minor);
    for (std::size_t r = 0; r < rows.size(); ++r)
    {
      CHECK(std::string(again.record(r), las.record_length) == std::string(las.record(rows[r]), las.record_length));
      CHECK(es::load_little_endian<double>(again.record(r) + las.record_length) == value_of_row[rows[r]]);
    }
    // the last descriptor is the attribute's, after descriptors of the records' own extra bytes
    const std::optional<std::size_t> vlr = es::las_extra_bytes_detail::extra_bytes_vlr(again);
    REQUIRE(vlr);
    const std::size_t length = es::load_little_endian<std::uint16_t>(written.data() + *vlr + 20);
    REQUIRE(length % 192 == 0);
    std::size_t declared = 0;
    for (std::size_t d = 0; d + 192 < length; d += 192)
      declared += es::las_extra_bytes_detail::declared_size(written.data() + *vlr + 54 + d);
    CHECK(declared == las.record_length - es::las_detail::base_record_sizes[las.point_format]);
    const char* attribute = written.data() + *vlr + 54 + length - 192;
    CHECK(int(attribute[2]) == 10);
    CHECK(std::string(attribute + 4) == "importance");
    // what follows the points (EVLRs) is the input's, and the header says where it starts
    if (las.evlr_count > 0)
      CHECK(es::load_little_endian<std::uint64_t>(written.data() + es::las_detail::evlr_start_at) ==
            again.offset_to_points + rows.size() * again.record_length);
    CHECK(written.substr(again.offset_to_points + rows.size() * again.record_length) ==
          std::string(file.bytes().substr(las.offset_to_points + las.point_count * las.record_length)));
  }
  es::Input_file bad(cli_input("grid_overdeclared_extra_bytes.las"));
  CHECK_THROWS_AS(es::check_room_for_attribute(es::read_las(bad.bytes()), "importance"), es::Read_error);
}

TEST_CASE("The picture of --render: the input beside the result, by importance, a PNG that decodes",
          "[program][render]")
{
  es::Input_file file(cli_input("grid.xyz"));
  const es::Cloud cloud = es::read_cloud(file.bytes(), es::Format::xyz);
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < cloud.size(); i += 4)
    kept.push_back(i);
  std::vector<double> importance(cloud.size(), 0.);
  importance[0] = 2.; // the greatest: yellow, the others dark purple
  const es::Picture picture = es::render_side_by_side(cloud, kept, importance);
  es::String_sink sink;
  es::write_png(sink, picture);
  REQUIRE(sink.bytes.substr(1, 3) == "PNG");

  int width = 0, height = 0, channels = 0;
  std::unique_ptr<unsigned char, void (*)(void*)> rgb(
    stbi_load_from_memory(reinterpret_cast<const unsigned char*>(sink.bytes.data()), int(sink.bytes.size()), &width,
                          &height, &channels, 3),
    stbi_image_free);
  REQUIRE(rgb);
  REQUIRE(width == picture.width);
  REQUIRE(height == picture.height);
  CHECK(std::equal(picture.rgb.begin(), picture.rgb.end(), rgb.get()));
  // painted pixels in each panel (not white, below the titles, above the legend)
  const auto painted = [&](int from, int to, std::array<std::uint8_t, 3> colour) {
    std::size_t count = 0;
    for (int y = 40; y < height - 40; ++y)
      for (int x = from; x < to; ++x)
        count += std::equal(colour.begin(), colour.end(), rgb.get() + (std::size_t(y) * width + x) * 3);
    return count;
  };
  const std::array<std::uint8_t, 3> purple = es::render_detail::colour_of(0.), yellow = es::render_detail::colour_of(1.);
  CHECK(purple == std::array<std::uint8_t, 3>{ 68, 1, 84 });
  CHECK(yellow == std::array<std::uint8_t, 3>{ 253, 231, 37 });
  const std::size_t input_purple = painted(0, width / 2, purple), result_purple = painted(width / 2, width, purple);
  CHECK(result_purple > 0);
  CHECK(input_purple > 2 * result_purple); // a quarter of the points, discs of the same size
  CHECK(painted(0, width / 2, yellow) > 0);
  CHECK(painted(width / 2, width, yellow) > 0); // point 0 is kept
  const unsigned char* corner = rgb.get() + (std::size_t(height - 1) * width + width - 1) * 3;
  CHECK((corner[0] == 255 && corner[1] == 255 && corner[2] == 255));

  // the same cloud scaled by powers of two, exactly: the same picture, where
  // depths kept as floats in the cloud's units overflowed beyond 3.4e38 (half
  // the points not drawn) and lost their order below about 1e-38
  for (int exponent : { 140, -170 })
  {
    es::Cloud scaled = cloud;
    for (es::Column& column : scaled.table.columns)
      if (column.name == "x" || column.name == "y" || column.name == "z")
        for (double& v : column.values)
          v = std::ldexp(v, exponent);
    const bool same = es::render_side_by_side(scaled, kept, importance).rgb == picture.rgb;
    CHECK(same);
  }
}

TEST_CASE("The thread limit of --threads holds while it lives, and the result does not change",
          "[program][threads]")
{
  test_parallel::require_tbb();
  es::Input_file file(cli_input("grid.xyz"));
  const es::Cloud cloud = es::read_cloud(file.bytes(), es::Format::xyz);
  const es::Settings s = count_settings(37, CGAL::Entropy_simplification::Mode::weighted_elimination);
  const std::vector<std::size_t> unlimited = kept_rows<test_parallel::Parallel_tag>(cloud, s);
#ifdef CGAL_LINKED_WITH_TBB
  const std::size_t before = tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
  {
    const es::Thread_limit limit(std::size_t(1));
    CHECK(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism) == 1);
    CHECK(kept_rows<test_parallel::Parallel_tag>(cloud, s) == unlimited);
  }
  CHECK(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism) == before);
#endif
  const es::Thread_limit none{ std::nullopt };
  CHECK(kept_rows<test_parallel::Parallel_tag>(cloud, s) == unlimited);
}

TEST_CASE("The program's report measures the kept rows as the library measures their points", "[program][report]")
{
  es::Input_file file(cli_input("grid.xyz"));
  const es::Cloud cloud = es::read_cloud(file.bytes(), es::Format::xyz);
  const std::vector<std::size_t> kept =
    kept_rows<CGAL::Sequential_tag>(cloud, count_settings(37, CGAL::Entropy_simplification::Mode::weighted_elimination));
  const es::Column* xyz[3] = { cloud.table.find("x"), cloud.table.find("y"), cloud.table.find("z") };
  std::vector<es::Kernel::Point_3> input, kept_points;
  for (std::size_t row = 0; row < cloud.size(); ++row)
  {
    const std::array<double, 3> p = es::coordinates(cloud, xyz, row);
    input.emplace_back(p[0], p[1], p[2]);
  }
  for (std::size_t row : kept)
    kept_points.push_back(input[row]);
  const auto expected = CGAL::measure_simplification_quality<CGAL::Sequential_tag>(input, kept_points);
  const auto report = es::quality_of<CGAL::Sequential_tag>(cloud, kept);
  CHECK(report.kept_size == 37);
  CHECK(report.input_size == 144);
  CHECK(report.mean_distance == expected.mean_distance);
  CHECK(report.max_distance == expected.max_distance);
  CHECK(report.point_to_plane == expected.point_to_plane);
  CHECK(report.mean_distance > 0.);
}

TEST_CASE("The program's report of --lod measures the first rows by rank at each boundary and at the level",
          "[program][report][lod]")
{
  es::Input_file file(cli_input("grid.xyz"));
  const es::Cloud cloud = es::read_cloud(file.bytes(), es::Format::xyz);
  const es::Column* xyz[3] = { cloud.table.find("x"), cloud.table.find("y"), cloud.table.find("z") };
  std::vector<es::Kernel::Point_3> input;
  for (std::size_t row = 0; row < cloud.size(); ++row)
  {
    const std::array<double, 3> p = es::coordinates(cloud, xyz, row);
    input.emplace_back(p[0], p[1], p[2]);
  }
  // any order of the rows: the rows by rank, reversed and rotated
  std::vector<std::size_t> by_rank(cloud.size());
  for (std::size_t r = 0; r < by_rank.size(); ++r)
    by_rank[r] = (by_rank.size() - 1 - r + 17) % by_rank.size();
  // 50, 20, 10, 5, 2 and 1% of 144 rounded up: 72, 28.8, 14.4, 7.2, 2.88, 1.44
  const std::vector<std::size_t> boundaries = { 72, 29, 15, 8, 3, 2 }, with_level = { 72, 37, 29, 15, 8, 3, 2 };
  REQUIRE(cloud.size() == 144);
  for (const std::optional<std::size_t> level : { std::optional<std::size_t>(), std::optional<std::size_t>(37) })
  {
    const std::vector<std::size_t>& sizes = level ? with_level : boundaries;
    const auto reports = es::prefix_reports<CGAL::Sequential_tag>(cloud, by_rank, level);
    REQUIRE(reports.size() == sizes.size());
    for (std::size_t j = 0; j < sizes.size(); ++j)
    {
      std::vector<es::Kernel::Point_3> first;
      for (std::size_t r = 0; r < sizes[j]; ++r)
        first.push_back(input[by_rank[r]]);
      const auto expected = CGAL::measure_simplification_quality<CGAL::Sequential_tag>(input, first);
      INFO("the first " << sizes[j]);
      CHECK(reports[j].kept_size == sizes[j]);
      CHECK(reports[j].mean_distance == expected.mean_distance);
      CHECK(reports[j].max_distance == expected.max_distance);
      CHECK((reports[j].point_to_plane == expected.point_to_plane ||
             (std::isnan(reports[j].point_to_plane) && std::isnan(expected.point_to_plane))));
    }
  }
  CHECK(es::prefix_reports<CGAL::Sequential_tag>(cloud, {}, std::nullopt).empty());
}

TEST_CASE("Georeferenced LAS: the same integer records with other offsets keep the same points",
          "[program][las]")
{
  es::Input_file local_file(cli_input("grid.las")), georeferenced_file(cli_input("grid_georeferenced.las"));
  const es::Cloud local = es::read_cloud(local_file.bytes(), es::Format::las);
  const es::Cloud georeferenced = es::read_cloud(georeferenced_file.bytes(), es::Format::las);
  REQUIRE(georeferenced.las->offset[0] == 512345.67);
  REQUIRE(local.las->offset[0] == 0.);
  for (auto mode : { CGAL::Entropy_simplification::Mode::weighted_elimination,
                     CGAL::Entropy_simplification::Mode::paper })
  {
    const es::Settings s = count_settings(40, mode);
    const std::vector<std::size_t> a = kept_rows<CGAL::Sequential_tag>(local, s);
    const std::vector<std::size_t> b = kept_rows<CGAL::Sequential_tag>(georeferenced, s);
    CHECK(a.size() == 40);
    CHECK(a == b);

    // and the written records are the same bytes
    es::String_sink out_a, out_b;
    es::write_las(out_a, *local.las, a);
    es::write_las(out_b, *georeferenced.las, b);
    const std::size_t start = local.las->offset_to_points;
    CHECK(out_a.bytes.size() == out_b.bytes.size());
    CHECK(out_a.bytes.substr(start) == out_b.bytes.substr(start));
  }
}

TEST_CASE("read_cloud: empty files, no points and non-finite coordinates are errors", "[program]")
{
  CHECK_THROWS_WITH(es::read_cloud("", es::Format::ply), Catch::Equals("the file is empty"));
  CHECK_THROWS_WITH(es::read_cloud("# only a comment\n", es::Format::xyz), Catch::Equals("the file holds no points"));
  CHECK_THROWS_WITH(es::read_cloud("OFF 0 0 0\n", es::Format::off), Catch::Equals("the file holds no points"));
  CHECK_THROWS_WITH(es::read_cloud("1 2 3\n1 inf 3\n", es::Format::xyz),
                    Catch::Equals("point #1 has a coordinate that is not a finite number"));
  CHECK_THROWS_WITH(es::read_cloud("-nan 2 3\n", es::Format::xyz), Catch::Contains("point #0"));
  // a non-finite normal is a property like any other, kept as read
  CHECK(es::read_cloud("1 2 3 nan 0 1\n", es::Format::xyz).size() == 1);
  // a UTF-8 byte order mark, in every text format
  for (const auto& text : { std::make_pair(es::Format::xyz, "1 2 3\n4 5 6\n"),
                            std::make_pair(es::Format::off, "OFF\n1 0 0\n1 2 3\n"),
                            std::make_pair(es::Format::ply, "ply\nformat ascii 1.0\nelement vertex 1\nproperty float "
                                                            "x\nproperty float y\nproperty float z\nend_header\n1 2 3\n") })
  {
    CHECK(es::read_cloud(text.second, text.first).size() >= 1);
    CHECK_THROWS_WITH(es::read_cloud(std::string("\xEF\xBB\xBF") + text.second, text.first),
                      Catch::StartsWith("the file starts with a UTF-8 byte order mark (bytes EF BB BF)"));
    // UTF-16 and UTF-32 text, either byte order: each character, the mark
    // first, takes 2 or 4 bytes
    for (int width : { 2, 4 })
      for (bool little : { true, false })
      {
        const std::string wide = std::string("\xEF\xBB\xBF") + text.second; // the mark, as UTF-8
        std::string encoded;
        for (std::size_t c = 0; c < wide.size(); c += c == 0 ? 3 : 1)
        {
          const unsigned int code = c == 0 ? 0xFEFF : (unsigned char)wide[c];
          std::string unit(std::size_t(width), '\0');
          for (int b = 0; b < width; ++b)
            unit[std::size_t(little ? b : width - 1 - b)] = char((code >> (8 * b)) & 0xFF);
          encoded += unit;
        }
        CHECK_THROWS_WITH(es::read_cloud(encoded, text.first),
                          Catch::StartsWith(std::string("the file is UTF-") + (width == 2 ? "16" : "32") + " text"));
      }
  }
}

TEST_CASE("Numbers as text: signs, extremes, and what is not a number", "[program]")
{
  double v = 0.;
  CHECK((es::parse_number("+1.5", v) && v == 1.5));
  CHECK((es::parse_number("-2e3", v) && v == -2000.));
  CHECK((es::parse_number("1e-400", v) && v == 0.));
  CHECK((es::parse_number("-1e400", v) && v == -std::numeric_limits<double>::infinity()));
  CHECK((es::parse_number("4.9e-324", v) && v == 4.9e-324));
  for (const char* bad : { "", "+", "-", "+-1", "-+1", "++1", "1,5", "0x10", "1e", " 1", "1 " })
    CHECK_FALSE(es::parse_number(bad, v));
  // holds() decides by range before converting, so NaN and huge values are simply not integers
  CHECK_FALSE(es::holds(es::Scalar_type::int8, std::numeric_limits<double>::quiet_NaN()));
  CHECK_FALSE(es::holds(es::Scalar_type::uint32, 1e300));
  CHECK_FALSE(es::holds(es::Scalar_type::int32, -1e19));
  CHECK(es::holds(es::Scalar_type::uint32, 4294967295.));
  CHECK_FALSE(es::holds(es::Scalar_type::uint32, 4294967296.));
  CHECK_FALSE(es::holds(es::Scalar_type::int16, 1.5));
}
