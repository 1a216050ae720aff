// An attribute added to LAS records as extra bytes (LAS 1.4 R15, 2.6), for
// --importance: 8 bytes (a double) after every byte of each record, declared
// by a descriptor in the Extra Bytes VLR (user "LASF_Spec", record 4): the
// input's, lengthened, or a new one after the input's VLRs. The records'
// bytes that no descriptor covers get "undocumented" descriptors first, so
// that the attribute lies where the descriptors say. Everything else is
// written as write_las() writes it.

#ifndef ENTROPY_SIMPLIFY_LAS_EXTRA_BYTES_H
#define ENTROPY_SIMPLIFY_LAS_EXTRA_BYTES_H

#include "byte_io.h"
#include "las_format.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace entropy_simplify {

namespace las_extra_bytes_detail {

inline constexpr std::size_t descriptor_size = 192, name_at = 4, description_at = 160;
inline constexpr unsigned undocumented = 0, double_type = 10;

// The number of bytes a descriptor declares: its options byte for
// undocumented bytes, the size of its type otherwise (types 11 to 30, now
// deprecated, are arrays of 2 and 3 of types 1 to 10). Read_error for a
// reserved type, whose size is unknown.
inline std::size_t declared_size(const char* descriptor)
{
  static const std::size_t sizes[11] = { 0, 1, 1, 2, 2, 4, 4, 8, 8, 4, 8 };
  const unsigned type = static_cast<unsigned char>(descriptor[2]);
  if (type == undocumented)
    return static_cast<unsigned char>(descriptor[3]);
  if (type <= 10)
    return sizes[type];
  if (type <= 30)
    return sizes[(type - 11) % 10 + 1] * ((type - 11) / 10 + 2);
  throw Read_error("its Extra Bytes VLR declares an attribute of the reserved data type " + std::to_string(type) +
                   ", whose size is unknown: an attribute cannot be added after it");
}

// The name of a descriptor, up to its first null byte.
inline std::string_view name_of(const char* descriptor)
{
  const std::string_view field(descriptor + name_at, 32);
  return field.substr(0, field.find('\0'));
}

inline std::string descriptor(unsigned type, unsigned options, std::string_view name, std::string_view description)
{
  std::string d(descriptor_size, '\0');
  d[2] = char(type);
  d[3] = char(options);
  name.substr(0, 32).copy(&d[name_at], 32);
  description.substr(0, 32).copy(&d[description_at], 32);
  return d;
}

// Where the input's Extra Bytes VLR starts, if it has one; read_las()
// checked that every VLR lies within the file. Throws Read_error when it has
// two, which LAS forbids: an attribute added to one would leave the other
// describing other records.
inline std::optional<std::size_t> extra_bytes_vlr(const Las_file& las)
{
  std::optional<std::size_t> found;
  std::size_t at = las.header_size;
  for (std::size_t i = 0; i < las.vlr_count; ++i)
  {
    const std::string_view user = las.bytes.substr(at + 2, 16);
    if (user.substr(0, user.find('\0')) == "LASF_Spec" && las_detail::field<std::uint16_t>(las, at + 18) == 4)
    {
      if (found)
        throw Read_error("it has two Extra Bytes VLRs, where LAS allows one: an attribute cannot be added to them");
      found = at;
    }
    at += las_detail::vlr_header_size + las_detail::field<std::uint16_t>(las, at + 20);
  }
  return found;
}

// Whether an EVLR holds the Extra Bytes record, which LAS 1.4 allows there;
// read_las() checked that every EVLR lies within the file.
inline bool has_extra_bytes_evlr(const Las_file& las)
{
  if (las.evlr_count == 0)
    return false;
  std::size_t at = std::size_t(las_detail::field<std::uint64_t>(las, las_detail::evlr_start_at));
  for (std::size_t i = 0; i < las.evlr_count; ++i)
  {
    const std::string_view user = las.bytes.substr(at + 2, 16);
    if (user.substr(0, user.find('\0')) == "LASF_Spec" && las_detail::field<std::uint16_t>(las, at + 18) == 4)
      return true;
    at += las_detail::evlr_header_size + std::size_t(las_detail::field<std::uint64_t>(las, at + 20));
  }
  return false;
}

inline std::size_t end_of_vlrs(const Las_file& las)
{
  std::size_t at = las.header_size;
  for (std::size_t i = 0; i < las.vlr_count; ++i)
    at += las_detail::vlr_header_size + las_detail::field<std::uint16_t>(las, at + 20);
  return at;
}

// The descriptors to add: undocumented ones for the records' extra bytes
// that the input declares none for, 255 bytes at most each, then the
// attribute's. Throws Read_error when the input declares more extra bytes
// than its records hold.
inline std::string descriptors_to_add(const Las_file& las, std::string_view name, std::string_view description)
{
  const std::size_t extra = las.record_length - las_detail::base_record_sizes[las.point_format];
  if (has_extra_bytes_evlr(las))
    throw Read_error("its Extra Bytes record is an EVLR, after the points: an attribute is only added to an Extra "
                     "Bytes VLR");
  std::size_t declared = 0;
  if (const std::optional<std::size_t> vlr = extra_bytes_vlr(las))
  {
    const std::size_t length = las_detail::field<std::uint16_t>(las, *vlr + 20);
    if (length % descriptor_size != 0)
      throw Read_error("its Extra Bytes VLR holds " + las_detail::bytes_text(length) +
                       ", not a whole number of 192-byte descriptors: an attribute cannot be added after them");
    for (std::size_t d = 0; d < length; d += descriptor_size)
    {
      const char* existing = las.bytes.data() + *vlr + las_detail::vlr_header_size + d;
      declared += declared_size(existing);
      if (!name.empty() && name_of(existing) == name)
        throw Read_error("its Extra Bytes VLR already declares an attribute '" + std::string(name) +
                         "': write to PLY, or drop the attribute first");
    }
  }
  if (declared > extra)
    throw Read_error("its Extra Bytes VLR declares " + las_detail::bytes_text(declared) + " per record, more than the " +
                     las_detail::bytes_text(extra) + " its records have beyond point format " +
                     std::to_string(las.point_format) + ": an attribute cannot be added after them");
  std::string added;
  int unnamed = 0;
  for (std::size_t left = extra - declared; left > 0; left -= (std::min)(left, std::size_t(255)))
    added += descriptor(undocumented, unsigned((std::min)(left, std::size_t(255))),
                        "undeclared_bytes_" + std::to_string(++unnamed), "bytes the input declared no name for");
  return added + descriptor(double_type, 0, name, description);
}

} // namespace las_extra_bytes_detail

