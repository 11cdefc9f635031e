// ros2vtk — vtkROS2Message: typed access to any registered message (see the header). Field
// paths are resolved by MessageFields over the generated introspection tables.
#include "vtkROS2Message.h"

#include "Internal/GenericMessageType.hpp"
#include "Internal/MessageFields.hpp"

#include "ros2vtk/wire/MessageTypeSupport.hpp"
#include "ros2vtk/wire/MessageYaml.hpp"

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkStringArray.h"
#include "vtkTypeInt64Array.h"
#include "vtkTypeUInt64Array.h"
#include "vtkUnsignedCharArray.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

void NoMessage(void*) {}

bool IsIntegerType(const std::string& type)
{
  return type == "byte" || type == "char" || type.rfind("int", 0) == 0 ||
    type.rfind("uint", 0) == 0;
}

bool IsFloatType(const std::string& type)
{
  return type == "float32" || type == "float64";
}

std::string SafePath(const char* path)
{
  return path ? path : "";
}

} // namespace

vtkStandardNewMacro(vtkROS2Message);

//------------------------------------------------------------------------------
vtkROS2Message::vtkROS2Message()
  : Message(nullptr, NoMessage)
{
}

//------------------------------------------------------------------------------
vtkROS2Message::~vtkROS2Message() = default;

//------------------------------------------------------------------------------
bool vtkROS2Message::Fail(const std::string& error)
{
  this->LastError = error;
  vtkErrorMacro(<< error);
  return false;
}

//------------------------------------------------------------------------------
bool vtkROS2Message::Succeed()
{
  this->LastError.clear();
  return true;
}

//------------------------------------------------------------------------------
bool vtkROS2Message::CheckType(const char* what)
{
  if (this->Type)
  {
    return true;
  }
  return this->Fail(std::string(what) + ": the message has no type yet (SetROSType)");
}

//------------------------------------------------------------------------------
void vtkROS2Message::Allocate(const ros2vtk::wire::MessageTypeSupport& type)
{
  this->Type = &type;
  this->Message = std::unique_ptr<void, void (*)(void*)>(type.create(), type.destroy);
}

//------------------------------------------------------------------------------
bool vtkROS2Message::SetROSType(const char* rosType)
{
  std::string error;
  const ros2vtk::wire::MessageTypeSupport* type = ros2vtk::scene::find_generic_type(rosType, error);
  if (!type)
  {
    return this->Fail("SetROSType: " + error);
  }
  this->Allocate(*type);
  this->Modified();
  return this->Succeed();
}

//------------------------------------------------------------------------------
const char* vtkROS2Message::GetROSType() const
{
  return this->Type ? this->Type->ros_type : "";
}

