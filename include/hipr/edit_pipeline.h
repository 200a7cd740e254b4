#pragma once
// The one path from an edit to the screen: the edit changes the scene, the scene before and
// after is diffed into a ChangeSet, and the scheduler updates the renderer's GPU scene and
// plans the re-render. `hipr replay` and the viewer go through it; `hipr bench` applies each
// edit once and replays its ChangeSet for every policy.
#include <functional>

#include "hipr/edits.h"
#include "hipr/focus.h"
#include "hipr/scene.h"
#include "hipr/scene_diff.h"
#include "hipr/scheduler.h"

namespace hipr {

// Applies `change` to `scene` and returns what it changed, diffing against a snapshot of what
// a diff reads (diff_snapshot), not a copy of the geometry.
ChangeSet change_scene(Scene& scene, const std::function<void(Scene&)>& change);

class EditPipeline {
 public:
  // `focus`: the focus the scheduler follows already (the viewer's), which edits that add or
  // remove instances renumber as they do the script's focus ops'.
  EditPipeline(Scene& scene, Scheduler& scheduler, Focus focus = {})
      : m_scene(scene), m_scheduler(scheduler), m_focus(std::move(focus)) {}

  // Applies the edit (InputError for an unknown name or key, the scene then unchanged) and,
  // when it changed anything, lets the scheduler re-render. Returns what changed. A focus op
  // changes nothing: it updates the focus the scheduler follows (Scheduler::set_focus).
  ChangeSet apply(const Edit& edit);
  // The same for any change of the scene (an undo or redo of the viewer's history).
  ChangeSet apply(const std::function<void(Scene&)>& change);
  // The focus the script's focus ops have made so far.
  const Focus& focus() const { return m_focus; }

 private:
  Scene& m_scene;
  Scheduler& m_scheduler;
  Focus m_focus;
};

}  // namespace hipr
