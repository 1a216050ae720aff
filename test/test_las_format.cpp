// Tests of the command-line program's LAS reader and writer, on files built
// byte by byte from the LAS specification: every version and point format,
// VLRs, EVLRs and waveform data, subsets written back, hostile headers,
// truncated and corrupted files, and CGAL's demo LAS files.

#include <catch2/catch.hpp>

#include "check_read_error.h"

#include "las_format.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

using namespace entropy_simplify;
using Catch::Matchers::Contains;


namespace {

// The specification's record sizes, written out again here so that the
// builder's field-by-field layout is checked against them.
const std::size_t base_sizes[11] = { 20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67 };

std::size_t header_size_of(int minor) { return minor <= 2 ? 227 : minor == 3 ? 235 : 375; }

bool is_extended(int format) { return format >= 6; }
bool has_wave_packets(int format) { return format == 4 || format == 5 || format == 9 || format == 10; }

struct Test_point
{
  std::int32_t x = 0, y = 0, z = 0;
  unsigned intensity = 0, return_number = 0, number_of_returns = 0, scan_direction = 0, edge = 0;
  unsigned classification = 0, synthetic = 0, key_point = 0, withheld = 0, overlap = 0, scanner_channel = 0;
  int scan_angle = 0; // the rank (int8) in formats 0-5, in units of 0.006 degrees (int16) in 6-10
  unsigned user_data = 0, point_source_id = 0;
  double gps_time = 0.;
  unsigned red = 0, green = 0, blue = 0, nir = 0;
};

struct Test_las
{
  int minor = 2, format = 0;
  std::size_t extra_bytes = 0;
  std::size_t header_padding = 0;       // user bytes at the end of the public header
  std::vector<std::string> vlrs, evlrs; // their payloads
  std::string before_points;            // user bytes between the VLRs and the points
  std::string waveform;                 // waveform data right after the points (1.3 and 1.4)
  std::uint64_t legacy_count = 0, count_64 = 0; // the header's counts; see build()
  double scale[3] = { 0.01, 0.001, 0.25 }, offset[3] = { 1000.5, -2e6, 3. };
  std::vector<Test_point> points;
};

template <typename T>
void append(std::string& bytes, T value)
{
  char b[sizeof(T)];
  store_little_endian(b, value);
  bytes.append(b, sizeof(T));
}

template <typename T>
void put(std::string& bytes, std::size_t at, T value)
{
  REQUIRE(at + sizeof(T) <= bytes.size());
  // through a copy: GCC 12 mistakes a write into a string for one past a literal (-Wstringop-overflow)
  char stored[sizeof(T)];
  store_little_endian(stored, value);
  bytes.replace(at, sizeof(T), stored, sizeof(T));
}

template <typename T>
T get(const std::string& bytes, std::size_t at)
{
  return load_little_endian<T>(&bytes[at]);
}

// Every attribute varies, so that a field read from the wrong place shows.
std::vector<Test_point> make_points(int format, std::size_t n)
{
  const bool extended = is_extended(format);
  std::vector<Test_point> points(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    Test_point& p = points[i];
    const int k = int(i);
    p.x = 1000 * k - 70000;
    p.y = -3 * k * k + 5;
    p.z = (k % 2 ? -1 : 1) * (11 * k + 2);
    p.intensity = unsigned(65535 - 1000 * k);
    p.return_number = i % (extended ? 16 : 8);
    p.number_of_returns = (5 * i + 1) % (extended ? 16 : 8);
    p.scan_direction = i % 2;
    p.edge = i / 2 % 2;
    p.classification = extended ? 37 * i % 256 : 3 * i % 32;
    p.synthetic = i / 3 % 2;
    p.key_point = i / 4 % 2;
    p.withheld = i / 5 % 2;
    p.overlap = extended ? i / 6 % 2 : 0;
    p.scanner_channel = extended ? i % 4 : 0;
    p.scan_angle = extended ? -30000 + 3001 * k % 60001 : -90 + 17 * k % 181;
    p.user_data = 29 * i % 256;
    p.point_source_id = unsigned(65535 - 3 * k);
    p.gps_time = 123456.5 + 0.25 * k;
    p.red = 256 * i;
    p.green = 65535 - 7 * i;
    p.blue = 1000 + i;
    p.nir = 40000 + i;
  }
  return points;
}

// A point record, field after field as the specification's tables list them.
std::string encode(const Test_las& las, const Test_point& p, std::size_t index)
{
  const int f = las.format;
  std::string r;
  append(r, p.x);
  append(r, p.y);
  append(r, p.z);
  append(r, std::uint16_t(p.intensity));
  if (!is_extended(f))
  {
    append(r, std::uint8_t(p.return_number | (p.number_of_returns << 3) | (p.scan_direction << 6) | (p.edge << 7)));
    append(r, std::uint8_t(p.classification | (p.synthetic << 5) | (p.key_point << 6) | (p.withheld << 7)));
    append(r, std::int8_t(p.scan_angle));
    append(r, std::uint8_t(p.user_data));
    append(r, std::uint16_t(p.point_source_id));
    if (f != 0 && f != 2)
      append(r, p.gps_time);
  }
  else
  {
    append(r, std::uint8_t(p.return_number | (p.number_of_returns << 4)));
    append(r, std::uint8_t(p.synthetic | (p.key_point << 1) | (p.withheld << 2) | (p.overlap << 3) |
                           (p.scanner_channel << 4) | (p.scan_direction << 6) | (p.edge << 7)));
    append(r, std::uint8_t(p.classification));
    append(r, std::uint8_t(p.user_data));
    append(r, std::int16_t(p.scan_angle));
    append(r, std::uint16_t(p.point_source_id));
    append(r, p.gps_time);
  }
  if (f == 2 || f == 3 || f == 5 || f == 7 || f == 8 || f == 10)
    for (unsigned value : { p.red, p.green, p.blue })
      append(r, std::uint16_t(value));
  if (f == 8 || f == 10)
    append(r, std::uint16_t(p.nir));
  if (has_wave_packets(f))
  {
    // descriptor index, byte offset to the waveform data, packet size, return point location, x(t) y(t) z(t)
    append(r, std::uint8_t(1 + index % 255));
    append(r, std::uint64_t(1000 * index));
    append(r, std::uint32_t(64));
    for (float value : { 0.5f * float(index), 0.25f, -0.5f, 1.f })
      append(r, value);
  }
  REQUIRE(r.size() == base_sizes[f]);
  for (std::size_t k = 0; k < las.extra_bytes; ++k)
    r += char(7 * index + k + 1);
  return r;
}

// A VLR (54-byte header) or, `extended`, an EVLR (60-byte header), then its payload.
std::string variable_length_record(const std::string& payload, std::size_t index, bool extended)
{
  std::string record;
  append(record, std::uint16_t(extended ? 0 : 0xaabb)); // reserved; LAS 1.0's record signature
  std::string user_id = "es_test";
  user_id.resize(16, '\0');
  record += user_id;
  append(record, std::uint16_t(1000 + index));
  if (extended)
    append(record, std::uint64_t(payload.size()));
  else
    append(record, std::uint16_t(payload.size()));
  std::string description = "test record " + std::to_string(index);
  description.resize(32, '\0');
  record += description;
  REQUIRE(record.size() == (extended ? 60u : 54u));
  return record + payload;
}

std::uint64_t count_with_return(const std::vector<Test_point>& points, const std::vector<std::size_t>& rows,
                                unsigned return_number)
{
  std::uint64_t count = 0;
  for (std::size_t row : rows)
    count += points[row].return_number == return_number;
  return count;
}

std::vector<std::size_t> all_rows(std::size_t n)
{
  std::vector<std::size_t> rows(n);
  for (std::size_t i = 0; i < n; ++i)
    rows[i] = i;
  return rows;
}

// The header's counts are the true ones unless `legacy_count` or `count_64`
// say otherwise; the bounds are the true ones; every byte of the header that
// no field below sets holds letters, so that copying them shows.
std::string build(const Test_las& t)
{
  const std::size_t header_size = header_size_of(t.minor) + t.header_padding;
  std::string file(header_size, '\0');
  for (std::size_t i = 4; i < header_size; ++i)
    file[i] = char('a' + i % 26);
  file.replace(0, 4, "LASF");
  file[24] = 1;
  file[25] = char(t.minor);
  put(file, 94, std::uint16_t(header_size));
  for (std::size_t i = 0; i < t.vlrs.size(); ++i)
    file += variable_length_record(t.vlrs[i], i, false);
  file += t.before_points;
  const std::size_t offset_to_points = file.size();
  put(file, 96, std::uint32_t(offset_to_points));
  put(file, 100, std::uint32_t(t.vlrs.size()));
  file[104] = char(t.format);
  put(file, 105, std::uint16_t(base_sizes[t.format] + t.extra_bytes));

  const std::vector<std::size_t> rows = all_rows(t.points.size());
  const bool legacy = !is_extended(t.format);
  put(file, 107, std::uint32_t(t.legacy_count ? t.legacy_count : legacy ? t.points.size() : 0));
  for (unsigned r = 1; r <= 5; ++r)
    put(file, 111 + 4 * (r - 1), std::uint32_t(legacy ? count_with_return(t.points, rows, r) : 0));
  for (int c = 0; c < 3; ++c)
  {
    put(file, 131 + 8 * c, t.scale[c]);
    put(file, 155 + 8 * c, t.offset[c]);
    put(file, 179 + 16 * c, 0.);
    put(file, 187 + 16 * c, 0.);
  }
  for (std::size_t i = 0; i < t.points.size(); ++i)
    file += encode(t, t.points[i], i);
  const std::size_t waveform_start = file.size();
  file += t.waveform;
  const std::size_t evlr_start = file.size();
  for (std::size_t i = 0; i < t.evlrs.size(); ++i)
    file += variable_length_record(t.evlrs[i], i, true);

  if (t.minor >= 3)
    put(file, 227, std::uint64_t(t.waveform.empty() ? 0 : waveform_start));
  if (t.minor >= 4)
  {
    put(file, 235, std::uint64_t(t.evlrs.empty() ? 0 : evlr_start));
    put(file, 243, std::uint32_t(t.evlrs.size()));
    put(file, 247, std::uint64_t(t.count_64 ? t.count_64 : t.points.size()));
    for (unsigned r = 1; r <= 15; ++r)
      put(file, 255 + 8 * (r - 1), count_with_return(t.points, rows, r));
  }
  return file;
}

// LAS 1.0 and 1.1 define point formats 0 and 1, 1.2 adds 2 and 3, 1.3 adds 4
// and 5, 1.4 adds 6 to 10. Some have extra bytes, a longer header, user bytes
// before the points; 1.3 and 1.4 files with wave packets have waveform data,
// 1.4 files EVLRs.
Test_las sample(int minor, int format, std::size_t n = 17)
{
  Test_las t;
  t.minor = minor;
  t.format = format;
  t.points = make_points(format, n);
  t.extra_bytes = format % 3 == 1 ? 5 : 0;
  t.header_padding = format % 2 ? 13 : 0;
  std::string long_payload(300, '\0');
  for (std::size_t i = 0; i < long_payload.size(); ++i)
    long_payload[i] = char(i * 13);
  t.vlrs = { "first VLR's payload", long_payload, "" };
  t.before_points = minor == 0 ? "\xdd\xcc" : format == 2 ? "user bytes" : ""; // LAS 1.0's start signature
  if (minor >= 3 && has_wave_packets(format))
    t.waveform = "waveform data packets: " + std::string(100, '\x5a');
  if (minor == 4)
    t.evlrs = { "first EVLR's payload", long_payload };
  t.scale[0] = format == 5 ? 1e-7 : 0.01;
  return t;
}

struct Version_and_format
{
  int minor, format;
};

std::vector<Version_and_format> every_version_and_format()
{
  std::vector<Version_and_format> cases;
  for (int minor = 0; minor <= 4; ++minor)
  {
    const int last_format = minor <= 1 ? 1 : minor == 2 ? 3 : minor == 3 ? 5 : 10;
    for (int format = 0; format <= last_format; ++format)
      cases.push_back({ minor, format });
  }
  return cases;
}

struct Expected_column
{
  std::string name;
  Scalar_type type;
  std::function<double(const Test_point&)> value;
};

// The columns las_point_table should make, from the specification's names.
std::vector<Expected_column> expected_columns(const Test_las& t)
{
  using T = Scalar_type;
  const int f = t.format;
  const bool extended = is_extended(f);
  std::vector<Expected_column> columns = {
    { "x", T::float64, [&t](const Test_point& p) { return p.x * t.scale[0] + t.offset[0]; } },
    { "y", T::float64, [&t](const Test_point& p) { return p.y * t.scale[1] + t.offset[1]; } },
    { "z", T::float64, [&t](const Test_point& p) { return p.z * t.scale[2] + t.offset[2]; } },
    { "intensity", T::uint16, [](const Test_point& p) { return double(p.intensity); } },
    { "return_number", T::uint8, [](const Test_point& p) { return double(p.return_number); } },
    { "number_of_returns", T::uint8, [](const Test_point& p) { return double(p.number_of_returns); } },
    { "scan_direction_flag", T::uint8, [](const Test_point& p) { return double(p.scan_direction); } },
    { "edge_of_flight_line", T::uint8, [](const Test_point& p) { return double(p.edge); } },
    { "classification", T::uint8, [](const Test_point& p) { return double(p.classification); } },
    { "synthetic", T::uint8, [](const Test_point& p) { return double(p.synthetic); } },
    { "key_point", T::uint8, [](const Test_point& p) { return double(p.key_point); } },
    { "withheld", T::uint8, [](const Test_point& p) { return double(p.withheld); } },
  };
  if (extended)
  {
    columns.push_back({ "overlap", T::uint8, [](const Test_point& p) { return double(p.overlap); } });
    columns.push_back({ "scanner_channel", T::uint8, [](const Test_point& p) { return double(p.scanner_channel); } });
  }
  columns.push_back({ extended ? "scan_angle" : "scan_angle_rank", extended ? T::int16 : T::int8,
                      [](const Test_point& p) { return double(p.scan_angle); } });
  columns.push_back({ "user_data", T::uint8, [](const Test_point& p) { return double(p.user_data); } });
  columns.push_back({ "point_source_id", T::uint16, [](const Test_point& p) { return double(p.point_source_id); } });
  if (f != 0 && f != 2)
    columns.push_back({ "gps_time", T::float64, [](const Test_point& p) { return p.gps_time; } });
  if (f == 2 || f == 3 || f == 5 || f == 7 || f == 8 || f == 10)
  {
    columns.push_back({ "red", T::uint16, [](const Test_point& p) { return double(p.red); } });
    columns.push_back({ "green", T::uint16, [](const Test_point& p) { return double(p.green); } });
    columns.push_back({ "blue", T::uint16, [](const Test_point& p) { return double(p.blue); } });
  }
  if (f == 8 || f == 10)
    columns.push_back({ "nir", T::uint16, [](const Test_point& p) { return double(p.nir); } });
  return columns;
}

void check_table(const Test_las& t, const Point_table& table, const std::vector<std::size_t>& rows)
{
  const std::vector<Expected_column> expected = expected_columns(t);
  REQUIRE(table.columns.size() == expected.size());
  for (std::size_t c = 0; c < expected.size(); ++c)
  {
    INFO("column " << c << ", expected '" << expected[c].name << "'");
    CHECK(table.columns[c].name == expected[c].name);
    CHECK(table.columns[c].type == expected[c].type);
    std::vector<double> values;
    for (std::size_t row : rows)
      values.push_back(expected[c].value(t.points[row]));
    CHECK(table.columns[c].values == values);
  }
}

// The header fields write_las rewrites; every other header byte is copied.
bool is_patched(std::size_t at, int minor)
{
  const bool counts = at >= 107 && at < 131, bounds = at >= 179 && at < 227;
  const bool waveform = minor >= 3 && at >= 227 && at < 235;
  const bool extended = minor >= 4 && ((at >= 235 && at < 243) || (at >= 247 && at < 375));
  return counts || bounds || waveform || extended;
}

std::size_t first_copied_difference(const std::string& in, const std::string& out, std::size_t size, int minor)
{
  for (std::size_t at = 0; at < size; ++at)
    if (!is_patched(at, minor) && in[at] != out[at])
      return at;
  return size;
}

std::string write(const Las_file& las, const std::vector<std::size_t>& rows)
{
  String_sink sink;
  write_las(sink, las, rows);
  return sink.bytes;
}

// `rows` of the file `t` describes, written and read again, against what the
// specification says the output must be, computed from `t`.
void check_subset(const Test_las& t, const std::vector<std::size_t>& rows)
{
  const std::string in = build(t);
  const Las_file las = read_las(in);
  const std::string out = write(las, rows);
  const Las_file again = read_las(out);
  const std::size_t length = las.record_length, start = las.offset_to_points;
  const std::size_t old_end = start + t.points.size() * length, new_end = start + rows.size() * length;

  CHECK(again.point_count == rows.size());
  CHECK(again.point_format == t.format);
  CHECK(again.record_length == length);
  CHECK(again.offset_to_points == start);
  CHECK(again.vlr_count == t.vlrs.size());
  CHECK(again.evlr_count == t.evlrs.size());
  REQUIRE(out.size() == in.size() - (t.points.size() - rows.size()) * length);
  CHECK(first_copied_difference(in, out, las.header_size, t.minor) == las.header_size);
  CHECK(out.substr(las.header_size, start - las.header_size) == in.substr(las.header_size, start - las.header_size));
  for (std::size_t k = 0; k < rows.size(); ++k)
    CHECK(out.substr(start + k * length, length) == in.substr(start + rows[k] * length, length));
  CHECK(out.substr(new_end) == in.substr(old_end));

  const bool legacy = !is_extended(t.format);
  CHECK(get<std::uint32_t>(out, 107) == (legacy ? rows.size() : 0));
  for (unsigned r = 1; r <= 5; ++r)
    CHECK(get<std::uint32_t>(out, 111 + 4 * (r - 1)) == (legacy ? count_with_return(t.points, rows, r) : 0));
  if (t.minor >= 4)
  {
    CHECK(get<std::uint64_t>(out, 247) == rows.size());
    for (unsigned r = 1; r <= 15; ++r)
      CHECK(get<std::uint64_t>(out, 255 + 8 * (r - 1)) == count_with_return(t.points, rows, r));
  }
  for (int c = 0; c < 3; ++c)
  {
    std::vector<double> values;
    for (std::size_t row : rows)
    {
      const Test_point& p = t.points[row];
      values.push_back((c == 0 ? p.x : c == 1 ? p.y : p.z) * t.scale[c] + t.offset[c]);
    }
    const double high = values.empty() ? 0. : *std::max_element(values.begin(), values.end());
    const double low = values.empty() ? 0. : *std::min_element(values.begin(), values.end());
    CHECK(get<double>(out, 179 + 16 * c) == high);
    CHECK(get<double>(out, 187 + 16 * c) == low);
  }
  if (t.minor >= 3)
    CHECK(get<std::uint64_t>(out, 227) == (t.waveform.empty() ? 0 : new_end));
  if (t.minor >= 4)
    CHECK(get<std::uint64_t>(out, 235) == (t.evlrs.empty() ? 0 : new_end + t.waveform.size()));
  check_table(t, las_point_table(again, all_rows(rows.size())), rows);
}

} // namespace

