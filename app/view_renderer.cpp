#include "view_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "display_options.h"
#include "frame_render.h"
#include "obscura/film/aov_buffers.h"
#include "obscura/film/film.h"
#include "obscura/math/error.h"
#include "obscura/math/request_error.h"
#include "obscura/math/value_limits.h"
#include "obscura/render/render_session.h"
#include "obscura/render/renderer.h"
#include "obscura/render/renderer_backend.h"
#include "render_command.h"
#include "render_options.h"
#include "usage_error.h"
#include "view_images.h"

namespace obscura::app {

namespace {

using Clock = std::chrono::steady_clock;

// `obscura render`'s options parsed from `arguments` exactly as `obscura render` parses them.
// The options keep pointers into the parser (which options were given), so both live together.
struct ParsedRender {
  std::unique_ptr<CLI::App> parser;
  std::unique_ptr<RenderOptions> options;
};

ParsedRender parse_render(const std::vector<std::string>& arguments) {
  ParsedRender parsed{std::make_unique<CLI::App>("render", "render"),
                      std::make_unique<RenderOptions>()};
  CLI::App& render = *parsed.parser;
  RenderOptions& options = *parsed.options;
  render.add_option("scene", options.scene);
  add_frame_options(render, options);
  std::vector<std::string> reversed(arguments.rbegin(), arguments.rend());  // CLI11's order
  try {
    render.parse(reversed);
  } catch (const CLI::ParseError& e) {
    throw UsageError(e.what());
  }
  options.width_given = render.count("--width") > 0;
  options.height_given = render.count("--height") > 0;
  options.spp_given = render.count("--spp") > 0;
  options.seed_given = render.count("--seed") > 0;
  resolve_render_options(options);
  // Finishing needs the whole frame after rendering, which the live view does not wait for.
  if (options.glare.on || options.glare.strength || options.flare)
    throw UsageError("obscura view does not show glare or flare (render the frame to see them)");
  return parsed;
}

// The ends of the passes a renderer paces `samples` in (film/pass_schedule.h: 1, 1, 2, 4, … up to
// `largest`): the moments the film holds whole passes.
bool is_pass_end(int done, int samples, int largest) {
  int end = 0, size = 1;
  while (end < samples) {
    end = std::min(samples, end + size);
    if (end == done) return true;
    if (end > 1) size = std::min(largest, size * 2);
  }
  return false;
}

// The tracer's largest pass (trace/render.cpp).
constexpr int kTracerLargestPass = 64;
// Frames the rasterizer's preview accumulates, at most, for depth of field and motion blur.
constexpr int kPreviewEffectSamples = 8;

}  // namespace

std::string ViewFrame::png(const std::string& view) const {
  std::lock_guard lock(mutex_);
  auto it = encoded_.find(view);
  if (it != encoded_.end()) return it->second;
  std::string bytes;
  if (view == "beauty")
    bytes = beauty_png(image, display);
  else if (view == "depth" && depth)
    bytes = depth_png(*depth);
  else if (view == "normal" && normal)
    bytes = normal_png(*normal);
  else if (view == "id" && id)
    bytes = id_png(*id);
  else if (view == "raster" && raster_image)
    bytes = beauty_png(*raster_image, display);
  else
    return {};
  return encoded_[view] = std::move(bytes);
}

ViewRenderer::ViewRenderer(std::vector<std::string> arguments, bool watch)
    : arguments_(std::move(arguments)), watch_(watch) {
  load();
}

ViewRenderer::~ViewRenderer() {
  stop();
}

void ViewRenderer::load() {
  ParsedRender parsed = parse_render(render_arguments(arguments_, ViewCamera{}));
  RenderOptions& options = *parsed.options;
  if (options.threads > 0 && !thread_limit_)
    thread_limit_.emplace(tbb::global_control::max_allowed_parallelism, size_t(options.threads));
  auto scene = std::make_unique<Scene>(load_render_scene(options, false));
  std::vector<std::string> notes;
  const Camera camera = resolve_render_camera(*scene, options, false, &notes);
  if (!options.quiet) {
    for (const std::string& w : scene->warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    for (const std::string& n : notes) std::fprintf(stderr, "warning: %s\n", n.c_str());
  }
  // The page orbits about the point the camera looks at, as far ahead as the scene's centre.
  const Bounds3f bounds = scene->bounds();
  const Point3d eye = camera.world_from_camera.at(camera.shutter.open_s)(Point3d(0, 0, 0));
  const Point3d centre(bounds.center().x, bounds.center().y, bounds.center().z);
  const double distance = length(centre - eye);
  target_distance_m_ = std::isfinite(distance) && distance > 1e-6 ? distance : 1.0;
  if (scene_file_.empty() && std::filesystem::is_regular_file(options.scene))
    scene_file_ = options.scene;
  session_.reset();  // the session refers to the scene it replaces
  scene_ = std::move(scene);
  session_ = std::make_unique<RenderSession>(*scene_);
  std::lock_guard lock(mutex_);
  if (!view_.placed) {
    const ViewCamera start = initial_view_camera(camera, target_distance_m_);
    view_.position = start.position;
    view_.target = start.target;
    view_.up = start.up;
  }
}

bool ViewRenderer::scene_file_changed() {
  if (!watch_ || scene_file_.empty()) return false;
  std::error_code error;
  const auto stamp = std::filesystem::last_write_time(scene_file_, error);
  const uintmax_t size = error ? 0 : std::filesystem::file_size(scene_file_, error);
  if (error) return false;  // being replaced: looked at again on the next round
  const bool changed = scene_stamp_ && (*scene_stamp_ != stamp || scene_size_ != size);
  scene_stamp_ = stamp;
  scene_size_ = size;
  return changed;
}

void ViewRenderer::start() {
  scene_file_changed();  // the stamp of the scene as loaded
  thread_ = std::thread([this] { loop(); });
}

void ViewRenderer::stop() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
    cancel_ = true;
  }
  changed_.notify_all();
  events_.notify_all();
  if (thread_.joinable()) thread_.join();
}

