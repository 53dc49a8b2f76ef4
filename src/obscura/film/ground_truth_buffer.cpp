#include "obscura/film/ground_truth_buffer.h"

#include <limits>

#include "obscura/math/error.h"

namespace obscura {

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInfinity = std::numeric_limits<float>::infinity();

// Channel indices, as kGroundTruthChannels lists them.
enum Channel : int {
  kZ = 0,
  kRange = 1,
  kP = 2,
  kN = 5,
  kNg = 8,
  kInstance = 11,
  kMaterial = 12,
  kForward = 13,
  kBackward = 15,
  kTime = 17,
};

}  // namespace

int ground_truth_channel(const std::string& name) {
  for (size_t c = 0; c < kGroundTruthChannels.size(); ++c)
    if (name == kGroundTruthChannels[c]) return int(c);
  return -1;
}

GroundTruthBuffer::GroundTruthBuffer(int width, int height)
    : image_(width, height, int(kGroundTruthChannels.size())) {
  image_.channel_names.assign(kGroundTruthChannels.begin(), kGroundTruthChannels.end());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      for (int c = 0; c < image_.channels; ++c) image_.at(x, y, c) = kNaN;
      image_.at(x, y, kZ) = image_.at(x, y, kRange) = kInfinity;
      image_.at(x, y, kInstance) = image_.at(x, y, kMaterial) = -1;
      image_.at(x, y, kTime) = 0;
    }
}

void GroundTruthBuffer::set_surface(int x, int y, const GroundTruthSurface& s) {
  image_.at(x, y, kZ) = float(s.z_m);
  image_.at(x, y, kRange) = float(s.range_m);
  for (int k = 0; k < 3; ++k) {
    image_.at(x, y, kP + k) = float(s.position[k]);
    image_.at(x, y, kN + k) = float(s.shading_normal[k]);
    image_.at(x, y, kNg + k) = float(s.geometric_normal[k]);
  }
  image_.at(x, y, kInstance) = float(s.instance);
  image_.at(x, y, kMaterial) = float(s.material);
}

void GroundTruthBuffer::set_forward_flow(int x, int y, std::optional<Vector2d> flow) {
  image_.at(x, y, kForward) = flow ? float(flow->x) : kNaN;
  image_.at(x, y, kForward + 1) = flow ? float(flow->y) : kNaN;
}

void GroundTruthBuffer::set_backward_flow(int x, int y, std::optional<Vector2d> flow) {
  image_.at(x, y, kBackward) = flow ? float(flow->x) : kNaN;
  image_.at(x, y, kBackward + 1) = flow ? float(flow->y) : kNaN;
}

void GroundTruthBuffer::set_time(int x, int y, double time_s) {
  image_.at(x, y, kTime) = float(time_s);
}

float GroundTruthBuffer::value(int x, int y, const std::string& name) const {
  const int c = ground_truth_channel(name);
  if (c < 0) throw Error("ground truth", "no channel named '" + name + "'");
  return image_.at(x, y, c);
}

}  // namespace obscura
