#include "Validation.hpp"

#include <sstream>

namespace ros2vtk {
namespace convert {
namespace detail {

bool fail(std::string* error, const char* where, const std::string& what)
{
  if (error)
  {
    // Reasons quote received text (labels, encodings, field names): capped, so a 1 MB label
    // cannot make a 1 MB error, and cut at a UTF-8 character boundary (issue 11.9).
    constexpr size_t kMaxReasonBytes = 1000;
    if (what.size() <= kMaxReasonBytes)
    {
      *error = std::string(where) + ": " + what;
      return false;
    }
    size_t cut = kMaxReasonBytes;
    while (cut > 0 && (static_cast<unsigned char>(what[cut]) & 0xC0) == 0x80)
    {
      --cut;
    }
    *error = std::string(where) + ": " + what.substr(0, cut) + "... (" +
      std::to_string(what.size()) + " bytes)";
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