TEST_CASE("read_las reads every LAS version and point format", "[las]")
{
  for (const Version_and_format& c : every_version_and_format())
  {
    INFO("LAS 1." << c.minor << ", point format " << c.format);
    const Test_las t = sample(c.minor, c.format);
    const std::string file = build(t);
    const Las_file las = read_las(file);
    CHECK(las.bytes.data() == file.data());
    CHECK(las.version_major == 1);
    CHECK(las.version_minor == c.minor);
    CHECK(las.point_format == c.format);
    CHECK(las.record_length == base_sizes[c.format] + t.extra_bytes);
    CHECK(las.point_count == t.points.size());
    CHECK(las.header_size == header_size_of(c.minor) + t.header_padding);
    CHECK(las.offset_to_points == las.header_size + 54 * 3 + 19 + 300 + t.before_points.size());
    CHECK(las.vlr_count == 3);
    CHECK(las.evlr_count == t.evlrs.size());
    for (int axis = 0; axis < 3; ++axis)
    {
      CHECK(las.scale[axis] == t.scale[axis]);
      CHECK(las.offset[axis] == t.offset[axis]);
    }
    for (std::size_t i = 0; i < t.points.size(); ++i)
    {
      const Test_point& p = t.points[i];
      CHECK(las.record(i) == file.data() + las.offset_to_points + i * las.record_length);
      CHECK(las.integer_xyz(i) == std::array<std::int32_t, 3>{ p.x, p.y, p.z });
      CHECK(las.local_xyz(i) == std::array<double, 3>{ p.x * t.scale[0], p.y * t.scale[1], p.z * t.scale[2] });
      CHECK(las.xyz(i) == std::array<double, 3>{ p.x * t.scale[0] + t.offset[0], p.y * t.scale[1] + t.offset[1],
                                                 p.z * t.scale[2] + t.offset[2] });
    }
    check_table(t, las_point_table(las, all_rows(t.points.size())), all_rows(t.points.size()));
    CHECK(las_has_unconverted_bytes(las) == (t.extra_bytes > 0 || has_wave_packets(c.format)));
  }
}

