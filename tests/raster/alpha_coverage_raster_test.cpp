// glTF alpha coverage in the rasterizer (alphaMode MASK and BLEND, COLOR_0 alpha), against the
// specification's definitions computed by hand: MASK keeps a surface exactly where the alpha
// texture's value is at least alphaCutoff (an iso-line of the texture, which bilinear filtering
// reproduces exactly for an affine alpha), per sample under MSAA; BLEND composes "over" the
// background back to front: c = a1·c1 + (1 − a1)·(a2·c2 + (1 − a2)·bg).
//
// The surfaces are black Lambertian reflectors that emit a known radiance, under a uniform
// environment that is the background: what a pixel shows is then emission and background only.
#include <gtest/gtest.h>

#include <memory>
#include <numbers>
#include <vector>

#include "obscura/camera/frames.h"
#include "obscura/raster/scene_rasterizer.h"
#include "obscura/trace/direct_lighting.h"
#include "obscura/trace/render.h"
#include "obscura/trace/trace_scene.h"
#include "raster_images.h"

namespace obscura::raster {
namespace {

constexpr int kSize = 64;
const Rgb kBackground(0.2f, 0.3f, 0.4f);

// An orthographic camera looking down −Z at the square [−1, 1]², which fills its film exactly.
Camera square_camera(int size = kSize) {
  Camera camera;
  camera.world_from_camera = world_from_camera_look_at({0, 0, 5}, {0, 0, 0});
  camera.projection = Orthographic{2, 2};
  camera.film.width_px = camera.film.height_px = size;
  camera.film.filter = BoxFilter{1e-6};  // the tracer's samples at pixel centres
  return camera;
}

// A quad over [x0, x1] × [−1, 1] at depth z, facing +Z, with glTF UVs: (0, 0) at the top left.
Mesh quad(uint32_t material, float x0, float x1, float z) {
  Mesh m;
  m.name = "quad";
  m.positions = {{x0, -1, z}, {x1, -1, z}, {x1, 1, z}, {x0, 1, z}};
  m.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  m.indices = {0, 1, 2, 0, 2, 3};
  m.material = material;
  return m;
}

Material emitter(Rgb emission, AlphaMode mode, float alpha = 1, float cutoff = 0.5f) {
  MetallicRoughnessMaterial mr;
  mr.base_color = Rgb(0.f);
  mr.metallic = 0;
  mr.specular = 0;  // purely diffuse, and black: only the emission shows
  mr.alpha = alpha;
  Material m;
  m.name = "surface";
  m.model = mr;
  m.emission = emission;
  m.alpha_mode = mode;
  m.alpha_cutoff = cutoff;
  return m;
}

// An n × n texture (linear floats) whose alpha at texel (i, j) is f(u, v) at the texel centre.
template <class F>
obscura::Texture alpha_texture(int n, F f) {
  obscura::Texture t;
  t.width = t.height = n, t.channels = 4;
  t.encoding = TextureEncoding::kLinear;
  t.wrap_u = t.wrap_v = TextureWrap::kClampToEdge;
  t.filter = obscura::TextureFilter::kBilinear;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      t.texels_float.insert(t.texels_float.end(),
                            {1.f, 1.f, 1.f, float(f((i + 0.5) / n, (j + 0.5) / n))});
  return t;
}

Scene base_scene() {
  Scene scene;
  Environment env;
  env.color = kBackground;
  scene.environment = env;
  scene.camera = square_camera();
  return scene;
}

// A white-emitting MASK quad over the view whose base colour texture has alpha (u + v)/2.
Scene masked_scene(float cutoff) {
  Scene scene = base_scene();
  scene.textures.push_back(alpha_texture(16, [](double u, double v) { return (u + v) / 2; }));
  Material m = emitter(Rgb(1.f), AlphaMode::kMask, 1, cutoff);
  std::get<MetallicRoughnessMaterial>(m.model).base_color_texture.texture = 0;
  scene.materials = {m};
  scene.add_meshes({quad(0, -1, 1, 0)});
  return scene;
}

test_images::RasterImages rasterize(const Scene& scene, RasterSettings settings = {}) {
  settings.surface_lights = false;
  return test_images::rasterize_with_aovs(scene, scene.camera, settings);
}

Rgb pixel(const Image& image, int x, int y) {
  return {image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2)};
}

void expect_rgb_near(Rgb got, Rgb want, float tolerance, const std::string& where) {
  EXPECT_NEAR(got.r, want.r, tolerance) << where;
  EXPECT_NEAR(got.g, want.g, tolerance) << where;
  EXPECT_NEAR(got.b, want.b, tolerance) << where;
}

TEST(RasterAlphaCoverage, MaskCutsAlongTheAlphaTexturesIsoLine) {
  // Pixel (x, y) has its centre at u = (x + ½)/64, v = (y + ½)/64; alpha = (u + v)/2 there
  // (bilinear filtering is exact for an affine alpha between the outermost texel centres, so
  // pixels within 2 of the border, where clamping flattens it, are left out). With cutoff 0.45
  // the surface remains where x + y + 1 ≥ 57.6.
  Scene scene = masked_scene(0.45f);
  const float exposure = float(scene.camera.exposure_scale());
  auto r = rasterize(scene);
  int kept = 0;
  for (int y = 2; y < kSize - 2; ++y)
    for (int x = 2; x < kSize - 2; ++x) {
      const bool inside = x + y + 1 >= 57.6;
      kept += inside;
      EXPECT_EQ(r.id.at(x, y, 0), inside ? 0.f : -1.f) << x << ", " << y;
      expect_rgb_near(pixel(r.color, x, y), (inside ? Rgb(1.f) : kBackground) * exposure, 1e-5f,
                      std::to_string(x) + ", " + std::to_string(y));
    }
  EXPECT_GT(kept, 1000);
}

TEST(RasterAlphaCoverage, MaskIsTestedPerSampleUnderMsaa) {
  // alpha = u along x only; the iso-line u = c crosses pixel 32 at 64·c. Direct3D's 4× pattern
  // puts the samples of pixel 32 at x = 32.5 + {−⅛, ⅜, −⅜, ⅛} = 32.375, 32.875, 32.125, 32.625:
  // the resolved pixel is the fraction of those with x ≥ 64·c.
  for (auto [line, covered] :
       {std::pair{32.2, 3}, std::pair{32.5, 2}, std::pair{32.7, 1}, std::pair{32.95, 0}}) {
    Scene scene = base_scene();
    scene.textures.push_back(alpha_texture(16, [](double u, double) { return u; }));
    Material m = emitter(Rgb(1.f), AlphaMode::kMask, 1, float(line / kSize));
    std::get<MetallicRoughnessMaterial>(m.model).base_color_texture.texture = 0;
    scene.materials = {m};
    scene.add_meshes({quad(0, -1, 1, 0)});
    const float exposure = float(scene.camera.exposure_scale());
    RasterSettings settings;
    settings.msaa_samples = 4;
    auto r = rasterize(scene, settings);
    const float f = covered / 4.f;
    for (int y : {5, 30, 58}) {
      expect_rgb_near(pixel(r.color, 32, y), (Rgb(1.f) * f + kBackground * (1 - f)) * exposure,
                      1e-5f, "line " + std::to_string(line));
      expect_rgb_near(pixel(r.color, 31, y), kBackground * exposure, 1e-5f, "left");
      expect_rgb_near(pixel(r.color, 33, y), Rgb(exposure), 1e-5f, "right");
    }
  }
}

TEST(RasterAlphaCoverage, ObjectIdsAgreeWithTheTracerOnAMaskedQuad) {
  // Coverage = texture alpha × COLOR_0 alpha (1 at the top vertices, 0.6 at the bottom), in front
  // of an opaque quad; both renderers must cut the same silhouette.
  Scene scene = masked_scene(0.3f);
  scene.materials.push_back(emitter(Rgb(0.5f), AlphaMode::kOpaque));
  scene.meshes[0].color_alphas = {0.6f, 0.6f, 1.f, 1.f};
  scene.add_meshes({quad(1, -1, 1, -1)});
  scene.camera = square_camera(96);
  scene.camera.world_from_camera = world_from_camera_look_at({0.7, 0.4, 5}, {0, 0, 0});
  auto raster = rasterize(scene);
  TraceScene trace_scene(scene, std::make_shared<EmbreeDevice>());
  Film film(96, 96);
  AovBuffers aovs(96, 96);
  render(trace_scene, scene.camera, DirectLightingIntegrator(), {.samples_per_pixel = 1, .seed = 1},
         film, {}, &aovs);
  Image traced = aovs.id();
  int agree = 0, front = 0, back = 0;
  for (int y = 0; y < 96; ++y)
    for (int x = 0; x < 96; ++x) {
      agree += traced.at(x, y, 0) == raster.id.at(x, y, 0);
      front += raster.id.at(x, y, 0) == 0, back += raster.id.at(x, y, 0) == 1;
    }
  EXPECT_GE(agree, int(0.999 * 96 * 96)) << 96 * 96 - agree << " pixels differ";
  EXPECT_GT(front, 1000);  // both the cut-out and what remains are large
  EXPECT_GT(back, 1000);
}

// Two overlapping BLEND quads: `near` (z = 0, x ∈ [−1, 0.5]) over `far` (z = −0.5, x ∈ [−0.5, 1]).
const Rgb kNear(1.f, 0.2f, 0.1f), kFar(0.1f, 0.9f, 0.3f);
constexpr float kNearAlpha = 0.6f, kFarAlpha = 0.7f;

Scene blended_scene(bool near_first, bool one_mesh) {
  Scene scene = base_scene();
  // The near quad's alpha is its factor (0.75) × its vertex colours' alpha (0.8).
  scene.materials = {emitter(kNear, AlphaMode::kBlend, 0.75f),
                     emitter(kFar, AlphaMode::kBlend, kFarAlpha)};
  Mesh near = quad(0, -1, 0.5f, 0), far = quad(1, -0.5f, 1, -0.5f);
  near.color_alphas.assign(4, 0.8f);
  if (!one_mesh) {
    scene.add_meshes(near_first ? std::vector<Mesh>{near, far} : std::vector<Mesh>{far, near});
    return scene;
  }
  // One mesh (one material: the far quad's) holding both quads, in either triangle order.
  Mesh both = far;
  both.positions.insert(both.positions.end(), near.positions.begin(), near.positions.end());
  both.uvs.insert(both.uvs.end(), near.uvs.begin(), near.uvs.end());
  const std::vector<uint32_t> far_tris = {0, 1, 2, 0, 2, 3}, near_tris = {4, 5, 6, 4, 6, 7};
  both.indices = near_first ? near_tris : far_tris;
  const std::vector<uint32_t>& rest = near_first ? far_tris : near_tris;
  both.indices.insert(both.indices.end(), rest.begin(), rest.end());
  scene.add_meshes({both});
  return scene;
}

TEST(RasterAlphaCoverage, BlendComposesOverTheBackgroundBackToFront) {
  for (bool near_first : {true, false}) {
    Scene scene = blended_scene(near_first, false);
    const float exposure = float(scene.camera.exposure_scale());
    auto r = rasterize(scene);
    const Rgb far_over_bg = kFar * kFarAlpha + kBackground * (1 - kFarAlpha);
    auto at = [&](float world_x) { return pixel(r.color, int((world_x + 1) / 2 * kSize), 32); };
    expect_rgb_near(at(-0.8f), (kNear * kNearAlpha + kBackground * (1 - kNearAlpha)) * exposure,
                    1e-5f, "near only");
    expect_rgb_near(at(0.0f), (kNear * kNearAlpha + far_over_bg * (1 - kNearAlpha)) * exposure,
                    1e-5f, "both");
    expect_rgb_near(at(0.8f), far_over_bg * exposure, 1e-5f, "far only");
    // The id names the surface that covers more than half of what lies behind.
    EXPECT_EQ(r.id.at(32, 32, 0), float(near_first ? 0 : 1));
  }
}

TEST(RasterAlphaCoverage, SortedBlendingDoesNotDependOnTheDrawOrder) {
  for (bool one_mesh : {false, true}) {
    Image a = rasterize(blended_scene(true, one_mesh)).color;
    Image b = rasterize(blended_scene(false, one_mesh)).color;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x)
        for (int c = 0; c < 3; ++c)
          ASSERT_EQ(a.at(x, y, c), b.at(x, y, c)) << x << ", " << y << " one mesh " << one_mesh;
  }
}

