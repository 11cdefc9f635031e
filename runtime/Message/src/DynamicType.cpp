// ros2vtk — MessageTypeSupport tables built at run time from type descriptions (DynamicType.hpp):
// validation of the description, layout, the generic create/copy/equal/CDR walk, defaults, the
// slot pool behind the seam's context-free function pointers, and the cache by type hash.
#include "ros2vtk/wire/DynamicType.hpp"

#include "MessageYamlDetail.hpp"
#include "ros2vtk/wire/CdrReader.hpp"
#include "ros2vtk/wire/CdrWriter.hpp"
#include "ros2vtk/wire/Utf8.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <new>
#include <set>
#include <utility>

namespace ros2vtk {
namespace wire {
namespace {

// type_description_interfaces/msg/FieldType ids.
constexpr uint8_t kNestedType = 1;
constexpr uint8_t kBoundedString = 21;
constexpr uint8_t kBoundedWString = 22;
constexpr uint8_t kArrayOffset = 48;
constexpr uint8_t kBoundedSequenceOffset = 96;
constexpr uint8_t kSequenceOffset = 144;

class DynamicType;

/// The element kind of a field: what one element (or the field itself) is in memory.
struct Element
{
  FieldType type = FieldType::UInt8;
  const DynamicType* nested = nullptr;
  size_t size = 1;
  size_t align = 1;
  uint32_t string_bound = 0;
};

/// Every array and sequence of a dynamic message: contiguous elements constructed in place.
struct DynamicContainer
{
  const Element* element;
  bool fixed;
  size_t count;
  unsigned char* data;
};

/// One scalar of a default value.
struct DefaultScalar
{
  int64_t i = 0;
  uint64_t u = 0;
  double d = 0.0;
  bool b = false;
  std::string s;
};

struct Member
{
  std::string name;
  Element element;
  Container container = Container::None;
  uint32_t array_size = 0; ///< N of T[N] or bound of T[<=N]
  size_t offset = 0;
  bool has_default = false;
  std::vector<DefaultScalar> defaults; ///< one for a scalar, the list for containers
};

size_t align_up(size_t offset, size_t alignment)
{
  return (offset + alignment - 1) / alignment * alignment;
}

template<typename T>
T& at(void* p)
{
  return *static_cast<T*>(p);
}

template<typename T>
const T& at(const void* p)
{
  return *static_cast<const T*>(p);
}

/// Calls f(T{}) with the C++ type of a primitive field type (not string / message).
template<typename F>
void with_primitive(FieldType type, F&& f)
{
  switch (type)
  {
    case FieldType::Bool:
      f(bool{});
      break;
    case FieldType::Byte:
    case FieldType::Char:
    case FieldType::UInt8:
      f(uint8_t{});
      break;
    case FieldType::Int8:
      f(int8_t{});
      break;
    case FieldType::Int16:
      f(int16_t{});
      break;
    case FieldType::UInt16:
      f(uint16_t{});
      break;
    case FieldType::Int32:
      f(int32_t{});
      break;
    case FieldType::UInt32:
      f(uint32_t{});
      break;
    case FieldType::Int64:
      f(int64_t{});
      break;
    case FieldType::UInt64:
      f(uint64_t{});
      break;
    case FieldType::Float32:
      f(float{});
      break;
    case FieldType::Float64:
      f(double{});
      break;
    case FieldType::String:
    case FieldType::WString:
    case FieldType::Message:
      break;
  }
}

bool is_primitive(FieldType type)
{
  return type != FieldType::String && type != FieldType::WString && type != FieldType::Message;
}

class DynamicType
{
public:
  std::string name;
  std::string dds_name;
  std::string hash;
  std::vector<Member> members;
  std::vector<FieldInfo> fields;
  std::vector<DescriptionConstant> constant_texts; // what `constants` points into
  std::vector<ConstantInfo> constants;
  size_t struct_size = 0;
  size_t align = alignof(void*);
  size_t min_serialized_size = 0; ///< lower bound of one serialized element (read_length)
  uint64_t default_elements = 0;  ///< elements a default-constructed message holds
  size_t slot = 0;
  MessageTypeSupport table{};
  // The description served on ~/get_type_description for this type (TypeDescriptionTable).
  std::vector<IndividualDescription> described;
  std::vector<std::vector<TypeDescriptionField>> described_fields;
  std::vector<IndividualTypeDescriptionTable> described_tables;
  TypeDescriptionTable description_table{};

