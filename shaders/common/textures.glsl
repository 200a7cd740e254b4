// Texture lookups from the packed RGBA8 texel buffer, with bilinear filtering and the glTF
// wrap modes. sRGB textures are decoded per texel before filtering, as hardware does. Each
// TextureInfo picks its UV set and applies its KHR_texture_transform before the lookup.
#ifndef HIPR_TEXTURES_GLSL
#define HIPR_TEXTURES_GLSL

float srgb_to_linear(float c) {
  return c <= 0.04045 ? c * (1.0 / 12.92) : pow((c + 0.055) * (1.0 / 1.055), 2.4);
}

int wrap_coord(int i, int size, bool clamp_mode, bool mirror) {
  if (clamp_mode) return clamp(i, 0, size - 1);
  if (mirror) {
    const int period = 2 * size;
    int m = i % period;
    if (m < 0) m += period;
    return m < size ? m : period - 1 - m;
  }
  int m = i % size;
  return m < 0 ? m + size : m;
}

vec4 fetch_texel(TextureInfo tex, int x, int y) {
  x = wrap_coord(x, int(tex.width), (tex.flags & kTextureClampU) != 0u, (tex.flags & kTextureMirrorU) != 0u);
  y = wrap_coord(y, int(tex.height), (tex.flags & kTextureClampV) != 0u, (tex.flags & kTextureMirrorV) != 0u);
  vec4 c = unpackUnorm4x8(b_texels[tex.texelOffset + uint(y) * tex.width + uint(x)]);
  if ((tex.flags & kTextureSrgb) != 0u) c.rgb = vec3(srgb_to_linear(c.r), srgb_to_linear(c.g), srgb_to_linear(c.b));
  return c;
}

// uvSets: TEXCOORD_0 in xy, TEXCOORD_1 in zw (as the UV buffer stores them).
vec4 sample_texture(uint index, vec4 uvSets) {
  const TextureInfo tex = b_textures[index];
  const vec3 uv1 = vec3((tex.flags & kTextureUv1) != 0u ? uvSets.zw : uvSets.xy, 1.0);
  vec2 uv = vec2(dot(tex.uvTransformU, uv1), dot(tex.uvTransformV, uv1));
  // Guard against NaN/huge UVs: they would index nowhere sensible.
  uv = clamp(uv, vec2(-1.0e6), vec2(1.0e6));
  if (any(isnan(uv))) uv = vec2(0.0);
  const vec2 p = uv * vec2(tex.width, tex.height);
  if ((tex.flags & kTextureNearest) != 0u) return fetch_texel(tex, int(floor(p.x)), int(floor(p.y)));
  const vec2 q = p - 0.5;
  const ivec2 i = ivec2(floor(q));
  const vec2 f = q - vec2(i);
  const vec4 a = mix(fetch_texel(tex, i.x, i.y), fetch_texel(tex, i.x + 1, i.y), f.x);
  const vec4 b = mix(fetch_texel(tex, i.x, i.y + 1), fetch_texel(tex, i.x + 1, i.y + 1), f.x);
  return mix(a, b, f.y);
}

#endif