TEST(RasterAlphaCoverage, BlendedSurfacesHideNothingAndAreHiddenByOpaqueOnes) {
  // An opaque quad in front of a blended one, first or last in the scene: it hides the blended
  // quad wherever it covers it, as blended surfaces are drawn after opaque ones, depth-tested.
  for (bool opaque_first : {true, false}) {
    Scene scene = base_scene();
    scene.materials = {emitter(Rgb(1.f), AlphaMode::kOpaque),
                       emitter(kFar, AlphaMode::kBlend, kFarAlpha)};
    Mesh opaque = quad(0, -1, 0, 0), blended = quad(1, -1, 1, -0.5f);
    scene.add_meshes(opaque_first ? std::vector<Mesh>{opaque, blended}
                                  : std::vector<Mesh>{blended, opaque});
    const float exposure = float(scene.camera.exposure_scale());
    auto r = rasterize(scene);
    expect_rgb_near(pixel(r.color, 10, 32), Rgb(exposure), 1e-5f, "opaque in front");
    expect_rgb_near(pixel(r.color, 50, 32),
                    (kFar * kFarAlpha + kBackground * (1 - kFarAlpha)) * exposure, 1e-5f,
                    "blended alone");
  }
}

TEST(RasterAlphaCoverage, CutOutsCastCutOutShadows) {
  // Sunlight straight down −Z onto a white floor at z = −1 through a MASK quad at z = 0 whose
  // alpha is u: its left half (u < 0.5) is cut away and lets the light through. The camera sits
  // between the two, looking down at the floor (the quad behind it).
  Scene scene = base_scene();
  scene.environment.reset();
  scene.textures.push_back(alpha_texture(16, [](double u, double) { return u; }));
  Material mask = emitter(Rgb(0.f), AlphaMode::kMask, 1, 0.5f);
  std::get<MetallicRoughnessMaterial>(mask.model).base_color_texture.texture = 0;
  MetallicRoughnessMaterial white;
  white.base_color = Rgb(1.f), white.metallic = 0, white.specular = 0;
  Material floor;
  floor.model = white;
  scene.materials = {mask, floor};
  Mesh ground = quad(1, -2, 2, -1);
  for (Point3f& p : ground.positions) p.y *= 2;
  scene.add_meshes({quad(0, -1, 1, 0), ground});
  obscura::DirectionalLight sun;
  sun.direction = {0, 0, -1};
  sun.irradiance = Rgb(3.f);
  scene.lights.push_back(Light{"sun", sun});
  scene.camera.world_from_camera = world_from_camera_look_at({0, 0, -0.5}, {0, 0, -1});
  RasterSettings settings;
  settings.shadow_map_size = 512;
  auto r = rasterize(scene, settings);
  const float exposure = float(scene.camera.exposure_scale());
  // The lit floor reflects E·ρ/π; in the shadow of the kept half, nothing.
  const float lit = 3.f / std::numbers::pi_v<float> * exposure;
  for (int y : {10, 32, 54}) {
    EXPECT_NEAR(pixel(r.color, 8, y).g, lit, 1e-3f * lit) << "under the cut-away half, " << y;
    EXPECT_NEAR(pixel(r.color, 24, y).g, lit, 1e-3f * lit) << y;
    EXPECT_NEAR(pixel(r.color, 40, y).g, 0.f, 1e-6f) << "under the kept half, " << y;
    EXPECT_NEAR(pixel(r.color, 56, y).g, 0.f, 1e-6f) << y;
  }
}

}  // namespace
}  // namespace obscura::raster
