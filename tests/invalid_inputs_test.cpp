// The Khronos validator's broken files (../shared/scenes/InvalidInputs, listed in EXPECTED.tsv):
// each must be refused with one clear line, both by load_scene and by the CLI, and nothing may
// be written. Two have a fallback that serves the user better than refusing.
#include <cctype>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "hipr/scene_loader.h"
#include "test_support.h"

namespace hipr {
namespace {
using test::lines_of;
using test::quoted;
namespace fs = std::filesystem;

struct InvalidInput {
  std::string file;           // relative to InvalidInputs/; empty when the folder is absent
  std::string what_is_wrong;  // from EXPECTED.tsv, for failure messages
};

std::ostream& operator<<(std::ostream& out, const InvalidInput& input) { return out << input.file; }

fs::path invalid_inputs_dir() { return test::shared_scene("InvalidInputs"); }

std::vector<std::string> split_tabs(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  for (std::string field; std::getline(stream, field, '\t');) fields.push_back(field);
  return fields;
}

// The rows of EXPECTED.tsv (columns: file, bytes, expected_validator_errors,
// expected_validator_warnings, what_is_wrong); empty when the scenes are absent.
std::vector<InvalidInput> expected_tsv_rows() {
  std::vector<InvalidInput> inputs;
  std::ifstream tsv(invalid_inputs_dir() / "EXPECTED.tsv");
  std::string line;
  std::getline(tsv, line);  // header
  while (std::getline(tsv, line)) {
    const std::vector<std::string> fields = split_tabs(line);
    if (fields.size() == 5) inputs.push_back({fields[0], fields[4]});
  }
  return inputs;
}

// Files where a warning and a fallback serve the user better than refusing the whole scene.
bool loads_with_fallback(const std::string& file) {
  return file == "image/not_found.gltf" || file == "mesh/primitive_no_position.gltf";
}

// The rows that must be refused (or, with `fallback`, loaded); one empty entry when the scenes
// are absent, so the suite reports a skip rather than nothing.
std::vector<InvalidInput> invalid_inputs(bool fallback) {
  std::vector<InvalidInput> inputs;
  for (const InvalidInput& input : expected_tsv_rows())
    if (loads_with_fallback(input.file) == fallback) inputs.push_back(input);
  if (inputs.empty()) inputs.push_back({});
  return inputs;
}

// Runs `hipr render FILE -o DIR/out.png` at 16x16, 1 spp, into a fresh folder.
struct CliRender {
  fs::path out_dir;
  fs::path output;
  test::CommandResult result;
};

CliRender render_with_cli(const fs::path& scene) {
  CliRender run;
  run.out_dir = test::temp_dir("invalid-cli");
  run.output = run.out_dir / "out.png";
  run.result = test::run_hipr("render " + quoted(scene) + " -o " + quoted(run.output) +
                              " --width 16 --height 16 --spp 1");
  return run;
}

class InvalidInputTest : public testing::TestWithParam<InvalidInput> {
 protected:
  void SetUp() override {
    if (GetParam().file.empty()) GTEST_SKIP() << "../shared/scenes/InvalidInputs is not available";
    m_path = invalid_inputs_dir() / GetParam().file;
  }
  fs::path m_path;
};

using RefusedInput = InvalidInputTest;
using FallbackInput = InvalidInputTest;

TEST_P(RefusedInput, LoaderThrowsOneLine) {
  try {
    load_scene(m_path);
    FAIL() << "loaded a file where " << GetParam().what_is_wrong;
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_FALSE(message.empty());
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_NE(message.find(m_path.filename().string()), std::string::npos) << message;
  }
}

TEST_P(RefusedInput, CliExitsTwoAndWritesNothing) {
  const CliRender run = render_with_cli(m_path);
  EXPECT_EQ(run.result.exit_code, kExitBadInput) << run.result.output;
  const std::vector<std::string> lines = lines_of(run.result.output);
  ASSERT_EQ(lines.size(), 1u) << run.result.output;
  EXPECT_EQ(lines[0].rfind("hipr: error: ", 0), 0u) << lines[0];
  EXPECT_NE(lines[0].find(m_path.filename().string()), std::string::npos) << lines[0];
  EXPECT_TRUE(fs::is_empty(run.out_dir))
      << "the output folder is not empty";  // no output, no temp file
}

TEST_P(FallbackInput, LoaderWarnsAndLoads) {
  testing::internal::CaptureStderr();
  Scene scene;
  EXPECT_NO_THROW(scene = load_scene(m_path));
  const std::string warnings = testing::internal::GetCapturedStderr();
  EXPECT_NE(warnings.find("hipr: warning: " + m_path.filename().string()), std::string::npos)
      << warnings;
  if (GetParam().file == "mesh/primitive_no_position.gltf") {
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_TRUE(scene.meshes[0].primitives.empty())
        << "the primitive without POSITION was not skipped";
  } else {
    EXPECT_NE(warnings.find("not_found.png"), std::string::npos) << warnings;
    EXPECT_TRUE(scene.textures.empty()) << "no texture uses the missing image";
  }
}

TEST_P(FallbackInput, CliRendersWithAWarning) {
  const CliRender run = render_with_cli(m_path);
  EXPECT_EQ(run.result.exit_code, kExitOk) << run.result.output;
  EXPECT_TRUE(fs::exists(run.output));
  EXPECT_NE(run.result.output.find("hipr: warning:"), std::string::npos) << run.result.output;
}

std::string invalid_input_name(const testing::TestParamInfo<InvalidInput>& param_info) {
  if (param_info.param.file.empty()) return "shared_scenes_absent";
  std::string name = param_info.param.file;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Files, RefusedInput, testing::ValuesIn(invalid_inputs(false)),
                         invalid_input_name);
INSTANTIATE_TEST_SUITE_P(Files, FallbackInput, testing::ValuesIn(invalid_inputs(true)),
                         invalid_input_name);

TEST(InvalidInputsList, CoversEveryFile) {
  if (!test::shared_scenes_available()) GTEST_SKIP() << "../shared/scenes is not available";
  // Every scene file in the folder is listed, so none escapes the tests above.
  size_t scene_files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(invalid_inputs_dir())) {
    const std::string extension = entry.path().extension().string();
    scene_files += extension == ".gltf" || extension == ".glb";
  }
  EXPECT_EQ(expected_tsv_rows().size(), scene_files);
  EXPECT_GE(scene_files, 21u);
}

}  // namespace
}  // namespace hipr
