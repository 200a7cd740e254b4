// The OpenEXR header walk (image/exr_header.h) that runs before OpenEXR: real files pass with
// their size, hostile headers are refused in microseconds instead of gigabytes.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "image/environment_loader.h"
#include "image/exr_header.h"
#include "image/image_io.h"
#include "test_support.h"

namespace hipr {
namespace {

namespace fs = std::filesystem;

// Builds a single-part header attribute by attribute, as the OpenEXR file layout describes it.
class ExrBytes {
 public:
  explicit ExrBytes(uint32_t version = 2) {
    bytes_ = {0x76, 0x2f, 0x31, 0x01};
    u32(version);
  }
  ExrBytes& attribute(const std::string& name, const std::string& type, int32_t size,
                      const std::vector<uint8_t>& value) {
    text(name);
    text(type);
    u32(uint32_t(size));
    bytes_.insert(bytes_.end(), value.begin(), value.end());
    return *this;
  }
  ExrBytes& data_window(int32_t x0, int32_t y0, int32_t x1, int32_t y1) {
    std::vector<uint8_t> box;
    for (int32_t v : {x0, y0, x1, y1})
      for (int k = 0; k < 4; ++k) box.push_back(uint8_t(uint32_t(v) >> (8 * k)));
    return attribute("dataWindow", "box2i", 16, box);
  }
  ExrBytes& end_header() {
    bytes_.push_back(0);
    return *this;
  }
  fs::path write(const std::string& name) const {
    const fs::path path = test::temp_dir("exr_header") / name;
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes_.data()), std::streamsize(bytes_.size()));
    return path;
  }

 private:
  void u32(uint32_t v) {
    for (int k = 0; k < 4; ++k) bytes_.push_back(uint8_t(v >> (8 * k)));
  }
  void text(const std::string& s) {
    bytes_.insert(bytes_.end(), s.begin(), s.end());
    bytes_.push_back(0);
  }
  std::vector<uint8_t> bytes_;
};

TEST(ExrHeader, ARealFileGivesItsDataWindow) {
  const fs::path path = test::temp_dir("exr_header") / "real.exr";
  write_image(path, ImageRGB{6, 3, std::vector<float>(6 * 3 * 3, 0.5f)});
  const auto window = scan_exr_header(path);
  ASSERT_TRUE(window.has_value());
  EXPECT_EQ(window->width, 6);
  EXPECT_EQ(window->height, 3);
  EXPECT_EQ(read_image(path).width, 6u);
}

TEST(ExrHeader, OtherFilesAreNotItsBusiness) {
  const fs::path path = test::temp_dir("exr_header") / "image.hdr";
  std::ofstream(path) << "#?RADIANCE\n";
  EXPECT_FALSE(scan_exr_header(path).has_value());
  EXPECT_FALSE(scan_exr_header(path.parent_path() / "missing.exr").has_value());
}

TEST(ExrHeader, AnAttributeLargerThanTheFileIsRefused) {
  // OpenEXR would allocate the claimed 1.9 GB before finding the file short.
  const fs::path path = ExrBytes()
                            .attribute("comments", "string", 0x74746173, {'a', 'b'})
                            .data_window(0, 0, 7, 3)
                            .end_header()
                            .write("huge_attribute.exr");
  EXPECT_THROW(scan_exr_header(path), InputError);
  EXPECT_THROW(load_environment(path), InputError);
  EXPECT_THROW(read_image(path), InputError);
}

TEST(ExrHeader, MalformedHeadersAreRefused) {
  EXPECT_THROW(scan_exr_header(ExrBytes().data_window(0, 0, 7, 3).write("unterminated.exr")),
               InputError);
  EXPECT_THROW(scan_exr_header(ExrBytes().end_header().write("no_window.exr")), InputError);
  EXPECT_THROW(scan_exr_header(ExrBytes().data_window(5, 0, 4, 3).end_header().write("empty.exr")),
               InputError);
  EXPECT_THROW(scan_exr_header(ExrBytes()
                                   .attribute(std::string(40, 'n'), "int", 4, {0, 0, 0, 0})
                                   .data_window(0, 0, 7, 3)
                                   .end_header()
                                   .write("long_name.exr")),
               InputError);
  EXPECT_THROW(scan_exr_header(ExrBytes()
                                   .attribute("x", "int", -4, {})
                                   .data_window(0, 0, 7, 3)
                                   .end_header()
                                   .write("negative_size.exr")),
               InputError);
}

