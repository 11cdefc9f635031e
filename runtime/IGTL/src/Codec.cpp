// ros2vtk — OpenIGTLink content ↔ values (Codec.hpp) with the 1.11 message classes. Decoding
// re-frames the content as a v1 message (whatever header version it came in) and runs the
// library's own receive path: MessageHeader::Unpack, SetMessageHeader, AllocatePack, Unpack.
// Sizes are checked first: 1.11 trusts the body size it is given.
#include "ros2vtk/igtl/Codec.hpp"

#include <igtlImageMessage.h>
#include <igtl_header.h>
#include <igtlMessageHeader.h>
#include <igtlPointMessage.h>
#include <igtlPolyDataMessage.h>
#include <igtlPositionMessage.h>
#include <igtlStringMessage.h>
#include <igtlTrackingDataMessage.h>
#include <igtlTransformMessage.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <list>

namespace ros2vtk {
namespace igtl {

namespace {

// The library's packed bytes (header v1 + body) as a Frame with the content only.
Frame frame_of(::igtl::MessageBase* message, const char* type, const std::string& device)
{
  Frame frame;
  frame.type = type;
  frame.device = device;
  const auto* body = static_cast<const std::uint8_t*>(message->GetPackBodyPointer());
  frame.content.assign(body, body + message->GetPackBodySize());
  return frame;
}

void stamp(::igtl::MessageBase* message, const std::string& device, std::uint64_t timestamp)
{
  message->SetDeviceName(device.substr(0, 20).c_str());
  message->SetTimeStamp(
    static_cast<unsigned int>(timestamp >> 32), static_cast<unsigned int>(timestamp & 0xffffffffu));
}

bool unpack(const Frame& frame, ::igtl::MessageBase* message, std::string& error)
{
  Frame v1 = frame;
  v1.metadata.clear();
  const std::vector<std::uint8_t> bytes = encode_frame(v1);
  ::igtl::MessageHeader::Pointer header = ::igtl::MessageHeader::New();
  header->InitPack();
  std::memcpy(header->GetPackPointer(), bytes.data(), IGTL_HEADER_SIZE);
  if (!(header->Unpack() & ::igtl::MessageHeader::UNPACK_HEADER))
  {
    error = "header not accepted by OpenIGTLink";
    return false;
  }
  message->SetMessageHeader(header);
  message->AllocatePack();
  if (static_cast<std::size_t>(message->GetPackBodySize()) != frame.content.size())
  {
    error = "body size mismatch";
    return false;
  }
  if (!frame.content.empty())
  {
    std::memcpy(message->GetPackBodyPointer(), frame.content.data(), frame.content.size());
  }
  if (!(message->Unpack(0) & ::igtl::MessageHeader::UNPACK_BODY))
  {
    error = frame.type + " body of " + std::to_string(frame.content.size()) +
      " bytes not accepted by OpenIGTLink";
    return false;
  }
  return true;
}

std::string size_error(const Frame& frame, const std::string& expected)
{
  return frame.type + " '" + frame.device + "': body of " + std::to_string(frame.content.size()) +
    " bytes, expected " + expected;
}

void to_igtl(const Matrix& m, ::igtl::Matrix4x4 out)
{
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      out[r][c] = static_cast<float>(m[4 * r + c]);
    }
  }
}

void from_igtl(::igtl::Matrix4x4 in, Matrix& m)
{
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      m[4 * r + c] = in[r][c];
    }
  }
}

// Half the extent from the first voxel to the last, along the image axes, in world units.
std::array<double, 3> corner_to_centre(const Image& image)
{
  std::array<double, 3> offset{ { 0, 0, 0 } };
  for (int axis = 0; axis < 3; ++axis)
  {
    const double half = image.spacing[axis] * (image.size[axis] - 1) / 2.0;
    for (int r = 0; r < 3; ++r)
    {
      offset[r] += image.ijk_to_world[4 * r + axis] * half;
    }
  }
  return offset;
}

} // namespace

std::size_t scalar_size(ScalarType type)
{
  switch (type)
  {
    case ScalarType::Int8:
    case ScalarType::UInt8:
      return 1;
    case ScalarType::Int16:
    case ScalarType::UInt16:
      return 2;
    case ScalarType::Float32:
      return 4;
    case ScalarType::Float64:
      return 8;
  }
  return 0;
}

