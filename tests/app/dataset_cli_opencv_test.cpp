// `obscura dataset` against OpenCV: every ground-truth position of every view reprojects through
// the poses and intrinsics of the exported COLMAP model (cv::projectPoints) onto its own pixel
// centre, and the flow between consecutive views is that reprojection into the neighbour.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <opencv2/calib3d.hpp>

#include "obscura/io/image_io.h"
#include "run_command.h"

namespace obscura {
namespace {

using DatasetOpenCv = test::TempDirTest;

struct View {
  cv::Mat rvec, tvec;
};

// COLMAP's text model as written: one PINHOLE camera, images in order.
void read_model(const std::string& folder, cv::Mat& k, std::vector<View>& views) {
  std::ifstream cameras(folder + "/cameras.txt");
  std::string line;
  while (std::getline(cameras, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream in(line);
    int id, w, h;
    std::string model;
    double fx, fy, cx, cy;
    in >> id >> model >> w >> h >> fx >> fy >> cx >> cy;
    ASSERT_EQ(model, "PINHOLE");
    // COLMAP's principal point is OpenCV's + 0.5.
    k = (cv::Mat_<double>(3, 3) << fx, 0, cx - 0.5, 0, fy, cy - 0.5, 0, 0, 1);
  }
  std::ifstream images(folder + "/images.txt");
  while (std::getline(images, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream in(line);
    int id;
    double qw, qx, qy, qz, tx, ty, tz;
    in >> id >> qw >> qx >> qy >> qz >> tx >> ty >> tz;
    cv::Mat r = (cv::Mat_<double>(3, 3) << 1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw),
                 2 * (qx * qz + qy * qw), 2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz),
                 2 * (qy * qz - qx * qw), 2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw),
                 1 - 2 * (qx * qx + qy * qy));
    View v;
    cv::Rodrigues(r, v.rvec);
    v.tvec = (cv::Mat_<double>(3, 1) << tx, ty, tz);
    views.push_back(v);
    std::getline(images, line);  // the image's (empty) 2D points
  }
}

float channel(const Image& image, const std::string& name, int x, int y) {
  for (int c = 0; c < image.channels; ++c)
    if (image.channel_names[size_t(c)] == name) return image.at(x, y, c);
  ADD_FAILURE() << "no channel " << name;
  return NAN;
}

TEST_F(DatasetOpenCv, PositionsReprojectAndFlowIsTheReprojection) {
  const std::string out = path("set");
  auto result = test::run_cli(
      "dataset -q --views orbit:6 --width 64 --height 48 --spp 1 "
      "--ground-truth --formats colmap -o " +
      out);
  ASSERT_EQ(result.exit_code, 0) << result.output;
  cv::Mat k;
  std::vector<View> views;
  read_model(out + "/sparse/0", k, views);
  ASSERT_EQ(views.size(), 6u);
  const cv::Mat no_distortion = cv::Mat::zeros(1, 4, CV_64F);
  double worst_position = 0, worst_flow = 0;
  int positions = 0, flows = 0;
  for (size_t i = 0; i < views.size(); ++i) {
    char name[64];
    std::snprintf(name, sizeof name, "/ground_truth/view_%04zu.exr", i);
    ImageMetadata metadata;
    const Image gt = read_exr_data(out + name, metadata);
    std::vector<cv::Point3d> points;
    std::vector<cv::Point2d> pixels;
    for (int y = 0; y < gt.height; ++y)
      for (int x = 0; x < gt.width; ++x) {
        const float px = channel(gt, "P.X", x, y);
        if (!std::isfinite(px)) continue;
        points.emplace_back(px, channel(gt, "P.Y", x, y), channel(gt, "P.Z", x, y));
        pixels.emplace_back(x, y);
      }
    ASSERT_GT(points.size(), size_t(64 * 48 / 4)) << name;
    std::vector<cv::Point2d> own;
    cv::projectPoints(points, views[i].rvec, views[i].tvec, k, no_distortion, own);
    for (size_t j = 0; j < points.size(); ++j, ++positions)
      worst_position = std::max(worst_position, cv::norm(own[j] - pixels[j]));
    for (int step : {+1, -1}) {
      const long other = long(i) + step;
      if (other < 0 || other >= long(views.size())) continue;
      std::vector<cv::Point2d> there;
      cv::projectPoints(points, views[size_t(other)].rvec, views[size_t(other)].tvec, k,
                        no_distortion, there);
      const std::string prefix = step > 0 ? "flow.forward." : "flow.backward.";
      for (size_t j = 0; j < points.size(); ++j) {
        const int x = int(pixels[j].x), y = int(pixels[j].y);
        const float fx = channel(gt, prefix + "X", x, y), fy = channel(gt, prefix + "Y", x, y);
        const cv::Point2d expected = there[j] - pixels[j];
        const bool on_film =
            there[j].x > -0.5 && there[j].x < 63.5 && there[j].y > -0.5 && there[j].y < 47.5;
        if (!std::isfinite(fx)) {
          // Undefined only where the point leaves the neighbour's film.
          EXPECT_FALSE(on_film && there[j].x > -0.49 && there[j].x < 63.49 && there[j].y > -0.49 &&
                       there[j].y < 47.49)
              << name << " " << prefix << " at " << x << "," << y;
          continue;
        }
        ++flows;
        worst_flow = std::max(worst_flow, cv::norm(cv::Point2d(fx, fy) - expected));
      }
    }
  }
  std::printf("%d positions reproject within %.3g px; %d flow vectors within %.3g px\n", positions,
              worst_position, flows, worst_flow);
  EXPECT_LT(worst_position, 1e-4);
  EXPECT_GT(flows, positions / 2);
  EXPECT_LT(worst_flow, 1e-4);
}

}  // namespace
}  // namespace obscura
