#include "obscura/render/dataset_views.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>

#include "obscura/io/input_file.h"
#include "obscura/math/error.h"
#include "obscura/math/number_list.h"
#include "obscura/math/request_error.h"
#include "obscura/render/camera_placement.h"

namespace obscura {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegrees = kPi / 180;
// A little room around the bounding sphere.
constexpr double kFramingMargin = 1.05;

std::vector<std::string> split(const std::string& text, char separator, size_t max_parts) {
  std::vector<std::string> parts;
  size_t start = 0;
  while (parts.size() + 1 < max_parts) {
    size_t at = text.find(separator, start);
    if (at == std::string::npos) break;
    parts.push_back(text.substr(start, at - start));
    start = at + 1;
  }
  parts.push_back(text.substr(start));
  return parts;
}

int view_count(const std::string& text, const std::string& spec) {
  int n = 0;
  auto [at, error] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (text.empty() || error != std::errc() || at != text.data() + text.size() || n < 1 ||
      n > kMaxDatasetViews)
    throw RequestError("--views: the number of views must be a whole number from 1 to " +
                       std::to_string(kMaxDatasetViews) + "; got '" + spec + "'");
  return n;
}

[[noreturn]] void bad_spec(const std::string& spec) {
  throw RequestError(
      "--views expects orbit:N[:ELEVATION], sphere:N, path:N:FILE or cameras; got '" + spec + "'");
}

struct Framing {
  Point3d centre;
  double distance = 0;
};

// Where orbit and sphere views stand: the bounds' centre and the distance at which the bounding
// sphere fills the narrower field of view.
Framing framing(const Scene& scene, const Camera& camera) {
  const Bounds3f bounds = scene.bounds();
  if (bounds.empty())
    throw RequestError("--views: the scene has no geometry to place views around");
  const Point3f c = bounds.center();
  const Vector3f d = bounds.diagonal();
  const double radius =
      std::max(0.5 * std::sqrt(double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z), 1e-6);
  const Vector2d fov = camera.fov_degrees();
  const double half = std::min({fov.x, fov.y, 170.0}) / 2 * kDegrees;
  if (!(half > 0))
    throw RequestError(std::string("--views orbit and sphere need a camera with a field of view; "
                                   "this one is ") +
                       std::string(projection_name(camera.projection)));
  return {Point3d(c.x, c.y, c.z), radius / std::sin(half) * kFramingMargin};
}

DatasetView placed_view(const Camera& base, size_t index, Point3d eye, Point3d target) {
  DatasetView view{dataset_view_name(index), base};
  view.camera.world_from_camera =
      AnimatedTransform(look_at_pose(eye, target, Vector3d(0, 1, 0), "view " + view.name));
  return view;
}

struct Keyframe {
  Point3d position, target;
};

std::vector<Keyframe> read_path(const std::string& file) {
  check_input_file(file, 16 << 20, "camera path files");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(file, "cannot be read");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<Keyframe> keys;
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    if (size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string word; words >> word;) w.push_back(word);
    if (w.empty()) continue;
    const std::string where = file + ":" + std::to_string(number);
    if (w.size() != 6) throw Error(where, "expected X Y Z TX TY TZ (position, look-at point)");
    double v[6];
    for (size_t i = 0; i < 6; ++i) {
      try {
        v[i] = parse_number(w[i], "keyframe");
      } catch (const Error&) {
        throw Error(where, "expected a finite number; got '" + w[i] + "'");
      }
    }
    keys.push_back({Point3d(v[0], v[1], v[2]), Point3d(v[3], v[4], v[5])});
  }
  if (keys.size() < 2) throw Error(file, "a camera path needs at least two keyframes");
  return keys;
}

// The N views along the keyframes' polyline, evenly spaced by distance (by keyframe when the
// positions do not move).
std::vector<DatasetView> path_views(const Camera& base, const std::vector<Keyframe>& keys, int n) {
  std::vector<double> at(keys.size(), 0.0);  // the distance along the path at each key
  for (size_t i = 1; i < keys.size(); ++i)
    at[i] = at[i - 1] + distance(keys[i - 1].position, keys[i].position);
  const bool still = !(at.back() > 0);
  if (still)
    for (size_t i = 0; i < keys.size(); ++i) at[i] = double(i);
  std::vector<DatasetView> views;
  for (int k = 0; k < n; ++k) {
    const double s = n == 1 ? 0 : at.back() * k / (n - 1);
    size_t i = 0;
    while (i + 2 < keys.size() && at[i + 1] < s) ++i;
    const double span = at[i + 1] - at[i];
    const double t = span > 0 ? std::clamp((s - at[i]) / span, 0.0, 1.0) : 0.0;
    const Point3d eye = keys[i].position + (keys[i + 1].position - keys[i].position) * t;
    const Point3d target = keys[i].target + (keys[i + 1].target - keys[i].target) * t;
    views.push_back(placed_view(base, size_t(k), eye, target));
  }
  return views;
}

}  // namespace