Frame encode_transform(const std::string& device, const Matrix& matrix, std::uint64_t timestamp)
{
  ::igtl::TransformMessage::Pointer message = ::igtl::TransformMessage::New();
  stamp(message, device, timestamp);
  ::igtl::Matrix4x4 m;
  to_igtl(matrix, m);
  message->SetMatrix(m);
  message->Pack();
  Frame frame = frame_of(message, "TRANSFORM", device);
  frame.timestamp = timestamp;
  return frame;
}

Frame encode_string(const std::string& device, const std::string& text, std::uint64_t timestamp)
{
  ::igtl::StringMessage::Pointer message = ::igtl::StringMessage::New();
  stamp(message, device, timestamp);
  message->SetString(text.c_str());
  message->SetEncoding(3); // US-ASCII (IANA 3), as Slicer's text nodes default to
  message->Pack();
  Frame frame = frame_of(message, "STRING", device);
  frame.timestamp = timestamp;
  return frame;
}

Frame encode_points(
  const std::string& device, const std::vector<PointItem>& points, std::uint64_t timestamp)
{
  ::igtl::PointMessage::Pointer message = ::igtl::PointMessage::New();
  stamp(message, device, timestamp);
  for (const PointItem& item : points)
  {
    ::igtl::PointElement::Pointer element = ::igtl::PointElement::New();
    element->SetName(item.name.substr(0, 63).c_str());
    element->SetGroupName(item.group.substr(0, 31).c_str());
    element->SetRGBA(item.rgba[0], item.rgba[1], item.rgba[2], item.rgba[3]);
    element->SetPosition(item.position[0], item.position[1], item.position[2]);
    element->SetRadius(item.radius);
    message->AddPointElement(element);
  }
  message->Pack();
  Frame frame = frame_of(message, "POINT", device);
  frame.timestamp = timestamp;
  return frame;
}

Frame encode_tracking_data(
  const std::string& device, const std::vector<TrackingItem>& items, std::uint64_t timestamp)
{
  ::igtl::TrackingDataMessage::Pointer message = ::igtl::TrackingDataMessage::New();
  stamp(message, device, timestamp);
  for (const TrackingItem& item : items)
  {
    ::igtl::TrackingDataElement::Pointer element = ::igtl::TrackingDataElement::New();
    element->SetName(item.name.substr(0, 20).c_str());
    element->SetType(::igtl::TrackingDataElement::TYPE_6D);
    ::igtl::Matrix4x4 m;
    to_igtl(item.matrix, m);
    element->SetMatrix(m);
    message->AddTrackingDataElement(element);
  }
  message->Pack();
  Frame frame = frame_of(message, "TDATA", device);
  frame.timestamp = timestamp;
  return frame;
}

Frame encode_image(const std::string& device, const Image& image, std::uint64_t timestamp)
{
  ::igtl::ImageMessage::Pointer message = ::igtl::ImageMessage::New();
  stamp(message, device, timestamp);
  message->SetDimensions(image.size[0], image.size[1], image.size[2]);
  message->SetSpacing(image.spacing[0], image.spacing[1], image.spacing[2]);
  message->SetScalarType(static_cast<int>(image.scalar));
  message->SetNumComponents(image.components);
  message->SetCoordinateSystem(::igtl::ImageMessage::COORDINATE_RAS);
  // The spec's translation is the volume centre; 1.11 writes what it is given.
  Matrix centred = image.ijk_to_world;
  const std::array<double, 3> offset = corner_to_centre(image);
  for (int r = 0; r < 3; ++r)
  {
    centred[4 * r + 3] += offset[r];
  }
  ::igtl::Matrix4x4 m;
  to_igtl(centred, m);
  message->SetMatrix(m);
  message->AllocateScalars();
  const std::size_t size =
    std::min<std::size_t>(image.data.size(), static_cast<std::size_t>(message->GetImageSize()));
  std::memcpy(message->GetScalarPointer(), image.data.data(), size);
  message->Pack();
  Frame frame = frame_of(message, "IMAGE", device);
  frame.timestamp = timestamp;
  return frame;
}

