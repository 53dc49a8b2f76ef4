#include "option_ranges.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "obscura/math/error.h"
#include "usage_error.h"

namespace obscura::app {

namespace {

// Shortest text for a limit: 65536, 1e+06, 0.5.
std::string limit_text(double v) {
  char buffer[32];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  return ec == std::errc() ? std::string(buffer, end) : std::to_string(v);
}

template <typename T>
bool parse_whole(const std::string& text, T& value) {
  const char* first = text.data();
  const char* last = first + text.size();
  auto [end, ec] = std::from_chars(first, last, value);
  return ec == std::errc() && end == last && !text.empty();
}

}  // namespace

CLI::Validator integer_in(int64_t lo, int64_t hi) {
  std::string range = "an integer from " + std::to_string(lo) + " to " + std::to_string(hi);
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        int64_t v = 0;
        if (!parse_whole(text, v) || v < lo || v > hi)
          return "expected " + range + "; got '" + text + "'";
        return {};
      },
      "INT in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

CLI::Validator unsigned_64() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        uint64_t v = 0;
        if (!parse_whole(text, v))
          return "expected an integer from 0 to " +
                 std::to_string(std::numeric_limits<uint64_t>::max()) + "; got '" + text + "'";
        return {};
      },
      "UINT64");
}

CLI::Validator number_in_or_infinity(double lo, double hi) {
  std::string range = "a number from " + limit_text(lo) + " to " + limit_text(hi) + ", or inf";
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        double v = 0;
        if (!parse_whole(text, v) || std::isnan(v) || v < lo || (std::isfinite(v) && v > hi))
          return "expected " + range + "; got '" + text + "'";
        return {};
      },
      "NUMBER in [" + limit_text(lo) + ", " + limit_text(hi) + "] or inf");
}

CLI::Validator number_in(double lo, double hi) {
  std::string range = "a number from " + limit_text(lo) + " to " + limit_text(hi);
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        double v = 0;
        // from_chars also reads "nan" and "inf"; the isfinite test turns those away.
        if (!parse_whole(text, v) || !std::isfinite(v) || v < lo || v > hi)
          return "expected " + range + "; got '" + text + "'";
        return {};
      },
      "NUMBER in [" + limit_text(lo) + ", " + limit_text(hi) + "]");
}

void check_image_size(int64_t width, int64_t height, bool from_command_line) {
  std::string problem;
  if (width < 1 || width > kMaxImageSidePx || height < 1 || height > kMaxImageSidePx)
    problem = "each side must be from 1 to " + std::to_string(kMaxImageSidePx) + " pixels";
  else if (width * height > kMaxImagePixels)
    problem = "at most " + std::to_string(kMaxImagePixels) + " pixels (2^28) in all";
  if (problem.empty()) return;
  std::string message = "an image of " + std::to_string(width) + " x " + std::to_string(height) +
                        " pixels is too large: " + problem;
  if (from_command_line) throw UsageError("--width/--height: " + message);
  throw Error("image size", message);
}

}  // namespace obscura::app