  void construct(void* message) const;
  void destroy(void* message) const;
  void copy(const void* from, void* to) const;
  bool equal(const void* a, const void* b) const;
  size_t body_size(const void* message, size_t offset) const;
  void serialize(const void* message, CdrWriter& writer) const;
  bool deserialize(void* message, CdrReader& reader) const;
};

const DynamicType* type_of(const void* message)
{
  return at<const DynamicType*>(message);
}

// --- one element ---------------------------------------------------------------------------

void construct_element(const Element& e, void* p)
{
  switch (e.type)
  {
    case FieldType::Message:
      e.nested->construct(p);
      break;
    case FieldType::String:
      new (p) std::string();
      break;
    case FieldType::WString:
      new (p) std::u16string();
      break;
    default:
      std::memset(p, 0, e.size);
      break;
  }
}

void destroy_element(const Element& e, void* p)
{
  using std::string;
  using std::u16string;
  switch (e.type)
  {
    case FieldType::Message:
      e.nested->destroy(p);
      break;
    case FieldType::String:
      static_cast<string*>(p)->~string();
      break;
    case FieldType::WString:
      static_cast<u16string*>(p)->~u16string();
      break;
    default:
      break;
  }
}

void copy_element(const Element& e, const void* from, void* to)
{
  switch (e.type)
  {
    case FieldType::Message:
      e.nested->copy(from, to);
      break;
    case FieldType::String:
      at<std::string>(to) = at<std::string>(from);
      break;
    case FieldType::WString:
      at<std::u16string>(to) = at<std::u16string>(from);
      break;
    default:
      std::memcpy(to, from, e.size);
      break;
  }
}

bool equal_element(const Element& e, const void* a, const void* b)
{
  switch (e.type)
  {
    case FieldType::Message:
      return e.nested->equal(a, b);
    case FieldType::String:
      return at<std::string>(a) == at<std::string>(b);
    case FieldType::WString:
      return at<std::u16string>(a) == at<std::u16string>(b);
    default:
      break;
  }
  bool same = false;
  with_primitive(e.type, [&](auto tag) {
    using T = decltype(tag);
    same = at<T>(a) == at<T>(b);
  });
  return same;
}

size_t element_size(const Element& e, const void* p, size_t offset)
{
  switch (e.type)
  {
    case FieldType::Message:
      return e.nested->body_size(p, offset);
    case FieldType::String:
    {
      const size_t length = at<std::string>(p).size();
      return align_up(offset, 4) + 4 +
        (e.string_bound ? std::min<size_t>(length, e.string_bound) : length) + 1;
    }
    case FieldType::WString:
    {
      const size_t length = at<std::u16string>(p).size();
      return align_up(offset, 4) + 4 +
        4 * (e.string_bound ? std::min<size_t>(length, e.string_bound) : length);
    }
    default:
      return align_up(offset, e.size) + e.size;
  }
}

void serialize_element(const Element& e, const void* p, CdrWriter& writer)
{
  switch (e.type)
  {
    case FieldType::Message:
      e.nested->serialize(p, writer);
      return;
    case FieldType::String:
    {
      const std::string& s = at<std::string>(p);
      writer.write_string(
        e.string_bound && s.size() > e.string_bound ? s.substr(0, e.string_bound) : s);
      return;
    }
    case FieldType::WString:
    {
      const std::u16string& s = at<std::u16string>(p);
      writer.write_wstring(
        e.string_bound && s.size() > e.string_bound ? s.substr(0, e.string_bound) : s);
      return;
    }
    default:
      break;
  }
  with_primitive(e.type, [&](auto tag) {
    using T = decltype(tag);
    writer.write(at<T>(p));
  });
}

bool deserialize_element(const Element& e, void* p, CdrReader& reader)
{
  switch (e.type)
  {
    case FieldType::Message:
      return e.nested->deserialize(p, reader);
    case FieldType::String:
      return reader.read_string(at<std::string>(p), e.string_bound);
    case FieldType::WString:
      return reader.read_wstring(at<std::u16string>(p), e.string_bound);
    default:
      break;
  }
  bool ok = false;
  with_primitive(e.type, [&](auto tag) {
    using T = decltype(tag);
    ok = reader.read(at<T>(p));
  });
  return ok;
}

// --- containers ----------------------------------------------------------------------------

void container_reallocate(DynamicContainer& c, size_t count)
{
  const Element& e = *c.element;
  unsigned char* data =
    count ? static_cast<unsigned char*>(::operator new(count* e.size)) : nullptr;
  const size_t kept = std::min(count, c.count);
  if (is_primitive(e.type))
  {
    // Plain bytes: one copy and one fill, not a call per element (a 1.6 MB PointCloud2 `data`
    // took 100x the generated decode element by element; see the decode benchmark).
    if (kept)
      std::memcpy(data, c.data, kept * e.size);
    if (count > kept)
      std::memset(data + kept * e.size, 0, (count - kept) * e.size);
    ::operator delete(c.data);
    c.data = data;
    c.count = count;
    return;
  }
  for (size_t i = 0; i < count; ++i)
  {
    construct_element(e, data + i * e.size);
  }
  for (size_t i = 0; i < c.count; ++i)
  {
    if (i < kept)
    {
      if (e.type == FieldType::String)
        at<std::string>(data + i * e.size).swap(at<std::string>(c.data + i * e.size));
      else if (e.type == FieldType::WString)
        at<std::u16string>(data + i * e.size).swap(at<std::u16string>(c.data + i * e.size));
      else
        copy_element(e, c.data + i * e.size, data + i * e.size);
    }
    destroy_element(e, c.data + i * e.size);
  }
  ::operator delete(c.data);
  c.data = data;
  c.count = count;
}

size_t container_size(const void* field)
{
  return at<DynamicContainer>(field).count;
}

void* container_element(void* field, size_t index)
{
  DynamicContainer& c = at<DynamicContainer>(field);
  return c.data + index * c.element->size;
}

bool container_resize(void* field, size_t count)
{
  DynamicContainer& c = at<DynamicContainer>(field);
  if (c.fixed)
  {
    return count == c.count;
  }
  if (count != c.count)
  {
    container_reallocate(c, count);
  }
  return true;
}

bool container_get_bool(const void* field, size_t index)
{
  const DynamicContainer& c = at<DynamicContainer>(field);
  return at<bool>(c.data + index);
}

void container_set_bool(void* field, size_t index, bool value)
{
  DynamicContainer& c = at<DynamicContainer>(field);
  at<bool>(c.data + index) = value;
}

// --- defaults ------------------------------------------------------------------------------

void apply_scalar_default(const Element& e, const DefaultScalar& value, void* p)
{
  switch (e.type)
  {
    case FieldType::String:
      at<std::string>(p) = value.s;
      return;
    case FieldType::WString:
      at<std::u16string>(p) = yaml_detail::utf32_to_utf16(yaml_detail::decode_utf8(value.s));
      return;
    case FieldType::Message:
      return;
    default:
      break;
  }
  with_primitive(e.type, [&](auto tag) {
    using T = decltype(tag);
    if constexpr (std::is_same<T, bool>::value)
      at<T>(p) = value.b;
    else if constexpr (std::is_floating_point<T>::value)
      at<T>(p) = static_cast<T>(value.d);
    else if constexpr (std::is_signed<T>::value)
      at<T>(p) = static_cast<T>(value.i);
    else
      at<T>(p) = static_cast<T>(value.u);
  });
}

// --- the message walk ----------------------------------------------------------------------

void DynamicType::construct(void* message) const
{
  at<const DynamicType*>(message) = this;
  unsigned char* base = static_cast<unsigned char*>(message);
  for (const Member& m : members)
  {
    void* p = base + m.offset;
    if (m.container == Container::None)
    {
      construct_element(m.element, p);
      if (m.has_default)
        apply_scalar_default(m.element, m.defaults[0], p);
      continue;
    }
    DynamicContainer& c =
      *new (p) DynamicContainer{ &m.element, m.container == Container::Array, 0, nullptr };
    const size_t count =
      m.container == Container::Array ? m.array_size : (m.has_default ? m.defaults.size() : 0);
    if (count)
      container_reallocate(c, count);
    if (m.has_default)
    {
      for (size_t i = 0; i < m.defaults.size() && i < c.count; ++i)
        apply_scalar_default(m.element, m.defaults[i], c.data + i * m.element.size);
    }
  }
}

void DynamicType::destroy(void* message) const
{
  unsigned char* base = static_cast<unsigned char*>(message);
  for (const Member& m : members)
  {
    void* p = base + m.offset;
    if (m.container == Container::None)
    {
      destroy_element(m.element, p);
      continue;
    }
    DynamicContainer& c = at<DynamicContainer>(p);
    for (size_t i = 0; i < c.count; ++i)
      destroy_element(m.element, c.data + i * m.element.size);
    ::operator delete(c.data);
    c.data = nullptr;
    c.count = 0;
  }
}

void DynamicType::copy(const void* from, void* to) const
{
  if (from == to)
    return;
  const unsigned char* a = static_cast<const unsigned char*>(from);
  unsigned char* b = static_cast<unsigned char*>(to);
  for (const Member& m : members)
  {
    if (m.container == Container::None)
    {
      copy_element(m.element, a + m.offset, b + m.offset);
      continue;
    }
    const DynamicContainer& source = at<DynamicContainer>(a + m.offset);
    DynamicContainer& target = at<DynamicContainer>(b + m.offset);
    if (target.count != source.count)
      container_reallocate(target, source.count);
    for (size_t i = 0; i < source.count; ++i)
      copy_element(m.element, source.data + i * m.element.size, target.data + i * m.element.size);
  }
}

bool DynamicType::equal(const void* x, const void* y) const
{
  const unsigned char* a = static_cast<const unsigned char*>(x);
  const unsigned char* b = static_cast<const unsigned char*>(y);
  for (const Member& m : members)
  {
    if (m.container == Container::None)
    {
      if (!equal_element(m.element, a + m.offset, b + m.offset))
        return false;
      continue;
    }
    const DynamicContainer& ca = at<DynamicContainer>(a + m.offset);
    const DynamicContainer& cb = at<DynamicContainer>(b + m.offset);
    if (ca.count != cb.count)
      return false;
    for (size_t i = 0; i < ca.count; ++i)
    {
      if (!equal_element(m.element, ca.data + i * m.element.size, cb.data + i * m.element.size))
        return false;
    }
  }
  return true;
}

size_t DynamicType::body_size(const void* message, size_t offset) const
{
  const unsigned char* base = static_cast<const unsigned char*>(message);
  for (const Member& m : members)
  {
    const void* p = base + m.offset;
    if (m.container == Container::None)
    {
      offset = element_size(m.element, p, offset);
      continue;
    }
    const DynamicContainer& c = at<DynamicContainer>(p);
    size_t count = c.count;
    if (m.container != Container::Array)
    {
      offset = align_up(offset, 4) + 4;
      if (m.container == Container::BoundedSequence)
        count = std::min<size_t>(count, m.array_size);
    }
    if (count == 0)
      continue;
    if (is_primitive(m.element.type))
    {
      offset = align_up(offset, m.element.size) + count * m.element.size;
      continue;
    }
    for (size_t i = 0; i < count; ++i)
      offset = element_size(m.element, c.data + i * m.element.size, offset);
  }
  return offset;
}

void DynamicType::serialize(const void* message, CdrWriter& writer) const
{
  const unsigned char* base = static_cast<const unsigned char*>(message);
  for (const Member& m : members)
  {
    const void* p = base + m.offset;
    if (m.container == Container::None)
    {
      serialize_element(m.element, p, writer);
      continue;
    }
    const DynamicContainer& c = at<DynamicContainer>(p);
    size_t count = c.count;
    if (m.container == Container::BoundedSequence)
      count = std::min<size_t>(count, m.array_size);
    if (m.container != Container::Array)
      writer.write_length(count);
    if (is_primitive(m.element.type) && m.element.type != FieldType::Bool)
    {
      with_primitive(m.element.type, [&](auto tag) {
        using T = decltype(tag);
        if constexpr (!std::is_same<T, bool>::value)
          writer.write_array(reinterpret_cast<const T*>(c.data), count);
      });
      continue;
    }
    for (size_t i = 0; i < count; ++i)
      serialize_element(m.element, c.data + i * m.element.size, writer);
  }
}

bool DynamicType::deserialize(void* message, CdrReader& reader) const
{
  unsigned char* base = static_cast<unsigned char*>(message);
  for (const Member& m : members)
  {
    void* p = base + m.offset;
    if (m.container == Container::None)
    {
      if (!deserialize_element(m.element, p, reader))
        return false;
      continue;
    }
    DynamicContainer& c = at<DynamicContainer>(p);
    if (m.container != Container::Array)
    {
      uint32_t count = 0;
      size_t minimum = 4; // a string's or wstring's length
      if (m.element.type == FieldType::Message)
        minimum = m.element.nested->min_serialized_size;
      else if (is_primitive(m.element.type))
        minimum = m.element.size;
      if (!reader.read_length(
            count, minimum, m.container == Container::BoundedSequence ? m.array_size : 0))
        return false;
      if (count != c.count)
        container_reallocate(c, count);
    }
    if (is_primitive(m.element.type) && m.element.type != FieldType::Bool)
    {
      bool ok = false;
      with_primitive(m.element.type, [&](auto tag) {
        using T = decltype(tag);
        if constexpr (!std::is_same<T, bool>::value)
          ok = reader.read_array(reinterpret_cast<T*>(c.data), c.count);
      });
      if (!ok)
        return false;
      continue;
    }
    for (size_t i = 0; i < c.count; ++i)
    {
      if (!deserialize_element(m.element, c.data + i * m.element.size, reader))
        return false;
    }
  }
  return true;
}

// --- the seam's function pointers ----------------------------------------------------------

std::array<std::atomic<const DynamicType*>, kMaxDynamicTypes> g_slots{};

template<size_t I>
void* slot_create()
{
  const DynamicType* type = g_slots[I].load(std::memory_order_acquire);
  void* message = ::operator new(type->struct_size);
  type->construct(message);
  return message;
}

template<size_t I>
const MessageTypeSupport* slot_nested()
{
  return &g_slots[I].load(std::memory_order_acquire)->table;
}

using CreateFunction = void* (*)();
using NestedFunction = const MessageTypeSupport* (*)();

template<size_t... I>
constexpr std::array<CreateFunction, sizeof...(I)> make_creates(std::index_sequence<I...>)
{
  return { { &slot_create<I>... } };
}

template<size_t... I>
constexpr std::array<NestedFunction, sizeof...(I)> make_nesteds(std::index_sequence<I...>)
{
  return { { &slot_nested<I>... } };
}

const std::array<CreateFunction, kMaxDynamicTypes> kCreate =
  make_creates(std::make_index_sequence<kMaxDynamicTypes>());
const std::array<NestedFunction, kMaxDynamicTypes> kNested =
  make_nesteds(std::make_index_sequence<kMaxDynamicTypes>());

void table_destroy(void* message)
{
  if (!message)
    return;
  type_of(message)->destroy(message);
  ::operator delete(message);
}

void table_copy(const void* from, void* to)
{
  type_of(from)->copy(from, to);
}

bool table_equal(const void* a, const void* b)
{
  return type_of(a) == type_of(b) && type_of(a)->equal(a, b);
}

size_t table_serialized_size(const void* message)
{
  return 4 + type_of(message)->body_size(message, 0);
}

void table_serialize(const void* message, CdrWriter& writer)
{
  type_of(message)->serialize(message, writer);
}

bool table_deserialize(void* message, CdrReader& reader)
{
  return type_of(message)->deserialize(message, reader);
}

// --- validation and building ---------------------------------------------------------------

struct DynamicRegistry
{
  std::mutex mutex;
  std::map<std::string, std::unique_ptr<DynamicType>> by_hash; // lower-case hash
  std::set<const MessageTypeSupport*> tables;
  size_t used_slots = 0;
};

DynamicRegistry& dynamic_registry()
{
  static DynamicRegistry instance;
  return instance;
}

std::string lower(std::string text)
{
  for (char& c : text)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::string quoted(const std::string& text)
{
  return "'" + clip_for_message(text, 120) + "'";
}

bool is_identifier(const std::string& text, size_t max_length)
{
  if (text.empty() || text.size() > max_length ||
    !std::isalpha(static_cast<unsigned char>(text[0])))
    return false;
  for (char c : text)
  {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_')
      return false;
  }
  return true;
}

/// "pkg/msg/Type" (at least two parts, each an identifier).
bool is_type_name(const std::string& text, size_t max_length)
{
  if (text.empty() || text.size() > max_length)
    return false;
  size_t parts = 0;
  size_t start = 0;
  while (true)
  {
    const size_t slash = text.find('/', start);
    const std::string part =
      text.substr(start, slash == std::string::npos ? std::string::npos : slash - start);
    if (!is_identifier(part, max_length))
      return false;
    ++parts;
    if (slash == std::string::npos)
      break;
    start = slash + 1;
  }
  return parts >= 2;
}

/// rosidl's DDS name: "pkg/msg/Type" -> "pkg::msg::dds_::Type_".
std::string dds_type_name(const std::string& ros_type)
{
  const size_t last = ros_type.rfind('/');
  std::string prefix = ros_type.substr(0, last);
  std::string result;
  for (char c : prefix)
  {
    if (c == '/')
      result += "::";
    else
      result += c;
  }
  return result + "::dds_::" + ros_type.substr(last + 1) + "_";
}

bool primitive_of(uint8_t base, FieldType* type, size_t* size)
{
  switch (base)
  {
    case 2:
      *type = FieldType::Int8;
      *size = 1;
      return true;
    case 3:
      *type = FieldType::UInt8;
      *size = 1;
      return true;
    case 4:
      *type = FieldType::Int16;
      *size = 2;
      return true;
    case 5:
      *type = FieldType::UInt16;
      *size = 2;
      return true;
    case 6:
      *type = FieldType::Int32;
      *size = 4;
      return true;
    case 7:
      *type = FieldType::UInt32;
      *size = 4;
      return true;
    case 8:
      *type = FieldType::Int64;
      *size = 8;
      return true;
    case 9:
      *type = FieldType::UInt64;
      *size = 8;
      return true;
    case 10:
      *type = FieldType::Float32;
      *size = 4;
      return true;
    case 11:
      *type = FieldType::Float64;
      *size = 8;
      return true;
    case 13:
      *type = FieldType::Char;
      *size = 1;
      return true; // IDL char: one byte
    case 15:
      *type = FieldType::Bool;
      *size = 1;
      return true;
    case 16:
      *type = FieldType::Byte;
      *size = 1;
      return true;
    default:
      return false;
  }
}

std::string trim(const std::string& text)
{
  size_t begin = 0, end = text.size();
  while (begin < end && std::isspace(static_cast<unsigned char>(text[begin])))
    ++begin;
  while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1])))
    --end;
  return text.substr(begin, end - begin);
}

