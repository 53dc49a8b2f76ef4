// The rasterizer's texture lookup (shading/material_point.h's TextureLookup): a material's
// textures read at one fragment, from their mipmapped raster form with the fragment's
// screen-space derivatives, so that a texture seen from afar is averaged rather than aliased.
#pragma once

#include <cstdint>
#include <vector>

#include "obscura/color/rgb.h"
#include "obscura/raster/texture.h"
#include "obscura/raster/varyings.h"
#include "obscura/scene/texture.h"

namespace obscura::raster {

// Texture coordinates and their screen-space derivatives at a fragment.
struct TextureCoordinates {
  float u = 0, v = 0, du_dx = 0, dv_dx = 0, du_dy = 0, dv_dy = 0;
};
// Both texture coordinate sets a fragment has (TEXCOORD_0 and TEXCOORD_1).
struct FragmentUvs {
  TextureCoordinates set[2];
};

// The scene's textures in raster form, by Scene::textures index (null where unused or empty):
// `color` the RGB pyramids, `alpha` the A channel as grey for the textures whose alpha a material
// reads (coverage, KHR_materials_specular's strength, KHR_materials_sheen's roughness; null where
// the image has none, which reads as 1 like an opaque texel).
struct TextureTable {
  std::vector<const Texture*> color, alpha;
};

OBSCURA_RASTER_INLINE Rgb sample_or_one(const Texture* t, const UvTransform& m,
                                        TextureFilter filter, const TextureCoordinates& c) {
  if (!t) return Rgb(1.f);
  // The derivatives go through the map's linear part, so mip selection sees the scaled texture.
  return t->sample(filter, m.m00 * c.u + m.m01 * c.v + m.m02, m.m10 * c.u + m.m11 * c.v + m.m12,
                   m.m00 * c.du_dx + m.m01 * c.dv_dx, m.m10 * c.du_dx + m.m11 * c.dv_dx,
                   m.m00 * c.du_dy + m.m01 * c.dv_dy, m.m10 * c.du_dy + m.m11 * c.dv_dy);
}

// The raster texture of `texture` in one of the table's columns; null where there is none.
OBSCURA_RASTER_INLINE const Texture* raster_texture(const std::vector<const Texture*>& column,
                                                    const TextureRef& texture) {
  return texture.valid() && size_t(texture.texture) < column.size()
             ? column[size_t(texture.texture)]
             : nullptr;
}

// The fragment's coordinates in a reference's UV set (sets past 1 are not kept: the loader warns).
OBSCURA_RASTER_INLINE const TextureCoordinates& coordinates_of(const FragmentUvs& uvs,
                                                               const TextureRef& texture) {
  return uvs.set[texture.uv_set == 1 ? 1 : 0];
}

class FragmentTextures {
 public:
  // `table` (null: no textures) and `uvs` must outlive the lookup.
  OBSCURA_RASTER_INLINE FragmentTextures(const TextureTable* table, TextureFilter filter,
                                         const FragmentUvs& uvs)
      : table_(table), filter_(filter), uvs_(uvs) {}

  // Whether the reference names a texture the rasterizer has (a valid reference to an empty
  // image has none).
  OBSCURA_RASTER_INLINE bool has(const TextureRef& texture) const {
    return table_ && raster_texture(table_->color, texture);
  }
  // RGB, or A, of the referenced texture at the fragment; 1 where there is no texture.
  OBSCURA_RASTER_INLINE Rgb color(const TextureRef& texture) const {
    if (!table_) return Rgb(1.f);
    return sample_or_one(raster_texture(table_->color, texture), texture.transform, filter_,
                         coordinates_of(uvs_, texture));
  }
  OBSCURA_RASTER_INLINE float alpha(const TextureRef& texture) const {
    if (!table_) return 1;
    return sample_or_one(raster_texture(table_->alpha, texture), texture.transform, filter_,
                         coordinates_of(uvs_, texture))
        .r;
  }

 private:
  const TextureTable* table_;
  TextureFilter filter_;
  const FragmentUvs& uvs_;
};

}  // namespace obscura::raster
