// LAS 1.0 to 1.4, uncompressed, point data record formats 0 to 10. The point
// records are kept as the file's bytes: LAS out is the input with the removed
// records left out and the header's counts, bounds and offsets updated, so
// every attribute, extra byte, VLR and EVLR survives; PLY or XYZ out gets the
// standard attributes as columns. The file is not trusted: every offset,
// length and count is checked against the file's size before anything is read
// or allocated, so a hostile header is a Read_error, never a crash.
//
// Georeferenced scans: the program simplifies local_xyz(), X * scale without
// the header's offset. Offsets of millions of metres (UTM, say) would cost
// precision otherwise, and two files that differ only in their offsets keep
// the same points.

#ifndef ENTROPY_SIMPLIFY_LAS_FORMAT_H
#define ENTROPY_SIMPLIFY_LAS_FORMAT_H

#include "byte_io.h"
#include "point_table.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace entropy_simplify {

inline std::string laz_not_supported_message()
{
  return "LAZ (compressed LAS) is not supported: Debian 12 packages no LAZ library. Convert the file to LAS "
         "first, for example with 'laszip -i in.laz -o in.las' or 'pdal translate in.laz in.las'";
}

struct Las_file
{
  std::string_view bytes; // the whole file; the caller keeps it alive
  int version_major = 0, version_minor = 0;
  int point_format = 0;
  std::size_t record_length = 0; // the format's base size, then extra bytes
  std::size_t point_count = 0;
  std::size_t header_size = 0, offset_to_points = 0;
  std::size_t vlr_count = 0, evlr_count = 0;
  std::size_t evlr_bytes = 0; // the EVLRs' headers and data
  double scale[3] = { 1., 1., 1. }, offset[3] = { 0., 0., 0. };
  std::vector<std::string> notes; // what is odd but readable, for the program to print

  const char* record(std::size_t i) const { return bytes.data() + offset_to_points + i * record_length; }

  std::array<std::int32_t, 3> integer_xyz(std::size_t i) const
  {
    const char* r = record(i);
    return { load_little_endian<std::int32_t>(r), load_little_endian<std::int32_t>(r + 4),
             load_little_endian<std::int32_t>(r + 8) };
  }

  std::array<double, 3> local_xyz(std::size_t i) const
  {
    const std::array<std::int32_t, 3> n = integer_xyz(i);
    return { n[0] * scale[0], n[1] * scale[1], n[2] * scale[2] };
  }

  std::array<double, 3> xyz(std::size_t i) const
  {
    std::array<double, 3> p = local_xyz(i);
    for (int c = 0; c < 3; ++c)
      p[c] += offset[c];
    return p;
  }
};

