// A PNG's chunk lengths are checked against the file before libpng allocates them
// (image/png_chunks.h): a few hostile bytes cannot claim gigabytes.
#include "image/png_chunks.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/file_util.h"
#include "image/image_io.h"
#include "test_support.h"

namespace hipr {
namespace {

namespace fs = std::filesystem;

void write_bytes(const fs::path& path, const std::vector<uint8_t>& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// The chunk walk over a PNG file as the image reader runs it.
void walk(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  scan_png_chunks(in, fs::file_size(path), path.string());
}

// The InputError's message, or "" when none is thrown.
std::string refusal(const fs::path& path) {
  try {
    (void)read_image(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(PngChunks, RealPngsAreWalkedWhole) {
  const fs::path dir = test::temp_dir("png_chunks");
  write_png8(dir / "written.png", 3, 2, 4, std::vector<uint8_t>(3 * 2 * 4, 77));
  std::vector<fs::path> pngs = {dir / "written.png"};
  // The README's pictures: PNGs other tools wrote, with their own ancillary chunks.
  for (const auto& entry :
       fs::directory_iterator(fs::path(HIPR_TEST_DATA_DIR) / ".." / ".." / "docs"))
    if (entry.path().extension() == ".png") pngs.push_back(entry.path());
  ASSERT_GT(pngs.size(), 1u);
  for (const fs::path& png : pngs) {
    EXPECT_NO_THROW(walk(png)) << png;
    EXPECT_EQ(refusal(png), "") << png;
  }
}

TEST(PngChunks, AChunkLongerThanTheFileIsRefusedBeforeLibpngAllocatesIt) {
  const fs::path dir = test::temp_dir("png_chunks");
  // Kept from the fuzzer: a 4 x 4 grey PNG whose second tEXt chunk claims 1,953,066,862 bytes
  // (libpng allocated them all: 2 GB and 12 s under AddressSanitizer).
  const fs::path found =
      fs::path(HIPR_TEST_DATA_DIR) / "fuzz" / "image" / "png_text_chunk_claims_2gb.png";
  EXPECT_NE(refusal(found).find("has a tEXt chunk of 1953066862 bytes that runs past the end"),
            std::string::npos)
      << refusal(found);
  // A PNG cut short inside its image data: the IDAT chunk no longer fits.
  write_png8(dir / "whole.png", 8, 8, 3, std::vector<uint8_t>(8 * 8 * 3, 200));
  std::vector<uint8_t> bytes = read_file_bytes(dir / "whole.png");
  ASSERT_GT(bytes.size(), 40u);
  bytes.resize(bytes.size() - 20);  // IEND is 12 bytes: 8 more come off the IDAT chunk
  write_bytes(dir / "cut.png", bytes);
  EXPECT_NE(refusal(dir / "cut.png").find("IDAT chunk"), std::string::npos)
      << refusal(dir / "cut.png");
  // A length beyond PNG's 2^31 - 1, whatever the file's size.
  bytes = read_file_bytes(dir / "whole.png");
  const size_t ihdr_length_at = 8;
  bytes[ihdr_length_at] = 0xff;
  write_bytes(dir / "huge_length.png", bytes);
  EXPECT_NE(refusal(dir / "huge_length.png").find("IHDR chunk of 4278190093 bytes"),
            std::string::npos)
      << refusal(dir / "huge_length.png");
}

}  // namespace
}  // namespace hipr