/// One scalar default as rosidl writes it (Python's str() of the value).
bool parse_scalar(FieldType type, const std::string& text, DefaultScalar& out)
{
  const std::string t = trim(text);
  switch (type)
  {
    case FieldType::String:
    case FieldType::WString:
      out.s = text;
      return true;
    case FieldType::Bool:
      if (t == "True" || t == "true" || t == "1")
        out.b = true;
      else if (t == "False" || t == "false" || t == "0")
        out.b = false;
      else
        return false;
      return true;
    case FieldType::Float32:
    case FieldType::Float64:
    {
      if (t.empty())
        return false;
      char* end = nullptr;
      out.d = std::strtod(t.c_str(), &end);
      return end == t.c_str() + t.size();
    }
    case FieldType::Message:
      return false;
    default:
      break;
  }
  bool ok = false;
  with_primitive(type, [&](auto tag) {
    using T = decltype(tag);
    if constexpr (std::is_integral<T>::value && !std::is_same<T, bool>::value)
    {
      const char* first = t.data();
      const char* last = t.data() + t.size();
      if (std::is_signed<T>::value)
      {
        int64_t value = 0;
        const auto result = std::from_chars(first, last, value);
        ok = result.ec == std::errc() && result.ptr == last &&
          value >= static_cast<int64_t>(std::numeric_limits<T>::min()) &&
          value <= static_cast<int64_t>(std::numeric_limits<T>::max());
        out.i = value;
      }
      else
      {
        uint64_t value = 0;
        const auto result = std::from_chars(first, last, value);
        ok = result.ec == std::errc() && result.ptr == last &&
          value <= static_cast<uint64_t>(std::numeric_limits<T>::max());
        out.u = value;
      }
    }
  });
  return ok;
}

