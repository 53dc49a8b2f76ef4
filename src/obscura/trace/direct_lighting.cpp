#include "obscura/trace/direct_lighting.h"

#include "obscura/math/sampling.h"

namespace obscura {

Rgb DirectLightingIntegrator::radiance(const TraceScene& scene, const Ray& ray,
                                       PixelSampler& sampler, RayCounts& counts) const {
  // The light sample's numbers are drawn even on a miss, so dimensions stay aligned per sample.
  float u_light = sampler.next_1d();
  Point2f u_point = sampler.next_2d();

  ++counts.camera;
  std::optional<SurfaceHit> hit = scene.intersect(ray);
  if (!hit) return {};
  const TraceMaterial& material = scene.material(hit->material);
  Vector3f wo = -ray.direction;

  // Light emitted by the surface itself (one-sided: the front face emits).
  Rgb result = dot(hit->geometric_normal, wo) > 0 ? material.emission : Rgb();
  if (scene.lights().empty() || material.diffuse.is_black()) return result;

  // Surfaces are two-sided for reflection: shade with the normal facing the viewer.
  Normal3f n = face_forward(hit->geometric_normal, wo);
  AreaLightSample light = scene.lights().sample(u_light, u_point);
  Vector3f to_light = light.position - hit->position;
  float distance2 = length_squared(to_light);
  if (distance2 <= 0) return result;
  Vector3f wi = to_light / std::sqrt(distance2);
  float cos_surface = dot(n, wi);
  float cos_light = -dot(light.normal, wi);
  if (cos_surface <= 0 || cos_light <= 0) return result;

  ++counts.shadow;
  Point3f origin = offset_ray_origin(hit->position, n, wi, scene.ray_epsilon());
  if (scene.occluded(origin, light.position)) return result;

  // L = f · Le · cosθ · cosθ' / d² / p_A, with the Lambertian f = ρ / π.
  float geometry = cos_surface * cos_light / distance2;
  result += material.diffuse * light.radiance * (kInvPi * geometry / light.pdf_area);
  return result;
}

}  // namespace obscura
