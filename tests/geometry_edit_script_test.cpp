// Geometry edits on the scene model: duplicate, delete, import and deform do what their names
// say, their undo puts back exactly the scene before, scripts parse them (and refuse what leaves
// the script's folder), and the diff turns them into the changed set.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "hipr/edits.h"
#include "hipr/scene_diff.h"
#include "hipr/scene_loader.h"
#include "hipr/scene_writer.h"
#include "test_support.h"

namespace hipr {
namespace {

Scene cornell() { return load_scene(test::asset("cornell_box.gltf")); }

// The box with a point light "lamp" too, as if the file had it.
Scene cornell_with_lamp() {
  Scene scene = cornell();
  scene.lights.push_back(PunctualLight{"lamp", LightType::Point, glm::vec3(1.0f), 2.0f});
  Node lamp;
  lamp.name = "lamp";
  lamp.light = int(scene.lights.size() - 1);
  lamp.local[3] = glm::vec4(0.0f, 0.5f, 0.0f, 1.0f);
  scene.nodes.push_back(lamp);
  scene.children.emplace_back();
  scene.root_nodes.push_back(uint32_t(scene.nodes.size() - 1));
  scene.loaded_node_count = scene.nodes.size();
  scene.loaded_light_count = scene.lights.size();
  return scene;
}

size_t instances_of(const Scene& scene, const std::string& name) {
  size_t count = 0;
  for (const Instance& instance : scene.instances())
    count += scene.nodes[instance.node].name == name ? 1 : 0;
  return count;
}

size_t camera_nodes(const Scene& scene) {
  const std::vector<bool> in_scene = scene.reachable_nodes();
  size_t count = 0;
  for (size_t n = 0; n < scene.nodes.size(); ++n)
    count += in_scene[n] && scene.nodes[n].camera >= 0 ? 1 : 0;
  return count;
}

// Applies the edit and checks that its inverse, applied after, gives back the scene's nodes,
// lights and meshes exactly.
void expect_undo_restores(Scene& scene, const Edit& edit) {
  const Scene before = scene;
  const Edit undo = inverse_edit(scene, edit);
  apply_edit(scene, edit);
  apply_edit(scene, undo);
  ASSERT_EQ(scene.nodes.size(), before.nodes.size()) << describe(edit);
  for (size_t n = 0; n < before.nodes.size(); ++n) {
    EXPECT_EQ(scene.nodes[n].name, before.nodes[n].name);
    EXPECT_EQ(scene.nodes[n].local, before.nodes[n].local);
    EXPECT_EQ(scene.nodes[n].parent, before.nodes[n].parent);
  }
  EXPECT_EQ(scene.root_nodes, before.root_nodes);
  EXPECT_EQ(scene.children, before.children);
  EXPECT_EQ(scene.lights, before.lights);
  ASSERT_EQ(scene.meshes.size(), before.meshes.size());
  for (size_t m = 0; m < before.meshes.size(); ++m)
    for (size_t p = 0; p < before.meshes[m].primitives.size(); ++p) {
      EXPECT_EQ(scene.meshes[m].primitives[p].positions, before.meshes[m].primitives[p].positions);
      EXPECT_EQ(scene.meshes[m].primitives[p].indices, before.meshes[m].primitives[p].indices);
    }
  EXPECT_EQ(scene.materials.size(), before.materials.size());
  EXPECT_EQ(scene.instances().size(), before.instances().size());
  EXPECT_EQ(scene.content_hash, before.content_hash);
}

TEST(GeometryEdits, DuplicateCopiesTheNodeBesideItAtTheOffset) {
  Scene scene = cornell();
  const size_t meshes = scene.meshes.size();
  const glm::mat4 original = scene.world_transform(uint32_t(find_node(scene, "short_block")));
  apply_edit(scene, DuplicateEdit{"short_block", "short_block_2", glm::vec3(0.1f, 0.0f, -0.2f)});
  const size_t copy = find_node(scene, "short_block_2");
  EXPECT_EQ(scene.nodes[copy].mesh, scene.nodes[find_node(scene, "short_block")].mesh)
      << "copies share meshes";
  EXPECT_EQ(scene.meshes.size(), meshes);
  const glm::mat4 moved = scene.world_transform(uint32_t(copy));
  EXPECT_EQ(glm::vec3(moved[3]), glm::vec3(original[3]) + glm::vec3(0.1f, 0.0f, -0.2f));
  EXPECT_EQ(instances_of(scene, "short_block_2"), 1u);
  EXPECT_THROW(apply_edit(scene, DuplicateEdit{"short_block", "short_block_2", {}}), InputError)
      << "name taken";
  EXPECT_THROW(apply_edit(scene, DuplicateEdit{"nothing", "x", {}}), InputError);
  // Without a name: "<node>.1", then ".2".
  apply_edit(scene, DuplicateEdit{"tall_block", "", {}});
  apply_edit(scene, DuplicateEdit{"tall_block", "", {}});
  EXPECT_EQ(instances_of(scene, "tall_block.1"), 1u);
  EXPECT_EQ(instances_of(scene, "tall_block.2"), 1u);
}

TEST(GeometryEdits, ADuplicatedLampIsALampOfItsOwn) {
  Scene scene = cornell_with_lamp();
  const size_t lights = scene.light_nodes().size();
  const std::string lamp = "lamp";
  apply_edit(scene, DuplicateEdit{lamp, "lamp_2", glm::vec3(0.2f, 0.0f, 0.0f)});
  EXPECT_EQ(scene.light_nodes().size(), lights + 1);
  apply_edit(scene, LightEdit{"lamp_2", 0.0f, std::nullopt, std::nullopt});
  EXPECT_GT(scene.lights[size_t(scene.nodes[find_node(scene, lamp)].light)].intensity, 0.0f);
}

TEST(GeometryEdits, DeleteRemovesTheSubtreeAndTheUndoPutsItBack) {
  Scene scene = cornell();
  const size_t instances = scene.instances().size();
  expect_undo_restores(scene, DeleteEdit{"tall_block"});
  apply_edit(scene, DeleteEdit{"tall_block"});
  EXPECT_EQ(scene.instances().size(), instances - 1);
  EXPECT_EQ(instances_of(scene, "tall_block"), 0u);
  EXPECT_THROW(find_node(scene, "tall_block"), InputError) << "a deleted node cannot be edited";
  EXPECT_THROW(apply_edit(scene, TransformEdit{"tall_block", glm::vec3(1.0f), std::nullopt}),
               InputError);
}

TEST(GeometryEdits, DuplicateAndImportUndoExactly) {
  Scene scene = cornell();
  expect_undo_restores(scene, DuplicateEdit{"short_block", "copy", glm::vec3(0.1f)});
  expect_undo_restores(
      scene, ImportEdit{test::asset("cornell_sphere.glb"), "sphere", glm::vec3(0.0f, 0.2f, 0.0f)});
  expect_undo_restores(
      scene,
      DeformEdit{"short_block", glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, 2.0f, 1.0f)), nullptr});
}

