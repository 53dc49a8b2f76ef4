#include "obscura/io/opencv_calibration_entries.h"

#include <cmath>
#include <initializer_list>

#include "obscura/io/lens_model_coefficients.h"
#include "obscura/math/error.h"
#include "obscura/math/number_text.h"

namespace obscura {

namespace {

// The first of `names` the file has; null when none.
const OpenCvEntry* find(const OpenCvEntries& entries, std::initializer_list<const char*> names,
                        std::string* found_name = nullptr) {
  for (const char* name : names) {
    auto it = entries.find(name);
    if (it != entries.end()) {
      if (found_name) *found_name = name;
      return &it->second;
    }
  }
  return nullptr;
}

const OpenCvEntry& matrix(const OpenCvEntry& e, const std::string& name, int rows, int cols) {
  if (e.kind != OpenCvEntry::Kind::matrix)
    throw Error(e.where, name + ": expected a " + std::to_string(rows) + "x" +
                             std::to_string(cols) + " !!opencv-matrix");
  bool shape_ok = rows * cols == int(e.values.size()) &&
                  ((e.rows == rows && e.cols == cols) || (cols == 1 && e.rows * e.cols == rows));
  if (!shape_ok)
    throw Error(e.where, name + ": expected a " + std::to_string(rows) + "x" +
                             std::to_string(cols) + " matrix; got " + std::to_string(e.rows) + "x" +
                             std::to_string(e.cols));
  for (double v : e.values)
    if (!std::isfinite(v)) throw Error(e.where, name + ": expected finite numbers");
  return e;
}

int image_side(const OpenCvEntries& entries, const char* name, const std::string& file) {
  auto it = entries.find(name);
  if (it == entries.end()) throw Error(file, std::string("missing ") + name + " (pixels)");
  const OpenCvEntry& e = it->second;
  double v = e.kind == OpenCvEntry::Kind::number ? e.values[0] : -1;
  if (!(v >= 1 && v <= 65536 && v == std::floor(v)))
    throw Error(e.where, std::string(name) + ": expected a whole number of pixels from 1 to 65536");
  return int(v);
}

// Whether the file describes cv::fisheye's model (the rule in opencv_calibration.h).
bool is_fisheye(const OpenCvEntries& entries, const std::string& distortion_key,
                size_t coefficient_count) {
  if (const OpenCvEntry* m = find(entries, {"distortion_model"})) {
    if (m->kind != OpenCvEntry::Kind::text)
      throw Error(m->where, "distortion_model: expected a name (opencv or fisheye)");
    if (m->text == "fisheye" || m->text == "kannala-brandt" || m->text == "equidistant")
      return true;
    if (m->text == "opencv" || m->text == "plumb_bob" || m->text == "rational_polynomial")
      return false;
    throw Error(m->where,
                "distortion_model: expected opencv, plumb_bob, rational_polynomial, "
                "fisheye, kannala-brandt or equidistant; got '" +
                    m->text + "'");
  }
  if (const OpenCvEntry* f = find(entries, {"fisheye"})) {
    if (f->kind == OpenCvEntry::Kind::number && (f->values[0] == 0 || f->values[0] == 1))
      return f->values[0] == 1;
    if (f->kind == OpenCvEntry::Kind::text && (f->text == "true" || f->text == "false"))
      return f->text == "true";
    throw Error(f->where, "fisheye: expected 0, 1, true or false");
  }
  return distortion_key == "D" && coefficient_count == 4;
}

std::array<std::array<double, 3>, 3> rodrigues(const OpenCvEntry& e) {
  double x = e.values[0], y = e.values[1], z = e.values[2];
  double angle = std::sqrt(x * x + y * y + z * z);
  std::array<std::array<double, 3>, 3> r{};
  if (angle == 0) {
    for (int i = 0; i < 3; ++i) r[i][i] = 1;
    return r;
  }
  double k[3] = {x / angle, y / angle, z / angle};
  double c = std::cos(angle), s = std::sin(angle);
  double cross[3][3] = {{0, -k[2], k[1]}, {k[2], 0, -k[0]}, {-k[1], k[0], 0}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      r[i][j] = (i == j ? c : 0) + (1 - c) * k[i] * k[j] + s * cross[i][j];
  return r;
}

std::optional<Transform> pose(const OpenCvEntries& entries, const std::string& file) {
  const OpenCvEntry* r = find(entries, {"R"});
  const OpenCvEntry* rvec = find(entries, {"rvec"});
  const OpenCvEntry* t = find(entries, {"T", "t", "tvec"});
  if (!r && !rvec && !t) return std::nullopt;
  if (!t) throw Error(file, "a rotation (R or rvec) without a translation (T, t or tvec)");
  if (!r && !rvec) throw Error(t->where, "a translation without a rotation (R or rvec)");
  CvExtrinsics e;
  if (r) {
    matrix(*r, "R", 3, 3);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) e.r[i][j] = r->values[3 * i + j];
  } else {
    e.r = rodrigues(matrix(*rvec, "rvec", 3, 1));
  }
  matrix(*t, "T", 3, 1);
  for (int i = 0; i < 3; ++i) e.t[i] = t->values[i];
  return world_from_camera_of(e, (r ? r : rvec)->where);
}

}  // namespace

OpenCvEntry number_entry(double value, std::string where) {
  OpenCvEntry e;
  e.kind = OpenCvEntry::Kind::number;
  e.values = {value};
  e.rows = e.cols = 1;
  e.where = std::move(where);
  return e;
}

OpenCvEntry text_entry(std::string text, std::string where) {
  OpenCvEntry e;
  e.kind = OpenCvEntry::Kind::text;
  e.text = std::move(text);
  e.where = std::move(where);
  return e;
}

OpenCvEntry matrix_entry(std::vector<double> values, int rows, int cols, std::string where) {
  OpenCvEntry e;
  e.kind = OpenCvEntry::Kind::matrix;
  e.values = std::move(values);
  e.rows = rows;
  e.cols = cols;
  e.where = std::move(where);
  return e;
}

OpenCvEntry other_entry(std::string where) {
  OpenCvEntry e;
  e.where = std::move(where);
  return e;
}

CameraCalibration calibration_from_opencv_entries(const OpenCvEntries& entries,
                                                  const std::string& file) {
  CameraCalibration c;
  const OpenCvEntry* k = find(entries, {"camera_matrix", "cameraMatrix", "K"});
  if (!k) throw Error(file, "missing the camera matrix (camera_matrix, cameraMatrix or K)");
  matrix(*k, "camera_matrix", 3, 3);
  const std::vector<double>& m = k->values;
  if (m[3] != 0 || m[6] != 0 || m[7] != 0 || m[8] != 1)
    throw Error(k->where, "camera_matrix: expected [fx skew cx; 0 fy cy; 0 0 1]");
  c.projection.k = {.fx = m[0], .fy = m[4], .cx = m[2], .cy = m[5], .skew = m[1]};
  std::string distortion_key;
  const OpenCvEntry* d =
      find(entries, {"distortion_coefficients", "distCoeffs", "dist_coeffs", "D"}, &distortion_key);
  std::vector<double> coefficients;
  if (d) {
    if (d->kind != OpenCvEntry::Kind::matrix || (d->rows != 1 && d->cols != 1))
      throw Error(d->where, distortion_key + ": expected a 1xN or Nx1 matrix of coefficients");
    coefficients = d->values;
  }
  bool fisheye = is_fisheye(entries, distortion_key, coefficients.size());
  if (!d) coefficients.assign(fisheye ? 4 : 5, 0.0);
  try {
    c.projection.lens =
        lens_model_from_coefficients(fisheye ? "kannala-brandt" : "opencv", coefficients);
  } catch (const Error& e) {
    throw Error(d->where, distortion_key + ": " + e.what());
  }
  c.projection.width_px = image_side(entries, "image_width", file);
  c.projection.height_px = image_side(entries, "image_height", file);
  if (const OpenCvEntry* a = find(entries, {"max_field_angle_degrees"})) {
    if (a->kind != OpenCvEntry::Kind::number)
      throw Error(a->where, "max_field_angle_degrees: expected a number in (0, 180]");
    c.projection.max_field_angle_degrees = a->values[0];
  }
  c.world_from_camera = pose(entries, file);
  validate_calibration(c, file);
  return c;
}

std::vector<OpenCvOutput> opencv_entries_of(const CameraCalibration& c) {
  const CalibratedProjection& p = c.projection;
  std::string model;
  std::vector<double> coefficients;
  if (std::holds_alternative<PinholeDistortion>(p.lens)) {
    model = "opencv";
    coefficients = lens_model_coefficients(p.lens);
  } else if (std::holds_alternative<KannalaBrandt>(p.lens)) {
    model = "fisheye";
    coefficients = lens_model_coefficients(p.lens);
  } else if (auto* f = std::get_if<ClassicFisheye>(&p.lens);
             f && f->mapping == FisheyeMapping::equidistant) {
    model = "fisheye";  // θd = θ: Kannala–Brandt with every k zero
    coefficients = {0, 0, 0, 0};
  } else {
    throw Error("OpenCV calibration file",
                std::string("OpenCV has no ") + lens_model_name(p.lens) +
                    " lens model (only its pinhole model and cv::fisheye's Kannala–Brandt)");
  }
  const Intrinsics& k = p.k;
  std::vector<OpenCvOutput> out;
  out.push_back({"image_width", number_entry(p.width_px)});
  out.push_back({"image_height", number_entry(p.height_px)});
  out.push_back(
      {"camera_matrix", matrix_entry({k.fx, k.skew, k.cx, 0, k.fy, k.cy, 0, 0, 1}, 3, 3)});
  int n = int(coefficients.size());
  out.push_back({"distortion_coefficients", matrix_entry(coefficients, 1, n)});
  out.push_back({"distortion_model", text_entry(model)});
  if (p.max_field_angle_degrees > 0)
    out.push_back({"max_field_angle_degrees", number_entry(p.max_field_angle_degrees)});
  if (c.world_from_camera) {
    CvExtrinsics e = cv_extrinsics(*c.world_from_camera);
    std::vector<double> r;
    for (const auto& row : e.r) r.insert(r.end(), row.begin(), row.end());
    out.push_back({"R", matrix_entry(r, 3, 3)});
    out.push_back({"T", matrix_entry({e.t[0], e.t[1], e.t[2]}, 3, 1)});
  }
  return out;
}

}  // namespace obscura