/// Python's repr of a str: '...' or "..." with backslash escapes. `i` at the quote.
bool parse_python_string(const std::string& text, size_t& i, std::string& out)
{
  const char quote = text[i++];
  while (i < text.size() && text[i] != quote)
  {
    char c = text[i++];
    if (c != '\\')
    {
      out += c;
      continue;
    }
    if (i >= text.size())
      return false;
    c = text[i++];
    switch (c)
    {
      case 'n':
        out += '\n';
        break;
      case 't':
        out += '\t';
        break;
      case 'r':
        out += '\r';
        break;
      case '\\':
        out += '\\';
        break;
      case '\'':
        out += '\'';
        break;
      case '"':
        out += '"';
        break;
      case 'x':
      {
        if (i + 2 > text.size())
          return false;
        unsigned value = 0;
        const auto result = std::from_chars(text.data() + i, text.data() + i + 2, value, 16);
        if (result.ptr != text.data() + i + 2)
          return false;
        out += static_cast<char>(value);
        i += 2;
        break;
      }
      default:
        return false;
    }
  }
  if (i >= text.size())
    return false;
  ++i;
  return true;
}

/// A container default: "[1, 2, 3]", "['a', 'b']" (Python's str() of a list; rclpy serves
/// tuples: "(False, True, False)", "(1,)").
bool parse_list(
  FieldType type, const std::string& text, std::vector<DefaultScalar>& out, uint64_t max_elements)
{
  const std::string t = trim(text);
  const bool list = t.size() >= 2 && t.front() == '[' && t.back() == ']';
  const bool tuple = t.size() >= 2 && t.front() == '(' && t.back() == ')';
  if (!list && !tuple)
    return false;
  const std::string body = t.substr(1, t.size() - 2);
  size_t i = 0;
  while (true)
  {
    while (i < body.size() && std::isspace(static_cast<unsigned char>(body[i])))
      ++i;
    if (i >= body.size())
      break;
    if (out.size() >= max_elements)
      return false;
    DefaultScalar value;
    if (type == FieldType::String || type == FieldType::WString)
    {
      if (body[i] != '\'' && body[i] != '"')
        return false;
      if (!parse_python_string(body, i, value.s))
        return false;
    }
    else
    {
      const size_t comma = body.find(',', i);
      const std::string item =
        body.substr(i, comma == std::string::npos ? std::string::npos : comma - i);
      if (!parse_scalar(type, item, value))
        return false;
      i = comma == std::string::npos ? body.size() : comma;
    }
    out.push_back(std::move(value));
    while (i < body.size() && std::isspace(static_cast<unsigned char>(body[i])))
      ++i;
    if (i >= body.size())
      break;
    if (body[i] != ',')
      return false;
    ++i;
  }
  return true;
}