TEST(GeometryEdits, AThousandDuplicateDeleteCyclesLeaveTheSceneAsItWas) {
  Scene scene = cornell_with_lamp();
  const size_t nodes = scene.nodes.size(), lights = scene.lights.size();
  const std::string lamp = "lamp";
  for (int i = 0; i < 1000; ++i) {
    apply_edit(scene, DuplicateEdit{i % 2 ? "short_block" : lamp, "copy", glm::vec3(0.01f)});
    apply_edit(scene, DeleteEdit{"copy"});
  }
  EXPECT_EQ(scene.nodes.size(), nodes);
  EXPECT_EQ(scene.lights.size(), lights);
}

TEST(GeometryEdits, ImportAppendsTheFilesSceneUnderANewNode) {
  Scene scene = cornell();
  const Scene other = load_scene(test::asset("cornell_sphere.glb"));
  const size_t meshes = scene.meshes.size(), materials = scene.materials.size(),
               instances = scene.instances().size();
  apply_edit(scene, ImportEdit{test::asset("cornell_sphere.glb"), "", glm::vec3(0.0f, 1.0f, 0.0f)});
  EXPECT_EQ(scene.meshes.size(), meshes + other.meshes.size());
  EXPECT_EQ(scene.materials.size(), materials + other.materials.size());
  EXPECT_EQ(scene.instances().size(), instances + other.instances().size());
  EXPECT_NE(scene.content_hash, cornell().content_hash)
      << "cached references must tell the scenes apart";
  const size_t root = find_node(scene, "cornell_sphere");  // the file's stem
  EXPECT_EQ(scene.nodes[root].parent, -1);
  // Every imported instance sits one metre up, its primitives on the imported materials.
  const std::vector<Instance> all = scene.instances();
  for (size_t i = instances; i < all.size(); ++i) {
    EXPECT_GE(all[i].mesh, meshes);
    for (const MeshPrimitive& p : scene.meshes[all[i].mesh].primitives)
      EXPECT_GE(p.material, materials);
  }
  EXPECT_EQ(camera_nodes(scene), 1u) << "the file's cameras stay out";
}

TEST(GeometryEdits, BadImportsAreInputErrorsAndChangeNothing) {
  Scene scene = cornell();
  const std::filesystem::path dir = test::temp_dir("bad_import");
  std::ofstream(dir / "broken.gltf") << "{ not json";
  const size_t nodes = scene.nodes.size();
  EXPECT_THROW(apply_edit(scene, ImportEdit{dir / "broken.gltf", "", {}}), InputError);
  EXPECT_THROW(apply_edit(scene, ImportEdit{dir / "missing.glb", "", {}}), InputError);
  EXPECT_EQ(scene.nodes.size(), nodes);
}

