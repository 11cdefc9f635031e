// ros2vtk — Collada arrays, accessors and primitives checked before assimp reads the file (why:
// see ColladaFileCheck.hpp).
#include "ColladaFileCheck.hpp"

#include <tinyxml2.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <map>
#include <set>
#include <vector>

namespace ros2vtk {
namespace robot {
namespace {

enum class Numbers
{
  Float,
  Integer,
  Index, ///< a non-negative integer below 2^31 (assimp keeps indices in unsigned int)
  Any    ///< names, booleans: counted, not parsed
};

// A token as assimp's fast number parsers read it: signs, digits (and '.', 'e' for floats), all of
// it consumed, finite. Hex, "nan" and locale forms are refused: assimp and strtod disagree on them.
// The common tokens (plain decimals, indices) are decided without strtold: a mesh holds millions
// of them, and strtold with a string per token cost a third of a Collada robot's load time.
bool is_number(const char* begin, const char* end, Numbers kind, long double* value)
{
  static const auto allowed_table = [](const char* chars) {
    std::array<bool, 256> table{};
    for (const char* c = chars; *c; ++c)
      table[static_cast<unsigned char>(*c)] = true;
    return table;
  };
  static const std::array<bool, 256> float_chars = allowed_table("0123456789+-.eE");
  static const std::array<bool, 256> integer_chars = allowed_table("0123456789+-");
  static const std::array<bool, 256> index_chars = allowed_table("0123456789");
  const std::array<bool, 256>& allowed = kind == Numbers::Float ? float_chars
    : kind == Numbers::Integer                                  ? integer_chars
                                                                : index_chars;
  const std::ptrdiff_t length = end - begin;
  if (length > 64)
    return false;
  bool exponent = false;
  for (const char* c = begin; c != end; ++c)
  {
    if (!allowed[static_cast<unsigned char>(*c)])
      return false;
    exponent = exponent || *c == 'e' || *c == 'E';
  }
  // Fast path: [sign] digits [. digits] with at least one digit and no exponent is what strtold
  // reads whole, and it is finite (at most 64 characters); a value is only needed for indices.
  const char* p =
    begin + ((kind != Numbers::Index && length > 0 && (*begin == '+' || *begin == '-')) ? 1 : 0);
  if (!exponent && p != end)
  {
    std::uint64_t integer = 0;
    int digits = 0, dots = 0;
    bool plain = true;
    for (const char* c = p; c != end && plain; ++c)
    {
      if (*c >= '0' && *c <= '9')
      {
        ++digits;
        integer = integer * 10 + static_cast<std::uint64_t>(*c - '0');
      }
      else if (*c == '.' && kind == Numbers::Float && dots == 0)
        ++dots;
      else
        plain = false;
    }
    if (plain && digits > 0 && (kind == Numbers::Float || digits <= 18))
    {
      if (kind == Numbers::Float)
        return true;
      *value =
        (*begin == '-') ? -static_cast<long double>(integer) : static_cast<long double>(integer);
      return kind == Numbers::Index ? *value < 2147483648.0L : std::fabs(*value) < 9.2e18L;
    }
  }
  char token[65];
  std::memcpy(token, begin, static_cast<std::size_t>(length));
  token[length] = '\0';
  char* stop = nullptr;
  errno = 0;
  *value = std::strtold(token, &stop);
  if (errno != 0 || stop != token + length || !std::isfinite(*value))
    return false;
  if (kind == Numbers::Index)
    return *value < 2147483648.0L;
  if (kind == Numbers::Integer)
    return std::fabs(*value) < 9.2e18L;
  return true;
}

struct Tokens
{
  std::uint64_t count = 0;
  long double sum = 0; ///< of the values (vcount lists)
  std::string bad;     ///< the first token that is not a number of its kind
};

// Character classes of the scanner below (one table look-up per character).
enum CharClass : std::uint8_t
{
  kEnd = 1,
  kSpace = 2,
  kDigit = 4,
  kSign = 8,
  kDot = 16,
  kExponent = 32,
  kOther = 64
};

const std::array<std::uint8_t, 256>& char_classes()
{
  static const std::array<std::uint8_t, 256> classes = [] {
    std::array<std::uint8_t, 256> table{};
    table.fill(kOther);
    table[0] = kEnd;
    for (const char c : { ' ', '\t', '\n', '\r' })
      table[static_cast<unsigned char>(c)] = kSpace;
    for (char c = '0'; c <= '9'; ++c)
      table[static_cast<unsigned char>(c)] = kDigit;
    table[static_cast<unsigned char>('+')] = table[static_cast<unsigned char>('-')] = kSign;
    table[static_cast<unsigned char>('.')] = kDot;
    table[static_cast<unsigned char>('e')] = table[static_cast<unsigned char>('E')] = kExponent;
    return table;
  }();
  return classes;
}

// Splits the text at white space and checks each token as is_number does. The forms a mesh is
// made of ([sign] digits [. digits]) are decided in the same pass over the characters that finds
// the token's end; everything else (exponents, stray characters, long tokens) goes to is_number.
// Why: a robot's Collada files hold millions of numbers, and three passes per token (split,
// allowed characters, fast path) were a sixth of the first load of a Collada robot.
Tokens scan(const char* text, Numbers kind)
{
  const std::array<std::uint8_t, 256>& classes = char_classes();
  const std::uint8_t allowed = kind == Numbers::Float ? (kDigit | kSign | kDot)
    : kind == Numbers::Integer                        ? (kDigit | kSign)
                                                      : kDigit;
  Tokens tokens;
  const char* p = text ? text : "";
  for (;;)
  {
    while (classes[static_cast<unsigned char>(*p)] == kSpace)
      ++p;
    if (*p == '\0')
      break;
    const char* start = p;
    std::uint8_t seen = 0;
    int digits = 0, dots = 0;
    bool sign_inside = false;
    std::uint64_t integer = 0;
    for (std::uint8_t c = classes[static_cast<unsigned char>(*p)]; !(c & (kSpace | kEnd));
         c = classes[static_cast<unsigned char>(*++p)])
    {
      seen |= c;
      if (c == kDigit)
      {
        ++digits;
        integer = integer * 10 + static_cast<std::uint64_t>(*p - '0');
      }
      else if (c == kDot)
        ++dots;
      else if (c == kSign && p != start)
        sign_inside = true;
    }
    ++tokens.count;
    if (kind == Numbers::Any || !tokens.bad.empty())
      continue;
    const bool plain = (seen & ~allowed) == 0 && !sign_inside && digits > 0 && p - start <= 64 &&
      dots <= (kind == Numbers::Float ? 1 : 0) && (kind == Numbers::Float || digits <= 18);
    long double value = 0;
    bool number = true;
    if (plain && kind != Numbers::Float)
    {
      value =
        (*start == '-') ? -static_cast<long double>(integer) : static_cast<long double>(integer);
      number = kind == Numbers::Index ? value < 2147483648.0L : std::fabs(value) < 9.2e18L;
    }
    else if (!plain)
      number = is_number(start, p, kind, &value);
    if (number)
      tokens.sum += value;
    else
      tokens.bad.assign(start, static_cast<std::size_t>(std::min<std::ptrdiff_t>(p - start, 32)));
  }
  return tokens;
}

constexpr std::uint64_t kRequired = ~std::uint64_t(0); // attribute_count: no default, must be there

// A count-like attribute: decimal digits only. Absent reads as `fallback`, or fails when the
// fallback is kRequired (COLLADA requires count on arrays, accessors and primitives, and assimp
// 5.2 crashes on an array without one: found by the mutation test).
bool attribute_count(const tinyxml2::XMLElement* element, const char* name, std::uint64_t fallback,
  std::uint64_t* value)
{
  const char* text = element->Attribute(name);
  if (!text)
    return *value = fallback, fallback != kRequired;
  if (!*text || std::strlen(text) > 18 || std::strspn(text, "0123456789") != std::strlen(text))
    return false;
  *value = std::strtoull(text, nullptr, 10);
  return true;
}

class Checker
{
public:
  bool run(const tinyxml2::XMLElement* root)
  {
    std::vector<const tinyxml2::XMLElement*> stack{ root };
    while (!stack.empty())
    {
      const tinyxml2::XMLElement* element = stack.back();
      stack.pop_back();
      if (!visit(element))
        return false;
      for (const auto* child = element->LastChildElement(); child;
           child = child->PreviousSiblingElement())
        stack.push_back(child);
    }
    return check_accessors();
  }