// Throws Read_error when a double attribute `name` cannot be added to `las`:
// its Extra Bytes record is inconsistent, already has `name`, or lies in an
// EVLR, or a length or offset would overflow its field.
inline void check_room_for_attribute(const Las_file& las, std::string_view name)
{
  namespace d = las_extra_bytes_detail;
  const std::size_t added = d::descriptors_to_add(las, name, "").size();
  const std::optional<std::size_t> vlr = d::extra_bytes_vlr(las);
  if (las.record_length + 8 > std::numeric_limits<std::uint16_t>::max() ||
      (vlr && las_detail::field<std::uint16_t>(las, *vlr + 20) + added > std::numeric_limits<std::uint16_t>::max()))
    throw Read_error("an attribute of 8 bytes would make its records or its Extra Bytes VLR longer than LAS "
                     "allows (65,535 bytes)");
  if (las.offset_to_points + added + las_detail::vlr_header_size > std::numeric_limits<std::uint32_t>::max())
    throw Read_error("an Extra Bytes descriptor would move its point data beyond the 4 GiB that the offset to "
                     "point data (byte 96) can hold");
}

// write_las() with `value_of_row[row]` after the bytes of each record,
// declared as the double attribute `name`.
inline void write_las_with_attribute(Sink& out, const Las_file& las, const std::vector<std::size_t>& rows,
                                     std::string_view name, std::string_view description,
                                     const std::vector<double>& value_of_row)
{
  namespace d = las_extra_bytes_detail;
  check_room_for_attribute(las, name);
  las_detail::check_rows(las, rows);
  const std::string descriptors = d::descriptors_to_add(las, name, description);
  const std::optional<std::size_t> vlr = d::extra_bytes_vlr(las);
  const std::size_t added = descriptors.size() + (vlr ? 0 : las_detail::vlr_header_size);
  const std::size_t record_length = las.record_length + 8, offset_to_points = las.offset_to_points + added;

  std::string header(las.bytes.substr(0, las.header_size));
  las_detail::patch_counts(header, las, rows);
  las_detail::patch_bounds(header, las, rows);
  las_detail::patch_offsets(header, las, offset_to_points + rows.size() * record_length);
  store_little_endian(&header[las_detail::record_length_at], std::uint16_t(record_length));
  store_little_endian(&header[las_detail::offset_to_points_at], std::uint32_t(offset_to_points));
  store_little_endian(&header[las_detail::vlr_count_at], std::uint32_t(las.vlr_count + (vlr ? 0 : 1)));
  out.write(header);

  // the VLRs, the descriptors at the end of the Extra Bytes VLR's data
  if (vlr)
  {
    const std::size_t length = las_detail::field<std::uint16_t>(las, *vlr + 20);
    std::string length_field(2, '\0');
    store_little_endian(&length_field[0], std::uint16_t(length + descriptors.size()));
    out.write(las.bytes.substr(las.header_size, *vlr + 20 - las.header_size));
    out.write(length_field);
    const std::size_t data_end = *vlr + las_detail::vlr_header_size + length;
    out.write(las.bytes.substr(*vlr + 22, data_end - (*vlr + 22)));
    out.write(descriptors);
    out.write(las.bytes.substr(data_end, las.offset_to_points - data_end));
  }
  else
  {
    const std::size_t vlrs_end = d::end_of_vlrs(las);
    std::string vlr_header(las_detail::vlr_header_size, '\0');
    std::string_view("LASF_Spec").copy(&vlr_header[2], 16);
    store_little_endian(&vlr_header[18], std::uint16_t(4));
    store_little_endian(&vlr_header[20], std::uint16_t(descriptors.size()));
    std::string_view("Extra Bytes").copy(&vlr_header[22], 32);
    out.write(las.bytes.substr(las.header_size, vlrs_end - las.header_size));
    out.write(vlr_header);
    out.write(descriptors);
    out.write(las.bytes.substr(vlrs_end, las.offset_to_points - vlrs_end));
  }

  las_detail::write_records(out, las, rows, [&](std::size_t row, std::string& buffer) {
    char value[8];
    store_little_endian(value, value_of_row[row]);
    buffer.append(value, 8);
  });
  out.write(las.bytes.substr(las_detail::points_end(las)));
}

} // namespace entropy_simplify

#endif // ENTROPY_SIMPLIFY_LAS_EXTRA_BYTES_H