std::string ViewRenderer::set_camera(const std::string& json) {
  std::string answer;
  {
    std::lock_guard lock(mutex_);
    view_ = parse_view_camera(json, view_);
    if (!message_sticky_) message_.clear();  // it was of the last camera
    ++generation_;
    cancel_ = true;  // the frame under way is of the old camera
    answer = nlohmann::json{{"generation", generation_}}.dump();
  }
  changed_.notify_all();
  return answer;
}

std::optional<double> ViewRenderer::depth_at(double x, double y) const {
  const std::shared_ptr<const ViewFrame> frame = latest();
  if (!frame || !frame->depth || !std::isfinite(x) || !std::isfinite(y)) return std::nullopt;
  const Image& depth = *frame->depth;
  const int px = int(std::floor(x)), py = int(std::floor(y));
  if (px < 0 || py < 0 || px >= depth.width || py >= depth.height) return std::nullopt;
  const double z = depth.at(px, py, 0);
  if (!std::isfinite(z) || z <= 0) return std::nullopt;
  return z;
}

std::optional<double> ViewRenderer::focus_at(double x, double y, uint64_t* generation) {
  const std::optional<double> depth = depth_at(x, y);
  if (!depth) return std::nullopt;
  {
    std::lock_guard lock(mutex_);
    view_.focus_distance_m = std::clamp(*depth, 1e-3, kMaxWorldCoordinateM);
    *generation = ++generation_;
    cancel_ = true;
  }
  changed_.notify_all();
  return depth;
}

std::shared_ptr<const ViewFrame> ViewRenderer::latest() const {
  std::lock_guard lock(mutex_);
  return latest_;
}

uint64_t ViewRenderer::wait_event(uint64_t after, std::chrono::milliseconds timeout) const {
  std::unique_lock lock(mutex_);
  events_.wait_for(lock, timeout, [&] { return stop_ || event_ > after; });
  return event_;
}

std::string ViewRenderer::event_json() const {
  std::lock_guard lock(mutex_);
  nlohmann::json json = {{"event", event_}, {"message", message_}};
  if (latest_) {
    const ViewFrame& f = *latest_;
    json["frame"] = {{"event", f.event},
                     {"generation", f.generation},
                     {"renderer", f.renderer},
                     {"pass", f.pass},
                     {"samples", f.samples},
                     {"samples_target", f.samples_target},
                     {"final", f.final},
                     {"seconds", f.seconds},
                     {"width", f.image.width},
                     {"height", f.image.height},
                     {"command", f.command},
                     {"scene_camera", f.scene_camera_json},
                     {"camera", nlohmann::json::parse(f.camera_json)}};
  }
  json["current_generation"] = generation_;
  return json.dump();
}

void ViewRenderer::publish(std::shared_ptr<ViewFrame> frame, bool even_if_stale) {
  {
    std::lock_guard lock(mutex_);
    if (frame->generation != generation_ && !even_if_stale) return;
    frame->event = ++event_;
    if (!message_sticky_) message_.clear();
    latest_ = std::move(frame);
  }
  events_.notify_all();
}

void ViewRenderer::set_message(const std::string& message, bool sticky) {
  {
    std::lock_guard lock(mutex_);
    message_ = message;
    message_sticky_ = sticky;
    ++event_;
  }
  events_.notify_all();
}

void ViewRenderer::loop() {
  uint64_t rendered = 0;
  while (true) {
    uint64_t generation;
    ViewCamera view;
    {
      std::unique_lock lock(mutex_);
      changed_.wait_for(lock, std::chrono::milliseconds(250),
                        [&] { return stop_ || generation_ != rendered; });
      if (stop_) return;
      generation = generation_;
      view = view_;
      cancel_ = false;
    }
    if (scene_file_changed()) {
      try {
        load();
        std::lock_guard lock(mutex_);
        message_.clear(), message_sticky_ = false;
        ++generation_;  // the same camera over the new scene
        continue;
      } catch (const std::exception& e) {
        // The last good scene stays; the page shows why the edit did not load.
        set_message(std::string("the scene file did not load, so the last one stays: ") + e.what(),
                    true);
      }
    }
    if (generation == rendered) continue;
    try {
      render(generation, view);
    } catch (const std::exception& e) {
      set_message(e.what(), false);
    }
    rendered = generation;
  }
}

