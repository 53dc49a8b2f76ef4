// How every renderer paces a frame: its samples (the tracer's samples per pixel, the
// rasterizer's accumulated frames) come in passes over the whole of its share of the frame, and
// between passes one rule decides whether to go on — cancelled, or would the next pass end after
// the time limit? — agreed by every part of a frame rendered together (film/work_share.h), so
// that a stopped frame is evenly sampled everywhere and its parts still assemble.
//
// Passes hold 1, 1, 2, 4, … samples, up to the renderer's largest pass (1 for a renderer whose
// samples are whole frames), so that a time limit can stop early in a render's life and long
// renders still take few stops.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>

#include "obscura/film/tiles.h"
#include "obscura/film/work_share.h"

namespace obscura {

// What stops a frame early, as the renderers' settings carry it.
struct FrameControl {
  double time_limit_s = 0;                    // ≥ 0; 0: none. At least one pass always runs.
  const std::atomic<bool>* cancel = nullptr;  // set from another thread (a signal handler)
  const WorkShare* share = nullptr;           // the team that agrees on stopping; null: alone
};

// What a renderer does with a pass under way when cancellation comes.
enum class OnCancel {
  kAbandonPass,   // skips what it has not started (the tracer's tiles): the pass does not count
  kCompletePass,  // finishes it (the rasterizer's frame): the pass counts
};

// One pass: samples [first, end) of every pixel (or frames [first, end)).
struct Pass {
  int first = 0, end = 0;
  int size() const { return end - first; }
};

class PassSchedule {
 public:
  // `samples` > 0 in all, passes of at most `largest_pass` (≥ 1). Throws obscura::Error for a
  // negative time limit. The clock starts here.
  PassSchedule(int samples, int largest_pass, OnCancel on_cancel, const FrameControl& control);

  // The next pass to render, or false when the frame is done or stopped.
  bool next(Pass& pass);
  // After rendering the pass next() gave: this process's verdict, then the team's (every part
  // calls this once per pass, so every part counts the same passes done).
  void finish(const Pass& pass);
  // Whether cancellation was asked for: a renderer skips what it has not started.
  bool cancel_requested() const;

  int done() const { return done_; }        // samples complete in every pixel
  int samples() const { return samples_; }  // asked for
  bool cancelled() const { return verdict_ == StopVerdict::kCancelled; }
  bool time_limited() const { return verdict_ == StopVerdict::kTimeLimit; }
  double seconds() const;  // since the schedule began

  // Progress over the whole frame while `pass` runs with `units_done` of its `units` (tiles,
  // say) finished, in samples × units, scaled down to fit the callback's int.
  void report(const ProgressCallback& progress, const Pass& pass, int units_done, int units) const;

 private:
  int samples_, largest_pass_;
  OnCancel on_cancel_;
  FrameControl control_;
  std::chrono::steady_clock::time_point start_;
  int done_ = 0, pass_size_ = 1;
  double pass_start_s_ = 0;
  StopVerdict verdict_ = StopVerdict::kGoOn;
};

}  // namespace obscura
