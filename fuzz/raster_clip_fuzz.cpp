// libFuzzer target for the input of `obscura raster-clip`: the bytes are its JSON file, parsed
// and checked from memory as read_raster_clip_file does after reading the file. An obscura::Error
// is the expected outcome for bad input; anything else escaping, a crash, a sanitizer report, a
// leak or > 2 GB is a finding.
#include <cstdint>
#include <string>

#include "obscura/io/json_reader.h"
#include "obscura/math/error.h"
#include "raster_clip_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    std::string text(reinterpret_cast<const char*>(data), size);
    obscura::app::parse_raster_clip(obscura::parse_json_text(text, "fuzz.json"), "fuzz.json");
  } catch (const obscura::Error&) {
    // a clear error for bad input: the expected outcome
  }
  return 0;
}
