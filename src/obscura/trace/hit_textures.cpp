#include "obscura/trace/hit_textures.h"

namespace obscura {

Rgb HitTextures::color(const TextureRef& texture) const {
  if (!texture.valid() || !textures_) return Rgb(1.f);
  const Vector4f texel = sample_texture((*textures_)[size_t(texture.texture)],
                                        texture.transform(texture_uv(hit_, texture.uv_set)));
  return {texel.x, texel.y, texel.z};
}

float HitTextures::alpha(const TextureRef& texture) const {
  if (!texture.valid() || !textures_) return 1;
  return sample_texture((*textures_)[size_t(texture.texture)],
                        texture.transform(texture_uv(hit_, texture.uv_set)))
      .w;
}

}  // namespace obscura
