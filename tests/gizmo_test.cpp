// The viewer's transform gizmo (app/viewer/gizmo.h): projection, hit tests and the transforms
// its drags make, without a window.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "app/viewer/gizmo.h"
#include "hipr/edits.h"

namespace hipr::viewer {
namespace {

// A camera 10 units above the origin looking straight down: world +x is screen right, world
// -z screen up, and +y points at the viewer.
ViewProjection top_view() {
  ViewProjection view;
  view.camera.camera_to_world = glm::mat4(glm::vec4(1, 0, 0, 0), glm::vec4(0, 0, -1, 0),
                                          glm::vec4(0, 1, 0, 0), glm::vec4(0, 10, 0, 1));
  view.camera.yfov = 0.8f;
  view.render_width = view.render_height = 200;
  view.layout = ViewLayout{200, 200, 10, 20, 2.0f};  // the image at (10, 20), shown 2x
  return view;
}

void expect_near(const glm::mat4& a, const glm::mat4& b, float tolerance) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(a[c][r], b[c][r], tolerance) << c << " " << r;
}

TEST(Gizmo, ProjectsAsTheRendererTracesPixels) {
  const ViewProjection view = top_view();
  // The origin is straight ahead: the image's centre, placed and scaled by the layout.
  EXPECT_EQ(*view.to_window(glm::vec3(0.0f)), glm::vec2(10 + 200, 20 + 200));
  // pixel_centre_ray's direction for render pixel (149, 49), followed 7 units: back to its centre.
  const float tan_half = std::tan(0.4f);
  const glm::vec2 ndc = (glm::vec2(149, 49) + 0.5f) / 200.0f * 2.0f - 1.0f;
  const glm::vec3 ray = glm::normalize(glm::vec3(0, -1, 0) + ndc.x * tan_half * glm::vec3(1, 0, 0) -
                                       ndc.y * tan_half * glm::vec3(0, 0, -1));
  const glm::vec2 back = *view.to_window(glm::vec3(0, 10, 0) + 7.0f * ray);
  EXPECT_NEAR(back.x, 10 + 2.0f * 149.5f, 1e-3f);
  EXPECT_NEAR(back.y, 20 + 2.0f * 49.5f, 1e-3f);
  EXPECT_FALSE(view.to_window(glm::vec3(0, 11, 0))) << "behind the camera";
}

TEST(Gizmo, HandlesAreHitWhereTheyAreDrawn) {
  const GizmoScreen s =
      *gizmo_screen(top_view(), glm::mat4(1.0f), GizmoSpace::World, GizmoMode::Translate, 80.0f);
  EXPECT_NEAR(glm::length(s.tips[0] - s.origin), 80.0f, 0.5f);
  EXPECT_GT(s.tips[0].x, s.origin.x) << "x to the right";
  EXPECT_GT(s.tips[2].y, s.origin.y + 70.0f) << "-z up, so +z down";
  EXPECT_EQ(gizmo_hit(s, GizmoMode::Translate, s.tips[0] + glm::vec2(0, 3), 7.0f), 0);
  EXPECT_EQ(gizmo_hit(s, GizmoMode::Translate, s.origin + glm::vec2(0, -60), 7.0f), -1);
  EXPECT_EQ(gizmo_hit(s, GizmoMode::Translate, s.origin + glm::vec2(0, 60), 7.0f), 2);
  EXPECT_EQ(gizmo_hit(s, GizmoMode::Translate, s.origin + glm::vec2(40, 40), 7.0f), -1);
  // y points at the camera: seen end-on, not draggable.
  EXPECT_EQ(gizmo_hit(s, GizmoMode::Translate, s.origin, 7.0f), -1);
  const GizmoScreen scale =
      *gizmo_screen(top_view(), glm::mat4(1.0f), GizmoSpace::World, GizmoMode::Scale, 80.0f);
  EXPECT_EQ(gizmo_hit(scale, GizmoMode::Scale, scale.origin + glm::vec2(2, 1), 7.0f),
            kGizmoUniformScale);
  const GizmoScreen rings =
      *gizmo_screen(top_view(), glm::mat4(1.0f), GizmoSpace::World, GizmoMode::Rotate, 80.0f);
  // Seen from above, y's ring is a circle around the origin; x's and z's are seen edge-on,
  // as lines through it (x's along screen y, z's along screen x).
  const float r = 0.9f * 80.0f;
  EXPECT_EQ(
      gizmo_hit(rings, GizmoMode::Rotate, rings.origin + r * glm::vec2(0.7071f, -0.7071f), 7.0f),
      1);
  EXPECT_EQ(gizmo_hit(rings, GizmoMode::Rotate, rings.origin + glm::vec2(0.0f, 30.0f), 7.0f), 0);
  EXPECT_EQ(gizmo_hit(rings, GizmoMode::Rotate, rings.origin + glm::vec2(30.0f, 0.0f), 7.0f), 2);
  EXPECT_EQ(gizmo_hit(rings, GizmoMode::Rotate, rings.origin + glm::vec2(30.0f, 30.0f), 7.0f), -1);
}

// A drag of the x arrow by its own length moves the node one handle length along world x;
// under a parent scaled 2x, that is half as far in the node's own (parent) space.
TEST(Gizmo, TranslateFollowsTheMouseAlongTheAxis) {
  const ViewProjection view = top_view();
  const glm::mat4 parent = glm::scale(glm::mat4(1.0f), glm::vec3(2.0f));
  const glm::mat4 local = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, 0, 0));
  const GizmoScreen s =
      *gizmo_screen(view, parent * local, GizmoSpace::World, GizmoMode::Translate, 80.0f);
  GizmoDrag drag(s, GizmoMode::Translate, 0, s.tips[0], local, parent, view.eye());
  const glm::mat4 moved = drag.local_at(s.tips[0] + (s.tips[0] - s.origin), false);
  EXPECT_NEAR(moved[3].x, 0.5f + s.world_length / 2.0f, 1e-4f);
  EXPECT_NEAR(moved[3].z, 0.0f, 1e-6f);
  // Snapped: a round step of a tenth of the handle.
  const glm::mat4 snapped = drag.local_at(s.tips[0] + 0.33f * (s.tips[0] - s.origin), true);
  const float step = nice_step(s.world_length);
  const float world = 2.0f * (snapped[3].x - 0.5f);
  EXPECT_NEAR(world / step, std::round(world / step), 1e-3f);
}

