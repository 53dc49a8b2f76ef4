#include "frame_files.h"

#include <cctype>
#include <charconv>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <utility>
#include <vector>

#include "obscura/io/finished_image.h"
#include "obscura/math/error.h"
#include "usage_error.h"

namespace obscura::app {

namespace {

constexpr int kMaxFrame = 100'000'000;

int parse_frame_number(const std::string& text, const std::string& range) {
  int value = 0;
  const char* end = text.data() + text.size();
  auto [at, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || at != end || value < -kMaxFrame || value > kMaxFrame)
    throw UsageError("--frames: expected FIRST:LAST[:STEP] with whole frame numbers (|n| ≤ " +
                     std::to_string(kMaxFrame) + "); got '" + range + "'");
  return value;
}

// The pattern's integer conversion: where it is ([start, end) of "%d" / "%04d"), its width and
// whether it pads with zeros.
struct Conversion {
  size_t start = 0, end = 0;
  int width = 0;
  bool zeros = false;
};

Conversion conversion_in(const std::string& pattern) {
  const std::string wrong =
      "--frames: the output must name each frame with one integer conversion such as "
      "out_%04d.exr (or be a .y4m video); got '" +
      pattern + "'";
  std::optional<Conversion> found;
  for (size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '%') continue;
    if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
      ++i;  // "%%" is a literal percent sign
      continue;
    }
    Conversion conversion{.start = i};
    size_t j = i + 1;
    if (j < pattern.size() && pattern[j] == '0') conversion.zeros = true, ++j;
    size_t digits = j;
    while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j])) &&
           j - digits < 2)
      conversion.width = conversion.width * 10 + (pattern[j++] - '0');
    if (j >= pattern.size() || pattern[j] != 'd' || found) throw UsageError(wrong);
    conversion.end = j + 1;
    found = conversion;
    i = j;
  }
  if (!found) throw UsageError(wrong);
  return *found;
}

// printf's "%0Wd" / "%Wd" for any width: the sign first, then zeros (or spaces before the sign).
std::string formatted(int frame, const Conversion& conversion) {
  std::string digits = std::to_string(std::llabs(frame));
  const size_t sign = frame < 0 ? 1 : 0;
  const size_t width = size_t(conversion.width);
  const size_t padding = width > digits.size() + sign ? width - digits.size() - sign : 0;
  if (conversion.zeros) return std::string(sign, '-') + std::string(padding, '0') + digits;
  return std::string(padding, ' ') + std::string(sign, '-') + digits;
}

}  // namespace

FrameRange parse_frame_range(const std::string& text) {
  std::vector<std::string> parts;
  for (size_t at = 0;;) {
    size_t colon = text.find(':', at);
    parts.push_back(text.substr(at, colon - at));
    if (colon == std::string::npos) break;
    at = colon + 1;
  }
  if (parts.size() < 2 || parts.size() > 3)
    throw UsageError("--frames: expected FIRST:LAST[:STEP] (e.g. 1:48 or 0:100:4); got '" + text +
                     "'");
  FrameRange range{.first = parse_frame_number(parts[0], text),
                   .last = parse_frame_number(parts[1], text),
                   .step = parts.size() == 3 ? parse_frame_number(parts[2], text) : 1};
  if (range.step < 1) throw UsageError("--frames: STEP must be at least 1; got '" + text + "'");
  if (range.last < range.first)
    throw UsageError("--frames: LAST is before FIRST in '" + text + "'");
  return range;
}

std::string frame_path(const std::string& pattern, int frame) {
  const Conversion conversion = conversion_in(pattern);
  std::string path;
  // "%%" elsewhere in the pattern stands for one "%".
  for (size_t i = 0; i < pattern.size(); ++i) {
    if (i == conversion.start) {
      path += formatted(frame, conversion);
      i = conversion.end - 1;
    } else {
      path += pattern[i];
      if (pattern[i] == '%' && i + 1 < pattern.size() && pattern[i + 1] == '%') ++i;
    }
  }
  return path;
}

bool finished_frame_exists(const std::string& path, int width, int height) {
  return finished_image_exists(path, width, height);
}

}  // namespace obscura::app
