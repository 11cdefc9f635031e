// ros2vtk — RIHS01 type hashes of run-time type descriptions (DynamicType.hpp), the C++ port of
// generator/ros2vtk_gen/typehash.py: SHA-256 of Python's json.dumps(..., separators=(', ', ': '),
// ensure_ascii=True) of the description with the default values left out.
#include "ros2vtk/wire/DynamicType.hpp"
#include "ros2vtk/wire/Utf8.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>

namespace ros2vtk {
namespace wire {
namespace {

// FIPS 180-4 SHA-256; small and dependency free (the toolkit links no crypto library).
class Sha256
{
public:
  void update(const std::string& text)
  {
    for (unsigned char byte : text)
    {
      block_[block_size_++] = byte;
      if (block_size_ == 64)
      {
        compress();
        block_size_ = 0;
      }
    }
    length_ += text.size();
  }

  std::string hex_digest()
  {
    const uint64_t bits = length_ * 8;
    block_[block_size_++] = 0x80;
    if (block_size_ > 56)
    {
      while (block_size_ < 64)
        block_[block_size_++] = 0;
      compress();
      block_size_ = 0;
    }
    while (block_size_ < 56)
      block_[block_size_++] = 0;
    for (int i = 7; i >= 0; --i)
      block_[block_size_++] = static_cast<unsigned char>(bits >> (8 * i));
    compress();
    std::string hex;
    char digits[9];
    for (uint32_t word : state_)
    {
      std::snprintf(digits, sizeof(digits), "%08x", word);
      hex += digits;
    }
    return hex;
  }

private:
  static uint32_t rotr(uint32_t x, int n) { return (x >> n) | (x << (32 - n)); }

  void compress()
  {
    static const uint32_t k[64] = { 0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b,
      0x59f111f1, 0x923f82a4, 0xab1c5ed5, 0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3,
      0x72be5d74, 0x80deb1fe, 0x9bdc06a7, 0xc19bf174, 0xe49b69c1, 0xefbe4786, 0x0fc19dc6,
      0x240ca1cc, 0x2de92c6f, 0x4a7484aa, 0x5cb0a9dc, 0x76f988da, 0x983e5152, 0xa831c66d,
      0xb00327c8, 0xbf597fc7, 0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967, 0x27b70a85,
      0x2e1b2138, 0x4d2c6dfc, 0x53380d13, 0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85,
      0xa2bfe8a1, 0xa81a664b, 0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585,
      0x106aa070, 0x19a4c116, 0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a,
      0x5b9cca4f, 0x682e6ff3, 0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa,
      0xa4506ceb, 0xbef9a3f7, 0xc67178f2 };
    uint32_t w[64];
    for (int i = 0; i < 16; ++i)
    {
      w[i] = (uint32_t(block_[4 * i]) << 24) | (uint32_t(block_[4 * i + 1]) << 16) |
        (uint32_t(block_[4 * i + 2]) << 8) | uint32_t(block_[4 * i + 3]);
    }
    for (int i = 16; i < 64; ++i)
    {
      const uint32_t s0 = rotr(w[i - 15], 7) ^ rotr(w[i - 15], 18) ^ (w[i - 15] >> 3);
      const uint32_t s1 = rotr(w[i - 2], 17) ^ rotr(w[i - 2], 19) ^ (w[i - 2] >> 10);
      w[i] = w[i - 16] + s0 + w[i - 7] + s1;
    }
    uint32_t a = state_[0], b = state_[1], c = state_[2], d = state_[3];
    uint32_t e = state_[4], f = state_[5], g = state_[6], h = state_[7];
    for (int i = 0; i < 64; ++i)
    {
      const uint32_t s1 = rotr(e, 6) ^ rotr(e, 11) ^ rotr(e, 25);
      const uint32_t ch = (e & f) ^ (~e & g);
      const uint32_t t1 = h + s1 + ch + k[i] + w[i];
      const uint32_t s0 = rotr(a, 2) ^ rotr(a, 13) ^ rotr(a, 22);
      const uint32_t maj = (a & b) ^ (a & c) ^ (b & c);
      const uint32_t t2 = s0 + maj;
      h = g;
      g = f;
      f = e;
      e = d + t1;
      d = c;
      c = b;
      b = a;
      a = t1 + t2;
    }
    state_[0] += a;
    state_[1] += b;
    state_[2] += c;
    state_[3] += d;
    state_[4] += e;
    state_[5] += f;
    state_[6] += g;
    state_[7] += h;
  }

