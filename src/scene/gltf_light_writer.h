#pragma once
// Scene punctual lights -> KHR_lights_punctual JSON.
#include <string>
#include <vector>

#include "hipr/scene.h"
#include "scene/gltf_json_values.h"

namespace hipr::gltf {

// Rewrites colour, intensity and range of doc's KHR_lights_punctual lights where `lights`
// differ from what they load as. A colour above glTF's [0, 1] is written as colour / peak with
// intensity x peak, and the exact values go to extras.hipr_light (gltf_hipr_extras.h).
void write_lights(Json& doc, const std::vector<PunctualLight>& lights, const std::string& name);

}  // namespace hipr::gltf