  std::string problem;

private:
  struct Accessor
  {
    const tinyxml2::XMLElement* element;
    std::string source;
    std::uint64_t count, stride, offset;
  };

  bool fail(const tinyxml2::XMLElement* element, const std::string& why)
  {
    problem =
      "line " + std::to_string(element->GetLineNum()) + ": <" + element->Name() + "> " + why;
    return false;
  }

  bool visit(const tinyxml2::XMLElement* element)
  {
    static const std::map<std::string, Numbers> arrays{ { "float_array", Numbers::Float },
      { "int_array", Numbers::Integer }, { "bool_array", Numbers::Any },
      { "Name_array", Numbers::Any }, { "IDREF_array", Numbers::Any },
      { "SIDREF_array", Numbers::Any }, { "token_array", Numbers::Any } };
    static const std::set<std::string> primitives{ "triangles", "lines", "polylist", "polygons",
      "linestrips", "tristrips", "trifans", "vertex_weights" };
    const std::string name = element->Name();
    const auto array = arrays.find(name);
    if (array != arrays.end())
      return visit_array(element, array->second);
    if (name == "accessor")
      return visit_accessor(element);
    if (primitives.count(name))
      return visit_primitive(element, name);
    return true;
  }

  bool visit_array(const tinyxml2::XMLElement* element, Numbers kind)
  {
    const Tokens tokens = scan(element->GetText(), kind);
    if (!tokens.bad.empty())
      return fail(element, "holds '" + tokens.bad + "', which is not a number of its kind");
    std::uint64_t count = 0;
    if (!attribute_count(element, "count", kRequired, &count))
      return fail(element, "has no count, or one that is not a number");
    if (count != tokens.count)
      return fail(element,
        "announces " + std::to_string(count) + " values but holds " + std::to_string(tokens.count));
    if (const char* id = element->Attribute("id"))
      array_sizes_[id] = count;
    return true;
  }