TEST(GeometryEdits, DeformMovesTheVerticesOfEveryUserOfTheMesh) {
  Scene scene = cornell();
  const size_t node = find_node(scene, "short_block");
  const size_t mesh = size_t(scene.nodes[node].mesh);
  const glm::vec3 first = scene.meshes[mesh].primitives[0].positions[0];
  const uint64_t revision = scene.meshes[mesh].revision;
  apply_edit(scene, DuplicateEdit{"short_block", "twin", glm::vec3(0.3f, 0.0f, 0.0f)});
  apply_edit(scene, DeformEdit{"short_block",
                               glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, 2.0f, 1.0f)), nullptr});
  EXPECT_EQ(scene.meshes[mesh].primitives[0].positions[0], first * glm::vec3(1.0f, 2.0f, 1.0f));
  EXPECT_NE(scene.meshes[mesh].revision, revision);
  EXPECT_EQ(scene.nodes[find_node(scene, "twin")].mesh, int(mesh))
      << "the twin shares the deformed mesh";
  // A mirror keeps triangles facing their normals: the winding turns with it.
  const std::vector<uint32_t> indices = scene.meshes[mesh].primitives[0].indices;
  apply_edit(scene, DeformEdit{"short_block",
                               glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f)), nullptr});
  EXPECT_EQ(scene.meshes[mesh].primitives[0].indices[1], indices[2]);
  EXPECT_THROW(apply_edit(scene, DeformEdit{"short_block", glm::mat4(0.0f), nullptr}), InputError)
      << "singular";
  EXPECT_THROW(apply_edit(scene, DeformEdit{"camera", glm::mat4(1.0f), nullptr}), InputError)
      << "no mesh";
}

TEST(GeometryEdits, TheDiffPairsInstancesByNode) {
  Scene scene = cornell();
  ChangeSet changes =
      test::edit_scene(scene, DuplicateEdit{"short_block", "copy", glm::vec3(0.1f, 0.0f, 0.0f)});
  ASSERT_EQ(changes.instances.size(), 1u)
      << "only the copy is new; the instances after it did not change";
  EXPECT_EQ(scene.nodes[scene.instances()[changes.instances[0]].node].name, "copy");
  EXPECT_TRUE(changes.transforms);
  EXPECT_FALSE(changes.geometry);

  const size_t tall = find_node(scene, "tall_block");
  changes = test::edit_scene(scene, DeleteEdit{"tall_block"});
  EXPECT_TRUE(changes.instances.empty());
  EXPECT_EQ(changes.departed, std::vector<uint32_t>{uint32_t(tall)});

  changes = test::edit_scene(
      scene, DeformEdit{"short_block", glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.1f, 0.0f)),
                        nullptr});
  EXPECT_TRUE(changes.geometry);
  EXPECT_EQ(changes.instances.size(), 2u) << "the block and its copy share the mesh";

  changes = test::edit_scene(scene, ImportEdit{test::asset("cornell_sphere.glb"), "sphere", {}});
  EXPECT_TRUE(changes.geometry);
  EXPECT_TRUE(changes.materials);
  EXPECT_EQ(changes.instances.size(),
            load_scene(test::asset("cornell_sphere.glb")).instances().size());
  EXPECT_TRUE(diff_scenes(scene, scene).empty());
  EXPECT_TRUE(diff_scenes(cornell(), cornell()).empty())
      << "two loads of one file are the same scene";
}

// The same objects (by node), placed alike, with the same triangles on the same materials, and
// the same lamps: what renders (material indices may differ: a file's imported materials come
// before glTF's default one).
void expect_same_content(const Scene& a, const Scene& b, const std::string& what) {
  const std::vector<Instance> ia = a.instances(), ib = b.instances();
  ASSERT_EQ(ia.size(), ib.size()) << what;
  for (size_t i = 0; i < ia.size(); ++i) {
    EXPECT_EQ(ia[i].node, ib[i].node) << what;
    EXPECT_EQ(ia[i].world, ib[i].world) << what;
    const Mesh& ma = a.meshes[ia[i].mesh];
    const Mesh& mb = b.meshes[ib[i].mesh];
    ASSERT_EQ(ma.primitives.size(), mb.primitives.size()) << what;
    for (size_t p = 0; p < ma.primitives.size(); ++p) {
      EXPECT_EQ(ma.primitives[p].positions, mb.primitives[p].positions) << what;
      EXPECT_EQ(ma.primitives[p].indices, mb.primitives[p].indices) << what;
      const MaterialParameters& pa = a.materials[ma.primitives[p].material].params;
      const MaterialParameters& pb = b.materials[mb.primitives[p].material].params;
      EXPECT_EQ(std::memcmp(&pa, &pb, sizeof pa), 0)
          << what << ": material of " << a.nodes[ia[i].node].name;
    }
  }
  ASSERT_EQ(a.light_nodes(), b.light_nodes()) << what;
  for (uint32_t n : a.light_nodes()) {
    EXPECT_EQ(a.lights[size_t(a.nodes[n].light)], b.lights[size_t(b.nodes[n].light)]) << what;
    EXPECT_EQ(a.world_transform(n), b.world_transform(n)) << what;
  }
}