TEST_CASE("las_point_table gives the rows asked for, in their order", "[las]")
{
  const Test_las t = sample(4, 8);
  const std::string file = build(t);
  const Las_file las = read_las(file);
  const std::vector<std::size_t> rows = { 16, 3, 3, 0 };
  check_table(t, las_point_table(las, rows), rows);
  CHECK(las_point_table(las, {}).size() == 0);
  CHECK_THROWS_AS(las_point_table(las, { 17 }), std::out_of_range);
}

TEST_CASE("write_las writes the kept records and updates the header", "[las]")
{
  for (const Version_and_format& c : every_version_and_format())
  {
    INFO("LAS 1." << c.minor << ", point format " << c.format);
    const Test_las t = sample(c.minor, c.format);
    std::vector<std::size_t> every_other;
    for (std::size_t i = 0; i < t.points.size(); i += 2)
      every_other.push_back(i);
    check_subset(t, every_other);
    check_subset(t, { 9 });
    check_subset(t, all_rows(t.points.size()));
    check_subset(t, {});
  }
}

TEST_CASE("write_las of every record gives the input back when its header is right", "[las]")
{
  Test_las t = sample(4, 1);
  t.header_padding = 0;
  const std::string in = build(t);
  // The builder leaves the bounds zero, and puts the right counts.
  const std::string out = write(read_las(in), all_rows(t.points.size()));
  CHECK(out.compare(0, 179, in, 0, 179) == 0);
  CHECK(out.compare(227, std::string::npos, in, 227, std::string::npos) == 0);
  CHECK(write(read_las(out), all_rows(t.points.size())) == out);
}

