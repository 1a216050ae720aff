// The program's in-memory form of a point file: named, typed columns, one
// row per point, so that every property read is written back.

#ifndef ENTROPY_SIMPLIFY_POINT_TABLE_H
#define ENTROPY_SIMPLIFY_POINT_TABLE_H

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace entropy_simplify {

// The scalar types of PLY, which also cover LAS's attributes. Every value of
// each is exactly a double, so a column holds doubles whatever its type.
enum class Scalar_type { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

inline std::size_t size_of(Scalar_type type)
{
  switch (type)
  {
  case Scalar_type::int8:
  case Scalar_type::uint8: return 1;
  case Scalar_type::int16:
  case Scalar_type::uint16: return 2;
  case Scalar_type::int32:
  case Scalar_type::uint32:
  case Scalar_type::float32: return 4;
  case Scalar_type::float64: return 8;
  }
  return 0;
}

inline bool is_integral(Scalar_type type)
{
  return type != Scalar_type::float32 && type != Scalar_type::float64;
}

// Whether `value` is a value of `type`: an integer in its range, or, for the
// floating types, any double (a float column may hold what a float rounds to).
inline bool holds(Scalar_type type, double value)
{
  // the range first: converting NaN or a value beyond int64 is undefined
  const auto integer_within = [value](double low, double high) {
    return value >= low && value <= high && value == double(std::int64_t(value));
  };
  switch (type)
  {
  case Scalar_type::int8: return integer_within(-128., 127.);
  case Scalar_type::uint8: return integer_within(0., 255.);
  case Scalar_type::int16: return integer_within(-32768., 32767.);
  case Scalar_type::uint16: return integer_within(0., 65535.);
  case Scalar_type::int32: return integer_within(-2147483648., 2147483647.);
  case Scalar_type::uint32: return integer_within(0., 4294967295.);
  case Scalar_type::float32:
  case Scalar_type::float64: return true;
  }
  return false;
}

// A file that cannot be read, with what is wrong and where.
struct Read_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

struct Column
{
  std::string name;
  Scalar_type type;
  std::vector<double> values;
};

// Columns are added by `column` alone, which keeps them indexed by name, so
// that a file of many properties is read in time linear in their number.
struct Point_table
{
  std::vector<Column> columns;

  Point_table() = default;
  // The table of `given`, in that order, a column per name.
  explicit Point_table(std::vector<Column> given)
  {
    for (Column& c : given)
      column(c.name, c.type).values = std::move(c.values);
  }

  std::size_t size() const { return columns.empty() ? 0 : columns.front().values.size(); }

  const Column* find(std::string_view name) const
  {
    const auto it = position.find(std::string(name));
    return it == position.end() ? nullptr : &columns[it->second];
  }

  // The column `name`, added last (empty, of `type`) when there is none.
  Column& column(std::string_view name, Scalar_type type)
  {
    const auto [it, added] = position.emplace(std::string(name), columns.size());
    if (added)
      columns.push_back(Column{ std::string(name), type, {} });
    return columns[it->second];
  }

private:
  std::unordered_map<std::string, std::size_t> position; // of each column in `columns`
};

// The rows of `table` listed in `rows`, in that order.
inline Point_table select_rows(const Point_table& table, const std::vector<std::size_t>& rows)
{
  Point_table selected;
  for (const Column& column : table.columns)
  {
    Column& out = selected.column(column.name, column.type);
    out.values.reserve(rows.size());
    for (std::size_t row : rows)
      out.values.push_back(column.values[row]);
  }
  return selected;
}

} // namespace entropy_simplify

#endif // ENTROPY_SIMPLIFY_POINT_TABLE_H
