// The Cornell box as published on Cornell's "Cornell Box Data" page (also transcribed in
// ../shared/assets/cornell/measured/): 16 quads in millimetres, walls facing into the box and
// block faces facing out. Reflectances are RGB approximations of the measured spectra
// (McGuire's); the light's colour follows its measured spectrum (more red than blue).
#include <array>

#include "obscura/camera/frames.h"
#include "obscura/math/transform.h"
#include "obscura/scene/builtin_scenes.h"

namespace obscura {

namespace {

using Quad = std::array<Point3f, 4>;

constexpr float kMetresPerMillimetre = 0.001f;

// The light is published coplanar with the ceiling (y = 548.8 mm); lowering it by 0.1 mm keeps
// the two surfaces from fighting for the same hits.
constexpr float kLightY = 548.7f;

void add_quads(Mesh& mesh, std::initializer_list<Quad> quads) {
  for (const Quad& q : quads) {
    auto base = uint32_t(mesh.positions.size());
    for (Point3f p : q)
      mesh.positions.emplace_back(p.x * kMetresPerMillimetre, p.y * kMetresPerMillimetre,
                                  p.z * kMetresPerMillimetre);
    // Two triangles per quad, keeping the quad's winding (the left wall is not planar).
    mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
}

Material diffuse(const char* name, Rgb reflectance, Rgb emission = {}) {
  Material m;
  m.name = name;
  DiffuseMaterial d;
  d.reflectance = reflectance;
  m.model = d;
  m.emission = emission;
  return m;
}

Mesh make_mesh(const char* name, uint32_t material, std::initializer_list<Quad> quads) {
  Mesh mesh;
  mesh.name = name;
  mesh.material = material;
  add_quads(mesh, quads);
  return mesh;
}

}  // namespace

Scene make_cornell_box() {
  enum : uint32_t { kWhite, kRed, kGreen, kLight };
  Scene scene;
  scene.name = "cornell-box";
  scene.materials = {
      diffuse("white", {0.725f, 0.71f, 0.68f}),
      diffuse("red", {0.63f, 0.065f, 0.05f}),
      diffuse("green", {0.14f, 0.45f, 0.091f}),
      diffuse("light", {0.78f, 0.78f, 0.78f}, {17.f, 12.f, 4.f}),
  };
  for (const Mesh& mesh : std::initializer_list<Mesh>{
           make_mesh("floor", kWhite,
                     {{{{552.8f, 0, 0}, {0, 0, 0}, {0, 0, 559.2f}, {549.6f, 0, 559.2f}}}}),
           make_mesh("light", kLight,
                     {{{{343, kLightY, 227},
                        {343, kLightY, 332},
                        {213, kLightY, 332},
                        {213, kLightY, 227}}}}),
           make_mesh(
               "ceiling", kWhite,
               {{{{556, 548.8f, 0}, {556, 548.8f, 559.2f}, {0, 548.8f, 559.2f}, {0, 548.8f, 0}}}}),
           make_mesh("back_wall", kWhite,
                     {{{{549.6f, 0, 559.2f},
                        {0, 0, 559.2f},
                        {0, 548.8f, 559.2f},
                        {556, 548.8f, 559.2f}}}}),
           make_mesh("right_wall", kGreen,
                     {{{{0, 0, 559.2f}, {0, 0, 0}, {0, 548.8f, 0}, {0, 548.8f, 559.2f}}}}),
           make_mesh(
               "left_wall", kRed,
               {{{{552.8f, 0, 0}, {549.6f, 0, 559.2f}, {556, 548.8f, 559.2f}, {556, 548.8f, 0}}}}),
           make_mesh("short_block", kWhite,
                     {{{{130, 165, 65}, {82, 165, 225}, {240, 165, 272}, {290, 165, 114}}},
                      {{{290, 0, 114}, {290, 165, 114}, {240, 165, 272}, {240, 0, 272}}},
                      {{{130, 0, 65}, {130, 165, 65}, {290, 165, 114}, {290, 0, 114}}},
                      {{{82, 0, 225}, {82, 165, 225}, {130, 165, 65}, {130, 0, 65}}},
                      {{{240, 0, 272}, {240, 165, 272}, {82, 165, 225}, {82, 0, 225}}}}),
           make_mesh("tall_block", kWhite,
                     {{{{423, 330, 247}, {265, 330, 296}, {314, 330, 456}, {472, 330, 406}}},
                      {{{423, 0, 247}, {423, 330, 247}, {472, 330, 406}, {472, 0, 406}}},
                      {{{472, 0, 406}, {472, 330, 406}, {314, 330, 456}, {314, 0, 456}}},
                      {{{314, 0, 456}, {314, 330, 456}, {265, 330, 296}, {265, 0, 296}}},
                      {{{265, 0, 296}, {265, 330, 296}, {423, 330, 247}, {423, 0, 247}}}}),
       })
    scene.add_mesh(mesh);
  // Published camera: at (278, 273, −800) mm looking along +Z, a 35 mm lens on a 25 × 25 mm
  // film (vertical FOV = 2·atan(12.5 / 35) = 39.3076°). The lens focuses on the box's centre
  // (z = 279.6 mm) for when depth of field is switched on.
  Point3d eye(0.278, 0.273, -0.800);
  scene.camera.name = "cornell";
  scene.camera.world_from_camera = world_from_camera_look_at(eye, eye + Vector3d(0, 0, 1));
  Perspective lens_and_film;
  lens_and_film.focal_length_mm = 35;
  lens_and_film.sensor_width_mm = lens_and_film.sensor_height_mm = 25;
  scene.camera.projection = lens_and_film;
  scene.camera.lens.focus_distance_m = 0.800 + 0.2796;
  scene.cameras.push_back(scene.camera);
  return scene;
}

}  // namespace obscura
