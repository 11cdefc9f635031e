// ros2vtk — the REP 2011 ~/get_type_description service of one node.
#include "ros2vtk/wire/TypeDescriptionService.hpp"

#include "ShippedTypes.hpp"
#include "ros2vtk/rcl_interfaces/msg/parameter_type.hpp"
#include "ros2vtk/wire/ParameterStore.hpp"
#include "ros2vtk/wire/Participant.hpp"
#include "ros2vtk/wire/Service.hpp"

#include <cctype>
#include <vector>

namespace ros2vtk {
namespace wire {

namespace tdi = ::ros2vtk::type_description_interfaces;

const char* const TypeDescriptionService::kEnableParameter = "start_type_description_service";

namespace {

/// rosidl_parse_type_hash_string's grammar: "RIHS01_" and 64 hex digits.
bool is_type_hash(const std::string& text)
{
  static const std::string prefix = "RIHS01_";
  if (text.size() != prefix.size() + 64 || text.compare(0, prefix.size(), prefix) != 0)
  {
    return false;
  }
  for (size_t i = prefix.size(); i < text.size(); ++i)
  {
    if (!std::isxdigit(static_cast<unsigned char>(text[i])))
    {
      return false;
    }
  }
  return true;
}

void to_message(
  const IndividualTypeDescriptionTable& table, tdi::msg::IndividualTypeDescription& message)
{
  message.type_name = table.type_name;
  message.fields.resize(table.field_count);
  for (uint32_t i = 0; i < table.field_count; ++i)
  {
    const TypeDescriptionField& from = table.fields[i];
    tdi::msg::Field& to = message.fields[i];
    to.name = from.name;
    to.type.type_id = from.type_id;
    to.type.capacity = from.capacity;
    to.type.string_capacity = from.string_capacity;
    to.type.nested_type_name = from.nested_type_name;
    to.default_value = from.default_value;
  }
}

/// The TypeSource of one described type: its entry's text, or the text of the generated type
/// the entry names (TypeSourceTable::defined_by).
void add_type_source(
  const IndividualTypeDescriptionTable& table, std::vector<tdi::msg::TypeSource>& sources)
{
  const TypeSourceTable* from = &table.source;
  const MessageTypeSupport* owner = from->defined_by ? from->defined_by() : nullptr;
  if (owner && owner->description)
  {
    from = &owner->description->type.source;
  }
  tdi::msg::TypeSource source;
  source.type_name = table.type_name;
  source.encoding = from->encoding ? from->encoding : "";
  source.raw_file_contents = from->raw_file_contents ? from->raw_file_contents : "";
  sources.push_back(std::move(source));
}

} // namespace

void to_message(const TypeDescriptionTable& table, tdi::msg::TypeDescription& message)
{
  to_message(table.type, message.type_description);
  message.referenced_type_descriptions.resize(table.referenced_count);
  for (uint32_t i = 0; i < table.referenced_count; ++i)
  {
    to_message(table.referenced[i], message.referenced_type_descriptions[i]);
  }
}

namespace {

IndividualDescription from_message(const tdi::msg::IndividualTypeDescription& message)
{
  IndividualDescription result;
  result.type_name = message.type_name;
  result.fields.reserve(message.fields.size());
  for (const tdi::msg::Field& field : message.fields)
  {
    DescriptionField f;
    f.name = field.name;
    f.type_id = field.type.type_id;
    f.capacity = field.type.capacity;
    f.string_capacity = field.type.string_capacity;
    f.nested_type_name = field.type.nested_type_name;
    f.default_value = field.default_value;
    result.fields.push_back(std::move(f));
  }
  return result;
}

} // namespace

TypeDescriptionData from_message(const tdi::msg::TypeDescription& message)
{
  TypeDescriptionData result;
  result.type = from_message(message.type_description);
  result.referenced.reserve(message.referenced_type_descriptions.size());
  for (const auto& referenced : message.referenced_type_descriptions)
  {
    result.referenced.push_back(from_message(referenced));
  }
  return result;
}

void answer_type_description_request(const NodeTypeCache& types,
  const tdi::srv::GetTypeDescription_Request& request,
  tdi::srv::GetTypeDescription_Response& response)
{
  response = tdi::srv::GetTypeDescription_Response();
  response.successful = false;
  if (!is_type_hash(request.type_hash))
  {
    response.failure_reason = "Failed to parse type hash";
    return;
  }
  const TypeDescriptionTable* description = types.find(request.type_hash);
  if (!description)
  {
    response.failure_reason = "Type not currently in use by this node";
    return;
  }
  to_message(*description, response.type_description);
  if (request.include_type_sources)
  {
    // As rcl: the type's own source, then one per referenced type, in the description's order.
    add_type_source(description->type, response.type_sources);
    for (uint32_t i = 0; i < description->referenced_count; ++i)
    {
      add_type_source(description->referenced[i], response.type_sources);
    }
  }
  response.successful = true;
}

bool TypeDescriptionService::enabled(
  ParameterStore& parameters, bool default_value, std::string* error)
{
  namespace rcl = ::ros2vtk::rcl_interfaces::msg;
  if (!parameters.has(kEnableParameter))
  {
    rcl::ParameterValue value;
    value.type = rcl::ParameterType::PARAMETER_BOOL;
    value.bool_value = default_value;
    rcl::ParameterDescriptor descriptor;
    descriptor.name = kEnableParameter;
    descriptor.type = rcl::ParameterType::PARAMETER_BOOL;
    descriptor.description = "If enabled, start the ~/get_type_description service.";
    descriptor.read_only = true;
    if (!parameters.declare(kEnableParameter, value, descriptor, error))
    {
      return false;
    }
  }
  const rcl::ParameterValue* value = parameters.get(kEnableParameter);
  if (!value || value->type != rcl::ParameterType::PARAMETER_BOOL)
  {
    if (error)
    {
      *error = std::string("parameter ") + kEnableParameter + " should be a bool";
    }
    return false;
  }
  return value->bool_value;
}

std::unique_ptr<TypeDescriptionService> TypeDescriptionService::create(
  Participant& participant, std::string* error)
{
  auto server = participant.create_service_server(
    shipped_service_type("type_description_interfaces/srv/GetTypeDescription"),
    "~/get_type_description", QoS::services(), error);
  if (!server)
  {
    return nullptr;
  }
  return std::unique_ptr<TypeDescriptionService>(
    new TypeDescriptionService(participant.type_cache(), std::move(server)));
}

TypeDescriptionService::TypeDescriptionService(
  const NodeTypeCache& types, std::unique_ptr<ServiceServer> server)
  : types_(types)
  , server_(std::move(server))
{
}

TypeDescriptionService::~TypeDescriptionService() = default;

size_t TypeDescriptionService::process()
{
  std::vector<ServiceRequest> requests;
  server_->take(requests); // malformed requests are rejected (and counted) by the server
  for (const auto& request : requests)
  {
    tdi::srv::GetTypeDescription_Response response;
    answer_type_description_request(types_,
      *static_cast<const tdi::srv::GetTypeDescription_Request*>(request.request.get()), response);
    server_->send_response(request.id, &response);
    ++answered_;
  }
  return requests.size();
}

} // namespace wire
} // namespace ros2vtk