Frame encode_polydata(const std::string& device, const Mesh& mesh, std::uint64_t timestamp)
{
  ::igtl::PolyDataMessage::Pointer message = ::igtl::PolyDataMessage::New();
  stamp(message, device, timestamp);
  ::igtl::PolyDataPointArray::Pointer points = ::igtl::PolyDataPointArray::New();
  for (std::size_t i = 0; i + 2 < mesh.points.size(); i += 3)
  {
    points->AddPoint(mesh.points[i], mesh.points[i + 1], mesh.points[i + 2]);
  }
  message->SetPoints(points);
  auto cells = [](const std::vector<std::vector<std::uint32_t>>& list) {
    ::igtl::PolyDataCellArray::Pointer array = ::igtl::PolyDataCellArray::New();
    for (const auto& cell : list)
    {
      array->AddCell(std::list<igtlUint32>(cell.begin(), cell.end()));
    }
    return array;
  };
  if (!mesh.polygons.empty())
  {
    message->SetPolygons(cells(mesh.polygons));
  }
  if (!mesh.lines.empty())
  {
    message->SetLines(cells(mesh.lines));
  }
  if (!mesh.vertices.empty())
  {
    message->SetVertices(cells(mesh.vertices));
  }
  message->Pack();
  Frame frame = frame_of(message, "POLYDATA", device);
  frame.timestamp = timestamp;
  return frame;
}

bool decode_transform(const Frame& frame, Matrix& matrix, std::string& error)
{
  if (frame.content.size() != 48)
  {
    error = size_error(frame, "48");
    return false;
  }
  ::igtl::TransformMessage::Pointer message = ::igtl::TransformMessage::New();
  if (!unpack(frame, message, error))
  {
    return false;
  }
  ::igtl::Matrix4x4 m;
  message->GetMatrix(m);
  from_igtl(m, matrix);
  for (double v : matrix)
  {
    if (!std::isfinite(v))
    {
      error = "TRANSFORM '" + frame.device + "': matrix holds a non-finite value";
      return false;
    }
  }
  return true;
}

bool decode_position(const Frame& frame, Matrix& matrix, std::string& error)
{
  if (frame.content.size() != 12 && frame.content.size() != 24 && frame.content.size() != 28)
  {
    error = size_error(frame, "12, 24 or 28");
    return false;
  }
  ::igtl::PositionMessage::Pointer message = ::igtl::PositionMessage::New();
  if (!unpack(frame, message, error))
  {
    return false;
  }
  float p[3];
  float q[4] = { 0.f, 0.f, 0.f, 1.f };
  message->GetPosition(p);
  if (frame.content.size() > 12)
  {
    message->GetQuaternion(q);
  }
  ::igtl::Matrix4x4 m;
  ::igtl::QuaternionToMatrix(q, m);
  m[0][3] = p[0];
  m[1][3] = p[1];
  m[2][3] = p[2];
  from_igtl(m, matrix);
  return true;
}

bool decode_string(const Frame& frame, std::string& text, std::string& error)
{
  if (frame.content.size() < 4 ||
    frame.content.size() != 4u + ((std::size_t(frame.content[2]) << 8) | frame.content[3]))
  {
    error = size_error(frame, "4 + the string length it states");
    return false;
  }
  ::igtl::StringMessage::Pointer message = ::igtl::StringMessage::New();
  if (!unpack(frame, message, error))
  {
    return false;
  }
  text = message->GetString();
  return true;
}

bool decode_points(const Frame& frame, std::vector<PointItem>& points, std::string& error)
{
  if (frame.content.size() % 136 != 0)
  {
    error = size_error(frame, "a multiple of 136");
    return false;
  }
  ::igtl::PointMessage::Pointer message = ::igtl::PointMessage::New();
  if (!unpack(frame, message, error))
  {
    return false;
  }
  points.clear();
  for (int i = 0; i < message->GetNumberOfPointElement(); ++i)
  {
    ::igtl::PointElement::Pointer element;
    message->GetPointElement(i, element);
    PointItem item;
    item.name = element->GetName();
    item.group = element->GetGroupName();
    element->GetRGBA(item.rgba.data());
    element->GetPosition(item.position.data());
    item.radius = element->GetRadius();
    if (!std::isfinite(item.position[0]) || !std::isfinite(item.position[1]) ||
      !std::isfinite(item.position[2]))
    {
      error = "POINT '" + frame.device + "': element " + std::to_string(i) + " is not finite";
      return false;
    }
    points.push_back(item);
  }
  return true;
}

