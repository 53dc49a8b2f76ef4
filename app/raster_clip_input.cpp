#include "raster_clip_input.h"

#include <cmath>

#include "obscura/io/json_reader.h"
#include "obscura/math/error.h"

namespace obscura::app {

namespace {

using json = nlohmann::ordered_json;

// The input, as the conformance format defines it (see docs/rasterizer.md).

// Reads JSON values, naming the JSON path of anything malformed: "file.json: triangles[2].clip".
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  const json& member(const json& object, const std::string& path, const std::string& key,
                     bool required = true) const {
    static const json kNull;
    if (!object.is_object()) fail(path, "expected an object");
    auto it = object.find(key);
    if (it == object.end()) {
      if (required) fail(path, "missing required key '" + key + "'");
      return kNull;
    }
    return *it;
  }
  double number(const json& v, const std::string& path) const {
    if (!v.is_number()) fail(path, "expected a number, got " + v.dump());
    return v.get<double>();
  }
  int positive_int(const json& v, const std::string& path, int max) const {
    if (!v.is_number_integer() || v.get<int64_t>() <= 0 || v.get<int64_t>() > max)
      fail(path, "expected an integer in [1, " + std::to_string(max) + "], got " + v.dump());
    return v.get<int>();
  }
  std::string string(const json& v, const std::string& path) const {
    if (!v.is_string()) fail(path, "expected a string, got " + v.dump());
    return v.get<std::string>();
  }
  std::vector<double> numbers(const json& v, const std::string& path, size_t count) const {
    if (!v.is_array() || v.size() != count)
      fail(path, "expected an array of " + std::to_string(count) + " numbers, got " + v.dump());
    std::vector<double> r;
    for (size_t i = 0; i < count; ++i)
      r.push_back(number(v[i], path + "[" + std::to_string(i) + "]"));
    return r;
  }
  Rgb color_255(const json& v, const std::string& path) const {
    std::vector<double> c = numbers(v, path, 3);
    for (double x : c)
      if (x < 0 || x > 255) fail(path, "colour channels must lie in [0, 255], got " + v.dump());
    return {float(c[0]), float(c[1]), float(c[2])};
  }
  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw Error(file_ + ": " + path, what);
  }

 private:
  std::string file_;
};

}  // namespace

ClipTriangles parse_raster_clip(const nlohmann::ordered_json& doc, const std::string& file) {
  Reader r(file);
  ClipTriangles c;
  c.name = r.string(r.member(doc, "(root)", "name"), "name");
  if (c.name.empty() || c.name.find('/') != std::string::npos || c.name == "." || c.name == "..")
    r.fail("name", "expected a non-empty file name without '/'");
  c.width = r.positive_int(r.member(doc, "(root)", "width"), "width", 16384);
  c.height = r.positive_int(r.member(doc, "(root)", "height"), "height", 16384);
  if (const json& v = r.member(doc, "(root)", "clear_color", false); !v.is_null())
    c.clear_color = r.color_255(v, "clear_color");
  if (const json& v = r.member(doc, "(root)", "clear_depth", false); !v.is_null()) {
    c.clear_depth = float(r.number(v, "clear_depth"));
    if (!(c.clear_depth >= 0 && c.clear_depth <= 1))
      r.fail("clear_depth", "expected a number in [0, 1]");
  }
  if (const json& v = r.member(doc, "(root)", "depth_func", false); !v.is_null()) {
    try {
      c.depth_func = raster::parse_depth_func(r.string(v, "depth_func"));
    } catch (const Error& e) {
      r.fail("depth_func", e.what());
    }
  }
  if (const json& v = r.member(doc, "(root)", "cull", false); !v.is_null()) {
    try {
      c.cull = raster::parse_cull_mode(r.string(v, "cull"));
    } catch (const Error& e) {
      r.fail("cull", e.what());
    }
  }
  const json& triangles = r.member(doc, "(root)", "triangles");
  if (!triangles.is_array()) r.fail("triangles", "expected an array of triangles");
  for (size_t t = 0; t < triangles.size(); ++t) {
    std::string path = "triangles[" + std::to_string(t) + "]";
    const json& tri = triangles[t];
    const json& id = r.member(tri, path, "id");
    if (!id.is_number_integer() || id.get<int64_t>() < 1 || id.get<int64_t>() > 65535)
      r.fail(path + ".id",
             "expected an integer in [1, 65535] (0 is the background), got " + id.dump());
    c.ids.push_back(id.get<uint32_t>());
    c.colors.push_back(r.color_255(r.member(tri, path, "color"), path + ".color"));
    const json& clip = r.member(tri, path, "clip");
    if (!clip.is_array() || clip.size() != 3)
      r.fail(path + ".clip", "expected 3 vertices [x, y, z, w], got " + clip.dump());
    for (int k = 0; k < 3; ++k) {
      std::vector<double> p = r.numbers(clip[k], path + ".clip[" + std::to_string(k) + "]", 4);
      Vector4f v{float(p[0]), float(p[1]), float(p[2]), float(p[3])};
      // A double such as 1e300 is no float: the rasterizer would meet Inf and NaN.
      if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z) || !std::isfinite(v.w))
        r.fail(path + ".clip[" + std::to_string(k) + "]",
               "expected numbers within a 32-bit float's range (|x| < 3.4e38)");
      c.clip.push_back(v);
    }
  }
  return c;
}

ClipTriangles read_raster_clip_file(const std::string& file) {
  // parse_json_file refuses directories, devices, FIFOs and oversized files, and names the line
  // and column of a syntax error.
  return parse_raster_clip(parse_json_file(file), file);
}

}  // namespace obscura::app
