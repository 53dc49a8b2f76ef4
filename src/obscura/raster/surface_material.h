// A scene material as the rasterizer shades it: one flat struct for every model, evaluated per
// fragment (or per vertex for Gouraud). Its textures are read through the mipmapped raster
// textures (fragment_textures.h), and which texture multiplies which factor is decided where the
// tracer's is, in shading/material_point.h.
//
// The mapping (docs/rasterizer.md has the reasoning):
//   diffuse             Lambert, reflectance × texture
//   phong               energy-conserving Phong / Blinn-Phong, the tracer's PhongBsdf
//   metallic-roughness  glTF's model as the tracer evaluates it (GGX, Smith, Schlick), with
//                       KHR_materials_specular and _ior; occlusion (R) darkens the ambient term
//   conductor           GGX with the exact conductor Fresnel; a mirror's lobe is widened to
//                       α = kMinHighlightAlpha so lights show as small highlights
//   dielectric          its GGX reflection lobe with the dielectric Fresnel (widened likewise);
//                       refraction shows only as ambient light passing through
//   emissive            reflects nothing
//   unlit (glTF)        KHR_materials_unlit: base colour × texture × vertex colour, as it is
//   transmission (glTF) KHR_materials_transmission as real-time viewers draw it: a thin glass
//                       wall (no refraction) that shows what was drawn behind it, tinted by the
//                       base colour (scene_program.h, shade_transmission)
//   clearcoat, sheen    KHR_materials_clearcoat and _sheen: the tracer's layering
//   (glTF)              (trace/layered_metallic_roughness_bsdf.h) for every light; the
//                       environment reaches the layers through their albedos at the shading
//                       normal's n·v, the coat reflecting it at its own roughness
// Every material adds its emission (× emission texture) on its front face.
#pragma once

#include <cstdint>

#include "obscura/color/rgb.h"
#include "obscura/raster/brdf.h"
#include "obscura/raster/fragment_textures.h"
#include "obscura/raster/texture.h"
#include "obscura/raster/varyings.h"
#include "obscura/scene/material.h"
#include "obscura/shading/charlie_sheen.h"
#include "obscura/shading/ggx_energy.h"
#include "obscura/shading/surface_material.h"
#include "obscura/shading/surface_response.h"

namespace obscura::raster {

// The surface model, the reflection formulas and the environment response are shared with
// REYES (shading/surface_response.h); the material's reading at a point too
// (shading/surface_material.h). The rasterizer adds its mipmapped texture table.
using shading::ambient_reflectance;
using shading::environment_response;
using shading::EnvironmentResponse;
using shading::kMinHighlightAlpha;
using shading::layered_cosine;
using shading::reflected_cosine;
using shading::SurfaceModel;
using shading::SurfacePoint;

struct SurfaceMaterial : shading::SurfaceMaterial {
  // The raster form of the scene's textures that the material's TextureRefs index (null: none).
  const TextureTable* textures = nullptr;
  TextureFilter filter = TextureFilter::kTrilinear;
};

// `textures` is the raster form of the scene's textures (null: draw without textures); it must
// outlive the material.
SurfaceMaterial compile_material(const Material& material, const TextureTable* textures);

// The coverage α at a point, for the cut-out test (see SurfaceMaterial::alpha_mode). Read from
// the full-resolution texture, bilinearly, as the tracer reads it: a cut-out is a threshold, and
// a threshold of MIP-averaged alpha moves the cut-out's edge (thin parts vanish or swell with
// distance) where the threshold of the texture itself is what the file describes. MSAA then
// antialiases the edge by testing each sample.
OBSCURA_RASTER_INLINE float coverage_alpha(const SurfaceMaterial& m, const FragmentUvs& uvs,
                                           float vertex_alpha) {
  const TextureFilter full_resolution =
      m.filter == TextureFilter::kNearest ? m.filter : TextureFilter::kBilinear;
  return m.base_alpha * vertex_alpha *
         FragmentTextures(m.textures, full_resolution, uvs).alpha(m.alpha_texture);
}

SurfacePoint surface_point(const SurfaceMaterial& m, const FragmentUvs& uvs, Rgb vertex_color);
// The same without textures (Gouraud shading at vertices).
SurfacePoint surface_point_untextured(const SurfaceMaterial& m, Rgb vertex_color);

}  // namespace obscura::raster
