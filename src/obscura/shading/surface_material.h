// A scene material compiled once for shading with the rasterizer's reflection formulas
// (surface_response.h), and its reading at a surface point through a renderer's texture lookup
// (material_point.h's TextureLookup): the rasterizer reads its mipmaps, REYES the texture at a
// grid vertex. Moved down from raster/ so that both read a material the one way.
#pragma once

#include <cstdint>

#include "obscura/color/rgb.h"
#include "obscura/scene/material.h"
#include "obscura/scene/texture.h"
#include "obscura/shading/material_point.h"
#include "obscura/shading/surface_response.h"

namespace obscura::shading {

struct SurfaceMaterial {
  SurfaceModel model = SurfaceModel::kLambert;
  Rgb base{0.8f, 0.8f, 0.8f};  // Lambert reflectance, Phong k_d, an unlit glTF base colour
  Rgb specular;                // Phong k_s
  float shininess = 0;         // Phong exponent
  float alpha = 1;             // conductor, dielectric: GGX width
  float ior = 1.5f;            // dielectric
  Rgb eta, k;                  // conductor
  Rgb multiple_scattering;     // conductor: the colour of its multiple-scattering lobe
  Rgb transmittance{1.f};      // dielectric
  // kMetallicRoughness, kLayeredMetallicRoughness: the scene's factors and textures, read at
  // each point as the tracer reads them (shading/material_point.h). Its clear coat and sheen
  // are dropped where the model is not layered (under transmission, as in the tracer).
  MetallicRoughnessMaterial metallic_roughness;
  Rgb emission;
  // The textures below are references into the scene's textures, read through the renderer's
  // lookup. `base_texture` multiplies `base` (the glTF base colour texture for metallic-roughness:
  // Gouraud shading modulates with it); occlusion (R) darkens the ambient term; the normal map is
  // tangent-space (shading/normal_map.h) with glTF's normalTexture.scale.
  TextureRef base_texture, occlusion_texture, emission_texture, normal_texture;
  float normal_scale = 1;
  bool double_sided = true;
  // glTF alpha coverage, for metallic-roughness materials as in the tracer: the base colour
  // factor's alpha × the A of `alpha_texture` (the base colour texture, read through the table's
  // alpha column) × the vertex colour's alpha.
  AlphaMode alpha_mode = AlphaMode::kOpaque;
  float base_alpha = 1, alpha_cutoff = 0.5f;
  TextureRef alpha_texture;

  // KHR_materials_transmission: drawn after the opaque surfaces, over what they left behind.
  bool transmits() const {
    return model == SurfaceModel::kMetallicRoughness && metallic_roughness.transmission > 0;
  }
};

SurfaceMaterial compile_surface_material(const Material& material);

// The glTF models' parameters at a point, as the reflection formulas take them.
void set_metallic_roughness(SurfacePoint& p, const MetallicRoughnessPoint& mr, bool layered);

// The material at a point whose textures `lookup` reads, with the vertex colour multiplied into
// its base colour (see SurfacePoint).
template <TextureLookup L>
SurfacePoint surface_point_with(const SurfaceMaterial& m, Rgb vertex_color, const L& lookup) {
  SurfacePoint p{};
  p.model = m.model;
  p.specular = m.specular;
  p.shininess = m.shininess;
  p.alpha = m.alpha;
  p.ior = m.ior;
  p.eta = m.eta, p.k = m.k, p.transmittance = m.transmittance;
  p.multiple_scattering = m.multiple_scattering;
  p.occlusion = lookup.color(m.occlusion_texture).r;
  switch (m.model) {
    case SurfaceModel::kMetallicRoughness:
    case SurfaceModel::kLayeredMetallicRoughness:
      set_metallic_roughness(p, metallic_roughness_at(m.metallic_roughness, vertex_color, lookup),
                             m.model == SurfaceModel::kLayeredMetallicRoughness);
      break;
    case SurfaceModel::kPhong:
    case SurfaceModel::kBlinnPhong:
      p.base = base_color_at(m.base, m.base_texture, vertex_color, lookup);
      conserve_energy(p.base, p.specular);
      p.lobe_normalization = m.model == SurfaceModel::kPhong
                                 ? phong_lobe_normalization(p.shininess)
                                 : blinn_phong_lobe_normalization(p.shininess);
      break;
    default:
      p.base = base_color_at(m.base, m.base_texture, vertex_color, lookup);
      break;
  }
  return p;
}

}  // namespace obscura::shading