namespace las_detail {

// Byte offsets of the public header's fields; the bounds are max x, min x,
// max y, min y, max z, min z. 1.3 added the waveform data's start, 1.4 the
// EVLRs and the 64-bit counts.
inline constexpr std::size_t version_major_at = 24, version_minor_at = 25, header_size_at = 94,
                             offset_to_points_at = 96, vlr_count_at = 100, point_format_at = 104,
                             record_length_at = 105, legacy_count_at = 107, legacy_by_return_at = 111,
                             scale_at = 131, offset_at = 155, bounds_at = 179, waveform_start_at = 227,
                             evlr_start_at = 235, evlr_count_at = 243, point_count_at = 247, by_return_at = 255;
inline constexpr std::size_t vlr_header_size = 54, evlr_header_size = 60;
inline constexpr std::size_t base_record_sizes[11] = { 20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67 };

inline std::size_t minimum_header_size(int minor) { return minor <= 2 ? 227 : minor == 3 ? 235 : 375; }

// Formats 6-10 (LAS 1.4) have 4-bit return numbers and a byte of classification flags.
inline bool is_extended(int format) { return format >= 6; }
inline bool has_gps_time(int format) { return format != 0 && format != 2; }
inline bool has_rgb(int format)
{
  return format == 2 || format == 3 || format == 5 || format == 7 || format == 8 || format == 10;
}
inline bool has_nir(int format) { return format == 8 || format == 10; }
inline bool has_wave_packets(int format) { return format == 4 || format == 5 || format == 9 || format == 10; }

template <typename T>
T field(const Las_file& las, std::size_t at)
{
  return load_little_endian<T>(las.bytes.data() + at);
}

inline std::string bytes_text(std::uint64_t n) { return std::to_string(n) + (n == 1 ? " byte" : " bytes"); }

inline std::size_t points_end(const Las_file& las)
{
  return las.offset_to_points + las.point_count * las.record_length;
}

// The signature, the version, and where the header and the point data lie.
inline void read_layout(Las_file& las)
{
  const std::string_view bytes = las.bytes;
  if (bytes.substr(0, 4) != "LASF")
    throw Read_error(bytes.empty() ? "the file is empty" : "not a LAS file: it does not start with 'LASF'");
  if (bytes.size() < minimum_header_size(0))
    throw Read_error("the LAS header is truncated: the file has " + bytes_text(bytes.size()) +
                     ", the shortest LAS header 227");
  las.version_major = field<std::uint8_t>(las, version_major_at);
  las.version_minor = field<std::uint8_t>(las, version_minor_at);
  if (las.version_major != 1 || las.version_minor > 4)
    throw Read_error("LAS version " + std::to_string(las.version_major) + "." + std::to_string(las.version_minor) +
                     " is not supported: this reader reads LAS 1.0 to 1.4");
  const std::string version = "LAS 1." + std::to_string(las.version_minor);
  las.header_size = field<std::uint16_t>(las, header_size_at);
  if (las.header_size < minimum_header_size(las.version_minor))
    throw Read_error("the header size (byte 94) is " + bytes_text(las.header_size) + ", less than the " +
                     std::to_string(minimum_header_size(las.version_minor)) + " of a " + version + " header");
  if (las.header_size > bytes.size())
    throw Read_error("the LAS header is truncated: its size (byte 94) is " + bytes_text(las.header_size) +
                     ", the file has " + bytes_text(bytes.size()));
  las.offset_to_points = field<std::uint32_t>(las, offset_to_points_at);
  if (las.offset_to_points < las.header_size || las.offset_to_points > bytes.size())
    throw Read_error("the offset to point data (byte 96) is " + std::to_string(las.offset_to_points) +
                     ", outside bytes " + std::to_string(las.header_size) + " (the end of the header) to " +
                     std::to_string(bytes.size()) + " (the end of the file)");
}

// LASzip marks compressed points by setting bit 7 (or 6) of the format byte.
inline void read_point_format(Las_file& las)
{
  const unsigned format = field<std::uint8_t>(las, point_format_at);
  if (format & 0xc0)
    throw Read_error("the point format byte (104) is " + std::to_string(format) +
                     ", which marks LASzip-compressed points. " + laz_not_supported_message());
  if (format > 10)
    throw Read_error("the point data record format (byte 104) is " + std::to_string(format) +
                     "; LAS has formats 0 to 10");
  if (is_extended(int(format)) && las.version_minor < 4)
    throw Read_error("point data record format " + std::to_string(format) + " needs LAS 1.4; the file is LAS 1." +
                     std::to_string(las.version_minor));
  las.point_format = int(format);
  las.record_length = field<std::uint16_t>(las, record_length_at);
  if (las.record_length < base_record_sizes[format])
    throw Read_error("the point record length (byte 105) is " + bytes_text(las.record_length) + ", less than the " +
                     std::to_string(base_record_sizes[format]) + " of point format " + std::to_string(format));
}

// Each VLR is a 54-byte header, its data's length at byte 20, then the data.
// Every VLR read moves at least 54 bytes on, so a huge count cannot hang.
inline void check_vlrs(Las_file& las)
{
  las.vlr_count = field<std::uint32_t>(las, vlr_count_at);
  std::size_t at = las.header_size;
  for (std::size_t i = 0; i < las.vlr_count; ++i)
  {
    const std::size_t room = las.offset_to_points - at;
    if (room < vlr_header_size || room - vlr_header_size < field<std::uint16_t>(las, at + 20))
      throw Read_error("VLR #" + std::to_string(i + 1) + " of " + std::to_string(las.vlr_count) + ", at byte " +
                       std::to_string(at) + ", runs past the start of the point data at byte " +
                       std::to_string(las.offset_to_points));
    at += vlr_header_size + field<std::uint16_t>(las, at + 20);
  }
}

// LAS 1.4 counts in 64 bits, and may leave the legacy 32-bit count zero.
inline void read_point_count(Las_file& las)
{
  std::uint64_t count = field<std::uint32_t>(las, legacy_count_at);
  if (las.version_minor >= 4 && field<std::uint64_t>(las, point_count_at) != 0)
    count = field<std::uint64_t>(las, point_count_at);
  const std::uint64_t room = las.bytes.size() - las.offset_to_points;
  if (count > room / las.record_length)
    throw Read_error("the header says " + std::to_string(count) + " point records of " +
                     bytes_text(las.record_length) + " from byte " + std::to_string(las.offset_to_points) +
                     ", more than the " + bytes_text(room) + " from there to the end of the file hold");
  las.point_count = std::size_t(count);
}

// LAS 1.4's EVLRs follow the point data: a 60-byte header, its data's
// length a 64-bit number at byte 20, then the data.
inline void check_evlrs(Las_file& las)
{
  if (las.version_minor < 4)
    return;
  las.evlr_count = field<std::uint32_t>(las, evlr_count_at);
  const std::uint64_t start = field<std::uint64_t>(las, evlr_start_at);
  if (las.evlr_count == 0)
    return;
  if (start < points_end(las) || start > las.bytes.size())
    throw Read_error("the start of the first EVLR (byte 235) is " + std::to_string(start) + ", outside bytes " +
                     std::to_string(points_end(las)) + " (the end of the point data) to " +
                     std::to_string(las.bytes.size()) + " (the end of the file)");
  Byte_reader reader(las.bytes, std::size_t(start));
  for (std::size_t i = 0; i < las.evlr_count; ++i)
  {
    const std::string evlr = "EVLR #" + std::to_string(i + 1) + " of " + std::to_string(las.evlr_count);
    const char* header = reader.take(evlr_header_size, (evlr + " (its header)").c_str());
    reader.take(std::size_t(load_little_endian<std::uint64_t>(header + 20)), (evlr + " (its data)").c_str());
  }
  las.evlr_bytes = reader.position() - std::size_t(start);
}

// A file read without error may still disagree with itself: LAS 1.4's two
// point counts may differ, and bytes that no header field accounts for may
// follow the records, where more records would be if the count were short.
// Both are read as the header says (the 64-bit count; the records it
// counts), and noted. The waveform data of LAS 1.3 and 1.4 runs to the
// EVLRs or the end of the file, so it leaves no bytes unaccounted for; its
// start, outside the bytes after the records, is noted and then ignored.
inline void note_inconsistencies(Las_file& las)
{
  const std::uint64_t legacy = field<std::uint32_t>(las, legacy_count_at);
  if (las.version_minor >= 4 && legacy != 0 && legacy != las.point_count)
    las.notes.push_back("the header's legacy point count (byte 107) is " + std::to_string(legacy) +
                        " and its 64-bit count (byte 247) " + std::to_string(las.point_count) + "; " +
                        std::to_string(las.point_count) + " points were read, as LAS 1.4 asks");
  const std::uint64_t waveform = las.version_minor >= 3 ? field<std::uint64_t>(las, waveform_start_at) : 0;
  if (waveform != 0 && (waveform < points_end(las) || waveform > las.bytes.size()))
    las.notes.push_back("the start of the waveform data (byte 227) is " + std::to_string(waveform) +
                        ", outside bytes " + std::to_string(points_end(las)) + " (the end of the point data) to " +
                        std::to_string(las.bytes.size()) + " (the end of the file): no waveform data is read "
                        "there, and a LAS output keeps the field as it is, moved with the end of the point data "
                        "when it lies beyond");
  else if (waveform != 0)
    return;
  const std::size_t unread = las.bytes.size() - points_end(las) - las.evlr_bytes;
  if (unread == 0)
    return;
  const bool one = unread == 1;
  las.notes.push_back(std::to_string(unread) + (one ? " byte" : " bytes") + " after the " +
                      std::to_string(las.point_count) + " point records that the header declares " +
                      (one ? "is" : "are") + " not part of any record or EVLR" +
                      (unread >= las.record_length
                         ? " (" + std::to_string(unread / las.record_length) + " records' worth)"
                         : std::string()) +
                      (one ? "; it is not read, and a LAS output keeps it as it is"
                           : "; they are not read, and a LAS output keeps them as they are") +
                      ": if more points are there, the header's point count is wrong");
}

inline void read_scale_and_offset(Las_file& las)
{
  static const char axes[] = "XYZ";
  for (int c = 0; c < 3; ++c)
  {
    las.scale[c] = field<double>(las, scale_at + 8 * c);
    las.offset[c] = field<double>(las, offset_at + 8 * c);
    if (!std::isfinite(las.scale[c]) || las.scale[c] == 0.)
      throw Read_error(std::string("the ") + axes[c] + " scale factor (byte " + std::to_string(scale_at + 8 * c) +
                       ") is " + (las.scale[c] == 0. ? "zero" : "not a finite number") +
                       "; a scale factor must be finite and non-zero");
    if (!std::isfinite(las.offset[c]))
      throw Read_error(std::string("the ") + axes[c] + " offset (byte " + std::to_string(offset_at + 8 * c) +
                       ") is not a finite number");
  }
}

} // namespace las_detail