struct Builder
{
  const TypeDescriptionData& description;
  const DynamicTypeLimits& limits;
  std::string* error;
  std::map<std::string, const IndividualDescription*> by_name;
  std::map<std::string, int> state; // 1 visiting, 2 done
  std::map<std::string, size_t> depth;
  std::vector<std::string> order; // referenced first (post-order)

  bool fail(const std::string& reason)
  {
    if (error)
      *error = "type description of " + quoted(description.type.type_name) + " refused: " + reason;
    return false;
  }

  bool check_fields(const IndividualDescription& type)
  {
    if (type.fields.empty())
      return fail(
        "type " + quoted(type.type_name) + " has no fields (rosidl gives empty types one)");
    if (type.fields.size() > limits.max_fields)
      return fail("type " + quoted(type.type_name) + " has " + std::to_string(type.fields.size()) +
        " fields (limit " + std::to_string(limits.max_fields) + ")");
    std::set<std::string> names;
    for (const DescriptionField& field : type.fields)
    {
      const std::string where = "field " + quoted(field.name) + " of " + quoted(type.type_name);
      if (!is_identifier(field.name, limits.max_name_length))
        return fail(where + ": not a valid field name");
      if (!names.insert(field.name).second)
        return fail(where + ": declared twice");
      const uint8_t id = field.type_id;
      uint8_t base = id;
      Container container = Container::None;
      if (id > kSequenceOffset)
      {
        base = id - kSequenceOffset;
        container = Container::Sequence;
      }
      else if (id > kBoundedSequenceOffset)
      {
        base = id - kBoundedSequenceOffset;
        container = Container::BoundedSequence;
      }
      else if (id > kArrayOffset)
      {
        base = id - kArrayOffset;
        container = Container::Array;
      }
      FieldType element = FieldType::UInt8;
      size_t size = 0;
      const bool known = base == kNestedType || base == 17 || base == 18 ||
        base == kBoundedString || base == kBoundedWString || primitive_of(base, &element, &size);
      if (!known || base > kBoundedWString)
        return fail(where + ": unknown or unsupported type id " + std::to_string(id) +
          " (long double, wchar and fixed strings are not ROS 2 .msg types)");
      if (container == Container::Array || container == Container::BoundedSequence)
      {
        if (field.capacity == 0)
          return fail(where + ": an array or bounded sequence with capacity 0");
        if (container == Container::Array && field.capacity > limits.max_array_size)
          return fail(where + ": array size " + std::to_string(field.capacity) +
            " exceeds the limit " + std::to_string(limits.max_array_size));
        if (field.capacity > std::numeric_limits<uint32_t>::max())
          return fail(
            where + ": capacity " + std::to_string(field.capacity) + " does not fit a CDR length");
      }
      else if (field.capacity != 0)
        return fail(where + ": capacity " + std::to_string(field.capacity) +
          " on a field that is no array or bounded sequence");
      const bool bounded_string = base == kBoundedString || base == kBoundedWString;
      if (bounded_string &&
        (field.string_capacity == 0 ||
          field.string_capacity >= std::numeric_limits<uint32_t>::max()))
        return fail(
          where + ": bounded string with capacity " + std::to_string(field.string_capacity));
      if (!bounded_string && field.string_capacity != 0)
        return fail(where + ": string capacity on a field that is no bounded string");
      if (base == kNestedType)
      {
        if (by_name.find(field.nested_type_name) == by_name.end())
          return fail(where + ": its type " + quoted(field.nested_type_name) +
            " is missing from the referenced types");
      }
      else if (!field.nested_type_name.empty())
        return fail(where + ": a nested type name on a field that is not nested");
      if (field.default_value.size() > limits.max_default_value_length)
        return fail(where + ": default value longer than " +
          std::to_string(limits.max_default_value_length) + " bytes");
      // Defaults are checked here, not only when the type is built: the hash leaves them out,
      // so a cached type of the same hash would otherwise let a malformed one through.
      if (!field.default_value.empty() && base != kNestedType)
      {
        if (base == 17 || base == kBoundedString)
          element = FieldType::String;
        else if (base == 18 || base == kBoundedWString)
          element = FieldType::WString;
        DefaultScalar scalar;
        std::vector<DefaultScalar> values;
        const uint64_t room =
          container == Container::Sequence ? limits.max_default_elements : field.capacity;
        const bool ok = container == Container::None
          ? parse_scalar(element, field.default_value, scalar)
          : parse_list(element, field.default_value, values, room);
        if (!ok)
          return fail(where + ": default value " + quoted(field.default_value) +
            " does not read as " + field_type_name(element) +
            (container == Container::None ? "" : " list"));
      }
    }
    return true;
  }

