// ros2vtk — OpenIGTLink framing: one message as header fields, content and metadata, and the
// incremental reader that cuts a TCP byte stream into such frames.
//
// Why by hand: Debian's OpenIGTLink 1.11 unpacks header version 1 only, while Slicer sends header
// version 2 (12-byte extended header + trailing metadata) for everything it pushes. We read the
// 58-byte header with the library's igtl_header_convert_byte_order and crc64, check the CRC over
// the whole body, cut the v2 extended header and metadata off, and hand the remaining content to
// the 1.11 message classes (Codec.hpp). Sending frames v1, or v2 when metadata is given.
#ifndef ros2vtk_igtl_Frame_hpp
#define ros2vtk_igtl_Frame_hpp

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace ros2vtk {
namespace igtl {

/// One OpenIGTLink message, de-framed.
struct Frame
{
  std::uint16_t header_version = 1;
  std::string type;                  ///< "TRANSFORM", "IMAGE", … (≤ 12 bytes)
  std::string device;                ///< device name (≤ 20 bytes)
  std::uint64_t timestamp = 0;       ///< OpenIGTLink fixed point: seconds << 32 | fraction
  std::vector<std::uint8_t> content; ///< the type's body, without v2 extended header and metadata
  std::map<std::string, std::string> metadata; ///< v2 only
};

/// Serialises `frame` (header version 1 when it has no metadata, else 2) with the CRC computed.
std::vector<std::uint8_t> encode_frame(const Frame& frame);

/// Seconds since the epoch as OpenIGTLink's 32.32 fixed-point timestamp.
std::uint64_t to_igtl_timestamp(double seconds);

/// Cuts a byte stream into frames. Bad input is told apart: a broken frame whose length is still
/// known (CRC mismatch, malformed v2 sections) is skipped and reported (the stream goes on); a
/// header that cannot be trusted (unknown version, body larger than the limit) is fatal for the
/// stream, since its boundaries are lost.
class FrameReader
{
public:
  enum class Result
  {
    Frame,    ///< `frame` holds the next message
    NeedMore, ///< not enough bytes yet
    Skipped,  ///< a message was dropped; `error` says why; call again
    Fatal     ///< the stream cannot be read further; `error` says why
  };

  explicit FrameReader(std::size_t max_body_size = 64u * 1024u * 1024u);
  void feed(const std::uint8_t* data, std::size_t size);
  Result next(Frame& frame, std::string& error);
  std::size_t buffered() const { return this->Buffer.size() - this->Offset; }

private:
  std::size_t MaxBodySize;
  std::vector<std::uint8_t> Buffer;
  std::size_t Offset = 0;
};

} // namespace igtl
} // namespace ros2vtk

#endif
