#include "sequence.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <numeric>
#include <optional>

#include <tbb/global_control.h>

#include "frame_files.h"
#include "frame_render.h"
#include "obscura/color/develop.h"
#include "obscura/io/image_io.h"
#include "obscura/io/image_reader.h"
#include "obscura/io/scene_loader.h"
#include "obscura/io/y4m_writer.h"
#include "obscura/math/error.h"
#include "obscura/render/camera_request.h"
#include "obscura/render/render_session.h"
#include "progress_bar.h"
#include "scene_choice_options.h"
#include "usage_error.h"

namespace obscura::app {

namespace {

// A developed video frame as bytes — its width and height (32 bits each), then its 8-bit codes —
// and back: what a rank keeps and sends rank 0 for the video.
std::vector<uint8_t> to_bytes(const DisplayImage& image) {
  std::vector<uint8_t> bytes(8 + image.codes.size());
  const int32_t size[2] = {image.width, image.height};
  std::memcpy(bytes.data(), size, sizeof size);
  for (size_t i = 0; i < image.codes.size(); ++i) bytes[8 + i] = uint8_t(image.codes[i]);
  return bytes;
}
DisplayImage from_bytes(const std::vector<uint8_t>& bytes) {
  DisplayImage image;
  int32_t size[2] = {0, 0};
  if (bytes.size() >= 8) std::memcpy(size, bytes.data(), sizeof size);
  image.width = size[0], image.height = size[1], image.channels = 3, image.bits = 8;
  if (size[0] <= 0 || size[1] <= 0 || bytes.size() != 8 + size_t(size[0]) * size[1] * 3)
    throw Error("sequence", "a video frame of " + std::to_string(bytes.size()) +
                                " bytes arrived, which is not a frame of the size it names");
  image.codes.assign(bytes.begin() + 8, bytes.end());
  return image;
}

// The frame rate as the stream header's ratio, in thousandths reduced (24 → 24:1, 29.97 →
// 2997:100).
Y4mSettings video_settings(double fps) {
  Y4mSettings settings;
  const long long thousandths = std::max(1LL, std::llround(fps * 1000));
  const long long divisor = std::gcd(thousandths, 1000LL);
  settings.fps_numerator = int(thousandths / divisor);
  settings.fps_denominator = int(1000 / divisor);
  return settings;
}

}  // namespace

void run_sequence(RenderOptions options, Team& team) {
  const FrameRange frames = parse_frame_range(options.frames);
  if (options.choice.time_s)
    throw UsageError("--time and --frames: each frame's time is frame / fps; give one of them");
  if (!options.shard.empty())
    throw UsageError(
        "--shard splits one frame; a sequence is split by frames (use mpirun, or "
        "give each task its own --frames range)");
  if (!(options.fps > 0 && options.fps <= 1e6))
    throw UsageError("--fps must be in (0, 1e6] frames per second");
  // Resolved once, here, on the options every frame copies (the renderer named, among them).
  resolve_render_options(options);
  const bool video = image_format_for_path(options.output) == ImageFormat::kY4m;
  if (!video) frame_path(options.output, frames.first);  // checks the pattern
  if (video && team.leads()) check_output_path(options.output, "--output");

  std::optional<tbb::global_control> thread_limit;
  if (options.threads > 0)
    thread_limit.emplace(tbb::global_control::max_allowed_parallelism, size_t(options.threads));
  const bool speaks = team.leads() && !options.quiet;
  InterruptGuard interrupt;

  // The video: opened by rank 0 once the frame size is known.
  std::unique_ptr<Y4mWriter> video_writer;
  std::vector<std::vector<uint8_t>> kept;         // MPI: this rank's video frames, in frame order
  std::optional<std::pair<int, int>> frame_size;  // known after the first scene this rank loads
  int rendered = 0, skipped = 0;
  RenderEnd worst = RenderEnd::kComplete;
  std::vector<int64_t> mine;

  // The scene is read once for the whole sequence and compiled once where nothing in it moves
  // (render/render_session.h); a glTF animation's skins and morph targets are posed again at
  // each frame's moment, and the renderers rebuild only those meshes.
  std::optional<Scene> scene;
  std::unique_ptr<RenderSession> session;

  team.open_counter();
  for (;;) {
    const int64_t ticket = team.take_ticket();
    if (ticket >= frames.size() || worst == RenderEnd::kInterrupted) break;
    // A cancel between frames (or during a frame's writing) renders no further frame.
    if (InterruptGuard::requested()) {
      worst = RenderEnd::kInterrupted;
      break;
    }
    mine.push_back(ticket);
    const int n = frames[ticket];
    RenderOptions frame_options = options;
    frame_options.choice.time_s = n / options.fps;
    if (!video) frame_options.output = frame_path(options.output, n);
    if (!video && frame_size &&
        finished_frame_exists(frame_options.output, frame_size->first, frame_size->second)) {
      ++skipped;
      continue;
    }
    frame_options.quiet = options.quiet || !team.leads();
    if (!scene) {
      scene = load_render_scene(frame_options, !video);
      scene->validate();
      session = std::make_unique<RenderSession>(*scene);
    }
    Camera camera = resolve_render_camera(*scene, frame_options, !video, nullptr);
    if (scene->poser) {
      const GltfLoadOptions at =
          gltf_load_options(frame_options.choice, requested_shutter(frame_options.camera));
      session->scene_changed(scene->pose(at.time_s, at.exposure_s));
    }
    // The first frame this rank prepares tells the frame size (the same for every frame): only
    // then is the check above still to be made.
    const bool size_was_known = frame_size.has_value();
    Bounds2i crop = camera.film.crop_pixels();
    frame_size = {crop.width(), crop.height()};
    if (!video && !size_was_known &&
        finished_frame_exists(frame_options.output, crop.width(), crop.height())) {
      ++skipped;
      continue;
    }
    ProgressBar bar("frame " + std::to_string(n), !speaks);
    RenderedFrame frame = render_frame(*session, camera, frame_options, {},
                                       [&](int done, int total) { bar.update(done, total); });
    bar.finish();
    worst = std::max(worst, frame.progress.end);
    ++rendered;
    if (!video) {
      if (frame.progress.partial() &&
          !format_keeps_metadata(image_format_for_path(frame_options.output))) {
        std::fprintf(stderr,
                     "obscura: %sframe %d stopped early and %s cannot say so: not written\n",
                     rank_prefix().c_str(), n, frame_options.output.c_str());
        continue;
      }
      worst = std::max(worst, write_frame(frame_options, frame_options.output, frame));
      continue;
    }
    DisplaySettings display = image_write_options(options.display).display;
    display.bits = 8;
    bool unfinished = false;  // a cancel during the glare: the video is not written
    DisplayImage developed =
        develop(pixels_of(frame.finished(&InterruptGuard::requested(), &unfinished)), display);
    if (unfinished) worst = RenderEnd::kInterrupted;
    if (team.alone()) {
      if (!video_writer)
        video_writer = std::make_unique<Y4mWriter>(options.output, developed.width,
                                                   developed.height, video_settings(options.fps));
      video_writer->write_frame(developed);
    } else {
      kept.push_back(to_bytes(developed));
    }
  }
  team.close_counter();

  // How the sequence ended, the same on every rank.
  const StopVerdict verdict = team.settle(worst == RenderEnd::kInterrupted ? StopVerdict::kCancelled
                                          : worst == RenderEnd::kTimeLimit ? StopVerdict::kTimeLimit
                                                                           : StopVerdict::kGoOn);
  const RenderEnd end = verdict == StopVerdict::kCancelled   ? RenderEnd::kInterrupted
                        : verdict == StopVerdict::kTimeLimit ? RenderEnd::kTimeLimit
                                                             : RenderEnd::kComplete;
  if (video && !team.alone() && end != RenderEnd::kInterrupted) {
    // Rank 0 writes the frames in order, each from the rank that rendered it; every other rank
    // sends its frames in the order it took them, which is frame order.
    const std::vector<int> owners = team.ticket_owners(mine, frames.size());
    if (team.leads()) {
      size_t next_own = 0;
      for (int owner : owners) {
        DisplayImage developed =
            from_bytes(owner == 0 ? std::move(kept[next_own++]) : team.receive(owner));
        if (!video_writer)
          video_writer = std::make_unique<Y4mWriter>(options.output, developed.width,
                                                     developed.height, video_settings(options.fps));
        video_writer->write_frame(developed);
      }
    } else {
      for (const std::vector<uint8_t>& bytes : kept) team.send(0, bytes);
    }
  }
  if (video) {
    if (end == RenderEnd::kInterrupted) {
      if (team.leads())
        std::fprintf(stderr,
                     "obscura: interrupted: %s is not written (a video is written whole; "
                     "render numbered frames to resume a sequence)\n",
                     options.output.c_str());
    } else if (video_writer) {
      video_writer->close();
      std::printf("%s\n", options.output.c_str());
    }
  }
  if (speaks) {
    std::string compiled;
    if (session)
      compiled = "; the scene read once, compiled " + std::to_string(session->compilations()) +
                 " time(s), brought up to date " + std::to_string(session->updates()) + " time(s)";
    std::fprintf(stderr, "sequence: %lld frames, %d rendered here, %d already there%s%s\n",
                 static_cast<long long>(frames.size()), rendered, skipped, compiled.c_str(),
                 end == RenderEnd::kInterrupted ? " [interrupted]" : "");
  }
  set_exit_status(exit_status_for(end));
}

}  // namespace obscura::app
