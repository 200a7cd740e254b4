#pragma once
// The table of editable OpenPBR parameters: name -> field of MaterialParameters.
#include <string>
#include <vector>

#include "hipr/material.h"

namespace hipr {

struct MaterialParameter {
  const char* name;
  size_t offset;   // into MaterialParameters
  int components;  // 1 (scalar) or 3 (colour)
  float min;       // valid range of every component
  float max;
};

const std::vector<MaterialParameter>& material_parameters();
const MaterialParameter* find_material_parameter(const std::string& name);

}  // namespace hipr
