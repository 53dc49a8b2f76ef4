// KHR_materials_clearcoat and KHR_materials_sheen read from glTF files built in the test: every
// factor and texture slot (with its channel's UV set and encoding), the defaults, the range
// checks naming the field, and no "not supported" warning for either.
#include <gtest/gtest.h>

#include <cstring>
#include <variant>

#include "gltf_hostile.h"
#include "obscura/io/gltf_loader.h"
#include "obscura/math/error.h"
#include "png_bytes.h"

namespace obscura {
namespace {

using nlohmann::json;

// A 1 m square facing +Z with UVs, drawn with materials[0], and two 1×1 PNG images as textures
// 0 and 1; callers add the material.
json textured_quad() {
  std::vector<uint8_t> bytes(48 + 32 + 12);
  const float positions[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  const float uvs[8] = {0, 1, 1, 1, 1, 0, 0, 0};
  const uint16_t indices[6] = {0, 1, 2, 0, 2, 3};
  std::memcpy(bytes.data(), positions, sizeof positions);
  std::memcpy(bytes.data() + 48, uvs, sizeof uvs);
  std::memcpy(bytes.data() + 80, indices, sizeof indices);
  auto png = [](uint8_t r, uint8_t g, uint8_t b, uint8_t a) {
    return "data:image/png;base64," + test::base64(test::rgba8_png(1, 1, {r, g, b, a}));
  };
  return {
      {"asset", {{"version", "2.0"}}},
      {"buffers",
       {{{"byteLength", bytes.size()},
         {"uri", "data:application/octet-stream;base64," + test::base64(bytes)}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
        {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 32}},
        {{"buffer", 0}, {"byteOffset", 80}, {"byteLength", 12}}}},
      {"accessors",
       {{{"bufferView", 0},
         {"componentType", 5126},
         {"count", 4},
         {"type", "VEC3"},
         {"min", {0, 0, 0}},
         {"max", {1, 1, 0}}},
        {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}},
        {{"bufferView", 2}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}}},
      {"images", {{{"uri", png(255, 128, 0, 64)}}, {{"uri", png(10, 20, 30, 200)}}}},
      {"textures", {{{"source", 0}}, {{"source", 1}}}},
      {"meshes",
       {{{"primitives",
          {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}, {"TEXCOORD_1", 1}}},
            {"indices", 2},
            {"material", 0}}}}}}},
      {"nodes", {{{"mesh", 0}}}},
      {"scenes", {{{"nodes", {0}}}}},
      {"scene", 0},
  };
}

Scene load(const json& document) {
  return test::load_gltf_json(document);
}

const MetallicRoughnessMaterial& mr(const Scene& scene) {
  return std::get<MetallicRoughnessMaterial>(scene.materials.at(0).model);
}

void expect_no_extension_warning(const Scene& scene) {
  for (const std::string& w : scene.warnings) {
    EXPECT_EQ(w.find("clearcoat"), std::string::npos) << w;
    EXPECT_EQ(w.find("sheen"), std::string::npos) << w;
  }
}

TEST(GltfClearcoat, ReadsFactorsAndTextures) {
  json doc = textured_quad();
  doc["extensionsUsed"] = {"KHR_materials_clearcoat"};
  doc["extensionsRequired"] = {"KHR_materials_clearcoat"};
  doc["materials"] = {{{"extensions",
                        {{"KHR_materials_clearcoat",
                          {{"clearcoatFactor", 0.8},
                           {"clearcoatTexture", {{"index", 0}}},
                           {"clearcoatRoughnessFactor", 0.25},
                           {"clearcoatRoughnessTexture", {{"index", 1}, {"texCoord", 1}}},
                           {"clearcoatNormalTexture", {{"index", 1}, {"scale", 0.5}}}}}}}}};
  Scene scene = load(doc);
  const MetallicRoughnessMaterial& m = mr(scene);
  EXPECT_FLOAT_EQ(m.clearcoat, 0.8f);
  EXPECT_FLOAT_EQ(m.clearcoat_roughness, 0.25f);
  EXPECT_TRUE(m.has_clearcoat());
  EXPECT_FALSE(m.purely_diffuse());
  ASSERT_TRUE(m.clearcoat_texture.valid());
  ASSERT_TRUE(m.clearcoat_roughness_texture.valid());
  ASSERT_TRUE(m.clearcoat_normal_texture.valid());
  EXPECT_EQ(m.clearcoat_roughness_texture.uv_set, 1u);
  EXPECT_FLOAT_EQ(m.clearcoat_normal_scale, 0.5f);
  // Coat data is linear: R of image 0 reads 255 → 1, G of image 1 reads 20/255 unconverted.
  const Texture& roughness = scene.textures.at(m.clearcoat_roughness_texture.texture);
  EXPECT_NEAR(sample_texture(roughness, {0.5f, 0.5f}).y, 20 / 255.f, 1e-3f);
  // The coat's normal map is the one the mesh's tangents are made for.
  EXPECT_EQ(&tangent_space_texture(scene.materials[0]), &m.clearcoat_normal_texture);
  expect_no_extension_warning(scene);
}

