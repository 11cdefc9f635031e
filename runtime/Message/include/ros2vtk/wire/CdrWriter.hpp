// ros2vtk — XCDR1 (PLAIN_CDR) writer for ROS 2 payloads.
//
// Why hand-written instead of Fast CDR: the generated serializers need a writer that is
// exactly what rmw_fastrtps puts on the wire (XCDR1, alignment relative to the byte after the
// 4-byte encapsulation header, 8-byte alignment for 64-bit types, strings with their NUL) and
// that can write straight into a Fast DDS payload without exceptions. Fast CDR 1.0 signals
// overflow by throwing, which we must never let cross into VTK's wrapping. The rules are in
// docs/wire-notes.md §7 and proven byte-exact against rclpy fixtures in tests/golden.
#ifndef ros2vtk_wire_CdrWriter_hpp
#define ros2vtk_wire_CdrWriter_hpp

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

namespace ros2vtk {
namespace wire {

/// Appends CDR data to a caller-owned buffer. The constructor writes the little-endian
/// encapsulation header `00 01 00 00`; every later offset is relative to the byte after it.
class CdrWriter
{
public:
  /// Writes into `buffer`, which is cleared first and grown as needed.
  explicit CdrWriter(std::vector<uint8_t>& buffer)
    : buffer_(buffer)
  {
    // assign, not clear + insert: g++ 12 reports a false -Warray-bounds/-Wstringop-overflow
    // for a range insert at the end of a vector it has just seen cleared.
    const uint8_t header[4] = { 0x00, 0x01, 0x00, 0x00 };
    buffer_.assign(header, header + 4);
  }

  /// Pre-allocates room for a payload of `total_size` bytes (header included).
  void reserve(size_t total_size) { buffer_.reserve(total_size); }

  /// Arithmetic primitives (not bool): aligned to their own size, written little-endian.
  template<typename T>
  void write(T value)
  {
    static_assert(std::is_arithmetic<T>::value && !std::is_same<T, bool>::value,
      "write() takes arithmetic non-bool values");
    align(sizeof(T));
    append(&value, sizeof(T));
  }

  /// bool is one byte, 0 or 1.
  void write(bool value)
  {
    const uint8_t byte = value ? 1 : 0;
    append(&byte, 1);
  }

  /// uint32 length including the terminating NUL, the bytes, then the NUL.
  void write_string(const std::string& value)
  {
    write(static_cast<uint32_t>(value.size() + 1));
    append(value.data(), value.size());
    const uint8_t nul = 0;
    append(&nul, 1);
  }

  /// wstring as rosidl_typesupport_fastrtps writes it: uint32 count, then one uint32 per unit.
  void write_wstring(const std::u16string& value)
  {
    write(static_cast<uint32_t>(value.size()));
    for (char16_t c : value)
    {
      write(static_cast<uint32_t>(c));
    }
  }

  /// The element count that precedes every sequence.
  void write_length(size_t count) { write(static_cast<uint32_t>(count)); }

  /// A run of arithmetic primitives; the first one is aligned, nothing is written for n == 0.
  template<typename T>
  void write_array(const T* values, size_t count)
  {
    static_assert(std::is_arithmetic<T>::value && !std::is_same<T, bool>::value,
      "write_array() takes arithmetic non-bool values");
    if (count == 0)
    {
      return;
    }
    align(sizeof(T));
    append(values, sizeof(T) * count);
  }

  /// Bytes written after the encapsulation header.
  size_t body_size() const { return buffer_.size() - 4; }

private:
  void align(size_t alignment)
  {
    const size_t misalignment = body_size() % alignment;
    if (misalignment != 0)
    {
      buffer_.resize(buffer_.size() + (alignment - misalignment), 0);
    }
  }

  void append(const void* data, size_t size)
  {
    if (size == 0)
    {
      return;
    }
    const size_t old_size = buffer_.size();
    buffer_.resize(old_size + size);
    std::memcpy(buffer_.data() + old_size, data, size);
  }

  std::vector<uint8_t>& buffer_;
};

/// Next multiple of `alignment` (CDR body offsets, docs/wire-notes.md): what the generated
/// payload_size() functions add up, shared so that generated files can be compiled together.
constexpr size_t cdr_align(size_t offset, size_t alignment)
{
  return (offset + alignment - 1) / alignment * alignment;
}

} // namespace wire
} // namespace ros2vtk

#endif
