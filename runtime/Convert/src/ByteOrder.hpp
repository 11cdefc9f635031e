// ros2vtk — private byte-order helpers for the image and point-cloud converters.
#ifndef ros2vtk_convert_ByteOrder_hpp
#define ros2vtk_convert_ByteOrder_hpp

#include <cstdint>
#include <cstring>

namespace ros2vtk {
namespace convert {
namespace detail {

/// True on big-endian hosts. (C++17 has no std::endian; the compiler folds this to a constant.)
inline bool host_is_big_endian()
{
  const uint16_t probe = 1;
  uint8_t first = 0;
  std::memcpy(&first, &probe, 1);
  return first == 0;
}

/// Copies one value of N bytes from src to dst, reversing its bytes when `swap` is set.
template<int N>
inline void copy_value(const uint8_t* src, uint8_t* dst, bool swap)
{
  if (swap)
  {
    for (int i = 0; i < N; ++i)
    {
      dst[i] = src[N - 1 - i];
    }
  }
  else
  {
    std::memcpy(dst, src, N);
  }
}

/// Reads a T stored at an unaligned address, optionally byte-swapped.
template<typename T>
inline T load_value(const uint8_t* src, bool swap)
{
  T value;
  copy_value<sizeof(T)>(src, reinterpret_cast<uint8_t*>(&value), swap);
  return value;
}

} // namespace detail
} // namespace convert
} // namespace ros2vtk

#endif
