#include "info_command.h"

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <variant>

#include "image_limit_option.h"
#include "obscura/io/scene_loader.h"
#include "obscura/scene/material_variants.h"
#include "scene_choice_options.h"

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

void run_info(const std::string& name, bool verbose, const SceneChoiceOptions& choice,
              const std::string& variant) {
  auto start = std::chrono::steady_clock::now();
  Scene scene = load_scene(name, gltf_load_options(choice, Shutter{}));
  if (!variant.empty()) select_material_variant(scene, variant);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);  // ru_maxrss is in kilobytes on Linux

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
  std::printf("load time    %.3f s\n", seconds);
  std::printf("memory       %s in the scene (%.1f bytes per stored triangle), %s peak process\n",
              megabytes(double(s.memory_bytes)).c_str(),
              s.unique_triangles ? double(s.memory_bytes) / double(s.unique_triangles) : 0.0,
              megabytes(double(usage.ru_maxrss) * 1024).c_str());
  if (verbose) {
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
  auto verbose = std::make_shared<bool>(false);
  auto variant = std::make_shared<std::string>();
  auto choice = std::make_shared<SceneChoiceOptions>();
  CLI::App* info =
      app.add_subcommand("info", "Print what a scene holds: counts, bounds, load time, memory");
  info->add_option("scene", *scene,
                   "A scene file or a built-in scene name; default: the Cornell box");
  info->add_flag("-v,--verbose", *verbose, "Also list materials, textures, lights and cameras");
  info->add_option("--gltf-variant", *variant,
                   "Select a glTF material variant (KHR_materials_variants) by name");
  add_scene_choice_options(*info, *choice);
  add_max_image_pixels_option(info);
  info->callback(
      [scene, verbose, choice, variant] { run_info(*scene, *verbose, *choice, *variant); });
}

}  // namespace obscura::app
