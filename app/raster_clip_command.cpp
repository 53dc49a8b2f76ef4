#include "raster_clip_command.h"

#include <bit>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "obscura/color/srgb.h"
#include "obscura/io/atomic_file.h"
#include "obscura/io/image_io.h"
#include "obscura/math/error.h"
#include "obscura/raster/pipeline.h"
#include "usage_error.h"

namespace obscura::app {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The input, as the conformance format defines it (see docs/rasterizer.md).
struct ClipTriangles {
  std::string name;
  int width = 0, height = 0;
  Rgb clear_color;  // 0–255 per channel, as the triangles' colours
  float clear_depth = 1.f;
  raster::DepthFunc depth_func = raster::DepthFunc::kLess;
  raster::CullMode cull = raster::CullMode::kNone;
  std::vector<uint32_t> ids;
  std::vector<Rgb> colors;     // 0–255
  std::vector<Vector4f> clip;  // three per triangle
};

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

ClipTriangles parse(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw Error(file, "cannot open for reading");
  json doc;
  try {
    doc = json::parse(in);
  } catch (const json::parse_error& e) {
    throw Error(file, std::string("not valid JSON: ") + e.what());
  }
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
      c.clip.push_back({float(p[0]), float(p[1]), float(p[2]), float(p[3])});
    }
  }
  return c;
}

// Passes clip positions through and paints each triangle with its own colour.
struct TriangleColorProgram {
  using Vertex = Vector4f;
  struct Varyings {
    float unused;
  };
  const std::vector<Rgb>* colors;
  raster::VertexOutput<Varyings> vertex(const Vector4f& clip) const { return {clip, {0.f}}; }
  Rgb fragment(const Varyings&, raster::FragmentInfo f) const { return (*colors)[f.primitive]; }
};

// Plain ("P2") greyscale PGM, row 0 first; written whole or not at all (AtomicFile).
void write_plain_pgm(const fs::path& path, int width, int height, const std::vector<uint32_t>& v) {
  uint32_t max_value = 1;
  for (uint32_t x : v) max_value = std::max(max_value, x);
  std::ostringstream out;
  out << "P2\n" << width << " " << height << "\n" << max_value << "\n";
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      out << v[size_t(y) * width + x] << (x + 1 == width ? '\n' : ' ');
  AtomicFile file(path.string());
  file.write(out.str());
  file.commit();
}

// Greyscale PFM ("Pf"): little-endian floats, bottom row first as the format requires.
void write_grey_pfm(const fs::path& path, const Image& image) {
  static_assert(std::endian::native == std::endian::little);
  AtomicFile file(path.string());
  file.write("Pf\n" + std::to_string(image.width) + " " + std::to_string(image.height) +
             "\n-1.0\n");
  for (int y = image.height - 1; y >= 0; --y)
    file.write(std::span<const uint8_t>(
        reinterpret_cast<const uint8_t*>(&image.data[size_t(y) * image.width]),
        sizeof(float) * size_t(image.width)));
  file.commit();
}

Rgb decode_255(Rgb c) {  // PNG stores sRGB-encoded bytes; the film holds linear values
  return {srgb_decode(c.r / 255.f), srgb_decode(c.g / 255.f), srgb_decode(c.b / 255.f)};
}

void run_raster_clip(const std::string& file, const std::string& out_dir) {
  if (!fs::is_directory(out_dir)) throw UsageError("--out: '" + out_dir + "' is not a directory");
  ClipTriangles input = parse(file);
  const fs::path base = fs::path(out_dir) / input.name;

  std::vector<Rgb> linear;
  for (Rgb c : input.colors) linear.push_back(decode_255(c));
  TriangleColorProgram program{&linear};
  raster::RenderTarget target(input.width, input.height, 1, /*aovs=*/true);
  target.clear(decode_255(input.clear_color), input.clear_depth);
  raster::DrawState state;
  state.depth_func = input.depth_func;
  state.cull = input.cull;
  raster::draw(target, state, program, input.clip);

  // Coverage counts: the same triangles, depth test off, each adding one.
  std::vector<Rgb> ones(input.colors.size(), Rgb(1.f));
  TriangleColorProgram count_program{&ones};
  raster::RenderTarget counts(input.width, input.height);
  counts.clear();
  raster::DrawState count_state;
  count_state.depth_func = raster::DepthFunc::kAlways;
  count_state.depth_write = false;
  count_state.cull = input.cull;
  count_state.blend = raster::BlendMode::kAdd;
  raster::draw(counts, count_state, count_program, input.clip);

  size_t n = size_t(input.width) * input.height;
  std::vector<uint32_t> ids(n), count(n);
  for (int y = 0; y < input.height; ++y)
    for (int x = 0; x < input.width; ++x) {
      size_t i = size_t(y) * input.width + x;
      ids[i] = target.object_id_at(x, y) == raster::kNoObject
                   ? 0
                   : input.ids[target.primitive_id_at(x, y)];
      count[i] = uint32_t(counts.color_at(x, y).r);
    }
  write_image(base.string() + ".png", target.resolve_color());
  write_plain_pgm(base.string() + ".ids.pgm", input.width, input.height, ids);
  write_plain_pgm(base.string() + ".count.pgm", input.width, input.height, count);
  write_grey_pfm(base.string() + ".depth.pfm", target.depth_image());
  std::printf("%s\n", base.string().c_str());
}

}  // namespace

void add_raster_clip_command(CLI::App& app) {
  auto file = std::make_shared<std::string>();
  auto out_dir = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand(
      "raster-clip",
      "Rasterize triangles given in clip space (conformance input, see docs/rasterizer.md)");
  cmd->add_option("file", *file, "JSON file: name, width, height, triangles with clip coordinates")
      ->required();
  cmd->add_option("--out", *out_dir,
                  "Directory for NAME.png, NAME.ids.pgm, NAME.count.pgm, NAME.depth.pfm")
      ->required();
  cmd->callback([file, out_dir] { run_raster_clip(*file, *out_dir); });
}

}  // namespace obscura::app
