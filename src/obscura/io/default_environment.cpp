#include "obscura/io/default_environment.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>

#include "obscura/io/scene_loader.h"
#include "obscura/io/texture_loader.h"
#include "obscura/math/error.h"

namespace obscura {

namespace {

// Mean radiance over the sphere of an equirectangular map (rows weighted by the solid angle they
// cover, ∝ sin θ), as luminance.
double mean_luminance(const Texture& map) {
  double sum = 0, weight = 0;
  for (int y = 0; y < map.height; ++y) {
    double w = std::sin(std::numbers::pi * (y + 0.5) / map.height);
    double row = 0;
    for (int x = 0; x < map.width; ++x) {
      Vector4f v = sample_texture(map, {(x + 0.5f) / map.width, (y + 0.5f) / map.height});
      row += 0.2126 * v.x + 0.7152 * v.y + 0.0722 * v.z;  // Rec. 709 luminance
    }
    sum += w * row;
    weight += w * map.width;
  }
  return weight > 0 ? sum / weight : 0;
}

Environment map_environment(Scene& scene, const std::string& file, float intensity) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw Error(file, "environment map does not exist (or is not a regular file)");
  Texture map = read_texture(file, TextureEncoding::kLinear, &scene.warnings);
  scene.input_files.push_back(file);
  map.wrap_v = TextureWrap::kClampToEdge;
  Environment env;
  env.texture = int32_t(scene.textures.size());
  env.intensity = intensity;
  scene.textures.push_back(std::move(map));
  return env;
}

// Inside the example scenes folder (io/scene_loader.h says where that is looked for).
constexpr const char* kStudioMap = "assets/envmaps/studio.exr";

Environment studio_environment(Scene& scene, const std::string& map_path, float intensity) {
  Environment env = map_environment(scene, map_path, intensity);
  // Normalised so that a white diffuse surface in it averages what it would in a uniform white
  // environment: the map's own scale is arbitrary (its photographed exposure).
  double mean = mean_luminance(scene.textures[env.texture]);
  if (mean > 0) env.intensity = float(intensity / mean);
  return env;
}

Environment white_environment(float intensity) {
  Environment env;
  env.color = Rgb(1.f);
  env.intensity = intensity;
  return env;
}

}  // namespace

EnvironmentChoice parse_environment_choice(const std::string& text) {
  if (text.empty()) throw Error("--environment", "expected auto, none, studio, white or a file");
  if (text == "auto") return {EnvironmentSource::kAuto, {}};
  if (text == "none") return {EnvironmentSource::kNone, {}};
  if (text == "studio") return {EnvironmentSource::kStudio, {}};
  if (text == "white") return {EnvironmentSource::kWhite, {}};
  return {EnvironmentSource::kFile, text};
}

bool scene_has_own_light(const Scene& scene) {
  if (!scene.lights.empty() || scene.environment) return true;
  for (const Instance& instance : scene.instances) {
    uint32_t index =
        instance.material >= 0 ? uint32_t(instance.material) : scene.meshes[instance.mesh].material;
    if (index >= scene.materials.size()) continue;
    const Material& m = scene.materials[index];
    if (!m.emission.is_black() && !m.emission_texture.valid()) return true;
  }
  return false;
}

EmitterLight emitter_light(const Scene& scene) {
  EmitterLight light;
  for (const Instance& instance : scene.instances) {
    if (instance.mesh >= scene.meshes.size()) continue;
    const uint32_t index = scene.material_of(instance);
    if (index >= scene.materials.size()) continue;
    const Material& m = scene.materials[index];
    if (m.emission.is_black() || m.emission_texture.valid()) continue;
    const Mesh& mesh = scene.meshes[instance.mesh];
    double area = 0;
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const Point3f a = instance.world_from_object(mesh.positions[mesh.indices[t]]);
      const Point3f b = instance.world_from_object(mesh.positions[mesh.indices[t + 1]]);
      const Point3f c = instance.world_from_object(mesh.positions[mesh.indices[t + 2]]);
      area += 0.5 * double(length(cross(b - a, c - a)));
    }
    ++light.emitters;
    light.power_w += std::numbers::pi * double(luminance(m.emission)) * area;
  }
  const Bounds3f b = scene.bounds();
  const double radius = b.empty() ? 0 : 0.5 * double(distance(b.min, b.max));
  const double surround = 4 * std::numbers::pi * std::numbers::pi * radius * radius;
  light.relative = surround > 0 ? light.power_w / surround : 0;
  return light;
}

namespace {

std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2g %%", 100 * fraction);
  return text;
}

}  // namespace

void apply_environment(Scene& scene, const EnvironmentChoice& choice) {
  switch (choice.source) {
    case EnvironmentSource::kAuto: {
      // Why the environment is added: no light at all, or emitters too faint to see by.
      std::string why = "the scene has no light of its own";
      if (scene_has_own_light(scene)) {
        if (!scene.lights.empty() || scene.environment) return;
        const EmitterLight emitters = emitter_light(scene);
        if (emitters.relative >= kFaintEmitterLight) return;
        why = "the scene's only light, " + std::to_string(emitters.emitters) +
              " emissive surface(s), would light it at " + percent(emitters.relative) +
              " of the studio environment's level (too faint to see it by; --environment none "
              "renders it by its own light alone)";
      }
      if (std::string map_path = find_scenes_file(kStudioMap); !map_path.empty()) {
        scene.environment = studio_environment(scene, map_path, choice.intensity);
        scene.warnings.push_back(why +
                                 "; it is lit by the studio environment "
                                 "(--environment none|studio|white|FILE to choose)");
      } else {
        scene.environment = white_environment(choice.intensity);
        scene.warnings.push_back(why + " and the studio map was not found (" +
                                 scenes_search_report(kStudioMap) +
                                 "); it is lit by a uniform white environment");
      }
      return;
    }
    case EnvironmentSource::kNone:
      scene.environment.reset();
      return;
    case EnvironmentSource::kStudio: {
      std::string map_path = find_scenes_file(kStudioMap);
      if (map_path.empty())
        throw Error("studio environment",
                    "the studio map " + std::string(kStudioMap) +
                        " was not found: " + scenes_search_report(kStudioMap));
      scene.environment = studio_environment(scene, map_path, choice.intensity);
      return;
    }
    case EnvironmentSource::kWhite:
      scene.environment = white_environment(choice.intensity);
      return;
    case EnvironmentSource::kFile:
      scene.environment = map_environment(scene, choice.file, choice.intensity);
      return;
  }
}

}  // namespace obscura
