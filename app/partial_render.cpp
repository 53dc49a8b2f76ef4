#include "partial_render.h"

#include <atomic>
#include <csignal>
#include <cstdio>

namespace obscura::app {

namespace {

int status_to_return = 0;
std::atomic<int> interrupt_signal{0};
static_assert(std::atomic<int>::is_always_lock_free, "stored from a signal handler");

const char* reason(RenderEnd end) {
  return end == RenderEnd::kInterrupted ? "interrupted" : "time limit";
}

std::string what_was_done(const RenderProgress& p) {
  return std::to_string(p.done) + " of " + std::to_string(p.requested) + " " + p.unit +
         (p.left_out.empty() ? "" : "; left out: " + p.left_out);
}

}  // namespace

void interrupt_leaving_out(RenderProgress& progress, const std::string& step) {
  progress.end = RenderEnd::kInterrupted;
  progress.left_out += (progress.left_out.empty() ? "" : ", ") + step;
}

ImageMetadata partial_metadata(const RenderProgress& p) {
  ImageMetadata metadata;
  if (!p.partial()) return metadata;
  metadata.attributes.emplace_back("obscura:partial", reason(p.end));
  metadata.description =
      std::string("Partial render (") +
      (p.end == RenderEnd::kInterrupted ? "interrupted" : "stopped by the time limit") +
      "): " + what_was_done(p);
  return metadata;
}

std::string partial_note(const RenderProgress& p) {
  if (!p.partial()) return "";
  return std::string(" [partial: ") + reason(p.end) + ", " + what_was_done(p) + "]";
}

void warn_if_unmarked(const std::string& path, const RenderProgress& p, bool quiet) {
  if (quiet || !p.partial() || format_keeps_metadata(image_format_for_path(path))) return;
  std::fprintf(stderr,
               "warning: %s: this format cannot record that the image is partial; only the exit "
               "status (%d) says so\n",
               path.c_str(), exit_status_for(p.end));
}

void set_exit_status(int status) {
  status_to_return = status;
}

int exit_status() {
  return status_to_return;
}

int exit_status_for(RenderEnd end) {
  return end == RenderEnd::kInterrupted ? interrupted_exit_status()
         : end == RenderEnd::kTimeLimit ? kExitTimeLimit
                                        : 0;
}

void note_interrupt_signal(int signal) noexcept {
  interrupt_signal.store(signal);
}

int interrupted_exit_status() {
  return interrupt_signal.load() == SIGTERM ? kExitTerminated : kExitInterrupted;
}

}  // namespace obscura::app