  bool visit(const std::string& name, size_t level, std::vector<std::string>& path)
  {
    if (level > limits.max_depth)
      return fail("nesting deeper than " + std::to_string(limits.max_depth) + " levels (" +
        quoted(name) + ")");
    int& s = state[name];
    if (s == 1)
    {
      std::string cycle;
      for (const std::string& step : path)
        cycle += step + " -> ";
      return fail(
        "the types refer to each other in a cycle: " + clip_for_message(cycle + name, 400));
    }
    if (s == 2)
      return true;
    s = 1;
    path.push_back(name);
    const IndividualDescription& type = *by_name[name];
    if (!check_fields(type))
      return false;
    for (const DescriptionField& field : type.fields)
    {
      if (field.type_id % kArrayOffset == kNestedType &&
        !visit(field.nested_type_name, level + 1, path))
        return false;
    }
    path.pop_back();
    state[name] = 2;
    order.push_back(name);
    return true;
  }

  /// The description of one type of the closure: itself and what it references.
  TypeDescriptionData closure(const std::string& name)
  {
    TypeDescriptionData result;
    result.type = *by_name[name];
    std::set<std::string> seen;
    std::vector<std::string> pending{ name };
    while (!pending.empty())
    {
      const std::string current = pending.back();
      pending.pop_back();
      for (const DescriptionField& field : by_name[current]->fields)
      {
        if (field.type_id % kArrayOffset == kNestedType &&
          seen.insert(field.nested_type_name).second)
          pending.push_back(field.nested_type_name);
      }
    }
    for (const std::string& referenced : seen)
      result.referenced.push_back(*by_name[referenced]);
    return result;
  }
};

