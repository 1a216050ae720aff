// The point files entropy_simplify reads and writes, chosen by extension:
// PLY, XYZ (and .pwn), OFF and LAS.

#ifndef ENTROPY_SIMPLIFY_POINT_FILES_H
#define ENTROPY_SIMPLIFY_POINT_FILES_H

#include "command_line.h"
#include "las_format.h"
#include "off_format.h"
#include "ply_format.h"
#include "xyz_format.h"

#include <CGAL/Entropy_simplification/internal/Indexed_points.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace entropy_simplify {

enum class Format { ply, xyz, off, las };

// The format a file name's extension names; Usage_error for any other.
inline Format format_of(const std::string& path)
{
  const std::size_t dot = path.rfind('.');
  std::string extension = dot == std::string::npos || path.find('/', dot) != std::string::npos ? "" : path.substr(dot + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (extension == "ply")
    return Format::ply;
  if (extension == "xyz" || extension == "pwn")
    return Format::xyz;
  if (extension == "off")
    return Format::off;
  if (extension == "las")
    return Format::las;
  if (extension == "laz")
    throw Usage_error("'" + path + "': " + laz_not_supported_message());
  throw Usage_error("'" + path + "': unsupported format '" + extension +
                    "'; the formats are .ply, .xyz, .pwn, .off and .las");
}

// A point file as read: a table of properties, or LAS records kept as they
// are so that they are written back byte for byte.
struct Cloud
{
  Point_table table; // every format but LAS
  std::optional<Las_file> las;
  bool binary_ply = true; // a PLY input's encoding
  std::vector<std::string> comments, notes;

  std::size_t size() const { return las ? las->point_count : table.size(); }
};

namespace point_files_detail {

// A LAS file's coordinates are X * scale + offset, X a 32-bit integer: the
// header tells whether some could exceed what the package processes.
inline void check_las_range(const Las_file& las)
{
  const double limit = CGAL::Entropy_simplification::internal::largest_coordinate;
  for (int c = 0; c < 3; ++c)
    if (std::abs(las.offset[c]) + 2147483648. * std::abs(las.scale[c]) > limit)
      throw Read_error(std::string("the header's ") + "XYZ"[c] + " scale and offset allow coordinates beyond 1e150 "
                       "in magnitude, which the program does not process");
}

// Non-finite coordinates are an error of the file, reported with the point.
inline void check_coordinates(const Point_table& table)
{
  const Column *x = table.find("x"), *y = table.find("y"), *z = table.find("z");
  for (std::size_t i = 0; i < table.size(); ++i)
    if (!(std::isfinite(x->values[i]) && std::isfinite(y->values[i]) && std::isfinite(z->values[i])))
      throw Read_error("point #" + std::to_string(i) + " has a coordinate that is not a finite number");
}

// Throws Read_error on a text file that starts with a byte order mark, which
// some editors write and none of the text formats allows: read on, the mark
// would be the first line's garbled start, or UTF-16 and UTF-32 text every
// line's.
inline void refuse_byte_order_mark(std::string_view bytes)
{
  using namespace std::string_view_literals;
  for (const auto& [mark, encoding] : { std::pair{ "\xFF\xFE\0\0"sv, "UTF-32" }, std::pair{ "\0\0\xFE\xFF"sv, "UTF-32" },
                                        std::pair{ "\xFF\xFE"sv, "UTF-16" }, std::pair{ "\xFE\xFF"sv, "UTF-16" } })
    if (bytes.substr(0, mark.size()) == mark)
      throw Read_error(std::string("the file is ") + encoding + " text (it starts with a byte order mark): convert "
                       "it to ASCII, for example with iconv -f " + encoding + " -t ASCII FILE");
  if (bytes.substr(0, 3) == "\xEF\xBB\xBF"sv)
    throw Read_error("the file starts with a UTF-8 byte order mark (bytes EF BB BF), which the format does not "
                     "allow: remove it, for example with sed -i '1s/^\\xEF\\xBB\\xBF//' FILE");
}

} // namespace point_files_detail

// Throws Read_error when the file is not of its format, has no points, or a
// coordinate that is not finite.
inline Cloud read_cloud(std::string_view bytes, Format format)
{
  if (bytes.empty())
    throw Read_error("the file is empty");
  if (format != Format::las)
    point_files_detail::refuse_byte_order_mark(bytes);
  Cloud cloud;
  switch (format)
  {
  case Format::ply:
  {
    Ply_cloud ply = read_ply(bytes);
    cloud.table = std::move(ply.table);
    cloud.binary_ply = ply.encoding != Ply_encoding::ascii;
    cloud.comments = std::move(ply.comments);
    cloud.notes = std::move(ply.notes);
    break;
  }
  case Format::xyz: cloud.table = read_xyz(bytes); break;
  case Format::off:
  {
    Off_cloud off = read_off(bytes);
    cloud.table = std::move(off.table);
    cloud.notes = std::move(off.notes);
    break;
  }
  case Format::las:
    cloud.las = read_las(bytes);
    cloud.notes = std::move(cloud.las->notes);
    break;
  }
  if (cloud.size() == 0)
    throw Read_error("the file holds no points");
  if (cloud.las)
    point_files_detail::check_las_range(*cloud.las);
  else
    point_files_detail::check_coordinates(cloud.table);
  return cloud;
}

// The coordinates the simplification sees. LAS points are taken without the
// header's offset, so that a georeferenced scan gives the same result
// wherever it lies, and without the precision lost by adding large offsets.
inline std::array<double, 3> coordinates(const Cloud& cloud, const Column* const xyz[3], std::size_t i)
{
  if (cloud.las)
    return cloud.las->local_xyz(i);
  return { xyz[0]->values[i], xyz[1]->values[i], xyz[2]->values[i] };
}

// The column `name` of `table`, of `type`, made of `value(r)` for each row
// r, in place of any column of that name.
template <typename Value>
void set_column(Point_table& table, std::string_view name, Scalar_type type, const Value& value)
{
  Column& column = table.column(name, type);
  column.type = type;
  column.values.resize(table.size());
  for (std::size_t r = 0; r < column.values.size(); ++r)
    column.values[r] = value(r);
}

// The properties of the kept points (`rows`) as a table, with `normals`
// (one per row) in place of the input's when given.
inline Point_table output_table(const Cloud& cloud, const std::vector<std::size_t>& rows,
                                const std::vector<std::array<double, 3> >* normals)
{
  Point_table table = cloud.las ? las_point_table(*cloud.las, rows) : select_rows(cloud.table, rows);
  if (normals)
  {
    const char* const names[] = { "nx", "ny", "nz" };
    for (int c = 0; c < 3; ++c)
      set_column(table, names[c], Scalar_type::float64, [&](std::size_t r) { return (*normals)[r][c]; });
  }
  return table;
}

// The names of the columns of `table` that `format` does not store.
inline std::vector<std::string> columns_not_stored(const Point_table& table, Format format)
{
  std::vector<std::string> kept = { "x", "y", "z" };
  if (format == Format::xyz && has_normals(table))
    kept.insert(kept.end(), { "nx", "ny", "nz" });
  std::vector<std::string> dropped;
  if (format == Format::xyz || format == Format::off)
    for (const Column& column : table.columns)
      if (std::find(kept.begin(), kept.end(), column.name) == kept.end())
        dropped.push_back(column.name);
  return dropped;
}

inline void write_table(Sink& out, const Point_table& table, Format format, bool binary_ply,
                        const std::vector<std::string>& comments)
{
  switch (format)
  {
  case Format::ply: write_ply(out, table, binary_ply, comments); break;
  case Format::xyz: write_xyz(out, table); break;
  case Format::off: write_off(out, table); break;
  case Format::las: break; // LAS is written from its records, with write_las
  }
}

} // namespace entropy_simplify

#endif // ENTROPY_SIMPLIFY_POINT_FILES_H
