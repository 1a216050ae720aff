// Tests of the command-line program's PLY reader and writer: the three
// encodings, every scalar type, what is dropped, exact round trips, every
// error, hostile counts, and CGAL's demo PLY files.

#include <catch2/catch.hpp>

#include "check_read_error.h"

#include "ply_format.h"

#include <cfloat>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

using namespace entropy_simplify;
using Catch::Matchers::Contains;


namespace {

std::string bytes(std::initializer_list<unsigned char> list) { return std::string(list.begin(), list.end()); }

std::string ascii_ply(const std::string& header, const std::string& body)
{
  return "ply\nformat ascii 1.0\n" + header + "end_header\n" + body;
}

std::string binary_ply(const std::string& header, const std::string& body, bool big_endian = false)
{
  return std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") + " 1.0\n" +
         header + "end_header\n" + body;
}

const std::string xyz_header = "element vertex 1\nproperty float x\nproperty float y\nproperty float z\n";

// The first difference between two tables, values compared bit for bit (so
// that -0 differs from 0); empty when they are identical.
std::string difference(const Point_table& a, const Point_table& b)
{
  if (a.columns.size() != b.columns.size())
    return "column counts differ";
  for (std::size_t c = 0; c < a.columns.size(); ++c)
  {
    const Column &p = a.columns[c], &q = b.columns[c];
    if (p.name != q.name || p.type != q.type || p.values.size() != q.values.size())
      return "column " + std::to_string(c) + " ('" + p.name + "', '" + q.name + "') differs in name, type or size";
    for (std::size_t row = 0; row < p.values.size(); ++row)
      if (std::memcmp(&p.values[row], &q.values[row], sizeof(double)) != 0)
      {
        std::ostringstream message;
        message.precision(17);
        message << "column '" << p.name << "' row " << row << ": " << p.values[row] << " != " << q.values[row];
        return message.str();
      }
  }
  return "";
}

Ply_cloud write_then_read(const Point_table& table, bool binary, const std::vector<std::string>& comments = {})
{
  String_sink sink;
  write_ply(sink, table, binary, comments);
  return read_ply(sink.bytes);
}

Column column(const std::string& name, Scalar_type type, std::vector<double> values)
{
  return Column{ name, type, std::move(values) };
}

} // namespace

TEST_CASE("read_ply reads an ASCII PLY file", "[ply]")
{
  const std::string file = "ply\nformat ascii 1.0\ncomment made by hand\nobj_info scanner 7\n"
                           "element vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
                           "property uchar red\nproperty double quality\nend_header\n"
                           "1.5 -2 0.25 200 0.1\n0 1e3 -0.5 7 -1e-300\n";
  const Ply_cloud cloud = read_ply(file);
  CHECK(cloud.encoding == Ply_encoding::ascii);
  CHECK(cloud.comments == std::vector<std::string>{ "made by hand", "scanner 7" });
  CHECK(cloud.notes.empty());
  const Point_table expected{ { column("x", Scalar_type::float32, { 1.5, 0. }),
                                column("y", Scalar_type::float32, { -2., 1000. }),
                                column("z", Scalar_type::float32, { 0.25, -0.5 }),
                                column("red", Scalar_type::uint8, { 200., 7. }),
                                column("quality", Scalar_type::float64, { 0.1, -1e-300 }) } };
  CHECK(difference(cloud.table, expected) == "");
}

TEST_CASE("read_ply rounds ASCII float properties to float, as binary PLY holds them", "[ply]")
{
  const Ply_cloud cloud = read_ply(ascii_ply(xyz_header, "0.1 37.3579 1e-50\n"));
  CHECK(cloud.table.columns[0].values[0] == double(0.1f));
  CHECK(cloud.table.columns[1].values[0] == double(37.3579f));
  CHECK(cloud.table.columns[2].values[0] == 0.);
}

TEST_CASE("read_ply reads binary PLY files of both byte orders", "[ply]")
{
  const std::string header = "element vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
                             "property uchar red\nproperty short t\n";
  // 1.5 -2 0.25 200 -2, then 0 1 -0.5 7 300
  const std::string little = bytes({ 0x00, 0x00, 0xc0, 0x3f, 0x00, 0x00, 0x00, 0xc0, 0x00, 0x00, 0x80, 0x3e, 0xc8,
                                     0xfe, 0xff, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x80, 0x3f, 0x00, 0x00, 0x00,
                                     0xbf, 0x07, 0x2c, 0x01 });
  const std::string big = bytes({ 0x3f, 0xc0, 0x00, 0x00, 0xc0, 0x00, 0x00, 0x00, 0x3e, 0x80, 0x00, 0x00, 0xc8,
                                  0xff, 0xfe, 0x00, 0x00, 0x00, 0x00, 0x3f, 0x80, 0x00, 0x00, 0xbf, 0x00, 0x00,
                                  0x00, 0x07, 0x01, 0x2c });
  const Point_table expected{ { column("x", Scalar_type::float32, { 1.5, 0. }),
                                column("y", Scalar_type::float32, { -2., 1. }),
                                column("z", Scalar_type::float32, { 0.25, -0.5 }),
                                column("red", Scalar_type::uint8, { 200., 7. }),
                                column("t", Scalar_type::int16, { -2., 300. }) } };

  const Ply_cloud from_little = read_ply(binary_ply(header, little));
  CHECK(from_little.encoding == Ply_encoding::binary_little_endian);
  CHECK(difference(from_little.table, expected) == "");
  const Ply_cloud from_big = read_ply(binary_ply(header, big, true));
  CHECK(from_big.encoding == Ply_encoding::binary_big_endian);
  CHECK(difference(from_big.table, expected) == "");
}

