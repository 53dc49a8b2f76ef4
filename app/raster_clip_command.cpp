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
#include "raster_clip_input.h"
#include "usage_error.h"

namespace obscura::app {

namespace {

namespace fs = std::filesystem;

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
  ClipTriangles input = read_raster_clip_file(file);
  const fs::path base = fs::path(out_dir) / input.name;
  RasterClipImages images = rasterize(input);
  write_image(base.string() + ".png", images.color);
  write_plain_pgm(base.string() + ".ids.pgm", input.width, input.height, images.ids);
  write_plain_pgm(base.string() + ".count.pgm", input.width, input.height, images.count);
  write_grey_pfm(base.string() + ".depth.pfm", images.depth);
  std::printf("%s\n", base.string().c_str());
}

}  // namespace

RasterClipImages rasterize(const ClipTriangles& input) {
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

  RasterClipImages images;
  size_t n = size_t(input.width) * input.height;
  images.ids.resize(n);
  images.count.resize(n);
  for (int y = 0; y < input.height; ++y)
    for (int x = 0; x < input.width; ++x) {
      size_t i = size_t(y) * input.width + x;
      images.ids[i] = target.object_id_at(x, y) == raster::kNoObject
                          ? 0
                          : input.ids[target.primitive_id_at(x, y)];
      images.count[i] = uint32_t(counts.color_at(x, y).r);
    }
  images.color = target.resolve_color();
  images.depth = target.depth_image();
  return images;
}

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
