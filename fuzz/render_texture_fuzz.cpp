// libFuzzer target that renders with an image its input encodes: the bytes are an image (the
// `image` target's formats, chosen from the leading bytes), decoded as a texture is, then used at
// once as a sphere's base colour and emission (sRGB), a floor's metallic-roughness texture
// (linear) and the environment map (linear), and a tiny frame is rendered by both renderers
// with its ground truth (tiny_render.h). Decoding keeps the `image` target's limit of 64 Ki
// pixels. Seeds: small images of each format and `regress-nan-texels.pfm` (NaN and infinite
// texels, which reached the renderers as a metallic-roughness texture before issue 32: now
// replaced where images are read). An obscura::Error is the expected outcome for bad input;
// anything else escaping, a crash, a sanitizer report, a non-finite pixel, a leak or > 2 GB is a
// finding.
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <variant>

#include "empty_folder.h"
#include "obscura/io/image_limits.h"
#include "obscura/io/json_scene.h"
#include "obscura/io/texture_loader.h"
#include "obscura/math/error.h"
#include "tiny_render.h"

namespace {

std::string format_of(const uint8_t* data, size_t size) {
  auto starts = [&](const char* magic, size_t n) {
    return size >= n && std::memcmp(data, magic, n) == 0;
  };
  if (starts("\x89PNG", 4)) return "png";
  if (starts("\x76\x2f\x31\x01", 4)) return "exr";
  if (starts("#?", 2)) return "hdr";
  if (starts("PF", 2) || starts("Pf", 2)) return "pfm";
  if (starts("\xff\xd8", 2)) return "jpg";
  if (starts("II*", 3) || starts("MM\0*", 4)) return "tif";
  return "tga";
}

// A sphere (material 0, "ball") over a floor (material 1, "floor"), a point light, no textures.
obscura::Scene untextured_scene() {
  obscura::Scene s = obscura::load_json_scene_text(
      R"({"name": "textured",
    "materials": {"ball": {"type": "metallic-roughness", "metallic": 0, "roughness": 0.5},
                  "floor": {"type": "metallic-roughness"}},
    "objects": [{"name": "ball", "shape": "sphere", "radius": 0.5, "segments": 12,
                 "material": "ball"},
                {"name": "floor", "shape": "rectangle", "size": [4, 4], "material": "floor",
                 "transform": {"translate": [0, -0.5, 0]}}],
    "cameras": [{"name": "c", "position": [0, 0.5, 3], "target": [0, 0, 0]}],
    "lights": [{"name": "l", "type": "point", "position": [1, 2, 2], "intensity": 20}]})",
      obscura::fuzz::make_empty_folder("obscura-render-texture-fuzz-empty") + "/scene.json");
  s.validate();
  return s;
}

void use_texture(obscura::Scene& scene, obscura::Texture colour) {
  obscura::Texture data = colour;
  data.encoding = obscura::TextureEncoding::kLinear;
  const auto colour_index = int32_t(scene.textures.size());
  scene.textures.push_back(std::move(colour));
  const auto data_index = int32_t(scene.textures.size());
  scene.textures.push_back(std::move(data));
  obscura::Material& ball = scene.materials.at(0);
  if (auto* mr = std::get_if<obscura::MetallicRoughnessMaterial>(&ball.model))
    mr->base_color_texture.texture = colour_index;
  ball.emission = obscura::Rgb(0.5f);
  ball.emission_texture.texture = colour_index;
  if (auto* mr = std::get_if<obscura::MetallicRoughnessMaterial>(&scene.materials.at(1).model))
    mr->metallic_roughness_texture.texture = data_index;
  obscura::Environment environment;
  environment.texture = data_index;
  scene.environment = environment;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const bool limited = (obscura::set_max_image_pixels(uint64_t(1) << 16), true);
  (void)limited;
  static const obscura::Scene untextured = untextured_scene();
  const std::string format = format_of(data, size);
  try {
    obscura::Scene scene = untextured;
    use_texture(scene,
                obscura::decode_texture(std::span<const uint8_t>(data, size), "fuzz." + format,
                                        format, obscura::TextureEncoding::kSrgb));
    scene.validate();
    obscura::fuzz::render_tiny(scene, scene.camera);
  } catch (const obscura::Error&) {
    // a clear error for bad input: the expected outcome
  }
  return 0;
}