namespace {

// Each scalar type at its extremes, little-endian, under both of its names.
struct Type_case
{
  const char* classic_name;
  const char* sized_name;
  Scalar_type type;
  std::vector<unsigned char> lowest, highest;
  double lowest_value, highest_value;
};

const std::vector<Type_case> type_cases = {
  { "char", "int8", Scalar_type::int8, { 0x80 }, { 0x7f }, -128., 127. },
  { "uchar", "uint8", Scalar_type::uint8, { 0x00 }, { 0xff }, 0., 255. },
  { "short", "int16", Scalar_type::int16, { 0x00, 0x80 }, { 0xff, 0x7f }, -32768., 32767. },
  { "ushort", "uint16", Scalar_type::uint16, { 0x00, 0x00 }, { 0xff, 0xff }, 0., 65535. },
  { "int", "int32", Scalar_type::int32, { 0x00, 0x00, 0x00, 0x80 }, { 0xff, 0xff, 0xff, 0x7f }, -2147483648.,
    2147483647. },
  { "uint", "uint32", Scalar_type::uint32, { 0, 0, 0, 0 }, { 0xff, 0xff, 0xff, 0xff }, 0., 4294967295. },
  { "float", "float32", Scalar_type::float32, { 0xff, 0xff, 0x7f, 0xff }, { 0xff, 0xff, 0x7f, 0x7f },
    -double(FLT_MAX), double(FLT_MAX) },
  { "double", "float64", Scalar_type::float64, { 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xef, 0xff },
    { 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xef, 0x7f }, -DBL_MAX, DBL_MAX },
};

// x y z are the integral types char, uchar and short: integer coordinates are
// columns like any other.
std::string every_type_header(bool sized_names)
{
  static const char* const names[] = { "x", "y", "z", "a", "b", "c", "d", "e" };
  std::string header = "element vertex 2\n";
  for (std::size_t t = 0; t < type_cases.size(); ++t)
    header += std::string("property ") + (sized_names ? type_cases[t].sized_name : type_cases[t].classic_name) +
              " " + names[t] + "\n";
  return header;
}

std::string every_type_body(bool big_endian)
{
  std::string body;
  for (bool highest : { false, true })
    for (const Type_case& c : type_cases)
    {
      std::vector<unsigned char> value = highest ? c.highest : c.lowest;
      if (big_endian)
        std::reverse(value.begin(), value.end());
      body.append(value.begin(), value.end());
    }
  return body;
}

void check_every_type(const Point_table& table)
{
  REQUIRE(table.columns.size() == type_cases.size());
  for (std::size_t t = 0; t < type_cases.size(); ++t)
  {
    INFO("type " << type_cases[t].classic_name);
    CHECK(table.columns[t].type == type_cases[t].type);
    CHECK(table.columns[t].values == std::vector<double>{ type_cases[t].lowest_value, type_cases[t].highest_value });
  }
  CHECK(table.find("x")->type == Scalar_type::int8);
}

} // namespace

TEST_CASE("read_ply reads every scalar type, by either name, in every encoding", "[ply]")
{
  for (bool sized_names : { false, true })
  {
    INFO("sized names: " << sized_names);
    std::string text;
    for (bool highest : { false, true })
    {
      for (const Type_case& c : type_cases)
      {
        std::string number;
        append_number(number, highest ? c.highest_value : c.lowest_value, c.type);
        text += number + " ";
      }
      text += "\n";
    }
    check_every_type(read_ply(ascii_ply(every_type_header(sized_names), text)).table);
    check_every_type(read_ply(binary_ply(every_type_header(sized_names), every_type_body(false))).table);
    check_every_type(read_ply(binary_ply(every_type_header(sized_names), every_type_body(true), true)).table);
  }
}

TEST_CASE("write_ply writes PLY's classic header and the values", "[ply]")
{
  const Point_table table{ { column("x", Scalar_type::float64, { 0.1, -2. }),
                             column("y", Scalar_type::float32, { double(0.1f), 3.5 }),
                             column("z", Scalar_type::int16, { -7., 300. }) } };
  String_sink ascii;
  write_ply(ascii, table, false, { "from a test" });
  CHECK(ascii.bytes == "ply\nformat ascii 1.0\ncomment from a test\nelement vertex 2\nproperty double x\n"
                       "property float y\nproperty short z\nend_header\n0.1 0.1 -7\n-2 3.5 300\n");
  String_sink binary;
  write_ply(binary, table, true);
  const std::string header = "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty double x\n"
                             "property float y\nproperty short z\nend_header\n";
  CHECK(binary.bytes ==
        header + bytes({ 0x9a, 0x99, 0x99, 0x99, 0x99, 0x99, 0xb9, 0x3f, 0xcd, 0xcc, 0xcc, 0x3d, 0xf9, 0xff,
                         0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xc0, 0x00, 0x00, 0x60, 0x40, 0x2c, 0x01 }));
}

