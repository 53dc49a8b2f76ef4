// COLOR_0 with four components: its alpha reaches Mesh::color_alphas (it multiplies the
// material's coverage in both renderers); opaque or three-component colours add nothing.
#include "gltf_hostile.h"

namespace obscura::test {
namespace {

class GltfVertexAlpha : public GltfHostile {
 protected:
  // The fixture's triangle with COLOR_0 given as float RGBA (alpha `a0, a1, a2`) or RGB.
  Scene load_with_colors(std::vector<float> alphas, bool rgba = true) {
    std::vector<uint8_t> bytes = buffer_bytes();
    std::vector<float> colors;
    for (float a : alphas) {
      colors.insert(colors.end(), {0.25f, 0.5f, 1.f});
      if (rgba) colors.push_back(a);
    }
    std::memcpy(bytes.data() + 48, colors.data(), colors.size() * sizeof(float));
    json doc = triangle();
    set_buffer(doc, bytes);
    doc["bufferViews"].push_back(
        {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", colors.size() * sizeof(float)}});
    int colors_accessor = add_accessor(doc, {{"bufferView", 3},
                                             {"componentType", 5126},
                                             {"count", 3},
                                             {"type", rgba ? "VEC4" : "VEC3"}});
    doc["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = colors_accessor;
    return load_gltf(write("colors.gltf", doc));
  }
};

TEST_F(GltfVertexAlpha, RgbaColoursKeepTheirAlpha) {
  Scene scene = load_with_colors({1.f, 0.5f, 0.f});
  ASSERT_EQ(scene.meshes.size(), 1u);
  const Mesh& mesh = scene.meshes[0];
  ASSERT_EQ(mesh.colors.size(), 3u);
  EXPECT_EQ(mesh.colors[1].g, 0.5f);
  ASSERT_EQ(mesh.color_alphas.size(), 3u);
  EXPECT_EQ(mesh.color_alphas[0], 1.f);
  EXPECT_EQ(mesh.color_alphas[1], 0.5f);
  EXPECT_EQ(mesh.color_alphas[2], 0.f);
}

TEST_F(GltfVertexAlpha, OpaqueOrRgbColoursAddNoAlpha) {
  EXPECT_TRUE(load_with_colors({1.f, 1.f, 1.f}).meshes[0].color_alphas.empty());
  Scene rgb = load_with_colors({0, 0, 0}, false);
  EXPECT_EQ(rgb.meshes[0].colors.size(), 3u);
  EXPECT_TRUE(rgb.meshes[0].color_alphas.empty());
}

}  // namespace
}  // namespace obscura::test
