// Bytes in and out: a bounds-checked reader over a file's bytes, the sink
// every writer writes to, and little-endian scalars (PLY's binary and LAS).

#ifndef ENTROPY_SIMPLIFY_BYTE_IO_H
#define ENTROPY_SIMPLIFY_BYTE_IO_H

#include "point_table.h"

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>

namespace entropy_simplify {

// Little-endian scalars, whatever the machine's order.
template <typename T>
T load_little_endian(const char* bytes)
{
  static_assert(std::is_arithmetic_v<T>);
  using Bits = std::conditional_t<sizeof(T) == 1, std::uint8_t,
               std::conditional_t<sizeof(T) == 2, std::uint16_t,
               std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t> > >;
  Bits bits = 0;
  for (std::size_t i = 0; i < sizeof(T); ++i)
    bits |= Bits(Bits(static_cast<unsigned char>(bytes[i])) << (8 * i));
  T value;
  std::memcpy(&value, &bits, sizeof(T));
  return value;
}

template <typename T>
void store_little_endian(char* bytes, T value)
{
  static_assert(std::is_arithmetic_v<T>);
  using Bits = std::conditional_t<sizeof(T) == 1, std::uint8_t,
               std::conditional_t<sizeof(T) == 2, std::uint16_t,
               std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t> > >;
  Bits bits;
  std::memcpy(&bits, &value, sizeof(T));
  for (std::size_t i = 0; i < sizeof(T); ++i)
    bytes[i] = char((bits >> (8 * i)) & 0xff);
}

// A value of `type` stored little-endian (big-endian when `big_endian`), as a double.
inline double load_scalar(const char* bytes, Scalar_type type, bool big_endian = false)
{
  char le[8];
  const std::size_t n = size_of(type);
  for (std::size_t i = 0; i < n; ++i)
    le[i] = big_endian ? bytes[n - 1 - i] : bytes[i];
  switch (type)
  {
  case Scalar_type::int8: return load_little_endian<std::int8_t>(le);
  case Scalar_type::uint8: return load_little_endian<std::uint8_t>(le);
  case Scalar_type::int16: return load_little_endian<std::int16_t>(le);
  case Scalar_type::uint16: return load_little_endian<std::uint16_t>(le);
  case Scalar_type::int32: return load_little_endian<std::int32_t>(le);
  case Scalar_type::uint32: return load_little_endian<std::uint32_t>(le);
  case Scalar_type::float32: return load_little_endian<float>(le);
  case Scalar_type::float64: return load_little_endian<double>(le);
  }
  return 0.;
}

// Stores `value`, a value of `type` (see holds()), little-endian.
inline void store_scalar(char* bytes, Scalar_type type, double value)
{
  switch (type)
  {
  case Scalar_type::int8: return store_little_endian(bytes, std::int8_t(value));
  case Scalar_type::uint8: return store_little_endian(bytes, std::uint8_t(value));
  case Scalar_type::int16: return store_little_endian(bytes, std::int16_t(value));
  case Scalar_type::uint16: return store_little_endian(bytes, std::uint16_t(value));
  case Scalar_type::int32: return store_little_endian(bytes, std::int32_t(value));
  case Scalar_type::uint32: return store_little_endian(bytes, std::uint32_t(value));
  case Scalar_type::float32: return store_little_endian(bytes, float(value));
  case Scalar_type::float64: return store_little_endian(bytes, value);
  }
}

// Reads a file's bytes front to back; reading past the end is a Read_error
// naming what was being read, never an access out of bounds.
class Byte_reader
{
public:
  explicit Byte_reader(std::string_view bytes, std::size_t position = 0) : bytes_(bytes), position_(position) {}

  std::size_t position() const { return position_; }
  std::size_t remaining() const { return position_ <= bytes_.size() ? bytes_.size() - position_ : 0; }

  // The next `n` bytes, or a Read_error saying that `what` is truncated.
  const char* take(std::size_t n, const char* what)
  {
    if (n > remaining())
      throw Read_error(std::string("the file is truncated: ") + what + " needs " + std::to_string(n) +
                       " bytes at byte " + std::to_string(position_) + ", " + std::to_string(remaining()) +
                       " remain");
    const char* at = bytes_.data() + position_;
    position_ += n;
    return at;
  }

  template <typename T>
  T little_endian(const char* what)
  {
    return load_little_endian<T>(take(sizeof(T), what));
  }

private:
  std::string_view bytes_;
  std::size_t position_;
};

// Where writers write. Each write is checked: a sink throws on failure
// (std::system_error for a file), so a writer never reports success over a
// short write.
class Sink
{
public:
  virtual ~Sink() = default;
  virtual void write(const char* data, std::size_t size) = 0;
  void write(std::string_view text) { write(text.data(), text.size()); }
};

// A sink in memory, for tests and the fuzzer's round trips.
class String_sink : public Sink
{
public:
  using Sink::write;
  void write(const char* data, std::size_t size) override { bytes.append(data, size); }
  std::string bytes;
};

} // namespace entropy_simplify

#endif // ENTROPY_SIMPLIFY_BYTE_IO_H
