#include "obscura/io/dng_file.h"

#include <algorithm>
#include <cmath>

#include "obscura/io/atomic_file.h"
#include "obscura/io/image_codecs_loader.h"
#include "obscura/math/error.h"
#include "obscura/math/number_text.h"

namespace obscura {

namespace {

std::string beside(const std::string& path, const std::string& name) {
  return path.substr(0, path.find_last_of('.')) + "." + name + ".exr";
}

std::vector<float> matrix_values(const Matrix3d& m) {
  std::vector<float> values;
  for (const auto& row : m.m)
    for (double v : row) values.push_back(float(v));
  return values;
}

// EXIF LightSource codes for CalibrationIlluminant (DNG 1.4, table "CalibrationIlluminant").
constexpr int kD65 = 21, kStandardA = 17;

}  // namespace

std::vector<std::string> sensor_ground_truth_paths(const std::string& dng_path) {
  return {beside(dng_path, "raw"), beside(dng_path, "irradiance"), beside(dng_path, "electrons")};
}

double dng_baseline_exposure(const RawCapture& capture) {
  const double film_one = capture.gain_dn_per_e * capture.electrons_per_film;
  return std::log2((capture.white_level - capture.black_level) / film_one);
}

std::vector<std::string> write_dng(const std::string& path, const RawCapture& capture,
                                   const DngWriteOptions& options) {
  if (image_format_for_path(path) != ImageFormat::kDng)
    throw Error(path, "a DNG's name must end in .dng");
  check_output_path(path);
  std::vector<std::string> paths = {path};
  if (options.ground_truth)
    for (const std::string& p : sensor_ground_truth_paths(path)) {
      check_output_path(p);
      paths.push_back(p);
    }

  EncodeRequest request;
  request.path = path;
  request.width = capture.width;
  request.height = capture.height;
  request.stored = SampleType::kUint16;
  request.data_type = SampleType::kUint16;
  std::vector<uint16_t> linear;
  const bool mono = capture.cfa == CfaPattern::kMonochrome;
  if (mono) {
    // One colour plane (LinearRaw, one sample): already "demosaiced".
    request.channels = 1;
    request.data = capture.raw.data();
  } else if (options.linear) {
    // Demosaiced in DN (black level kept, so the tags stay true), clamped to the ADC's range.
    Image mosaic = raw_image(capture);
    Image rgb = demosaic(mosaic, capture.cfa, options.demosaic);
    linear.resize(rgb.data.size());
    for (size_t i = 0; i < linear.size(); ++i)
      linear[i] = uint16_t(std::clamp(std::round(double(rgb.data[i])), 0.0, 65535.0));
    request.channels = 3;
    request.data = linear.data();
  } else {
    request.channels = 1;
    request.data = capture.raw.data();
    request.attributes.push_back({"CFAPattern", std::string(cfa_pattern_name(capture.cfa))});
  }
  request.attributes.push_back({"Make", std::string("Obscura")});
  request.attributes.push_back({"Model", options.model});
  request.attributes.push_back({"UniqueCameraModel", "Obscura " + options.model});
  request.attributes.push_back({"Software", std::string("Obscura " OBSCURA_VERSION)});
  if (!options.metadata.description.empty())
    request.attributes.push_back({"ImageDescription", options.metadata.description});
  request.attributes.push_back({"BlackLevel", std::vector<float>{float(capture.black_level)}});
  request.attributes.push_back({"WhiteLevel", int(capture.white_level)});
  // A monochrome sensor has one colour plane: a 1 × 3 matrix (its rows are equal) and one
  // neutral value.
  const size_t planes = mono ? 1 : 3;
  std::vector<float> matrix1 = matrix_values(capture.response.color_matrix_d65);
  std::vector<float> matrix2 = matrix_values(capture.response.color_matrix_a);
  matrix1.resize(3 * planes);
  matrix2.resize(3 * planes);
  request.attributes.push_back({"ColorMatrix1", matrix1});
  request.attributes.push_back({"CalibrationIlluminant1", kD65});
  request.attributes.push_back({"ColorMatrix2", matrix2});
  request.attributes.push_back({"CalibrationIlluminant2", kStandardA});
  const Vec3d& n = capture.response.neutral_d65;
  std::vector<float> neutral = {float(n[0]), float(n[1]), float(n[2])};
  neutral.resize(planes);
  request.attributes.push_back({"AsShotNeutral", neutral});
  request.attributes.push_back(
      {"BaselineExposure", std::vector<float>{float(dng_baseline_exposure(capture))}});
  const std::vector<unsigned char> bytes = image_codecs().encode(request);

  OutputTransaction transaction;
  write_file_atomically(path, bytes);
  if (options.ground_truth) {
    ImageMetadata metadata = options.metadata;
    metadata.attributes.emplace_back("obscura:sensor_black_level",
                                     number_text(capture.black_level));
    metadata.attributes.emplace_back("obscura:sensor_gain_dn_per_e",
                                     number_text(capture.gain_dn_per_e));
    write_exr_data(paths[1], raw_image(capture), metadata);
    write_exr_data(paths[2], capture.irradiance_lux, metadata);
    write_exr_data(paths[3], capture.electrons, metadata);
  }
  transaction.commit();
  return paths;
}

}  // namespace obscura
