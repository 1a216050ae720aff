// PLY: the vertex element of an ASCII or binary PLY file in, with all its
// scalar properties; a PLY of points out. The file is not trusted: every count
// is checked against the bytes left before anything is read or allocated for
// it, so a hostile header is a Read_error, never gigabytes or a crash.

#ifndef ENTROPY_SIMPLIFY_PLY_FORMAT_H
#define ENTROPY_SIMPLIFY_PLY_FORMAT_H

#include "byte_io.h"
#include "point_table.h"
#include "text_numbers.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

namespace entropy_simplify {

enum class Ply_encoding { ascii, binary_little_endian, binary_big_endian };

struct Ply_cloud
{
  Point_table table;                  // the vertex element's scalar properties, in file order, with their types
  Ply_encoding encoding = Ply_encoding::ascii;
  std::vector<std::string> comments;  // the text of the header's comment and obj_info lines
  std::vector<std::string> notes;     // what was read but not kept, for the program to print
};

namespace ply_detail {

// Indexed by Scalar_type: PLY's classic names, which the writer uses, and
// their sized synonyms.
inline constexpr std::string_view classic_type_names[] = { "char", "uchar", "short", "ushort",
                                                           "int",  "uint",  "float", "double" };
inline constexpr std::string_view sized_type_names[] = { "int8",  "uint8",  "int16",   "uint16",
                                                         "int32", "uint32", "float32", "float64" };

inline bool parse_type(std::string_view name, Scalar_type& type)
{
  for (int t = 0; t < 8; ++t)
    if (name == classic_type_names[t] || name == sized_type_names[t])
    {
      type = Scalar_type(t);
      return true;
    }
  return false;
}

inline std::string type_name(Scalar_type type) { return std::string(classic_type_names[int(type)]); }

struct Property
{
  std::string name;
  Scalar_type type;                             // of the value, or of a list's items
  bool is_list = false;
  Scalar_type count_type = Scalar_type::uint8;  // of a list's length
};

struct Element
{
  std::string name;
  std::size_t count = 0;
  std::vector<Property> properties;
};

struct Header
{
  Ply_encoding encoding = Ply_encoding::ascii;
  std::vector<std::string> comments;
  std::vector<Element> elements;
};

[[noreturn]] inline void throw_header_error(const Text_reader& reader, std::string_view line, const std::string& what)
{
  throw Read_error("PLY header line " + std::to_string(reader.line_number()) + " '" +
                   excerpt(line, 80) + "': " + what);
}

// A header line's first tokens; seven are enough to know that a line has too many.
inline std::vector<std::string_view> header_tokens(std::string_view line)
{
  std::vector<std::string_view> tokens;
  std::string_view token;
  while (tokens.size() < 7 && next_token_of_line(line, token))
    tokens.push_back(token);
  return tokens;
}

// What follows the keyword and one separator, so that writing the text back
// after "comment " gives the same line.
inline std::string comment_text(std::string_view line)
{
  std::string_view keyword;
  next_token_of_line(line, keyword);
  if (!line.empty())
    line.remove_prefix(1);
  return std::string(line);
}

inline bool parse_count(std::string_view token, std::size_t& count)
{
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), count);
  return error == std::errc() && end == token.data() + token.size();
}

inline Ply_encoding parse_format(const std::vector<std::string_view>& tokens, const Text_reader& reader,
                                 std::string_view line)
{
  static constexpr std::string_view names[] = { "ascii", "binary_little_endian", "binary_big_endian" };
  const auto name = std::find(std::begin(names), std::end(names), tokens.size() == 3 ? tokens[1] : "");
  if (tokens.size() != 3 || name == std::end(names) || tokens[2] != "1.0")
    throw_header_error(reader, line, "unknown format: PLY 1.0 is ascii, binary_little_endian or binary_big_endian");
  return Ply_encoding(name - std::begin(names));
}

// `names`: those of the elements declared before, which a header of many
// elements looks up in constant time, not by a pass over them.
inline Element parse_element(const std::vector<std::string_view>& tokens, std::unordered_set<std::string>& names,
                             const Text_reader& reader, std::string_view line)
{
  Element element;
  if (tokens.size() != 3 || !parse_count(tokens[2], element.count))
    throw_header_error(reader, line, "an element line is 'element NAME COUNT', COUNT a non-negative integer");
  element.name = std::string(tokens[1]);
  if (!names.insert(element.name).second)
    throw_header_error(reader, line, "element '" + element.name + "' is declared twice");
  return element;
}

