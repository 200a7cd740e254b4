#pragma once
#include <filesystem>

#include "hipr/scene.h"

namespace hipr {

// Reads an equirectangular .hdr/.exr (any size) as linear RGB. Non-finite or negative texels
// become 0 (with one warning) so the importance-sampling tables stay valid.
Environment load_environment(const std::filesystem::path& path);

}  // namespace hipr
