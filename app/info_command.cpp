#include "info_command.h"

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <variant>

#include <tbb/global_control.h>

#include "image_limit_option.h"
#include "obscura/io/scene_loader.h"
#include "obscura/scene/material_variants.h"
#include "obscura/trace/trace_scene.h"
#include "scene_choice_options.h"
#include "usage_error.h"

namespace obscura::app {

namespace {

std::string with_commas(size_t n) {
  std::string digits = std::to_string(n), out;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

std::string megabytes(double bytes) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f MB", bytes / 1e6);
  return buffer;
}

const char* light_type(const LightModel& model) {
  if (std::holds_alternative<PointLight>(model)) return "point";
  if (std::holds_alternative<SpotLight>(model)) return "spot";
  return "directional";
}

double peak_resident_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) * 1024;  // ru_maxrss is in kilobytes on Linux
}

// Wall time and the CPU time of all the process's threads (user + system) since a start.
struct Stopwatch {
  std::chrono::steady_clock::time_point wall = std::chrono::steady_clock::now();
  double cpu = cpu_seconds();

  static double cpu_seconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    auto seconds = [](timeval t) { return double(t.tv_sec) + double(t.tv_usec) * 1e-6; };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
  }
  double wall_seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count();
  }
  double cpu_seconds_since() const { return cpu_seconds() - cpu; }
};

struct InfoOptions {
  bool verbose = false;
  bool bvh = false;  // also build the tracer's scene (Embree's BVH), timed
  int threads = 0;   // for the BVH build; 0 = all cores
  std::string variant;
};

void run_info(const std::string& name, const SceneChoiceOptions& choice,
              const InfoOptions& options) {
  if (options.threads < 0)
    throw UsageError("--threads must be 0 (all cores) or positive; got " +
                     std::to_string(options.threads));
  std::optional<tbb::global_control> thread_limit;
  if (options.threads > 0)
    thread_limit.emplace(tbb::global_control::max_allowed_parallelism, size_t(options.threads));
  const std::string& variant = options.variant;
  const double baseline_bytes = peak_resident_bytes();  // what the process held before loading
  Stopwatch load;
  Scene scene = load_scene(name, gltf_load_options(choice, Shutter{}));
  if (!variant.empty()) select_material_variant(scene, variant);
  const double seconds = load.wall_seconds(), cpu_seconds = load.cpu_seconds_since();
  double bvh_seconds = 0, bvh_cpu_seconds = 0, embree_bytes = 0;
  if (options.bvh) {
    Stopwatch build;
    auto device = std::make_shared<EmbreeDevice>();
    TraceScene trace(scene, device);
    bvh_seconds = build.wall_seconds();
    bvh_cpu_seconds = build.cpu_seconds_since();
    embree_bytes = double(device->memory_bytes());
  }
  const double peak_bytes = peak_resident_bytes();

  SceneStats s = scene.stats();
  Bounds3f b = scene.bounds();
  std::printf("scene        %s\n", scene.name.c_str());
  std::printf("triangles    %s rendered, %s stored\n", with_commas(s.triangles).c_str(),
              with_commas(s.unique_triangles).c_str());
  std::printf("vertices     %s\n", with_commas(s.vertices).c_str());
  std::printf("meshes       %zu\n", s.meshes);
  std::printf("instances    %zu (%zu animated)\n", s.instances,
              size_t(std::count_if(scene.instances.begin(), scene.instances.end(),
                                   [](const Instance& i) { return i.animated(); })));
  std::printf("materials    %zu\n", s.materials);
  std::printf("textures     %zu\n", s.textures);
  std::printf("lights       %zu point/spot/directional, %zu emissive instances%s\n", s.lights,
              s.emissive_meshes, scene.environment ? ", an environment" : "");
  std::printf("cameras      %zu\n", s.cameras);
  if (!scene.material_variants.empty()) {
    std::string names;
    for (const std::string& v : scene.material_variants)
      names.append(names.empty() ? "" : ", ").append(v).append(v == variant ? " (selected)" : "");
    std::printf("variants     %s\n", names.c_str());
  }
  if (b.empty())
    std::printf("bounds       empty\n");
  else
    std::printf("bounds       (%.4g, %.4g, %.4g) to (%.4g, %.4g, %.4g), size %.4g x %.4g x %.4g\n",
                b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z, b.max.x - b.min.x,
                b.max.y - b.min.y, b.max.z - b.min.z);
  std::printf("load time    %.3f s (%.3f s CPU)\n", seconds, cpu_seconds);
  if (options.bvh)
    std::printf("bvh build    %.3f s (%.3f s CPU) for the tracer's scene; Embree holds %s\n",
                bvh_seconds, bvh_cpu_seconds, megabytes(embree_bytes).c_str());
  std::printf(
      "memory       %s in the scene (%.1f bytes per stored triangle), %s peak process (%s above "
      "the %s before loading)\n",
      megabytes(double(s.memory_bytes)).c_str(),
      s.unique_triangles ? double(s.memory_bytes) / double(s.unique_triangles) : 0.0,
      megabytes(peak_bytes).c_str(), megabytes(peak_bytes - baseline_bytes).c_str(),
      megabytes(baseline_bytes).c_str());
  if (options.verbose) {
    for (const Material& m : scene.materials)
      std::printf("  material   %s (%s)\n", m.name.c_str(),
                  std::string(material_type_name(m.model)).c_str());
    for (const Texture& t : scene.textures)
      std::printf("  texture    %s %dx%d, %d channels\n", t.name.c_str(), t.width, t.height,
                  t.channels);
    for (const Light& l : scene.lights)
      std::printf("  light      %s (%s)\n", l.name.c_str(), light_type(l.model));
    for (const Camera& c : scene.cameras) {
      Vector2d fov = c.fov_degrees();
      std::printf("  camera     %s (%s, field of view %.4g x %.4g deg%s)\n", c.name.c_str(),
                  std::string(projection_name(c.projection)).c_str(), fov.x, fov.y,
                  c.world_from_camera.is_animated() ? ", moving" : "");
    }
  }
  for (const std::string& w : scene.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
}

}  // namespace

void add_info_command(CLI::App& app) {
  auto scene = std::make_shared<std::string>();
  auto options = std::make_shared<InfoOptions>();
  auto choice = std::make_shared<SceneChoiceOptions>();
  CLI::App* info =
      app.add_subcommand("info", "Print what a scene holds: counts, bounds, load time, memory");
  info->add_option("scene", *scene,
                   "A scene file or a built-in scene name; default: the Cornell box");
  info->add_flag("-v,--verbose", options->verbose,
                 "Also list materials, textures, lights and cameras");
  info->add_flag(
      "--bvh", options->bvh,
      "Also build the path tracer's scene (Embree's BVH) and report its time and memory");
  info->add_option("--threads", options->threads,
                   "Threads for the loaders and the BVH build (0 = all cores)");
  info->add_option("--gltf-variant", options->variant,
                   "Select a glTF material variant (KHR_materials_variants) by name");
  add_scene_choice_options(*info, *choice);
  add_max_image_pixels_option(info);
  info->callback([scene, choice, options] { run_info(*scene, *choice, *options); });
}

}  // namespace obscura::app