TEST_CASE("write_las rejects rows that are not records of the file", "[las]")
{
  const std::string file = build(sample(2, 0));
  const Las_file las = read_las(file);
  String_sink sink;
  CHECK_THROWS_AS(write_las(sink, las, { 0, 17 }), std::out_of_range);
  CHECK(sink.bytes.empty());
}

TEST_CASE("write_las writes the records a megabyte at a time", "[las]")
{
  struct Counting_sink : Sink
  {
    using Sink::write;
    void write(const char*, std::size_t size) override
    {
      ++writes;
      bytes += size;
    }
    std::size_t writes = 0, bytes = 0;
  };
  Test_las t = sample(2, 0, 0);
  t.points.assign(120000, Test_point{}); // 2.4 MB of records
  const std::string file = build(t);
  Counting_sink sink;
  write_las(sink, read_las(file), all_rows(t.points.size()));
  CHECK(sink.bytes == file.size());
  CHECK(sink.writes <= 8);
}

TEST_CASE("read_las takes LAS 1.4's 64-bit point count unless it is zero", "[las]")
{
  Test_las t = sample(4, 1);
  t.legacy_count = 3;
  CHECK(read_las(build(t)).point_count == 17);
  t.count_64 = 0;
  t.legacy_count = 0;
  std::string file = build(t);
  put(file, 247, std::uint64_t(0));
  put(file, 107, std::uint32_t(12));
  CHECK(read_las(file).point_count == 12);
  put(file, 25, char(3)); // LAS 1.3 has no 64-bit count: bytes 235 to 375 are user bytes of its header
  CHECK(read_las(file).point_count == 12);
}

