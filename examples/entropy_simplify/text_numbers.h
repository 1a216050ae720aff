// Numbers as text, for the text formats (XYZ, OFF, ASCII PLY): parsed and
// printed with <charconv>, so that neither depends on the locale and every
// double prints in the fewest digits that read back to it.

#ifndef ENTROPY_SIMPLIFY_TEXT_NUMBERS_H
#define ENTROPY_SIMPLIFY_TEXT_NUMBERS_H

#include "point_table.h"

#include <charconv>
#include <cstdlib>
#include <cstdint>
#include <string>
#include <string_view>
#include <system_error>

namespace entropy_simplify {

// The whole of `token` as a number (a leading '+' allowed; "nan" and "inf"
// are numbers, which callers check); false when it is not one. A magnitude
// beyond a double's range reads as infinite or zero, as strtod reads it.
inline bool parse_number(std::string_view token, double& value)
{
  const bool plus = !token.empty() && token.front() == '+';
  if (plus)
    token.remove_prefix(1);
  // from_chars takes no '+', and no second sign follows a first
  if (token.empty() || token.front() == '+' || (plus && token.front() == '-'))
    return false;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (end != token.data() + token.size())
    return false;
  if (error == std::errc::result_out_of_range)
    value = std::strtod(std::string(token).c_str(), nullptr);
  return error == std::errc() || error == std::errc::result_out_of_range;
}

inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// At most `length` characters of a file's text for an error message, bytes
// that do not print shown as '?'.
inline std::string excerpt(std::string_view text, std::size_t length = 40)
{
  std::string shown(text.substr(0, length));
  for (char& c : shown)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f)
      c = '?';
  return shown;
}

// Reads text line by line, or token by token across lines, counting lines
// for error messages.
class Text_reader
{
public:
  explicit Text_reader(std::string_view text, std::size_t position = 0) : text_(text), position_(position) {}

  std::size_t position() const { return position_; }
  // the number of the line the last line or token read was on, from 1
  std::size_t line_number() const { return line_; }
  bool at_end() const { return position_ >= text_.size(); }
  // whether only white space and line ends are left
  bool rest_is_blank() const
  {
    return at_end() || text_.find_first_not_of(" \t\r\v\f\n", position_) == std::string_view::npos;
  }

  // The next line, without its end of line (LF, CRLF, or CR alone, as old
  // Mac files have it); false at the end of the text.
  bool next_line(std::string_view& line)
  {
    if (at_end())
      return false;
    if (line_started_)
      ++line_;
    const std::size_t end = text_.find_first_of("\r\n", position_);
    const std::size_t stop = end == std::string_view::npos ? text_.size() : end;
    line = text_.substr(position_, stop - position_);
    position_ = stop == text_.size() ? stop : stop + (text_.substr(stop, 2) == "\r\n" ? 2 : 1);
    line_started_ = true;
    return true;
  }

  // The next whitespace-separated token, across lines; false at the end.
  bool next_token(std::string_view& token)
  {
    while (!at_end() && (is_space(text_[position_]) || text_[position_] == '\n'))
    {
      if (text_[position_] == '\n')
        ++line_;
      ++position_;
    }
    if (at_end())
      return false;
    const std::size_t start = position_;
    while (!at_end() && !is_space(text_[position_]) && text_[position_] != '\n')
      ++position_;
    token = text_.substr(start, position_ - start);
    return true;
  }

  // The next token as a number, or a Read_error naming `what` and the line.
  double next_number(const std::string& what)
  {
    std::string_view token;
    if (!next_token(token))
      throw Read_error("the file ends before " + what);
    double value;
    if (!parse_number(token, value))
      throw Read_error("line " + std::to_string(line_) + ": " + what + " is not a number: '" +
                       excerpt(token) + "'");
    return value;
  }

private:
  std::string_view text_;
  std::size_t position_;
  std::size_t line_ = 1;
  bool line_started_ = false;
};

// The whitespace-separated tokens of one line.
inline bool next_token_of_line(std::string_view& line, std::string_view& token)
{
  std::size_t start = 0;
  while (start < line.size() && is_space(line[start]))
    ++start;
  if (start == line.size())
    return false;
  std::size_t end = start;
  while (end < line.size() && !is_space(line[end]))
    ++end;
  token = line.substr(start, end - start);
  line.remove_prefix(end);
  return true;
}

// Appends `value`, a value of `type`, in the fewest characters that read
// back to it (as a float for float32).
inline void append_number(std::string& out, double value, Scalar_type type)
{
  char buffer[32];
  std::to_chars_result result;
  if (is_integral(type))
    result = std::to_chars(buffer, buffer + sizeof buffer, std::int64_t(value));
  else if (type == Scalar_type::float32)
    result = std::to_chars(buffer, buffer + sizeof buffer, float(value));
  else
    result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

} // namespace entropy_simplify

#endif // ENTROPY_SIMPLIFY_TEXT_NUMBERS_H
