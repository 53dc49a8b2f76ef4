#include "obscura/shading/scene_lighting.h"

#include <cmath>
#include <numbers>

namespace obscura::shading {

void add_emissive_surface_lights(const Scene& scene, PunctualLights& lights) {
  for (const Instance& instance : scene.instances) {
    const Material& material = scene.materials[scene.material_of(instance)];
    if (material.emission.is_black()) continue;
    if (auto light = surface_light(scene.meshes[instance.mesh], instance.world_from_object,
                                   material.emission))
      lights.surface.push_back(*light);
  }
}

Rgb environment_mean_radiance(const Scene& scene) {
  if (!scene.environment) return {};
  const Environment& env = *scene.environment;
  const Rgb scale = env.color * env.intensity;
  if (env.texture < 0) return scale;
  const Texture& t = scene.textures[size_t(env.texture)];
  Rgb sum;
  double weight = 0;
  for (int y = 0; y < t.height; ++y) {
    // Rows of an equirectangular map cover solid angle ∝ sin θ.
    float w = std::sin(std::numbers::pi_v<float> * (y + 0.5f) / t.height);
    for (int x = 0; x < t.width; ++x) {
      Vector4f v = sample_texture(t, {(x + 0.5f) / t.width, (y + 0.5f) / t.height});
      sum += Rgb(v.x, v.y, v.z) * w;
    }
    weight += double(w) * t.width;
  }
  return scale * (sum / float(weight));
}

}  // namespace obscura::shading
