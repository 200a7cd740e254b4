#pragma once
// The edits the viewer's keys and buttons make, apart from the widgets (so tests run them
// without a window): how edits name nodes, a refused edit as a message, duplicate and delete of
// the selection.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/viewer/session.h"
#include "app/viewer/viewer_state.h"

namespace hipr::viewer {

// An edit; a refusal (InputError) becomes a message and returns false, the scene unchanged.
bool try_edit(Session& session, ViewerState& state, const Edit& edit);

// The selected node, when it is in the scene (an undo may have taken it out); else none, and
// the selection is cleared.
std::optional<uint32_t> selected_node(const Session& session, ViewerState& state);
// Ctrl+D: a copy of the selected node beside it (to the view's right by a tenth of the scene's
// size), which becomes the selection. Delete: the selected node goes, and the selection with it.
void duplicate_selection(Session& session, ViewerState& state);
void delete_selection(Session& session, ViewerState& state);

// Files dropped on the window: a .gltf/.glb opens (as the File panel's Open does: unsaved
// edits ask first), or with Shift held is imported into the scene as a new object (an undoable
// edit, one per file). Anything else is a message. Only the first file opens.
void drop_files(Session& session, ViewerState& state, const std::vector<std::string>& paths,
                bool shift);

// How edits name a node or material: its name when that finds it, else "#index".
std::string node_reference(const Scene& scene, uint32_t node);
std::string material_reference(const Scene& scene, uint32_t material);
// For labels: the name, or "#index" for unnamed ones.
std::string node_label(const Scene& scene, uint32_t node);

}  // namespace hipr::viewer