TEST_CASE("write_ply writes the classic names of every type, and read_ply reads them back", "[ply]")
{
  Point_table table;
  for (const Type_case& c : type_cases)
    table.columns.push_back(column(c.sized_name, c.type, { c.lowest_value, c.highest_value }));
  for (bool binary : { false, true })
  {
    String_sink sink;
    write_ply(sink, table, binary);
    for (const Type_case& c : type_cases)
      CHECK_THAT(sink.bytes, Contains(std::string("property ") + c.classic_name + " " + c.sized_name + "\n"));
  }
}

TEST_CASE("Properties, types and values survive write_ply then read_ply exactly", "[ply]")
{
  const double inf = std::numeric_limits<double>::infinity();
  const Point_table table{ {
    column("x", Scalar_type::float64, { 1e-300, 4.9e-324, -0., DBL_MAX, -DBL_MAX, 0.1, 2.2250738585072014e-308 }),
    column("y", Scalar_type::float32,
           { double(3.4028235e38f), double(1e-45f), -0., double(FLT_MIN), double(0.1f), -double(FLT_MAX),
             double(FLT_MIN / 3.f) }),
    column("z", Scalar_type::float64, { inf, -inf, 1., 1. / 3, 123456789.123, 1e300, -1e-310 }),
    column("i8", Scalar_type::int8, { -128., 127., 0., -1., 1., 5., -5. }),
    column("u8", Scalar_type::uint8, { 0., 255., 1., 2., 3., 4., 128. }),
    column("i16", Scalar_type::int16, { -32768., 32767., 0., 1., -1., 2., 3. }),
    column("u16", Scalar_type::uint16, { 0., 65535., 1., 2., 3., 4., 5. }),
    column("i32", Scalar_type::int32, { -2147483648., 2147483647., 0., 1., -1., 2., 3. }),
    column("u32", Scalar_type::uint32, { 0., 4294967295., 1., 2., 3., 4., 5. }),
    column("f", Scalar_type::float32, { 1., 2., 3., 4., 5., 6., double(1.17549435e-38f) }),
  } };
  for (bool binary : { false, true })
  {
    INFO("binary: " << binary);
    const Ply_cloud cloud = write_then_read(table, binary);
    CHECK(cloud.encoding == (binary ? Ply_encoding::binary_little_endian : Ply_encoding::ascii));
    CHECK(difference(cloud.table, table) == "");
    CHECK(difference(write_then_read(cloud.table, !binary).table, table) == "");
  }
}

TEST_CASE("Comments survive write_ply then read_ply", "[ply]")
{
  const Point_table table{ { column("x", Scalar_type::float64, { 1. }), column("y", Scalar_type::float64, { 2. }),
                             column("z", Scalar_type::float64, { 3. }) } };
  const std::vector<std::string> comments = { "Generated by the CGAL library", "  indented", "", "tab\tinside" };
  for (bool binary : { false, true })
  {
    const Ply_cloud cloud = write_then_read(table, binary, comments);
    CHECK(cloud.comments == comments);
    CHECK(write_then_read(cloud.table, binary, cloud.comments).comments == comments);
  }
  // a comment is one line
  CHECK(write_then_read(table, false, { "two\nlines" }).comments == std::vector<std::string>{ "two lines" });
}

TEST_CASE("read_ply reads past the elements before the vertex element, and those after it to note what does not "
          "match the header",
          "[ply]")
{
  const std::string header = "element material 2\nproperty uchar r\nproperty list uchar int ids\n"
                             "element vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
                             "element face 3\nproperty list uchar int vertex_indices\nproperty uchar flags\n";
  const Point_table expected{ { column("x", Scalar_type::float32, { 1., 4. }),
                                column("y", Scalar_type::float32, { 2., 5. }),
                                column("z", Scalar_type::float32, { 3., 6. }) } };
  const std::vector<std::string> notes = { "2 materials dropped: a simplified point set has only vertices",
                                           "3 faces dropped: a simplified point set has only vertices" };
  const auto with_mismatch = [&](const std::string& reason) {
    std::vector<std::string> all = notes;
    all.push_back("the elements after the vertices do not match the header (" + reason +
                  "): if the vertices are not what the header declares either, the file is not read right");
    return all;
  };
  SECTION("ASCII")
  {
    const Ply_cloud cloud = read_ply(ascii_ply(header, "1 3 0 1 2\n2 0\n1 2 3\n4 5 6\n3 0 1 2 0\nnot read\n"));
    CHECK(difference(cloud.table, expected) == "");
    CHECK(cloud.notes == with_mismatch("the file is truncated: it ends after 2 of 3 records of element 'face'"));
    CHECK(read_ply(ascii_ply(header, "1 3 0 1 2\n2 0\n1 2 3\n4 5 6\n3 0 1 2 0\n3 0 1 2 0\n3 0 1 2 0\n")).notes ==
          notes);
  }
  SECTION("binary")
  {
    // material 1: r = 1, ids = { 7 }; material 2: r = 2, ids = {}; then the
    // vertices, then a face cut short, which is noted
    const std::string body = bytes({ 0x01, 0x01, 0x07, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x80, 0x3f, 0x00,
                                     0x00, 0x00, 0x40, 0x00, 0x00, 0x40, 0x40, 0x00, 0x00, 0x80, 0x40, 0x00, 0x00,
                                     0xa0, 0x40, 0x00, 0x00, 0xc0, 0x40, 0x03, 0x00 });
    const Ply_cloud cloud = read_ply(binary_ply(header, body));
    CHECK(difference(cloud.table, expected) == "");
    CHECK(cloud.notes == with_mismatch("the PLY header claims 3 records of element 'face', more than the 2 bytes "
                                       "left in the file can hold"));
  }
  SECTION("empty elements give no note")
  {
    const Ply_cloud cloud = read_ply(ascii_ply("element face 0\nproperty list uchar int vertex_indices\n" +
                                                 xyz_header + "element edge 1\nproperty int a\n",
                                               "1 2 3\n7\n"));
    CHECK(cloud.notes == std::vector<std::string>{ "1 edge dropped: a simplified point set has only vertices" });
  }
}