// `names`: those of the element's properties declared before (see parse_element).
inline Property parse_property(const std::vector<std::string_view>& tokens, std::unordered_set<std::string>& names,
                               const Text_reader& reader, std::string_view line)
{
  Property property;
  property.is_list = tokens.size() == 5 && tokens[1] == "list";
  if (tokens.size() != (property.is_list ? 5 : 3))
    throw_header_error(reader, line, "a property line is 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
  if (!parse_type(tokens[tokens.size() - 2], property.type) ||
      (property.is_list && !parse_type(tokens[2], property.count_type)))
    throw_header_error(reader, line, "unknown type");
  if (!is_integral(property.count_type))
    throw_header_error(reader, line, "a list's length must be of an integer type");
  property.name = std::string(tokens.back());
  if (!names.insert(property.name).second)
    throw_header_error(reader, line, "property '" + property.name + "' is declared twice");
  return property;
}

// Lines may end in "\r\n": the '\r' is no part of a comment.
inline std::string_view without_carriage_returns(std::string_view line)
{
  while (!line.empty() && line.back() == '\r')
    line.remove_suffix(1);
  return line;
}

// Leaves `reader` at the first byte after the end_header line.
inline Header read_header(Text_reader& reader)
{
  std::string_view line;
  if (!reader.next_line(line) || without_carriage_returns(line) != "ply")
    throw Read_error("not a PLY file: it does not start with a 'ply' line");
  Header header;
  bool has_format = false;
  std::unordered_set<std::string> element_names, property_names; // the last element's
  while (reader.next_line(line))
  {
    line = without_carriage_returns(line);
    const std::vector<std::string_view> tokens = header_tokens(line);
    const std::string_view keyword = tokens.empty() ? "" : tokens[0];
    if (keyword == "comment" || keyword == "obj_info")
      header.comments.push_back(comment_text(line));
    else if (keyword == "format" && !has_format)
    {
      header.encoding = parse_format(tokens, reader, line);
      has_format = true;
    }
    else if (keyword == "element")
    {
      header.elements.push_back(parse_element(tokens, element_names, reader, line));
      property_names.clear();
    }
    else if (keyword == "property" && !header.elements.empty())
      header.elements.back().properties.push_back(parse_property(tokens, property_names, reader, line));
    else if (keyword == "end_header" && tokens.size() == 1)
    {
      if (!has_format)
        throw Read_error("the PLY header has no format line");
      return header;
    }
    else
      throw_header_error(reader, line, "not a line of a PLY header (or one out of place)");
  }
  throw Read_error("the PLY header has no end_header line");
}

// The fewest bytes a record of `element` takes: in binary, its scalars and
// its lists' lengths; in ASCII, two per value ("0 " or "0\n"), a list taking
// at least its length, a record of nothing an empty line.
inline std::size_t shortest_record(const Element& element, bool ascii)
{
  std::size_t bytes = 0;
  for (const Property& property : element.properties)
    bytes += ascii ? 2 : size_of(property.is_list ? property.count_type : property.type);
  return ascii ? std::max<std::size_t>(bytes, 1) : bytes;
}

// Called before reading an element, with the bytes left after the ones before it.
inline void check_count_fits(const Element& element, bool ascii, std::size_t remaining)
{
  // the file's last value needs no separator after it
  const std::size_t available = remaining + (ascii && !element.properties.empty() ? 1 : 0);
  const std::size_t shortest = shortest_record(element, ascii);
  if (shortest > 0 && element.count > available / shortest)
    throw Read_error("the PLY header claims " + std::to_string(element.count) + " records of element '" +
                     element.name + "', more than the " + std::to_string(remaining) +
                     " bytes left in the file can hold");
}

// ---- Binary bodies ----

// Reads past a list, its length checked against the bytes left first.
inline void skip_binary_list(Byte_reader& reader, const Property& list, bool big_endian, const std::string& what)
{
  const double length = load_scalar(reader.take(size_of(list.count_type), what.c_str()), list.count_type, big_endian);
  if (length < 0. || std::size_t(length) > reader.remaining() / size_of(list.type))
    throw Read_error("list '" + list.name + "' of " + what + " claims " + std::to_string(std::int64_t(length)) +
                     " items at byte " + std::to_string(reader.position()) + ", which the " +
                     std::to_string(reader.remaining()) + " bytes left in the file cannot hold");
  reader.take(std::size_t(length) * size_of(list.type), what.c_str());
}

inline void skip_binary_element(Byte_reader& reader, const Element& element, bool big_endian)
{
  const std::string what = "element '" + element.name + "'";
  const bool has_lists = std::any_of(element.properties.begin(), element.properties.end(),
                                     [](const Property& p) { return p.is_list; });
  if (!has_lists) // check_count_fits() bounds the product
    reader.take(element.count * shortest_record(element, false), what.c_str());
  else
    for (std::size_t i = 0; i < element.count; ++i)
      for (const Property& property : element.properties)
        if (property.is_list)
          skip_binary_list(reader, property, big_endian, what);
        else
          reader.take(size_of(property.type), what.c_str());
}

inline void read_binary_vertices(Byte_reader& reader, const Element& vertex, bool big_endian, Point_table& table)
{
  const std::string what = "element 'vertex'";
  for (std::size_t i = 0; i < vertex.count; ++i)
  {
    std::size_t column = 0;
    for (const Property& property : vertex.properties)
      if (property.is_list)
        skip_binary_list(reader, property, big_endian, what);
      else
        table.columns[column++].values.push_back(
          load_scalar(reader.take(size_of(property.type), what.c_str()), property.type, big_endian));
  }
}

// ---- ASCII bodies: one record a line ----

// `token` as a float. It is parsed anew, not rounded from `value`, the
// double it reads as: rounding twice gives the wrong float for a few decimals
// (7.038531e-26), which would break ASCII round trips. False when it is too
// large; too small, it rounds to 0.
inline bool parse_float(std::string_view token, double& value)
{
  const std::string_view number = token.substr(token.front() == '+' ? 1 : 0);
  float rounded;
  const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), rounded);
  if (error == std::errc() && end == number.data() + number.size())
    value = rounded;
  else if (std::abs(value) < 1.)
    value = float(value);
  else
    return false;
  return true;
}

