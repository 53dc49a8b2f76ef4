#include "obscura/film/pass_schedule.h"

#include <algorithm>
#include <limits>
#include <string>

#include "obscura/math/error.h"

namespace obscura {

PassSchedule::PassSchedule(int samples, int largest_pass, OnCancel on_cancel,
                           const FrameControl& control)
    : samples_(samples),
      largest_pass_(std::max(1, largest_pass)),
      on_cancel_(on_cancel),
      control_(control),
      start_(std::chrono::steady_clock::now()) {
  if (samples <= 0)
    throw Error("samples", "must be a positive count; got " + std::to_string(samples));
  if (!(control.time_limit_s >= 0))
    throw Error("time limit", "must be ≥ 0 seconds; got " + std::to_string(control.time_limit_s));
}

double PassSchedule::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

bool PassSchedule::cancel_requested() const {
  return control_.cancel && control_.cancel->load(std::memory_order_relaxed);
}

bool PassSchedule::next(Pass& pass) {
  if (verdict_ != StopVerdict::kGoOn || done_ >= samples_) return false;
  pass = {done_, std::min(samples_, done_ + pass_size_)};
  pass_start_s_ = seconds();
  return true;
}

void PassSchedule::finish(const Pass& pass) {
  // The pass after this one: as large until two samples are in, then twice as large, up to the
  // largest (so 1, 1, 2, 4, …).
  const int next_size = pass.end > 1 ? std::min(largest_pass_, pass_size_ * 2) : pass_size_;
  StopVerdict own = StopVerdict::kGoOn;
  if (cancel_requested()) {
    own = StopVerdict::kCancelled;
  } else if (pass.end < samples_ && control_.time_limit_s > 0) {
    // At this pass's speed per sample, would the next one end after the limit?
    const double now = seconds(), pass_seconds = now - pass_start_s_;
    const double next_seconds =
        pass_seconds * std::min(samples_ - pass.end, next_size) / std::max(1, pass.size());
    if (now + next_seconds > control_.time_limit_s) own = StopVerdict::kTimeLimit;
  }
  verdict_ = control_.share ? control_.share->agree(own) : own;
  // Cancelled anywhere in the team, a renderer that abandons passes may have skipped pixels on
  // some part: the pass counts nowhere.
  if (verdict_ != StopVerdict::kCancelled || on_cancel_ == OnCancel::kCompletePass)
    done_ = pass.end;
  pass_size_ = next_size;
}

void PassSchedule::report(const ProgressCallback& progress, const Pass& pass, int units_done,
                          int units) const {
  if (!progress) return;
  // 64 bits: a time-limited render asks for up to 2^30 samples.
  const int64_t total = int64_t(samples_) * units;
  const int64_t now = int64_t(pass.first) * units + int64_t(pass.size()) * units_done;
  const int64_t scale = total / std::numeric_limits<int>::max() + 1;
  progress(int(now / scale), int(total / scale));
}

}  // namespace obscura
