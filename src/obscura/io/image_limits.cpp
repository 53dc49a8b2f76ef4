#include "obscura/io/image_limits.h"

#include <atomic>
#include <cerrno>
#include <cstdlib>

#include "obscura/math/error.h"

namespace obscura {

namespace {

constexpr const char* kVariable = "OBSCURA_MAX_IMAGE_PIXELS";

// 0 means "not set": the environment variable or the default applies.
std::atomic<uint64_t> process_limit{0};

uint64_t parse_positive(const char* text) {
  const char* p = text;
  while (*p == ' ') ++p;
  if (*p < '0' || *p > '9') return 0;  // also refuses a sign
  errno = 0;
  char* end = nullptr;
  unsigned long long value = std::strtoull(p, &end, 10);
  if (errno == ERANGE || *end != '\0') return 0;
  return value;
}

std::string dimensions(int64_t width, int64_t height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

}  // namespace

uint64_t max_image_pixels() {
  if (uint64_t limit = process_limit.load()) return limit;
  const char* text = std::getenv(kVariable);
  if (!text || !*text) return kDefaultMaxImagePixels;
  uint64_t value = parse_positive(text);
  if (value == 0)
    throw Error(kVariable, std::string("'") + text +
                               "' is not a limit; expected a positive whole number of pixels, "
                               "e.g. 268435456 for 16384x16384");
  return value;
}

void set_max_image_pixels(std::optional<uint64_t> pixels) {
  if (pixels && *pixels == 0)
    throw Error("--max-image-pixels", "the limit must be a positive number of pixels");
  process_limit.store(pixels.value_or(0));
}

void check_decoded_size(const std::string& source, int64_t width, int64_t height, int64_t depth,
                        int64_t channels) {
  if (width <= 0 || height <= 0 || depth <= 0)
    throw Error(source, "image declares a size of " + dimensions(width, height) +
                            (depth != 1 ? "x" + std::to_string(depth) : "") +
                            " pixels; expected a positive width and height");
  if (depth != 1)
    throw Error(source, "image is a volume of depth " + std::to_string(depth) +
                            "; expected a flat (2D) image");
  if (channels <= 0 || channels > kMaxImageChannels)
    throw Error(source, "image declares " + std::to_string(channels) + " channels; expected 1 to " +
                            std::to_string(kMaxImageChannels));
  uint64_t row_values = 0;
  if (__builtin_mul_overflow(uint64_t(width), uint64_t(channels), &row_values) ||
      row_values > kMaxImageRowValues)
    throw Error(source, "image rows are " + std::to_string(width) + " pixels of " +
                            std::to_string(channels) + " channels; at most " +
                            std::to_string(kMaxImageRowValues) + " values per row are read");
  uint64_t limit = max_image_pixels();
  uint64_t pixels = 0, pixel_equivalents = 0;
  bool overflow = __builtin_mul_overflow(uint64_t(width), uint64_t(height), &pixels) ||
                  __builtin_mul_overflow(pixels, (uint64_t(channels) + 3) / 4, &pixel_equivalents);
  if (overflow || pixel_equivalents > limit)
    // Kept short: glTF loading shows it in a warning cut at 200 characters.
    throw Error(source, "image is " + dimensions(width, height) +
                            (channels > 4 ? "x" + std::to_string(channels) + " channels" : "") +
                            " (" + std::to_string(pixel_equivalents) +
                            " pixels), over the decoded-size limit of " + std::to_string(limit) +
                            "; raise it with --max-image-pixels or " + kVariable);
}

}  // namespace obscura
