// glTF material extensions read from files built in the test: KHR_materials_unlit (shown as its
// exact base colour by both renderers), KHR_materials_variants (selection by name), and the
// transmission/volume parameters with their range checks.
#include <gtest/gtest.h>

#include <cstring>
#include <variant>

#include "gltf_hostile.h"
#include "obscura/camera/frames.h"
#include "obscura/film/film.h"
#include "obscura/io/gltf_loader.h"
#include "obscura/math/error.h"
#include "obscura/raster/scene_rasterizer.h"
#include "obscura/scene/material_variants.h"
#include "obscura/trace/path_tracer.h"
#include "obscura/trace/render.h"
#include "obscura/trace/trace_material.h"
#include "obscura/trace/trace_scene.h"
#include "png_bytes.h"

namespace obscura {
namespace {

using nlohmann::json;

// A 4 m square in the z = 0 plane facing +Z, drawn with materials[0], as a glTF JSON document;
// callers add materials and extensions.
json quad_document() {
  std::vector<uint8_t> bytes(48 + 12);
  const float positions[12] = {-2, -2, 0, 2, -2, 0, 2, 2, 0, -2, 2, 0};
  const uint16_t indices[6] = {0, 1, 2, 0, 2, 3};
  std::memcpy(bytes.data(), positions, sizeof positions);
  std::memcpy(bytes.data() + 48, indices, sizeof indices);
  return {
      {"asset", {{"version", "2.0"}}},
      {"buffers",
       {{{"byteLength", bytes.size()},
         {"uri", "data:application/octet-stream;base64," + test::base64(bytes)}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
        {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 12}}}},
      {"accessors",
       {{{"bufferView", 0},
         {"componentType", 5126},
         {"count", 4},
         {"type", "VEC3"},
         {"min", {-2, -2, 0}},
         {"max", {2, 2, 0}}},
        {{"bufferView", 1}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}}},
      {"meshes",
       {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"material", 0}}}}}}},
      {"nodes", {{{"mesh", 0}}}},
      {"scenes", {{{"nodes", {0}}}}},
      {"scene", 0},
  };
}

Scene load(const json& document) {
  return test::load_gltf_json(document);
}

const MetallicRoughnessMaterial& mr(const Scene& scene, size_t i) {
  return std::get<MetallicRoughnessMaterial>(scene.materials.at(i).model);
}

json unlit_material(std::vector<double> color) {
  return {{"pbrMetallicRoughness", {{"baseColorFactor", color}}},
          {"emissiveFactor", {1, 1, 1}},  // unlit ignores it
          {"extensions", {{"KHR_materials_unlit", json::object()}}}};
}

TEST(GltfUnlit, ReadAsUnlitWithoutEmission) {
  json doc = quad_document();
  doc["materials"] = json::array({unlit_material({0.2, 0.4, 0.6, 1})});
  doc["extensionsUsed"] = {"KHR_materials_unlit"};
  doc["extensionsRequired"] = {"KHR_materials_unlit"};  // UnlitTest requires it
  Scene scene = load(doc);
  EXPECT_TRUE(mr(scene, 0).unlit);
  EXPECT_TRUE(scene.materials[0].emission.is_black());
  for (const std::string& w : scene.warnings) EXPECT_EQ(w.find("unlit"), std::string::npos) << w;
}

TEST(GltfUnlit, BothRenderersShowTheExactBaseColourWhateverTheLight) {
  json doc = quad_document();
  const Rgb color(0.2f, 0.4f, 0.6f);
  doc["materials"] = json::array({unlit_material({0.2, 0.4, 0.6, 1})});
  Scene scene = load(doc);
  // A bright environment and a point light: an unlit surface ignores both.
  scene.environment = Environment();
  scene.environment->color = Rgb(3.f);
  scene.lights.push_back({"lamp", PointLight{{0, 0, 2}, Rgb(50.f)}});
  scene.camera.world_from_camera = world_from_camera_look_at({0.3, 0.2, 3}, {0, 0, 0});
  scene.camera.projection = Perspective::from_horizontal_fov_degrees(30);
  scene.camera.film.width_px = scene.camera.film.height_px = 8;
  const float exposure = float(scene.camera.exposure_scale());

  TraceScene trace(scene, std::make_shared<EmbreeDevice>());
  Film traced(8, 8);
  render(trace, scene.camera, PathTracer(), {.samples_per_pixel = 16, .seed = 1}, traced);
  raster::SceneRasterizer rasterizer(scene, {});
  Film rasterized(8, 8);
  rasterizer.render(scene.camera, rasterized);
  for (const Film* film : {&traced, &rasterized})
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(film->pixel({4, 4})[c], color[c] * exposure, 1e-5f) << c;
}

