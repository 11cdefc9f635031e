// ros2vtk — PLY header grammar and body records checked before assimp reads the file (why: see
// PlyFileCheck.hpp).
#include "PlyFileCheck.hpp"

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <vector>

namespace ros2vtk {
namespace robot {
namespace {

enum class PlyFormat
{
  Ascii,
  BinaryLittleEndian,
  BinaryBigEndian
};

struct PlyType
{
  int bytes;
  bool integer;
  bool is_signed;
};

const std::map<std::string, PlyType>& ply_types()
{
  static const std::map<std::string, PlyType> types{ { "char", { 1, true, true } },
    { "int8", { 1, true, true } }, { "uchar", { 1, true, false } }, { "uint8", { 1, true, false } },
    { "short", { 2, true, true } }, { "int16", { 2, true, true } },
    { "ushort", { 2, true, false } }, { "uint16", { 2, true, false } },
    { "int", { 4, true, true } }, { "int32", { 4, true, true } }, { "uint", { 4, true, false } },
    { "uint32", { 4, true, false } }, { "float", { 4, false, true } },
    { "float32", { 4, false, true } }, { "double", { 8, false, true } },
    { "float64", { 8, false, true } } };
  return types;
}

struct PlyProperty
{
  std::string name;
  bool list = false;
  PlyType count_type{ 0, true, false }; ///< lists only
  PlyType value_type{ 0, true, false };
  bool vertex_index = false; ///< a face's vertex_indices list: values must name a vertex
};

struct PlyElement
{
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader
{
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  std::uint64_t vertices = 0;
  std::size_t body_offset = 0; ///< first byte after the end_header line
  int body_first_line = 0;     ///< its line number (ASCII messages)
};

// Reads the header lines of `bytes` into `header`; false with `why` on the first violation of the
// PLY grammar (messages say "line N: …" as before the body was checked too).
bool parse_header(const std::string& bytes, PlyHeader* header, std::string* why)
{
  std::size_t pos = 0;
  auto next_line = [&](std::string* line) {
    if (pos >= bytes.size())
      return false;
    const std::size_t end = bytes.find('\n', pos);
    *line = bytes.substr(pos, (end == std::string::npos ? bytes.size() : end) - pos);
    pos = end == std::string::npos ? bytes.size() : end + 1;
    if (!line->empty() && line->back() == '\r')
      line->pop_back();
    return true;
  };
  std::string line;
  if (!next_line(&line) || line != "ply")
    return *why = "the first line is not 'ply'", false;
  bool has_format = false;
  std::set<std::string> vertex_axes; // x, y, z seen on "vertex"
  bool face_needs_indices = false;   // a "face" element without its vertex_indices list yet
  const char* kNoIndices = "the 'face' element has no 'property list <type> <type> vertex_indices'";
  for (int number = 2; next_line(&line); ++number)
  {
    const std::string at = "line " + std::to_string(number) + ": ";
    if (number > 10000)
      return *why = "no end_header in the first 10000 lines", false;
    for (unsigned char c : line)
      if ((c < 0x20 && c != '\t') || c > 0x7e)
        return *why = at + "a byte that is not printable ASCII", false;
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    std::vector<std::string> rest;
    for (std::string word; words >> word;)
      rest.push_back(word);
    if (keyword == "end_header")
    {
      if (!has_format)
        return *why = "no 'format' line", false;
      if (vertex_axes.size() != 3)
        return *why = "no 'element vertex' with properties x, y and z", false;
      if (face_needs_indices)
        return *why = kNoIndices, false;
      for (const PlyElement& element : header->elements)
        if (element.properties.empty() && element.count > 0)
          return *why = "the element '" + element.name + "' has records but no properties", false;
      header->body_offset = pos;
      header->body_first_line = number + 1;
      return true;
    }
    if (keyword == "format")
    {
      static const std::map<std::string, PlyFormat> formats{ { "ascii", PlyFormat::Ascii },
        { "binary_little_endian", PlyFormat::BinaryLittleEndian },
        { "binary_big_endian", PlyFormat::BinaryBigEndian } };
      if (rest.size() != 2 || formats.count(rest[0]) == 0)
        return *why =
                 at + "expected 'format ascii|binary_little_endian|binary_big_endian <version>'",
               false;
      header->format = formats.at(rest[0]);
      has_format = true;
    }
    else if (keyword == "element")
    {
      if (rest.size() != 2 || rest[1].find_first_not_of("0123456789") != std::string::npos ||
        rest[1].size() > 12)
        return *why = at + "expected 'element <name> <count>'", false;
      if (face_needs_indices)
        return *why = at + kNoIndices, false;
      PlyElement element;
      element.name = rest[0];
      element.count = std::stoull(rest[1]);
      // Every record takes at least one byte, so a count beyond the file size is a lie that
      // a reader would trust with its allocations.
      if (element.count > bytes.size())
        return *why = at + "the element '" + element.name + "' announces " + rest[1] +
                 " records, more than a " + std::to_string(bytes.size()) + "-byte file can hold",
               false;
      if (element.name == "vertex")
        header->vertices = element.count;
      face_needs_indices = element.name == "face";
      header->elements.push_back(element);
    }
    else if (keyword == "property")
    {
      const auto& types = ply_types();
      const bool scalar = rest.size() == 2 && types.count(rest[0]);
      const bool list =
        rest.size() == 4 && rest[0] == "list" && types.count(rest[1]) && types.count(rest[2]);
      if (header->elements.empty() || !(scalar || list))
        return *why = at +
                 "expected 'property <type> <name>' or 'property list <type> <type> <name>' after "
                 "an element",
               false;
      PlyElement& element = header->elements.back();
      PlyProperty property;
      property.name = rest.back();
      property.list = list;
      property.value_type = types.at(list ? rest[2] : rest[0]);
      if (list)
      {
        property.count_type = types.at(rest[1]);
        if (!property.count_type.integer)
          return *why = at + "a list count of type '" + rest[1] + "' (counts are integers)", false;
      }
      // Faces are read through a list named vertex_indices (or vertex_index).
      if (element.name == "vertex" && scalar &&
        (property.name == "x" || property.name == "y" || property.name == "z"))
        vertex_axes.insert(property.name);
      if (list && (property.name == "vertex_indices" || property.name == "vertex_index"))
      {
        if (!property.value_type.integer)
          return *why = at + "vertex indices of type '" + rest[2] + "' (indices are integers)",
                 false;
        property.vertex_index = true;
        if (element.name == "face")
          face_needs_indices = false;
      }
      element.properties.push_back(property);
    }
    else if (keyword != "comment" && keyword != "obj_info" && !keyword.empty())
    {
      return *why = at + "unknown keyword '" + keyword + "'", false;
    }
  }
  return *why = "no end_header", false;
}

// ---- values -----------------------------------------------------------------------------------

bool in_range(const PlyType& type, long double value)
{
  if (!type.integer)
    return type.bytes == 8 || std::fabs(value) <= std::numeric_limits<float>::max();
  const int bits = type.bytes * 8;
  const long double low = type.is_signed ? -std::ldexp(1.0L, bits - 1) : 0.0L;
  const long double high =
    type.is_signed ? std::ldexp(1.0L, bits - 1) - 1 : std::ldexp(1.0L, bits) - 1;
  return value >= low && value <= high;
}

// An ASCII value as assimp's fast parsers read it: decimal digits and signs (and '.', 'e' for
// floating types) only, all of the token consumed, finite and within the type's range. Hex
// floats, "nan" and locale forms are refused (assimp would read them differently from strtod).
bool parse_ascii_value(const std::string& token, const PlyType& type, long double* value)
{
  const char* allowed = type.integer ? "0123456789+-" : "0123456789+-.eE";
  if (token.empty() || token.find_first_not_of(allowed) != std::string::npos)
    return false;
  char* end = nullptr;
  errno = 0;
  *value = std::strtold(token.c_str(), &end);
  if (errno != 0 || end != token.c_str() + token.size() || !std::isfinite(*value))
    return false;
  if (type.integer && *value != std::floor(*value))
    return false;
  return in_range(type, *value);
}

bool read_binary_value(const std::string& bytes, std::size_t* pos, const PlyType& type,
  bool big_endian, long double* value)
{
  const auto size = static_cast<std::size_t>(type.bytes);
  if (bytes.size() - *pos < size)
    return false;
  std::uint64_t bits = 0; // the value's bits, assembled from the file's byte order
  for (std::size_t i = 0; i < size; ++i)
  {
    const auto byte = static_cast<unsigned char>(bytes[*pos + (big_endian ? i : size - 1 - i)]);
    bits = (bits << 8) | byte;
  }
  *pos += size;
  if (!type.integer)
  {
    if (size == 4)
    {
      const auto narrow = static_cast<std::uint32_t>(bits);
      float f = 0;
      std::memcpy(&f, &narrow, 4);
      *value = f;
    }
    else
    {
      double d = 0;
      std::memcpy(&d, &bits, 8);
      *value = d;
    }
    return true;
  }
  if (type.is_signed && (bits >> (size * 8 - 1)) & 1)
    *value = static_cast<long double>(bits) - std::ldexp(1.0L, static_cast<int>(size * 8));
  else
    *value = static_cast<long double>(bits);
  return true;
}

// ---- body -------------------------------------------------------------------------------------

// assimp 5.2's post-processing crashes (SIGBUS) on a face without indices (found by tests/fuzz).
const char* const kEmptyFace = "a face with no vertex indices";

std::string vertex_index_problem(long double index, std::uint64_t vertices)
{
  if (index >= 0 && index < static_cast<long double>(vertices))
    return {};
  std::ostringstream out;
  out << "vertex index " << static_cast<long long>(index) << " is outside [0, " << vertices << ")";
  return out.str();
}

bool check_ascii_body(const std::string& bytes, const PlyHeader& header, std::string* why)
{
  std::size_t pos = header.body_offset;
  int number = header.body_first_line;
  for (const PlyElement& element : header.elements)
  {
    for (std::uint64_t record = 0; record < element.count; ++record, ++number)
    {
      const std::string at = "line " + std::to_string(number) + ": ";
      if (pos >= bytes.size())
        return *why = "the body ends after " + std::to_string(record) + " of " +
                 std::to_string(element.count) + " '" + element.name + "' records",
               false;
      const std::size_t end = std::min(bytes.find('\n', pos), bytes.size());
      std::istringstream words(bytes.substr(pos, end - pos));
      pos = end + 1;
      std::vector<std::string> tokens;
      for (std::string word; words >> word;)
        tokens.push_back(word);
      std::size_t next = 0;
      long double value = 0;
      for (const PlyProperty& property : element.properties)
      {
        std::uint64_t values = 1;
        if (property.list)
        {
          if (next >= tokens.size() ||
            !parse_ascii_value(tokens[next], property.count_type, &value) || value < 0)
            return *why = at + "the list '" + property.name + "' has no valid count", false;
          if (property.vertex_index && value < 1)
            return *why = at + kEmptyFace, false;
          values = static_cast<std::uint64_t>(value);
          ++next;
        }
        if (values > tokens.size() - next)
          return *why = at + std::to_string(tokens.size()) +
                   " values, fewer than the header announces for a '" + element.name + "' record",
                 false;
        for (std::uint64_t k = 0; k < values; ++k, ++next)
        {
          if (!parse_ascii_value(tokens[next], property.value_type, &value))
            return *why = at + "the value '" + tokens[next].substr(0, 32) + "' of '" +
                     property.name + "' is not a number of its type",
                   false;
          const std::string index_problem =
            property.vertex_index ? vertex_index_problem(value, header.vertices) : "";
          if (!index_problem.empty())
            return *why = at + index_problem, false;
        }
      }
      if (next != tokens.size())
        return *why = at + std::to_string(tokens.size()) + " values where the header announces " +
                 std::to_string(next) + " for a '" + element.name + "' record",
               false;
    }
  }
  if (bytes.find_first_not_of(" \t\r\n", std::min(pos, bytes.size())) != std::string::npos)
    return *why =
             "line " + std::to_string(number) + ": data after the last record the header announces",
           false;
  return true;
}

bool check_binary_body(const std::string& bytes, const PlyHeader& header, std::string* why)
{
  const bool big_endian = header.format == PlyFormat::BinaryBigEndian;
  std::size_t pos = header.body_offset;
  for (const PlyElement& element : header.elements)
  {
    for (std::uint64_t record = 0; record < element.count; ++record)
    {
      const std::string at = "byte " + std::to_string(pos) + ": ";
      const std::string ends = "the body ends inside '" + element.name + "' record " +
        std::to_string(record) + " of " + std::to_string(element.count);
      long double value = 0;
      for (const PlyProperty& property : element.properties)
      {
        std::uint64_t values = 1;
        if (property.list)
        {
          if (!read_binary_value(bytes, &pos, property.count_type, big_endian, &value))
            return *why = ends, false;
          if (value < 0)
            return *why = at + "the list '" + property.name + "' has a negative count", false;
          if (property.vertex_index && value < 1)
            return *why = at + kEmptyFace, false;
          values = static_cast<std::uint64_t>(value);
        }
        // Checked before the loop, so that a huge count cannot make the walk long.
        if (values > (bytes.size() - pos) / static_cast<std::size_t>(property.value_type.bytes))
          return *why = ends, false;
        for (std::uint64_t k = 0; k < values; ++k)
        {
          read_binary_value(bytes, &pos, property.value_type, big_endian, &value);
          const std::string index_problem =
            property.vertex_index ? vertex_index_problem(value, header.vertices) : "";
          if (!index_problem.empty())
            return *why = at + index_problem, false;
        }
      }
    }
  }
  return true;
}

} // namespace

bool PlyFileCheck::check(const std::string& path, std::string* error)
{
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  PlyHeader header;
  std::string why;
  if (!parse_header(bytes, &header, &why))
  {
    if (error)
      *error = "PLY file '" + path + "' has a malformed header: " + why;
    return false;
  }
  const bool body_ok = header.format == PlyFormat::Ascii ? check_ascii_body(bytes, header, &why)
                                                         : check_binary_body(bytes, header, &why);
  if (!body_ok && error)
    *error = "PLY file '" + path + "' does not match its header: " + why;
  return body_ok;
}

} // namespace robot
} // namespace ros2vtk
