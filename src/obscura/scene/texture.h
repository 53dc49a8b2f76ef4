// Image textures: decoded texels plus how to look them up.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "obscura/math/vector.h"

namespace obscura {

// What happens outside [0, 1] (glTF sampler wrap modes).
enum class TextureWrap { kRepeat, kMirroredRepeat, kClampToEdge };
// How texels are reconstructed: the nearest texel, bilinear, or trilinear over a MIP chain.
enum class TextureFilter { kNearest, kBilinear, kTrilinear };
// How stored values relate to linear light. Colour textures (base colour, emission) are
// sRGB-encoded; data textures (normals, metallic-roughness, occlusion) are linear.
enum class TextureEncoding { kSrgb, kLinear };

struct Texture {
  std::string name;
  std::string source;  // the file (or "file.glb#image3") the texels came from, for messages
  int width = 0, height = 0, channels = 0;  // channels 1..4
  // Exactly one of these holds width × height × channels values, row 0 at the top: 8-bit files
  // stay 8-bit (a quarter of the memory), float files (EXR, HDR) stay float.
  std::vector<uint8_t> texels_8bit;
  std::vector<float> texels_float;
  TextureEncoding encoding = TextureEncoding::kSrgb;
  TextureWrap wrap_u = TextureWrap::kRepeat, wrap_v = TextureWrap::kRepeat;
  TextureFilter filter = TextureFilter::kTrilinear;

  // Value of channel c at texel (x, y) in [0, 1] (8-bit) or as stored (float), still encoded.
  float texel(int x, int y, int c) const {
    size_t i = (size_t(y) * width + x) * channels + c;
    return texels_8bit.empty() ? texels_float[i] : texels_8bit[i] * (1.f / 255.f);
  }
  size_t memory_bytes() const {
    return texels_8bit.capacity() + texels_float.capacity() * sizeof(float) + name.capacity() +
           source.capacity();
  }
};

// The texture's value at `uv` (glTF convention: (0, 0) is the image's top-left corner, texel
// centres at half-integers × texel size) as linear RGBA: sRGB textures are decoded, missing
// channels filled as glTF does (grey → RGB, alpha 1). Wrap modes apply per axis; kNearest picks
// one texel, kBilinear and kTrilinear blend the four nearest (no MIP levels are built here).
Vector4f sample_texture(const Texture& texture, Point2f uv);
// The texel index along an axis of `size` texels for integer coordinate i, per the wrap mode.
int wrap_texel_index(int i, int size, TextureWrap wrap);

// An affine map of texture coordinates, applied before the lookup: glTF's KHR_texture_transform,
// uv' = T · R · S · uv with T the offset, S the scale and R = [cos r, sin r; −sin r, cos r] (the
// extension's rotation, counter-clockwise in UV space with v pointing down).
struct UvTransform {
  float m00 = 1, m01 = 0, m02 = 0;
  float m10 = 0, m11 = 1, m12 = 0;

  static UvTransform offset_rotation_scale(Point2f offset, float rotation, Point2f scale);
  bool is_identity() const {
    return m00 == 1 && m01 == 0 && m02 == 0 && m10 == 0 && m11 == 1 && m12 == 0;
  }
  Point2f operator()(Point2f uv) const {
    return {m00 * uv.x + m01 * uv.y + m02, m10 * uv.x + m11 * uv.y + m12};
  }
};

// A material's use of a texture: which one, which UV set, and how the UVs are transformed.
struct TextureRef {
  int32_t texture = -1;  // index into Scene::textures; −1 = none
  uint32_t uv_set = 0;   // TEXCOORD_n: which of the mesh's sets (Mesh::uv_set)
  UvTransform transform = {};
  bool valid() const { return texture >= 0; }
};

}  // namespace obscura
