#include "obscura/trace/whitted.h"

#include <cmath>

namespace obscura {

Rgb WhittedIntegrator::radiance(const TraceScene& scene, const Ray& ray, Sampler& sampler,
                                RayCounts& counts, FirstHit* first_hit) const {
  Ray unit = ray;
  unit.direction = normalize(ray.direction);
  return trace(scene, unit, sampler, counts, 0, first_hit);
}

Rgb WhittedIntegrator::trace(const TraceScene& scene, const Ray& ray, Sampler& sampler,
                             RayCounts& counts, int depth, FirstHit* first_hit) const {
  // Numbers for this vertex's light sample, drawn whether used or not (aligned dimensions).
  float u_select = sampler.next_1d();
  Point2f u_light = sampler.next_2d();

  depth == 0 ? ++counts.camera : ++counts.bounce;
  std::optional<SurfaceHit> hit = scene.intersect(ray);
  const LightSet& lights = scene.light_set();
  if (!hit) {
    const EnvironmentLight* env = lights.environment();
    return env ? env->radiance(ray.direction) : Rgb();
  }
  if (depth == 0) record_first_hit(scene, *hit, ray.direction, first_hit);
  const TraceMaterial& material = scene.material(hit->material);
  Vector3f wo = -ray.direction;
  Rgb L = dot(hit->geometric_normal, wo) > 0 ? material.emitted(*hit) : Rgb();

  AnyBsdf bsdf = material.bsdf_at(*hit);
  Normal3f n = bsdf.is_transmissive() ? hit->shading_normal : reflection_normal(*hit, wo);
  ShadingFrame frame = ShadingFrame::from_normal(to_vector(n));
  Vector3f wo_local = frame.to_local(wo);

  // 1. Direct light: one light sample and its shadow ray.
  if (!bsdf.is_delta() && !lights.empty()) {
    std::optional<LightSample> ls = lights.sample(hit->position, u_select, u_light);
    if (ls && ls->pdf > 0) {
      Vector3f wi_local = frame.to_local(ls->wi);
      Rgb f = bsdf.f(wo_local, wi_local) * std::abs(wi_local.z);
      if (!f.is_black() &&
          dot(hit->geometric_normal, wo) * dot(hit->geometric_normal, ls->wi) > 0) {
        Ray shadow = shadow_ray(scene, *hit, *ls);
        ++counts.shadow;
        if (!scene.occluded(shadow)) L += f * ls->radiance / ls->pdf;
      }
    }
  }

  // 2. Perfect specular surfaces: follow every delta lobe (reflection and refraction split
  //    deterministically by their weights, as Whitted did).
  if (bsdf.is_delta() && depth < settings_.max_depth) {
    // A delta BSDF picks its lobe from the 1D number: probe both sides of the Fresnel split.
    for (float u_lobe : {0.f, 0x1.fffffep-1f}) {
      std::optional<BsdfSample> bs = bsdf.sample(wo_local, u_lobe, {0.5f, 0.5f});
      if (!bs || bs->pdf <= 0) continue;
      // Weight = f·|cos|/pdf · (probability of the lobe), i.e. the lobe's full energy.
      Rgb weight = bs->f * std::abs(bs->wi.z);
      Vector3f wi = normalize(frame.to_world(bs->wi));
      L += weight * trace(scene, spawn_ray(scene, *hit, wi), sampler, counts, depth + 1, nullptr);
      if (bs->pdf >= 1) break;  // a single lobe (mirror, total internal reflection)
    }
  }
  return L;
}

}  // namespace obscura
