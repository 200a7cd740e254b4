#pragma once
// The viewer's ImGui panels. The side panel holds the file and history controls, the scene
// tree, the selected object (transform, visibility, OpenPBR materials), lights, environment,
// HiPR settings and the display; the status line sits at the bottom of the view. Widgets edit
// the scene through the session (a refused edit becomes a message, never a lost scene) and
// leave everything else to the main loop as requests in ViewerState.
#include <string>

#include "app/viewer/scene_edits.h"
#include "app/viewer/session.h"
#include "app/viewer/viewer_state.h"

namespace hipr::viewer {

// Width of the side panel in window pixels (the window is this much wider than the render).
constexpr float kPanelWidth = 360.0f;

void draw_side_panel(Session& session, ViewerState& state, float x, float height);
void draw_status_line(const Session& session, const ViewerState& state, float x, float y,
                      float width);

// An edit from a widget. While any widget stays active (a slider or colour being dragged) its
// edits form one undo step. Returns false when the scene refused it (shown as a message).
bool ui_edit(Session& session, ViewerState& state, const Edit& edit);
// Closes that undo step once no widget is active; call once per frame after the panels.
void end_ui_edit_group(Session& session, ViewerState& state);

// The last widget's help while hovered, wrapped to the panel's width (flags' help is one line).
void tooltip(const char* help);

// Sections of the side panel (scene_panels.cpp).
void scene_tree_section(Session& session, ViewerState& state);
void selection_section(Session& session, ViewerState& state);
void lights_section(Session& session, ViewerState& state);
void environment_section(Session& session, ViewerState& state);
void camera_section(Session& session, ViewerState& state);  // camera_panel.cpp

}  // namespace hipr::viewer
