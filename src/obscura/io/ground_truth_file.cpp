#include "obscura/io/ground_truth_file.h"

#include <cstdio>
#include <variant>

#include "obscura/camera/intrinsics.h"
#include "obscura/io/lens_model_coefficients.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

// Round-trip precision: a reader parsing the text gets the very double back.
std::string exact(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

std::string joined(std::initializer_list<double> values) {
  std::string s;
  for (double v : values) {
    if (!s.empty()) s += ' ';
    s += exact(v);
  }
  return s;
}

std::string matrix_text(const Matrix4& m) {
  std::string s;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      if (!s.empty()) s += ' ';
      s += exact(m.m[r][c]);
    }
  return s;
}

// "name key=value …": what the projection needs besides the film geometry. Projections this
// file does not know yet give their name alone.
std::string projection_text(const Camera& camera) {
  std::string text(projection_name(camera.projection));
  const std::string parameters = std::visit(
      Overloaded{[](const Perspective& p) {
                   return "focal_length_mm=" + exact(p.focal_length_mm) +
                          " sensor_width_mm=" + exact(p.sensor_width_mm) +
                          " sensor_height_mm=" + exact(p.sensor_height_mm) +
                          " lens_shift=" + exact(p.lens_shift.x) + "," + exact(p.lens_shift.y);
                 },
                 [](const Orthographic& o) {
                   return "view_height_m=" + exact(o.view_height_m) +
                          (o.view_width_m ? " view_width_m=" + exact(*o.view_width_m) : "");
                 },
                 [](const Fisheye& f) { return "fov_degrees=" + exact(f.fov_degrees); },
                 [](const CalibratedProjection& c) {
                   // K at the calibration's size, the lens model and its coefficients in the
                   // order the CLI and OpenCV use, the field limit.
                   std::string coefficients;
                   for (double v : lens_model_coefficients(c.lens)) {
                     if (!coefficients.empty()) coefficients += ',';
                     coefficients += exact(v);
                   }
                   return "fx=" + exact(c.k.fx) + " fy=" + exact(c.k.fy) + " cx=" + exact(c.k.cx) +
                          " cy=" + exact(c.k.cy) + " skew=" + exact(c.k.skew) +
                          " calibration_size=" + std::to_string(c.width_px) + "x" +
                          std::to_string(c.height_px) + " lens=" + lens_model_name(c.lens) +
                          (coefficients.empty() ? "" : " coefficients=" + coefficients) +
                          " max_field_angle_degrees=" + exact(c.max_field_angle_degrees);
                 },
                 [](const auto&) { return std::string(); }},
      camera.projection);
  if (!parameters.empty()) text += " " + parameters;
  if (camera.lens_radius_m() > 0)
    text += " image_distance_mm=" + exact(camera.image_distance_mm());  // focused, not at ∞
  return text;
}

}  // namespace

ImageMetadata ground_truth_metadata(const Camera& camera, const GroundTruthTimes& times) {
  ImageMetadata m;
  m.description = "Obscura ground truth (docs/ground_truth.md)";
  auto add = [&](const std::string& key, const std::string& value) {
    m.attributes.emplace_back("obscura:" + key, value);
  };
  const Bounds2i crop = camera.film.crop_pixels();
  add("camera:projection", projection_text(camera));
  add("camera:resolution",
      std::to_string(camera.film.width_px) + " " + std::to_string(camera.film.height_px));
  add("camera:pixel_aspect", exact(camera.film.pixel_aspect));
  add("camera:crop", std::to_string(crop.min.x) + " " + std::to_string(crop.min.y) + " " +
                         std::to_string(crop.max.x) + " " + std::to_string(crop.max.y));
  try {
    const Intrinsics k = intrinsics(camera);
    add("camera:K", joined({k.fx, k.fy, k.cx, k.cy}));
    if (k.skew != 0) add("camera:skew", exact(k.skew));
  } catch (const Error&) {
    // No pinhole intrinsics for this projection: the key is left out.
  }
  const Vector2d fov = camera.fov_degrees();
  add("camera:fov_degrees", joined({fov.x, fov.y}));
  add("camera:near_far", joined({camera.near_m, camera.far_m}));
  if (camera.has_projection_matrix())
    add("camera:clip_from_camera", matrix_text(camera.projection_matrix()));
  add("camera:world_from_camera", matrix_text(camera.world_from_camera.at(times.first_s).matrix()));
  add("camera:axes",
      "world: right-handed, Y up, metres; camera: X right, Y up, looking down -Z (OpenGL; "
      "OpenCV's frame is this with Y and Z negated); matrices row-major, acting on column "
      "vectors; pixels: (0,0) the top-left corner, x right, y down");
  add("camera:shutter", joined({camera.shutter.open_s, camera.shutter.close_s}));
  if (camera.shutter.line_time_s > 0)
    add("camera:rolling_shutter",
        exact(camera.shutter.line_time_s) + " " + readout_name(camera.shutter.readout));
  add("ground_truth:times", joined({times.first_s, times.second_s}));
  return m;
}

void write_ground_truth(const std::string& path, const GroundTruthBuffer& buffer,
                        const Camera& camera, const GroundTruthTimes& times) {
  write_exr_data(path, buffer.image(), ground_truth_metadata(camera, times));
}

}  // namespace obscura
