// Depth of field and motion blur by accumulation, measured on edges as the tracer's tests
// measure them: the blur must be the circle of confusion worked out by hand from the thin-lens
// formula, or the distance an edge travels while the shutter is open.
#include "obscura/raster/accumulation.h"

#include <gtest/gtest.h>

#include <limits>
#include <set>

#include <tbb/global_control.h>

#include "obscura/math/error.h"
#include "raster/effects_test_scene.h"

namespace obscura::raster {
namespace {

using test::disk_edge;
using test::kPixelMm;
using test::kStripHeight;
using test::kStripWidth;
using test::partial_pixels;
using test::predicted_width_10_90;
using test::Rect;
using test::row_profile;
using test::width_10_90;

// Renders the rectangles with `samples` accumulated frames; `move` gives each rectangle's
// x offset at time t (object motion).
Image accumulate_rects(const Camera& camera, std::vector<Rect> rects, AccumulationSettings settings,
                       const std::function<double(double)>& move = {},
                       RenderTarget* middle_frame = nullptr) {
  Film film(camera.film.width_px, camera.film.height_px);
  accumulate(
      camera, settings,
      [&](const FrameParameters& frame, RenderTarget& target) {
        std::vector<Rect> moved = rects;
        if (move)
          for (Rect& r : moved)
            r.x0 += move(frame.sample.time_s), r.x1 += move(frame.sample.time_s);
        test::draw_rects(moved, frame, target);
      },
      film, {}, middle_frame);
  return film.to_image();
}

Image accumulate_rects(const Camera& camera, std::vector<Rect> rects, int samples,
                       const std::function<double(double)>& move = {}, uint64_t seed = 1) {
  return accumulate_rects(camera, std::move(rects), {.samples = samples, .seed = seed}, move);
}

// A white half-plane x ≥ 0 at `depth`: a vertical edge through the film's centre.
std::vector<Rect> half_plane(double depth) {
  return {{0, 50, -50, 50, depth}};
}

TEST(AccumulatedDepthOfField, InFocusEdgeIsSharpAndTwiceTheDistanceBlursByTheCircleOfConfusion) {
  Camera camera = test::strip_camera();
  camera.lens.depth_of_field = true;
  camera.lens.f_number = 1;
  camera.lens.focus_distance_m = 0.5;

  auto focused = row_profile(accumulate_rects(camera, half_plane(0.5), 64), kStripHeight / 2);
  EXPECT_LE(width_10_90(focused), 1.0);
  EXPECT_EQ(partial_pixels(focused, 0, 1), 0);

  // By hand: A = f/N = 50 mm; c = A·(S − S_f)/S · f/(S_f − f) = 50 · 500/1000 · 50/450 mm
  // = 2.778 mm on the sensor, 7.41 pixels of 0.375 mm.
  const double coc_px = 50.0 * (1000 - 500) / 1000 * 50 / (500 - 50) / kPixelMm;
  auto far = row_profile(accumulate_rects(camera, half_plane(1), 256), kStripHeight / 2);
  double r = coc_px / 2;
  EXPECT_NEAR(width_10_90(far), predicted_width_10_90([r](double s) { return disk_edge(r, s); }),
              0.1)
      << "circle of confusion " << coc_px << " px";
  // The blur spans the circle's diameter: every pixel centre within c/2 of the edge is partly
  // covered, none beyond.
  EXPECT_NEAR(partial_pixels(far, 0, 1), coc_px, 1.0);
  EXPECT_EQ(far[size_t(std::floor(kStripWidth / 2 - r - 0.5))], 0.0);
  EXPECT_EQ(far[size_t(std::ceil(kStripWidth / 2 + r - 0.5))], 1.0);
}

TEST(AccumulatedDepthOfField, BladesDoNotChangeTheFocusPlane) {
  Camera camera = test::strip_camera();
  camera.lens.depth_of_field = true;
  camera.lens.f_number = 1;
  camera.lens.focus_distance_m = 0.5;
  camera.lens.aperture = {.blades = 5, .rotation_degrees = 10};
  auto focused = row_profile(accumulate_rects(camera, half_plane(0.5), 32), kStripHeight / 2);
  EXPECT_EQ(partial_pixels(focused, 0, 1), 0);
  auto far = row_profile(accumulate_rects(camera, half_plane(1), 32), kStripHeight / 2);
  EXPECT_GT(partial_pixels(far, 0, 1), 5);
}

// 0.1 m of travel at 2 m in front of a 50 mm lens: f·T/S = 2.5 mm on the sensor, 6.67 pixels.
constexpr double kTravelPx = 50 * 0.1 / 2 / kPixelMm;

TEST(AccumulatedMotionBlur, AMovingSquaresEdgeBlursByItsTravel) {
  Camera camera = test::strip_camera();
  camera.shutter = {.open_s = 0, .close_s = 0.01};
  auto move = [](double t) { return 0.1 * t / 0.01; };  // 10 m/s along +X
  auto blurred = row_profile(accumulate_rects(camera, half_plane(2), 64, move), kStripHeight / 2);
  // The edge sweeps uniformly from x = 48 to 48 + travel: a linear ramp.
  double edge_x = kStripWidth / 2 + kTravelPx / 2;
  auto smear = [](double s) { return std::clamp(s / kTravelPx + 0.5, 0.0, 1.0); };
  EXPECT_NEAR(width_10_90(blurred), predicted_width_10_90(smear, edge_x), 0.1);
  EXPECT_NEAR(partial_pixels(blurred, 0, 1), kTravelPx, 1.0);

  camera.shutter = {.open_s = 0.005, .close_s = 0.005};  // instantaneous: sharp at t = 5 ms
  auto sharp = row_profile(accumulate_rects(camera, half_plane(2), 16, move), kStripHeight / 2);
  EXPECT_EQ(partial_pixels(sharp, 0, 1), 0);
  EXPECT_NEAR(test::crossing(sharp, 0.5), edge_x, 0.5 + 1e-9);
}

TEST(AccumulatedMotionBlur, AMovingCameraBlursAStillEdgeByTheSameTravel) {
  Camera camera = test::strip_camera();
  camera.shutter = {.open_s = 0, .close_s = 0.01};
  camera.world_from_camera =
      AnimatedTransform({{0.0, Transform()}, {0.01, Transform::translate({0.1, 0, 0})}});
  auto blurred = row_profile(accumulate_rects(camera, half_plane(2), 64), kStripHeight / 2);
  double edge_x = kStripWidth / 2 - kTravelPx / 2;  // the edge moves left on the film
  auto smear = [](double s) { return std::clamp(s / kTravelPx + 0.5, 0.0, 1.0); };
  EXPECT_NEAR(width_10_90(blurred), predicted_width_10_90(smear, edge_x), 0.1);
}

TEST(AccumulationSamples, TimesAndLensPointsAreStratified) {
  Camera camera;
  camera.shutter = {.open_s = 0.25, .close_s = 0.75};
  for (uint64_t seed : {0u, 7u}) {
    auto samples = accumulation_samples(camera, 64, seed);
    // Sobol' points form a (0, 6, 2)-net in each pair of their first dimensions (and Owen
    // scrambling keeps that): one point in each 1/64 of the shutter, each 8 × 8 cell of the
    // lens square, and each 8 × 8 cell of (lens x, time).
    std::set<int> times, lens_cells, lens_time_cells;
    for (const LensTimeSample& s : samples) {
      double u_t = (s.time_s - 0.25) / 0.5;
      ASSERT_GE(u_t, 0);
      ASSERT_LT(u_t, 1);
      times.insert(int(u_t * 64));
      lens_cells.insert(int(s.lens_sample.x * 8) * 8 + int(s.lens_sample.y * 8));
      lens_time_cells.insert(int(s.lens_sample.x * 8) * 8 + int(u_t * 8));
    }
    EXPECT_EQ(times.size(), 64u);
    EXPECT_EQ(lens_cells.size(), 64u);
    EXPECT_EQ(lens_time_cells.size(), 64u);
  }
  EXPECT_NE(accumulation_samples(camera, 4, 1)[0].time_s,
            accumulation_samples(camera, 4, 2)[0].time_s);
  auto single = accumulation_samples(camera, 1, 3);
  EXPECT_EQ(single[0].lens_sample, Point2d(0.5, 0.5));
  EXPECT_EQ(single[0].time_s, 0.5);
  EXPECT_THROW(accumulation_samples(camera, 0, 0), Error);
}

TEST(Accumulation, IsBitIdenticalForAnyThreadCount) {
  Camera camera = test::strip_camera(64);
  camera.lens.depth_of_field = true;
  camera.lens.f_number = 2;
  camera.lens.focus_distance_m = 1;
  camera.shutter = {.open_s = 0, .close_s = 0.01};
  std::vector<Rect> rects = {{-0.1, 0.05, -0.05, 0.08, 0.7, {1, 0.5, 0.2}},
                             {-0.3, 0.3, -0.2, 0.02, 1.5, {0.2, 0.4, 1}}};
  auto move = [](double t) { return 3 * t; };
  auto render_with = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return accumulate_rects(camera, rects, 24, move, 9);
  };
  Image one = render_with(1), two = render_with(2), four = render_with(4);
  EXPECT_EQ(one.data, two.data);
  EXPECT_EQ(one.data, four.data);
}

TEST(Accumulation, WithDepthOfFieldOffEveryFrameLooksThroughTheLensCentre) {
  Camera camera = test::strip_camera();
  camera.lens.depth_of_field = true;
  camera.lens.f_number = 1;
  camera.lens.focus_distance_m = 0.5;
  auto sharp = row_profile(
      accumulate_rects(camera, half_plane(1), {.samples = 8, .seed = 1, .depth_of_field = false}),
      kStripHeight / 2);
  EXPECT_EQ(partial_pixels(sharp, 0, 1), 0);
}

TEST(Accumulation, KeepsTheFrameNearestMidShutter) {
  Camera camera = test::strip_camera();
  camera.shutter = {.open_s = 0, .close_s = 0.01};
  auto move = [](double t) { return 0.1 * t / 0.01; };
  const AccumulationSettings settings{.samples = 8, .seed = 4, .aovs = true};
  double kept_time = 0;
  for (const LensTimeSample& s : accumulation_samples(camera, 8, 4))
    if (std::abs(s.time_s - 0.005) < std::abs(kept_time - 0.005)) kept_time = s.time_s;
  RenderTarget middle(1, 1);
  accumulate_rects(camera, half_plane(2), settings, move, &middle);
  ASSERT_TRUE(middle.has_aovs());
  // The kept frame's edge is where the square was at that time: x = 48 + travel · t / T.
  double edge_x = kStripWidth / 2 + kTravelPx * kept_time / 0.01;
  int first_white = int(std::ceil(edge_x - 0.5));
  EXPECT_EQ(middle.color_at(first_white - 1, 4).g, 0.f);
  EXPECT_EQ(middle.color_at(first_white, 4).g, 1.f);
  EXPECT_FLOAT_EQ(middle.view_depth_at(kStripWidth - 1, 4), 2.f);  // 2 m along the axis
  EXPECT_EQ(middle.view_depth_at(0, 4), std::numeric_limits<float>::infinity());  // nothing
}

TEST(Accumulation, NeedsAccumulationForDepthOfFieldOrMotionWhileTheShutterIsOpen) {
  Camera camera;
  EXPECT_FALSE(needs_accumulation(camera, false));
  EXPECT_TRUE(needs_accumulation(camera, true));
  camera.shutter = {.open_s = 0, .close_s = 0};
  EXPECT_FALSE(needs_accumulation(camera, true));
  camera.lens.depth_of_field = true;
  EXPECT_TRUE(needs_accumulation(camera, false));
  EXPECT_FALSE(has_motion_blur(camera, false));  // the lens alone blurs nothing in time
  camera.shutter = {.open_s = 0, .close_s = 0.01};
  EXPECT_FALSE(has_motion_blur(camera, false));
  EXPECT_TRUE(has_motion_blur(camera, true));
}

TEST(Accumulation, RejectsCamerasWithoutMatrices) {
  Camera camera;
  camera.projection = Equirectangular{};
  Film film(8, 8);
  EXPECT_THROW(accumulate(
                   camera, {}, [](const FrameParameters&, RenderTarget&) {}, film),
               Error);
}

}  // namespace
}  // namespace obscura::raster
