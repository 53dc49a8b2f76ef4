// A scene material's parameters at one surface point: its factors multiplied by its textures
// there, the one reading of Material both renderers shade with.
//
// How a texture is read is the caller's: the tracer samples the full-resolution texture at the
// hit (trace/hit_textures.h), the rasterizer its mipmapped textures with the fragment's screen
// derivatives (raster/fragment_textures.h). Each passes a TextureLookup, and the functions here
// say which channel of which texture multiplies which factor — pbrt-v4 parameterises its
// materials by a texture evaluator the same way. Keeping that mapping in one place is the point:
// two copies of it drifted apart before (the rasterizer ignored KHR_materials_specular's
// textures).
//
// A base colour is formed as factor × (texture × vertex colour), in both renderers alike. (The
// grouping matters to the last bit: the rasterizer's vertex colour is interpolated, 1 only to
// within a rounding where the mesh has none, and this is the grouping it has always used.)
#pragma once

#include <concepts>

#include "obscura/color/rgb.h"
#include "obscura/math/vector.h"
#include "obscura/scene/material.h"
#include "obscura/scene/texture.h"
#include "obscura/shading/inline.h"
#include "obscura/shading/normal_map.h"

namespace obscura::shading {

// Reads a material's textures at one point: `color` the RGB of a texture, `alpha` its A channel,
// each 1 where the reference names no texture (so a factor without a texture stays as it is).
template <class L>
concept TextureLookup = requires(const L& lookup, const TextureRef& texture) {
  { lookup.color(texture) } -> std::same_as<Rgb>;
  { lookup.alpha(texture) } -> std::same_as<float>;
};

// The lookup of a point without textures: every factor as it is (the rasterizer's per-vertex
// shading).
struct NoTextures {
  OBSCURA_SHADING_INLINE Rgb color(const TextureRef&) const { return Rgb(1.f); }
  OBSCURA_SHADING_INLINE float alpha(const TextureRef&) const { return 1; }
};

// A colour factor times its texture's RGB (emission and its texture, for one).
template <TextureLookup L>
OBSCURA_SHADING_INLINE Rgb textured(Rgb factor, const TextureRef& texture, const L& lookup) {
  return factor * lookup.color(texture);
}

// A base colour (Lambert reflectance, Phong k_d, glTF base colour) at the point: the factor times
// its texture's RGB times the vertex colour.
template <TextureLookup L>
OBSCURA_SHADING_INLINE Rgb base_color_at(Rgb factor, const TextureRef& texture, Rgb vertex_color,
                                         const L& lookup) {
  return factor * (lookup.color(texture) * vertex_color);
}

// A tangent-space normal map's perturbation of the unit `normal` (tangent: xyz, w = handedness),
// read from `map` with glTF's normalTexture.scale; `normal` itself where there is no map.
template <TextureLookup L>
OBSCURA_SHADING_INLINE Vector3f normal_mapped(const TextureRef& map, float scale, Vector3f normal,
                                              Vector4f tangent, const L& lookup) {
  if (!map.valid()) return normal;
  const Rgb texel = lookup.color(map);
  return perturbed_normal(normal, tangent, {texel.r, texel.g, texel.b}, scale);
}

// glTF metallic-roughness and its extensions at a point. Each field is its factor in
// MetallicRoughnessMaterial times the texture channel glTF assigns it; nothing is clamped or
// converted (GGX widths, F0), which each renderer's reflection model does its own way.
struct MetallicRoughnessPoint {
  Rgb base_color;                 // × base colour texture RGB × vertex colour
  float metallic = 1;             // × metallic-roughness texture B
  float roughness = 1;            // × metallic-roughness texture G
  float specular = 1;             // KHR_materials_specular: × specular texture A
  Rgb specular_color{1.f};        // × specular colour texture RGB
  float ior = 1.5f;               // KHR_materials_ior (untextured)
  float transmission = 0;         // KHR_materials_transmission: × its texture R
  float clearcoat = 0;            // KHR_materials_clearcoat: × its texture R (0 without a coat)
  float clearcoat_roughness = 0;  // × its roughness texture G
  Rgb sheen_color;            // KHR_materials_sheen: × its colour texture RGB (black: no sheen)
  float sheen_roughness = 0;  // × its roughness texture A
};

template <TextureLookup L>
MetallicRoughnessPoint metallic_roughness_at(const MetallicRoughnessMaterial& m, Rgb vertex_color,
                                             const L& lookup) {
  MetallicRoughnessPoint p;
  p.base_color = base_color_at(m.base_color, m.base_color_texture, vertex_color, lookup);
  p.metallic = m.metallic;
  p.roughness = m.roughness;
  if (m.metallic_roughness_texture.valid()) {
    const Rgb texel = lookup.color(m.metallic_roughness_texture);
    p.roughness *= texel.g;
    p.metallic *= texel.b;
  }
  p.specular = m.specular * lookup.alpha(m.specular_texture);
  p.specular_color = textured(m.specular_color, m.specular_color_texture, lookup);
  p.ior = m.ior;
  // Textures of absent layers are not read: their factors are zero whatever the texture says.
  if (m.transmission > 0) p.transmission = m.transmission * lookup.color(m.transmission_texture).r;
  if (m.has_clearcoat()) {
    p.clearcoat = m.clearcoat * lookup.color(m.clearcoat_texture).r;
    p.clearcoat_roughness = m.clearcoat_roughness * lookup.color(m.clearcoat_roughness_texture).g;
  }
  if (m.has_sheen()) {
    p.sheen_color = textured(m.sheen_color, m.sheen_color_texture, lookup);
    p.sheen_roughness = m.sheen_roughness * lookup.alpha(m.sheen_roughness_texture);
  }
  return p;
}

}  // namespace obscura::shading
