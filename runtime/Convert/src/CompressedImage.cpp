// ros2vtk — PNG / JPEG bytes <-> vtkImageData through VTK's image readers and writers
// (CompressedImage.hpp). The codecs report problems through VTK error events; an observer keeps
// them out of the output window and turns them into the returned reason.
#include "ros2vtk/convert/CompressedImage.hpp"

#include "Validation.hpp"

#include <vtkCommand.h>
#include <vtkExecutive.h>
#include <vtkImageData.h>
#include <vtkImageReader2.h>
#include <vtkImageWriter.h>
#include <vtkJPEGReader.h>
#include <vtkJPEGWriter.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtk_zlib.h>

#include <cstring>

namespace ros2vtk {
namespace convert {

using detail::fail;

namespace {

/// Collects the first error (and warning) text a VTK algorithm reports.
class ErrorCatcher : public vtkCommand
{
public:
  static ErrorCatcher* New() { return new ErrorCatcher; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    if (event == vtkCommand::ErrorEvent && this->Text.empty())
    {
      this->Text = data ? static_cast<const char*>(data) : "unknown error";
      while (!this->Text.empty() && (this->Text.back() == '\n' || this->Text.back() == ' '))
      {
        this->Text.pop_back();
      }
    }
  }
  std::string Text;
};

bool starts_with(const std::vector<uint8_t>& data, const uint8_t* magic, size_t size)
{
  return data.size() >= size && std::memcmp(data.data(), magic, size) == 0;
}

uint32_t be32(const uint8_t* p)
{
  return (uint32_t(p[0]) << 24) | (uint32_t(p[1]) << 16) | (uint32_t(p[2]) << 8) | uint32_t(p[3]);
}

/// vtkPNGReader (VTK 9.1) sets no setjmp point, so any libpng error on bad bytes would jump
/// into nowhere and crash the process. Everything libpng treats as an error is therefore
/// checked here first: chunk bounds and CRCs, IHDR, unknown critical chunks, PLTE for palette
/// images, and that the IDAT stream inflates to exactly the rows the header promises with
/// valid filter bytes. Returns "" when libpng will read the data, else the reason.
std::string png_problem(const std::vector<uint8_t>& d)
{
  size_t pos = 8;
  bool first = true, ended = false, hasPalette = false, idatDone = false;
  uint32_t width = 0, height = 0;
  int depth = 0, colorType = 0, interlace = 0;
  std::vector<uint8_t> idat;
  while (!ended)
  {
    if (d.size() - pos < 12)
    {
      return "the data ends before the IEND chunk (truncated?)";
    }
    const uint32_t length = be32(&d[pos]);
    const std::string type(reinterpret_cast<const char*>(&d[pos + 4]), 4);
    if (length > d.size() - pos - 12)
    {
      return "chunk '" + type + "' runs past the end of the data (truncated?)";
    }
    const uint8_t* body = &d[pos + 8];
    const uLong crc = crc32(crc32(0L, Z_NULL, 0), &d[pos + 4], static_cast<uInt>(length + 4));
    if (crc != be32(body + length))
    {
      return "chunk '" + type + "' has a bad CRC";
    }
    if (first != (type == "IHDR"))
    {
      return first ? "the first chunk is not IHDR" : "a second IHDR chunk";
    }
    first = false;
    if (type == "IHDR")
    {
      if (length != 13)
      {
        return "IHDR is not 13 bytes";
      }
      width = be32(body);
      height = be32(body + 4);
      depth = body[8];
      colorType = body[9];
      interlace = body[12];
      const bool depthOk =
        (colorType == 0 && (depth == 1 || depth == 2 || depth == 4 || depth == 8 || depth == 16)) ||
        (colorType == 3 && (depth == 1 || depth == 2 || depth == 4 || depth == 8)) ||
        ((colorType == 2 || colorType == 4 || colorType == 6) && (depth == 8 || depth == 16));
      if (width < 1 || height < 1 || width > 1000000 || height > 1000000 || !depthOk ||
        body[10] != 0 || body[11] != 0 || interlace > 1)
      {
        return "IHDR is invalid (size, bit depth, colour type or method)";
      }
    }
    else if (type == "PLTE")
    {
      hasPalette = true;
    }
    else if (type == "IDAT")
    {
      if (idatDone)
      {
        return "IDAT chunks are not consecutive";
      }
      idat.insert(idat.end(), body, body + length);
    }
    else if (type == "IEND")
    {
      ended = true;
    }
    else if (type[0] >= 'A' && type[0] <= 'Z')
    {
      return "unknown critical chunk '" + type + "'";
    }
    if (!idat.empty() && type != "IDAT")
    {
      idatDone = true;
    }
    pos += 12 + length;
  }
  if (idat.empty())
  {
    return "no IDAT chunk";
  }
  if (colorType == 3 && !hasPalette)
  {
    return "a palette image without PLTE";
  }
  const int channels[7] = { 1, 0, 3, 1, 2, 0, 4 };
  const uint64_t bitsPerPixel = static_cast<uint64_t>(channels[colorType]) * depth;
  // The filtered rows of every pass (one pass unless Adam7-interlaced).
  std::vector<std::pair<uint64_t, uint64_t>> passes; // rows, bytes per row without the filter byte
  const uint32_t x0[7] = { 0, 4, 0, 2, 0, 1, 0 }, y0[7] = { 0, 0, 4, 0, 2, 0, 1 };
  const uint32_t dx[7] = { 8, 8, 4, 4, 2, 2, 1 }, dy[7] = { 8, 8, 8, 4, 4, 2, 2 };
  for (int p = 0; p < (interlace ? 7 : 1); ++p)
  {
    const uint64_t w =
      interlace ? (width > x0[p] ? (width - x0[p] + dx[p] - 1) / dx[p] : 0) : width;
    const uint64_t h =
      interlace ? (height > y0[p] ? (height - y0[p] + dy[p] - 1) / dy[p] : 0) : height;
    if (w > 0 && h > 0)
    {
      passes.emplace_back(h, (w * bitsPerPixel + 7) / 8);
    }
  }
  uint64_t expected = 0;
  for (const auto& pass : passes)
  {
    expected += pass.first * (pass.second + 1);
  }
  if (expected > (uint64_t(1) << 30))
  {
    return "the image is larger than 1 GiB";
  }
  std::vector<uint8_t> raw(static_cast<size_t>(expected) + 1);
  z_stream stream{};
  if (inflateInit(&stream) != Z_OK)
  {
    return "zlib cannot start";
  }
  stream.next_in = idat.data();
  stream.avail_in = static_cast<uInt>(idat.size());
  stream.next_out = raw.data();
  stream.avail_out = static_cast<uInt>(raw.size());
  const int status = inflate(&stream, Z_FINISH);
  const uint64_t produced = stream.total_out;
  inflateEnd(&stream);
  if (status != Z_STREAM_END || produced != expected)
  {
    return "the image data does not inflate to the " + std::to_string(expected) +
      " bytes the header promises";
  }
  size_t at = 0;
  for (const auto& pass : passes)
  {
    for (uint64_t row = 0; row < pass.first; ++row)
    {
      if (raw[at] > 4)
      {
        return "a row has an invalid filter type";
      }
      at += static_cast<size_t>(pass.second) + 1;
    }
  }
  return "";
}

// What is wrong with JPEG data, checked up to the start of the scan, or "". VTK 9.1's memory
// source for libjpeg reads past the end of the buffer when a marker segment's length runs past it
// (a segfault under AddressSanitizer on mutated data, reading whatever follows the buffer
// otherwise), so every segment before the scan must fit before libjpeg sees the bytes.
std::string jpeg_problem(const std::vector<uint8_t>& d)
{
  size_t at = 2; // after SOI
  bool frame = false;
  while (true)
  {
    if (at >= d.size() || d[at] != 0xff)
    {
      return "no marker at byte " + std::to_string(at);
    }
    while (at < d.size() && d[at] == 0xff)
    {
      ++at; // fill bytes
    }
    if (at >= d.size())
    {
      return "the data ends inside a marker";
    }
    const uint8_t marker = d[at++];
    if (marker == 0x01 || (marker >= 0xd0 && marker <= 0xd7))
    {
      continue; // TEM, RSTn: no length
    }
    if (marker == 0xd8 || marker == 0xd9 || marker == 0x00)
    {
      return "unexpected marker 0xff" +
        std::string(marker == 0x00 ? "00"
            : marker == 0xd8       ? "d8"
                                   : "d9") +
        " before the scan";
    }
    if (at + 2 > d.size())
    {
      return "the data ends inside a segment length";
    }
    const size_t length = (size_t(d[at]) << 8) | d[at + 1];
    if (length < 2 || at + length > d.size())
    {
      return "a segment of " + std::to_string(length) + " bytes at byte " + std::to_string(at) +
        " runs past the end of the data (" + std::to_string(d.size()) + " bytes)";
    }
    if (marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 && marker != 0xcc)
    {
      frame = true; // SOFn
    }
    at += length;
    if (marker == 0xda) // SOS: the entropy-coded data follows
    {
      if (!frame)
      {
        return "a scan before any frame header";
      }
      return at < d.size() ? "" : "no data after the scan header";
    }
  }
}

} // namespace

bool compressed_to_image(const std::string& format, const std::vector<uint8_t>& data,
  vtkImageData* image, std::string* error)
{
  const char* where = "compressed_to_image";
  if (!image)
  {
    return fail(error, where, "output image is null");
  }
  static const uint8_t png[8] = { 0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a };
  static const uint8_t jpeg[3] = { 0xff, 0xd8, 0xff };
  vtkSmartPointer<vtkImageReader2> reader;
  if (starts_with(data, png, sizeof(png)))
  {
    const std::string problem = png_problem(data);
    if (!problem.empty())
    {
      return fail(error, where,
        "cannot decode the PNG data (format '" + format + "', " + std::to_string(data.size()) +
          " bytes): " + problem);
    }
    reader = vtkSmartPointer<vtkPNGReader>::New();
  }
  else if (starts_with(data, jpeg, sizeof(jpeg)))
  {
    const std::string problem = jpeg_problem(data);
    if (!problem.empty())
    {
      return fail(error, where,
        "cannot decode the JPEG data (format '" + format + "', " + std::to_string(data.size()) +
          " bytes): " + problem);
    }
    reader = vtkSmartPointer<vtkJPEGReader>::New();
  }
  else
  {
    return fail(error, where,
      "the " + std::to_string(data.size()) + " bytes (format '" + format +
        "') are neither PNG nor JPEG");
  }
  vtkNew<ErrorCatcher> catcher;
  reader->AddObserver(vtkCommand::ErrorEvent, catcher);
  reader->AddObserver(vtkCommand::WarningEvent, catcher);
  // A reader that fails makes its executive report "returned failure" too: the same reason.
  vtkNew<ErrorCatcher> executiveCatcher;
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executiveCatcher);
  reader->SetMemoryBuffer(data.data());
  reader->SetMemoryBufferLength(static_cast<vtkIdType>(data.size()));
  reader->Update();
  vtkImageData* decoded = reader->GetOutput();
  const int* dims = decoded ? decoded->GetDimensions() : nullptr;
  vtkDataArray* scalars = decoded ? decoded->GetPointData()->GetScalars() : nullptr;
  if (!catcher->Text.empty() || reader->GetErrorCode() != 0 || !scalars || !dims || dims[0] < 1 ||
    dims[1] < 1 ||
    scalars->GetNumberOfTuples() != static_cast<vtkIdType>(dims[0]) * dims[1] * dims[2])
  {
    return fail(error, where,
      std::string("cannot decode the ") + reader->GetDescriptiveName() + " data (format '" +
        format + "', " + std::to_string(data.size()) + " bytes)" +
        (catcher->Text.empty() ? std::string() : ": " + catcher->Text));
  }
  image->DeepCopy(decoded);
  image->SetOrigin(0.0, 0.0, 0.0);
  image->SetSpacing(1.0, 1.0, 1.0);
  image->Modified();
  return true;
}

bool image_to_compressed(vtkImageData* image, const std::string& codec, std::string* format,
  std::vector<uint8_t>* data, std::string* error)
{
  const char* where = "image_to_compressed";
  if (!image || !format || !data)
  {
    return fail(error, where, image ? "output pointer is null" : "input image is null");
  }
  const bool isPng = codec.empty() || codec == "png";
  const bool isJpeg = codec == "jpeg" || codec == "jpg";
  if (!isPng && !isJpeg)
  {
    return fail(error, where, "encoding '" + codec + "' is neither png nor jpeg");
  }
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  const int* dims = image->GetDimensions();
  if (!scalars || dims[0] < 1 || dims[1] < 1)
  {
    return fail(error, where, "the image has no scalars");
  }
  if (dims[2] != 1)
  {
    return fail(error, where, "the image has " + std::to_string(dims[2]) + " slices, not 1");
  }
  const int type = scalars->GetDataType();
  const int components = scalars->GetNumberOfComponents();
  if (isPng &&
    ((type != VTK_UNSIGNED_CHAR && type != VTK_UNSIGNED_SHORT) || components < 1 || components > 4))
  {
    return fail(error, where,
      std::string(
        "png takes unsigned char or unsigned short scalars with 1 to 4 components, not ") +
        scalars->GetDataTypeAsString() + " x " + std::to_string(components));
  }
  if (isJpeg && (type != VTK_UNSIGNED_CHAR || (components != 1 && components != 3)))
  {
    return fail(error, where,
      std::string("jpeg takes unsigned char scalars with 1 or 3 components, not ") +
        scalars->GetDataTypeAsString() + " x " + std::to_string(components));
  }
  vtkSmartPointer<vtkImageWriter> writer;
  vtkUnsignedCharArray* result = nullptr;
  vtkNew<ErrorCatcher> catcher;
  if (isPng)
  {
    auto png = vtkSmartPointer<vtkPNGWriter>::New();
    png->WriteToMemoryOn();
    writer = png;
  }
  else
  {
    auto jpeg = vtkSmartPointer<vtkJPEGWriter>::New();
    jpeg->WriteToMemoryOn();
    writer = jpeg;
  }
  writer->AddObserver(vtkCommand::ErrorEvent, catcher);
  writer->SetInputData(image);
  writer->Write();
  if (isPng)
  {
    result = vtkPNGWriter::SafeDownCast(writer)->GetResult();
  }
  else
  {
    result = vtkJPEGWriter::SafeDownCast(writer)->GetResult();
  }
  if (!catcher->Text.empty() || !result || result->GetNumberOfValues() == 0)
  {
    return fail(error, where,
      std::string("the ") + (isPng ? "png" : "jpeg") + " writer failed" +
        (catcher->Text.empty() ? std::string() : ": " + catcher->Text));
  }
  const unsigned char* bytes = result->GetPointer(0);
  data->assign(bytes, bytes + result->GetNumberOfValues());
  *format = isPng ? "png" : "jpeg";
  return true;
}

} // namespace convert
} // namespace ros2vtk
