#include "obscura/io/nerf_transforms.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include "obscura/io/json_reader.h"
#include "obscura/io/lens_model_coefficients.h"
#include "obscura/math/error.h"
#include "obscura/math/number_text.h"

namespace obscura {

namespace {

using Json = nlohmann::ordered_json;

// nerfstudio's and instant-ngp's cx, cy are OpenCV's plus half a pixel (see the header).
constexpr double kNerfPixelOffset = 0.5;

// The value of `key` for a frame: the frame's own, else the file's.
const Json* value_of(const Json& root, const Json* frame, const char* key, std::string& where,
                     const std::string& frame_path) {
  if (frame && frame->contains(key)) {
    where = frame_path + "." + key;
    return &(*frame)[key];
  }
  if (root.contains(key)) {
    where = std::string("$.") + key;
    return &root[key];
  }
  return nullptr;
}

struct Reader {
  const Json& root;
  const Json* frame;
  std::string frame_path, file;

  std::optional<double> number(const char* key) const {
    std::string where;
    const Json* v = value_of(root, frame, key, where, frame_path);
    if (!v) return std::nullopt;
    if (!v->is_number() || !std::isfinite(v->get<double>()))
      throw Error(file + ": " + where, "expected a finite number");
    return v->get<double>();
  }
  int side(const char* key) const {
    std::optional<double> v = number(key);
    if (!v)
      throw Error(file, std::string("missing \"") + key +
                            "\": the image size in pixels (the original NeRF files leave it to "
                            "the images; add w and h)");
    if (!(*v >= 1 && *v <= 65536 && *v == std::floor(*v)))
      throw Error(file + ": $." + key, "expected a whole number of pixels from 1 to 65536");
    return int(*v);
  }
  std::string model() const {
    std::string where;
    const Json* v = value_of(root, frame, "camera_model", where, frame_path);
    if (!v) return "OPENCV";
    if (!v->is_string()) throw Error(file + ": " + where, "expected a camera model name");
    std::string m = v->get<std::string>();
    if (m != "OPENCV" && m != "OPENCV_FISHEYE" && m != "PINHOLE" && m != "SIMPLE_PINHOLE")
      throw Error(file + ": " + where,
                  "expected OPENCV, OPENCV_FISHEYE, PINHOLE or SIMPLE_PINHOLE; got '" + m + "'");
    return m;
  }
};

CameraCalibration intrinsics_of(const Reader& r) {
  CameraCalibration c;
  CalibratedProjection& p = c.projection;
  p.width_px = r.side("w");
  p.height_px = r.side("h");
  std::optional<double> fx = r.number("fl_x"), fy = r.number("fl_y");
  // A full field of view of π or more has no pinhole focal length: tan(angle / 2) turns negative
  // or wraps round to a tiny positive value (6.3 rad gave a focal length that imaged nothing).
  auto field_angle = [&](const char* key) {
    std::optional<double> angle = r.number(key);
    if (angle && !(*angle > 0 && *angle < std::numbers::pi))
      throw Error(r.file + ": " + key,
                  "must be a full field of view in (0, π) radians; got " + number_text(*angle));
    return angle;
  };
  if (!fx) {
    std::optional<double> angle = field_angle("camera_angle_x");
    if (!angle) throw Error(r.file, "missing the focal length (fl_x or camera_angle_x)");
    fx = 0.5 * p.width_px / std::tan(0.5 * *angle);
  }
  if (!fy) {
    std::optional<double> angle = field_angle("camera_angle_y");
    fy = angle ? 0.5 * p.height_px / std::tan(0.5 * *angle) : *fx;
  }
  p.k.fx = *fx;
  p.k.fy = *fy;
  p.k.cx = r.number("cx").value_or(0.5 * p.width_px) - kNerfPixelOffset;
  p.k.cy = r.number("cy").value_or(0.5 * p.height_px) - kNerfPixelOffset;
  auto k = [&](const char* key) { return r.number(key).value_or(0.0); };
  std::string model = r.model();
  if (model == "OPENCV_FISHEYE") {
    p.lens = KannalaBrandt{k("k1"), k("k2"), k("k3"), k("k4")};
  } else {
    if (k("k4") != 0)
      throw Error(r.file,
                  "k4 is not part of OpenCV's pinhole model (k1 k2 p1 p2 k3); "
                  "camera_model " +
                      model);
    p.lens = lens_model_from_coefficients("opencv", {k("k1"), k("k2"), k("p1"), k("p2"), k("k3")});
  }
  return c;
}

Transform pose_of(const Json& matrix, const std::string& where) {
  auto fail = [&] { throw Error(where, "expected a 4x4 array of finite numbers (rows)"); };
  if (!matrix.is_array() || matrix.size() != 4) fail();
  double m[4][4];
  for (size_t i = 0; i < 4; ++i) {
    if (!matrix[i].is_array() || matrix[i].size() != 4) fail();
    for (size_t j = 0; j < 4; ++j) {
      if (!matrix[i][j].is_number()) fail();
      m[i][j] = matrix[i][j].get<double>();
      if (!std::isfinite(m[i][j])) fail();
    }
  }
  if (m[3][0] != 0 || m[3][1] != 0 || m[3][2] != 0 || m[3][3] != 1)
    throw Error(where, "the last row must be [0, 0, 0, 1]");
  // The OpenCV-frame extrinsics of camera → world M: R = F·Aᵀ, t = −F·Aᵀ·b for M = [A | b].
  CvExtrinsics e;
  for (int i = 0; i < 3; ++i) {
    double sign = i == 0 ? 1 : -1;
    e.t[i] = 0;
    for (int j = 0; j < 3; ++j) {
      e.r[i][j] = sign * m[j][i];
      e.t[i] -= sign * m[j][i] * m[j][3];
    }
  }
  return world_from_camera_of(e, where);
}

bool frame_matches(const std::string& file_path, const std::string& name) {
  if (file_path == name) return true;
  std::filesystem::path p(file_path);
  return p.filename().string() == name || p.stem().string() == name;
}

}  // namespace

CameraCalibration parse_nerf_transforms(const std::string& text, const std::string& file,
                                        const std::string& image_name) {
  Json root = parse_json_text(text, file);
  if (!root.is_object()) throw Error(file, "expected a JSON object (transforms.json)");
  if (root.contains("is_fisheye") && root["is_fisheye"] != false)
    throw Error(file + ": $.is_fisheye",
                "instant-ngp's is_fisheye is not supported; give "
                "camera_model OPENCV_FISHEYE");
  const Json* frames = root.contains("frames") ? &root["frames"] : nullptr;
  if (frames && !frames->is_array()) throw Error(file + ": $.frames", "expected an array");
  if (!frames || frames->empty()) {
    if (!image_name.empty()) throw Error(file, "no frame named '" + image_name + "': no frames");
    CameraCalibration c = intrinsics_of({root, nullptr, "", file});
    validate_calibration(c, file);
    return c;
  }
  std::string names;
  for (size_t i = 0; i < frames->size(); ++i) {
    const Json& frame = (*frames)[i];
    std::string path = "$.frames[" + std::to_string(i) + "]";
    if (!frame.is_object()) throw Error(file + ": " + path, "expected an object");
    std::string file_path;
    if (frame.contains("file_path")) {
      if (!frame["file_path"].is_string())
        throw Error(file + ": " + path + ".file_path", "expected a string");
      file_path = frame["file_path"].get<std::string>();
    }
    if (!image_name.empty() && !frame_matches(file_path, image_name)) {
      if (names.size() < 200) names += (names.empty() ? "" : ", ") + file_path;
      continue;
    }
    CameraCalibration c = intrinsics_of({root, &frame, path, file});
    if (!frame.contains("transform_matrix"))
      throw Error(file + ": " + path, "missing transform_matrix (camera to world)");
    c.world_from_camera =
        pose_of(frame["transform_matrix"], file + ": " + path + ".transform_matrix");
    c.image_name = file_path;
    validate_calibration(c, file + ": " + path);
    return c;
  }
  throw Error(file, "no frame named '" + image_name + "'; its frames: " + names);
}

namespace {

using Fields = std::vector<std::pair<std::string, std::string>>;

// The intrinsics' keys and their values' JSON text.
Fields intrinsic_fields(const CalibratedProjection& p) {
  if (p.k.skew != 0) throw Error("transforms.json", "NeRF's transforms.json has no skew");
  std::string model;
  std::vector<std::pair<const char*, double>> distortion;
  if (auto* d = std::get_if<PinholeDistortion>(&p.lens)) {
    if (d->k4 != 0 || d->k5 != 0 || d->k6 != 0 || d->s1 != 0 || d->s2 != 0 || d->s3 != 0 ||
        d->s4 != 0 || d->tau_x != 0 || d->tau_y != 0)
      throw Error("transforms.json",
                  "NeRF's OPENCV model has only k1 k2 p1 p2 k3 (no rational "
                  "k4..k6, thin-prism or tilt terms)");
    model = "OPENCV";
    distortion = {{"k1", d->k1}, {"k2", d->k2}, {"k3", d->k3}, {"p1", d->p1}, {"p2", d->p2}};
  } else if (auto* kb = std::get_if<KannalaBrandt>(&p.lens)) {
    model = "OPENCV_FISHEYE";
    distortion = {{"k1", kb->k1}, {"k2", kb->k2}, {"k3", kb->k3}, {"k4", kb->k4}};
  } else if (auto* f = std::get_if<ClassicFisheye>(&p.lens);
             f && f->mapping == FisheyeMapping::equidistant) {
    model = "OPENCV_FISHEYE";
    distortion = {{"k1", 0}, {"k2", 0}, {"k3", 0}, {"k4", 0}};
  } else {
    throw Error("transforms.json", std::string("NeRF's transforms.json has no ") +
                                       lens_model_name(p.lens) + " lens model");
  }
  Fields fields = {{"camera_model", "\"" + model + "\""},
                   {"w", std::to_string(p.width_px)},
                   {"h", std::to_string(p.height_px)},
                   {"fl_x", exact_number(p.k.fx)},
                   {"fl_y", exact_number(p.k.fy)},
                   {"cx", exact_number(p.k.cx + kNerfPixelOffset)},
                   {"cy", exact_number(p.k.cy + kNerfPixelOffset)}};
  for (const auto& [key, value] : distortion) fields.emplace_back(key, exact_number(value));
  // instant-ngp's field of view, for readers that look only at it.
  if (is_planar(p.lens))
    fields.emplace_back("camera_angle_x", exact_number(2 * std::atan(0.5 * p.width_px / p.k.fx)));
  return fields;
}

void append_fields(std::string& out, const Fields& fields, const std::string& indent) {
  for (const auto& [key, value] : fields)
    out.append(indent).append("\"").append(key).append("\": ").append(value).append(",\n");
}

}  // namespace

std::string nerf_transforms_text(const CameraCalibration& c) {
  return nerf_transforms_text(std::vector<CameraCalibration>{c});
}

std::string nerf_transforms_text(const std::vector<CameraCalibration>& frames) {
  std::vector<Fields> intrinsics;
  for (const CameraCalibration& c : frames) intrinsics.push_back(intrinsic_fields(c.projection));
  // Intrinsics every frame shares go to the top level, as nerfstudio writes them; otherwise
  // each frame carries its own (a frame's value wins in every reader).
  const bool shared = std::all_of(intrinsics.begin(), intrinsics.end(),
                                  [&](const Fields& f) { return f == intrinsics.front(); });
  std::string out = "{\n";
  if (shared && !intrinsics.empty()) append_fields(out, intrinsics.front(), "  ");
  out.append("  \"frames\": [");
  for (size_t i = 0; i < frames.size(); ++i) {
    const CameraCalibration& c = frames[i];
    out.append(i ? ",\n    {\n" : "\n    {\n");
    if (!shared) append_fields(out, intrinsics[i], "      ");
    const Matrix4 m = c.world_from_camera.value_or(Transform()).matrix();
    // A name that is not UTF-8 (COLMAP's NAME is bytes) gets U+FFFD where it breaks, not an
    // error.
    std::string name = Json(c.image_name.empty() ? "image.png" : c.image_name)
                           .dump(-1, ' ', false, Json::error_handler_t::replace);
    out.append("      \"file_path\": ").append(name);
    out.append(",\n      \"transform_matrix\": [\n");
    for (int r = 0; r < 4; ++r) {
      out.append("        [");
      for (int j = 0; j < 4; ++j) out.append(j ? ", " : "").append(exact_number(m.m[r][j]));
      out.append(r < 3 ? "],\n" : "]\n");
    }
    out.append("      ]\n    }");
  }
  out.append(frames.empty() ? "]\n}\n" : "\n  ]\n}\n");
  return out;
}

}  // namespace obscura
