// Scenes without a camera (most real assets): the view is decided once, from the scene as
// loaded, and only a camera edit moves it. Moving, hiding or copying objects changes the scene's
// bounds, and a view derived from the bounds would follow them: the edit would be seen as a
// camera move.
#include <glm/gtc/matrix_transform.hpp>

#include "hipr/edits.h"
#include "hipr/scene_loader.h"
#include "hipr/scene_writer.h"
#include "scene/default_camera.h"
#include "test_support.h"

namespace hipr {
namespace {
namespace fs = std::filesystem;

void expect_same_view(const Camera& a, const Camera& b, const std::string& after) {
  EXPECT_EQ(a.camera_to_world, b.camera_to_world) << after;
  EXPECT_EQ(a.yfov, b.yfov) << after;
  EXPECT_EQ(a.znear, b.znear) << after;
}

class DefaultCamera : public ::testing::Test {
 protected:
  void SetUp() override {
    m_dir = test::temp_dir("default-camera");
    m_path = test::camera_less_cornell_box(m_dir);
    m_scene = load_scene(m_path);
    ASSERT_LT(m_scene.camera_node(), 0);
    ASSERT_TRUE(m_scene.default_camera.has_value()) << "decided at load";
    m_loaded = resolve_camera(m_scene);
  }

  // Applies `edit` as the viewer does (its inverse kept for undo); the view must not move.
  void edit(const Edit& e) {
    m_undo.push_back(inverse_edit(m_scene, e));
    apply_edit(m_scene, e);
    expect_same_view(resolve_camera(m_scene), m_loaded, describe(e));
  }

  void undo_all() {
    for (auto it = m_undo.rbegin(); it != m_undo.rend(); ++it) apply_edit(m_scene, *it);
    m_undo.clear();
  }

  fs::path m_dir, m_path;
  Scene m_scene;
  Camera m_loaded;
  std::vector<Edit> m_undo;
};

TEST_F(DefaultCamera, MovesHidesAndGeometryEditsKeepTheLoadedView) {
  const size_t loaded_nodes = m_scene.nodes.size();
  edit(TransformEdit{"tall_block", glm::vec3(0.0f, 0.0f, 1.5f), std::nullopt});
  EXPECT_NE(framing_camera(m_scene).camera_to_world, m_loaded.camera_to_world)
      << "the move grows the bounds: a view framed from them would have moved";
  for (const char* node :
       {"floor", "ceiling", "back_wall", "left_wall", "right_wall", "tall_block", "light"})
    edit(VisibilityEdit{node, false});
  EXPECT_NE(framing_camera(m_scene).camera_to_world, m_loaded.camera_to_world)
      << "only the short block is left";
  edit(DuplicateEdit{"short_block", "copy", glm::vec3(2.0f, 0.0f, 0.0f)});
  edit(DeformEdit{"short_block", glm::scale(glm::mat4(1.0f), glm::vec3(3.0f)), nullptr});
  edit(DeleteEdit{"copy"});
  undo_all();
  expect_same_view(resolve_camera(m_scene), m_loaded, "undo of everything");
  EXPECT_LT(m_scene.camera_node(), 0);
  EXPECT_EQ(m_scene.nodes.size(), loaded_nodes);
}

TEST_F(DefaultCamera, ACameraEditMovesItAndItsUndoReturnsToTheLoadedView) {
  m_undo.push_back(inverse_edit(m_scene, CameraEdit{glm::vec3(0.0f, 0.1f, 0.0f), std::nullopt}));
  apply_edit(m_scene, CameraEdit{glm::vec3(0.0f, 0.1f, 0.0f), std::nullopt});
  const Camera moved = resolve_camera(m_scene);
  EXPECT_NEAR(moved.camera_to_world[3].y - m_loaded.camera_to_world[3].y, 0.1f, 1e-6f);
  undo_all();
  expect_same_view(resolve_camera(m_scene), m_loaded, "the camera edit's undo");
}

// Saving writes the view as a camera node: the file reopens as it was seen, bit for bit.
TEST_F(DefaultCamera, ASavedEditReopensAsItWasSeen) {
  edit(TransformEdit{"tall_block", glm::vec3(0.0f, 0.0f, 1.5f), std::nullopt});
  const fs::path saved = m_dir / "saved.gltf";
  save_scene(m_scene, saved);
  const Scene reloaded = load_scene(saved);
  ASSERT_GE(reloaded.camera_node(), 0);
  expect_same_view(resolve_camera(reloaded), m_loaded, "save and reload");
  // Saving again writes no second camera.
  save_scene(reloaded, m_dir / "again.gltf");
  EXPECT_EQ(load_scene(m_dir / "again.gltf").cameras.size(), 1u);
}

// A scene built in code has no stored view until its first edit: the view from before it.
TEST_F(DefaultCamera, ASceneBuiltInCodeKeepsItsViewFromBeforeItsFirstEdit) {
  m_scene.default_camera.reset();
  edit(TransformEdit{"tall_block", glm::vec3(0.0f, 0.0f, 1.5f), std::nullopt});
  EXPECT_TRUE(m_scene.default_camera.has_value());
}

// An imported file's own default view stays behind: importing adds no camera.
TEST_F(DefaultCamera, AnImportBringsNoView) {
  edit(ImportEdit{m_path, "copy", glm::vec3(0.0f, 0.0f, 2.0f)});
  EXPECT_LT(m_scene.camera_node(), 0);
  EXPECT_TRUE(m_scene.cameras.empty());
}

}  // namespace
}  // namespace hipr
