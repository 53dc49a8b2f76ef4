// A render that ended before doing all it was asked to (Ctrl-C, or --time-limit with a sample
// count given): the image so far is written, and both the file and the exit status say so.
//
// Exit status: 0 complete; 3 stopped by --time-limit before the samples (tracer) or frames
// (rasterizer) asked for; 128 + the signal when interrupted, as shells report a command a signal
// ended: 130 for Ctrl-C (SIGINT), 143 for SIGTERM (a farm manager's or mpirun's cancel). In the
// file: "obscura:partial" = "time limit" or "interrupted" (EXR, PNG; Y4M as the header tag
// XOBSCURA_PARTIAL) and an ImageDescription naming what was done (EXR, PNG, TIFF, JPEG). HDR and
// PFM cannot hold either: a warning says so and the exit status remains.
#pragma once

#include <string>

#include "obscura/io/image_io.h"

namespace obscura::app {

inline constexpr int kExitTimeLimit = 3;
inline constexpr int kExitInterrupted = 130;  // SIGINT, or a cancel that came with no signal
inline constexpr int kExitTerminated = 143;   // SIGTERM

enum class RenderEnd { kComplete, kTimeLimit, kInterrupted };

struct RenderProgress {
  RenderEnd end = RenderEnd::kComplete;
  long long done = 0, requested = 0;  // samples per pixel, or accumulated frames
  std::string unit;                   // "samples per pixel", "frames"
  std::string left_out;               // what a cancel left out after the render: "glare", …
  bool partial() const { return end != RenderEnd::kComplete; }
};

// Marks the progress interrupted, `step` (the glare, the ground truth) left out by the cancel.
void interrupt_leaving_out(RenderProgress& progress, const std::string& step);

// The metadata that marks a partial image (empty for a complete one).
ImageMetadata partial_metadata(const RenderProgress& progress);
// " [partial: time limit, 12 of 64 samples per pixel]", or "" when complete.
std::string partial_note(const RenderProgress& progress);
// Warns (stderr, unless quiet) when `path`'s format cannot record that the image is partial.
void warn_if_unmarked(const std::string& path, const RenderProgress& progress, bool quiet);

// The status main() returns once the command has finished without an error (0 unless set).
void set_exit_status(int status);
int exit_status();
int exit_status_for(RenderEnd end);

// Records the signal that asked for the cancel (0: none yet). Async-signal-safe: the signal
// handler calls it.
void note_interrupt_signal(int signal) noexcept;
// The exit status of an interrupted command: 143 after SIGTERM, else 130.
int interrupted_exit_status();

}  // namespace obscura::app