TEST_CASE("read_ply drops the vertex element's list properties with a note", "[ply]")
{
  const std::string header = "element vertex 2\nproperty float x\nproperty list uchar short neighbors\n"
                             "property float y\nproperty float z\n";
  const Point_table expected{ { column("x", Scalar_type::float32, { 1., 4. }),
                                column("y", Scalar_type::float32, { 2., 5. }),
                                column("z", Scalar_type::float32, { 3., 6. }) } };
  const std::string note = "vertex list property 'neighbors' dropped: only scalar properties are kept";
  const Ply_cloud ascii = read_ply(ascii_ply(header, "1 2 10 -11 2 3\n4 0 5 6\n"));
  CHECK(difference(ascii.table, expected) == "");
  CHECK(ascii.notes == std::vector<std::string>{ note });
  const std::string body = bytes({ 0x00, 0x00, 0x80, 0x3f, 0x02, 0x0a, 0x00, 0xf5, 0xff, 0x00, 0x00, 0x00, 0x40,
                                   0x00, 0x00, 0x40, 0x40, 0x00, 0x00, 0x80, 0x40, 0x00, 0x00, 0x00, 0xa0, 0x40,
                                   0x00, 0x00, 0xc0, 0x40 });
  const Ply_cloud binary = read_ply(binary_ply(header, body));
  CHECK(difference(binary.table, expected) == "");
  CHECK(binary.notes == std::vector<std::string>{ note });
  // the list's items are checked as a kept value would be
  CHECK_READ_ERROR(read_ply(ascii_ply(header, "1 2 10 40000 2 3\n4 0 5 6\n")), "does not fit property 'neighbors'");
  CHECK_READ_ERROR(read_ply(ascii_ply(header, "1 -1 2 3\n4 0 5 6\n")), "-1 does not fit property 'neighbors' of type uchar");
  const std::string signed_length = "element vertex 1\nproperty float x\nproperty list char short neighbors\n"
                                    "property float y\nproperty float z\n";
  CHECK_READ_ERROR(read_ply(ascii_ply(signed_length, "1 -1 2 3\n")), "list 'neighbors' has a negative length");
  CHECK_READ_ERROR(read_ply(ascii_ply(header, "1 9 1 2 3\n4 0 5 6\n")), "too few values");
}

TEST_CASE("read_ply notes data after the vertices when they are the last element", "[ply]")
{
  // a header that counts 2 of 3 vertices: 2 are read, and the third is noted
  const std::string header = "element vertex 2\nproperty float x\nproperty float y\nproperty float z\n";
  const Ply_cloud ascii = read_ply(ascii_ply(header, "1 2 3\n4 5 6\n7 8 9\n"));
  CHECK(ascii.table.size() == 2);
  CHECK(ascii.notes == std::vector<std::string>{ "6 bytes follow the 2 vertices that the header declares, and were "
                                                 "not read: if more vertices are there, the header's count is "
                                                 "wrong" });
  const std::string three = bytes({ 0x00, 0x00, 0x80, 0x3f, 0x00, 0x00, 0x00, 0x40, 0x00, 0x00, 0x40, 0x40 });
  const Ply_cloud binary = read_ply(binary_ply(header, three + three + three + "\n"));
  CHECK(binary.table.size() == 2);
  CHECK(binary.notes == std::vector<std::string>{ "13 bytes follow the 2 vertices that the header declares, and "
                                                  "were not read: if more vertices are there, the header's count "
                                                  "is wrong" });
  CHECK(read_ply(binary_ply(xyz_header, three + "x")).notes ==
        std::vector<std::string>{ "1 byte follows the 1 vertex that the header declares, and was not read: if more "
                                  "vertices are there, the header's count is wrong" });
  // white space after ASCII vertices, and nothing after binary ones, is no news
  CHECK(read_ply(ascii_ply(header, "1 2 3\n4 5 6\n \t\r\n\n")).notes.empty());
  CHECK(read_ply(binary_ply(header, three + three)).notes.empty());
}