  std::array<uint32_t, 8> state_ = { 0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a, 0x510e527f,
    0x9b05688c, 0x1f83d9ab, 0x5be0cd19 };
  unsigned char block_[64] = {};
  size_t block_size_ = 0;
  uint64_t length_ = 0;
};

void append_escaped_unit(std::string& out, uint32_t unit)
{
  char text[16];
  std::snprintf(text, sizeof(text), "\\u%04x", static_cast<unsigned>(unit & 0xFFFF));
  out += text;
}

/// A JSON string as Python's json.dumps(ensure_ascii=True) writes it; false on invalid UTF-8.
bool append_json_string(std::string& out, const std::string& text)
{
  out += '"';
  size_t i = 0;
  while (i < text.size())
  {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c < 0x80)
    {
      switch (c)
      {
        case '"':
          out += "\\\"";
          break;
        case '\\':
          out += "\\\\";
          break;
        case '\n':
          out += "\\n";
          break;
        case '\r':
          out += "\\r";
          break;
        case '\t':
          out += "\\t";
          break;
        case '\b':
          out += "\\b";
          break;
        case '\f':
          out += "\\f";
          break;
        default:
          if (c < 0x20 || c == 0x7f)
            append_escaped_unit(out, c);
          else
            out += static_cast<char>(c);
      }
      ++i;
      continue;
    }
    size_t bad = 0;
    const size_t length = detail::utf8_sequence(text, i, &bad);
    if (length == 0)
    {
      return false;
    }
    uint32_t code = c & (0xFF >> (length + 1));
    for (size_t k = 1; k < length; ++k)
    {
      code = (code << 6) | (static_cast<unsigned char>(text[i + k]) & 0x3F);
    }
    if (code >= 0x10000)
    {
      code -= 0x10000;
      append_escaped_unit(out, 0xD800 + (code >> 10));
      append_escaped_unit(out, 0xDC00 + (code & 0x3FF));
    }
    else
    {
      append_escaped_unit(out, code);
    }
    i += length;
  }
  out += '"';
  return true;
}

bool append_individual(std::string& out, const IndividualDescription& type, std::string* error)
{
  out += "{\"type_name\": ";
  if (!append_json_string(out, type.type_name))
  {
    if (error)
      *error = "a type name is not valid UTF-8";
    return false;
  }
  out += ", \"fields\": [";
  for (size_t i = 0; i < type.fields.size(); ++i)
  {
    const DescriptionField& field = type.fields[i];
    if (i != 0)
      out += ", ";
    out += "{\"name\": ";
    std::string nested;
    if (!append_json_string(out, field.name) || !append_json_string(nested, field.nested_type_name))
    {
      if (error)
        *error = "a field name of " + clip_for_message(type.type_name) + " is not valid UTF-8";
      return false;
    }
    out += ", \"type\": {\"type_id\": " + std::to_string(field.type_id) +
      ", \"capacity\": " + std::to_string(field.capacity) +
      ", \"string_capacity\": " + std::to_string(field.string_capacity) +
      ", \"nested_type_name\": " + nested + "}}";
  }
  out += "]}";
  return true;
}

} // namespace

std::string type_description_hash(const TypeDescriptionData& description, std::string* error)
{
  std::vector<const IndividualDescription*> referenced;
  for (const IndividualDescription& type : description.referenced)
  {
    referenced.push_back(&type);
  }
  std::stable_sort(referenced.begin(), referenced.end(),
    [](const IndividualDescription* a, const IndividualDescription* b) {
      return a->type_name < b->type_name;
    });
  std::string json = "{\"type_description\": ";
  if (!append_individual(json, description.type, error))
  {
    return std::string();
  }
  json += ", \"referenced_type_descriptions\": [";
  for (size_t i = 0; i < referenced.size(); ++i)
  {
    if (i != 0)
      json += ", ";
    if (!append_individual(json, *referenced[i], error))
    {
      return std::string();
    }
  }
  json += "]}";
  Sha256 sha;
  sha.update(json);
  return "RIHS01_" + sha.hex_digest();
}

} // namespace wire
} // namespace ros2vtk