TEST_CASE("read_las notes counts that disagree and bytes after the records", "[las]")
{
  // a well-formed file of any version and format gives no note
  for (const Version_and_format& vf : every_version_and_format())
    CHECK(read_las(build(sample(vf.minor, vf.format))).notes.empty());

  SECTION("LAS 1.4's legacy count differs from its 64-bit count")
  {
    Test_las t = sample(4, 1);
    t.legacy_count = 3;
    const Las_file las = read_las(build(t));
    CHECK(las.point_count == 17);
    REQUIRE(las.notes.size() == 1);
    CHECK(las.notes[0] == "the header's legacy point count (byte 107) is 3 and its 64-bit count (byte 247) 17; "
                          "17 points were read, as LAS 1.4 asks");
  }
  SECTION("a header that counts 10 of 17 records")
  {
    for (int minor : { 2, 4 })
    {
      // LAS 1.2 has nothing after its records; 1.4 has EVLRs there, which
      // are accounted for, and its legacy count is left 0 in format 6
      Test_las t = sample(minor, minor == 2 ? 1 : 6);
      if (minor == 2)
        t.legacy_count = 10;
      else
        t.count_64 = 10;
      const Las_file las = read_las(build(t));
      CHECK(las.point_count == 10);
      const std::string unread = std::to_string(7 * las.record_length);
      REQUIRE(las.notes.size() == 1);
      CHECK(las.notes[0] == unread + " bytes after the 10 point records that the header declares are not part of "
                                     "any record or EVLR (7 records' worth); they are not read, and a LAS output "
                                     "keeps them as they are: if more points are there, the header's point count "
                                     "is wrong");
    }
  }
  SECTION("a byte after the records")
  {
    const std::string file = build(sample(2, 0)) + "x";
    CHECK(read_las(file).notes == std::vector<std::string>{
                                    "1 byte after the 17 point records that the header declares is not part of any "
                                    "record or EVLR; it is not read, and a LAS output keeps it as it is: if more "
                                    "points are there, the header's point count is wrong" });
  }
  SECTION("waveform data after the records is accounted for")
  {
    Test_las t = sample(3, 4);
    t.legacy_count = 10;
    CHECK(read_las(build(t)).notes.empty());
  }
  SECTION("a waveform start outside the bytes after the records is noted, and then the bytes there")
  {
    std::string file = build(sample(3, 1));
    const std::uint64_t end = file.size();
    for (std::uint64_t start : { std::uint64_t(100), end + 3, std::uint64_t(1) << 40 })
    {
      put(file, 227, start);
      const Las_file las = read_las(file + "xy");
      REQUIRE(las.notes.size() == 2);
      CHECK(las.notes[0] == "the start of the waveform data (byte 227) is " + std::to_string(start) +
                              ", outside bytes " + std::to_string(end) + " (the end of the point data) to " +
                              std::to_string(end + 2) + " (the end of the file): no waveform data is read there, "
                              "and a LAS output keeps the field as it is, moved with the end of the point data "
                              "when it lies beyond");
      CHECK(las.notes[1].rfind("2 bytes after the 17 point records", 0) == 0);
    }
  }
}