  bool visit_accessor(const tinyxml2::XMLElement* element)
  {
    Accessor accessor{ element, element->Attribute("source") ? element->Attribute("source") : "", 0,
      1, 0 };
    if (!attribute_count(element, "count", kRequired, &accessor.count) ||
      !attribute_count(element, "stride", 1, &accessor.stride) ||
      !attribute_count(element, "offset", 0, &accessor.offset))
      return fail(element, "has no count, or a count, stride or offset that is not a number");
    accessors_.push_back(accessor);
    return true;
  }

  // Arrays may follow their accessors in the document, so accessors are checked at the end.
  bool check_accessors()
  {
    for (const Accessor& accessor : accessors_)
    {
      if (accessor.source.empty() || accessor.source[0] != '#')
        continue; // an external source: assimp does not follow it
      const auto array = array_sizes_.find(accessor.source.substr(1));
      if (array == array_sizes_.end())
        return fail(accessor.element,
          "names the array '" + accessor.source + "', which the file does not hold");
      const long double needed = static_cast<long double>(accessor.offset) +
        static_cast<long double>(accessor.count) * static_cast<long double>(accessor.stride);
      if (needed > static_cast<long double>(array->second))
        return fail(accessor.element,
          "reads " + std::to_string(accessor.count) + " x " + std::to_string(accessor.stride) +
            " values from '" + accessor.source + "', which holds " + std::to_string(array->second));
    }
    return true;
  }