// `value`, read from `token`, as a value of `type`: a float rounded to float
// (as binary PLY holds it); an integer in range, -0 made 0 (as it reads
// back). False when it is none.
inline bool convert_to(Scalar_type type, std::string_view token, double& value)
{
  if (type == Scalar_type::float64)
    return true;
  if (type == Scalar_type::float32)
    return parse_float(token, value);
  // holds() converts to std::int64_t first, undefined for NaN or beyond its range
  if (!(std::abs(value) < 4294967296.) || !holds(type, value))
    return false;
  if (value == 0.)
    value = 0.;
  return true;
}

inline std::string at_line(const Text_reader& reader) { return "line " + std::to_string(reader.line_number()) + ": "; }

// The next value of a vertex line, for `property`, of `type`.
inline double next_ascii_value(const Text_reader& reader, std::string_view& line, const Property& property,
                               Scalar_type type)
{
  std::string_view token;
  if (!next_token_of_line(line, token))
    throw Read_error(at_line(reader) + "a vertex has too few values: property '" + property.name + "' is missing");
  double value;
  if (!parse_number(token, value))
    throw Read_error(at_line(reader) + "property '" + property.name + "' is not a number: '" +
                     excerpt(token, 40) + "'");
  if (!convert_to(type, token, value))
    throw Read_error(at_line(reader) + excerpt(token, 40) + " does not fit property '" +
                     property.name + "' of type " + type_name(type));
  return value;
}

// Each item is checked like a value kept; a length beyond the line's values
// ends in "too few values", the loop consuming a token a turn.
inline void skip_ascii_list(const Text_reader& reader, std::string_view& line, const Property& list)
{
  const double length = next_ascii_value(reader, line, list, list.count_type);
  if (length < 0.)
    throw Read_error(at_line(reader) + "list '" + list.name + "' has a negative length");
  for (std::size_t i = 0; i < std::size_t(length); ++i)
    next_ascii_value(reader, line, list, list.type);
}

