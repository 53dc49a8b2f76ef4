#include "camera_export.h"

#include <cstdio>
#include <filesystem>

#include "obscura/io/atomic_file.h"
#include "obscura/io/calibration_file.h"
#include "obscura/io/colmap_model.h"
#include "obscura/math/error.h"
#include "usage_error.h"

namespace obscura::app {

namespace {

void write_text(const std::string& path, const std::string& text) {
  AtomicFile file(path);
  file.write(text);
  file.commit();
}

}  // namespace

void export_calibration(const Camera& camera, const std::string& format_name,
                        const std::optional<std::string>& output) {
  std::optional<CalibrationFormat> format = calibration_format_from_name(format_name);
  if (!format)
    throw UsageError("--export expects opencv-yaml, opencv-json, colmap or nerf; got '" +
                     format_name + "'");
  if (*format == CalibrationFormat::colmap && !output)
    throw UsageError("--export colmap writes cameras.txt and images.txt: give --output FOLDER");
  CameraCalibration calibration;
  try {
    calibration = calibration_of(camera);
  } catch (const Error& e) {
    throw Error("--export " + format_name, e.what());
  }
  for (const std::string& omission : calibration_omissions(*format, calibration))
    std::fprintf(stderr, "warning: %s\n", omission.c_str());
  if (*format == CalibrationFormat::colmap) {
    ColmapModelText model;
    try {
      model = colmap_model_text(calibration);
    } catch (const Error& e) {
      throw Error("--export colmap", e.what());
    }
    namespace fs = std::filesystem;
    std::error_code error;
    fs::create_directories(*output, error);
    if (!fs::is_directory(*output))
      throw Error(*output, "--output for --export colmap must be a folder (" +
                               (error ? error.message() : std::string("not a directory")) + ")");
    fs::path dir(*output);
    write_text((dir / "cameras.txt").string(), model.cameras);
    write_text((dir / "images.txt").string(), model.images);
    write_text((dir / "points3D.txt").string(),
               "# 3D point list with one line of data per point:\n"
               "#   POINT3D_ID, X, Y, Z, R, G, B, ERROR, TRACK[] as (IMAGE_ID, POINT2D_IDX)\n"
               "# Number of points: 0, mean track length: 0\n");
    return;
  }
  std::string text;
  try {
    text = calibration_text(*format, calibration);
  } catch (const Error& e) {
    throw Error("--export " + format_name, e.what());
  }
  if (output)
    write_text(*output, text);
  else
    std::fwrite(text.data(), 1, text.size(), stdout);
}

}  // namespace obscura::app
