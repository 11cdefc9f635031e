#include "Validation.hpp"

#include <sstream>

namespace ros2vtk {
namespace convert {
namespace detail {

bool fail(std::string* error, const char* where, const std::string& what)
{
  if (error)
  {
    *error = std::string(where) + ": " + what;
  }
  return false;
}

bool check_length_scale(double length_scale, const char* where, std::string* error)
{
  if (!std::isfinite(length_scale) || length_scale <= 0.0)
  {
    return fail(error, where,
      "length_scale must be a finite positive number (1000 for millimetres, 1 for none), got " +
        number_text(length_scale));
  }
  return true;
}

std::string number_text(double value)
{
  std::ostringstream text;
  text << value;
  return text.str();
}

} // namespace detail
} // namespace convert
} // namespace ros2vtk