// A quarter turn counter-clockwise on screen around the up axis (which points at the camera),
// snapped: exactly +90 degrees about world y, through the node's origin.
TEST(Gizmo, RotateTurnsAboutTheAxisThroughTheNodesOrigin) {
  const ViewProjection view = top_view();
  const glm::mat4 local = glm::translate(glm::mat4(1.0f), glm::vec3(1.0f, 0.0f, -0.5f)) *
                          glm::scale(glm::mat4(1.0f), glm::vec3(0.5f, 1.0f, 2.0f));
  const GizmoScreen s = *gizmo_screen(view, local, GizmoSpace::World, GizmoMode::Rotate, 80.0f);
  const float r = 0.9f * glm::length(s.tips[0] - s.origin);
  GizmoDrag drag(s, GizmoMode::Rotate, 1, s.origin + glm::vec2(r, 0.0f), local, glm::mat4(1.0f),
                 view.eye());
  glm::mat4 turned(1.0f);
  for (int i = 1; i <= 9; ++i) {  // through the upper right quadrant, as a mouse would go
    const float a = glm::radians(10.0f * float(i)) + (i == 9 ? 0.03f : 0.0f);
    turned = drag.local_at(s.origin + r * glm::vec2(std::cos(a), -std::sin(a)), true);
  }
  glm::mat4 expected = euler_rotation(glm::vec3(0, 90, 0)) * glm::mat4(glm::mat3(local));
  expected[3] = local[3];
  expect_near(turned, expected, 1e-5f);
  EXPECT_NEAR(local_pose(turned).rotation_degrees.y, 90.0f, 1e-3f);
}

TEST(Gizmo, ScaleStretchesAlongTheNodesOwnAxes) {
  const ViewProjection view = top_view();
  const glm::mat4 local = euler_rotation(glm::vec3(0, 30, 0));  // turned: its x is not world x
  const GizmoScreen s = *gizmo_screen(view, local, GizmoSpace::World, GizmoMode::Scale, 80.0f);
  GizmoDrag along_x(s, GizmoMode::Scale, 0, s.tips[0], local, glm::mat4(1.0f), view.eye());
  const glm::mat4 wider = along_x.local_at(s.tips[0] + 1.02f * (s.tips[0] - s.origin), true);
  EXPECT_NEAR(local_pose(wider).scale.x, 2.0f, 1e-5f) << "snapped to tenths";
  EXPECT_NEAR(local_pose(wider).scale.z, 1.0f, 1e-5f);
  EXPECT_NEAR(local_pose(wider).rotation_degrees.y, 30.0f, 1e-3f) << "no shear, same turn";
  GizmoDrag even(s, GizmoMode::Scale, kGizmoUniformScale, s.origin + glm::vec2(20, 0), local,
                 glm::mat4(1.0f), view.eye());
  const glm::mat4 doubled = even.local_at(s.origin + glm::vec2(20 + 80, 0), false);
  for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(local_pose(doubled).scale[axis], 2.0f, 1e-5f);
}

TEST(Gizmo, NiceStepsAreOneTwoOrFiveTimesAPowerOfTen) {
  EXPECT_FLOAT_EQ(nice_step(1.0f), 0.1f);
  EXPECT_FLOAT_EQ(nice_step(3.0f), 0.2f);
  EXPECT_FLOAT_EQ(nice_step(0.07f), 0.005f);
}

}  // namespace
}  // namespace hipr::viewer