// Throws Read_error, saying what is wrong and where, for anything but an
// uncompressed LAS 1.0-1.4 file whose parts all lie within `bytes`.
inline Las_file read_las(std::string_view bytes)
{
  Las_file las;
  las.bytes = bytes;
  las_detail::read_layout(las);
  las_detail::read_point_format(las);
  las_detail::check_vlrs(las);
  las_detail::read_point_count(las);
  las_detail::check_evlrs(las);
  las_detail::read_scale_and_offset(las);
  las_detail::note_inconsistencies(las);
  return las;
}

// Formats with waveform packets, and records longer than their format, hold
// bytes that las_point_table() leaves out.
inline bool las_has_unconverted_bytes(const Las_file& las)
{
  return las_detail::has_wave_packets(las.point_format) ||
         las.record_length > las_detail::base_record_sizes[las.point_format];
}

namespace las_detail {

inline void check_rows(const Las_file& las, const std::vector<std::size_t>& rows)
{
  for (std::size_t row : rows)
    if (row >= las.point_count)
      throw std::out_of_range("LAS record " + std::to_string(row) + " does not exist: the file has " +
                              std::to_string(las.point_count));
}

// How many of the records `rows` have each return number, 0 to 15.
inline std::array<std::uint64_t, 16> count_by_return(const Las_file& las, const std::vector<std::size_t>& rows)
{
  const unsigned mask = is_extended(las.point_format) ? 0x0f : 0x07;
  std::array<std::uint64_t, 16> counts{};
  for (std::size_t row : rows)
    ++counts[static_cast<unsigned char>(las.record(row)[14]) & mask];
  return counts;
}

// LAS 1.4 wants the legacy counts zero where they cannot tell the truth:
// formats 6-10 (up to 15 returns) and more than 2^32 - 1 records.
inline void patch_counts(std::string& header, const Las_file& las, const std::vector<std::size_t>& rows)
{
  const std::array<std::uint64_t, 16> by_return = count_by_return(las, rows);
  const bool legacy = !is_extended(las.point_format) && rows.size() <= std::numeric_limits<std::uint32_t>::max();
  store_little_endian(&header[legacy_count_at], std::uint32_t(legacy ? rows.size() : 0));
  for (int r = 1; r <= 5; ++r)
    store_little_endian(&header[legacy_by_return_at + 4 * (r - 1)], std::uint32_t(legacy ? by_return[r] : 0));
  if (las.version_minor < 4)
    return;
  store_little_endian(&header[point_count_at], std::uint64_t(rows.size()));
  for (int r = 1; r <= 15; ++r)
    store_little_endian(&header[by_return_at + 8 * (r - 1)], by_return[r]);
}

// The bounds of the real coordinates; zeros when no record is kept.
inline void patch_bounds(std::string& header, const Las_file& las, const std::vector<std::size_t>& rows)
{
  std::array<double, 3> low{}, high{};
  for (std::size_t k = 0; k < rows.size(); ++k)
  {
    const std::array<double, 3> p = las.xyz(rows[k]);
    for (int c = 0; c < 3; ++c)
    {
      low[c] = k == 0 ? p[c] : std::min(low[c], p[c]);
      high[c] = k == 0 ? p[c] : std::max(high[c], p[c]);
    }
  }
  for (int c = 0; c < 3; ++c)
  {
    store_little_endian(&header[bounds_at + 16 * c], high[c]);
    store_little_endian(&header[bounds_at + 16 * c + 8], low[c]);
  }
}

// The waveform data (1.3) and the EVLRs (1.4) follow the point data and move
// with its end. An offset before that end (0 for none) points at nothing that
// moves, and stays.
inline void patch_offsets(std::string& header, const Las_file& las, std::uint64_t new_end)
{
  const std::uint64_t old_end = points_end(las);
  const auto move = [&](std::size_t at) {
    const std::uint64_t start = load_little_endian<std::uint64_t>(&header[at]);
    if (start >= old_end)
      store_little_endian(&header[at], start - old_end + new_end);
  };
  if (las.version_minor >= 3)
    move(waveform_start_at);
  if (las.version_minor >= 4)
    move(evlr_start_at);
}

// A megabyte at a time: one write per record would make a syscall of each.
// `append(row, buffer)` adds what follows the bytes of record `row`.
template <typename Append>
void write_records(Sink& out, const Las_file& las, const std::vector<std::size_t>& rows, const Append& append)
{
  constexpr std::size_t chunk = std::size_t(1) << 20;
  std::string buffer;
  buffer.reserve(chunk + 2 * las.record_length);
  for (std::size_t row : rows)
  {
    buffer.append(las.record(row), las.record_length);
    append(row, buffer);
    if (buffer.size() >= chunk)
    {
      out.write(buffer);
      buffer.clear();
    }
  }
  out.write(buffer);
}

} // namespace las_detail

