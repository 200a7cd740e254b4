// Host/device ABI of the path tracer: struct layouts and constants.
// Compiles as C++ (through glm) and as GLSL; GLSL side uses `layout(scalar)` buffers, whose
// packing equals C++'s natural packing of these float/uint members, so the two never drift.
#ifndef HIPR_SHARED_ABI_H
#define HIPR_SHARED_ABI_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
namespace hipr::abi {
using vec2 = glm::vec2;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using uint = uint32_t;
using uint64_t = std::uint64_t;
#define HIPR_CONST constexpr
#else
#define HIPR_CONST const
#endif

// Descriptor bindings are declared per pass in bindings/ (the scene's set in bindings/scene.h).

// ---- constants ----
HIPR_CONST uint kPixelOwed = 0x80000000u;
HIPR_CONST uint kPixelCountMask = 0x7fffffffu;
// Tile flags (TileState::flags, one word per tile): the interface between the engine's kernels
// and HiPR's. Who writes and who reads each (carry_tiles.comp carries the ranked ones across
// edits, mark_owed.comp clears the display's at an edit):
//   flag          written by                          read by
//   Active        mark_active, light_reach (stage 1)  trace_tiles (stage 2 requires it, the
//                                                     schedule's steps may skip it),
//                                                     schedule_keys, overlay; HiprStages (|A|)
//   Discovered    trace_tiles with discovery          schedule_keys; HiprStages (discovered)
//   Shown         resolve_display                     hipr bench (changed tiles shown)
//   Settled       resolve_display                     resolve_display
//   Focus         mark_active                         trace_tiles (the focus's target)
//   Scored        mark_active, light_reach            schedule_keys; HiprStages (seeded)
//   Reshow        resolve_display                     show_display (which clears it)
//   Reprojected   mark_active                         schedule_keys
//   Moved         mark_active                         schedule_keys
//   Lead          mark_active                         trace_tiles (a lead step requires it)
//   EditLead      mark_active                         HiprStages (lead tiles)
HIPR_CONST uint kTileActive = 1u;      // an element of E is visible in the tile (stage 1)
HIPR_CONST uint kTileDiscovered = 2u;  // reached by a secondary vertex or occlusion (stage 2)
HIPR_CONST uint kTileShown = 4u;       // since the last edit, the display has shown this tile's fresh estimate (weight >= 1/2)
HIPR_CONST uint kTileSettled = 8u;     // the display shows the fresh estimate alone, until the next edit
HIPR_CONST uint kTileFocus = 16u;      // the focus is seen in the tile (stage 1): it may run ahead of the round
HIPR_CONST uint kTileScored = 32u;     // stage 1 gave the tile a change or focus score (a seed of the order)
HIPR_CONST uint kTileReshow = 64u;     // within a resolve: show_display.comp rewrites the tile's pixels (set and cleared there)
HIPR_CONST uint kTileReprojected = 128u;  // stage 1 after a camera edit: the tile's pixels were reprojected
HIPR_CONST uint kTileMoved = 256u;        // ... and one of them moved on screen by kStillMotion or more, or was rejected
HIPR_CONST uint kTileLead = 512u;         // stage 1: the tile may run ahead of the round (the focus, or a pixel that leads after an edit)
HIPR_CONST uint kTileEditLead = 1024u;    // stage 1: a pixel of the tile leads after the edit (docs/method.md#the-edits-lead)
HIPR_CONST float kWeightScale = 16777216.0f;  // fixed-point scale of tile weights (2^24)
// Stage 1's changed-record flags: bit 0 the record is in the changed set E, the bits above
// its focus weight (kFocusWeightScale units; 0: not a focus).
HIPR_CONST uint kRecordChanged = 1u;
// The record's material is view-dependent (material_is_view_dependent): after a camera edit its
// pixels rank with the rejected ones (mark_active.comp). Not a change: discovery ignores it.
HIPR_CONST uint kRecordViewDependent = 0x80000000u;
HIPR_CONST uint kFocusWeightShift = 1u;
HIPR_CONST float kFocusWeightScale = 16.0f;
HIPR_CONST uint kFocusWeightMax = 16000u;       // a seed's weight, fixed point (1000 x the scale)
HIPR_CONST uint kFocusPixelMax = 0x7fffu;       // a pixel's summed focus weight (tile sums stay in 32 bits)
HIPR_CONST uint kMaxFocusDiscs = 16u;
// Changed punctual lights stage 1 follows to the surfaces they reach (light_reach.comp); an edit
// that changes more makes every tile active.
HIPR_CONST uint kMaxReachLights = 16u;
// light_reach.comp: a reached pixel scores 1 + kReachScoreScale x r^2, r the relative change of
// its direct light (a mark_active.comp pixel scores 1 or 2).
HIPR_CONST float kReachScoreScale = 63.0f;
HIPR_CONST uint kSortBlock = 256u;     // keys per workgroup in the radix sort
HIPR_CONST uint kSortRadix = 256u;     // 8-bit digits

// Lobe and path-prefix classes of discovery weights (w_lobe, w_path indices).
HIPR_CONST uint kPathDirect = 0u;    // x_k is the first vertex after the camera hit (k = 1)
HIPR_CONST uint kPathIndirect = 1u;  // an earlier diffuse/glossy bounce after x_0 (E D D+ ...)
HIPR_CONST uint kPathCaustic = 2u;   // x_0 diffuse, then only specular/transmission (E D S+ ...)
HIPR_CONST uint kWorkgroupSize = 64u;

// Path guiding (common/guiding.glsl): directions fall in kGuidePhiBins x kGuideCosBins bins of
// equal solid angle (azimuth about +Y x the cosine to +Y). Per cell the guide keeps kGuideSlots
// floats (the bins' CDF, then the guide's probability) and the training kGuideSumSlots integers
// (each bin's sum, each bin's largest splat, then the cell's number of splats).
HIPR_CONST uint kGuidePhiBins = 16u;
HIPR_CONST uint kGuideCosBins = 8u;
HIPR_CONST uint kGuideBins = kGuidePhiBins * kGuideCosBins;
HIPR_CONST uint kGuideSlots = kGuideBins + 1u;
HIPR_CONST uint kGuideSumSlots = 2u * kGuideBins + 1u;
HIPR_CONST uint kGuideMaxCells = 4096u;
HIPR_CONST uint kInvalidIndex = 0xffffffffu;
HIPR_CONST uint kRecordUnknown = 0xfffffffeu;  // DisplayTexel: no G-buffer said which surface it shows
// DisplayTexel: reprojected from the view before a camera edit and rejected (off-screen,
// disoccluded, another surface there): it depicts no surface the pixel sees now.
HIPR_CONST uint kRecordRejected = 0xfffffffdu;
// GBufferTexel::normal, DisplayTexel::shownNormal / staleNormal: no normal known (the
// environment, or a value of unknown surface). Octahedral normals (common/octahedral.glsl) are
// two snorm16 in [-32767, 32767]: -32768 in both halves is none of them.
HIPR_CONST uint kNormalUnknown = 0x80008000u;
// Two records' surfaces differ where their geometric normals are further apart than this
// (about 25 degrees): a block's side face and its front face are one record, but a value of one
// is no estimate of the other.
HIPR_CONST float kSurfaceTurnCosine = 0.9f;

HIPR_CONST uint kLightTriangle = 0u;
HIPR_CONST uint kLightPoint = 1u;
HIPR_CONST uint kLightSpot = 2u;
HIPR_CONST uint kLightDirectional = 3u;
HIPR_CONST uint kLightEnvironment = 4u;

// Random numbers of paths (common/rng.glsl); values of RenderSettings::sampler.
HIPR_CONST uint kSamplerSobol = 0u;
HIPR_CONST uint kSamplerRandom = 1u;

// The colour channel a path carries after a dispersive dielectric (common/dispersion.glsl):
// 0, 1, 2 for R, G, B, or none yet.
HIPR_CONST uint kNoChannel = 3u;

// HIPR_LIGHT_SAMPLING values (a define of trace_tiles.comp).
#define kLightSamplingMis 0
#define kLightSamplingBsdfOnly 1
#define kLightSamplingLightOnly 2

HIPR_CONST uint kMaterialDoubleSided = 1u;
HIPR_CONST uint kMaterialThinWalled = 2u;
HIPR_CONST uint kMaterialIgnoreTextureAlpha = 4u;  // glTF OPAQUE: base colour texture alpha is not opacity

HIPR_CONST uint kTextureSrgb = 1u;        // texels are sRGB-encoded colour (decode to linear)
HIPR_CONST uint kTextureNearest = 2u;     // nearest-texel lookup instead of bilinear
HIPR_CONST uint kTextureClampU = 4u;
HIPR_CONST uint kTextureClampV = 8u;
HIPR_CONST uint kTextureMirrorU = 16u;
HIPR_CONST uint kTextureMirrorV = 32u;
HIPR_CONST uint kTextureUv1 = 64u;        // reads TEXCOORD_1 instead of TEXCOORD_0

// Software traversal (devices without ray queries): a two-level BVH built on the host
// (src/render/bvh_builder.cpp, src/render/software_bvh.cpp) and walked by
// shaders/common/bvh_traversal.glsl. A node's count is kBvhLeaf | items for a leaf (items at
// `first`), 0 for an interior node (children at `first` and `first + 1`).
HIPR_CONST uint kBvhLeaf = 0x80000000u;
HIPR_CONST uint kBvhMaxDepth = 30u;          // the builder's limit: the kernels' stacks hold 32
HIPR_CONST uint kBvhTriangleCutout = 0x80000000u;  // BvhTriangle::geometry: runs the opacity test

// ---- structs ----

// One entry per (instance, mesh primitive): TLAS instance custom index + geometry index.
struct GeometryRecord {
  uint materialIndex;
  uint firstIndex;    // into the index buffer
  uint vertexOffset;  // added to every index
  uint lightOffset;   // first Light of this primitive's emissive triangles, or kInvalidIndex
  // The record's index in a fresh upload of the scene (records in Scene::instances() order).
  // Edits that add or remove instances keep every other record where it is (stored G-buffers
  // name records), so the index may differ; what must not differ, the cutout's random choice,
  // keys on this.
  uint identity;
};

// OpenPBR 1.1 surface parameters (names follow the spec). The foundation BSDF reads the base
// diffuse and emission; the remaining parameters are carried for the full OpenPBR BSDF.
// Units: thin_film_thickness(_min) in nanometres (glTF's unit; OpenPBR's micrometres x 1000),
// specular_rotation in radians
// (glTF's anisotropyRotation, counter-clockwise from the tangent), transmission_depth in metres.
// How glTF fills each field: src/scene/gltf_material_table.cpp.
struct MaterialBlock {
  vec3 base_color;
  float base_weight;
  float base_metalness;
  float base_diffuse_roughness;
  float specular_weight;
  float specular_roughness;
  vec3 specular_color;
  float specular_ior;
  float specular_anisotropy;
  float specular_rotation;
  float transmission_weight;
  float transmission_depth;
  vec3 transmission_color;
  float transmission_dispersion_scale;        // Abbe number: abbe_number / scale (0: none)
  float transmission_dispersion_abbe_number;
  float subsurface_weight;
  vec3 subsurface_color;
  float subsurface_radius;
  float coat_weight;
  float coat_roughness;
  float coat_ior;
  float coat_darkening;
  vec3 coat_color;
  float fuzz_weight;
  vec3 fuzz_color;
  float fuzz_roughness;
  float thin_film_weight;
  float thin_film_thickness;      // at iridescence_thickness_texture G = 1 (or without texture)
  float thin_film_ior;
  float thin_film_thickness_min;  // at iridescence_thickness_texture G = 0
  float emission_luminance;
  vec3 emission_color;
  float geometry_opacity;
  float alpha_cutoff;  // >= 0: opaque where opacity >= cutoff, else absent (MASK); < 0: stochastic coverage
  uint flags;  // kMaterial*
  float normal_scale;
  float coat_normal_scale;
  // Texture indices into the TextureInfo table, or kInvalidIndex. Channels as glTF packs them.
  uint base_color_texture;         // RGB: base_color, A: opacity
  uint metallic_roughness_texture; // glTF packing: G roughness, B metalness
  uint normal_texture;             // tangent-space normal map
  uint emission_texture;           // RGB: emission_color multiplier
  uint transmission_texture;          // R: transmission_weight
  uint clearcoat_texture;             // R: coat_weight
  uint clearcoat_roughness_texture;   // G: coat_roughness
  uint clearcoat_normal_texture;      // tangent-space normal of the coat (coat_normal_scale)
  uint sheen_color_texture;           // RGB: fuzz_color
  uint sheen_roughness_texture;       // A: fuzz_roughness
  uint specular_texture;              // A: specular_weight
  uint specular_color_texture;        // RGB: specular_color
  uint iridescence_texture;           // R: thin_film_weight
  uint iridescence_thickness_texture; // G: thin_film_thickness = mix(min, max, G)
  uint anisotropy_texture;            // RG: direction in tangent space (x2-1), B: strength
};

// How a material reads one texture: which texels, sampler, UV set and UV transform
// (KHR_texture_transform). Several entries may share texels (texelOffset).
struct TextureInfo {
  uint texelOffset;
  uint width;
  uint height;
  uint flags;         // kTexture*
  vec3 uvTransformU;  // u' = dot(uvTransformU, vec3(u, v, 1))
  vec3 uvTransformV;  // v' = dot(uvTransformV, vec3(u, v, 1))
};

// What shaders/common/material_inputs.glsl returns at one surface point (material_probe.comp).
struct MaterialInputsProbe {
  float transmissionWeight;
  float coatWeight;
  float coatRoughness;
  vec3 coatNormal;
  vec3 fuzzColor;
  float fuzzRoughness;
  float specularWeight;
  vec3 specularColor;
  float thinFilmWeight;
  float thinFilmThickness;
  float anisotropyStrength;
  vec3 anisotropyDirection;
};

// Where material_probe.comp evaluates: a point of one triangle, in its object space.
struct ProbePush {
  uint record;
  uint primitive;
  vec2 barycentrics;
};

// Emissive triangles reference their geometry (so emission textures evaluate exactly as on a
// hit); punctual lights use position/direction/intensity; the environment uses none of these.
struct Light {
  uint type;
  uint geometryRecord;  // triangle: the GeometryRecord it belongs to
  uint primitive;       // triangle: primitive index within that record
  float area;           // triangle: world-space area
  vec3 position;        // triangle: vertex 0; point/spot: position
  float spotCosOuter;
  vec3 edge1;           // triangle: v1 - v0
  float spotCosInner;
  vec3 edge2;           // triangle: v2 - v0
  float range;          // point/spot: 0 = infinite
  vec3 direction;       // spot/directional: direction the light travels
  uint group;           // light group its contribution is kept in, kInvalidIndex: pooled
  vec3 intensity;       // point/spot: candela * colour; directional: lux * colour
  uint treeLeaf;        // its leaf in the light tree (LightTreeNode), kInvalidIndex: not in it
};

// Many-light sampling (src/render/light_tree.h, common/light_tree.glsl): a node of the binary
// tree over the lights at finite distance. An inner node's children are `child` and `child + 1`.
// 44 bytes, of which the walk reads 40 per child (the 64-byte node before, box corners and a
// word per cosine and flag, took 0-4 % more of a render on lavapipe: BENCHMARKS.md).
// Flags in `child`; the low bits are the first child, or the light of a leaf:
HIPR_CONST uint kLightTreeLeaf = 0x80000000u;
HIPR_CONST uint kLightTreeTwoSided = 0x40000000u;  // some light emits on both sides (the cone holds both ways)
// Every light is a one-sided surface facing exactly `axis` (spread 0, reach 90 degrees) and lies
// where dot(axis, y) >= front, `cone` holding front's bits: a point x with dot(axis, x) < front is
// behind all of them and gets no light. The cone bound cannot say so for a point inside the
// node's bounding sphere (a ceiling point beside a ceiling light).
HIPR_CONST uint kLightTreeFacing = 0x20000000u;
// An inner node whose lights the cost of a split could not tell apart (no plane divides them
// into groups whose power, cone and box are smaller: the two triangles of one quad lamp): the
// walk takes its children, and theirs, by power alone, as the power CDF would, without the two
// importances a level (src/render/light_tree.cpp: at most 8 lights below it).
HIPR_CONST uint kLightTreeByPower = 0x10000000u;
HIPR_CONST uint kLightTreeIndexMask = 0x0fffffffu;
struct LightTreeNode {
  vec3 centre;    // of the box around its lights
  float radius2;  // squared distance from centre to the box's corners, rounded up: a sphere around every light
  vec3 axis;      // unit; every emitting normal or spot axis is within theta_o of it
  float power;    // the sum of its lights' intensity toward a point in front (luminance)
  // Without kLightTreeFacing: cos theta_o (low 16 bits) and cos theta_e (how far past an
  // emitting normal light leaves; high 16 bits), each (cos + 1) / 2 as unorm16 rounded down
  // (wider cones; common/light_tree_cone.glsl decodes). With it: front.
  uint cone;
  uint child;
  uint parent;  // kInvalidIndex at the root; read only by the walk up (light_tree_pmf)
};

// count's top bit (kPixelOwed) marks a pixel that still holds radiance from before the last
// edit: its next visit restarts it. Until then it keeps showing the previous radiance.
// sumSquares (per channel) gives the variance of the mean, which the display rule weighs
// against how far the fresh estimate is from the stale one.
struct PixelAccum {
  vec3 sum;
  uint count;
  vec3 sumSquares;
};

// What the screen shows at a pixel (`shown`), and the stale estimate captured at the last edit
// (`stale`, the mean of `staleSamples` samples) that the display rules weigh fresh samples against.
struct DisplayTexel {
  vec3 shown;
  uint staleSamples;
  vec3 stale;
  uint shownSamples;  // samples behind `shown`: 1 / its variance in units of one sample's (a blend: of its mix)
  uint shownRecord;   // the G-buffer record (surface) `shown` depicts, kRecordUnknown if not known
  uint staleRecord;   // the same for `stale`
  uint shownNormal;   // the G-buffer's geometric normal with shownRecord (kNormalUnknown if not known)
  uint staleNormal;   // the same for `stale`
  uint flags;         // kShownGrouped, kStaleGrouped, kShownCurrent, kStaleCurrent
  // The share of `shown`'s variance left on the screen when the display denoiser last filtered
  // it (denoise_blend.comp); 1 where it has not since the last edit or camera move (the capture
  // and the reprojection reset it). The display rules weigh a fresh estimate by the noise the
  // screen shows of it (show_display.comp).
  float screenNoise;
};

// The difference estimate (docs/method.md#the-difference-estimate): per pixel, the values of the
// first kDifferenceSamples samples of the last scene state that reached them, so that after an
// edit sample i of the new state, drawn with the same random numbers, is compared with sample i of
// the old one. Values are kept as floats rounded to a half's precision (11 significant bits, no
// clamp to its range): a value the edit did not change rounds the same on both sides, so its
// difference is exactly zero, and the sun's nits are kept as they are.
HIPR_CONST uint kDifferenceSamples = 2u;
// DifferenceRecord::values, three per colour: the kept samples (slot j at 3j), then since the
// last edit, for the differenced samples i (d_i = new_i - old_i; w = 1 / (stale^2 + 0.01), the
// weights relMSE gives errors): the sum of d_i, the sums of w d_i (old_i - stale) and of
// w (old_i - stale)^2 (per channel: their ratio over a tile estimates how much of the old samples'
// noise the new ones replaced) and, last, one value: the sum over channels of w d_i^2. A sum that
// overflows (beyond any radiance a scene may hold, scene/scene_limits.h) marks a sample too bright
// to judge (resolve_display.comp keeps the pixel's stale value).
HIPR_CONST uint kDifferenceSum = 6u;
HIPR_CONST uint kDifferenceCross = 9u;
HIPR_CONST uint kDifferenceOld = 12u;
HIPR_CONST uint kDifferenceSquares = 15u;
HIPR_CONST uint kDifferenceValues = 16u;
// DisplayTexel::flags bits 4-5: how many kept samples are of the scene state the stale estimate
// is of (0: no difference estimate). Set by the capture, cleared by a relight.
HIPR_CONST uint kDifferenceValidShift = 4u;
HIPR_CONST uint kDifferenceValidMask = 3u;

// 64 bytes per pixel (resolve_display.comp reads it; trace_tiles.comp writes it).
struct DifferenceRecord {
  float values[kDifferenceValues];
};

// What resolve_display.comp judged of a tile at its last resolve since the last edit (the
// capture clears it), for show_display.comp: the gate of its pixels and, for the difference rule,
// the sums its pixels' regression weights are fitted on.
struct TileJudgement {
  vec3 cross;       // difference rule: sum w d (old - s) over the tile's changed pixels, per channel
  vec3 spread;      // difference rule: sum w (old - s)^2 over them; a pixel's regression weight
                    // is fitted on the others' sums (held_out_regression)
  uint state;       // kJudge*
  uint epoch;       // ResolvePush::epoch of the resolve that judged it (0: the capture)
};
// show_display.comp weighs a pixel by the display rule's sums over the square of
// (2 kDisplayWindowRadius + 1)^2 pixels around it (9 x 9: about an 8 x 8 tile's statistics),
// not over its tile: no tile seams.
HIPR_CONST uint kDisplayWindowRadius = 4u;
HIPR_CONST uint kJudgeNone = 0u;     // not resolved since the last edit
HIPR_CONST uint kJudgeStale = 1u;    // a pixel lacks the fresh samples to judge: blend pixels keep s
HIPR_CONST uint kJudgeWeighed = 2u;  // blend pixels show what the rule weighs over their windows
HIPR_CONST uint kJudgeFresh = 3u;    // blend pixels show f (difference pixels still their estimate)
HIPR_CONST uint kJudgeSettled = 4u;  // every pixel shows f alone, until the next edit

// At most this many punctual lights are sampled each at every vertex (render/light_tables.h).
HIPR_CONST uint kEachPunctualLights = 8u;

// Light groups (relight.comp): each group's share of a pixel's radiance is kept apart, so an edit
// of an emitter's intensity or colour rescales it. At most this many groups.
HIPR_CONST uint kMaxLightGroups = 8u;
// DisplayTexel::flags: the per-group parts of `shown` / `stale` are in the stale-groups buffer
// (shown only while it equals stale; relight.comp); `shown` is an estimate of the scene as it is
// since the last edit (not the stale estimate of an earlier one: the difference estimate needs to
// know which scene state a captured value is of).
HIPR_CONST uint kShownGrouped = 1u;
HIPR_CONST uint kStaleGrouped = 2u;
HIPR_CONST uint kShownCurrent = 4u;
HIPR_CONST uint kStaleCurrent = 8u;  // `stale` is an estimate of the scene since the last edit too (relit)
// Set by reproject_display.comp, cleared by the next capture: the pixel's value was reprojected
// from less than kStillMotion pixels away (the surface barely moved on screen).
HIPR_CONST uint kShownStill = 64u;
HIPR_CONST float kStillMotion = 0.25f;

// Parameters of relight.comp: per light group, the factor (per channel) its radiance is scaled by.
struct RelightPush {
  vec3 factors[kMaxLightGroups];
  uint pixelCount;
  uint groupCount;
};

// resolve_display.comp rules (ResolvePush::rule).
HIPR_CONST uint kDisplayImmediate = 0u;  // a pixel shows its fresh estimate from its first sample
HIPR_CONST uint kDisplaySwitch = 1u;     // a tile shows its fresh estimate once it is expected closer to the truth
HIPR_CONST uint kDisplayBlend = 2u;      // a tile shows the blend of stale and fresh with the least expected error
HIPR_CONST uint kDisplayCapture = 3u;    // at an edit: what is shown becomes the stale estimate
HIPR_CONST uint kDisplayDifference = 4u; // blend, where a pixel's stale estimate is corrected by its difference estimate

// Counters the kernels add to. 64-bit so long renders never wrap.
struct RenderStats {
  uint64_t rays;        // all of them: camera + extension + shadow
  uint64_t cameraRays;  // a path's first segment (none in a tile the camera sees no object in)
  uint64_t shadowRays;  // toward a light sample
  uint64_t samples;
  uint nonFiniteSamples;
  uint padding;
  uint64_t guideRays;   // traced by the guide's training paths (all kinds; not in `rays`)
};

struct FrameParams {
  vec3 cameraPosition;
  float tanHalfFovY;
  vec3 cameraRight;  // unit vectors of the camera frame in world space
  float aspect;      // width / height
  vec3 cameraUp;
  vec3 cameraForward;
  uint seed;
  uint width;
  uint height;
  uint tileSize;
  uint tilesX;
  uint maxDepth;
  uint lightCount;         // entries in the Light table
  uint environmentLight;   // index of the environment in the Light table, or kInvalidIndex
  uint environmentWidth;
  uint environmentHeight;
  float environmentIntensity;
  float environmentRotation;  // radians about +Y
  // HiPR discovery (stage 2): tile weight dW = lum(beta_k) * wLobe[l] * wPath[c] / (1 + k)
  vec4 wLobe;         // diffuse, glossy, specular, transmission (sum 1)
  vec3 wPath;         // direct, indirect, caustic (sum 1)
  float wOcclusion;   // added (times lum(beta)) when a shadow ray is blocked by E
  float depthEpsilon; // relative depth tolerance of the projection test
  uint tileCount;
  uint tilesY;
  float rayOffsetScale;  // size of the scene (diagonal of its bounds): scales ray_offset.glsl's offsets
  uint sampleSequence;   // kSamplerSobol or kSamplerRandom (common/rng.glsl)
  float lensRadius;      // thin lens (world units); 0: a pinhole (Camera::aperture_radius)
  float focusDistance;   // along the view axis: the plane that stays sharp
  // Light selection (common/lights.glsl): with this probability the light tree picks a light at
  // finite distance (0: a power CDF over every light picks them all, --light-selection power);
  // otherwise the CDF at b_light_cdf[lightCdfOffset] picks among the rest (the lights at infinity).
  float lightTreeProbability;
  uint lightCdfOffset;
  // Path guiding (common/guiding.glsl; 0 cells: none): a grid of guideResolution cells over the
  // scene's bounds from guideLo, guideInvCell cells per world unit along each axis.
  vec3 guideLo;
  uint guideCells;
  vec3 guideInvCell;
  uint guideResolutionX;
  uint guideResolutionY;
  uint guideResolutionZ;
  // Punctual lights sampled each at every vertex (common/lights.glsl): Light table entries
  // [eachLightOffset, eachLightOffset + eachLightCount), which light selection never picks.
  uint eachLightOffset;
  uint eachLightCount;
};

// Software traversal: one BVH node (bounds in the space of the level it belongs to).
struct BvhNode {
  vec3 lo;
  uint first;
  vec3 hi;
  uint count;
};

// A triangle of a mesh's BVH, its vertices gathered in object space.
struct BvhTriangle {
  vec3 v0;
  uint geometry;   // primitive of the mesh (the geometry index a ray query reports) | kBvhTriangleCutout
  vec3 v1;
  uint primitive;  // triangle index within that primitive
  vec3 v2;
  uint padding;
};

// A visible instance in the top-level BVH: its transforms as rows of 3x4 matrices.
struct BvhInstance {
  vec4 worldToObject[3];
  vec4 objectToWorld[3];
  uint blasRoot;     // its mesh's root in the node buffer of all meshes
  uint customIndex;  // first GeometryRecord of the instance
  uint padding0;
  uint padding1;
};

// Stage 1 output per pixel: what the pixel-centre ray hit.
struct GBufferTexel {
  uint record;  // GeometryRecord index, kInvalidIndex for background
  float depth;  // camera-space depth (along the view axis); 3e38 for background
  uint normal;  // the triangle's geometric normal in world space (octahedral), kNormalUnknown for background
};

// Per-dispatch parameters of trace_tiles.comp.
struct TracePush {
  uint listOffset;       // first entry of the tile list to render
  uint tileCount;        // entries of the tile list to render
  uint tileStride;       // coprime to the workgroup count: spreads tiles over CPU threads
  uint samplesPerPixel;  // samples each pixel receives in this dispatch
  uint groupsPerTile;    // workgroups needed to cover one tile
  uint requireFlags;     // render only tiles whose flags have all of these bits
  uint skipFlags;        // skip tiles whose flags have any of these bits
  // 0: every pixel gets samplesPerPixel more. Otherwise the scheduler's round target: a pixel
  // gets what it lacks of this many samples (none when it has them), so a re-planned round
  // leaves every pixel with the same count (docs/method.md#focus).
  uint sampleTarget;
  // With a round target: the target of the tiles flagged kTileFocus (the focus runs ahead of the
  // round, never past the count the render converges to); 0: sampleTarget.
  uint focusTarget;
  // With a round target: the target of the pixels stage 1 marked in the pixel-lead bits (after an
  // edit, those that show a moved, shown or hidden object or a surface they no longer see: their
  // fresh estimate is on screen from its first samples; docs/method.md#the-edits-lead); 0: none.
  uint leadTarget;
};

// A pinhole view as FrameParams holds it: what reproject_display.comp needs of the camera before
// a camera edit (the push constant).
struct ViewFrame {
  vec3 position;
  float tanHalfFovY;
  vec3 right;  // unit
  float aspect;
  vec3 up;  // unit
  uint padding0;
  vec3 forward;  // unit
  uint padding1;
};

// Stage 1's focus (docs/method.md#focus): a disc on screen whose pixels are seeds.
struct FocusDisc {
  vec2 center;  // pixels, x right, y down (a pixel's centre is at + 0.5)
  float radius;  // pixels
  uint weight;   // fixed point, kFocusWeightScale units
};

// Per-dispatch parameters of resolve_display.comp: which schedule entries to resolve (as
// TracePush) and how.
struct ResolvePush {
  uint listOffset;  // kInvalidIndex: tiles 0 .. tileCount - 1 in id order, without the list
  uint tileCount;
  uint requireFlags;
  uint skipFlags;
  uint rule;        // kDisplay*
  float threshold;  // switch: show the fresh estimate when D > threshold * V (see the shader)
  uint useGBuffer;  // 1: the G-buffer describes the current scene (stage 1 ran since the last edit)
  uint difference;  // 1: the film keeps DifferenceRecords (the capture maintains them)
  uint epoch;       // this resolve's number (> 0): show_display.comp skips pixels no tile it judged reaches
  uint showReach;   // tiles around a judged one that hold pixels whose window reaches into it (0 for immediate)
};

// Per-dispatch parameters of display.comp: the rendered image is drawn into the window at
// (viewX, viewY) scaled by viewScale (window pixels per rendered pixel, nearest texel).
struct DisplayPush {
  uint outputWidth;
  uint outputHeight;
  uint sourceWidth;
  uint sourceHeight;
  int viewX;
  int viewY;
  float viewScale;
  float exposureScale;  // 2^EV, as tonemap_srgb8
  uint background;      // RGBA8 outside the rendered image
  uint overlayEnabled;  // 0: the overlay buffer is ignored
  uint toneMapper;      // kTone* (common/tone_mappers.glsl), after the exposure
  uint sourceStride;    // floats per rendered pixel in the source; its first three: the radiance
};

// The viewer's overlays (overlay.comp): what OverlayPush::mode draws over the image.
HIPR_CONST uint kOverlayNone = 0u;
HIPR_CONST uint kOverlayIds = 1u;      // each object in its own colour, opaque
HIPR_CONST uint kOverlayWeights = 2u;  // stage 2's tile weights as a heat map, active tiles blue
HIPR_CONST uint kOverlayOwed = 3u;     // tiles still showing radiance from before the last edit

struct OverlayPush {
  uint mode;           // kOverlay*
  uint selectedNode;   // its outline is drawn on top; kInvalidIndex: none
  uint pass;           // 0: the largest tile weight (over tiles), 1: the overlay (over pixels)
  uint width;
  uint height;
  uint tileSize;
  uint tilesX;
  uint tileCount;
};

// Per GeometryRecord, what the overlays colour and outline by.
struct OverlayRecord {
  uint instance;
  uint node;
};

// Radix sort pass: keys/values move from one buffer pair to the other by one 8-bit digit.
struct SortPush {
  uint count;
  uint shift;    // 0, 8, 16, 24
  uint pingToPong;  // 1: read ping write pong; 0: the reverse
  uint groups;   // workgroups over `count` keys
};

// ---- the display denoiser (denoise_*.comp; docs/method.md, "The denoised display") ----
// What the pixel centre's ray sees, guiding the filter's edges: recomputed only when the scene
// or the camera changed.
struct DenoiseGuide {
  uint record;     // GeometryRecord, kInvalidIndex for background
  float distance;  // along the pixel centre's ray (0 for background)
  uint normal;     // vertex normal (before normal mapping) facing the camera, octahedral, two snorm16
  uint albedo;     // what the radiance is demodulated by: unorm8 RGB; A 0 where veiled, 0.25 on an
                   // outline (guide_veiled, guide_outline)
  uint emissionRG; // what the surface emits toward the camera, set apart before the filter:
  uint emissionB;  // three halfs (infinite past half's range: such a pixel is shown as it is);
                   // background: the environment's mean over the pixel's footprint, where the
                   // fourth half (emissionB's high half) is positive: the standard deviation of
                   // its luminance there, at least kFootprintDeviationFloor (footprint_environment)
};

HIPR_CONST float kFootprintDeviationFloor = 1.0e-4;
// The environment's mean over a pixel is that of this many stratified lookups: shown while the
// pixel has fewer samples (denoise_prepare.comp: kept_value).
HIPR_CONST uint kFootprintLookups = 128u;

// A pixel's key in the filter (denoise_prepare.comp): neighbours mix only where their keys do
// (common/denoise.glsl: keys_mix).
HIPR_CONST uint kDenoiseSurfaceMask = 0x0fffffffu;  // the surface shown, + 1
// What is shown is the stale estimate, bit for bit, though the pixel was re-rendered since the
// edit: its fresh samples found no change (the difference rule). It mixes with either state.
HIPR_CONST uint kDenoiseUnchanged = 0x10000000u;
HIPR_CONST uint kDenoiseBoundary = 0x20000000u;     // a neighbour sees another surface, normal or albedo
HIPR_CONST uint kDenoiseCurrent = 0x40000000u;      // what is shown is of the scene since the last edit
HIPR_CONST uint kDenoiseKept = 0x80000000u;         // shown as it is, read by no neighbour

struct DenoisePush {
  uint width;
  uint height;
  uint step;           // a-trous pass: the taps' spacing (1, 2, 4, ...)
  uint historyReset;   // temporal: 1 starts the history over (an edit, a camera move, settings)
  float strength;      // scales the luminance edge's tolerance (0: nothing moves)
  uint displayState;   // prepare: 1 uses the display's sample counts and scene states
  float historyKeep;   // temporal: the share of the last frame kept per sample (0: none)
};

#ifdef __cplusplus
}  // namespace hipr::abi
#endif
#endif
