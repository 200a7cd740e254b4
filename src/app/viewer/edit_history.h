#pragma once
// Undo/redo of scene edits. A step is one or more edits with their inverses (inverse_edit);
// a group (one mouse drag, one slider drag) makes a single step however many edits it issued.
// Undo applies the step's inverses newest first, redo its edits again; the caller diffs the
// scene before and after and hands the change to the scheduler, so HiPR re-renders what an
// undo changed exactly as it does for an edit.
#include <cstdint>
#include <string>
#include <vector>

#include "hipr/edits.h"

namespace hipr::viewer {

class EditHistory {
 public:
  // Applies `edit` to `scene` and records it, dropping anything that could be redone. An
  // edit apply_edit refuses throws InputError with the scene untouched and nothing recorded.
  void apply(Scene& scene, const Edit& edit);

  // Edits between begin_group and end_group form one step (nested calls are counted).
  void begin_group();
  void end_group();

  bool can_undo() const { return !m_undo.empty(); }
  bool can_redo() const { return !m_redo.empty(); }
  size_t undo_count() const { return m_undo.size(); }
  size_t redo_count() const { return m_redo.size(); }
  // Restores the scene before the last step; false when there is nothing to undo.
  bool undo(Scene& scene);
  // Applies the last undone step again; false when there is nothing to redo.
  bool redo(Scene& scene);
  // What undo / redo would do, for the UI ("transform tall_block", "material red (12 edits)").
  std::string undo_label() const;
  std::string redo_label() const;

  // The scene as it is now was saved (or loaded); unsaved() tells whether it changed since.
  void mark_saved();
  bool unsaved() const;

 private:
  struct Step {
    std::vector<Edit> forward;
    std::vector<Edit> inverse;  // inverse[i] undoes forward[i]
    uint64_t id = 0;            // changes whenever the step's edits change (unsaved())
  };
  static std::string label(const Step& step);
  uint64_t top_id() const { return m_undo.empty() ? 0 : m_undo.back().id; }

  std::vector<Step> m_undo, m_redo;
  int m_group_depth = 0;
  bool m_group_has_step = false;  // the open group already pushed its step
  uint64_t m_next_id = 1;
  uint64_t m_saved_id = 0;  // top_id() when saved
};

}  // namespace hipr::viewer