TEST(ExrHeader, LongNamesNeedTheirFlag) {
  const std::string name(40, 'n');
  const auto file = [&](uint32_t version, const char* file_name) {
    return ExrBytes(version)
        .attribute(name, "int", 4, {0, 0, 0, 0})
        .data_window(0, 0, 7, 3)
        .end_header()
        .write(file_name);
  };
  EXPECT_TRUE(scan_exr_header(file(2 | 0x400, "long_names.exr")).has_value());
  EXPECT_THROW(scan_exr_header(file(2, "short_names.exr")), InputError);
}

TEST(ExrHeader, EveryPartOfAMultipartFileIsWalkedAndTheLargestReported) {
  const fs::path path = ExrBytes(2 | 0x1000)
                            .data_window(0, 0, 3, 3)
                            .end_header()
                            .data_window(0, 0, 99, 49)
                            .end_header()
                            .end_header()  // the empty header that ends the list
                            .write("parts.exr");
  const auto window = scan_exr_header(path);
  ASSERT_TRUE(window.has_value());
  EXPECT_EQ(window->width, 100);
  EXPECT_EQ(window->height, 50);
  // A second part that claims more than the file is refused like the first.
  EXPECT_THROW(scan_exr_header(ExrBytes(2 | 0x1000)
                                   .data_window(0, 0, 3, 3)
                                   .end_header()
                                   .attribute("x", "string", 1 << 30, {})
                                   .write("bad_second_part.exr")),
               InputError);
  // Without the list's end, the walk runs past the file.
  EXPECT_THROW(
      scan_exr_header(
          ExrBytes(2 | 0x1000).data_window(0, 0, 3, 3).end_header().write("unended_parts.exr")),
      InputError);
}

TEST(ExrHeader, PlausibleSizesNeverOverflow) {
  EXPECT_TRUE(plausible_image_size(4, 2, 100));
  EXPECT_FALSE(plausible_image_size(0, 2, 100));
  // 2^32 x 2^32 would wrap to 0 in 64 bits.
  EXPECT_FALSE(plausible_image_size(int64_t(1) << 32, int64_t(1) << 32, 1u << 20));
  EXPECT_FALSE(plausible_image_size(int64_t(1) << 20, int64_t(1) << 20, 1u << 20));
  EXPECT_TRUE(plausible_image_size(1 << 10, 1 << 10, 1u << 20));
}

TEST(ExrHeader, AWindowBeyondTheFileIsRefusedBeforeOpenExrSeesIt) {
  // A valid header claiming 2^31 x 2^31 texels in a few dozen bytes.
  const fs::path path = ExrBytes()
                            .data_window(-1073741824, -1073741824, 1073741823, 1073741823)
                            .end_header()
                            .write("vast_window.exr");
  const auto window = scan_exr_header(path);
  ASSERT_TRUE(window.has_value());
  EXPECT_EQ(window->width, int64_t(1) << 31);
  EXPECT_THROW(load_environment(path), InputError);
  EXPECT_THROW(read_image(path), InputError);
  EXPECT_EQ(read_image_attribute(path, "hipr:spp"), "");
}

TEST(ExrHeader, AMapLargerThanHiprReadsIsRefusedBeforeOpenExrSeesIt) {
  // 16385 x 8192 texels, one row over the environment maps' 2^27, in a file large enough to
  // hold them by plausible_image_size (a long comment pads it).
  const fs::path path =
      ExrBytes()
          .attribute("comments", "string", 140000, std::vector<uint8_t>(140000, 'x'))
          .data_window(0, 0, 16384, 8191)
          .end_header()
          .write("wide_map.exr");
  ASSERT_TRUE(plausible_image_size(16385, 8192, fs::file_size(path)));
  try {
    load_environment(path);
    ADD_FAILURE() << "a map beyond 2^27 texels was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is larger (16385x8192) than hipr reads"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace hipr
