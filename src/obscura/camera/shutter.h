// The shutter: the interval during which the film is exposed. Camera and object motion are
// sampled inside it (motion blur); its length is the exposure time of the physical exposure.
#pragma once

namespace obscura {

struct Shutter {
  double open_s = 0;
  double close_s = 1.0 / 60;  // ≥ open_s; equal means an instantaneous exposure (no blur)

  double duration_s() const { return close_s - open_s; }
  // The time for a uniform sample u ∈ [0, 1).
  double time_at(double u) const { return open_s + u * (close_s - open_s); }
};

// Throws obscura::Error naming the values when close < open or either is not finite.
void validate(const Shutter& s);

}  // namespace obscura
