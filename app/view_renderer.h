// The live view's render loop (`obscura view`, docs/view.md): one scene, loaded once and compiled
// once in a RenderSession, rendered again whenever the page moves the camera — first the
// rasterizer's frame, then (unless the rasterizer is the renderer asked for) the path tracer's,
// published pass by pass as its samples come in. A camera change cancels the frame under way
// through the pass schedule's cancel flag (film/pass_schedule.h): the tracer stops within a tile,
// the rasterizer within its frame. The scene file is watched: an edit is loaded, and one that
// fails to load leaves the last scene in place and its message on the page.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <tbb/global_control.h>

#include "obscura/camera/camera.h"
#include "obscura/color/develop.h"
#include "obscura/film/image.h"
#include "view_camera.h"

namespace obscura {
struct Scene;
class RenderSession;
}  // namespace obscura

namespace obscura::app {

// One published image and what the page shows beside it.
struct ViewFrame {
  uint64_t event = 0;       // the event that published it (ViewRenderer::wait_event)
  uint64_t generation = 0;  // the camera it shows: each change of camera or scene is a new one
  std::string renderer;     // the renderer's name: "raster", "path", …
  int pass = 0;             // passes published so far for this camera (the rasterizer's is 1)
  int samples = 0;          // samples per pixel in it (the rasterizer: frames accumulated)
  int samples_target = 0;   // asked for
  bool final = false;       // the last image of this camera
  double seconds = 0;       // from the camera change to this image
  Image image;              // the finished frame, linear RGB
  std::shared_ptr<const Image> depth, normal, id;  // the rasterizer's AOVs of the same camera
  std::shared_ptr<const Image> raster_image;       // and its image, for the wipe
  std::shared_ptr<const Camera> camera;            // the camera resolved, for the exports
  DisplaySettings display;
  std::string camera_json, command, scene_camera_json;

  // The image as a PNG: "beauty", "depth", "normal", "id" or "raster" (the rasterizer's image of
  // the same camera); empty for another name. Encoded on
  // first request and kept (a frame is shared by every client that asks for it).
  std::string png(const std::string& view) const;

 private:
  mutable std::mutex mutex_;
  mutable std::map<std::string, std::string> encoded_;
};

class ViewRenderer {
 public:
  // `arguments`: the `obscura view` command line after `view`. Loads the scene; throws what
  // loading it throws (UsageError, RequestError, obscura::Error), so a bad start fails at once.
  ViewRenderer(std::vector<std::string> arguments, bool watch);
  ~ViewRenderer();
  ViewRenderer(const ViewRenderer&) = delete;
  ViewRenderer& operator=(const ViewRenderer&) = delete;

  void start();  // the render thread
  void stop();   // cancels the frame under way, joins, and wakes every waiter

  // The page's camera (JSON, view_camera.h); returns it as now set. Throws RequestError.
  std::string set_camera(const std::string& json);
  // Focuses at raster point (x, y) of the latest frame: the depth there becomes the focus
  // distance. Returns the depth, or nothing where the frame sees nothing; `generation` receives
  // the camera's new generation.
  std::optional<double> focus_at(double x, double y, uint64_t* generation);
  // The depth along the optical axis at raster point (x, y) of the latest frame.
  std::optional<double> depth_at(double x, double y) const;

  std::shared_ptr<const ViewFrame> latest() const;
  // Blocks until an event after `after` (a frame or a message), `timeout`, or stop(); returns the
  // latest event's number (`after` when none came).
  uint64_t wait_event(uint64_t after, std::chrono::milliseconds timeout) const;
  // What the page is told of the latest event: the frame's numbers and camera, or a message.
  std::string event_json() const;
  bool stopping() const { return stop_; }

 private:
  void loop();
  void load();  // parses the arguments and loads the scene; throws
  bool scene_file_changed();
  void render(uint64_t generation, const ViewCamera& view);
  // Makes `frame` the latest unless a newer camera is asked for — or, with `even_if_stale`
  // (the rasterizer's preview), always: while the camera keeps moving, the last camera's image is
  // better than none.
  void publish(std::shared_ptr<ViewFrame> frame, bool even_if_stale = false);
  // `sticky`: a scene file that did not load, said until one loads; otherwise the message is of
  // the camera asked for, and the next camera clears it.
  void set_message(const std::string& message, bool sticky);

  std::vector<std::string> arguments_;
  bool watch_;
  std::filesystem::path scene_file_;  // empty: a built-in scene, not watched
  std::optional<std::filesystem::file_time_type> scene_stamp_;
  uintmax_t scene_size_ = 0;

  // Owned by the render thread once started.
  std::unique_ptr<Scene> scene_;
  std::unique_ptr<RenderSession> session_;
  double target_distance_m_ = 1;
  std::optional<tbb::global_control> thread_limit_;  // --threads

  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;  // the render thread waits for a new camera
  mutable std::condition_variable events_;   // clients wait for a new event
  ViewCamera view_;
  uint64_t generation_ = 1, event_ = 0;
  std::shared_ptr<const ViewFrame> latest_;
  std::string message_;  // the last error (a camera the scene cannot take, a broken edit)
  bool message_sticky_ = false;
  std::atomic<bool> cancel_{false}, stop_{false};
  std::thread thread_;
};

}  // namespace obscura::app
