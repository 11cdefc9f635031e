// ros2vtk — OpenIGTLink framing (Frame.hpp): header v1/v2 by hand around the 1.11 C utilities.
// Layout: OpenIGTLink Documents/Protocol/header.md (58-byte header; v2 body = 12-byte extended
// header, content, metadata header (count + 8 bytes per entry), metadata keys and values).
#include "ros2vtk/igtl/Frame.hpp"

#include <igtl_header.h>
#include <igtl_util.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace ros2vtk {
namespace igtl {

namespace {

std::uint16_t get_u16(const std::uint8_t* p)
{
  return static_cast<std::uint16_t>((p[0] << 8) | p[1]);
}
std::uint32_t get_u32(const std::uint8_t* p)
{
  return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) |
    std::uint32_t(p[3]);
}
void put_u16(std::vector<std::uint8_t>& out, std::uint16_t v)
{
  out.push_back(static_cast<std::uint8_t>(v >> 8));
  out.push_back(static_cast<std::uint8_t>(v));
}
void put_u32(std::vector<std::uint8_t>& out, std::uint32_t v)
{
  put_u16(out, static_cast<std::uint16_t>(v >> 16));
  put_u16(out, static_cast<std::uint16_t>(v));
}

std::string fixed_string(const char* field, std::size_t size)
{
  std::size_t n = 0;
  while (n < size && field[n] != '\0')
  {
    ++n;
  }
  return std::string(field, n);
}

// Splits a v2 body into content and metadata; false with `error` when the sections do not fit.
bool split_v2(const std::uint8_t* body, std::size_t size, Frame& frame, std::string& error)
{
  if (size < 12)
  {
    error = "header v2 body of " + std::to_string(size) + " bytes has no 12-byte extended header";
    return false;
  }
  const std::size_t ext_size = get_u16(body);
  const std::size_t meta_header_size = get_u16(body + 2);
  const std::size_t meta_size = get_u32(body + 4);
  if (ext_size < 12 || ext_size + meta_header_size + meta_size > size)
  {
    error = "header v2 sections (extended header " + std::to_string(ext_size) +
      ", metadata header " + std::to_string(meta_header_size) + ", metadata " +
      std::to_string(meta_size) + ") exceed the body of " + std::to_string(size) + " bytes";
    return false;
  }
  const std::size_t meta_start = size - meta_header_size - meta_size;
  frame.content.assign(body + ext_size, body + meta_start);
  if (meta_header_size == 0)
  {
    return true;
  }
  if (meta_header_size < 2)
  {
    error = "metadata header of " + std::to_string(meta_header_size) + " bytes";
    return false;
  }
  const std::uint8_t* mh = body + meta_start;
  const std::size_t count = get_u16(mh);
  if (2 + 8 * count != meta_header_size)
  {
    error = "metadata header of " + std::to_string(meta_header_size) + " bytes for " +
      std::to_string(count) + " entries";
    return false;
  }
  const std::uint8_t* data = mh + meta_header_size;
  std::size_t used = 0;
  for (std::size_t i = 0; i < count; ++i)
  {
    const std::uint8_t* entry = mh + 2 + 8 * i;
    const std::size_t key_size = get_u16(entry);
    const std::size_t value_size = get_u32(entry + 4);
    if (used + key_size + value_size > meta_size)
    {
      error = "metadata entry " + std::to_string(i) + " runs past the metadata section";
      return false;
    }
    std::string key(reinterpret_cast<const char*>(data + used), key_size);
    used += key_size;
    frame.metadata[key] = std::string(reinterpret_cast<const char*>(data + used), value_size);
    used += value_size;
  }
  return true;
}

} // namespace

std::uint64_t to_igtl_timestamp(double seconds)
{
  if (!(seconds > 0.0))
  {
    return 0;
  }
  const double whole = std::floor(seconds);
  const auto fraction = static_cast<std::uint64_t>((seconds - whole) * 4294967296.0);
  return (static_cast<std::uint64_t>(whole) << 32) | (fraction & 0xffffffffu);
}

