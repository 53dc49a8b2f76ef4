// Normal maps and the second UV set in both renderers, against closed-form radiance: a flat
// Lambertian quad whose normal map holds one texel encoding a known tilted normal, lit by one
// directional light, reflects ρ/π · E · cos(angle between the light and the tilted normal).
// The tilted normal expected in the world is worked out by hand from the UV layout and the
// placement (which way u grows, which way the image's up lies), not from the tangent code.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "obscura/camera/frames.h"
#include "obscura/raster/scene_rasterizer.h"
#include "obscura/trace/direct_lighting.h"
#include "obscura/trace/render.h"
#include "obscura/trace/trace_scene.h"

namespace obscura {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kAlbedo = 0.8f;
constexpr int kSize = 16;

float radians(float degrees) {
  return degrees * kPi / 180;
}

// A direction tilted by `degrees` from +z towards the unit `towards` (in the z = 0 plane).
Vector3f tilted(float degrees, Vector3f towards) {
  return towards * std::sin(radians(degrees)) + Vector3f(0, 0, 1) * std::cos(radians(degrees));
}

// A one-texel float normal map holding the tangent-space unit normal n (encoded as (n + 1) / 2).
Texture normal_texel(Vector3f n) {
  Texture t;
  t.width = t.height = 1, t.channels = 3;
  t.texels_float = {(n.x + 1) / 2, (n.y + 1) / 2, (n.z + 1) / 2};
  t.encoding = TextureEncoding::kLinear;
  t.filter = TextureFilter::kNearest;
  return t;
}

struct QuadSetup {
  Vector3f texel_normal{0, 0, 1};  // in tangent space
  float normal_scale = 1;
  bool mirrored_uvs = false;          // the image flipped left to right on the quad
  bool file_tangents = false;         // give the mesh tangents instead of generating them
  Transform placement = Transform();  // of the quad (front face +z before it)
  Vector3f to_light{0, 0, 1};         // unit, world
  bool from_below = false;            // camera (and the side seen) under the quad
};

// The 2 m square quad at z = 0, front face +z, UVs with the image's top-left at (−1, 1).
Scene normal_map_scene(const QuadSetup& s) {
  Scene scene;
  Material m = diffuse_material("bumpy", Rgb(kAlbedo));
  m.normal_texture.texture = 0;
  m.normal_scale = s.normal_scale;
  scene.materials = {m};
  scene.textures = {normal_texel(s.texel_normal)};
  Mesh quad;
  quad.name = "quad";
  quad.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  quad.normals.assign(4, Normal3f(0, 0, 1));
  quad.indices = {0, 1, 2, 0, 2, 3};
  quad.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  if (s.mirrored_uvs) quad.uvs = {{1, 1}, {0, 1}, {0, 0}, {1, 0}};
  if (s.file_tangents)
    quad.tangents.assign(4, Vector4f(s.mirrored_uvs ? -1 : 1, 0, 0, s.mirrored_uvs ? -1 : 1));
  scene.add_mesh(std::move(quad), s.placement);
  scene.lights = {{"sun", DirectionalLight{.direction = -s.to_light, .irradiance = Rgb(1.f)}}};
  Camera camera;
  camera.world_from_camera =
      world_from_camera_look_at({0, 0, s.from_below ? -3.0 : 3.0}, {0, 0, 0});
  // Orthographic: the same view direction at every pixel, straight at the quad (which fills the
  // view), so no pixel sees a normal from the side (math/shading_normal.h would bend it).
  camera.projection = Orthographic{.view_height_m = 1.5, .view_width_m = 1.5};
  camera.film.width_px = camera.film.height_px = kSize;
  camera.film.filter = BoxFilter{1e-6};  // one sample at each pixel centre
  scene.camera = camera;
  return scene;
}

Image traced(const Scene& scene, Instancing instancing = Instancing::kAuto) {
  TraceScene trace(scene, std::make_shared<EmbreeDevice>(), {.instancing = instancing});
  Film film(kSize, kSize);
  render(trace, scene.camera, DirectLightingIntegrator(), {.samples_per_pixel = 1, .seed = 1},
         film);
  return film.to_image();
}

Image rasterized(const Scene& scene) {
  raster::RasterSettings settings;
  settings.shadow_map_size = 0;
  raster::SceneRasterizer rasterizer(scene, settings);
  Film film(kSize, kSize);
  rasterizer.render(scene.camera, film);
  return film.to_image();
}

// Every pixel of `image` shows radiance ρ/π · E · max(0, n · l) in every channel.
void expect_lit_as(const Image& image, Vector3f expected_normal, Vector3f to_light,
                   const char* renderer, float tolerance = 1e-3f) {
  float expected = kAlbedo / kPi * std::max(0.f, dot(expected_normal, to_light));
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(image.at(x, y, c), expected, tolerance * (kAlbedo / kPi))
            << renderer << " pixel " << x << ", " << y;
}

void expect_both_lit_as(const QuadSetup& s, Vector3f expected_normal, float tolerance = 1e-3f) {
  Scene scene = normal_map_scene(s);
  expect_lit_as(traced(scene, Instancing::kNever), expected_normal, s.to_light, "tracer (flat)",
                tolerance);
  expect_lit_as(traced(scene, Instancing::kAlways), expected_normal, s.to_light,
                "tracer (instanced)", tolerance);
  expect_lit_as(rasterized(scene), expected_normal, s.to_light, "rasterizer", tolerance);
}

const Vector3f kX{1, 0, 0}, kY{0, 1, 0};

TEST(NormalMap, AFlatTexelLeavesTheSurfaceAsItIs) {
  expect_both_lit_as({.to_light = tilted(60, kX)}, {0, 0, 1});
}

TEST(NormalMap, ATexelTiltedAlongUTiltsTheNormalTowardsGrowingU) {
  // u grows along +x: a texel tilted 30° towards +X tilts the normal 30° towards +x. Lit from
  // 60° on that side it meets the light at 30°; from 20° on the other side at 50°.
  QuadSetup s{.texel_normal = tilted(30, kX), .to_light = tilted(60, kX)};
  expect_both_lit_as(s, tilted(30, kX));
  s.to_light = tilted(20, -kX);
  expect_both_lit_as(s, tilted(30, kX));
}

TEST(NormalMap, ATexelTiltedUpTheImageTiltsTheNormalUpTheImage) {
  // The image's up is +y on the quad.
  expect_both_lit_as({.texel_normal = tilted(30, kY), .to_light = tilted(45, kY)}, tilted(30, kY));
  expect_both_lit_as({.texel_normal = tilted(30, kY), .to_light = tilted(45, -kY)}, tilted(30, kY));
}

TEST(NormalMap, TheFilesTangentsAreUsed) {
  expect_both_lit_as(
      {.texel_normal = tilted(30, kX), .file_tangents = true, .to_light = tilted(60, kX)},
      tilted(30, kX));
}

TEST(NormalMap, AMirroredLayoutMirrorsTheBumps) {
  // The image flipped left to right: u grows along −x, so +X in the texel tilts towards −x,
  // while the image's up (+Y) stays +y. Generated tangents and the file's (w = −1) alike.
  for (bool file : {false, true}) {
    expect_both_lit_as({.texel_normal = tilted(30, kX),
                        .mirrored_uvs = true,
                        .file_tangents = file,
                        .to_light = tilted(60, -kX)},
                       tilted(30, -kX));
    expect_both_lit_as({.texel_normal = tilted(30, kY),
                        .mirrored_uvs = true,
                        .file_tangents = file,
                        .to_light = tilted(45, kY)},
                       tilted(30, kY));
  }
}

TEST(NormalMap, TheScaleMultipliesTheTangentialPart) {
  // glTF: normalize((x·s, y·s, z)): a 30° tilt at scale 0.5 becomes atan(0.5 · tan 30°).
  float degrees = std::atan(0.5f * std::tan(radians(30))) * 180 / kPi;
  expect_both_lit_as(
      {.texel_normal = tilted(30, kX), .normal_scale = 0.5f, .to_light = tilted(60, kX)},
      tilted(degrees, kX));
}

TEST(NormalMap, TheFrameTurnsAndMirrorsWithThePlacement) {
  // A quarter turn about z carries u's direction to +y; a mirror in x carries it to −x and
  // leaves the image's up at +y (the front face stays +z).
  expect_both_lit_as({.texel_normal = tilted(30, kX),
                      .placement = Transform::rotate_z(kPi / 2),
                      .to_light = tilted(60, kY)},
                     tilted(30, kY));
  expect_both_lit_as({.texel_normal = tilted(30, kX),
                      .placement = Transform::scale(-1, 1, 1),
                      .to_light = tilted(60, -kX)},
                     tilted(30, -kX));
  expect_both_lit_as({.texel_normal = tilted(30, kY),
                      .placement = Transform::scale(-1, 1, 1),
                      .to_light = tilted(45, kY)},
                     tilted(30, kY));
}

TEST(NormalMap, TheBackFaceIsLitWithTheWholeNormalFlipped) {
  // Seen from below, a double-sided surface's perturbed normal is reversed: −(tilted 30° to +x).
  Vector3f flipped = -tilted(30, kX);
  Vector3f to_light = -tilted(60, -kX);  // from below, on the −x side
  expect_both_lit_as({.texel_normal = tilted(30, kX), .to_light = to_light, .from_below = true},
                     flipped);
}

TEST(NormalMap, ANormalBelowTheSurfaceIsHeldAtTheHorizonNotFlipped) {
  // A texel tilted 100° would shade from inside the object; it is held (just above) the
  // horizon on its own side, so light from that side still reaches it and light from the other
  // side does not.
  expect_both_lit_as({.texel_normal = tilted(100, kX), .to_light = tilted(60, kX)}, kX, 0.02f);
  expect_both_lit_as({.texel_normal = tilted(100, kX), .to_light = tilted(60, -kX)}, kX, 0.02f);
}

// TEXCOORD_1: a 4 × 1 texture, red in the left half and green in the right; UV set 0 maps the
// quad into the left half and set 1 into the right one (far enough from the middle that the
// rasterizer's bilinear filter sees one colour), so the reference's set decides the colour.
Scene two_uv_sets(uint32_t uv_set, bool normal_map) {
  Scene scene;
  Material m = diffuse_material("two sets", Rgb(1.f));
  std::get<DiffuseMaterial>(m.model).reflectance_texture = {.texture = 0, .uv_set = uv_set};
  Texture halves;
  halves.width = 4, halves.height = 1, halves.channels = 3;
  halves.texels_float = {1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0};
  halves.encoding = TextureEncoding::kLinear;
  halves.filter = TextureFilter::kNearest;
  scene.textures = {halves};
  if (normal_map) {  // on the other set: flat where set 0 points, tilted where set 1 does
    Texture normals = halves;
    Vector3f t = tilted(30, kX);
    float tx = (t.x + 1) / 2, ty = (t.y + 1) / 2, tz = (t.z + 1) / 2;
    normals.texels_float = {0.5f, 0.5f, 1, 0.5f, 0.5f, 1, tx, ty, tz, tx, ty, tz};
    scene.textures.push_back(normals);
    m.normal_texture = {.texture = 1, .uv_set = 1 - uv_set};
  }
  scene.materials = {m};
  Mesh quad;
  quad.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  quad.normals.assign(4, Normal3f(0, 0, 1));
  quad.indices = {0, 1, 2, 0, 2, 3};
  quad.uvs = {{0.15f, 0.9f}, {0.35f, 0.9f}, {0.35f, 0.1f}, {0.15f, 0.1f}};
  quad.uvs1 = {{0.65f, 0.9f}, {0.85f, 0.9f}, {0.85f, 0.1f}, {0.65f, 0.1f}};
  scene.add_mesh(std::move(quad));
  scene.lights = {{"sun", DirectionalLight{.direction = -tilted(60, kX), .irradiance = Rgb(1.f)}}};
  scene.camera = normal_map_scene({}).camera;
  return scene;
}

TEST(TexCoord1, EachTextureReadsItsOwnUvSet) {
  const float cos60 = 0.5f, cos30 = std::cos(radians(30));
  for (uint32_t set : {0u, 1u}) {
    for (bool normal_map : {false, true}) {
      Scene scene = two_uv_sets(set, normal_map);
      // Set 0 reads red, set 1 green; the normal map on the other set is tilted only on set 1.
      float cosine = normal_map && set == 0 ? cos30 : cos60;
      float lit = 1 / kPi * cosine;
      for (const auto& [name, image] :
           {std::pair{"tracer", traced(scene)}, std::pair{"rasterizer", rasterized(scene)}}) {
        for (int y = 0; y < kSize; ++y)
          for (int x = 0; x < kSize; ++x) {
            ASSERT_NEAR(image.at(x, y, 0), set == 0 ? lit : 0, 1e-3f) << name << " set " << set;
            ASSERT_NEAR(image.at(x, y, 1), set == 1 ? lit : 0, 1e-3f) << name << " set " << set;
            ASSERT_NEAR(image.at(x, y, 2), 0, 1e-4f) << name;
          }
      }
    }
  }
}

}  // namespace
}  // namespace obscura
