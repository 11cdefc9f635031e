// ros2vtk — Fast DDS 2.9 TopicDataType over a generated MessageTypeSupport table.
//
// Writers pass pointers to message structs; readers get ReceivedSample holders, so a malformed
// sample still reaches us (flagged) instead of being dropped silently inside Fast DDS.
#ifndef ros2vtk_wire_TypeAdapter_hpp
#define ros2vtk_wire_TypeAdapter_hpp

#include "ros2vtk/wire/MessageTypeSupport.hpp"

#include <fastdds/dds/topic/TopicDataType.hpp>

#include <string>

namespace ros2vtk {
namespace wire {

/// What a DataReader hands us for each sample.
struct ReceivedSample
{
  void* message = nullptr; ///< created by the type support, owned by the holder until taken
  bool valid = false;
  std::string error;
};

class TypeAdapter : public eprosima::fastdds::dds::TopicDataType
{
public:
  explicit TypeAdapter(const MessageTypeSupport& type);

  bool serialize(void* data, eprosima::fastrtps::rtps::SerializedPayload_t* payload) override;
  bool deserialize(eprosima::fastrtps::rtps::SerializedPayload_t* payload, void* data) override;
  std::function<uint32_t()> getSerializedSizeProvider(void* data) override;
  void* createData() override;
  void deleteData(void* data) override;
  bool getKey(
    void* data, eprosima::fastrtps::rtps::InstanceHandle_t* handle, bool force_md5) override;

  const MessageTypeSupport& type() const { return type_; }

private:
  const MessageTypeSupport& type_;
};

} // namespace wire
} // namespace ros2vtk

#endif