  bool visit_primitive(const tinyxml2::XMLElement* element, const std::string& name)
  {
    std::uint64_t count = 0;
    if (!attribute_count(element, "count", kRequired, &count))
      return fail(element, "has no count, or one that is not a number");
    std::uint64_t stride = 1; // indices per vertex: the largest input offset + 1
    for (const auto* input = element->FirstChildElement("input"); input;
         input = input->NextSiblingElement("input"))
    {
      std::uint64_t offset = 0;
      if (!attribute_count(input, "offset", 0, &offset) || offset > 1000)
        return fail(input, "has an offset that is not a small number");
      stride = std::max(stride, offset + 1);
    }
    const char* list_name = name == "vertex_weights" ? "v" : "p";
    const bool one_list =
      name == "triangles" || name == "lines" || name == "polylist" || name == "vertex_weights";
    std::uint64_t lists = 0;
    Tokens indices;
    for (const auto* list = element->FirstChildElement(); list; list = list->NextSiblingElement())
    {
      const std::string child = list->Name();
      if (child != list_name && child != "ph")
        continue;
      ++lists;
      const tinyxml2::XMLElement* holder = child == "ph" ? list->FirstChildElement("p") : list;
      const Tokens tokens = scan(holder ? holder->GetText() : nullptr, Numbers::Index);
      if (!tokens.bad.empty())
        return fail(list, "holds '" + tokens.bad + "', which is not an index");
      if (tokens.count % stride != 0)
        return fail(list,
          "holds " + std::to_string(tokens.count) + " indices, not a multiple of the " +
            std::to_string(stride) + " inputs");
      indices.count += tokens.count;
    }
    if (one_list && lists > 1)
      return fail(element, std::string("has more than one <") + list_name + ">");
    long double expected = 0; // indices the count and inputs announce, where they fix it
    if (name == "triangles")
      expected = static_cast<long double>(count) * 3 * stride;
    else if (name == "lines")
      expected = static_cast<long double>(count) * 2 * stride;
    else if (name == "polylist" || name == "vertex_weights")
    {
      const auto* vcount = element->FirstChildElement("vcount");
      const Tokens sizes = scan(vcount ? vcount->GetText() : nullptr, Numbers::Index);
      if (!sizes.bad.empty())
        return fail(vcount, "holds '" + sizes.bad + "', which is not a count");
      if (sizes.count != count)
        return fail(element,
          "announces " + std::to_string(count) + " entries but its <vcount> holds " +
            std::to_string(sizes.count));
      expected = sizes.sum * stride;
    }
    else if (lists != count)
    {
      return fail(element,
        "announces " + std::to_string(count) + " index lists but holds " + std::to_string(lists));
    }
    else
    {
      return true;
    }
    if (static_cast<long double>(indices.count) != expected)
      return fail(element,
        "holds " + std::to_string(indices.count) + " indices where its count and inputs announce " +
          std::to_string(static_cast<unsigned long long>(expected)));
    return true;
  }

  std::map<std::string, std::uint64_t> array_sizes_;
  std::vector<Accessor> accessors_;
};

} // namespace

bool ColladaFileCheck::check(const std::string& path, std::string* error)
{
  tinyxml2::XMLDocument document;
  if (document.LoadFile(path.c_str()) != tinyxml2::XML_SUCCESS || !document.RootElement())
  {
    if (error)
      *error = "Collada file '" + path + "' is not well-formed XML: " +
        (document.ErrorStr() ? std::string(document.ErrorStr()) : std::string("no root element"));
    return false;
  }
  Checker checker;
  if (checker.run(document.RootElement()))
    return true;
  if (error)
    *error = "Collada file '" + path + "' is inconsistent: " + checker.problem;
  return false;
}

} // namespace robot
} // namespace ros2vtk