TEST_CASE("read_ply reads past the elements after the vertices and notes what follows them, or what does not "
          "match the header there",
          "[ply]")
{
  const std::string header = "element vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
                             "element face 1\nproperty list uchar int vertex_indices\n";
  const std::string face_dropped = "1 face dropped: a simplified point set has only vertices";
  // a face, then nothing: only the face is noted
  CHECK(read_ply(ascii_ply(header, "1 2 3\n4 5 6\n3 0 1 1\n")).notes == std::vector<std::string>{ face_dropped });
  // a face, then a line more: noted, whatever the order of the elements
  const Ply_cloud more = read_ply(ascii_ply(header, "1 2 3\n4 5 6\n3 0 1 1\n7 8 9\n"));
  CHECK(more.table.size() == 2);
  CHECK(more.notes == std::vector<std::string>{ face_dropped, "6 bytes follow the elements that the header "
                                                "declares, the 2 vertices and those after them, and were not read: "
                                                "if more vertices are there, the header's counts are wrong" });
  // the face missing: the elements after the vertices do not match
  const Ply_cloud missing = read_ply(ascii_ply(header, "1 2 3\n4 5 6\n"));
  REQUIRE(missing.notes.size() == 2);
  CHECK_THAT(missing.notes[1], Catch::StartsWith("the elements after the vertices do not match the header ("));
  // a binary header over a text body, the vertices not last (a hostile
  // review's file, read silently before): the text left over is noted
  const std::string no_faces = "element vertex 2\nproperty double x\nproperty double y\nproperty double z\n"
                               "element face 0\nproperty list uchar int vertex_indices\n";
  const Ply_cloud text_body = read_ply(binary_ply(no_faces, "1.5 2.5 3.5\n4.5 5.5 6.5\n7.5 8.5 9.5\n10 11 12\n"
                                                            "13 14 15\n16 17 18\n"));
  REQUIRE(text_body.notes.size() == 1);
  CHECK_THAT(text_body.notes[0], Catch::Contains("bytes follow the elements that the header declares"));
  // a binary face, then nothing: no note but the face's
  const std::string vertices = bytes({ 0x00, 0x00, 0x80, 0x3f, 0x00, 0x00, 0x00, 0x40, 0x00, 0x00, 0x40, 0x40 });
  const std::string face = bytes({ 0x03, 0x00, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00 });
  CHECK(read_ply(binary_ply(header, vertices + vertices + face)).notes == std::vector<std::string>{ face_dropped });
}

TEST_CASE("read_ply accepts \\r\\n line ends", "[ply]")
{
  const Ply_cloud ascii = read_ply("ply\r\nformat ascii 1.0\r\ncomment hello\r\nelement vertex 2\r\n"
                                   "property float x\r\nproperty float y\r\nproperty int z\r\nend_header\r\n"
                                   "1 2 3\r\n4 5 6\r\n");
  CHECK(ascii.comments == std::vector<std::string>{ "hello" });
  CHECK(ascii.table.size() == 2);
  CHECK(ascii.table.columns[2].values == std::vector<double>{ 3., 6. });
  const Ply_cloud binary = read_ply("ply\r\nformat binary_little_endian 1.0\r\nelement vertex 1\r\n"
                                    "property uchar x\r\nproperty uchar y\r\nproperty uchar z\r\nend_header\r\n" +
                                    bytes({ 0x0d, 0x0a, 0x20 }));
  CHECK(binary.table.columns[0].values == std::vector<double>{ 13. });
  CHECK(binary.table.columns[1].values == std::vector<double>{ 10. });
  CHECK(binary.table.columns[2].values == std::vector<double>{ 32. });
}

TEST_CASE("read_ply reads a vertex element of no vertices", "[ply]")
{
  for (const std::string& file :
       { ascii_ply("element vertex 0\nproperty float x\nproperty float y\nproperty float z\n", ""),
         binary_ply("element vertex 0\nproperty float x\nproperty float y\nproperty float z\n", "") })
  {
    const Ply_cloud cloud = read_ply(file);
    CHECK(cloud.table.columns.size() == 3);
    CHECK(cloud.table.size() == 0);
  }
}