bool decode_tracking_data(const Frame& frame, std::vector<TrackingItem>& items, std::string& error)
{
  if (frame.content.size() % 70 != 0) // IGTL_TDATA_ELEMENT_SIZE
  {
    error = size_error(frame, "a multiple of 70");
    return false;
  }
  ::igtl::TrackingDataMessage::Pointer message = ::igtl::TrackingDataMessage::New();
  if (!unpack(frame, message, error))
  {
    return false;
  }
  items.clear();
  for (int i = 0; i < message->GetNumberOfTrackingDataElements(); ++i)
  {
    ::igtl::TrackingDataElement::Pointer element;
    message->GetTrackingDataElement(i, element);
    TrackingItem item;
    item.name = element->GetName();
    ::igtl::Matrix4x4 m;
    element->GetMatrix(m);
    from_igtl(m, item.matrix);
    for (double v : item.matrix)
    {
      if (!std::isfinite(v))
      {
        error = "TDATA '" + frame.device + "': element " + std::to_string(i) + " is not finite";
        return false;
      }
    }
    items.push_back(item);
  }
  return true;
}

bool decode_image(const Frame& frame, Image& image, std::string& error)
{
  const std::size_t header = 72; // IGTL_IMAGE_HEADER_SIZE
  if (frame.content.size() < header)
  {
    error = size_error(frame, "at least 72");
    return false;
  }
  const std::uint8_t* h = frame.content.data();
  const int components = h[2];
  const int scalar = h[3];
  const bool big_endian = h[4] == 1;
  auto u16 = [&](int at) {
    return (std::size_t(h[at]) << 8) | h[at + 1];
  };
  const std::size_t si = u16(6), sj = u16(8), sk = u16(10);
  const std::size_t oi = u16(60), oj = u16(62), ok = u16(64); // sub-volume offset
  const std::size_t di = u16(66), dj = u16(68), dk = u16(70); // sub-volume size
  const auto type = static_cast<ScalarType>(scalar);
  const std::size_t bytes = scalar_size(type);
  if (bytes == 0)
  {
    error = "IMAGE '" + frame.device + "': scalar type " + std::to_string(scalar) +
      " is not one of int8, uint8, int16, uint16, float32, float64";
    return false;
  }
  if (components < 1 || oi || oj || ok || di != si || dj != sj || dk != sk)
  {
    error = "IMAGE '" + frame.device + "': sub-volumes and zero components are not supported";
    return false;
  }
  const std::size_t expected = header + si * sj * sk * std::size_t(components) * bytes;
  if (frame.content.size() != expected)
  {
    error = size_error(frame, std::to_string(expected));
    return false;
  }
  ::igtl::ImageMessage::Pointer message = ::igtl::ImageMessage::New();
  if (!unpack(frame, message, error))
  {
    return false;
  }
  image.size = { { int(si), int(sj), int(sk) } };
  message->GetSpacing(image.spacing.data());
  image.components = components;
  image.scalar = type;
  ::igtl::Matrix4x4 m;
  message->GetMatrix(m);
  from_igtl(m, image.ijk_to_world);
  const std::array<double, 3> offset = corner_to_centre(image);
  for (int r = 0; r < 3; ++r)
  {
    image.ijk_to_world[4 * r + 3] -= offset[r]; // centre -> first voxel
  }
  const auto* pixels = static_cast<const std::uint8_t*>(message->GetScalarPointer());
  image.data.assign(pixels, pixels + (expected - header));
  if (big_endian && bytes > 1) // OpenIGTLink keeps pixels in the sender's byte order
  {
    for (std::size_t i = 0; i + bytes <= image.data.size(); i += bytes)
    {
      std::reverse(image.data.begin() + long(i), image.data.begin() + long(i + bytes));
    }
  }
  return true;
}

} // namespace igtl
} // namespace ros2vtk
