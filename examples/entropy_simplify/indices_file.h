// --indices FILE: the 0-based input index of each point, one per line, in
// the order given (by rank), as plain text any tool reads (NumPy's loadtxt,
// awk, a spreadsheet).

#ifndef ENTROPY_SIMPLIFY_INDICES_FILE_H
#define ENTROPY_SIMPLIFY_INDICES_FILE_H

#include "byte_io.h"

#include <charconv>
#include <string>
#include <vector>

namespace entropy_simplify {

// A megabyte at a time: one write per line would make a syscall of each.
inline void write_indices(Sink& out, const std::vector<std::size_t>& rows)
{
  constexpr std::size_t chunk = std::size_t(1) << 20;
  std::string buffer;
  buffer.reserve(chunk + 32);
  char digits[24];
  for (std::size_t row : rows)
  {
    buffer.append(digits, std::to_chars(digits, digits + sizeof digits, row).ptr);
    buffer.push_back('\n');
    if (buffer.size() >= chunk)
    {
      out.write(buffer);
      buffer.clear();
    }
  }
  out.write(buffer);
}

} // namespace entropy_simplify

#endif // ENTROPY_SIMPLIFY_INDICES_FILE_H
