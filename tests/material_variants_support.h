#pragma once
// The shipped Cornell box with two KHR_materials_variants variants, for the variant tests.
#include <filesystem>

namespace hipr::test {

// Writes it into `dir` (with its .bin): variant "warm" makes the tall block red and the short
// one green; variant "lamp" makes the tall block of the ceiling light's emissive material.
std::filesystem::path cornell_box_with_variants(const std::filesystem::path& dir);

}  // namespace hipr::test
