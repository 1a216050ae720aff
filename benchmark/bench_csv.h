// Copyright (c) 2026 The Entropy_simplification authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reading the benchmark's own CSV files back.

#ifndef ENTROPY_SIMPLIFICATION_BENCH_CSV_H
#define ENTROPY_SIMPLIFICATION_BENCH_CSV_H

#include <string>
#include <vector>

namespace bench {

// The fields of a CSV line; a field may be quoted, holding commas.
inline std::vector<std::string> fields_of(const std::string& line)
{
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (char c : line)
  {
    if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
      fields.emplace_back();
    else
      fields.back() += c;
  }
  return fields;
}

} // namespace bench

#endif // ENTROPY_SIMPLIFICATION_BENCH_CSV_H
