// The files of a numbered sequence (`obscura render --frames A:B[:STEP] -o out_%04d.exr`): the
// frame range, counted rather than listed (a range of 200 M frames costs nothing until frames are
// rendered), each frame's file name, and whether a frame's file is already finished (resume).
#pragma once

#include <cstdint>
#include <string>

namespace obscura::app {

// The frame numbers of "A:B[:STEP]": A, A + STEP, … up to B inclusive.
struct FrameRange {
  int first = 0, last = 0, step = 1;
  int64_t size() const { return (int64_t(last) - first) / step + 1; }
  int operator[](int64_t index) const { return int(first + index * step); }
};

// Parses "A:B[:STEP]" (|A|, |B| ≤ 1e8, STEP ≥ 1, A ≤ B). Throws UsageError.
FrameRange parse_frame_range(const std::string& text);

// The output path of frame n: the pattern's one printf integer conversion (%d, %04d, %040d: any
// width up to 99) filled in, "%%" standing for "%". Throws UsageError for a pattern without
// exactly one such conversion.
std::string frame_path(const std::string& pattern, int frame);

// Whether `path` holds a finished frame: an image of width × height not marked partial whose
// every pixel reads back (a truncated or damaged file is rendered again).
bool finished_frame_exists(const std::string& path, int width, int height);

}  // namespace obscura::app
