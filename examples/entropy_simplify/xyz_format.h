// XYZ (and CGAL's .pwn): one point a line, `x y z` or `x y z nx ny nz`.

#ifndef ENTROPY_SIMPLIFY_XYZ_FORMAT_H
#define ENTROPY_SIMPLIFY_XYZ_FORMAT_H

#include "byte_io.h"
#include "text_numbers.h"

#include <string>
#include <string_view>

namespace entropy_simplify {

// Blank lines and lines starting with '#' are skipped. Every other line holds
// 3 or 6 numbers, as many as the first such line: a line of another length is
// an error rather than a guess (a 9-number line is a triangle, not a point).
inline Point_table read_xyz(std::string_view bytes)
{
  static const char* const names[] = { "x", "y", "z", "nx", "ny", "nz" };
  Point_table table;
  Text_reader reader(bytes);
  std::string_view line;
  std::size_t width = 0;
  while (reader.next_line(line))
  {
    double values[6];
    std::size_t count = 0;
    std::string_view token, rest = line;
    while (next_token_of_line(rest, token))
    {
      if (count == 0 && token.front() == '#')
        break;
      if (count == 6 || !parse_number(token, values[count]))
        throw Read_error("line " + std::to_string(reader.line_number()) +
                         ": an XYZ line holds 3 or 6 numbers (x y z, then a normal), got '" +
                         excerpt(line, 80) + "'");
      ++count;
    }
    if (count == 0)
      continue;
    if (width == 0 && (count == 3 || count == 6))
    {
      width = count;
      for (std::size_t c = 0; c < width; ++c)
        table.column(names[c], Scalar_type::float64);
    }
    if (count != width)
      throw Read_error("line " + std::to_string(reader.line_number()) + " holds " + std::to_string(count) +
                       " numbers; " + (width == 0 ? std::string("XYZ lines hold 3 or 6")
                                                   : "the lines before it hold " + std::to_string(width)));
    for (std::size_t c = 0; c < width; ++c)
      table.columns[c].values.push_back(values[c]);
  }
  return table;
}

// `names` of `table`, as one line of text per row.
inline void write_columns_as_lines(Sink& out, const Point_table& table, const std::vector<std::string>& names)
{
  std::vector<const Column*> columns;
  for (const std::string& name : names)
    columns.push_back(table.find(name));
  std::string buffer;
  for (std::size_t row = 0; row < table.size(); ++row)
  {
    for (std::size_t c = 0; c < columns.size(); ++c)
    {
      if (c > 0)
        buffer += ' ';
      append_number(buffer, columns[c]->values[row], columns[c]->type);
    }
    buffer += '\n';
    if (buffer.size() >= (1 << 20))
    {
      out.write(buffer);
      buffer.clear();
    }
  }
  out.write(buffer);
}

inline bool has_normals(const Point_table& table)
{
  return table.find("nx") && table.find("ny") && table.find("nz");
}

// x y z, and the normal when the table has one; other columns are not
// written (the program says so).
inline void write_xyz(Sink& out, const Point_table& table)
{
  if (has_normals(table))
    write_columns_as_lines(out, table, { "x", "y", "z", "nx", "ny", "nz" });
  else
    write_columns_as_lines(out, table, { "x", "y", "z" });
}

} // namespace entropy_simplify

#endif // ENTROPY_SIMPLIFY_XYZ_FORMAT_H
