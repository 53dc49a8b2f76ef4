// libFuzzer target for `obscura merge`'s reader: the bytes are a partial film (an OpenEXR data file
// written by `render --shard`), read as merge reads each part — the EXR through CheckedImageInput,
// then the header attributes (part, renderer, tile size, channel layout, progress, finishing) and
// the channels they name — merged as the only part of a one-part frame, and finished. An
// obscura::Error is the expected outcome for bad input; anything else escaping, a crash, a
// sanitizer report, a leak or > 2 GB is a finding.
#include <unistd.h>
#include <cstdint>
#include <fstream>
#include <string>

#include "empty_folder.h"
#include "obscura/io/image_limits.h"
#include "obscura/math/error.h"
#include "shard_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // As image_fuzz: small decodes, so the limits flag defects rather than large legal images.
  static const bool limited = (obscura::set_max_image_pixels(uint64_t(1) << 16), true);
  (void)limited;
  // The reader opens files: each input goes to one file of this process's own.
  static const std::string path = obscura::fuzz::make_empty_folder("obscura-shard-fuzz") +
                                  "/part-" + std::to_string(getpid()) + ".exr";
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), std::streamsize(size));
  try {
    obscura::app::ShardFile shard = obscura::app::read_shard(path);
    obscura::app::RenderedFrame frame = obscura::app::merge_shards({shard});
    // Finished as merge finishes it (its layers and recipe, render/frame_finish.h), where that
    // stays cheap: the glare's PSF (its size follows the pixel pitch) and a blur thousands of
    // pixels wide are legal and merely slow, and their numbers were parsed and checked above.
    frame.finish.glare.reset();
    if (frame.finish.depth_of_field && frame.finish.depth_of_field->settings.max_coc_px > 32)
      frame.finish.depth_of_field.reset();
    frame.finished();
  } catch (const obscura::Error&) {
    // a clear error for bad input: the expected outcome
  }
  return 0;
}