void ViewRenderer::render(uint64_t generation, const ViewCamera& view) {
  const Clock::time_point start = Clock::now();
  const std::vector<std::string> arguments = render_arguments(arguments_, view);
  ParsedRender parsed = parse_render(arguments);
  RenderOptions& options = *parsed.options;
  std::vector<std::string> notes;
  const Camera camera = resolve_render_camera(*scene_, options, false, &notes);
  const Bounds2i crop = camera.film.crop_pixels();
  const DisplaySettings display = image_write_options(options.display).display;
  const std::string command = shell_command(arguments);
  const std::string camera_json = view_camera_json(view, camera);
  const std::string scene_json = scene_camera_json(camera, view);
  const auto shared_camera = std::make_shared<const Camera>(camera);
  auto frame_of = [&](const char* renderer, Image image) {
    auto frame = std::make_shared<ViewFrame>();
    frame->camera = shared_camera;
    frame->generation = generation;
    frame->renderer = renderer;
    frame->image = std::move(image);
    frame->display = display;
    frame->camera_json = camera_json;
    frame->command = command;
    frame->scene_camera_json = scene_json;
    frame->seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return frame;
  };

  // 1. The rasterizer's frame, with the depth and normals that click-to-focus and the AOV views
  //    read (its AOVs are the exact values at each pixel's centre).
  const Renderer asked = options.tracer.renderer;
  const Renderer raster = parse_renderer("raster").value();
  FrameSettings settings = frame_settings(options, scene_->render, WorkShare{});
  settings.cancel = &cancel_;
  const bool raster_only = asked == raster;
  FrameSettings raster_settings = settings;
  raster_settings.renderer = raster;
  // A preview before the tracer's frame: depth of field and motion blur from a few accumulated
  // frames keep it quick (the rasterizer asked for as the renderer keeps its own count).
  if (!raster_only)
    raster_settings.raster.effect_samples =
        std::min(raster_settings.raster.effect_samples, kPreviewEffectSamples);
  Film raster_film(crop.width(), crop.height());
  AovBuffers raster_aovs(crop.width(), crop.height(), false);
  const FrameStats raster_stats =
      session_->render(camera, raster_settings, raster_film, &raster_aovs);
  // The rasterizer completes the frame under way when cancelled, so it is shown even then.
  auto depth = std::make_shared<const Image>(raster_aovs.depth());
  auto normal = std::make_shared<const Image>(raster_aovs.normal());
  auto id = std::make_shared<const Image>(raster_aovs.id());
  auto raster_image = std::make_shared<const Image>(raster_film.to_image());
  {
    auto frame = frame_of("raster", *raster_image);
    frame->pass = 1;
    frame->samples = frame->samples_target = raster_stats.done;
    frame->final = raster_only && !raster_stats.cancelled;
    frame->depth = depth;
    frame->normal = normal;
    frame->id = id;
    frame->raster_image = raster_image;
    // Encoded before it is announced: the page asks for it at once, and by then the tracer below
    // holds every core.
    frame->png("beauty");
    publish(std::move(frame), true);
  }
  if (raster_only || cancel_) return;

  // 2. The renderer asked for, pass by pass: between two passes every tile is done and none of
  //    the next has started, so the film holds whole passes and is copied as it is.
  Film film(crop.width(), crop.height());
  std::optional<AovBuffers> aovs;
  if (options.tracer.aovs) aovs.emplace(crop.width(), crop.height());
  const int samples = settings.samples_per_pixel;
  int pass = 1;
  auto progress = [&](int done, int total) {
    if (cancel_ || total <= 0 || total % samples != 0) return;
    const int units = total / samples;
    if (done % units != 0) return;
    const int done_samples = done / units;
    if (done_samples >= samples || !is_pass_end(done_samples, samples, kTracerLargestPass)) return;
    auto frame = frame_of(asked.name(), film.to_image());
    frame->pass = ++pass;
    frame->samples = done_samples;
    frame->samples_target = samples;
    frame->depth = depth;
    frame->normal = normal;
    frame->id = id;
    frame->raster_image = raster_image;
    publish(std::move(frame));
  };
  const FrameStats stats =
      session_->render(camera, settings, film, aovs ? &*aovs : nullptr,
                       asked.capabilities().takes_samples_per_pixel ? ProgressCallback(progress)
                                                                    : ProgressCallback());
  if (stats.cancelled || cancel_) return;
  auto frame = frame_of(asked.name(), film.to_image());
  frame->pass = ++pass;
  frame->samples = stats.done;
  frame->samples_target = stats.requested;
  frame->final = true;
  frame->depth = depth;
  frame->normal = normal;
  frame->id = id;
  frame->raster_image = raster_image;
  publish(std::move(frame));
}

}  // namespace obscura::app