//------------------------------------------------------------------------------
void vtkROS2Message::Reset()
{
  if (this->Type)
  {
    this->Allocate(*this->Type);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkROS2Message::CopyFromRaw(const ros2vtk::wire::MessageTypeSupport& type, const void* message)
{
  if (this->Type != &type)
  {
    this->Allocate(type);
  }
  type.copy(message, this->Message.get());
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkROS2Message::GetNumberOfFields(const char* path)
{
  std::vector<ros2vtk::scene::FieldDescription> fields;
  std::string error;
  if (!this->CheckType("GetNumberOfFields") ||
    !ros2vtk::scene::list_fields(*this->Type, SafePath(path), fields, &error))
  {
    if (!error.empty())
    {
      this->Fail("GetNumberOfFields: " + error);
    }
    return -1;
  }
  this->Succeed();
  return static_cast<int>(fields.size());
}

//------------------------------------------------------------------------------
std::string vtkROS2Message::GetFieldName(const char* path, int index)
{
  std::vector<ros2vtk::scene::FieldDescription> fields;
  std::string error;
  if (!this->CheckType("GetFieldName"))
  {
    return std::string();
  }
  if (!ros2vtk::scene::list_fields(*this->Type, SafePath(path), fields, &error))
  {
    this->Fail("GetFieldName: " + error);
    return std::string();
  }
  if (index < 0 || index >= static_cast<int>(fields.size()))
  {
    this->Fail("GetFieldName: index " + std::to_string(index) + " out of range (" +
      std::to_string(fields.size()) + " fields)");
    return std::string();
  }
  this->Succeed();
  return fields[static_cast<size_t>(index)].name;
}

//------------------------------------------------------------------------------
std::string vtkROS2Message::GetFieldType(const char* path)
{
  ros2vtk::scene::FieldDescription description;
  std::string error;
  if (!this->CheckType("GetFieldType"))
  {
    return std::string();
  }
  if (!ros2vtk::scene::describe_field(*this->Type, SafePath(path), description, &error))
  {
    this->Fail("GetFieldType: " + error);
    return std::string();
  }
  this->Succeed();
  return description.type_name;
}

//------------------------------------------------------------------------------
int vtkROS2Message::GetNumberOfConstants()
{
  if (!this->CheckType("GetNumberOfConstants"))
  {
    return -1;
  }
  this->Succeed();
  return static_cast<int>(this->Type->constant_count);
}

//------------------------------------------------------------------------------
std::string vtkROS2Message::GetConstantName(int index)
{
  if (!this->CheckType("GetConstantName"))
  {
    return std::string();
  }
  if (index < 0 || index >= static_cast<int>(this->Type->constant_count))
  {
    this->Fail("GetConstantName: index " + std::to_string(index) + " out of range (" +
      std::to_string(this->Type->constant_count) + " constants in " + this->Type->ros_type + ")");
    return std::string();
  }
  this->Succeed();
  return this->Type->constants[index].name;
}

//------------------------------------------------------------------------------
std::string vtkROS2Message::GetConstant(const char* name)
{
  if (!this->CheckType("GetConstant"))
  {
    return std::string();
  }
  const std::string wanted = SafePath(name);
  for (uint32_t i = 0; i < this->Type->constant_count; ++i)
  {
    if (wanted == this->Type->constants[i].name)
    {
      this->Succeed();
      return this->Type->constants[i].value;
    }
  }
  this->Fail("GetConstant: " + std::string(this->Type->ros_type) + " has no constant '" + wanted +
    "'" + (this->Type->constant_count ? "" : " (it declares none)"));
  return std::string();
}

//------------------------------------------------------------------------------
bool vtkROS2Message::IsMessageField(const char* path)
{
  ros2vtk::scene::FieldDescription description;
  return this->Type &&
    ros2vtk::scene::describe_field(*this->Type, SafePath(path), description, nullptr) &&
    description.is_message && !description.is_container;
}

//------------------------------------------------------------------------------
bool vtkROS2Message::IsArrayField(const char* path)
{
  ros2vtk::scene::FieldDescription description;
  return this->Type &&
    ros2vtk::scene::describe_field(*this->Type, SafePath(path), description, nullptr) &&
    description.is_container;
}

//------------------------------------------------------------------------------
std::string vtkROS2Message::GetField(const char* path)
{
  std::string value;
  std::string error;
  if (!this->CheckType("GetField"))
  {
    return value;
  }
  if (!ros2vtk::scene::get_field_as_text(
        *this->Type, this->Message.get(), SafePath(path), value, &error))
  {
    this->Fail("GetField: " + error);
    return std::string();
  }
  this->Succeed();
  return value;
}

//------------------------------------------------------------------------------
bool vtkROS2Message::SetField(const char* path, const char* value)
{
  std::string error;
  if (!this->CheckType("SetField"))
  {
    return false;
  }
  if (!ros2vtk::scene::set_field_from_text(
        *this->Type, this->Message.get(), SafePath(path), value ? value : "", &error))
  {
    return this->Fail("SetField: " + error);
  }
  this->Modified();
  return this->Succeed();
}

//------------------------------------------------------------------------------
double vtkROS2Message::GetFieldAsDouble(const char* path)
{
  const std::string text = this->GetField(path);
  if (!this->LastError.empty())
  {
    return 0.0;
  }
  if (text == "true" || text == "false")
  {
    return text == "true" ? 1.0 : 0.0;
  }
  if (text == ".nan")
  {
    return std::nan("");
  }
  if (text == ".inf" || text == "-.inf")
  {
    return text[0] == '-' ? -HUGE_VAL : HUGE_VAL;
  }
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end)
  {
    this->Fail("GetFieldAsDouble: field '" + SafePath(path) + "' is not a number");
    return 0.0;
  }
  return value;
}

//------------------------------------------------------------------------------
bool vtkROS2Message::SetFieldFromDouble(const char* path, double value)
{
  const std::string type = this->GetFieldType(path);
  if (!this->LastError.empty())
  {
    return false;
  }
  if (IsFloatType(type))
  {
    // repr() digits: the text parses back to exactly `value`. strtod does not read YAML's
    // .nan / .inf spellings, so those go in as C spellings.
    const std::string text = std::isnan(value) ? "nan"
      : std::isinf(value)                      ? (value < 0 ? "-inf" : "inf")
                                               : ros2vtk::wire::format_yaml_float(value);
    return this->SetField(path, text.c_str());
  }
  if (IsIntegerType(type))
  {
    if (!std::isfinite(value) || value != std::floor(value))
    {
      return this->Fail("SetFieldFromDouble: field '" + SafePath(path) + "' is " + type +
        " and takes whole numbers only");
    }
    char text[64];
    std::snprintf(text, sizeof(text), "%.0f", value);
    return this->SetField(path, text);
  }
  if (type == "bool")
  {
    return this->SetField(path, value != 0.0 ? "true" : "false");
  }
  return this->Fail(
    "SetFieldFromDouble: field '" + SafePath(path) + "' is " + type + ", not a number");
}

//------------------------------------------------------------------------------
vtkTypeInt64 vtkROS2Message::GetFieldAsInteger(const char* path)
{
  const std::string type = this->GetFieldType(path);
  if (!this->LastError.empty())
  {
    return 0;
  }
  if (!IsIntegerType(type) && type != "bool")
  {
    this->Fail("GetFieldAsInteger: field '" + SafePath(path) + "' is " + type + ", not an integer");
    return 0;
  }
  const std::string text = this->GetField(path);
  if (text == "true" || text == "false")
  {
    return text == "true" ? 1 : 0;
  }
  errno = 0;
  const long long value = std::strtoll(text.c_str(), nullptr, 10);
  if (errno == ERANGE)
  {
    this->Fail("GetFieldAsInteger: the value of '" + SafePath(path) + "' (" + text +
      ") does not fit a signed 64-bit integer; read it with GetField");
    return 0;
  }
  return static_cast<vtkTypeInt64>(value);
}

//------------------------------------------------------------------------------
bool vtkROS2Message::SetFieldFromInteger(const char* path, vtkTypeInt64 value)
{
  return this->SetField(path, std::to_string(static_cast<long long>(value)).c_str());
}

//------------------------------------------------------------------------------
bool vtkROS2Message::GetFieldAsBool(const char* path)
{
  return this->GetField(path) == "true";
}

//------------------------------------------------------------------------------
bool vtkROS2Message::SetFieldFromBool(const char* path, bool value)
{
  return this->SetField(path, value ? "true" : "false");
}

//------------------------------------------------------------------------------
int vtkROS2Message::GetFieldLength(const char* path)
{
  size_t length = 0;
  std::string error;
  if (!this->CheckType("GetFieldLength"))
  {
    return -1;
  }
  if (!ros2vtk::scene::get_field_length(
        *this->Type, this->Message.get(), SafePath(path), length, &error))
  {
    this->Fail("GetFieldLength: " + error);
    return -1;
  }
  this->Succeed();
  return static_cast<int>(length);
}

//------------------------------------------------------------------------------
bool vtkROS2Message::SetFieldLength(const char* path, int length)
{
  std::string error;
  if (!this->CheckType("SetFieldLength"))
  {
    return false;
  }
  if (length < 0)
  {
    return this->Fail("SetFieldLength: a length cannot be negative");
  }
  if (!ros2vtk::scene::resize_field(
        *this->Type, this->Message.get(), SafePath(path), static_cast<size_t>(length), &error))
  {
    return this->Fail("SetFieldLength: " + error);
  }
  this->Modified();
  return this->Succeed();
}

//------------------------------------------------------------------------------
bool vtkROS2Message::GetFieldAsArray(const char* path, vtkDataArray* values)
{
  const int length = this->GetFieldLength(path);
  if (length < 0)
  {
    return false;
  }
  if (!values)
  {
    return this->Fail("GetFieldAsArray: null output array");
  }
  const std::string base = SafePath(path);
  auto* int64s = vtkTypeInt64Array::SafeDownCast(values);
  auto* uint64s = vtkTypeUInt64Array::SafeDownCast(values);
  values->SetNumberOfComponents(1);
  values->SetNumberOfTuples(length);
  for (int i = 0; i < length; ++i)
  {
    const std::string element = base + "[" + std::to_string(i) + "]";
    if (int64s)
    {
      int64s->SetValue(i, this->GetFieldAsInteger(element.c_str()));
    }
    else if (uint64s)
    {
      uint64s->SetValue(i, std::strtoull(this->GetField(element.c_str()).c_str(), nullptr, 10));
    }
    else
    {
      values->SetTuple1(i, this->GetFieldAsDouble(element.c_str()));
    }
    if (!this->LastError.empty())
    {
      return false;
    }
  }
  return this->Succeed();
}

//------------------------------------------------------------------------------
bool vtkROS2Message::SetFieldFromArray(const char* path, vtkDataArray* values)
{
  if (!values || values->GetNumberOfComponents() != 1)
  {
    return this->Fail("SetFieldFromArray: give an array with one component");
  }
  // Checked on a copy, so a value that does not fit leaves the message as it was.
  vtkNew<vtkROS2Message> work;
  work->DeepCopy(this);
  const vtkIdType count = values->GetNumberOfTuples();
  if (!work->SetFieldLength(path, static_cast<int>(count)))
  {
    return this->Fail(std::string("SetFieldFromArray: ") + work->GetLastError());
  }
  const std::string base = SafePath(path);
  auto* int64s = vtkTypeInt64Array::SafeDownCast(values);
  auto* uint64s = vtkTypeUInt64Array::SafeDownCast(values);
  for (vtkIdType i = 0; i < count; ++i)
  {
    const std::string element = base + "[" + std::to_string(i) + "]";
    const bool ok = int64s ? work->SetFieldFromInteger(element.c_str(), int64s->GetValue(i))
      : uint64s ? work->SetField(element.c_str(), std::to_string(uint64s->GetValue(i)).c_str())
                : work->SetFieldFromDouble(element.c_str(), values->GetTuple1(i));
    if (!ok)
    {
      return this->Fail(
        "SetFieldFromArray: element " + std::to_string(i) + ": " + work->GetLastError());
    }
  }
  this->DeepCopy(work);
  return this->Succeed();
}

//------------------------------------------------------------------------------
bool vtkROS2Message::GetFieldAsStringArray(const char* path, vtkStringArray* values)
{
  const int length = this->GetFieldLength(path);
  if (length < 0)
  {
    return false;
  }
  if (!values)
  {
    return this->Fail("GetFieldAsStringArray: null output array");
  }
  values->SetNumberOfValues(length);
  for (int i = 0; i < length; ++i)
  {
    values->SetValue(i, this->GetField((SafePath(path) + "[" + std::to_string(i) + "]").c_str()));
    if (!this->LastError.empty())
    {
      return false;
    }
  }
  return this->Succeed();
}

//------------------------------------------------------------------------------
bool vtkROS2Message::SetFieldFromStringArray(const char* path, vtkStringArray* values)
{
  if (!values)
  {
    return this->Fail("SetFieldFromStringArray: null array");
  }
  vtkNew<vtkROS2Message> work;
  work->DeepCopy(this);
  const vtkIdType count = values->GetNumberOfValues();
  if (!work->SetFieldLength(path, static_cast<int>(count)))
  {
    return this->Fail(std::string("SetFieldFromStringArray: ") + work->GetLastError());
  }
  for (vtkIdType i = 0; i < count; ++i)
  {
    if (!work->SetField(
          (SafePath(path) + "[" + std::to_string(i) + "]").c_str(), values->GetValue(i).c_str()))
    {
      return this->Fail(
        "SetFieldFromStringArray: element " + std::to_string(i) + ": " + work->GetLastError());
    }
  }
  this->DeepCopy(work);
  return this->Succeed();
}

//------------------------------------------------------------------------------
bool vtkROS2Message::GetMessage(const char* path, vtkROS2Message* message)
{
  if (!this->CheckType("GetMessage"))
  {
    return false;
  }
  if (!message)
  {
    return this->Fail("GetMessage: null output message");
  }
  const ros2vtk::wire::MessageTypeSupport* type = nullptr;
  std::string error;
  void* nested =
    ros2vtk::scene::locate_message(*this->Type, this->Message.get(), SafePath(path), type, &error);
  if (!nested)
  {
    return this->Fail("GetMessage: " + error);
  }
  message->CopyFromRaw(*type, nested);
  return this->Succeed();
}

//------------------------------------------------------------------------------
bool vtkROS2Message::SetMessage(const char* path, vtkROS2Message* message)
{
  if (!this->CheckType("SetMessage"))
  {
    return false;
  }
  if (!message || !message->Type)
  {
    return this->Fail("SetMessage: the message to copy in has no type");
  }
  const ros2vtk::wire::MessageTypeSupport* type = nullptr;
  std::string error;
  void* nested =
    ros2vtk::scene::locate_message(*this->Type, this->Message.get(), SafePath(path), type, &error);
  if (!nested)
  {
    return this->Fail("SetMessage: " + error);
  }
  if (type != message->Type)
  {
    return this->Fail("SetMessage: field '" + SafePath(path) + "' is a " + type->ros_type +
      ", not a " + message->Type->ros_type);
  }
  type->copy(message->Message.get(), nested);
  this->Modified();
  return this->Succeed();
}

//------------------------------------------------------------------------------
std::string vtkROS2Message::GetYAML()
{
  if (!this->CheckType("GetYAML"))
  {
    return std::string();
  }
  this->Succeed();
  return ros2vtk::wire::to_yaml(*this->Type, this->Message.get());
}

//------------------------------------------------------------------------------
bool vtkROS2Message::SetYAML(const char* yaml)
{
  if (!this->CheckType("SetYAML"))
  {
    return false;
  }
  // Parsed into a copy: invalid YAML leaves the message as it was.
  std::unique_ptr<void, void (*)(void*)> parsed(this->Type->create(), this->Type->destroy);
  this->Type->copy(this->Message.get(), parsed.get());
  std::string error;
  if (!ros2vtk::wire::from_yaml(*this->Type, yaml ? yaml : "", parsed.get(), &error))
  {
    return this->Fail(
      "SetYAML: invalid YAML for " + std::string(this->Type->ros_type) + ": " + error);
  }
  this->Message = std::move(parsed);
  this->Modified();
  return this->Succeed();
}

//------------------------------------------------------------------------------
bool vtkROS2Message::Serialize(vtkUnsignedCharArray* bytes)
{
  if (!this->CheckType("Serialize"))
  {
    return false;
  }
  if (!bytes)
  {
    return this->Fail("Serialize: null output array");
  }
  std::vector<uint8_t> buffer;
  ros2vtk::wire::serialize_message(*this->Type, this->Message.get(), buffer);
  bytes->SetNumberOfComponents(1);
  bytes->SetNumberOfTuples(static_cast<vtkIdType>(buffer.size()));
  std::copy(buffer.begin(), buffer.end(), bytes->GetPointer(0));
  return this->Succeed();
}

//------------------------------------------------------------------------------
bool vtkROS2Message::Deserialize(vtkUnsignedCharArray* bytes)
{
  if (!this->CheckType("Deserialize"))
  {
    return false;
  }
  if (!bytes)
  {
    return this->Fail("Deserialize: null input array");
  }
  std::unique_ptr<void, void (*)(void*)> parsed(this->Type->create(), this->Type->destroy);
  std::string error;
  const auto size = static_cast<size_t>(bytes->GetNumberOfValues());
  if (!ros2vtk::wire::deserialize_message(
        *this->Type, size ? bytes->GetPointer(0) : nullptr, size, parsed.get(), &error))
  {
    return this->Fail("Deserialize: " + error);
  }
  this->Message = std::move(parsed);
  this->Modified();
  return this->Succeed();
}

//------------------------------------------------------------------------------
bool vtkROS2Message::Equals(vtkROS2Message* other)
{
  return other && this->Type && other->Type == this->Type &&
    this->Type->equal(this->Message.get(), other->Message.get());
}

//------------------------------------------------------------------------------
void vtkROS2Message::DeepCopy(vtkROS2Message* other)
{
  if (!other || other == this)
  {
    return;
  }
  if (!other->Type)
  {
    this->Type = nullptr;
    this->Message = std::unique_ptr<void, void (*)(void*)>(nullptr, NoMessage);
    this->Modified();
    return;
  }
  this->CopyFromRaw(*other->Type, other->Message.get());
}

//------------------------------------------------------------------------------
void vtkROS2Message::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ROSType: " << this->GetROSType() << "\n";
}