TEST_CASE("read_ply reports a header that is not PLY's", "[ply]")
{
  CHECK_READ_ERROR(read_ply(""), "not a PLY file");
  CHECK_READ_ERROR(read_ply("PLY\nformat ascii 1.0\nend_header\n"), "not a PLY file");
  CHECK_READ_ERROR(read_ply("plyformat ascii 1.0\n"), "not a PLY file");
  CHECK_READ_ERROR(read_ply("ply\nformat ascii 1.0\n" + xyz_header), "no end_header");
  CHECK_READ_ERROR(read_ply("ply\n" + xyz_header + "end_header\n1 2 3\n"), "no format line");
  CHECK_READ_ERROR(read_ply("ply\nformat binary 1.0\n" + xyz_header + "end_header\n"), "unknown format");
  CHECK_READ_ERROR(read_ply("ply\nformat ascii 2.0\n" + xyz_header + "end_header\n"), "unknown format");
  CHECK_READ_ERROR(read_ply("ply\nformat ascii\n" + xyz_header + "end_header\n"), "line 2 'format ascii': unknown format");
  CHECK_READ_ERROR(read_ply("ply\nformat ascii 1.0\nformat ascii 1.0\n" + xyz_header + "end_header\n"), "line 3");
  CHECK_READ_ERROR(read_ply(ascii_ply("elements vertex 1\n", "")), "line 3 'elements vertex 1': not a line of a PLY header");
  CHECK_READ_ERROR(read_ply(ascii_ply("\n" + xyz_header, "1 2 3\n")), "line 3 '': not a line of a PLY header");
  CHECK_READ_ERROR(read_ply(ascii_ply("property float x\n" + xyz_header, "1 2 3\n")), "line 3 'property float x'");
  CHECK_READ_ERROR(read_ply(ascii_ply(xyz_header + "end_header now\n", "1 2 3\n")), "line 7 'end_header now'");
  CHECK_READ_ERROR(read_ply(ascii_ply("element vertex 1\nproperty float32 x\nproperty float y\nproperty real z\n", "1 2 3\n")),
                   "line 6 'property real z': unknown type");
  CHECK_READ_ERROR(read_ply(ascii_ply(xyz_header + "property list uchar int\n", "1 2 3 0\n")), "property list COUNT_TYPE");
  CHECK_READ_ERROR(read_ply(ascii_ply(xyz_header + "property list float int a\n", "1 2 3 0\n")), "integer type");
  CHECK_READ_ERROR(read_ply(ascii_ply(xyz_header + "property list uchar bool a\n", "1 2 3 0\n")), "unknown type");
  CHECK_READ_ERROR(read_ply(ascii_ply(xyz_header + "property float x extra\n", "1 2 3 0\n")), "property TYPE NAME");
  CHECK_READ_ERROR(read_ply(ascii_ply(xyz_header + "element vertex 1\n", "1 2 3\n")), "element 'vertex' is declared twice");
}

TEST_CASE("read_ply reports a missing vertex element or coordinate", "[ply]")
{
  CHECK_READ_ERROR(read_ply(ascii_ply("element point 1\nproperty float x\nproperty float y\nproperty float z\n", "1 2 3\n")),
                   "no vertex element");
  CHECK_READ_ERROR(read_ply(ascii_ply("element vertex 1\nproperty float x\nproperty float y\n", "1 2\n")),
                   "no x, y, z vertex properties");
  CHECK_READ_ERROR(read_ply(ascii_ply("element vertex 1\nproperty float x\nproperty float y\nproperty list uchar float z\n",
                             "1 2 1 3\n")),
                   "no x, y, z vertex properties");
  CHECK_READ_ERROR(read_ply(ascii_ply(xyz_header + "property int y\n", "1 2 3 4\n")), "property 'y' is declared twice");
  CHECK_READ_ERROR(read_ply(ascii_ply(xyz_header + "property list uchar int z\n", "1 2 3 0\n")),
                   "property 'z' is declared twice");
}

TEST_CASE("read_ply reports a count that is not a non-negative integer", "[ply]")
{
  for (const char* count : { "-3", "3.5", "three", "+3", "0x10", "", "18446744073709551616", "1e3" })
  {
    INFO("count '" << count << "'");
    CHECK_READ_ERROR(read_ply(ascii_ply(std::string("element vertex ") + count + "\nproperty float x\nproperty float y\n"
                                                                          "property float z\n",
                               "1 2 3\n")),
                     "COUNT a non-negative integer");
  }
}

TEST_CASE("read_ply reports a truncated body", "[ply]")
{
  const std::string header = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
  // long enough for 3 vertices of one digit each, the count passes the check before reading
  CHECK_READ_ERROR(read_ply(ascii_ply(header, "1.25 2.25 3.25\n4.25 5.25 6.25\n")), "ends after 2 of 3 vertices");
  CHECK_READ_ERROR(read_ply(binary_ply(header, std::string(35, '\0'))), "more than the 35 bytes");
  const std::string faces = "element face 2\nproperty list uchar int vertex_indices\n";
  CHECK_READ_ERROR(read_ply(ascii_ply(faces + header, "3 0 1 2 3 4 5 6 7 8 9 10 11")),
                   "ends after 1 of 2 records of element 'face'");
  // the second face's list runs past the end of the file
  CHECK_READ_ERROR(read_ply(binary_ply(faces + header, bytes({ 0x00, 0x06 }) + std::string(20, '\0'))),
                   "list 'vertex_indices' of element 'face' claims 6 items at byte");
  // the first vertex's list leaves too little for the second vertex
  const std::string listed = "element vertex 2\nproperty uchar x\nproperty uchar y\nproperty uchar z\n"
                             "property list uchar uchar a\n";
  CHECK(read_ply(binary_ply(listed, bytes({ 1, 2, 3, 0, 4, 5, 6, 0 }))).table.size() == 2);
  CHECK_READ_ERROR(read_ply(binary_ply(listed, bytes({ 1, 2, 3, 3, 9, 9, 9, 4 }))),
                   "the file is truncated: element 'vertex' needs 1 bytes");
  CHECK_READ_ERROR(read_ply(binary_ply(listed, bytes({ 1, 2, 3, 3, 9, 9, 9, 4 }), true)), "the file is truncated");
}