void fill_description_table(DynamicType& type, const TypeDescriptionData& closure)
{
  type.described.push_back(closure.type);
  for (const IndividualDescription& referenced : closure.referenced)
    type.described.push_back(referenced);
  std::sort(type.described.begin() + 1, type.described.end(),
    [](const IndividualDescription& a, const IndividualDescription& b) {
      return a.type_name < b.type_name;
    });
  for (const IndividualDescription& individual : type.described)
  {
    std::vector<TypeDescriptionField> fields;
    for (const DescriptionField& f : individual.fields)
    {
      fields.push_back({ f.name.c_str(), f.type_id, f.capacity, f.string_capacity,
        f.nested_type_name.c_str(), f.default_value.c_str() });
    }
    type.described_fields.push_back(std::move(fields));
  }
  for (size_t i = 0; i < type.described.size(); ++i)
  {
    const IndividualDescription& individual = type.described[i];
    const char* encoding =
      individual.source_encoding.empty() ? "dynamic" : individual.source_encoding.c_str();
    type.described_tables.push_back({ individual.type_name.c_str(),
      static_cast<uint32_t>(type.described_fields[i].size()), type.described_fields[i].data(),
      { encoding, individual.source_contents.c_str(), nullptr } });
  }
  type.description_table.type = type.described_tables[0];
  type.description_table.referenced_count = static_cast<uint32_t>(type.described_tables.size() - 1);
  type.description_table.referenced = type.described_tables.data() + 1;
}

/// Builds one type whose referenced types are built already (`built`). Registry locked.
std::unique_ptr<DynamicType> build_one(Builder& builder, const std::string& name,
  const std::string& hash, const std::map<std::string, const DynamicType*>& built, size_t slot)
{
  const IndividualDescription& source = *builder.by_name[name];
  auto type = std::make_unique<DynamicType>();
  type->name = name;
  type->dds_name = dds_type_name(name);
  type->hash = hash;
  type->slot = slot;
  size_t offset = sizeof(void*); // the hidden type pointer
  uint64_t default_elements = 0;
  type->members.reserve(source.fields.size());
  for (const DescriptionField& field : source.fields)
  {
    const std::string where = "field " + quoted(field.name) + " of " + quoted(name);
    Member m;
    m.name = field.name;
    uint8_t base = field.type_id;
    if (field.type_id > kSequenceOffset)
    {
      base = field.type_id - kSequenceOffset;
      m.container = Container::Sequence;
    }
    else if (field.type_id > kBoundedSequenceOffset)
    {
      base = field.type_id - kBoundedSequenceOffset;
      m.container = Container::BoundedSequence;
    }
    else if (field.type_id > kArrayOffset)
    {
      base = field.type_id - kArrayOffset;
      m.container = Container::Array;
    }
    m.array_size = static_cast<uint32_t>(field.capacity);
    Element& e = m.element;
    uint64_t elements_per_item = 1;
    if (base == kNestedType)
    {
      e.type = FieldType::Message;
      e.nested = built.at(field.nested_type_name);
      e.size = e.nested->struct_size;
      e.align = e.nested->align;
      elements_per_item = e.nested->default_elements + 1;
    }
    else if (base == 17 || base == kBoundedString)
    {
      e.type = FieldType::String;
      e.size = sizeof(std::string);
      e.align = alignof(std::string);
    }
    else if (base == 18 || base == kBoundedWString)
    {
      e.type = FieldType::WString;
      e.size = sizeof(std::u16string);
      e.align = alignof(std::u16string);
    }
    else
    {
      primitive_of(base, &e.type, &e.size);
      e.align = e.size;
    }
    e.string_bound = static_cast<uint32_t>(field.string_capacity);
    // Defaults (rosidl's text); messages have none.
    if (!field.default_value.empty() && e.type != FieldType::Message)
    {
      m.has_default = true;
      bool ok;
      if (m.container == Container::None)
      {
        m.defaults.resize(1);
        ok = parse_scalar(e.type, field.default_value, m.defaults[0]);
      }
      else
      {
        const uint64_t room =
          m.container == Container::Sequence ? builder.limits.max_default_elements : m.array_size;
        ok = parse_list(e.type, field.default_value, m.defaults, room);
      }
      if (!ok)
      {
        builder.fail(where + ": default value " + quoted(field.default_value) +
          " does not read as " + field_type_name(e.type) +
          (m.container == Container::None ? "" : " list"));
        return nullptr;
      }
    }
    // What one default message holds, to refuse descriptions whose default value alone is huge.
    const uint64_t items = m.container == Container::Array
      ? m.array_size
      : (m.container == Container::None ? 1 : m.defaults.size());
    const uint64_t cost = items > std::numeric_limits<uint64_t>::max() / elements_per_item
      ? std::numeric_limits<uint64_t>::max()
      : items * elements_per_item;
    default_elements = default_elements > std::numeric_limits<uint64_t>::max() - cost
      ? std::numeric_limits<uint64_t>::max()
      : default_elements + cost;
    if (default_elements > builder.limits.max_default_elements)
    {
      builder.fail(where + ": a default " + quoted(name) + " would hold more than " +
        std::to_string(builder.limits.max_default_elements) + " elements");
      return nullptr;
    }
    // Layout.
    const size_t size = m.container == Container::None ? e.size : sizeof(DynamicContainer);
    const size_t align = m.container == Container::None ? e.align : alignof(DynamicContainer);
    offset = align_up(offset, align);
    m.offset = offset;
    offset += size;
    type->align = std::max(type->align, align);
    // Lower bound of the serialized size (alignment only adds), capped so that CdrReader::
    // read_length's count * minimum never overflows (a smaller bound is still a bound).
    uint64_t minimum = 0;
    if (m.container == Container::None)
      minimum = e.type == FieldType::Message ? e.nested->min_serialized_size
                                             : (is_primitive(e.type) ? e.size : 4);
    else if (m.container == Container::Array)
      minimum = static_cast<uint64_t>(m.array_size) *
        (e.type == FieldType::Message ? e.nested->min_serialized_size
                                      : (is_primitive(e.type) ? e.size : 4));
    else
      minimum = 4;
    type->min_serialized_size = static_cast<size_t>(
      std::min<uint64_t>(uint64_t(type->min_serialized_size) + minimum, uint64_t(1) << 24));
    type->members.push_back(std::move(m));
  }
  type->default_elements = default_elements;
  type->struct_size = align_up(offset, type->align);
  // The FieldInfo table (names point into members, which no longer move).
  for (const Member& m : type->members)
  {
    FieldInfo info{};
    info.name = m.name.c_str();
    info.type = m.element.type;
    info.container = m.container;
    info.array_size = m.container == Container::Array || m.container == Container::BoundedSequence
      ? m.array_size
      : 0;
    info.string_bound = m.element.string_bound;
    info.offset = m.offset;
    info.nested = m.element.type == FieldType::Message ? kNested[m.element.nested->slot] : nullptr;
    if (m.container != Container::None)
    {
      info.size = &container_size;
      info.element = &container_element;
      info.resize = &container_resize;
      if (m.element.type == FieldType::Bool)
      {
        info.get_bool = &container_get_bool;
        info.set_bool = &container_set_bool;
      }
    }
    type->fields.push_back(info);
  }
  fill_description_table(*type, builder.closure(name));
  MessageTypeSupport& t = type->table;
  t.ros_type = type->name.c_str();
  t.dds_type_name = type->dds_name.c_str();
  t.type_hash = type->hash.c_str();
  t.struct_size = type->struct_size;
  t.field_count = static_cast<uint32_t>(type->fields.size());
  t.fields = type->fields.data();
  // Descriptions carry no constants; the .msg source the peer sent may (parse_msg_constants).
  type->constant_texts = source.constants;
  for (const DescriptionConstant& c : type->constant_texts)
  {
    type->constants.push_back(ConstantInfo{ c.name.c_str(), c.type, c.value.c_str() });
  }
  t.constant_count = static_cast<uint32_t>(type->constants.size());
  t.constants = type->constants.empty() ? nullptr : type->constants.data();
  t.create = kCreate[slot];
  t.destroy = &table_destroy;
  t.copy = &table_copy;
  t.equal = &table_equal;
  t.serialized_size = &table_serialized_size;
  t.serialize = &table_serialize;
  t.deserialize = &table_deserialize;
  t.description = &type->description_table;
  return type;
}

} // namespace