json variants_document() {
  json doc = quad_document();
  doc["materials"] = {
      {{"name", "default red"}, {"pbrMetallicRoughness", {{"baseColorFactor", {1, 0, 0, 1}}}}},
      {{"name", "green"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0, 1, 0, 1}}}}},
      {{"name", "blue"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 1, 1}}}}}};
  doc["extensionsUsed"] = {"KHR_materials_variants"};
  doc["extensions"]["KHR_materials_variants"]["variants"] = {
      {{"name", "Leaf"}}, {{"name", "Sky"}}, {{"name", "Plain"}}};
  doc["meshes"][0]["primitives"][0]["extensions"]["KHR_materials_variants"]["mappings"] = {
      {{"material", 1}, {"variants", {0}}}, {{"material", 2}, {"variants", {1}}}};
  return doc;
}

TEST(GltfVariants, SelectionChangesTheMaterialByName) {
  Scene scene = load(variants_document());
  EXPECT_EQ(scene.material_variants, (std::vector<std::string>{"Leaf", "Sky", "Plain"}));
  ASSERT_EQ(scene.instances.size(), 1u);
  EXPECT_EQ(scene.material_of(scene.instances[0]), 0u);  // the file's default
  select_material_variant(scene, "Sky");
  EXPECT_EQ(scene.materials[scene.material_of(scene.instances[0])].name, "blue");
  select_material_variant(scene, "Leaf");
  EXPECT_EQ(scene.materials[scene.material_of(scene.instances[0])].name, "green");
  // A variant this primitive does not map keeps what it has.
  select_material_variant(scene, "Plain");
  EXPECT_EQ(scene.materials[scene.material_of(scene.instances[0])].name, "green");
}

TEST(GltfVariants, APosedMeshTakesItsPrimitivesVariants) {
  // A morph target makes the node's mesh a posed copy of its own; the variants still apply.
  json doc = variants_document();
  doc["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", 0}}};
  doc["meshes"][0]["weights"] = {0.5};
  Scene scene = load(doc);
  ASSERT_EQ(scene.instances.size(), 1u);
  EXPECT_NE(scene.instances[0].mesh, 0u);  // the posed copy, not the file's primitive
  select_material_variant(scene, "Sky");
  EXPECT_EQ(scene.materials[scene.material_of(scene.instances[0])].name, "blue");
}

TEST(GltfVariants, UnknownNameIsAnErrorListingTheNames) {
  Scene scene = load(variants_document());
  try {
    select_material_variant(scene, "Sea");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'Sea'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'Leaf', 'Sky', 'Plain'"), std::string::npos) << e.what();
  }
  json without = quad_document();
  without["materials"] = json::array({json::object()});
  Scene plain = load(without);
  EXPECT_THROW(select_material_variant(plain, "Leaf"), Error);
}

TEST(GltfVariants, BadMappingsNameTheField) {
  json doc = variants_document();
  doc["meshes"][0]["primitives"][0]["extensions"]["KHR_materials_variants"]["mappings"][1]
     ["variants"] = {7};
  try {
    load(doc);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("mappings[1].variants[0]"), std::string::npos) << e.what();
  }
}

