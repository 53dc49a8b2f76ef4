#include "obscura/trace/path_tracer.h"

#include <algorithm>
#include <cmath>

#include "obscura/color/rgb_to_spectrum.h"

namespace obscura {

namespace {

using Strategy = PathTracerSettings::Strategy;

// The local frame a BSDF is evaluated in at a hit seen from direction wo (world). Reflection-only
// BSDFs reflect on both faces: their frame turns to the viewer's side. Transmissive ones keep +Z
// on the front (outside) face, where their index of refraction is measured from.
ShadingFrame frame_for(const SurfaceHit& hit, const AnyBsdf& bsdf, Vector3f wo) {
  Normal3f n = bsdf.is_transmissive() ? hit.shading_normal : reflection_normal(hit, wo);
  return ShadingFrame::from_normal(to_vector(n));
}

// Whether wi leaves the surface on the side the geometry allows: reflection stays on wo's side
// of the true (geometric) surface, transmission crosses it. This keeps shading normals from
// leaking light through surfaces.
bool consistent_sides(const SurfaceHit& hit, Vector3f wo, Vector3f wi, bool transmission) {
  float side_o = dot(hit.geometric_normal, wo), side_i = dot(hit.geometric_normal, wi);
  return transmission ? side_o * side_i < 0 : side_o * side_i > 0;
}

}  // namespace

Rgb PathTracer::radiance(const TraceScene& scene, const Ray& ray, Sampler& sampler,
                         RayCounts& counts, FirstHit* first_hit) const {
  return trace(scene, ray, nullptr, sampler, counts, first_hit);
}

Rgb PathTracer::spectral_radiance(const TraceScene& scene, const Ray& ray,
                                  SampledWavelengths& wavelengths, Sampler& sampler,
                                  RayCounts& counts, FirstHit* first_hit) const {
  return trace(scene, ray, &wavelengths, sampler, counts, first_hit);
}

Rgb PathTracer::trace(const TraceScene& scene, const Ray& camera_ray,
                      SampledWavelengths* wavelengths, Sampler& sampler, RayCounts& counts,
                      FirstHit* first_hit) const {
  const LightSet& lights = scene.light_set();
  const bool use_light_sampling = settings_.strategy != Strategy::kBsdfOnly;
  const bool use_bsdf_hits = settings_.strategy != Strategy::kLightOnly;
  const LightSampling light_sampling = use_bsdf_hits ? LightSampling::kForMis : LightSampling::kAll;
  Rgb L, beta(1.f);
  Ray ray = camera_ray;
  ray.direction = normalize(ray.direction);
  bool specular_bounce = true;  // the camera "sample" is a delta: count emission fully
  float bsdf_pdf = 0;           // of the direction that led to the current vertex
  float eta_scale = 1;          // radiance scaling by refraction, undone for Russian roulette
  Point3f previous = ray.origin;

  for (int depth = 0;; ++depth) {
    depth == 0 ? ++counts.camera : ++counts.bounce;
    std::optional<SurfaceHit> hit = scene.intersect(ray);

    // 1. Escaped: the environment's light, MIS-weighted against having sampled it directly.
    if (!hit) {
      if (const EnvironmentLight* env = lights.environment()) {
        Rgb le = env->radiance(ray.direction);
        if (wavelengths) le = lift_illuminant(le, *wavelengths);
        if (specular_bounce)
          L += beta * le;
        else if (use_bsdf_hits)
          L += beta * le *
               (use_light_sampling ? power_heuristic(bsdf_pdf, lights.pdf_environment(
                                                                   ray.direction, light_sampling))
                                   : 1.f);
      }
      break;
    }
    if (depth == 0) record_first_hit(scene, *hit, ray.direction, first_hit);
    const TraceMaterial& material = scene.material(hit->material);
    Vector3f wo = -ray.direction;
    // Reaching a closed volume's boundary from inside: what its medium absorbed on the way.
    if (material.absorbs_inside() && dot(hit->geometric_normal, wo) < 0)
      beta *= wavelengths ? material.transmittance_inside(hit->t, *wavelengths)
                          : material.transmittance_inside(hit->t);

    // 2. Hit an emitter's front face: its light, MIS-weighted against light sampling.
    if (material.emits()) {
      Rgb le = material.emitted_towards(*hit, wo);
      if (wavelengths && !le.is_black())
        le = lift_emission(le, material.emission_spectrum(), *wavelengths);
      if (le.is_black()) {
      } else if (specular_bounce) {
        L += beta * le;
      } else if (use_bsdf_hits) {
        float light_pdf = use_light_sampling
                              ? lights.pdf_area_light(previous, hit->mesh, hit->primitive,
                                                      hit->position, light_sampling)
                              : 0.f;
        L += beta * le * power_heuristic(bsdf_pdf, light_pdf);
      }
    }
    if (depth + 1 >= settings_.max_depth) break;

    // A dispersive refraction sends each wavelength its own way: follow the hero alone.
    if (wavelengths && material.disperses() && !wavelengths->secondary_terminated()) {
      wavelengths->terminate_secondary();
      beta = Rgb(beta[0], 0, 0);
    }
    AnyBsdf bsdf = material.bsdf_at(*hit, wavelengths);
    ShadingFrame frame = frame_for(*hit, bsdf, wo);
    bsdf.orient(frame);
    Vector3f wo_local = frame.to_local(wo);
    const bool sample_light =
        use_light_sampling && !bsdf.is_delta() && !lights.empty(light_sampling);
    const bool roulette = depth + 1 >= settings_.roulette_depth;

    // Numbers for this vertex, at the same dimensions path by path. Drawn only here, past the
    // exits above, which need none: a path that escapes (most camera rays under an environment)
    // or ends draws nothing more. Numbers this vertex will not use (no light to sample, no
    // roulette yet) are skipped rather than computed; as the sampler's numbers depend only on
    // the dimension, every number used is the same as when all are drawn up front.
    float u_light_select = 0, u_roulette = 0;
    Point2f u_light;
    if (sample_light) {
      u_light_select = sampler.next_1d();
      u_light = sampler.next_2d();
    } else {
      sampler.skip_1d();
      sampler.skip_2d();
    }
    float u_lobe = sampler.next_1d();
    Point2f u_bsdf = sampler.next_2d();
    if (roulette)
      u_roulette = sampler.next_1d();
    else
      sampler.skip_1d();

    // 3. Next-event estimation: a light sample, shadow ray, MIS weight against the BSDF.
    if (sample_light) {
      std::optional<LightSample> ls =
          lights.sample(hit->position, u_light_select, u_light, light_sampling);
      if (ls && ls->pdf > 0 && !ls->radiance.is_black()) {
        Rgb le =
            wavelengths ? lift_emission(ls->radiance, ls->spectrum, *wavelengths) : ls->radiance;
        Vector3f wi_local = frame.to_local(ls->wi);
        Rgb f = bsdf.f(wo_local, wi_local) * std::abs(wi_local.z);
        bool transmission = wi_local.z * wo_local.z < 0;
        if (!f.is_black() && consistent_sides(*hit, wo, ls->wi, transmission)) {
          Ray shadow = shadow_ray(scene, *hit, *ls);
          ++counts.shadow;
          if (!scene.occluded(shadow)) {
            float weight = ls->is_delta || !use_bsdf_hits
                               ? 1.f
                               : power_heuristic(ls->pdf, bsdf.pdf(wo_local, wi_local));
            L += beta * f * le * (weight / ls->pdf);
          }
        }
      }
    }

    // 4. Continue the path in a direction drawn from the BSDF.
    std::optional<BsdfSample> bs = bsdf.sample(wo_local, u_lobe, u_bsdf);
    if (!bs || bs->pdf <= 0 || bs->f.is_black()) break;
    Vector3f wi = normalize(frame.to_world(bs->wi));
    if (!consistent_sides(*hit, wo, wi, bs->is_transmission)) break;
    beta *= bs->f * (std::abs(bs->wi.z) / bs->pdf);
    specular_bounce = bs->is_delta;
    bsdf_pdf = bs->pdf;
    if (bs->is_transmission) eta_scale *= bs->eta * bs->eta;
    previous = hit->position;
    ray = spawn_ray(scene, *hit, wi);

    // 5. Russian roulette: continue with probability ∝ throughput, reweighting survivors.
    Rgb rr_beta = beta * eta_scale;
    if (roulette) {
      float q = std::max(0.f, 1 - rr_beta.max_component());
      if (u_roulette < q) break;
      beta = beta / (1 - q);
    }
    if (beta.is_black()) break;
  }
  return L;
}

}  // namespace obscura
