// ros2vtk — Fast DDS 2.9 TopicDataType over a generated MessageTypeSupport table.
#include "TypeAdapter.hpp"

#include "ros2vtk/wire/CdrReader.hpp"
#include "ros2vtk/wire/CdrWriter.hpp"

#include <cstring>
#include <vector>

namespace ros2vtk {
namespace wire {

using eprosima::fastrtps::rtps::SerializedPayload_t;

TypeAdapter::TypeAdapter(const MessageTypeSupport& type)
  : type_(type)
{
  setName(type.dds_type_name);
  // Initial payload size of the history pools; PREALLOCATED_WITH_REALLOC grows it as needed.
  m_typeSize = 512;
  m_isGetKeyDefined = false; // ROS messages are unkeyed (NO_KEY topics)
  // Never announce Fast DDS 2.x type objects: Fast DDS 3 (Kilted) would compare them against its
  // XTypes 1.3 identifiers and refuse to match. Type names alone must match (WIRE_NOTES §2.7.1).
  auto_fill_type_object(false);
  auto_fill_type_information(false);
}

bool TypeAdapter::serialize(void* data, SerializedPayload_t* payload)
{
  // Serialize into a thread-local buffer, then copy. The payload comes from Fast DDS's pool,
  // sized by getSerializedSizeProvider; it is too small only if the message changed meanwhile.
  thread_local std::vector<uint8_t> buffer;
  serialize_message(type_, data, buffer);
  if (buffer.size() > payload->max_size)
  {
    return false;
  }
  std::memcpy(payload->data, buffer.data(), buffer.size());
  payload->length = static_cast<uint32_t>(buffer.size());
  payload->encapsulation = CDR_LE;
  return true;
}

bool TypeAdapter::deserialize(SerializedPayload_t* payload, void* data)
{
  auto* sample = static_cast<ReceivedSample*>(data);
  if (sample->message == nullptr)
  {
    sample->message = type_.create();
  }
  std::string error;
  sample->valid =
    deserialize_message(type_, payload->data, payload->length, sample->message, &error);
  sample->error = sample->valid ? std::string() : error;
  // Always report success so the sample reaches our listener, which counts and reports it.
  return true;
}

std::function<uint32_t()> TypeAdapter::getSerializedSizeProvider(void* data)
{
  const MessageTypeSupport* type = &type_;
  return [type, data]() {
    return static_cast<uint32_t>(type->serialized_size(data));
  };
}

void* TypeAdapter::createData()
{
  return new ReceivedSample();
}

void TypeAdapter::deleteData(void* data)
{
  auto* sample = static_cast<ReceivedSample*>(data);
  if (sample->message)
  {
    type_.destroy(sample->message);
  }
  delete sample;
}

bool TypeAdapter::getKey(void*, eprosima::fastrtps::rtps::InstanceHandle_t*, bool)
{
  return false;
}

} // namespace wire
} // namespace ros2vtk
