#include "hipr/edit_pipeline.h"

namespace hipr {

ChangeSet change_scene(Scene& scene, const std::function<void(Scene&)>& change) {
  const Scene before = diff_snapshot(scene);
  change(scene);
  return diff_scenes(before, scene);
}

ChangeSet EditPipeline::apply(const Edit& edit) {
  if (const auto* focus = std::get_if<FocusEdit>(&edit)) {
    m_focus = with_focus_edit(m_scene, m_focus, *focus);
    m_scheduler.set_focus(m_focus);
    return {};
  }
  return apply([&](Scene& scene) { apply_edit(scene, edit); });
}

ChangeSet EditPipeline::apply(const std::function<void(Scene&)>& change) {
  const std::vector<Instance> before =
      m_focus.empty() ? std::vector<Instance>{} : m_scene.instances();
  const ChangeSet changes = change_scene(m_scene, change);
  if (!m_focus.empty()) {  // a duplicate or delete renumbers the instances the seeds name
    m_focus = follow_instances(m_focus, before, m_scene.instances());
    m_scheduler.renumber_focus(m_focus);
  }
  if (!changes.empty())
    m_scheduler.on_edit(m_scene, changes);  // e.g. a slider released where it started
  return changes;
}

}  // namespace hipr