TEST(GltfClearcoat, DefaultsDisableTheCoat) {
  json doc = textured_quad();
  doc["materials"] = {{{"extensions", {{"KHR_materials_clearcoat", json::object()}}}}};
  Scene scene = load(doc);
  EXPECT_EQ(mr(scene).clearcoat, 0.f);
  EXPECT_EQ(mr(scene).clearcoat_roughness, 0.f);
  EXPECT_FALSE(mr(scene).has_clearcoat());
  EXPECT_FALSE(mr(scene).clearcoat_normal_texture.valid());
}

TEST(GltfSheen, ReadsFactorsAndTextures) {
  json doc = textured_quad();
  doc["extensionsUsed"] = {"KHR_materials_sheen"};
  doc["materials"] = {{{"pbrMetallicRoughness", {{"metallicFactor", 0}}},
                       {"extensions",
                        {{"KHR_materials_sheen",
                          {{"sheenColorFactor", {0.9, 0.5, 0.25}},
                           {"sheenColorTexture", {{"index", 0}}},
                           {"sheenRoughnessFactor", 0.75},
                           {"sheenRoughnessTexture", {{"index", 1}}}}}}}}};
  Scene scene = load(doc);
  const MetallicRoughnessMaterial& m = mr(scene);
  EXPECT_FLOAT_EQ(m.sheen_color.g, 0.5f);
  EXPECT_FLOAT_EQ(m.sheen_roughness, 0.75f);
  EXPECT_TRUE(m.has_sheen());
  ASSERT_TRUE(m.sheen_color_texture.valid());
  ASSERT_TRUE(m.sheen_roughness_texture.valid());
  // The colour is sRGB-encoded (128 → 0.216), the roughness in the alpha channel (200/255).
  Vector4f color = sample_texture(scene.textures.at(m.sheen_color_texture.texture), {0.5f, 0.5f});
  EXPECT_NEAR(color.y, 0.2158f, 2e-3f);
  Vector4f rough =
      sample_texture(scene.textures.at(m.sheen_roughness_texture.texture), {0.5f, 0.5f});
  EXPECT_NEAR(rough.w, 200 / 255.f, 1e-3f);
  expect_no_extension_warning(scene);
}

TEST(GltfSheen, BlackSheenColourDisablesTheLayer) {
  json doc = textured_quad();
  doc["materials"] = {{{"extensions", {{"KHR_materials_sheen", {{"sheenRoughnessFactor", 1}}}}}}};
  EXPECT_FALSE(mr(load(doc)).has_sheen());
}

TEST(GltfClearcoatSheen, OutOfRangeValuesNameTheField) {
  struct Case {
    const char* extension;
    json value;
    const char* field;
  };
  for (const Case& c :
       {Case{"KHR_materials_clearcoat", {{"clearcoatFactor", 1.5}}, "clearcoatFactor"},
        Case{"KHR_materials_clearcoat", {{"clearcoatFactor", "1"}}, "clearcoatFactor"},
        Case{"KHR_materials_clearcoat",
             {{"clearcoatRoughnessFactor", -0.1}},
             "clearcoatRoughnessFactor"},
        Case{"KHR_materials_clearcoat", {{"clearcoatTexture", 0}}, "clearcoatTexture"},
        Case{"KHR_materials_clearcoat",
             {{"clearcoatNormalTexture", {{"index", 0}, {"scale", "big"}}}},
             "clearcoatNormalTexture.scale"},
        Case{"KHR_materials_sheen", {{"sheenColorFactor", {1, 2, 0}}}, "sheenColorFactor"},
        Case{"KHR_materials_sheen", {{"sheenColorFactor", {1, 1}}}, "sheenColorFactor"},
        Case{"KHR_materials_sheen", {{"sheenRoughnessFactor", 2}}, "sheenRoughnessFactor"},
        Case{"KHR_materials_sheen",
             {{"sheenRoughnessTexture", {{"index", 9}}}},
             "sheenRoughnessTexture"}}) {
    json doc = textured_quad();
    doc["materials"] = {{{"extensions", {{c.extension, c.value}}}}};
    test::expect_error_naming(
        load, doc, std::string("materials[0].extensions.") + c.extension + "." + c.field);
  }
}

}  // namespace
}  // namespace obscura
