#pragma once
// The geometry edits (duplicate, delete, import, deform) and their undo, applied to the scene
// model: see hipr/edits.h for what each does.
#include "hipr/edits.h"

namespace hipr {

void apply_duplicate(Scene& scene, const DuplicateEdit& edit);
void apply_delete(Scene& scene, const DeleteEdit& edit);
void apply_import(Scene& scene, const ImportEdit& edit);
void apply_deform(Scene& scene, const DeformEdit& edit);
void apply_structure(Scene& scene, const StructureEdit& edit);

// Throw the InputError the apply_ function would, without changing anything (inverse_edit
// checks an edit before building its undo). An import is checked when it loads its file.
void check_duplicate(const Scene& scene, const DuplicateEdit& edit);
void check_deform(const Scene& scene, const DeformEdit& edit);

// The undo of a duplicate, delete or import: the structure as it is now.
StructureEdit structure_undo(const Scene& scene);

// A camera edit in a scene without a camera node first makes its default view
// (Scene::default_camera) a camera node, so that the edit has something to move. Returns the
// camera node.
size_t pin_default_camera(Scene& scene);

}  // namespace hipr