// Saving an import writes its meshes, materials and lamp: the saved file loads as the edited
// scene, in .gltf and .glb (textured imports: geometry_update_test.cpp renders them).
TEST(GeometryEdits, SavedImportsLoadAsTheEditedScene) {
  Scene scene = cornell();
  apply_edit(scene,
             ImportEdit{test::asset("cornell_sphere.glb"), "sphere", glm::vec3(0.3f, 0.1f, 0.0f)});
  apply_edit(scene, MaterialEdit{"#" + std::to_string(scene.materials.size() - 1),
                                 {{"base_color", {0.2f, 0.3f, 0.4f}}}});
  const std::filesystem::path dir = test::temp_dir("saved_import");
  for (const char* name : {"imported.gltf", "imported.glb"}) {
    save_scene(scene, dir / name);
    const Scene reloaded = load_scene(dir / name);
    expect_same_content(scene, reloaded, name);
  }
}

TEST(GeometryEdits, ScriptsParseTheFourOps) {
  const std::filesystem::path dir = test::temp_dir("geometry_script");
  const auto edits = parse_edit_script(R"({"edits": [
    {"op": "duplicate", "node": "short_block", "as": "short_block_2", "translate": [0.1, 0, 0]},
    {"op": "delete", "node": "tall_block"},
    {"op": "import", "file": "props/chair.glb", "as": "chair", "translate": [0, 0, 1]},
    {"op": "deform", "node": "short_block", "matrix": [1,0,0,0, 0,2,0,0, 0,0,1,0, 0,0,0,1]}
  ]})",
                                       "s.json", dir);
  ASSERT_EQ(edits.size(), 4u);
  EXPECT_EQ(std::get<DuplicateEdit>(edits[0]).as, "short_block_2");
  EXPECT_EQ(std::get<DeleteEdit>(edits[1]).node, "tall_block");
  EXPECT_EQ(std::get<ImportEdit>(edits[2]).file, dir / "props/chair.glb");
  EXPECT_EQ(std::get<DeformEdit>(edits[3]).matrix[1][1], 2.0f);

  const auto refused = [&](const std::string& edit) {
    EXPECT_THROW(parse_edit_script(R"({"edits": [)" + edit + "]}", "s.json", dir), InputError)
        << edit;
  };
  refused(R"({"op": "import", "file": "../outside.glb"})");
  refused(R"({"op": "import", "file": "props/../../outside.glb"})");
  refused(R"({"op": "import", "file": "/etc/passwd"})");
  refused(R"({"op": "import"})");
  refused(R"({"op": "deform", "node": "a"})");
  refused(R"({"op": "deform", "node": "a", "matrix": [1, 2]})");
  refused(R"({"op": "delete", "node": "a", "as": "b"})");
  refused(R"({"op": "duplicate", "node": "a", "translate": [1, 2]})");
  // A link inside the folder that points out of it is refused too.
  std::filesystem::create_directories(dir / "out");
  std::filesystem::create_symlink("/etc", dir / "escape");
  refused(R"({"op": "import", "file": "escape/hosts"})");
}

// An environment file an edit script names is confined as an import is: absolute paths, ".."
// and links out of the folder are refused before anything is opened; built-in names are no paths.
TEST(EditScript, EnvironmentFilesStayInTheScriptsFolder) {
  const std::filesystem::path dir = test::temp_dir("environment_script");
  const auto parse = [&](const std::string& source) {
    return parse_edit_script(R"({"edits": [{"op": "environment", "source": ")" + source + R"("}]})",
                             "s.json", dir);
  };
  for (const char* source :
       {"/etc/hostname", "../outside.hdr", "maps/../../outside.exr", "escape/hostname"}) {
    if (std::string(source) == "escape/hostname")
      std::filesystem::create_symlink("/etc", dir / "escape");
    try {
      parse(source);
      ADD_FAILURE() << "accepted " << source;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("script's folder"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(std::get<EnvironmentEdit>(parse("maps/room.hdr").front()).source,
            dir / "maps/room.hdr");
  for (const char* name : {"studio", "sky", "none"})
    EXPECT_EQ(std::get<EnvironmentEdit>(parse(name).front()).source, std::filesystem::path(name));
}

}  // namespace
}  // namespace hipr
