#include "obscura/io/colmap_model.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <vector>

#include "obscura/io/lens_model_coefficients.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

// COLMAP's principal point is OpenCV's plus half a pixel (see the header).
constexpr double kColmapPixelOffset = 0.5;

struct ColmapCameraModel {
  const char* name;
  int focal_count;  // 1: f (fx = fy), 2: fx, fy
  int coefficient_count;
  bool fisheye;
};

constexpr ColmapCameraModel kModels[] = {
    {"SIMPLE_PINHOLE", 1, 0, false}, {"PINHOLE", 2, 0, false},
    {"SIMPLE_RADIAL", 1, 1, false},  {"RADIAL", 1, 2, false},
    {"OPENCV", 2, 4, false},         {"FULL_OPENCV", 2, 8, false},
    {"OPENCV_FISHEYE", 2, 4, true},  {"SIMPLE_RADIAL_FISHEYE", 1, 1, true},
    {"RADIAL_FISHEYE", 1, 2, true},
};

std::vector<std::string> words(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream stream(line);
  std::string word;
  while (stream >> word) out.push_back(word);
  return out;
}

double number(const std::string& word, const std::string& where, const std::string& field) {
  char* end = nullptr;
  errno = 0;
  double v = std::strtod(word.c_str(), &end);
  if (word.empty() || end != word.c_str() + word.size() || errno != 0 || !std::isfinite(v))
    throw Error(where, field + ": expected a finite number; got '" + word + "'");
  return v;
}

long whole_number(const std::string& word, const std::string& where, const std::string& field,
                  long min, long max) {
  double v = number(word, where, field);
  if (v != std::floor(v) || v < min || v > max)
    throw Error(where, field + ": expected a whole number from " + std::to_string(min) + " to " +
                           std::to_string(max) + "; got '" + word + "'");
  return long(v);
}

