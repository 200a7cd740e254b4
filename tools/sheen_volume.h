#pragma once
// The volume OpenPBR's fuzz stands for (Zeltner, Burley and Chiang 2022): a slab of unit
// thickness and density filled with white fibre-like SGGX microflakes standing along the
// normal, of roughness alpha (the SGGX matrix diag(1, 1, alpha^4) in the slab's frame). Its
// directional albedo R(mu, alpha) is what the fuzz lobe reflects; the LTC sheen's albedo fit
// and table were made from the same simulation. Deterministic for a given seed.
#include <cstdint>

namespace hipr::tools {

// Share of the light arriving at cosine mu that the slab sends back up (light leaving through
// the bottom is lost), from `paths` random walks.
double sheen_volume_albedo(double mu, double alpha, int paths, std::uint64_t seed);

}  // namespace hipr::tools
