// The ground-truth file read back with OpenImageIO: its channel names, values as written (NaN and
// ±∞ included) and the camera in its header, against the analytic camera of the test scene.
#include "obscura/io/ground_truth_file.h"

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <set>
#include <sstream>
#include <vector>

#include "ground_truth_test_scene.h"
#include "obscura/math/error.h"
#include "run_command.h"

namespace obscura {
namespace {

using S = testing::GroundTruthScene;

std::vector<double> numbers(const std::string& text) {
  std::istringstream in(text);
  std::vector<double> v;
  for (double x; in >> x;) v.push_back(x);
  return v;
}

class GroundTruthFile : public test::TempDirTest {};

TEST_F(GroundTruthFile, ChannelsAndCameraReadBackWithOpenImageIO) {
  const Scene scene = testing::ground_truth_scene(true);
  GroundTruthBuffer buffer(S::kWidth, S::kHeight);
  buffer.set_surface(3, 2,
                     {.z_m = 5,
                      .range_m = 6,
                      .position = {1, 2, -5},
                      .shading_normal = {0, 0, 1},
                      .geometric_normal = {0, 1, 0},
                      .instance = 7,
                      .material = 4});
  buffer.set_forward_flow(3, 2, Vector2d(1.25, -2.5));
  buffer.set_time(3, 2, 0.01);
  // The reference time is the shutter's close: the pose written is the moved camera's.
  const std::string file = path("truth.exr");
  write_ground_truth(file, buffer, scene.camera, {S::kClose, S::kOpen});

  auto in = OIIO::ImageInput::open(file);
  ASSERT_TRUE(in);
  const OIIO::ImageSpec& spec = in->spec();
  EXPECT_EQ(spec.width, S::kWidth);
  EXPECT_EQ(spec.height, S::kHeight);
  const std::set<std::string> names(spec.channelnames.begin(), spec.channelnames.end());
  const std::set<std::string> expected = {"Z",
                                          "range",
                                          "P.X",
                                          "P.Y",
                                          "P.Z",
                                          "N.X",
                                          "N.Y",
                                          "N.Z",
                                          "Ng.X",
                                          "Ng.Y",
                                          "Ng.Z",
                                          "instance",
                                          "material",
                                          "flow.forward.X",
                                          "flow.forward.Y",
                                          "flow.backward.X",
                                          "flow.backward.Y",
                                          "time"};
  EXPECT_EQ(names, expected);
  std::vector<float> pixels(size_t(spec.width) * spec.height * spec.nchannels);
  ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
  auto value = [&](int x, int y, const std::string& name) {
    const int c = spec.channelindex(name);
    EXPECT_GE(c, 0) << name;
    return pixels[(size_t(y) * spec.width + x) * spec.nchannels + c];
  };
  EXPECT_EQ(value(3, 2, "Z"), 5.f);
  EXPECT_EQ(value(3, 2, "range"), 6.f);
  EXPECT_EQ(value(3, 2, "P.Y"), 2.f);
  EXPECT_EQ(value(3, 2, "Ng.Y"), 1.f);
  EXPECT_EQ(value(3, 2, "instance"), 7.f);
  EXPECT_EQ(value(3, 2, "material"), 4.f);
  EXPECT_EQ(value(3, 2, "flow.forward.X"), 1.25f);
  EXPECT_EQ(value(3, 2, "flow.forward.Y"), -2.5f);
  EXPECT_TRUE(std::isnan(value(3, 2, "flow.backward.X")));
  EXPECT_EQ(value(3, 2, "time"), 0.01f);
  // A miss, as written.
  EXPECT_TRUE(std::isinf(value(0, 0, "Z")));
  EXPECT_TRUE(std::isnan(value(0, 0, "P.X")));
  EXPECT_EQ(value(0, 0, "instance"), -1.f);

  // K in OpenCV's convention (integer pixel centres): the raster principal point minus ½.
  const std::vector<double> k = numbers(spec.get_string_attribute("obscura:camera:K"));
  ASSERT_EQ(k.size(), 4u);
  EXPECT_NEAR(k[0], S::fx(), 1e-9);
  EXPECT_NEAR(k[1], S::fx(), 1e-9);
  EXPECT_NEAR(k[2], S::cx() - 0.5, 1e-9);
  EXPECT_NEAR(k[3], S::cy() - 0.5, 1e-9);
  EXPECT_EQ(numbers(spec.get_string_attribute("obscura:camera:resolution")),
            (std::vector<double>{S::kWidth, S::kHeight}));
  EXPECT_EQ(numbers(spec.get_string_attribute("obscura:camera:crop")),
            (std::vector<double>{0, 0, S::kWidth, S::kHeight}));
  const std::string projection = spec.get_string_attribute("obscura:camera:projection");
  EXPECT_EQ(projection.rfind("perspective ", 0), 0u) << projection;
  EXPECT_NE(projection.find("lens_shift=0.1"), std::string::npos);
  EXPECT_EQ(numbers(spec.get_string_attribute("obscura:ground_truth:times")),
            (std::vector<double>{S::kClose, S::kOpen}));
  EXPECT_NE(spec.get_string_attribute("obscura:camera:axes").find("looking down -Z"),
            std::string::npos);
  // The pose at close, row-major: translation (0.2, 0.1, 0.3), a 3° turn about +Y.
  const std::vector<double> m =
      numbers(spec.get_string_attribute("obscura:camera:world_from_camera"));
  ASSERT_EQ(m.size(), 16u);
  const double a = S::kTurnDegrees * std::numbers::pi / 180;
  const std::vector<double> expected_pose = {
      std::cos(a),  0, std::sin(a), S::kMoveX, 0, 1, 0, S::kMoveY,
      -std::sin(a), 0, std::cos(a), S::kMoveZ, 0, 0, 0, 1};
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(m[i], expected_pose[i], 1e-12) << i;
}

TEST_F(GroundTruthFile, RefusesAnythingButExr) {
  const Scene scene = testing::ground_truth_scene(false);
  GroundTruthBuffer buffer(4, 4);
  EXPECT_THROW(write_ground_truth(path("truth.png"), buffer, scene.camera, {}), Error);
  EXPECT_FALSE(std::filesystem::exists(path("truth.png")));
}

TEST_F(GroundTruthFile, KIsLeftOutWithoutPinholeIntrinsics) {
  Camera camera;
  camera.projection = Fisheye{.fov_degrees = 180};
  const ImageMetadata m = ground_truth_metadata(camera, {});
  for (const auto& [key, value] : m.attributes) EXPECT_NE(key, "obscura:camera:K");
  bool projection = false;
  for (const auto& [key, value] : m.attributes)
    if (key == "obscura:camera:projection") projection = value == "fisheye fov_degrees=180";
  EXPECT_TRUE(projection);
}

}  // namespace
}  // namespace obscura