// The lines of a text, numbered from 1, without '\r'.
std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream stream(text);
  std::string line;
  while (std::getline(stream, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

bool is_blank_or_comment(const std::string& line) {
  size_t first = line.find_first_not_of(" \t");
  return first == std::string::npos || line[first] == '#';
}

CameraCalibration camera_from_line(const std::vector<std::string>& w, const std::string& where) {
  // CAMERA_ID MODEL WIDTH HEIGHT PARAMS[]
  const ColmapCameraModel* model = nullptr;
  for (const ColmapCameraModel& m : kModels)
    if (w[1] == m.name) model = &m;
  if (!model)
    throw Error(where,
                "MODEL: expected SIMPLE_PINHOLE, PINHOLE, SIMPLE_RADIAL, RADIAL, OPENCV, "
                "FULL_OPENCV, OPENCV_FISHEYE, SIMPLE_RADIAL_FISHEYE or RADIAL_FISHEYE; got '" +
                    w[1] + "'");
  size_t expected = 4 + size_t(model->focal_count) + 2 + size_t(model->coefficient_count);
  if (w.size() != expected)
    throw Error(where, std::string(model->name) + " expects " + std::to_string(expected - 4) +
                           " parameters; got " + std::to_string(w.size() - 4));
  CameraCalibration c;
  CalibratedProjection& p = c.projection;
  p.width_px = int(whole_number(w[2], where, "WIDTH", 1, 65536));
  p.height_px = int(whole_number(w[3], where, "HEIGHT", 1, 65536));
  std::vector<double> params;
  for (size_t i = 4; i < w.size(); ++i)
    params.push_back(number(w[i], where, "PARAMS[" + std::to_string(i - 4) + "]"));
  size_t n = 0;
  p.k.fx = params[n++];
  p.k.fy = model->focal_count == 2 ? params[n++] : p.k.fx;
  p.k.cx = params[n++] - kColmapPixelOffset;
  p.k.cy = params[n++] - kColmapPixelOffset;
  std::vector<double> k(params.begin() + long(n), params.end());
  if (model->fisheye) {
    k.resize(4, 0.0);
    p.lens = lens_model_from_coefficients("kannala-brandt", k);
  } else {
    // SIMPLE_RADIAL and RADIAL are OpenCV's k1 (and k2); FULL_OPENCV's order is OpenCV's.
    k.resize(k.size() <= 4 ? 4 : 8, 0.0);
    p.lens = lens_model_from_coefficients("opencv", k);
  }
  validate_calibration(c, where);
  return c;
}

std::array<std::array<double, 3>, 3> rotation_from_quaternion(double w, double x, double y,
                                                              double z) {
  double n = std::sqrt(w * w + x * x + y * y + z * z);
  w /= n, x /= n, y /= n, z /= n;
  return {{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
           {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
           {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
}

// Shepperd's method: the largest of the four squared components is computed first, so no
// division by a small number.
std::array<double, 4> quaternion_from_rotation(const std::array<std::array<double, 3>, 3>& r) {
  double trace = r[0][0] + r[1][1] + r[2][2];
  std::array<double, 4> q;  // w x y z
  if (trace >= r[0][0] && trace >= r[1][1] && trace >= r[2][2]) {
    double s = 2 * std::sqrt(1 + trace);
    q = {s / 4, (r[2][1] - r[1][2]) / s, (r[0][2] - r[2][0]) / s, (r[1][0] - r[0][1]) / s};
  } else if (r[0][0] >= r[1][1] && r[0][0] >= r[2][2]) {
    double s = 2 * std::sqrt(1 + r[0][0] - r[1][1] - r[2][2]);
    q = {(r[2][1] - r[1][2]) / s, s / 4, (r[0][1] + r[1][0]) / s, (r[0][2] + r[2][0]) / s};
  } else if (r[1][1] >= r[2][2]) {
    double s = 2 * std::sqrt(1 + r[1][1] - r[0][0] - r[2][2]);
    q = {(r[0][2] - r[2][0]) / s, (r[0][1] + r[1][0]) / s, s / 4, (r[1][2] + r[2][1]) / s};
  } else {
    double s = 2 * std::sqrt(1 + r[2][2] - r[0][0] - r[1][1]);
    q = {(r[1][0] - r[0][1]) / s, (r[0][2] + r[2][0]) / s, (r[1][2] + r[2][1]) / s, s / 4};
  }
  if (q[0] < 0)
    for (double& v : q) v = -v;  // COLMAP's own output keeps QW ≥ 0
  return q;
}

// The COLMAP model name and parameters (after fx/f, fy, cx, cy) for a lens model.
std::pair<std::string, std::vector<double>> colmap_model_of(const CalibratedProjection& p) {
  if (auto* d = std::get_if<PinholeDistortion>(&p.lens)) {
    if (d->s1 != 0 || d->s2 != 0 || d->s3 != 0 || d->s4 != 0 || d->tau_x != 0 || d->tau_y != 0)
      throw Error("COLMAP cameras.txt",
                  "COLMAP has no thin-prism (s1..s4) or tilt (τx, τy) coefficients for the "
                  "pinhole model");
    if (d->k3 == 0 && d->k4 == 0 && d->k5 == 0 && d->k6 == 0) {
      if (d->k1 == 0 && d->k2 == 0 && d->p1 == 0 && d->p2 == 0) return {"PINHOLE", {}};
      return {"OPENCV", {d->k1, d->k2, d->p1, d->p2}};
    }
    return {"FULL_OPENCV", {d->k1, d->k2, d->p1, d->p2, d->k3, d->k4, d->k5, d->k6}};
  }
  if (auto* kb = std::get_if<KannalaBrandt>(&p.lens))
    return {"OPENCV_FISHEYE", {kb->k1, kb->k2, kb->k3, kb->k4}};
  if (auto* f = std::get_if<ClassicFisheye>(&p.lens);
      f && f->mapping == FisheyeMapping::equidistant)
    return {"OPENCV_FISHEYE", {0, 0, 0, 0}};
  throw Error("COLMAP cameras.txt",
              std::string("COLMAP has no ") + lens_model_name(p.lens) + " lens model");
}

}  // namespace

CameraCalibration parse_colmap_model(const std::string& cameras_text,
                                     const std::string& cameras_file,
                                     const std::string* images_text, const std::string& images_file,
                                     const std::string& image_name) {
  std::map<long, CameraCalibration> cameras;
  long first_camera = -1;
  std::vector<std::string> camera_lines = lines_of(cameras_text);
  for (size_t i = 0; i < camera_lines.size(); ++i) {
    if (is_blank_or_comment(camera_lines[i])) continue;
    std::string where = cameras_file + ":" + std::to_string(i + 1);
    std::vector<std::string> w = words(camera_lines[i]);
    if (w.size() < 4)
      throw Error(where,
                  "expected CAMERA_ID MODEL WIDTH HEIGHT PARAMS[]; got '" + camera_lines[i] + "'");
    long id = whole_number(w[0], where, "CAMERA_ID", 0, 2147483647);
    if (cameras.count(id)) throw Error(where, "CAMERA_ID " + w[0] + " appears twice");
    cameras[id] = camera_from_line(w, where);
    if (first_camera < 0) first_camera = id;
  }
  if (cameras.empty()) throw Error(cameras_file, "no camera (expected CAMERA_ID MODEL WIDTH ...)");
  if (!images_text) {
    if (!image_name.empty())
      throw Error(cameras_file, "image '" + image_name + "' asked for, but there is no " +
                                    "images.txt beside it");
    return cameras[first_camera];
  }
  std::vector<std::string> image_lines = lines_of(*images_text);
  std::string names;
  for (size_t i = 0; i < image_lines.size(); ++i) {
    if (is_blank_or_comment(image_lines[i])) continue;
    std::string where = images_file + ":" + std::to_string(i + 1);
    std::vector<std::string> w = words(image_lines[i]);
    ++i;  // the image's 2D points, a line of its own even when empty
    if (w.size() < 10)
      throw Error(where, "expected IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME (10 fields); got " +
                             std::to_string(w.size()));
    for (size_t j = 10; j < w.size(); ++j) w[9] += " " + w[j];  // a NAME with spaces
    whole_number(w[0], where, "IMAGE_ID", 0, 2147483647);
    if (!image_name.empty() && w[9] != image_name) {
      if (names.size() < 200) names += (names.empty() ? "" : ", ") + w[9];
      continue;
    }
    double q[4], t[3];
    const char* fields[] = {"QW", "QX", "QY", "QZ", "TX", "TY", "TZ"};
    for (int j = 0; j < 4; ++j) q[j] = number(w[1 + size_t(j)], where, fields[j]);
    for (int j = 0; j < 3; ++j) t[j] = number(w[5 + size_t(j)], where, fields[4 + j]);
    double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!(norm > 1e-6) || !std::isfinite(norm))
      throw Error(where, "QW QX QY QZ: expected a rotation quaternion (non-zero)");
    long camera_id = whole_number(w[8], where, "CAMERA_ID", 0, 2147483647);
    auto found = cameras.find(camera_id);
    if (found == cameras.end())
      throw Error(where, "CAMERA_ID " + w[8] + " is not in " + cameras_file);
    CameraCalibration c = found->second;
    CvExtrinsics e{.r = rotation_from_quaternion(q[0], q[1], q[2], q[3]), .t = {t[0], t[1], t[2]}};
    c.world_from_camera = world_from_camera_of(e, where);
    c.image_name = w[9];
    return c;
  }
  if (image_name.empty()) throw Error(images_file, "no image (expected IMAGE_ID QW QX ...)");
  throw Error(images_file, "no image named '" + image_name + "'; its images: " + names);
}

ColmapModelText colmap_model_text(const CameraCalibration& c) {
  return colmap_model_text(std::vector<CameraCalibration>{c});
}

ColmapModelText colmap_model_text(const std::vector<CameraCalibration>& images) {
  // One camera line per distinct intrinsics (the same model, size and parameters, to the bit).
  std::vector<std::string> camera_lines;
  std::vector<size_t> camera_of(images.size());
  for (size_t i = 0; i < images.size(); ++i) {
    const CalibratedProjection& p = images[i].projection;
    if (p.k.skew != 0) throw Error("COLMAP cameras.txt", "COLMAP's camera models have no skew");
    auto [model, coefficients] = colmap_model_of(p);
    std::string line = model + " " + std::to_string(p.width_px) + " " + std::to_string(p.height_px);
    std::vector<double> params = {p.k.fx, p.k.fy, p.k.cx + kColmapPixelOffset,
                                  p.k.cy + kColmapPixelOffset};
    params.insert(params.end(), coefficients.begin(), coefficients.end());
    for (double v : params) line.append(" ").append(exact_number(v));
    auto found = std::find(camera_lines.begin(), camera_lines.end(), line);
    camera_of[i] = size_t(found - camera_lines.begin());
    if (found == camera_lines.end()) camera_lines.push_back(line);
  }
  ColmapModelText out;
  out.cameras =
      "# Camera list with one line of data per camera:\n"
      "#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n"
      "# Number of cameras: " +
      std::to_string(camera_lines.size()) + "\n";
  for (size_t i = 0; i < camera_lines.size(); ++i)
    out.cameras.append(std::to_string(i + 1)).append(" ").append(camera_lines[i]).append("\n");
  out.images =
      "# Image list with two lines of data per image:\n"
      "#   IMAGE_ID, QW, QX, QY, QZ, TX, TY, TZ, CAMERA_ID, NAME\n"
      "#   POINTS2D[] as (X, Y, POINT3D_ID)\n"
      "# Number of images: " +
      std::to_string(images.size()) + ", mean observations per image: 0\n";
  for (size_t i = 0; i < images.size(); ++i) {
    const CameraCalibration& c = images[i];
    // Without a pose: COLMAP's identity (R = I, t = 0).
    CvExtrinsics e{.r = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, .t = {0, 0, 0}};
    if (c.world_from_camera) e = cv_extrinsics(*c.world_from_camera);
    std::array<double, 4> q = quaternion_from_rotation(e.r);
    std::string name = c.image_name.empty() ? "image.png" : c.image_name;
    for (char& ch : name)
      if (ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r') ch = '_';  // NAME is one word
    out.images.append(std::to_string(i + 1));
    for (double v : q) out.images.append(" ").append(exact_number(v));
    for (double v : e.t) out.images.append(" ").append(exact_number(v));
    out.images.append(" ").append(std::to_string(camera_of[i] + 1)).append(" ").append(name);
    out.images.append("\n\n");
  }
  return out;
}

}  // namespace obscura
