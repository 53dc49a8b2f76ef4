// The path tracer against Blender Cycles (an independent renderer) on the Cornell-like scene of
// data/reference/cornell: the same glTF file, camera, film and light transport. Our RMSE
// against Cycles' high-sample reference must be within 1.5× of Cycles' own at the same sample
// count, and the image mean must agree within noise (no bias).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "obscura/film/image_metrics.h"
#include "obscura/io/image_io.h"
#include "obscura/io/scene_loader.h"
#include "obscura/trace/path_tracer.h"
#include "obscura/trace/render.h"
#include "test_paths.h"
#include "trace_test_scenes.h"

namespace obscura {
namespace {

std::shared_ptr<EmbreeDevice> device() {
  return testing::embree_device();
}

double read_number(const std::string& path) {
  std::ifstream file(path);
  double value = 0;
  file >> value;
  return value;
}

// Renders the glTF scene with `camera` at 256 spp (box filter 1 px, Cycles' max_bounces 64 =
// 65 scattering events) and compares with the reference render.
void expect_matches_cycles(const Camera& camera, const std::string& reference_exr,
                           double cycles_rmse_256spp) {
  ASSERT_GT(cycles_rmse_256spp, 0);
  // The glTF scene as a user would load it: every material carries KHR_materials_specular with
  // specular 0 (purely diffuse) and the light KHR_materials_emissive_strength 15.
  Scene scene = load_scene_file(test::source_path("data/reference/cornell/cornell.glb"));
  scene.camera = camera;
  TraceScene trace_scene(scene, device());
  Film film(camera.film.width_px, camera.film.height_px);
  render(trace_scene, camera, PathTracer({.max_depth = 65}), {.samples_per_pixel = 256, .seed = 1},
         film);

  Image reference = read_image(reference_exr);
  ASSERT_EQ(reference.width, film.width());
  ASSERT_EQ(reference.height, film.height());
  const ImageDifference diff = compare_images(film.to_image(), reference, 3);
  const double n = diff.pixels() * 3, rmse = diff.rmse();
  EXPECT_LT(rmse, 1.5 * cycles_rmse_256spp)
      << "RMSE " << rmse << " vs Cycles' " << cycles_rmse_256spp;
  // The mean of n values each with error ~rmse: a bias beyond 4·rmse/√(n/3) is not noise.
  const double bias = diff.mean_difference();
  EXPECT_LT(std::abs(bias), 4 * rmse / std::sqrt(n / 3)) << "mean difference " << bias;
  ::testing::Test::RecordProperty("rmse", std::to_string(rmse));
}

TEST(CyclesReference, PinholeCornellBox) {
  // data/reference/cornell: 16,384 spp, 128², pinhole at (0, 1, 3.9) looking at (0, 1, 0),
  // 50 mm on a 36 mm-wide sensor (horizontal FOV 39.5978°).
  Camera camera = testing::make_camera({0, 1, 3.9}, {0, 1, 0}, 128, 39.597752709049864);
  expect_matches_cycles(
      camera, test::source_path("data/reference/cornell/cornell_ref.exr"),
      read_number(test::source_path("data/reference/cornell/cycles_rmse_256spp.txt")));
}

TEST(CyclesReference, ThinLensCornellBox) {
  // data/reference/cornell-dof (made with ../shared/tools/peers/cycles, see its README): the
  // same scene through a 50 mm f/0.25 lens focused at 3.4 m (between the boxes; the back wall
  // blurs by 3 px, the ceiling light by 1.3 px), circular aperture, Cycles' convention of a fixed
  // field of view: `--focal-length 50 --sensor 36x24 --fstop 0.25 --focus-distance 3.4
  // --focus-breathing off`.
  Camera camera;
  camera.world_from_camera = world_from_camera_look_at({0, 1, 3.9}, {0, 1, 0});
  Perspective lens;
  lens.focal_length_mm = 50;
  lens.sensor_width_mm = 36;
  lens.sensor_height_mm = 24;
  camera.projection = lens;
  camera.film.width_px = camera.film.height_px = 128;
  camera.lens.depth_of_field = true;
  camera.lens.f_number = 0.25;
  camera.lens.focus_distance_m = 3.4;
  camera.lens.focus_breathing = false;
  expect_matches_cycles(
      camera, test::source_path("data/reference/cornell-dof/cornell_dof_ref.exr"),
      read_number(test::source_path("data/reference/cornell-dof/cycles_rmse_256spp.txt")));
}

}  // namespace
}  // namespace obscura
