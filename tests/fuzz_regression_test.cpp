// Every input kept in tests/data/fuzz/<target>/ (found by tools/fuzz.sh, or written by hand for a
// known danger) goes through the fuzz targets' own code: it must load or be refused with an
// InputError, never crash, throw anything else or read outside its folder.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <vector>

#include "fuzz/fuzz_inputs.h"
#include "test_support.h"

namespace hipr {
namespace {

namespace fs = std::filesystem;

const fs::path kInputs = fs::path(HIPR_TEST_DATA_DIR) / "fuzz";

std::vector<uint8_t> bytes_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

template <typename Run>
void replay_all(const char* target, Run run) {
  size_t count = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(kInputs / target)) {
    const std::vector<uint8_t> data = bytes_of(entry.path());
    EXPECT_NO_THROW(run(data)) << entry.path();
    ++count;
  }
  EXPECT_GT(count, 0u) << "no inputs kept for " << target;
}

TEST(FuzzRegressions, GltfInputs) {
  const fs::path folder = test::temp_dir("fuzz_gltf");
  replay_all("gltf", [&](const std::vector<uint8_t>& d) {
    fuzz::load_gltf_bytes(d.data(), d.size(), folder);
  });
}

TEST(FuzzRegressions, EditScriptInputs) {
  replay_all("edit_script", [](const std::vector<uint8_t>& d) {
    fuzz::apply_edit_script_bytes(d.data(), d.size(),
                                  test::asset("cornell_box.gltf").parent_path());
  });
}

TEST(FuzzRegressions, EnvironmentInputs) {
  const fs::path folder = test::temp_dir("fuzz_env");
  replay_all("environment", [&](const std::vector<uint8_t>& d) {
    fuzz::load_environment_bytes(d.data(), d.size(), folder);
  });
}

TEST(FuzzRegressions, ImageInputs) {
  const fs::path folder = test::temp_dir("fuzz_image");
  replay_all("image", [&](const std::vector<uint8_t>& d) {
    fuzz::read_image_bytes(d.data(), d.size(), folder);
  });
}

}  // namespace
}  // namespace hipr
