// The Khronos glTF-Validator (tools/validate_gltf.js) finds no new errors in saved scenes:
// unedited, after edits of every kind, as .gltf and as .glb, and with every material parameter
// set. Skips when node or the
// validator package (installed into tools/node_modules by tools/setup-deps.sh) is absent.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>

#include "gltf_transform_support.h"
#include "hipr/edits.h"
#include "hipr/scene_loader.h"
#include "hipr/scene_writer.h"
#include "scene_writer_support.h"
#include "test_support.h"

namespace hipr {
namespace {
namespace fs = std::filesystem;

struct Report {
  int errors = 0;
  int warnings = 0;
  std::map<std::string, int> error_codes;
};

bool validator_available() {
  if (std::system("command -v node >/dev/null 2>&1") != 0) return false;
  return fs::exists(fs::path(HIPR_TOOLS_DIR) / "node_modules" / "gltf-validator" / "package.json");
}

// One validator run over `files` (its start-up is shared): a report per file, in order.
std::vector<Report> validate(const std::vector<fs::path>& files) {
  std::string command = "node '" + (fs::path(HIPR_TOOLS_DIR) / "validate_gltf.js").string() + "'";
  for (const fs::path& file : files) command += " '" + file.string() + "'";
  command += " 2>&1";
  std::string output;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) {
    ADD_FAILURE() << "cannot run " << command;
    return {};
  }
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) output.append(buffer.data(), n);
  const int status = pclose(pipe);
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (code != 0) {
    ADD_FAILURE() << "validate_gltf.js exited with " << code << ": " << output;
    return {};
  }
  std::vector<Report> reports;
  for (const std::string& line : test::lines_of(output)) {
    const nlohmann::json summary = nlohmann::json::parse(line);
    Report report;
    report.errors = summary["errors"];
    report.warnings = summary["warnings"];
    for (const auto& [code_name, count] : summary["error_codes"].items())
      report.error_codes[code_name] = count;
    reports.push_back(report);
  }
  EXPECT_EQ(reports.size(), files.size());
  return reports;
}

void expect_no_new_errors(const Report& original, const Report& saved, const std::string& what) {
  EXPECT_LE(saved.errors, original.errors) << what;
  EXPECT_LE(saved.warnings, original.warnings) << what << ": new warnings";
  for (const auto& [code, count] : saved.error_codes) {
    const auto it = original.error_codes.find(code);
    EXPECT_TRUE(it != original.error_codes.end() && count <= it->second)
        << what << ": new error " << code;
  }
}

TEST(GltfValidator, SavedScenesHaveNoNewErrors) {
  if (!validator_available()) {
    if (test::gltf_validator_required())
      FAIL() << "the set-up installs the glTF validator, yet it is absent";
    GTEST_SKIP() << "node or the gltf-validator package is absent (see tools/setup-deps.sh)";
  }
  std::vector<fs::path> sources = {test::asset("cornell_box.gltf"),
                                   test::asset("cornell_sphere.glb"),
                                   test::asset("furnace_sphere.gltf")};
  if (test::shared_scenes_available())
    for (const test::SharedScene& s : test::shared_scenes_to_save())
      sources.push_back(test::shared_scene(s.file));

  const fs::path dir = test::temp_dir("validator");
  // Compressed sources save too: their data kept as it was, edited meshes written anew.
  if (test::gltf_transform_available())
    for (const char* command : {"draco", "meshopt", "quantize"})
      sources.push_back(
          test::gltf_transform(command, test::asset("cornell_box.gltf"),
                               dir / ("cornell_box_" + std::string(command) + ".glb")));
  else if (test::gltf_validator_required())
    ADD_FAILURE() << "glTF-Transform is not installed (tools/setup-deps.sh installs it)";
  for (const fs::path& source : sources) {
    SCOPED_TRACE(source.string());
    Scene scene = load_scene(source);
    const fs::path out = dir / source.stem();
    fs::create_directories(out);
    save_scene(scene, out / "unedited.gltf");
    save_scene(scene, out / "unedited.glb");
    for (const Edit& edit : test::typical_edits(scene)) apply_edit(scene, edit);
    save_scene(scene, out / "edited.gltf");
    save_scene(scene, out / "edited.glb");
    // Every OpenPBR parameter of material 0 set (extensions added, values beyond glTF's ranges).
    apply_edit(scene, test::every_parameter_edit("#0", 1));
    save_scene(scene, out / "every_parameter.gltf");
    // Geometry edits: the first object duplicated and deformed (new nodes, a mesh written anew),
    // the last one deleted (unlisted).
    const std::vector<Instance> instances = scene.instances();
    if (!instances.empty()) {
      const std::string first = "#" + std::to_string(instances.front().node);
      apply_edit(scene, DuplicateEdit{first, "validator_copy", glm::vec3(0.1f)});
      apply_edit(scene, DeformEdit{first, glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, 1.2f, 1.0f)),
                                   nullptr});
      if (instances.size() > 1)
        apply_edit(scene, DeleteEdit{"#" + std::to_string(instances.back().node)});
    }
    save_scene(scene, out / "geometry.gltf");
    save_scene(scene, out / "geometry.glb");
    const std::vector<std::string> names = {
        "unedited.gltf",        "unedited.glb",  "edited.gltf", "edited.glb",
        "every_parameter.gltf", "geometry.gltf", "geometry.glb"};
    std::vector<fs::path> files = {source};
    for (const std::string& name : names) files.push_back(out / name);
    const std::vector<Report> reports = validate(files);
    ASSERT_EQ(reports.size(), files.size());
    std::cout << "[validator] " << source.filename().string() << ": original " << reports[0].errors
              << " errors, " << reports[0].warnings << " warnings";
    for (size_t i = 0; i < names.size(); ++i) {
      expect_no_new_errors(reports[0], reports[i + 1], names[i]);
      std::cout << "; " << names[i] << " " << reports[i + 1].errors << "/"
                << reports[i + 1].warnings;
    }
    std::cout << " (errors/warnings)\n";
  }
}

}  // namespace
}  // namespace hipr
