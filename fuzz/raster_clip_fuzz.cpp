// libFuzzer target for the input of `obscura raster-clip`: the bytes are its JSON file, parsed
// and checked from memory as read_raster_clip_file does after reading the file, then (up to
// 64 x 64 pixels) rasterized as the command does before writing its images. An obscura::Error
// is the expected outcome for bad input; anything else escaping, a crash, a sanitizer report, a
// leak or > 2 GB is a finding.
#include <cstdint>
#include <string>

#include "obscura/io/json_reader.h"
#include "obscura/math/error.h"
#include "obscura/raster/clip_triangles.h"
#include "raster_clip_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    std::string text(reinterpret_cast<const char*>(data), size);
    obscura::app::ClipTriangles input =
        obscura::app::parse_raster_clip(obscura::parse_json_text(text, "fuzz.json"), "fuzz.json");
    // Draw what parses, when small: the clipper and rasterizer see hostile coordinates too
    // (a 16384 x 16384 target would only measure memory).
    if (int64_t(input.width) * input.height <= 64 * 64) obscura::raster::draw_clip_triangles(input);
  } catch (const obscura::Error&) {
    // a clear error for bad input: the expected outcome
  }
  return 0;
}
