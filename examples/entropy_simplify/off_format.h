// OFF: the vertices of an OFF or NOFF file in; a plain OFF of points out.

#ifndef ENTROPY_SIMPLIFY_OFF_FORMAT_H
#define ENTROPY_SIMPLIFY_OFF_FORMAT_H

#include "xyz_format.h"

#include <charconv>
#include <string>
#include <string_view>
#include <vector>

namespace entropy_simplify {

struct Off_cloud
{
  Point_table table;
  std::vector<std::string> notes;
};

namespace off_detail {

// The next line holding something other than a '#' comment, split in tokens.
inline bool next_content_line(Text_reader& reader, std::vector<std::string_view>& tokens)
{
  std::string_view line;
  while (reader.next_line(line))
  {
    tokens.clear();
    std::string_view token;
    while (next_token_of_line(line, token) && token.front() != '#')
      tokens.push_back(token);
    if (!tokens.empty())
      return true;
  }
  return false;
}

inline std::size_t parse_count(std::string_view token, const char* what)
{
  std::size_t count = 0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), count);
  if (error != std::errc() || end != token.data() + token.size())
    throw Read_error(std::string("the OFF header's ") + what + " is not a count: '" +
                     excerpt(token, 40) + "'");
  return count;
}

// Whether `tokens` may be a face: a vertex count, then at least that many
// indices (and perhaps a colour).
inline bool may_be_a_face(const std::vector<std::string_view>& tokens)
{
  std::size_t count = 0;
  const auto [end, error] = std::from_chars(tokens[0].data(), tokens[0].data() + tokens[0].size(), count);
  return error == std::errc() && end == tokens[0].data() + tokens[0].size() && count >= 1 &&
         tokens.size() > count;
}

// The vertices a header declares are all that is read. Faces may follow
// them, when the header declares some; anything else suggests that the
// header counts the vertices wrong, and the user should hear of it, as of
// a PLY file's bytes after its vertices.
inline void note_lines_after_vertices(Text_reader& reader, std::size_t vertices, std::size_t faces,
                                      std::vector<std::string>& notes)
{
  std::vector<std::string_view> tokens;
  if (!next_content_line(reader, tokens) || (faces > 0 && may_be_a_face(tokens)))
    return;
  notes.push_back("line " + std::to_string(reader.line_number()) + ", after the " + std::to_string(vertices) +
                  (vertices == 1 ? " vertex" : " vertices") + " that the header declares, is not " +
                  (faces > 0 ? "a face" : "read, as the header declares no faces") +
                  ": if more vertices are there, the header's count is wrong");
}

} // namespace off_detail

// The header is `OFF` or `NOFF` (a normal after each vertex), then the
// counts of vertices, faces and edges, on the same line or the next. Faces
// are not read, a simplified point set having none; what follows the
// vertices is noted when it cannot be a face.
inline Off_cloud read_off(std::string_view bytes)
{
  Text_reader reader(bytes);
  std::vector<std::string_view> tokens;
  if (!off_detail::next_content_line(reader, tokens) || (tokens[0] != "OFF" && tokens[0] != "NOFF"))
    throw Read_error("not an OFF file: it does not start with OFF or NOFF (other OFF variants are not supported)");
  const bool normals = tokens[0] == "NOFF";
  tokens.erase(tokens.begin());
  if (tokens.empty() && !off_detail::next_content_line(reader, tokens))
    throw Read_error("the OFF header has no vertex count");
  if (tokens.size() != 3)
    throw Read_error("line " + std::to_string(reader.line_number()) +
                     ": the OFF header needs 3 counts (vertices, faces, edges)");
  const std::size_t vertices = off_detail::parse_count(tokens[0], "vertex count");
  const std::size_t faces = off_detail::parse_count(tokens[1], "face count");
  // "0 0 0\n" is the shortest vertex line (the last needs no '\n'): a
  // larger count cannot be true
  const std::size_t width = normals ? 6 : 3;
  if (vertices > (bytes.size() - reader.position() + 1) / (2 * width))
    throw Read_error("the OFF header claims " + std::to_string(vertices) + " vertices, more than the " +
                     std::to_string(bytes.size() - reader.position()) + " bytes after it can hold");

  static const char* const names[] = { "x", "y", "z", "nx", "ny", "nz" };
  Off_cloud cloud;
  for (std::size_t c = 0; c < width; ++c)
    cloud.table.column(names[c], Scalar_type::float64).values.reserve(vertices);
  for (std::size_t v = 0; v < vertices; ++v)
  {
    if (!off_detail::next_content_line(reader, tokens))
      throw Read_error("the file is truncated: it ends after " + std::to_string(v) + " of " +
                       std::to_string(vertices) + " vertices");
    if (tokens.size() != width)
      throw Read_error("line " + std::to_string(reader.line_number()) + " holds " +
                       std::to_string(tokens.size()) + " values; a vertex of " + (normals ? "NOFF" : "OFF") +
                       " holds " + std::to_string(width));
    for (std::size_t c = 0; c < width; ++c)
    {
      double value;
      if (!parse_number(tokens[c], value))
        throw Read_error("line " + std::to_string(reader.line_number()) + ": '" +
                         excerpt(tokens[c], 40) + "' is not a number");
      cloud.table.columns[c].values.push_back(value);
    }
  }
  if (faces > 0)
    cloud.notes.push_back(std::to_string(faces) + (faces == 1 ? " face" : " faces") +
                          " dropped: a simplified point set has no faces");
  off_detail::note_lines_after_vertices(reader, vertices, faces, cloud.notes);
  return cloud;
}

// A plain OFF of the points: the variant every reader knows (CloudCompare
// refuses NOFF, so normals are not written).
inline void write_off(Sink& out, const Point_table& table)
{
  out.write("OFF\n" + std::to_string(table.size()) + " 0 0\n");
  write_columns_as_lines(out, table, { "x", "y", "z" });
}

} // namespace entropy_simplify

#endif // ENTROPY_SIMPLIFY_OFF_FORMAT_H
