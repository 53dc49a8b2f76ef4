#include "obscura/raster/surface_material.h"

#include "obscura/shading/material_point.h"

namespace obscura::raster {

SurfaceMaterial compile_material(const Material& material, const TextureTable* textures) {
  SurfaceMaterial s;
  static_cast<shading::SurfaceMaterial&>(s) = shading::compile_surface_material(material);
  s.textures = textures;
  return s;
}

SurfacePoint surface_point_untextured(const SurfaceMaterial& m, Rgb vertex_color) {
  return shading::surface_point_with(m, vertex_color, shading::NoTextures{});
}

SurfacePoint surface_point(const SurfaceMaterial& m, const FragmentUvs& uvs, Rgb vertex_color) {
  return shading::surface_point_with(m, vertex_color, FragmentTextures(m.textures, m.filter, uvs));
}

}  // namespace obscura::raster
