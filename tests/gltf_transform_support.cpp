#include "gltf_transform_support.h"

#include <gtest/gtest.h>

#include "test_support.h"

namespace hipr::test {
namespace fs = std::filesystem;

namespace {

fs::path cli() {
  return fs::path(HIPR_TOOLS_DIR) / "node_modules" / "@gltf-transform" / "cli" / "bin" / "cli.js";
}

}  // namespace

bool gltf_transform_available() {
  static const bool available =
      fs::exists(cli()) && run_command("node " + quoted(cli()) + " --version").exit_code == 0;
  return available;
}

fs::path gltf_transform(const std::string& command, const fs::path& input, const fs::path& output,
                        const std::string& arguments) {
  const CommandResult result = run_command("node " + quoted(cli()) + " " + command + " " +
                                           quoted(input) + " " + quoted(output) + " " + arguments);
  EXPECT_EQ(result.exit_code, 0) << "gltf-transform " << command << ": " << result.output;
  return output;
}

}  // namespace hipr::test