TEST_CASE("read_ply reports ASCII values that are not numbers of their type", "[ply]")
{
  const std::string header = "element vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
                             "property uchar red\nproperty int label\nproperty char c\n";
  CHECK(read_ply(ascii_ply(header, "1 2 3 255 -2147483648 -128\n")).table.size() == 1);
  CHECK_READ_ERROR(read_ply(ascii_ply(header, "1 2 3 300 0 0\n")), "line 11: 300 does not fit property 'red' of type uchar");
  CHECK_READ_ERROR(read_ply(ascii_ply(header, "1 2 3 -1 0 0\n")), "-1 does not fit property 'red'");
  CHECK_READ_ERROR(read_ply(ascii_ply(header, "1 2 3 0 1.5 0\n")), "1.5 does not fit property 'label' of type int");
  CHECK_READ_ERROR(read_ply(ascii_ply(header, "1 2 3 0 2147483648 0\n")), "does not fit property 'label'");
  CHECK_READ_ERROR(read_ply(ascii_ply(header, "1 2 3 0 1e300 0\n")), "does not fit property 'label'");
  CHECK_READ_ERROR(read_ply(ascii_ply(header, "1 2 3 0 nan 0\n")), "does not fit property 'label'");
  CHECK_READ_ERROR(read_ply(ascii_ply(header, "1 2 3 0 -inf 0\n")), "does not fit property 'label'");
  CHECK_READ_ERROR(read_ply(ascii_ply(header, "1 2 3 0 0 -129\n")), "does not fit property 'c' of type char");
  CHECK_READ_ERROR(read_ply(ascii_ply(header, "1e39 2 3 0 0 0\n")), "1e39 does not fit property 'x' of type float");
  CHECK_READ_ERROR(read_ply(ascii_ply(header, "1 two 3 0 0 0\n")), "line 11: property 'y' is not a number: 'two'");
  CHECK_READ_ERROR(read_ply(ascii_ply(header, "1 2 3 0 0 0,\n")), "property 'c' is not a number");
  // non-finite coordinates are the program's to check
  CHECK(std::isinf(read_ply(ascii_ply(header, "inf 2 3 0 0 0\n")).table.columns[0].values[0]));
  CHECK(std::isnan(read_ply(ascii_ply(header, "1 nan 3 0 0 0\n")).table.columns[1].values[0]));
  // -0 in an integer column is 0, as it reads back
  CHECK(!std::signbit(read_ply(ascii_ply(header, "1 2 3 -0 0 0\n")).table.columns[3].values[0]));
}

TEST_CASE("read_ply reads one ASCII vertex a line, of exactly its properties' values", "[ply]")
{
  const std::string header = "element vertex 2\nproperty float x\nproperty float y\nproperty float z\n";
  CHECK_READ_ERROR(read_ply(ascii_ply(header, "1 2 3 4\n5 6 7\n")), "line 8: a vertex has too many values: '4'");
  CHECK_READ_ERROR(read_ply(ascii_ply(header, "1 2\n3 4 5 6 7 8\n")), "line 8: a vertex has too few values: property 'z'");
  CHECK_READ_ERROR(read_ply(ascii_ply(header, "1 2 3 4 5 6\n\n")), "too many values");
  CHECK_READ_ERROR(read_ply(ascii_ply(header, "1 2 3\n\n4 5 6\n")), "line 9: a vertex has too few values");
  // what follows the vertex element is not read
  CHECK(read_ply(ascii_ply(header, "1 2 3\n4 5 6\n\ngarbage")).table.size() == 2);
  CHECK(read_ply(ascii_ply(header, "\t1 2  3 \n4 5 6")).table.size() == 2);
}

