// ros2vtk — private helpers shared by the converters: error reporting and input checks.
#ifndef ros2vtk_convert_Validation_hpp
#define ros2vtk_convert_Validation_hpp

#include <cmath>
#include <limits>
#include <string>

namespace ros2vtk {
namespace convert {
namespace detail {

/// Writes "<where>: <what>" into *error when error is not null; always returns false so that
/// callers can `return fail(error, ...)`.
bool fail(std::string* error, const char* where, const std::string& what);

/// length_scale must be a finite positive number (1000 for mm, 1 for no scaling).
bool check_length_scale(double length_scale, const char* where, std::string* error);

inline bool all_finite(const double* values, int count)
{
  for (int i = 0; i < count; ++i)
  {
    if (!std::isfinite(values[i]))
    {
      return false;
    }
  }
  return true;
}

/// True when `value` is finite and fits T (a float holds 1e37 m, not 1e40 mm).
template<typename T>
bool finite_in(double value)
{
  return std::isfinite(value) &&
    std::fabs(value) <= static_cast<double>(std::numeric_limits<T>::max());
}

/// `value` as T, out-of-range values as +-infinity (a plain cast of 1e40 to float is undefined).
template<typename T>
T narrow_coordinate(double value)
{
  if (std::isfinite(value) && std::fabs(value) > static_cast<double>(std::numeric_limits<T>::max()))
  {
    return value > 0 ? std::numeric_limits<T>::infinity() : -std::numeric_limits<T>::infinity();
  }
  return static_cast<T>(value);
}

/// "1.5" style text for messages (shortest form that round-trips is not needed here).
std::string number_text(double value);

} // namespace detail
} // namespace convert
} // namespace ros2vtk

#endif
