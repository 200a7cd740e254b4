// Whole images are read by the reader their content names, among the formats each use accepts
// (image/image_reader.h): never by the file's extension, never by every reader OpenImageIO has.
#include "image/image_reader.h"

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <fstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "image/environment_loader.h"
#include "image/image_io.h"
#include "test_support.h"

namespace hipr {
namespace {

namespace fs = std::filesystem;

// The InputError's message, or "" when none is thrown.
template <typename F>
std::string input_error(F&& read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Writes `channels` float channels, each pixel's channel c holding c + 1.
void write_with_oiio(const fs::path& path, const char* format, int channels) {
  auto out = OIIO::ImageOutput::create(format);
  ASSERT_TRUE(out);
  const OIIO::ImageSpec spec(4, 2, channels, OIIO::TypeDesc::FLOAT);
  std::vector<float> pixels(size_t(4 * 2 * channels));
  for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = float(i % size_t(channels) + 1);
  ASSERT_TRUE(out->open(path.string(), spec));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
  ASSERT_TRUE(out->close());
}

TEST(ImageReader, TheContentNamesTheReaderNotTheExtension) {
  const fs::path dir = test::temp_dir("image_reader");
  write_image(dir / "render.exr", ImageRGB{4, 2, std::vector<float>(4 * 2 * 3, 0.25f)});
  fs::copy_file(dir / "render.exr", dir / "render.png", fs::copy_options::overwrite_existing);
  const ImageRGB image = read_image(dir / "render.png");  // OpenEXR, whatever its name says
  EXPECT_EQ(image.width, 4u);
  EXPECT_EQ(image.rgb, std::vector<float>(4 * 2 * 3, 0.25f));
  fs::copy_file(dir / "render.exr", dir / "map.hdr", fs::copy_options::overwrite_existing);
  EXPECT_EQ(load_environment(dir / "map.hdr").width, 4u);
}

TEST(ImageReader, FormatsOutsideTheUseAreRefusedInOneLine) {
  const fs::path dir = test::temp_dir("image_reader");
  // A TIFF named .hdr: OpenImageIO alone would find the TIFF reader for it.
  write_with_oiio(dir / "map.tif", "tiff", 3);
  fs::copy_file(dir / "map.tif", dir / "map.hdr", fs::copy_options::overwrite_existing);
  const std::string message = input_error([&] { load_environment(dir / "map.hdr"); });
  EXPECT_NE(message.find("is not OpenEXR or Radiance .hdr"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);
  // A PNG is an image to compare, not an environment map.
  write_png8(dir / "shot.png", 2, 2, 3, std::vector<uint8_t>(2 * 2 * 3, 128));
  EXPECT_EQ(read_image(dir / "shot.png").width, 2u);
  EXPECT_NE(input_error([&] { load_environment(dir / "shot.png"); }), "");
  // Bytes of no format, and an empty file.
  std::ofstream(dir / "noise.exr") << "BM not quite anything";
  EXPECT_NE(input_error([&] { read_image(dir / "noise.exr"); }).find("is not OpenEXR, PNG or"),
            std::string::npos);
  std::ofstream(dir / "empty.hdr").flush();
  EXPECT_NE(input_error([&] { load_environment(dir / "empty.hdr"); }), "");
  EXPECT_EQ(read_image_attribute(dir / "noise.exr", "hipr:spp"), "");
}

TEST(ImageReader, OnlyTheFirstThreeChannelsAreRead) {
  const fs::path dir = test::temp_dir("image_reader");
  write_with_oiio(dir / "layers.exr", "openexr", 7);  // channels hold 1, 2, ... 7
  const ImageRGB image = read_image(dir / "layers.exr");
  const Environment map = load_environment(dir / "layers.exr");
  ASSERT_EQ(image.rgb.size(), size_t(4 * 2 * 3));
  ASSERT_EQ(map.texels.size(), size_t(4 * 2));
  for (size_t i = 0; i < 4 * 2; ++i) {
    // OpenImageIO gives R, G, B first whatever order OpenEXR stores the channels in.
    EXPECT_EQ(image.rgb[3 * i], 1.0f);
    EXPECT_EQ(image.rgb[3 * i + 1], 2.0f);
    EXPECT_EQ(image.rgb[3 * i + 2], 3.0f);
    EXPECT_EQ(map.texels[i], glm::vec3(1.0f, 2.0f, 3.0f));
  }
  write_with_oiio(dir / "grey.exr", "openexr", 1);  // one channel: grey in all three
  const ImageRGB grey = read_image(dir / "grey.exr");
  EXPECT_EQ(grey.rgb, std::vector<float>(4 * 2 * 3, 1.0f));
  // Grey and alpha (a two-channel PNG): the grey in all three, as environment maps read it;
  // alpha is not a colour.
  auto out = OIIO::ImageOutput::create("png");
  ASSERT_TRUE(out);
  const std::vector<uint8_t> grey_alpha = {51, 255, 51, 255, 51, 255, 51, 255};
  ASSERT_TRUE(out->open((dir / "grey_alpha.png").string(),
                        OIIO::ImageSpec(2, 2, 2, OIIO::TypeDesc::UINT8)));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, grey_alpha.data()));
  ASSERT_TRUE(out->close());
  const ImageRGB shaded = read_image(dir / "grey_alpha.png");
  ASSERT_EQ(shaded.rgb.size(), size_t(2 * 2 * 3));
  for (size_t i = 0; i < 2 * 2; ++i) {
    EXPECT_NEAR(shaded.rgb[3 * i], 0.2f, 1e-6f);
    EXPECT_EQ(shaded.rgb[3 * i + 1], shaded.rgb[3 * i]);
    EXPECT_EQ(shaded.rgb[3 * i + 2], shaded.rgb[3 * i]);
  }
}

// A PNG's alpha is not a colour: its translucent pixels are read, and written, with the colours
// the file stores, the same as an opaque PNG of those colours (OpenImageIO's default multiplies
// them by alpha when reading and divides them by it when writing).
TEST(ImageReader, APngsColoursAreReadAsStoredWhateverItsAlpha) {
  const fs::path dir = test::temp_dir("image_reader");
  const std::vector<uint8_t> colours = {200, 100, 50, 10, 20, 30, 255, 128, 0, 90, 90, 90};
  std::vector<uint8_t> translucent;
  const uint8_t alphas[] = {128, 1, 255, 0};
  for (size_t i = 0; i < 4; ++i) {
    translucent.insert(translucent.end(), colours.begin() + 3 * i, colours.begin() + 3 * i + 3);
    translucent.push_back(alphas[i]);
  }
  write_png8(dir / "opaque.png", 2, 2, 3, colours);
  write_png8(dir / "translucent.png", 2, 2, 4, translucent);
  const ImageRGB opaque = read_image(dir / "opaque.png");
  const ImageRGB read = read_image(dir / "translucent.png");
  EXPECT_NEAR(opaque.rgb[0], 200.0f / 255.0f, 1e-6f);
  EXPECT_EQ(read.rgb, opaque.rgb);
}

// Every format's signature names it, from its own bytes only; one byte short, it names none.
TEST(ImageSignature, EachFormatIsKnownByItsFirstBytesAlone) {
  using namespace std::string_literals;  // (the signatures hold NUL bytes)
  const auto bytes = [](const std::string& text) {
    return std::vector<unsigned char>(text.begin(), text.end());
  };
  const std::vector<std::pair<std::vector<unsigned char>, ImageFormat>> files = {
      {bytes("\x76\x2f\x31\x01...."s), ImageFormat::OpenExr},
      {bytes("#?RADIANCE\n"s), ImageFormat::Radiance},
      {bytes("\x89PNG\r\n\x1a\n...."s), ImageFormat::Png},
      {bytes("RIFF\x10\0\0\0WEBPVP8 "s), ImageFormat::Webp},
      {bytes("DDS |\0\0\0"s), ImageFormat::Dds},
      {bytes("\0\0\0\x1c"
             "ftypavif"s),
       ImageFormat::Avif},
      {bytes("\0\0\0\x1c"
             "ftypavis"s),
       ImageFormat::Avif},
  };
  for (const auto& [file, format] : files) {
    EXPECT_EQ(image_format_of(file.data(), file.size()), format) << image_format_name(format);
    // The shortest prefix that names it: one byte less names nothing.
    size_t shortest = file.size();
    while (shortest > 0 && image_format_of(file.data(), shortest - 1) == format) --shortest;
    ASSERT_GT(shortest, 0u) << image_format_name(format);
    EXPECT_EQ(image_format_of(file.data(), shortest - 1), std::nullopt)
        << image_format_name(format);
  }
  // Another ISO media brand (HEIC) or RIFF form (WAVE) is not an image hipr reads.
  const std::vector<unsigned char> heic = bytes(
      "\0\0\0\x1c"
      "ftypheic"s);
  const std::vector<unsigned char> wave = bytes("RIFF\x10\0\0\0WAVEfmt "s);
  EXPECT_EQ(image_format_of(heic.data(), heic.size()), std::nullopt);
  EXPECT_EQ(image_format_of(wave.data(), wave.size()), std::nullopt);
}

}  // namespace
}  // namespace hipr