TEST_CASE("read_ply rejects a count the file cannot hold before allocating for it", "[ply]")
{
  // 4e9 vertices of 3 floats would be 96 GB of doubles: the count is
  // checked against the bytes left, so this is a Read_error, not bad_alloc
  const auto padded = [](std::string file) {
    file.resize(200, '\n');
    return file;
  };
  const std::string header = "element vertex 4000000000\nproperty float x\nproperty float y\nproperty float z\n";
  CHECK_READ_ERROR(read_ply(padded(ascii_ply(header, "1 2 3\n"))),
                   "claims 4000000000 records of element 'vertex', more than the");
  CHECK_READ_ERROR(read_ply(padded(binary_ply(header, ""))), "claims 4000000000 records of element 'vertex'");
  CHECK_READ_ERROR(read_ply(padded(binary_ply(header, "", true))), "claims 4000000000 records of element 'vertex'");
  const std::string largest = "element vertex 18446744073709551615\nproperty float x\nproperty float y\n"
                              "property float z\n";
  CHECK_READ_ERROR(read_ply(ascii_ply(largest, "1 2 3\n")), "claims 18446744073709551615 records");
  CHECK_READ_ERROR(read_ply(binary_ply(largest, std::string(12, '\0'))), "claims 18446744073709551615 records");

  // elements before the vertex element too, a list's length counting
  const std::string faces = "element face 4000000000\nproperty list uchar int vertex_indices\n";
  CHECK_READ_ERROR(read_ply(padded(ascii_ply(faces + xyz_header, ""))), "records of element 'face'");
  CHECK_READ_ERROR(read_ply(padded(binary_ply(faces + xyz_header, ""))), "records of element 'face'");
  // an element of nothing takes no bytes in binary: its count is harmless
  CHECK(read_ply(binary_ply("element nothing 18446744073709551615\n" + xyz_header, std::string(12, '\0')))
          .table.size() == 1);

  // exactly as many as fit: "1 2 3" needs 5 bytes, binary 3 floats 12
  CHECK(read_ply(ascii_ply(xyz_header, "1 2 3")).table.size() == 1);
  CHECK_READ_ERROR(read_ply(ascii_ply(xyz_header, "1 2")), "more than the 3 bytes");
  CHECK(read_ply(binary_ply(xyz_header, std::string(12, '\0'))).table.size() == 1);
  CHECK_READ_ERROR(read_ply(binary_ply(xyz_header, std::string(11, '\0'))), "more than the 11 bytes");
}

TEST_CASE("read_ply checks a binary list's length against the bytes left before reading past it", "[ply]")
{
  // one face whose list claims 4e9 ints (16 GB) before the vertex element
  const std::string header = "element face 1\nproperty list uint int vertex_indices\n" + xyz_header;
  const std::string body = bytes({ 0x00, 0x28, 0x6b, 0xee }) + std::string(12, '\0');
  CHECK_READ_ERROR(read_ply(binary_ply(header, body)), "claims 4000000000 items");
  CHECK_READ_ERROR(read_ply(binary_ply(header, bytes({ 0xee, 0x6b, 0x28, 0x00 }) + std::string(12, '\0'), true)),
                   "claims 4000000000 items");
  // and a negative length
  const std::string signed_header = "element face 1\nproperty list int int vertex_indices\n" + xyz_header;
  CHECK_READ_ERROR(read_ply(binary_ply(signed_header, bytes({ 0xff, 0xff, 0xff, 0xff }) + std::string(12, '\0'))),
                   "claims -1 items");
  // in the vertex element too
  const std::string vertex_list = "element vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
                                  "property list uint double a\n";
  CHECK_READ_ERROR(read_ply(binary_ply(vertex_list, std::string(12, '\0') + bytes({ 0xff, 0xff, 0xff, 0xff }))),
                   "claims 4294967295 items");
}

TEST_CASE("write_ply writes to its sink a buffer at a time", "[ply]")
{
  struct Counting_sink : Sink
  {
    using Sink::write;
    void write(const char* data, std::size_t size) override
    {
      ++writes;
      total.append(data, size);
    }
    std::size_t writes = 0;
    std::string total;
  };
  Point_table table;
  for (const char* name : { "x", "y", "z" })
    table.columns.push_back(column(name, Scalar_type::float64, std::vector<double>(100000, 0.123456789)));
  for (bool binary : { false, true })
  {
    Counting_sink sink;
    write_ply(sink, table, binary);
    CHECK(sink.writes <= sink.total.size() / (1 << 20) + 1);
    CHECK(read_ply(sink.total).table.size() == 100000);
  }

  struct Failing_sink : Sink
  {
    using Sink::write;
    void write(const char*, std::size_t) override { throw std::runtime_error("disk full"); }
  };
  Failing_sink failing;
  CHECK_THROWS_WITH(write_ply(failing, table, true), "disk full");
}

#ifdef ES_TEST_DATA_DIR
namespace {

std::string file_bytes(const std::filesystem::path& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The vertex count in the header's text, read without read_ply.
std::size_t header_vertex_count(const std::string& file)
{
  const std::size_t at = file.find("\nelement vertex ");
  REQUIRE(at != std::string::npos);
  return std::stoul(file.substr(at + 16, 20));
}

} // namespace

TEST_CASE("read_ply reads CGAL's demo PLY files, and writes them back exactly", "[ply][data]")
{
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(ES_TEST_DATA_DIR) / "points_3"))
  {
    if (entry.path().extension() != ".ply")
      continue;
    ++files;
    INFO(entry.path().string());
    const std::string file = file_bytes(entry.path());
    const Ply_cloud cloud = read_ply(file);
    CHECK(cloud.table.size() == header_vertex_count(file));
    CHECK(cloud.table.find("x"));
    CHECK(!cloud.comments.empty());
    for (bool binary : { false, true })
    {
      INFO("binary: " << binary);
      const Ply_cloud again = write_then_read(cloud.table, binary, cloud.comments);
      CHECK(difference(again.table, cloud.table) == "");
      CHECK(again.comments == cloud.comments);
    }
  }
  CHECK(files >= 10);
}
#endif