inline void skip_ascii_element(Text_reader& reader, const Element& element)
{
  std::string_view line;
  for (std::size_t i = 0; i < element.count; ++i)
    if (!reader.next_line(line))
      throw Read_error("the file is truncated: it ends after " + std::to_string(i) + " of " +
                       std::to_string(element.count) + " records of element '" + element.name + "'");
}

inline void read_ascii_vertices(Text_reader& reader, const Element& vertex, Point_table& table)
{
  std::string_view line, token;
  for (std::size_t i = 0; i < vertex.count; ++i)
  {
    if (!reader.next_line(line))
      throw Read_error("the file is truncated: it ends after " + std::to_string(i) + " of " +
                       std::to_string(vertex.count) + " vertices");
    std::size_t column = 0;
    for (const Property& property : vertex.properties)
      if (property.is_list)
        skip_ascii_list(reader, line, property);
      else
        table.columns[column++].values.push_back(next_ascii_value(reader, line, property, property.type));
    if (next_token_of_line(line, token))
      throw Read_error(at_line(reader) + "a vertex has too many values: '" + excerpt(token, 40) +
                       "' follows its last property");
  }
}

// The vertices a header declares are all that is kept: a file holding more
// data after its last element may count them wrong, and its user should
// hear of it. `last` is that element.
inline void note_bytes_after_elements(std::size_t bytes, const Element& last, const Element& vertex,
                                      std::vector<std::string>& notes)
{
  if (bytes == 0)
    return;
  const std::string follow = std::to_string(bytes) + (bytes == 1 ? " byte follows" : " bytes follow") + " the ";
  const std::string not_read = std::string(bytes == 1 ? "was" : "were") + " not read: if more vertices are there, ";
  if (&last == &vertex)
    notes.push_back(follow + std::to_string(vertex.count) + (vertex.count == 1 ? " vertex" : " vertices") +
                    " that the header declares, and " + not_read + "the header's count is wrong");
  else
    notes.push_back(follow + "elements that the header declares, the " + std::to_string(vertex.count) +
                    (vertex.count == 1 ? " vertex" : " vertices") + " and those after them, and " + not_read +
                    "the header's counts are wrong");
}

// Reads past the elements after the vertices, [first, beyond), and notes
// the bytes after them, or what does not match the header there: a header
// that counts the vertices wrong, or whose format is not the body's, shows
// there as well when the vertices are not the last element.
template <typename Iterator>
inline void note_what_follows_vertices(Iterator first, Iterator beyond, const Element& vertex, bool ascii,
                                       bool big_endian, std::string_view bytes, Text_reader& text,
                                       Byte_reader& binary, std::vector<std::string>& notes)
{
  const Element* last = &vertex;
  try
  {
    for (Iterator element = first; element != beyond; ++element)
    {
      check_count_fits(*element, ascii, ascii ? bytes.size() - text.position() : binary.remaining());
      if (ascii)
        skip_ascii_element(text, *element);
      else
        skip_binary_element(binary, *element, big_endian);
      last = &*element;
    }
  }
  catch (const Read_error& error)
  {
    notes.push_back(std::string("the elements after the vertices do not match the header (") + error.what() +
                    "): if the vertices are not what the header declares either, the file is not read right");
    return;
  }
  note_bytes_after_elements(ascii ? (text.rest_is_blank() ? 0 : bytes.size() - text.position()) : binary.remaining(),
                            *last, vertex, notes);
}

// ---- What is kept ----

// The vertex element's scalar properties as empty columns; its lists, and
// the other elements, as notes.
inline Point_table vertex_columns(const Header& header, const Element& vertex, std::vector<std::string>& notes)
{
  Point_table table;
  for (const Property& property : vertex.properties)
    if (property.is_list)
      notes.push_back("vertex list property '" + property.name + "' dropped: only scalar properties are kept");
    else
      table.column(property.name, property.type);
  if (!table.find("x") || !table.find("y") || !table.find("z"))
    throw Read_error("the PLY file has no x, y, z vertex properties");
  for (const Element& element : header.elements)
    if (&element != &vertex && element.count > 0)
      notes.push_back(std::to_string(element.count) + " " + element.name + (element.count == 1 ? "" : "s") +
                      " dropped: a simplified point set has only vertices");
  return table;
}

} // namespace ply_detail

