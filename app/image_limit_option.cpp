#include "image_limit_option.h"

#include <cstdint>
#include <limits>
#include <string>

#include "obscura/io/image_limits.h"

namespace obscura::app {

void add_max_image_pixels_option(CLI::App* command) {
  command
      // Signed, so that a negative number is refused rather than wrapped to a huge one.
      ->add_option_function<int64_t>(
          "--max-image-pixels",
          [](const int64_t& pixels) { set_max_image_pixels(uint64_t(pixels)); },
          "Refuse to decode an input image of more pixels (width x height; images of more than "
          "4 channels count per 4 channels); default " +
              std::to_string(kDefaultMaxImagePixels) +
              " (8192x8192) or the environment variable OBSCURA_MAX_IMAGE_PIXELS")
      ->check(CLI::Range(int64_t(1), std::numeric_limits<int64_t>::max()));
}

}  // namespace obscura::app