TEST_CASE("local_xyz leaves out the offset, so georeferenced copies agree", "[las]")
{
  Test_las near = sample(2, 1), far = sample(2, 1);
  far.offset[0] = 500000.;
  far.offset[1] = 4.5e6;
  far.offset[2] = -100.;
  const std::string near_file = build(near), far_file = build(far);
  const Las_file a = read_las(near_file), b = read_las(far_file);
  for (std::size_t i = 0; i < near.points.size(); ++i)
  {
    CHECK(a.local_xyz(i) == b.local_xyz(i));
    CHECK(b.xyz(i)[0] == b.local_xyz(i)[0] + 500000.);
    CHECK(b.xyz(i)[1] == b.local_xyz(i)[1] + 4.5e6);
  }
}

TEST_CASE("read_las rejects hostile headers with a clear message", "[las]")
{
  const std::string v12 = build(sample(2, 1)), v14 = build(sample(4, 6));
  const Las_file las12 = read_las(v12), las14 = read_las(v14);
  const auto patched = [](std::string file, std::size_t at, auto value) {
    put(file, at, value);
    return file;
  };

  CHECK_READ_ERROR(read_las(""), "the file is empty");
  CHECK_READ_ERROR(read_las("LAS"), "does not start with 'LASF'");
  CHECK_READ_ERROR(read_las(v12.substr(0, 100)), "the LAS header is truncated: the file has 100 bytes");
  CHECK_READ_ERROR(read_las(v14.substr(0, 300)), "its size (byte 94) is 375 bytes, the file has 300 bytes");
  CHECK_READ_ERROR(read_las("LASG" + v12.substr(4)), "not a LAS file");
  CHECK_READ_ERROR(read_las(patched(v12, 24, char(2))), "LAS version 2.2 is not supported");
  CHECK_READ_ERROR(read_las(patched(patched(v12, 24, char(2)), 25, char(0))), "LAS version 2.0 is not supported");
  CHECK_READ_ERROR(read_las(patched(v12, 25, char(5))), "LAS version 1.5 is not supported");
  CHECK_READ_ERROR(read_las(patched(v14, 94, std::uint16_t(235))), "the header size (byte 94) is 235 bytes, less than the 375");
  CHECK_READ_ERROR(read_las(patched(v12, 94, std::uint16_t(0xffff))), "the LAS header is truncated");
  CHECK_READ_ERROR(read_las(patched(v12, 96, std::uint32_t(200))), "the offset to point data (byte 96) is 200, outside bytes");
  CHECK_READ_ERROR(read_las(patched(v12, 96, std::uint32_t(0xffffffff))), "(the end of the file)");

  // the second VLR's length, at byte 20 of its header
  const std::size_t second_vlr = las12.header_size + 54 + 19;
  CHECK_READ_ERROR(read_las(patched(v12, second_vlr + 20, std::uint16_t(0xffff))),
                   "VLR #2 of 3, at byte " + std::to_string(second_vlr) + ", runs past the start of the point data");
  CHECK_READ_ERROR(read_las(patched(v12, 100, std::uint32_t(4))), "VLR #4 of 4");
  CHECK_READ_ERROR(read_las(patched(v12, 100, std::uint32_t(0xffffffff))), "VLR #4 of 4294967295");

  CHECK_READ_ERROR(read_las(patched(v12, 107, std::uint32_t(18))), "the header says 18 point records of 33 bytes");
  CHECK_READ_ERROR(read_las(patched(v12, 107, std::uint32_t(0xffffffff))), "4294967295 point records");
  CHECK_READ_ERROR(read_las(patched(v14, 247, std::uint64_t(-1))), "18446744073709551615 point records of 30 bytes");
  CHECK_READ_ERROR(read_las(patched(v14, 247, std::uint64_t(1) << 63)), "9223372036854775808 point records");
  CHECK_READ_ERROR(read_las(patched(v12, 105, std::uint16_t(27))), "the point record length (byte 105) is 27 bytes, less than the 28");
  CHECK_READ_ERROR(read_las(patched(v12, 104, char(11))), "LAS has formats 0 to 10");
  CHECK_READ_ERROR(read_las(patched(v12, 104, char(6))), "point data record format 6 needs LAS 1.4");

  const std::size_t evlr_start = get<std::uint64_t>(v14, 235);
  CHECK_READ_ERROR(read_las(v14.substr(0, v14.size() - 1)), "EVLR #2 of 2 (its data) needs 300 bytes");
  CHECK_READ_ERROR(read_las(patched(v14, 243, std::uint32_t(3))), "EVLR #3 of 3 (its header)");
  CHECK_READ_ERROR(read_las(patched(v14, 243, std::uint32_t(0xffffffff))), "EVLR #3 of 4294967295");
  CHECK_READ_ERROR(read_las(patched(v14, evlr_start + 20, std::uint64_t(-1))), "EVLR #1 of 2 (its data)");
  CHECK_READ_ERROR(read_las(patched(v14, 235, std::uint64_t(v14.size() + 1))), "the start of the first EVLR (byte 235)");
  CHECK_READ_ERROR(read_las(patched(v14, 235, std::uint64_t(-1))), "the start of the first EVLR (byte 235)");
  CHECK_READ_ERROR(read_las(patched(v14, 235, std::uint64_t(evlr_start - 1))), "(the end of the point data)");
  CHECK(read_las(patched(v14, 243, std::uint32_t(1))).evlr_count == 1); // bytes after the EVLRs are allowed

  for (char laz : { char(0x80 | 1), char(0x40 | 1), char(0x80 | 6) })
  {
    CHECK_READ_ERROR(read_las(patched(v12, 104, laz)), "LAZ (compressed LAS) is not supported");
    CHECK_READ_ERROR(read_las(patched(v12, 104, laz)), "laszip -i in.laz -o in.las");
  }
  CHECK_READ_ERROR(read_las(patched(v12, 139, 0.)), "the Y scale factor (byte 139) is zero");
  CHECK_READ_ERROR(read_las(patched(v12, 131, std::numeric_limits<double>::infinity())), "X scale factor (byte 131) is not a finite");
  CHECK_READ_ERROR(read_las(patched(v12, 147, std::numeric_limits<double>::quiet_NaN())), "Z scale factor");
  CHECK_READ_ERROR(read_las(patched(v12, 171, std::numeric_limits<double>::quiet_NaN())), "the Z offset (byte 171) is not a finite");
  CHECK(las12.point_count == 17);
  CHECK(las14.point_count == 17);
}

