// ros2vtk — bounds-checked XCDR1 (PLAIN_CDR) reader for ROS 2 payloads.
//
// Why hand-written instead of Fast CDR: bytes from the network are hostile. Fast CDR 1.0
// resizes a std::vector to whatever 32-bit length the sample claims before noticing the buffer
// is short (a 4 GiB allocation from a 12-byte sample), and it reports errors by exceptions.
// This reader checks every length against the bytes that remain *before* allocating, rejects
// bools other than 0/1, and records the first failure (what and where) instead of throwing.
#ifndef ros2vtk_wire_CdrReader_hpp
#define ros2vtk_wire_CdrReader_hpp

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>

#include "ros2vtk/wire/Utf8.hpp"

namespace ros2vtk {
namespace wire {

/// Reads one serialized payload (encapsulation header included). After the first failure
/// every read returns false and ok() stays false; error() says what and at which offset.
class CdrReader
{
public:
  CdrReader(const uint8_t* data, size_t size)
    : data_(data)
    , size_(size)
  {
    if (size_ < 4)
    {
      fail("payload shorter than the 4-byte encapsulation header");
      return;
    }
    if (data_[0] != 0x00 || data_[1] > 0x01)
    {
      fail("unsupported encapsulation (only CDR_BE 00 00 and CDR_LE 00 01 are ROS 2 payloads)");
      return;
    }
    swap_ = (data_[1] == 0x00) != is_big_endian_host();
    body_ = data_ + 4;
    body_size_ = size_ - 4;
  }

  bool ok() const { return error_.empty(); }
  const std::string& error() const { return error_; }

  /// Body bytes not read yet (RTPS may pad up to 3 zero bytes after the body: ignore them).
  size_t remaining() const { return ok() ? body_size_ - position_ : 0; }

  /// Arithmetic primitives (not bool).
  template<typename T>
  bool read(T& value)
  {
    static_assert(std::is_arithmetic<T>::value && !std::is_same<T, bool>::value,
      "read() takes arithmetic non-bool values");
    if (!align(sizeof(T)) || !need(sizeof(T), "primitive"))
    {
      return false;
    }
    std::memcpy(&value, body_ + position_, sizeof(T));
    if (swap_)
    {
      value = byte_swap(value);
    }
    position_ += sizeof(T);
    return true;
  }

  /// bool: one byte that must be 0 or 1 (Fast CDR rejects anything else too).
  bool read(bool& value)
  {
    if (!need(1, "bool"))
    {
      return false;
    }
    const uint8_t byte = body_[position_];
    if (byte > 1)
    {
      return fail("bool byte is neither 0 nor 1");
    }
    value = byte == 1;
    position_ += 1;
    return true;
  }

  /// string / string<=bound. A length of 0 is accepted as empty; the NUL is stripped.
  bool read_string(std::string& value, uint32_t bound = 0)
  {
    uint32_t length = 0;
    if (!read(length))
    {
      return false;
    }
    if (length == 0)
    {
      value.clear();
      return true;
    }
    if (!need(length, "string"))
    {
      return false;
    }
    const char* chars = reinterpret_cast<const char*>(body_ + position_);
    size_t count = length;
    if (chars[count - 1] == '\0')
    {
      --count;
    }
    if (bound != 0 && count > bound)
    {
      return fail("string longer than its bound");
    }
    value.assign(chars, count);
    position_ += length;
    invalid_utf8_ += repair_utf8(value); // U+FFFD, as rclpy decodes (see Utf8.hpp)
    return true;
  }

  /// Invalid UTF-8 sequences replaced by U+FFFD in the strings read so far.
  size_t invalid_utf8_replaced() const { return invalid_utf8_; }

  /// wstring: uint32 count, then one uint32 per UTF-16 unit.
  bool read_wstring(std::u16string& value, uint32_t bound = 0)
  {
    uint32_t count = 0;
    if (!read_length(count, 4))
    {
      return false;
    }
    if (bound != 0 && count > bound)
    {
      return fail("wstring longer than its bound");
    }
    value.resize(count);
    for (uint32_t i = 0; i < count; ++i)
    {
      uint32_t unit = 0;
      if (!read(unit))
      {
        return false;
      }
      value[i] = static_cast<char16_t>(unit);
    }
    return true;
  }

  /// A sequence count. Rejects counts that cannot fit in the remaining bytes given the
  /// smallest possible serialized element (1 for structs and bytes), so no caller allocates
  /// memory for elements that are not there.
  bool read_length(uint32_t& count, size_t min_element_size, uint32_t bound = 0)
  {
    if (!read(count))
    {
      return false;
    }
    if (bound != 0 && count > bound)
    {
      return fail("sequence longer than its bound");
    }
    const size_t element = min_element_size == 0 ? 1 : min_element_size;
    if (static_cast<uint64_t>(count) * element > body_size_ - position_)
    {
      return fail("sequence length exceeds the remaining bytes");
    }
    return true;
  }

  /// A run of arithmetic primitives; the first one is aligned, nothing is read for n == 0.
  template<typename T>
  bool read_array(T* values, size_t count)
  {
    static_assert(std::is_arithmetic<T>::value && !std::is_same<T, bool>::value,
      "read_array() takes arithmetic non-bool values");
    if (count == 0)
    {
      return ok();
    }
    if (!align(sizeof(T)) || !need(sizeof(T) * count, "array"))
    {
      return false;
    }
    std::memcpy(values, body_ + position_, sizeof(T) * count);
    if (swap_)
    {
      for (size_t i = 0; i < count; ++i)
      {
        values[i] = byte_swap(values[i]);
      }
    }
    position_ += sizeof(T) * count;
    return true;
  }

  /// Marks the payload as rejected; returns false for convenient `return r.fail(...)`.
  bool fail(const char* what)
  {
    if (error_.empty())
    {
      error_ = std::string(what) + " (at body offset " + std::to_string(position_) + " of " +
        std::to_string(body_size_) + ")";
    }
    return false;
  }

private:
  static bool is_big_endian_host()
  {
    const uint16_t probe = 1;
    uint8_t first = 0;
    std::memcpy(&first, &probe, 1);
    return first == 0;
  }

  template<typename T>
  static T byte_swap(T value)
  {
    uint8_t bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    for (size_t i = 0; i < sizeof(T) / 2; ++i)
    {
      const uint8_t tmp = bytes[i];
      bytes[i] = bytes[sizeof(T) - 1 - i];
      bytes[sizeof(T) - 1 - i] = tmp;
    }
    std::memcpy(&value, bytes, sizeof(T));
    return value;
  }

  bool need(size_t bytes, const char* what)
  {
    if (!ok())
    {
      return false;
    }
    if (bytes > body_size_ - position_)
    {
      error_ = std::string("truncated payload: ") + what + " needs " + std::to_string(bytes) +
        " bytes at body offset " + std::to_string(position_) + ", only " +
        std::to_string(body_size_ - position_) + " remain";
      return false;
    }
    return true;
  }

  bool align(size_t alignment)
  {
    if (!ok())
    {
      return false;
    }
    const size_t misalignment = position_ % alignment;
    if (misalignment != 0)
    {
      const size_t padding = alignment - misalignment;
      if (!need(padding, "alignment padding"))
      {
        return false;
      }
      position_ += padding;
    }
    return true;
  }

  const uint8_t* data_ = nullptr;
  size_t size_ = 0;
  const uint8_t* body_ = nullptr;
  size_t body_size_ = 0;
  size_t position_ = 0;
  bool swap_ = false;
  std::string error_;
  size_t invalid_utf8_ = 0;
};

} // namespace wire
} // namespace ros2vtk

#endif
