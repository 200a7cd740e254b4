#include "image/exr_header.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <fstream>
#include <string>

#include "core/error.h"

namespace hipr {
namespace {

constexpr std::array<unsigned char, 4> kMagic = {0x76, 0x2f, 0x31, 0x01};
constexpr uint32_t kLongNamesFlag = 0x400;  // names up to 255 bytes instead of 31
constexpr uint32_t kMultipartFlag = 0x1000;

uint32_t little_endian_u32(const unsigned char* p) {
  return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

// A forward reader over the file that knows how many bytes remain, so every claimed size is
// checked against the file before anything is read or allocated.
class HeaderReader {
 public:
  HeaderReader(const std::filesystem::path& path, uintmax_t size)
      : path_(path), in_(path, std::ios::binary), remaining_(size) {
    if (!in_) fail("cannot be opened");
  }

  [[noreturn]] void fail(const std::string& why) const {
    throw InputError("OpenEXR file " + path_.string() + " " + why);
  }

  void read(void* out, uintmax_t count) {
    if (count > remaining_) fail("has a header that runs past the end of the file");
    in_.read(static_cast<char*>(out), std::streamsize(count));
    if (!in_) fail("cannot be read");
    remaining_ -= count;
  }

  void skip(uintmax_t count) {
    if (count > remaining_) fail("has a header attribute larger than the file");
    in_.seekg(std::streamoff(count), std::ios::cur);
    remaining_ -= count;
  }

  // A NUL-terminated name of at most max_length bytes ("" ends a header).
  std::string name(size_t max_length) {
    std::string text;
    for (;;) {
      char c = 0;
      read(&c, 1);
      if (c == '\0') return text;
      if (text.size() == max_length) fail("has an attribute name longer than OpenEXR allows");
      text.push_back(c);
    }
  }

 private:
  const std::filesystem::path& path_;
  std::ifstream in_;
  uintmax_t remaining_;
};

}  // namespace

std::optional<ExrDataWindow> scan_exr_header(const std::filesystem::path& path) {
  std::error_code ec;
  const uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) return std::nullopt;  // the caller's own open reports a missing file
  std::array<unsigned char, 8> start{};
  {
    std::ifstream in(path, std::ios::binary);
    if (!in.read(reinterpret_cast<char*>(start.data()), 8)) return std::nullopt;
  }
  if (std::memcmp(start.data(), kMagic.data(), kMagic.size()) != 0) return std::nullopt;

  HeaderReader reader(path, size);
  reader.skip(8);
  const uint32_t version = little_endian_u32(start.data() + 4);
  const size_t max_name = (version & kLongNamesFlag) ? 255 : 31;
  const bool multipart = (version & kMultipartFlag) != 0;

  std::optional<ExrDataWindow> largest;
  for (int part = 0;; ++part) {
    std::optional<ExrDataWindow> window;
    bool empty_header = true;
    for (;;) {
      const std::string attribute = reader.name(max_name);
      if (attribute.empty()) break;
      empty_header = false;
      const std::string type = reader.name(max_name);
      unsigned char size_bytes[4];
      reader.read(size_bytes, 4);
      const int32_t value_size = int32_t(little_endian_u32(size_bytes));
      if (value_size < 0) reader.fail("has an attribute of negative size");
      if (attribute == "dataWindow") {
        if (type != "box2i" || value_size != 16) reader.fail("has a malformed dataWindow");
        unsigned char box[16];
        reader.read(box, 16);
        const int64_t x_min = int32_t(little_endian_u32(box));
        const int64_t y_min = int32_t(little_endian_u32(box + 4));
        const int64_t x_max = int32_t(little_endian_u32(box + 8));
        const int64_t y_max = int32_t(little_endian_u32(box + 12));
        if (x_max < x_min || y_max < y_min) reader.fail("has an empty dataWindow");
        window = ExrDataWindow{x_max - x_min + 1, y_max - y_min + 1};
      } else {
        reader.skip(uintmax_t(value_size));
      }
    }
    // A multi-part file's header list ends with an empty header; a single part has one header.
    if (multipart && empty_header && part > 0) break;
    if (!window) reader.fail("has a header without a dataWindow");
    // Sides reach 2^32: compared as doubles, whose products cannot wrap.
    if (!largest || double(window->width) * double(window->height) >
                        double(largest->width) * double(largest->height))
      largest = window;
    if (!multipart) break;
  }
  return largest;
}

bool plausible_image_size(int64_t width, int64_t height, uintmax_t file_bytes) {
  constexpr int64_t kMaxSide = int64_t(1) << 31;  // sides up to 2^31: the product fits 64 bits
  if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide) return false;
  return uintmax_t(width) * uintmax_t(height) <= std::max<uintmax_t>(file_bytes, 4096) * 1024;
}

}  // namespace hipr
