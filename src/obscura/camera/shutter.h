// The shutter: the interval during which the film is exposed. Camera and object motion are
// sampled inside it (motion blur); its length is the exposure time of the physical exposure.
//
// A rolling shutter (CMOS sensors read line by line) exposes each sensor line for the same
// duration, but line n starts n · line_time_s after the first, in the readout's order: a panning
// camera sees verticals lean, a spinning propeller bends. Camera::readout_delay_s gives a film
// point's delay; the interval some line is exposing is Camera::exposure_interval().
#pragma once

#include <optional>
#include <string_view>

namespace obscura {

// The order in which sensor lines are read: rows from the top or bottom, or columns from the left
// or right of the image.
enum class Readout { top_to_bottom, bottom_to_top, left_to_right, right_to_left };

// Whether the sensor lines are the image's rows (else its columns), and whether they are read
// from the image's bottom or right edge.
inline bool reads_rows(Readout r) {
  return r == Readout::top_to_bottom || r == Readout::bottom_to_top;
}
inline bool reads_backwards(Readout r) {
  return r == Readout::bottom_to_top || r == Readout::right_to_left;
}

struct Shutter {
  double open_s = 0;
  double close_s = 1.0 / 60;  // ≥ open_s; equal means an instantaneous exposure (no blur)
  double line_time_s = 0;     // ≥ 0; 0: a global shutter (every line at once)
  Readout readout = Readout::top_to_bottom;

  double duration_s() const { return close_s - open_s; }
  // The time for a uniform sample u ∈ [0, 1).
  double time_at(double u) const { return open_s + u * (close_s - open_s); }
};

// Throws obscura::Error naming the values when close < open, either is not finite, or the line
// time is negative or not finite.
void validate(const Shutter& s);

// "top-to-bottom", "bottom-to-top", "left-to-right", "right-to-left": the CLI and JSON names.
const char* readout_name(Readout r);
// The inverse; nothing for another name.
std::optional<Readout> readout_from_name(std::string_view name);

}  // namespace obscura
