// The rasterizer and the tracer on the Khronos sample models users bring (tests/data/gltf/, through
// the fidelity suite's cameras): the same object is seen at ≥ 99.9 % of pixel centres, alpha-cut
// silhouettes (MASK; BLEND is compared as opaque), instancing, negative scale and node transforms
// included, and every disagreement lies on a silhouette.
#include <gtest/gtest.h>

#include <memory>
#include <ostream>
#include <string>

#include "gltf_fidelity_scene.h"
#include "obscura/raster/scene_rasterizer.h"
#include "obscura/trace/direct_lighting.h"
#include "obscura/trace/render.h"
#include "obscura/trace/trace_scene.h"
#include "raster_images.h"

namespace obscura::raster {
namespace {

// One tracer sample at each pixel centre, where the rasterizer samples too.
Image traced_ids(const Scene& scene, Camera camera) {
  camera.film.filter = BoxFilter{1e-6};
  TraceScene trace_scene(scene, std::make_shared<EmbreeDevice>());
  Film film(camera.film.width_px, camera.film.height_px);
  AovBuffers aovs(camera.film.width_px, camera.film.height_px);
  render(trace_scene, camera, DirectLightingIntegrator(), {.samples_per_pixel = 1, .seed = 1}, film,
         {}, &aovs);
  return aovs.id();
}

using test_images::on_silhouette;

struct Sample {
  const char* name;
  const char* model;
};

void PrintTo(const Sample& sample, std::ostream* os) {
  *os << sample.name;
}

class SampleModel : public ::testing::TestWithParam<Sample> {};

TEST_P(SampleModel, ObjectIdsAgreeWithTheTracerAtPixelCentres) {
  const Sample& sample = GetParam();
  Scene scene = test::fidelity_scene(sample.name, sample.model, 160);
  // A blended surface has no one id at a pixel (the tracer's first hit is drawn by its alpha,
  // the rasterizer composites every layer): compare blended surfaces as opaque ones.
  for (Material& material : scene.materials)
    if (material.alpha_mode == AlphaMode::kBlend) material.alpha_mode = AlphaMode::kOpaque;
  Image traced = traced_ids(scene, scene.camera);
  Image rastered = test_images::rasterize_with_aovs(scene, scene.camera).id;
  int agree = 0, seen = 0, off_silhouette = 0, total = traced.width * traced.height;
  for (int y = 0; y < traced.height; ++y)
    for (int x = 0; x < traced.width; ++x) {
      if (traced.at(x, y, 0) == rastered.at(x, y, 0)) {
        ++agree;
        seen += traced.at(x, y, 0) >= 0;
      } else if (!on_silhouette(traced, x, y) && ++off_silhouette <= 5) {
        ADD_FAILURE() << "pixel (" << x << ", " << y << ") is id " << rastered.at(x, y, 0)
                      << " in the raster, " << traced.at(x, y, 0)
                      << " in the tracer, away from any silhouette";
      }
    }
  EXPECT_GE(double(agree) / total, 0.999) << total - agree << " pixels differ";
  EXPECT_EQ(off_silhouette, 0);
  EXPECT_GT(seen, total / 10);  // not an empty frame
}

INSTANTIATE_TEST_SUITE_P(
    Gltf, SampleModel,
    ::testing::Values(Sample{"Duck", "Duck/Duck.glb"},
                      Sample{"OrientationTest", "OrientationTest/OrientationTest.glb"},
                      Sample{"NegativeScaleTest", "NegativeScaleTest/NegativeScaleTest.glb"},
                      Sample{"SimpleInstancing", "SimpleInstancing/SimpleInstancing.glb"},
                      Sample{"TextureSettingsTest", "TextureSettingsTest/TextureSettingsTest.glb"},
                      Sample{"AlphaBlendModeTest", "AlphaBlendModeTest/AlphaBlendModeTest.glb"},
                      Sample{"TwoSidedPlane", "TwoSidedPlane/glTF/TwoSidedPlane.gltf"}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace obscura::raster
