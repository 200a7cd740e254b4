#pragma once
// Public material parameters into the GPU's MaterialBlock (shaders/shared/abi.h).
#include "hipr/material.h"
#include "shaders/shared/abi.h"

namespace hipr {

abi::MaterialBlock pack_material(const MaterialParameters& parameters);

}  // namespace hipr
