#include "image/image_reader.h"

#include <array>
#include <cstring>
#include <fstream>

#include "core/error.h"

namespace hipr {
namespace {

struct FormatInfo {
  ImageFormat format;
  const char* reader;  // OpenImageIO's name for its reader
  const char* name;    // as the error message says it
  const char* magic;   // the bytes every file of the format starts with
  size_t magic_size;
};

constexpr std::array<FormatInfo, 3> kFormats{{
    {ImageFormat::OpenExr, "openexr", "OpenEXR", "\x76\x2f\x31\x01", 4},
    {ImageFormat::Radiance, "hdr", "Radiance .hdr", "#?", 2},  // #?RADIANCE or #?RGBE
    {ImageFormat::Png, "png", "PNG", "\x89PNG\r\n\x1a\n", 8},
}};

const FormatInfo& info_of(ImageFormat format) {
  for (const FormatInfo& info : kFormats)
    if (info.format == format) return info;
  throw InternalError("open_image_reader: unknown image format");
}

}  // namespace

std::unique_ptr<OIIO::ImageInput> open_image_reader(const std::filesystem::path& path,
                                                    std::initializer_list<ImageFormat> accepted,
                                                    const std::string& what) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError("cannot read " + what + " " + path.string());
  std::array<char, 8> head{};
  file.read(head.data(), std::streamsize(head.size()));
  const size_t size = size_t(file.gcount());
  std::string names;  // "A", "A or B", "A, B or C"
  size_t named = 0;
  for (const ImageFormat format : accepted) {
    const FormatInfo& info = info_of(format);
    ++named;
    names += std::string(named == 1 ? "" : named == accepted.size() ? " or " : ", ") + info.name;
    if (size < info.magic_size || std::memcmp(head.data(), info.magic, info.magic_size) != 0)
      continue;
    std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::create(info.reader);
    if (!input) throw InternalError(std::string("OpenImageIO has no ") + info.reader + " reader");
    OIIO::ImageSpec spec;
    if (!input->open(path.string(), spec))
      throw InputError("cannot read " + what + " " + path.string() + ": " + input->geterror());
    return input;
  }
  throw InputError(what + " " + path.string() + " is not " + names);
}

}  // namespace hipr
