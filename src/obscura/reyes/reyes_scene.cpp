#include "obscura/reyes/reyes_scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace obscura::reyes {

namespace {

constexpr double kPi = std::numbers::pi;

// The tracer's equirectangular mapping (u = ½ along −Z growing towards +X, v = θ/π from +Y).
Point2f environment_uv(Vector3d d) {
  const double u = 0.5 + std::atan2(d.x, -d.z) / (2 * kPi);
  const double v = std::acos(std::clamp(d.y, -1.0, 1.0)) / kPi;
  return {float(u), float(v)};
}

}  // namespace

ReyesScene::ReyesScene(const Scene& scene) : scene_(&scene), motion_(scene) {
  scene.validate();
  materials_.reserve(scene.materials.size());
  for (const Material& m : scene.materials)
    materials_.push_back(shading::compile_surface_material(m));
  shading::add_scene_lights(scene, lights_);
  for (const Instance& instance : scene.instances) {
    const Mesh& mesh = scene.meshes[instance.mesh];
    moves_ = moves_ || instance.animated() || mesh.deforms();
    const Material& material = scene.materials[scene.material_of(instance)];
    if (!material.emission.is_black())
      if (auto light = shading::surface_light(mesh, instance.world_from_object, material.emission))
        lights_.surface.push_back(*light);
  }
  if (scene.environment) {
    const Environment& env = *scene.environment;
    environment_scale_ = env.color * env.intensity;
    environment_from_world_ = inverse(env.world_from_environment);
    Rgb mean = environment_scale_;
    if (env.texture >= 0 && scene.textures[size_t(env.texture)].width > 0) {
      environment_map_ = &scene.textures[size_t(env.texture)];
      const Texture& t = *environment_map_;
      // The mean radiance over the sphere: rows of an equirectangular map cover solid angle
      // ∝ sin θ.
      Rgb sum;
      double weight = 0;
      for (int y = 0; y < t.height; ++y) {
        const float w = float(std::sin(kPi * (y + 0.5) / t.height));
        for (int x = 0; x < t.width; ++x) {
          const Vector4f v = sample_texture(t, {(x + 0.5f) / t.width, (y + 0.5f) / t.height});
          sum += Rgb(v.x, v.y, v.z) * w;
        }
        weight += double(w) * t.width;
      }
      mean = environment_scale_ * (sum / float(weight));
    }
    lights_.ambient = mean;
  }
}

Rgb ReyesScene::background(Vector3d d) const {
  if (!scene_->environment) return {};
  if (!environment_map_) return environment_scale_;
  const Vector4f v = sample_texture(*environment_map_, environment_uv(environment_from_world_(d)));
  return Rgb(v.x, v.y, v.z) * environment_scale_;
}

}  // namespace obscura::reyes
