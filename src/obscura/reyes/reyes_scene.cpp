#include "obscura/reyes/reyes_scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "obscura/shading/scene_lighting.h"

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
  for (const Material& m : scene.materials) {
    materials_.push_back(shading::compile_surface_material(m));
    Displacement d;
    d.scale = m.displacement;
    double texel_max = 1;
    if (m.displacement_texture.valid() &&
        scene.textures[size_t(m.displacement_texture.texture)].width > 0) {
      d.texture = &scene.textures[size_t(m.displacement_texture.texture)];
      d.reference = m.displacement_texture;
      // Bilinear lookups never leave the texels' range.
      texel_max = 0;
      for (int y = 0; y < d.texture->height; ++y)
        for (int x = 0; x < d.texture->width; ++x)
          texel_max = std::max(texel_max, std::abs(double(d.texture->texel(x, y, 0))));
    }
    d.largest = std::abs(d.scale) * texel_max;
    d.bound = m.displacement_bound ? double(*m.displacement_bound) : d.largest;
    displacements_.push_back(d);
  }
  shading::add_scene_lights(scene, lights_);
  shading::add_emissive_surface_lights(scene, lights_);
  lights_.ambient = shading::environment_mean_radiance(scene);
  for (const Instance& instance : scene.instances)
    moves_ = moves_ || instance.animated() || scene.meshes[instance.mesh].deforms();
  if (scene.environment) {
    const Environment& env = *scene.environment;
    environment_scale_ = env.color * env.intensity;
    environment_from_world_ = inverse(env.world_from_environment);
    if (env.texture >= 0 && scene.textures[size_t(env.texture)].width > 0)
      environment_map_ = &scene.textures[size_t(env.texture)];
  }
}

double Displacement::at(Point2f uv) const {
  if (!texture) return scale;
  return scale * double(sample_texture(*texture, reference.transform(uv)).x);
}

Rgb ReyesScene::background(Vector3d d) const {
  if (!scene_->environment) return {};
  if (!environment_map_) return environment_scale_;
  const Vector4f v = sample_texture(*environment_map_, environment_uv(environment_from_world_(d)));
  return Rgb(v.x, v.y, v.z) * environment_scale_;
}

}  // namespace obscura::reyes
