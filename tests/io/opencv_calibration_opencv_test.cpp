// OpenCV calibration files against cv::FileStorage itself: what OpenCV writes (YAML and JSON) we
// read, and what we write OpenCV reads, with the same numbers.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include <filesystem>

#include "obscura/io/calibration_file.h"
#include "obscura/io/lens_model_coefficients.h"
#include "obscura/io/opencv_calibration.h"
#include "run_command.h"

namespace obscura {
namespace {

using OpenCvFiles = test::TempDirTest;

const cv::Matx33d kK(812.5, 0.75, 320.25, 0, 798.125, 241.5, 0, 0, 1);

void write_with_opencv(const std::string& path, const cv::Mat& distortion, bool fisheye_flag) {
  cv::FileStorage fs(path, cv::FileStorage::WRITE);
  ASSERT_TRUE(fs.isOpened());
  fs << "image_width" << 640 << "image_height" << 480;
  fs << "camera_matrix" << cv::Mat(kK);
  fs << "distortion_coefficients" << distortion;
  if (fisheye_flag) fs << "fisheye" << 1;
  cv::Mat r = (cv::Mat_<double>(3, 3) << 0, 0, 1, 0, 1, 0, -1, 0, 0);
  fs << "R" << r << "T" << (cv::Mat_<double>(3, 1) << 0.5, -0.25, 2);
  fs.release();
}

TEST_F(OpenCvFiles, WeReadWhatFileStorageWrites) {
  for (const char* extension : {".yaml", ".json"}) {
    cv::Mat d =
        (cv::Mat_<double>(1, 8) << -0.27, 0.09, 0.0011, -0.0006, -0.013, 0.02, 0.004, -0.001);
    std::string path = this->path(std::string("opencv") + extension);
    write_with_opencv(path, d, false);
    CameraCalibration c = read_calibration_file(path, "");
    const CalibratedProjection& p = c.projection;
    EXPECT_EQ(p.width_px, 640);
    EXPECT_EQ(p.height_px, 480);
    EXPECT_EQ(p.k.fx, 812.5) << extension;
    EXPECT_EQ(p.k.skew, 0.75);
    EXPECT_EQ(p.k.cx, 320.25);
    EXPECT_EQ(p.k.fy, 798.125);
    EXPECT_EQ(p.k.cy, 241.5);
    std::vector<double> expected(d.begin<double>(), d.end<double>());
    EXPECT_EQ(lens_model_coefficients(p.lens), expected) << extension;
    ASSERT_TRUE(c.world_from_camera);
    CvExtrinsics e = cv_extrinsics(*c.world_from_camera);
    EXPECT_NEAR(e.r[0][2], 1, 1e-15);
    EXPECT_NEAR(e.r[2][0], -1, 1e-15);
    EXPECT_NEAR(e.t[2], 2, 1e-15);
    // A fisheye file: four coefficients and the flag.
    write_with_opencv(path, (cv::Mat_<double>(4, 1) << 0.03, -0.004, 0.001, -0.0002), true);
    CameraCalibration f = read_calibration_file(path, "");
    ASSERT_TRUE(std::holds_alternative<KannalaBrandt>(f.projection.lens)) << extension;
    EXPECT_EQ(std::get<KannalaBrandt>(f.projection.lens).k2, -0.004);
  }
}

TEST_F(OpenCvFiles, FileStorageReadsWhatWeWrite) {
  CameraCalibration c;
  c.projection.k = {.fx = 700.125, .fy = 690.5, .cx = 300.75, .cy = 200.25, .skew = 0.5};
  c.projection.width_px = 600;
  c.projection.height_px = 400;
  c.projection.lens = lens_model_from_coefficients("opencv", {-0.1, 0.02, 0.001, 0.002, 0.003});
  c.world_from_camera = Transform::translate({1, 2, 3}) * Transform::rotate_y(0.3);
  for (CalibrationFormat format :
       {CalibrationFormat::opencv_yaml, CalibrationFormat::opencv_json}) {
    std::string text = calibration_text(format, c);
    cv::FileStorage fs(text, cv::FileStorage::READ | cv::FileStorage::MEMORY);
    ASSERT_TRUE(fs.isOpened()) << text;
    cv::Mat k, d, r, t;
    int width = 0, height = 0;
    fs["camera_matrix"] >> k;
    fs["distortion_coefficients"] >> d;
    fs["image_width"] >> width;
    fs["image_height"] >> height;
    fs["R"] >> r;
    fs["T"] >> t;
    EXPECT_EQ(width, 600);
    EXPECT_EQ(height, 400);
    ASSERT_EQ(k.rows, 3);
    EXPECT_EQ(k.at<double>(0, 0), 700.125);
    EXPECT_EQ(k.at<double>(0, 1), 0.5);
    EXPECT_EQ(k.at<double>(0, 2), 300.75);
    EXPECT_EQ(k.at<double>(1, 1), 690.5);
    EXPECT_EQ(k.at<double>(1, 2), 200.25);
    ASSERT_EQ(d.total(), 5u);
    EXPECT_EQ(d.at<double>(0, 4), 0.003);
    CvExtrinsics e = cv_extrinsics(*c.world_from_camera);
    ASSERT_EQ(r.rows, 3);
    ASSERT_EQ(t.total(), 3u);
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(t.at<double>(i), e.t[size_t(i)]);
      for (int j = 0; j < 3; ++j) EXPECT_EQ(r.at<double>(i, j), e.r[size_t(i)][size_t(j)]);
    }
    std::string model;
    fs["distortion_model"] >> model;
    EXPECT_EQ(model, "opencv");
  }
}

}  // namespace
}  // namespace obscura