TEST_CASE("read_las rejects every truncation of a file and survives corrupted headers", "[las]")
{
  const std::string file = build(sample(4, 10, 3));
  for (std::size_t size = 0; size < file.size(); ++size)
    CHECK_THROWS_AS(read_las(file.substr(0, size)), Read_error);

  // Each byte of the header and the VLRs set to 0x00, 0x7f and 0xff: a Read_error,
  // or a file that writes and reads back.
  std::size_t read = 0, rejected = 0;
  for (std::size_t at = 0; at < read_las(file).offset_to_points; ++at)
    for (unsigned char value : { 0x00, 0x7f, 0xff })
    {
      std::string corrupted = file;
      corrupted[at] = char(value);
      try
      {
        const Las_file las = read_las(corrupted);
        const std::vector<std::size_t> rows = all_rows(las.point_count);
        CHECK(read_las(write(las, rows)).point_count == las.point_count);
        CHECK(las_point_table(las, rows).size() == las.point_count);
        ++read;
      }
      catch (const Read_error&)
      {
        ++rejected;
      }
    }
  CHECK(read > 0);
  CHECK(rejected > 0);
}

TEST_CASE("laz_not_supported_message says why and how to convert", "[las]")
{
  const std::string message = laz_not_supported_message();
  CHECK_THAT(message, Contains("LAZ (compressed LAS) is not supported"));
  CHECK_THAT(message, Contains("Debian 12"));
  CHECK_THAT(message, Contains("laszip -i in.laz -o in.las"));
  CHECK_THAT(message, Contains("pdal translate in.laz in.las"));
}

