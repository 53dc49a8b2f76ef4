// render(): a frame into numpy arrays without copying the film, with the GIL released while the
// renderer runs, progress reported to a Python callable, and Ctrl-C stopping the render and
// raising obscura.RenderInterrupted (a KeyboardInterrupt) that carries the image so far.
//
// The renderer runs on a worker thread; the calling thread waits in short slices without the
// GIL and takes it back between slices to let Python see signals (PyErr_CheckSignals only runs
// handlers on the main thread, and only when asked) and to call the progress callback, so that
// neither ever runs on a thread Python does not know.
#include <pybind11/stl.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <set>
#include <thread>

#include "arrays.h"
#include "bindings.h"
#include "errors.h"
#include "obscura/render/renderer.h"
#include "obscura/render/renderer_backend.h"
#include "render_call.h"
#include "session.h"

namespace obscura::python {

namespace {

struct RenderResult {
  py::object image;
  py::dict aovs;
  double seconds = 0, rays = 0;
  int done = 0, requested = 0;
  bool cancelled = false, time_limited = false;
  std::vector<std::string> warnings;
};

// What the worker and the waiting thread share.
struct RenderJob {
  std::mutex mutex;
  std::condition_variable finished_signal;
  bool finished = false;
  std::atomic<bool> cancel{false};
  std::atomic<int> done{0}, total{0};
  std::atomic<int> progress_calls{0};  // bumps on every report, so a change is seen
  std::optional<RenderOutcome> outcome;
  std::exception_ptr error;
};

constexpr auto kWaitSlice = std::chrono::milliseconds(20);

RenderResult result_of(RenderOutcome&& outcome, const std::vector<std::string>& aov_names) {
  RenderResult r;
  r.image = image_to_array(std::move(outcome.image));
  if (outcome.aovs)
    for (const std::string& name : aov_names) {
      Image aov = name == "albedo"   ? outcome.aovs->albedo()
                  : name == "normal" ? outcome.aovs->normal()
                  : name == "depth"  ? outcome.aovs->depth()
                  : name == "range"  ? outcome.aovs->range()
                                     : outcome.aovs->id();
      r.aovs[py::str(name)] = image_to_array(std::move(aov));
    }
  r.seconds = outcome.seconds;
  r.rays = outcome.rays;
  r.done = outcome.done;
  r.requested = outcome.requested;
  r.cancelled = outcome.cancelled;
  r.time_limited = outcome.time_limited;
  r.warnings = std::move(outcome.warnings);
  return r;
}

[[noreturn]] void raise_interrupted(RenderResult&& result) {
  py::object image = result.image;
  py::dict aovs = result.aovs;
  py::object instance = py::reinterpret_borrow<py::object>(render_interrupted_type())(
      "render interrupted after " + std::to_string(result.done) + " of " +
      std::to_string(result.requested) + " samples per pixel");
  instance.attr("image") = image;
  instance.attr("aovs") = aovs;
  instance.attr("result") = py::cast(std::move(result));
  PyErr_SetObject(render_interrupted_type().ptr(), instance.ptr());
  throw py::error_already_set();
}

RenderResult render_frame_py(
    const py::object& scene_or_session, std::optional<Camera> camera, const std::string& renderer,
    std::optional<int> spp, const std::vector<std::string>& aov_names, int threads,
    std::optional<uint64_t> seed, const std::string& sampler, int max_depth, double time_limit,
    const py::object& progress, int msaa, const std::string& shading, bool cull, bool wireframe,
    int shadow_map, const std::string& raster_dof, int raster_samples, std::optional<bool> spectral,
    bool glare, std::optional<double> glare_strength, std::optional<int> glare_radius,
    std::optional<bool> flare, std::optional<double> reyes_shading_rate,
    std::optional<int> reyes_grid_size, std::optional<int> reyes_bucket_size,
    std::optional<int> reyes_pixel_samples, std::optional<int> reyes_eye_splits) {
  static const std::set<std::string> known{"albedo", "normal", "depth", "range", "id"};
  for (const std::string& name : aov_names)
    if (!known.count(name))
      throw py::value_error("aovs: unknown AOV '" + name +
                            "'; expected 'albedo', 'normal', 'depth', 'range' or 'id'");
  const std::optional<Renderer> kind = parse_renderer(renderer);  // unknown: render_call says so
  if (kind && !kind->capabilities().albedo &&
      std::count(aov_names.begin(), aov_names.end(), "albedo"))
    throw py::value_error("aovs: the renderer '" + std::string(kind->name()) +
                          "' has no 'albedo' AOV (it has 'normal', 'depth', 'range' and 'id')");
  if (threads < 0)
    throw py::value_error("threads: expected 0 (all cores) or a positive count, got " +
                          std::to_string(threads));
  if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw py::type_error("progress: expected a callable progress(done, total) or None");
  RenderRequest request{.renderer = renderer,
                        .frame = {.samples_per_pixel = spp,
                                  .seed = seed,
                                  .spectral = spectral,
                                  .glare = glare,
                                  .glare_strength = glare_strength,
                                  .glare_radius_px = glare_radius,
                                  .flare = flare,
                                  .reyes_shading_rate = reyes_shading_rate,
                                  .reyes_grid_size = reyes_grid_size,
                                  .reyes_bucket_size = reyes_bucket_size,
                                  .reyes_pixel_samples = reyes_pixel_samples,
                                  .reyes_eye_splits = reyes_eye_splits},
                        .sampler = sampler,
                        .max_depth = max_depth,
                        .time_limit_s = time_limit,
                        .aovs = !aov_names.empty(),
                        .msaa = msaa,
                        .shading = shading,
                        .cull = cull,
                        .wireframe = wireframe,
                        .shadow_map = shadow_map,
                        .raster_dof = raster_dof,
                        .raster_samples = raster_samples};

  // As `obscura render --threads`: a limit on TBB's pool for the render's duration.
  std::optional<tbb::global_control> thread_limit;
  if (threads > 0)
    thread_limit.emplace(tbb::global_control::max_allowed_parallelism, size_t(threads));

  // A Scene renders alone; a RenderSession keeps what it compiled (one render at a time).
  // The GIL is released while the render runs, so another Python thread may change the Scene
  // meanwhile (replace its meshes, textures, lights): the render works on a snapshot taken here,
  // with the GIL held, which no Python code can reach. (A session already holds its own copy.)
  std::optional<const Scene> snapshot;
  PythonSession* session = nullptr;
  if (py::isinstance<PythonSession>(scene_or_session))
    session = &scene_or_session.cast<PythonSession&>();
  else if (py::isinstance<Scene>(scene_or_session))
    snapshot.emplace(scene_or_session.cast<const Scene&>());
  else
    throw py::type_error("render: expected a Scene or a RenderSession, got " +
                         std::string(py::str(py::type::of(scene_or_session))));

  RenderJob job;
  const Camera* view = camera ? &*camera : nullptr;
  std::thread worker([&] {
    try {
      const ProgressCallback report = [&](int done, int total) {
        job.done = done;
        job.total = total;
        ++job.progress_calls;
      };
      std::optional<std::lock_guard<std::mutex>> one_at_a_time;
      if (session) one_at_a_time.emplace(session->busy);
      RenderOutcome outcome =
          session ? render_request(*session->session, view, request, &job.cancel, report)
                  : render_request(*snapshot, view, request, &job.cancel, report);
      std::lock_guard lock(job.mutex);
      job.outcome = std::move(outcome);
    } catch (...) {
      std::lock_guard lock(job.mutex);
      job.error = std::current_exception();
    }
    std::lock_guard lock(job.mutex);
    job.finished = true;
    job.finished_signal.notify_all();
  });

  std::optional<py::error_already_set> python_error;  // a signal, or the callback raised
  int reported = 0;
  for (bool finished = false; !finished;) {
    {
      py::gil_scoped_release release;
      std::unique_lock lock(job.mutex);
      finished = job.finished_signal.wait_for(lock, kWaitSlice, [&] { return job.finished; });
    }
    if (python_error) continue;  // already stopping: only wait
    if (PyErr_CheckSignals() != 0) {
      python_error.emplace();
      job.cancel = true;
      continue;
    }
    const int calls = job.progress_calls;
    if (!progress.is_none() && calls != reported) {
      reported = calls;
      try {
        progress(job.done.load(), job.total.load());
      } catch (py::error_already_set& e) {
        python_error.emplace(std::move(e));
        job.cancel = true;
      }
    }
  }
  {
    py::gil_scoped_release release;
    worker.join();
  }
  if (job.error) std::rethrow_exception(job.error);
  RenderResult result = result_of(std::move(*job.outcome), aov_names);
  if (python_error) {
    if (python_error->matches(PyExc_KeyboardInterrupt)) raise_interrupted(std::move(result));
    throw std::move(*python_error);
  }
  if (!progress.is_none() && job.progress_calls != reported)
    progress(job.done.load(), job.total.load());
  return result;
}

}  // namespace

void bind_render(py::module_& m) {
  py::class_<RenderResult>(m, "RenderResult",
                           "What render() returns: the image, the AOVs and how the render went.")
      .def_readonly("image", &RenderResult::image,
                    "Linear Rec.709 RGB, float32 (H, W, 3), sharing the film's memory.")
      .def_readonly("aovs", &RenderResult::aovs,
                    "The requested AOVs by name, float32 (H, W, C): 'albedo' (3), 'normal' "
                    "(3, world space), 'depth' (1, depth along the camera's optical axis in "
                    "metres, what Camera.unproject takes for planar projections; +inf where "
                    "nothing was hit), 'range' (1, distance along the ray in metres, what "
                    "unproject takes for spherical ones; +inf where nothing was hit), 'id' (1, "
                    "the mesh index, -1 where nothing was hit).")
      .def_readonly("seconds", &RenderResult::seconds, "Render time in seconds.")
      .def_readonly("rays", &RenderResult::rays, "Rays traced (tracer).")
      .def_readonly("samples_per_pixel", &RenderResult::done,
                    "Samples per pixel completed everywhere (rasterizer: frames).")
      .def_readonly("requested", &RenderResult::requested, "Samples per pixel asked for.")
      .def_readonly("cancelled", &RenderResult::cancelled, "Stopped by Ctrl-C or the callback.")
      .def_readonly("time_limited", &RenderResult::time_limited, "Stopped by time_limit.")
      .def_property_readonly(
          "partial", [](const RenderResult& r) { return r.cancelled || r.time_limited; },
          "Fewer samples than requested.")
      .def_readonly("warnings", &RenderResult::warnings, "What the user should know.")
      .def("__repr__", [](const RenderResult& r) {
        return "<obscura.RenderResult " + std::to_string(r.done) + "/" +
               std::to_string(r.requested) + " spp, " + std::to_string(r.seconds) + " s>";
      });

  m.def("render", &render_frame_py, py::arg("scene"), py::arg("camera") = py::none(), py::kw_only(),
        py::arg("renderer") = "path", py::arg("spp") = py::none(),
        py::arg("aovs") = std::vector<std::string>{}, py::arg("threads") = 0,
        py::arg("seed") = py::none(), py::arg("sampler") = "sobol", py::arg("max_depth") = 0,
        py::arg("time_limit") = 0.0, py::arg("progress") = py::none(), py::arg("msaa") = 1,
        py::arg("shading") = "phong", py::arg("cull") = false, py::arg("wireframe") = false,
        py::arg("shadow_map") = 1024, py::arg("raster_dof") = "accumulate",
        py::arg("raster_samples") = 32, py::arg("spectral") = py::none(), py::arg("glare") = false,
        py::arg("glare_strength") = py::none(), py::arg("glare_radius") = py::none(),
        py::arg("flare") = py::none(), py::arg("reyes_shading_rate") = py::none(),
        py::arg("reyes_grid_size") = py::none(), py::arg("reyes_bucket_size") = py::none(),
        py::arg("reyes_pixel_samples") = py::none(), py::arg("reyes_eye_splits") = py::none(),
        "Renders `camera` (default: the scene's camera) over `scene` (a Scene, or a "
        "RenderSession that keeps what it compiled for the next call) and returns a "
        "RenderResult whose .image is float32 (H, W, 3) linear RGB without a copy of the film. "
        "renderer: 'path', 'whitted', 'direct', 'raster' or 'reyes'; spp: samples per pixel "
        "(default: "
        "the scene file's render.spp, else 32, as `obscura render`); aovs: any of 'albedo' "
        "(tracer only), 'normal', 'depth' (along the optical axis), 'range' (along the ray), "
        "'id'; threads: 0 = all cores (the image is the same for any count); seed, sampler "
        "('sobol', 'independent'), max_depth (0: the renderer's "
        "default), time_limit (seconds, 0: none) as on `obscura render`. progress(done, total) "
        "is called from this thread as passes complete; raising from it stops the render and "
        "re-raises. The GIL is released while rendering. Ctrl-C stops the render and raises "
        "obscura.RenderInterrupted (a KeyboardInterrupt) with .image and .aovs so far. "
        "The rasterizer's options, as on `obscura render --renderer raster`: msaa (1, 4, 8), "
        "shading ('flat', 'gouraud', 'phong', 'blinn-phong'), cull, wireframe, shadow_map "
        "(texels, 0: none), raster_dof ('off', 'accumulate', 'post') and raster_samples "
        "(frames accumulated for depth of field and motion blur). Finishing, as on `obscura "
        "render`: spectral (path tracer), glare / glare_strength / glare_radius (diffraction "
        "glare), flare (ghost flares of a lens-system camera); REYES's knobs, as on `obscura "
        "render --renderer reyes`: reyes_shading_rate, reyes_grid_size, reyes_bucket_size, "
        "reyes_pixel_samples, reyes_eye_splits; each not given is the scene "
        "file's render block's, as seed is. Every renderer goes through the library's "
        "render_frame and every frame is finished by its finish_frame, as the CLI's are, so the "
        "images are the CLI's bit for bit.");
}

}  // namespace obscura::python
