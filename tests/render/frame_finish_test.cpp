// Frame finishing's recipe and layers: the recipe survives its text exactly, a malformed or
// hostile one is an error naming what is wrong (never a crash or a huge allocation), and a frame
// finished from the recipe is the frame the camera's own glare gives.
#include "obscura/render/frame_finish.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

#include "obscura/camera/perspective.h"
#include "obscura/film/film.h"
#include "obscura/math/error.h"
#include "obscura/render/camera_glare.h"

namespace obscura {
namespace {

Image sums_of(const Image& rgb) {
  Film film(rgb.width, rgb.height);
  for (int y = 0; y < rgb.height; ++y)
    for (int x = 0; x < rgb.width; ++x) film.add_sample({x, y}, rgb.rgb(x, y));
  return film.sums();
}

Image point_light(int width, int height) {
  Image image(width, height, 3);
  for (int c = 0; c < 3; ++c) image.data[(size_t(height / 2) * width + width / 2) * 3 + c] = 100;
  return image;
}

TEST(FrameFinish, TheRecipeSurvivesItsTextExactly) {
  FrameFinish finish;
  finish.depth_of_field = DepthOfFieldFinish{
      .pixel_aspect = 1.0 / 3, .settings = {.max_coc_px = 31.7, .depth_tolerance = 0.1}};
  finish.flare = true;
  finish.glare = GlareFinish{.aperture = {.blades = 7, .rotation_degrees = 12.345678901234567},
                             .f_number = 2.8000000000000003,
                             .pixel_width_mm = 0.0043,
                             .pixel_height_mm = 0.0043000000000000001,
                             .settings = {.strength = 2.5, .radius_px = 64}};
  const std::string text = frame_finish_text(finish);
  const FrameFinish back = parse_frame_finish(text, "test");
  EXPECT_EQ(frame_finish_text(back), text);
  ASSERT_TRUE(back.depth_of_field && back.glare);
  EXPECT_EQ(back.depth_of_field->pixel_aspect, 1.0 / 3);  // exact, not to 17 digits' rounding
  EXPECT_EQ(back.glare->aperture.rotation_degrees, 12.345678901234567);
  EXPECT_EQ(back.glare->f_number, 2.8000000000000003);
  EXPECT_TRUE(back.flare);
  EXPECT_EQ(frame_finish_text({}), "none");
  EXPECT_FALSE(parse_frame_finish("none", "test").any());
}

TEST(FrameFinish, MalformedRecipesAreErrorsNamingThePart) {
  for (const std::string text :
       {"", "bogus", "dof=1,2", "dof=1,2,3;dof=1,2,3", "flare=1", "glare=3.5,0,2,1,1,1,8",
        "glare=6,0,2,1,1,1,99999", "glare=6,0,-2,1,1,1,8", "glare=6,0,2,1,1,nan,8",
        "dof=inf,32,0.05", "glare=6,0,2,1,1,1e400,8"}) {
    try {
      parse_frame_finish(text, "part.exr: obscura:finish");
      ADD_FAILURE() << "accepted '" << text << "'";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("obscura:finish"), std::string::npos) << e.what();
    }
  }
}

TEST(FrameFinish, HostileDepthOfFieldNumbersAreRefusedNotAllocated) {
  const Image sums = sums_of(point_light(8, 6));
  Image layer(8, 6, 2);
  layer.channel_names = {"Z", "C"};
  for (size_t p = 0; p < 8 * 6; ++p) layer.data[2 * p] = 1, layer.data[2 * p + 1] = 3;
  for (DepthOfFieldFinish dof : {DepthOfFieldFinish{.pixel_aspect = 1e300, .settings = {}},
                                 DepthOfFieldFinish{.pixel_aspect = 1e-300, .settings = {}},
                                 DepthOfFieldFinish{.pixel_aspect = 1, .settings = {1e30, 0.05}},
                                 DepthOfFieldFinish{.pixel_aspect = 1, .settings = {32, 1e-300}}}) {
    FrameFinish finish;
    finish.depth_of_field = dof;
    EXPECT_THROW(finish_frame(sums, {{"dof", layer}}, finish), Error);
  }
}

TEST(FrameFinish, AMissingOrMisshapedLayerIsAnError) {
  const Image sums = sums_of(point_light(8, 6));
  FrameFinish flare;
  flare.flare = true;
  EXPECT_THROW(finish_frame(sums, {}, flare), Error);
  EXPECT_THROW(finish_frame(sums, {{"flare", Image(8, 6, 2)}}, flare), Error);
  EXPECT_THROW(finish_frame(sums, {{"flare", Image(8, 5, 3)}}, flare), Error);
  // And with the layer, its light is added to the frame.
  Image light(8, 6, 3);
  light.data[0] = 0.25f;
  const Image finished = finish_frame(sums, {{"flare", light}}, flare);
  EXPECT_EQ(finished.data[0], 0.25f);
}

TEST(FrameFinish, GlareFromTheRecipeIsTheCamerasGlare) {
  // The numbers the recipe carries give the PSF the camera gives: a shard's merge glares its
  // frame as the process that rendered it would have.
  Camera camera;
  // 6 µm pixels, as a real sensor's: the PSF's grid stays small (1 mm pixels need a huge one).
  auto& sensor = std::get<Perspective>(camera.projection);
  sensor.sensor_width_mm = 33 * 0.006;
  sensor.sensor_height_mm = 21 * 0.006;
  camera.film.width_px = 33;
  camera.film.height_px = 21;
  camera.lens.f_number = 11;
  camera.lens.aperture.blades = 6;
  camera.lens.aperture.rotation_degrees = 15;
  const GlareSettings settings{.strength = 3, .radius_px = 12};
  Image direct = point_light(33, 21);
  apply_glare(direct, camera, settings);

  FrameFinish finish;
  finish.glare = glare_finish(camera, settings);
  const Image finished = finish_frame(sums_of(point_light(33, 21)), {}, finish);
  ASSERT_EQ(finished.data.size(), direct.data.size());
  EXPECT_EQ(std::memcmp(finished.data.data(), direct.data.data(), direct.data.size() * 4), 0);
  // The glare spread the light: a pixel three away from the point now holds some.
  EXPECT_GT(finished.rgb(16 + 3, 10).g, 0.f);
}

}  // namespace
}  // namespace obscura
