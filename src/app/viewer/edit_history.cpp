#include "app/viewer/edit_history.h"

#include <algorithm>

namespace hipr::viewer {

void EditHistory::apply(Scene& scene, const Edit& edit) {
  // The inverse looks up every name and key first: a refused edit throws here, before the
  // scene is touched.
  Edit inverse = inverse_edit(scene, edit);
  apply_edit(scene, edit);
  m_redo.clear();
  if (m_group_depth > 0 && m_group_has_step && !m_undo.empty()) {
    m_undo.back().forward.push_back(edit);
    m_undo.back().inverse.push_back(std::move(inverse));
    m_undo.back().id = m_next_id++;
    return;
  }
  m_undo.push_back({{edit}, {std::move(inverse)}, m_next_id++});
  m_group_has_step = m_group_depth > 0;
}

void EditHistory::begin_group() {
  if (m_group_depth++ == 0) m_group_has_step = false;
}

void EditHistory::end_group() {
  if (m_group_depth > 0 && --m_group_depth == 0) m_group_has_step = false;
}

bool EditHistory::undo(Scene& scene) {
  if (m_undo.empty()) return false;
  Step step = std::move(m_undo.back());
  m_undo.pop_back();
  for (auto it = step.inverse.rbegin(); it != step.inverse.rend(); ++it) apply_edit(scene, *it);
  m_redo.push_back(std::move(step));
  m_group_has_step = false;  // a group never continues into an undone step
  return true;
}

bool EditHistory::redo(Scene& scene) {
  if (m_redo.empty()) return false;
  Step step = std::move(m_redo.back());
  m_redo.pop_back();
  for (const Edit& edit : step.forward) apply_edit(scene, edit);
  m_undo.push_back(std::move(step));
  m_group_has_step = false;
  return true;
}

std::string EditHistory::label(const Step& step) {
  std::string text = describe(step.forward.front());
  if (step.forward.size() > 1) text += " (" + std::to_string(step.forward.size()) + " edits)";
  return text;
}

std::string EditHistory::undo_label() const { return m_undo.empty() ? "" : label(m_undo.back()); }
std::string EditHistory::redo_label() const { return m_redo.empty() ? "" : label(m_redo.back()); }

void EditHistory::mark_saved() { m_saved_id = top_id(); }
bool EditHistory::unsaved() const { return top_id() != m_saved_id; }

}  // namespace hipr::viewer