TEST(GltfSpecular, TexturesScaleStrengthAndColourInTheTracer) {
  // One texel: sRGB colour (255, 188, 0) and alpha 0.5 (128/255); KHR_materials_specular reads
  // strength from A and colour from RGB.
  json doc = quad_document();
  doc["images"] = {{{"uri", "data:image/png;base64," +
                                test::base64(test::rgba8_png(1, 1, {255, 188, 0, 128}))}}};
  doc["textures"] = {{{"source", 0}}};
  doc["extensionsUsed"] = {"KHR_materials_specular"};
  doc["materials"] = {
      {{"pbrMetallicRoughness", {{"metallicFactor", 0}, {"roughnessFactor", 1}}},
       {"extensions",
        {{"KHR_materials_specular",
          {{"specularTexture", {{"index", 0}}}, {"specularColorTexture", {{"index", 0}}}}}}}}};
  Scene scene = load(doc);
  const MetallicRoughnessMaterial& m = mr(scene, 0);
  ASSERT_TRUE(m.specular_texture.valid());
  ASSERT_TRUE(m.specular_color_texture.valid());
  EXPECT_EQ(scene.textures[m.specular_texture.texture].encoding, TextureEncoding::kLinear);
  EXPECT_EQ(scene.textures[m.specular_color_texture.texture].encoding, TextureEncoding::kSrgb);
  EXPECT_TRUE(scene.warnings.empty()) << ::testing::PrintToString(scene.warnings);

  // The tracer's BSDF equals the untextured one with specular = 128/255 and colour = the
  // texel decoded (sRGB 188/255 → 0.5029).
  SurfaceHit hit;
  hit.shading_normal = hit.geometric_normal = Normal3f(0, 0, 1);
  AnyBsdf textured = TraceMaterial(scene.materials[0], &scene.textures).bsdf_at(hit);
  Material expected_material = scene.materials[0];
  auto& e = std::get<MetallicRoughnessMaterial>(expected_material.model);
  e.specular_texture = e.specular_color_texture = {};
  e.specular = 128.f / 255;
  e.specular_color = Rgb(1.f, 0.50289f, 0.f);
  AnyBsdf expected = TraceMaterial(expected_material, &scene.textures).bsdf_at(hit);
  Vector3f wo = normalize(Vector3f(0.3f, 0.1f, 1)), wi = normalize(Vector3f(-0.2f, 0.4f, 1));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(textured.f(wo, wi)[c], expected.f(wo, wi)[c], 1e-4f) << c;
  EXPECT_GT(expected.f(wo, wi).r, expected.f(wo, wi).b);  // the colour reaches the lobe
}

TEST(GltfTransmission, ReadsTransmissionIorAndVolume) {
  json doc = quad_document();
  doc["materials"] = {{{"pbrMetallicRoughness", {{"metallicFactor", 0}}},
                       {"extensions",
                        {{"KHR_materials_transmission", {{"transmissionFactor", 0.75}}},
                         {"KHR_materials_ior", {{"ior", 1.33}}},
                         {"KHR_materials_volume",
                          {{"thicknessFactor", 0.1},
                           {"attenuationDistance", 0.5},
                           {"attenuationColor", {0.9, 0.5, 0.25}}}}}}}};
  Scene scene = load(doc);
  const MetallicRoughnessMaterial& m = mr(scene, 0);
  EXPECT_FLOAT_EQ(m.transmission, 0.75f);
  EXPECT_FLOAT_EQ(m.ior, 1.33f);
  EXPECT_TRUE(m.has_volume());
  EXPECT_FLOAT_EQ(m.attenuation_distance, 0.5f);
  EXPECT_FLOAT_EQ(m.attenuation_color.b, 0.25f);
  for (const std::string& w : scene.warnings)
    EXPECT_EQ(w.find("KHR_materials_"), std::string::npos) << w;
}

TEST(GltfTransmission, OutOfRangeValuesNameTheField) {
  struct Case {
    const char* extension;
    json value;
    const char* field;
  };
  for (const Case& c :
       {Case{"KHR_materials_transmission", {{"transmissionFactor", 1.5}}, "transmissionFactor"},
        Case{"KHR_materials_volume", {{"attenuationDistance", 0}}, "attenuationDistance"},
        Case{"KHR_materials_volume", {{"thicknessFactor", -1}}, "thicknessFactor"},
        Case{"KHR_materials_volume", {{"attenuationColor", {1, 2}}}, "attenuationColor"}}) {
    json doc = quad_document();
    doc["materials"] = {{{"extensions", {{c.extension, c.value}}}}};
    test::expect_error_naming(
        load, doc, std::string("materials[0].extensions.") + c.extension + "." + c.field);
  }
}

}  // namespace
}  // namespace obscura