// `las` with only the records `rows`, in that order: every byte of the input
// but the removed records, with the header's point counts, counts by return,
// bounds and the offsets of what follows the points updated.
inline void write_las(Sink& out, const Las_file& las, const std::vector<std::size_t>& rows)
{
  las_detail::check_rows(las, rows);
  std::string header(las.bytes.substr(0, las.header_size));
  las_detail::patch_counts(header, las, rows);
  las_detail::patch_bounds(header, las, rows);
  las_detail::patch_offsets(header, las, las.offset_to_points + rows.size() * las.record_length);
  out.write(header);
  out.write(las.bytes.substr(las.header_size, las.offset_to_points - las.header_size));
  las_detail::write_records(out, las, rows, [](std::size_t, std::string&) {});
  out.write(las.bytes.substr(las_detail::points_end(las)));
}

namespace las_detail {

// A standard attribute: the value of `type` at `byte` of a record, or its
// `bits` bits from bit `shift` when `bits` is not 0.
struct Attribute
{
  const char* name;
  Scalar_type type;
  std::size_t byte;
  unsigned shift = 0, bits = 0;
};

inline std::vector<Attribute> attributes(int format)
{
  using T = Scalar_type;
  std::vector<Attribute> list;
  if (!is_extended(format))
    list = { { "intensity", T::uint16, 12 },         { "return_number", T::uint8, 14, 0, 3 },
             { "number_of_returns", T::uint8, 14, 3, 3 }, { "scan_direction_flag", T::uint8, 14, 6, 1 },
             { "edge_of_flight_line", T::uint8, 14, 7, 1 }, { "classification", T::uint8, 15, 0, 5 },
             { "synthetic", T::uint8, 15, 5, 1 },     { "key_point", T::uint8, 15, 6, 1 },
             { "withheld", T::uint8, 15, 7, 1 },      { "scan_angle_rank", T::int8, 16 },
             { "user_data", T::uint8, 17 },           { "point_source_id", T::uint16, 18 } };
  else
    list = { { "intensity", T::uint16, 12 },         { "return_number", T::uint8, 14, 0, 4 },
             { "number_of_returns", T::uint8, 14, 4, 4 }, { "scan_direction_flag", T::uint8, 15, 6, 1 },
             { "edge_of_flight_line", T::uint8, 15, 7, 1 }, { "classification", T::uint8, 16 },
             { "synthetic", T::uint8, 15, 0, 1 },     { "key_point", T::uint8, 15, 1, 1 },
             { "withheld", T::uint8, 15, 2, 1 },      { "overlap", T::uint8, 15, 3, 1 },
             { "scanner_channel", T::uint8, 15, 4, 2 }, { "scan_angle", T::int16, 18 },
             { "user_data", T::uint8, 17 },           { "point_source_id", T::uint16, 20 } };
  const std::size_t gps_at = is_extended(format) ? 22 : 20;
  const std::size_t rgb_at = format == 2 ? 20 : is_extended(format) ? 30 : 28;
  if (has_gps_time(format))
    list.push_back({ "gps_time", T::float64, gps_at });
  if (has_rgb(format))
    list.insert(list.end(), { { "red", T::uint16, rgb_at }, { "green", T::uint16, rgb_at + 2 },
                              { "blue", T::uint16, rgb_at + 4 } });
  if (has_nir(format))
    list.push_back({ "nir", T::uint16, 36 });
  return list;
}

inline double attribute_value(const Attribute& attribute, const char* record)
{
  const double value = load_scalar(record + attribute.byte, attribute.type);
  if (attribute.bits == 0)
    return value;
  return double((unsigned(value) >> attribute.shift) & ((1u << attribute.bits) - 1));
}

} // namespace las_detail

// The records `rows` as a table: x y z, the real coordinates, then the
// format's standard attributes under their LAS names.
inline Point_table las_point_table(const Las_file& las, const std::vector<std::size_t>& rows)
{
  las_detail::check_rows(las, rows);
  Point_table table;
  for (const char* axis : { "x", "y", "z" })
    table.column(axis, Scalar_type::float64).values.reserve(rows.size());
  for (std::size_t row : rows)
  {
    const std::array<double, 3> p = las.xyz(row);
    for (int c = 0; c < 3; ++c)
      table.columns[c].values.push_back(p[c]);
  }
  for (const las_detail::Attribute& attribute : las_detail::attributes(las.point_format))
  {
    Column& column = table.column(attribute.name, attribute.type);
    column.values.reserve(rows.size());
    for (std::size_t row : rows)
      column.values.push_back(las_detail::attribute_value(attribute, las.record(row)));
  }
  return table;
}

} // namespace entropy_simplify

#endif // ENTROPY_SIMPLIFY_LAS_FORMAT_H
