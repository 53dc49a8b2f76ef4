#include "obscura/trace/light_set.h"

#include <algorithm>
#include <cmath>

#include "obscura/math/sampling.h"

namespace obscura {

LightSet::LightSet(AreaLights area_lights, std::optional<EnvironmentLight> environment,
                   std::vector<PunctualLight> punctual, float scene_radius)
    : area_(std::move(area_lights)),
      environment_(std::move(environment)),
      punctual_(std::move(punctual)) {
  std::vector<float> power(kFirstPunctual + punctual_.size(), 0.f);
  power[kArea] = float(area_.power());
  // Distant light crossing the scene's bounding disk: π r² · π L̄.
  if (environment_)
    power[kEnvironment] =
        kPi * scene_radius * scene_radius * kPi * environment_->average_luminance();
  for (size_t i = 0; i < punctual_.size(); ++i)
    power[kFirstPunctual + i] = punctual_[i].power(scene_radius);
  auto any_light = [](const std::vector<float>& w) {
    return std::any_of(w.begin(), w.end(), [](float p) { return p > 0; });
  };
  if (any_light(power)) selection_all_ = Distribution1D(power);
  if (environment_ && environment_->is_constant()) power[kEnvironment] = 0;
  if (any_light(power)) selection_for_mis_ = Distribution1D(power);
}

std::optional<LightSample> LightSet::sample(Point3f p, float u_select, Point2f u,
                                            LightSampling which) const {
  if (empty(which)) return std::nullopt;
  float p_kind;
  auto kind = int(selection(which).sample_discrete(u_select, &p_kind));
  if (p_kind <= 0) return std::nullopt;
  // Area lights are entry 0, spanning [0, p_kind) of u_select: reuse it, rescaled, to pick the
  // triangle.
  float u_inner = std::min(u_select / p_kind, 0x1.fffffep-1f);
  if (kind >= kFirstPunctual) {
    std::optional<PunctualLight::Incident> in = punctual_[kind - kFirstPunctual].incident(p);
    if (!in) return std::nullopt;
    return LightSample{.wi = in->wi,
                       .distance = in->distance,
                       .radiance = in->radiance,
                       .pdf = p_kind,
                       .is_delta = true,
                       .position = p + in->wi * in->distance,
                       .normal = {}};
  }
  if (kind == kEnvironment) {
    // Selection gives the environment no probability when there is none; this holds even if a
    // degenerate selection ever picked its slot.
    if (!environment_) return std::nullopt;
    EnvironmentSample s = environment_->sample(u);
    if (s.pdf <= 0) return std::nullopt;
    return LightSample{
        .wi = s.wi, .radiance = s.radiance, .pdf = s.pdf * p_kind, .position = {}, .normal = {}};
  }
  std::optional<AreaLightSample> s = area_.sample(p, std::max(0.f, u_inner), u);
  if (!s) return std::nullopt;
  return LightSample{.wi = s->wi,
                     .distance = s->distance,
                     .radiance = s->radiance,
                     .pdf = s->pdf * p_kind,
                     .position = s->position,
                     .normal = s->normal,
                     .spectrum = s->spectrum};
}

float LightSet::pdf_area_light(Point3f p, uint32_t mesh, uint32_t primitive, Point3f light_point,
                               LightSampling which) const {
  if (empty(which)) return 0;
  return area_.pdf(p, mesh, primitive, light_point) * selection(which).probability(kArea);
}

float LightSet::pdf_environment(Vector3f wi, LightSampling which) const {
  if (!environment_ || empty(which)) return 0;
  float p_kind = selection(which).probability(kEnvironment);
  return p_kind > 0 ? environment_->pdf(wi) * p_kind : 0;
}

}  // namespace obscura
