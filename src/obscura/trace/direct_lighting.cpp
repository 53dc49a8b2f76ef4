#include "obscura/trace/direct_lighting.h"

#include <cmath>

#include "obscura/math/sampling.h"

namespace obscura {

Rgb DirectLightingIntegrator::radiance(const TraceScene& scene, const Ray& ray, Sampler& sampler,
                                       RayCounts& counts, FirstHit* first_hit) const {
  // The light sample's numbers are drawn even on a miss, so dimensions stay aligned per sample.
  float u_light = sampler.next_1d();
  Point2f u_point = sampler.next_2d();

  ++counts.camera;
  std::optional<SurfaceHit> hit = scene.intersect(ray);
  if (!hit) return {};
  record_first_hit(scene, *hit, ray.direction, first_hit);
  const TraceMaterial& material = scene.material(hit->material);
  Vector3f wo = normalize(-ray.direction);

  // Light emitted by the surface itself (one-sided: the front face emits).
  Rgb result = material.emitted_towards(*hit, wo);
  AnyBsdf bsdf = material.bsdf_at(*hit);
  if (bsdf.is_delta()) return result;

  // Surfaces are two-sided for reflection: shade with the shading normal on the viewer's side
  // (as Whitted and the path tracer do); light must arrive on the viewer's side of the geometry.
  Normal3f n = reflection_normal(*hit, wo);
  ShadingFrame frame = ShadingFrame::from_normal(to_vector(n));
  bsdf.orient(frame);
  const Vector3f wo_local = frame.to_local(wo);
  const float side = dot(hit->geometric_normal, wo);

  // 1. Every point, spot and directional light, each with its shadow ray: they have no area to
  //    sample, so all of them are taken (deterministic, as a rasterizer shades them).
  for (const PunctualLight& light : scene.light_set().punctual()) {
    std::optional<PunctualLight::Incident> in = light.incident(hit->position);
    if (!in || side * dot(hit->geometric_normal, in->wi) <= 0) continue;
    Vector3f wi_local = frame.to_local(in->wi);
    Rgb f = bsdf.f(wo_local, wi_local) * std::abs(wi_local.z);
    if (f.is_black()) continue;
    Ray shadow;
    shadow.origin =
        offset_ray_origin(hit->position, hit->geometric_normal, in->wi, scene.ray_epsilon());
    shadow.direction = in->wi;
    shadow.time = hit->time;
    if (std::isfinite(in->distance)) shadow.t_max = in->distance * (1 - 1e-4f);
    ++counts.shadow;
    if (!scene.occluded(shadow)) result += f * in->radiance;
  }

  // 2. One sample on the area lights, with its shadow ray.
  if (scene.lights().empty()) return result;
  AreaLightPoint light = scene.lights().sample_point(u_light, u_point);
  Vector3f to_light = light.position - hit->position;
  float distance2 = length_squared(to_light);
  if (distance2 <= 0) return result;
  Vector3f wi = to_light / std::sqrt(distance2);
  float cos_surface = dot(n, wi);
  float cos_light = -dot(light.normal, wi);
  if (cos_surface <= 0 || cos_light <= 0 || side * dot(hit->geometric_normal, wi) <= 0)
    return result;

  ++counts.shadow;
  Point3f origin = offset_ray_origin(hit->position, hit->geometric_normal, wi, scene.ray_epsilon());
  if (scene.occluded(origin, light.position, hit->time)) return result;

  // L = f · Le · cosθ · cosθ' / d² / p_A.
  float geometry = cos_surface * cos_light / distance2;
  Rgb f = bsdf.f(wo_local, frame.to_local(wi));
  result += f * light.radiance * (geometry / light.pdf_area);
  return result;
}

}  // namespace obscura