const MessageTypeSupport* build_dynamic_message_type(const TypeDescriptionData& description,
  const std::string& expected_hash, std::string* error, const DynamicTypeLimits& limits)
{
  Builder builder{ description, limits, error, {}, {}, {}, {} };
  const std::string& main = description.type.type_name;
  if (!is_type_name(main, limits.max_name_length))
  {
    builder.fail("not a ROS type name (pkg/msg/Type)");
    return nullptr;
  }
  if (description.referenced.size() > limits.max_types)
  {
    builder.fail(std::to_string(description.referenced.size()) + " referenced types (limit " +
      std::to_string(limits.max_types) + ")");
    return nullptr;
  }
  builder.by_name[main] = &description.type;
  for (const IndividualDescription& referenced : description.referenced)
  {
    if (!is_type_name(referenced.type_name, limits.max_name_length))
    {
      builder.fail("referenced type " + quoted(referenced.type_name) + " is not a ROS type name");
      return nullptr;
    }
    if (!builder.by_name.emplace(referenced.type_name, &referenced).second)
    {
      builder.fail("type " + quoted(referenced.type_name) + " is described twice");
      return nullptr;
    }
  }
  std::vector<std::string> path;
  if (!builder.visit(main, 0, path))
  {
    return nullptr;
  }
  const std::string hash = type_description_hash(description, error);
  if (hash.empty())
  {
    return nullptr;
  }
  if (!expected_hash.empty() && lower(expected_hash) != lower(hash))
  {
    builder.fail("its hash " + hash + " differs from the hash the publisher announces, " +
      clip_for_message(expected_hash, 80));
    return nullptr;
  }

  DynamicRegistry& r = dynamic_registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  auto cached = r.by_hash.find(hash);
  if (cached != r.by_hash.end())
  {
    return &cached->second->table;
  }
  // Build bottom-up; every type of the closure is looked up by its own hash first.
  std::map<std::string, const DynamicType*> built;
  std::vector<std::unique_ptr<DynamicType>> fresh;
  for (const std::string& name : builder.order)
  {
    const std::string own_hash =
      name == main ? hash : type_description_hash(builder.closure(name), error);
    if (own_hash.empty())
      return nullptr;
    auto existing = r.by_hash.find(own_hash);
    if (existing != r.by_hash.end())
    {
      built[name] = existing->second.get();
      continue;
    }
    if (r.used_slots + fresh.size() >= kMaxDynamicTypes)
    {
      builder.fail(
        "this process holds " + std::to_string(kMaxDynamicTypes) + " runtime types already");
      return nullptr;
    }
    auto type = build_one(builder, name, own_hash, built, r.used_slots + fresh.size());
    if (!type)
      return nullptr;
    built[name] = type.get();
    fresh.push_back(std::move(type));
  }
  for (auto& type : fresh)
  {
    g_slots[type->slot].store(type.get(), std::memory_order_release);
    r.tables.insert(&type->table);
    if (!find_message_type(type->name))
    {
      register_message_type(&type->table);
    }
    r.by_hash[type->hash] = std::move(type);
  }
  r.used_slots += fresh.size();
  return &r.by_hash.at(hash)->table;
}

bool is_dynamic_message_type(const MessageTypeSupport* type)
{
  DynamicRegistry& r = dynamic_registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  return r.tables.count(type) != 0;
}

size_t dynamic_message_type_count()
{
  DynamicRegistry& r = dynamic_registry();
  std::lock_guard<std::mutex> lock(r.mutex);
  return r.by_hash.size();
}

} // namespace wire
} // namespace ros2vtk