std::string dataset_view_name(size_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "view_%04zu", index);
  return name;
}

std::vector<DatasetView> dataset_views(const Scene& scene, const CameraRequest& request,
                                       const std::string& spec, std::optional<int> width_px,
                                       std::optional<int> height_px,
                                       std::vector<std::string>* notes) {
  if (request.position || request.look_at || request.up)
    throw RequestError(
        "--views places every view's camera: --position, --look-at and --up do not apply");
  const std::vector<std::string> parts = split(spec, ':', 3);
  const std::string& kind = parts[0];
  std::vector<DatasetView> views;
  if (kind == "cameras") {
    if (parts.size() != 1) bad_spec(spec);
    std::vector<std::string> names;
    for (const Camera& c : scene.cameras) names.push_back(c.name);
    if (names.empty()) names.push_back(scene.camera.name);
    for (const std::string& name : names) {
      CameraRequest one = request;
      one.camera_name = name;
      views.push_back({dataset_view_name(views.size()),
                       resolve_camera(scene, one, width_px, height_px, notes)});
    }
    return views;
  }
  return dataset_views(scene, resolve_camera(scene, request, width_px, height_px, notes), spec);
}

std::vector<DatasetView> dataset_views(const Scene& scene, const Camera& base,
                                       const std::string& spec) {
  const std::vector<std::string> parts = split(spec, ':', 3);
  const std::string& kind = parts[0];
  std::vector<DatasetView> views;
  if (kind == "cameras") {
    if (parts.size() != 1) bad_spec(spec);
    std::vector<Camera> cameras = scene.cameras;
    if (cameras.empty()) cameras.push_back(scene.camera);
    for (Camera& c : cameras) {
      c.film = base.film;
      c.validate();
      views.push_back({dataset_view_name(views.size()), std::move(c)});
    }
    return views;
  }
  if (kind != "orbit" && kind != "sphere" && kind != "path") bad_spec(spec);
  if (parts.size() < 2 || (kind == "sphere" && parts.size() != 2) ||
      (kind == "path" && parts.size() != 3))
    bad_spec(spec);
  const int n = view_count(parts[1], spec);
  if (kind == "path") return path_views(base, read_path(parts[2]), n);
  const Framing f = framing(scene, base);
  if (kind == "orbit") {
    double elevation = 20;
    if (parts.size() == 3) {
      elevation = parse_number(parts[2], "--views orbit elevation");
      if (!(std::abs(elevation) < 89.9))
        throw RequestError("--views orbit: the elevation must be within ±89.9 degrees; got '" +
                           spec + "'");
    }
    const double e = elevation * kDegrees;
    for (int k = 0; k < n; ++k) {
      const double azimuth = 2 * kPi * k / n;
      const Vector3d direction(std::cos(e) * std::sin(azimuth), std::sin(e),
                               std::cos(e) * std::cos(azimuth));
      views.push_back(placed_view(base, size_t(k), f.centre + direction * f.distance, f.centre));
    }
    return views;
  }
  const double golden_angle = kPi * (3 - std::sqrt(5.0));  // 137.5°
  for (int k = 0; k < n; ++k) {
    const double y = 1 - (2.0 * k + 1) / n;
    const double ring = std::sqrt(std::max(0.0, 1 - y * y));
    const double azimuth = golden_angle * k;
    const Vector3d direction(ring * std::sin(azimuth), y, ring * std::cos(azimuth));
    // A single view (y = 0) or views near the poles: up stays world +Y (never exactly parallel:
    // |y| ≤ 1 − 1/N).
    views.push_back(placed_view(base, size_t(k), f.centre + direction * f.distance, f.centre));
  }
  return views;
}

}  // namespace obscura
