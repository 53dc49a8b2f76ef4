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

#include "obscura/io/atomic_file.h"
#include "obscura/io/image_io.h"
#include "obscura/math/error.h"
#include "obscura/raster/clip_triangles.h"
#include "raster_clip_input.h"
#include "usage_error.h"

namespace obscura::app {

namespace {

namespace fs = std::filesystem;

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

void run_raster_clip(const std::string& file, const std::string& out_dir) {
  if (!fs::is_directory(out_dir)) throw UsageError("--out: '" + out_dir + "' is not a directory");
  ClipTriangles input = read_raster_clip_file(file);
  const fs::path base = fs::path(out_dir) / input.name;
  raster::ClipTriangleImages images = raster::draw_clip_triangles(input);
  write_image(base.string() + ".png", images.color);
  write_plain_pgm(base.string() + ".ids.pgm", input.width, input.height, images.ids);
  write_plain_pgm(base.string() + ".count.pgm", input.width, input.height, images.count);
  write_grey_pfm(base.string() + ".depth.pfm", images.depth);
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