// Reads the vertex element; the other elements are read past, and what
// follows the last is noted.
inline Ply_cloud read_ply(std::string_view bytes)
{
  using namespace ply_detail;
  Text_reader text(bytes);
  Header header = read_header(text);
  const auto vertex = std::find_if(header.elements.begin(), header.elements.end(),
                                   [](const Element& e) { return e.name == "vertex"; });
  if (vertex == header.elements.end())
    throw Read_error("the PLY file has no vertex element");

  Ply_cloud cloud;
  cloud.encoding = header.encoding;
  cloud.comments = std::move(header.comments);
  cloud.table = vertex_columns(header, *vertex, cloud.notes);
  const bool ascii = header.encoding == Ply_encoding::ascii;
  const bool big_endian = header.encoding == Ply_encoding::binary_big_endian;
  Byte_reader binary(bytes, text.position());
  for (auto element = header.elements.begin(); element != vertex; ++element)
  {
    check_count_fits(*element, ascii, ascii ? bytes.size() - text.position() : binary.remaining());
    if (ascii)
      skip_ascii_element(text, *element);
    else
      skip_binary_element(binary, *element, big_endian);
  }
  check_count_fits(*vertex, ascii, ascii ? bytes.size() - text.position() : binary.remaining());
  for (Column& column : cloud.table.columns)
    column.values.reserve(vertex->count);
  if (ascii)
    read_ascii_vertices(text, *vertex, cloud.table);
  else
    read_binary_vertices(binary, *vertex, big_endian, cloud.table);
  note_what_follows_vertices(vertex + 1, header.elements.end(), *vertex, ascii, big_endian, bytes, text, binary,
                             cloud.notes);
  return cloud;
}

namespace ply_detail {

inline std::string header_text(const Point_table& table, bool binary, const std::vector<std::string>& comments)
{
  std::string header = binary ? "ply\nformat binary_little_endian 1.0\n" : "ply\nformat ascii 1.0\n";
  for (std::string comment : comments)
  {
    std::replace(comment.begin(), comment.end(), '\n', ' '); // a comment is one line
    header += "comment " + comment + "\n";
  }
  header += "element vertex " + std::to_string(table.size()) + "\n";
  for (const Column& column : table.columns)
    header += "property " + type_name(column.type) + " " + column.name + "\n";
  return header + "end_header\n";
}

inline void append_row(std::string& buffer, const Point_table& table, std::size_t row, bool binary)
{
  for (std::size_t c = 0; c < table.columns.size(); ++c)
  {
    const Column& column = table.columns[c];
    if (binary)
    {
      char bytes[8];
      store_scalar(bytes, column.type, column.values[row]);
      buffer.append(bytes, size_of(column.type));
    }
    else
    {
      if (c > 0)
        buffer += ' ';
      append_number(buffer, column.values[row], column.type);
    }
  }
  if (!binary)
    buffer += '\n';
}

} // namespace ply_detail

// Every value must be a value of its column's type (see holds()); `binary`
// writes binary_little_endian. The sink sees a write per MiB, not per value.
inline void write_ply(Sink& out, const Point_table& table, bool binary, const std::vector<std::string>& comments = {})
{
  for (const Column& column : table.columns)
    if (column.values.size() != table.size())
      throw std::invalid_argument("write_ply: column '" + column.name + "' is not as long as the others");
  constexpr std::size_t flush_size = std::size_t(1) << 20;
  std::string buffer = ply_detail::header_text(table, binary, comments);
  buffer.reserve(flush_size + 4096);
  for (std::size_t row = 0; row < table.size(); ++row)
  {
    ply_detail::append_row(buffer, table, row, binary);
    if (buffer.size() >= flush_size)
    {
      out.write(buffer);
      buffer.clear();
    }
  }
  if (!buffer.empty())
    out.write(buffer);
}

} // namespace entropy_simplify

#endif // ENTROPY_SIMPLIFY_PLY_FORMAT_H
