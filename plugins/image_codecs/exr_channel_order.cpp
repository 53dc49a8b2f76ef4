#include "exr_channel_order.h"

#include <algorithm>
#include <array>

namespace obscura::codecs {

namespace {

std::string layer_of(const std::string& name) {
  size_t dot = name.rfind('.');
  return dot == std::string::npos ? "" : name.substr(0, dot);
}

int colour_rank(const std::string& name) {
  size_t dot = name.rfind('.');
  std::string suffix = dot == std::string::npos ? name : name.substr(dot + 1);
  static const std::array<const char*, 4> kColour = {"R", "G", "B", "A"};
  for (size_t i = 0; i < kColour.size(); ++i)
    if (suffix == kColour[i]) return int(i);
  return int(kColour.size());
}

}  // namespace

std::vector<std::string> exr_channel_order(std::vector<std::string> names) {
  // Stable: channels of equal rank keep the file's order.
  std::stable_sort(names.begin(), names.end(), [](const std::string& a, const std::string& b) {
    std::string la = layer_of(a), lb = layer_of(b);
    if (la != lb) return la < lb;  // "" (no layer) sorts first
    return colour_rank(a) < colour_rank(b);
  });
  return names;
}

}  // namespace obscura::codecs
