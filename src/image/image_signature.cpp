#include "image/image_signature.h"

#include <array>
#include <cstring>

namespace hipr {
namespace {

struct Signature {
  ImageFormat format;
  const char* name;
  size_t at;          // where the bytes are
  const char* bytes;  // what every file of the format has there
  size_t size;
  const char* also;  // and, when not null, these 4 bytes at 8 (WebP's form type, AVIF's brand)
};

// AVIF has two brands (a still image, a sequence): two rows.
constexpr std::array<Signature, 7> kSignatures{{
    {ImageFormat::OpenExr, "OpenEXR", 0, "\x76\x2f\x31\x01", 4, nullptr},
    {ImageFormat::Radiance, "Radiance .hdr", 0, "#?", 2, nullptr},  // #?RADIANCE or #?RGBE
    {ImageFormat::Png, "PNG", 0, "\x89PNG\r\n\x1a\n", 8, nullptr},
    {ImageFormat::Webp, "WebP", 0, "RIFF", 4, "WEBP"},
    {ImageFormat::Dds, "DDS", 0, "DDS ", 4, nullptr},
    {ImageFormat::Avif, "AVIF", 4, "ftyp", 4, "avif"},
    {ImageFormat::Avif, "AVIF", 4, "ftyp", 4, "avis"},
}};

bool holds(const unsigned char* bytes, size_t size, size_t at, const char* tag, size_t n) {
  return size >= at + n && std::memcmp(bytes + at, tag, n) == 0;
}

}  // namespace

std::optional<ImageFormat> image_format_of(const unsigned char* bytes, size_t size) {
  for (const Signature& s : kSignatures)
    if (holds(bytes, size, s.at, s.bytes, s.size) && (!s.also || holds(bytes, size, 8, s.also, 4)))
      return s.format;
  return std::nullopt;
}

const char* image_format_name(ImageFormat format) {
  for (const Signature& s : kSignatures)
    if (s.format == format) return s.name;
  return "an unknown format";
}

}  // namespace hipr