std::vector<std::uint8_t> encode_frame(const Frame& frame)
{
  std::vector<std::uint8_t> body;
  const bool v2 = !frame.metadata.empty();
  if (v2)
  {
    std::size_t meta_size = 0;
    for (const auto& kv : frame.metadata)
    {
      meta_size += kv.first.size() + kv.second.size();
    }
    const std::size_t meta_header_size = 2 + 8 * frame.metadata.size();
    body.reserve(12 + frame.content.size() + meta_header_size + meta_size);
    put_u16(body, 12);
    put_u16(body, static_cast<std::uint16_t>(meta_header_size));
    put_u32(body, static_cast<std::uint32_t>(meta_size));
    put_u32(body, 0); // message ID: only video frames use one
    body.insert(body.end(), frame.content.begin(), frame.content.end());
    put_u16(body, static_cast<std::uint16_t>(frame.metadata.size()));
    for (const auto& kv : frame.metadata)
    {
      put_u16(body, static_cast<std::uint16_t>(kv.first.size()));
      put_u16(body, 3); // IANA 3 = US-ASCII, as OpenIGTLinkIO writes
      put_u32(body, static_cast<std::uint32_t>(kv.second.size()));
    }
    for (const auto& kv : frame.metadata)
    {
      body.insert(body.end(), kv.first.begin(), kv.first.end());
      body.insert(body.end(), kv.second.begin(), kv.second.end());
    }
  }
  igtl_header header;
  std::memset(&header, 0, sizeof(header));
  header.version = v2 ? 2 : 1;
  std::memcpy(header.name, frame.type.data(),
    std::min<std::size_t>(frame.type.size(), IGTL_HEADER_TYPE_SIZE));
  std::memcpy(header.device_name, frame.device.data(),
    std::min<std::size_t>(frame.device.size(), IGTL_HEADER_NAME_SIZE)); // truncated to 20 bytes
  header.timestamp = frame.timestamp;
  const std::vector<std::uint8_t>& payload = v2 ? body : frame.content;
  header.body_size = payload.size();
  header.crc = crc64(const_cast<unsigned char*>(payload.data()), payload.size(), 0);
  igtl_header_convert_byte_order(&header);
  std::vector<std::uint8_t> out(IGTL_HEADER_SIZE + payload.size());
  std::memcpy(out.data(), &header, IGTL_HEADER_SIZE);
  if (!payload.empty())
  {
    std::memcpy(out.data() + IGTL_HEADER_SIZE, payload.data(), payload.size());
  }
  return out;
}

FrameReader::FrameReader(std::size_t max_body_size)
  : MaxBodySize(max_body_size)
{
}

void FrameReader::feed(const std::uint8_t* data, std::size_t size)
{
  if (this->Offset > 0 && this->Offset == this->Buffer.size())
  {
    this->Buffer.clear();
    this->Offset = 0;
  }
  else if (this->Offset > (1u << 20))
  {
    this->Buffer.erase(
      this->Buffer.begin(), this->Buffer.begin() + static_cast<long>(this->Offset));
    this->Offset = 0;
  }
  this->Buffer.insert(this->Buffer.end(), data, data + size);
}

FrameReader::Result FrameReader::next(Frame& frame, std::string& error)
{
  if (this->buffered() < IGTL_HEADER_SIZE)
  {
    return Result::NeedMore;
  }
  igtl_header header;
  std::memcpy(&header, this->Buffer.data() + this->Offset, IGTL_HEADER_SIZE);
  igtl_header_convert_byte_order(&header);
  const std::string type = fixed_string(header.name, IGTL_HEADER_TYPE_SIZE);
  const std::string device = fixed_string(header.device_name, IGTL_HEADER_NAME_SIZE);
  if (header.version != 1 && header.version != 2)
  {
    error = "header version " + std::to_string(header.version) + " (type '" + type +
      "'): not OpenIGTLink header v1 or v2, the stream cannot be followed";
    return Result::Fatal;
  }
  if (header.body_size > this->MaxBodySize)
  {
    error = type + " '" + device + "': body of " + std::to_string(header.body_size) +
      " bytes exceeds the limit of " + std::to_string(this->MaxBodySize);
    return Result::Fatal;
  }
  const std::size_t body_size = static_cast<std::size_t>(header.body_size);
  if (this->buffered() < IGTL_HEADER_SIZE + body_size)
  {
    return Result::NeedMore;
  }
  const std::uint8_t* body = this->Buffer.data() + this->Offset + IGTL_HEADER_SIZE;
  this->Offset += IGTL_HEADER_SIZE + body_size;
  const std::uint64_t crc = crc64(const_cast<unsigned char*>(body), body_size, 0);
  if (crc != header.crc)
  {
    error = type + " '" + device + "': CRC mismatch, message dropped";
    return Result::Skipped;
  }
  frame = Frame();
  frame.header_version = header.version;
  frame.type = type;
  frame.device = device;
  frame.timestamp = header.timestamp;
  if (header.version == 2)
  {
    std::string why;
    if (!split_v2(body, body_size, frame, why))
    {
      error = type + " '" + device + "': " + why + ", message dropped";
      return Result::Skipped;
    }
  }
  else
  {
    frame.content.assign(body, body + body_size);
  }
  return Result::Frame;
}

} // namespace igtl
} // namespace ros2vtk