#ifdef ES_LAS_DATA_DIR
namespace {

std::string read_file(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  REQUIRE(in);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

} // namespace

TEST_CASE("read_las and write_las on CGAL's demo LAS files", "[las][data]")
{
  for (const char* name : { "urban.las", "pig_points.las", "oni.las" })
  {
    INFO(name);
    const std::string file = read_file(std::string(ES_LAS_DATA_DIR) + "/" + name);
    const Las_file las = read_las(file);
    CHECK(las.point_count == get<std::uint32_t>(file, 107));
    CHECK(las.point_count > 400);
    const std::size_t start = get<std::uint32_t>(file, 96), length = get<std::uint16_t>(file, 105);
    CHECK(las.offset_to_points == start);
    CHECK(las.record_length == length);

    const Point_table table = las_point_table(las, all_rows(las.point_count));
    REQUIRE(table.size() == las.point_count);
    for (std::size_t i = 0; i < las.point_count; ++i)
      for (int c = 0; c < 3; ++c)
      {
        const double expected = get<std::int32_t>(file, start + i * length + 4 * c) * get<double>(file, 131 + 8 * c) +
                                 get<double>(file, 155 + 8 * c);
        if (table.columns[c].values[i] != expected)
          FAIL_CHECK("point " << i << " coordinate " << c << ": " << table.columns[c].values[i] << " != " << expected);
      }

    std::vector<std::size_t> rows;
    for (std::size_t i = 1; i < las.point_count; i += 3)
      rows.push_back(i);
    const std::string out = write(las, rows);
    const Las_file again = read_las(out);
    CHECK(again.point_count == rows.size());
    CHECK(out.size() == file.size() - (las.point_count - rows.size()) * length);
    std::size_t differing_records = 0;
    for (std::size_t k = 0; k < rows.size(); ++k)
      differing_records += out.compare(start + k * length, length, file, start + rows[k] * length, length) != 0;
    CHECK(differing_records == 0);

    // All records: the counts by return are the file's own.
    const std::string whole = write(las, all_rows(las.point_count));
    CHECK(whole.compare(107, 24, file, 107, 24) == 0);
    CHECK(whole.compare(227, std::string::npos, file, 227, std::string::npos) == 0);
  }
}
#endif
