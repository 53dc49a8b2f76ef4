#include "obscura/trace/layered_metallic_roughness_bsdf.h"

#include <algorithm>

#include "obscura/math/sampling.h"
#include "obscura/shading/charlie_sheen.h"
#include "obscura/shading/fresnel.h"
#include "obscura/shading/ggx.h"
#include "obscura/shading/ggx_energy.h"
#include "obscura/shading/normal_map.h"

namespace obscura {

namespace {

// KHR_materials_clearcoat fixes the coat's index of refraction at 1.5: F0 = 0.04.
const float kCoatF0 = shading::fresnel_f0(1.5f);

}  // namespace

LayeredMetallicRoughnessBsdf::LayeredMetallicRoughnessBsdf(const MetallicRoughnessParameters& p,
                                                           const LayerParameters& l)
    : base(p),
      layers(l),
      // The floor MetallicRoughnessBsdf uses: never a delta lobe, D still finite in float.
      coat_(std::max(Ggx::alpha_from_roughness(l.clearcoat_roughness), 2 * Ggx::kSmoothAlpha)),
      sheen_alpha_(shading::sheen_alpha(l.sheen_roughness)),
      sheen_max_(l.sheen_color.max_component()) {
  layers.clearcoat = std::clamp(layers.clearcoat, 0.f, 1.f);
  const float f0 = base.dielectric_f0.max_component();
  const float color = luminance(p.base_color);
  base_albedo_ =
      (1 - p.metallic) * (color * (1 - f0 * p.specular) + f0 * p.specular) + p.metallic * color;
}

void LayeredMetallicRoughnessBsdf::set_coat_normal(Vector3f coat_world, Vector3f shading_world) {
  coat_world_ = coat_world, shading_world_ = shading_world;
  has_coat_normal_ = true;
}

void LayeredMetallicRoughnessBsdf::orient(const ShadingFrame& frame) {
  if (!has_coat_normal_) return;
  // The frame may look at the surface's back face: the coat turns over with the shading normal.
  Vector3f n = dot(frame.n, shading_world_) < 0 ? -coat_world_ : coat_world_;
  n = shading::keep_above_surface(frame.to_local(n), Vector3f(0, 0, 1));
  coat_tilted_ = n.x != 0 || n.y != 0;
  if (coat_tilted_) coat_frame_ = ShadingFrame::from_normal(normalize(n));
}

LayeredMetallicRoughnessBsdf::Choice LayeredMetallicRoughnessBsdf::choice(Vector3f wo) const {
  Choice c;
  const float mu_c = to_coat(wo).z;
  const float coat =
      layers.clearcoat > 0 && mu_c > 0
          ? layers.clearcoat * shading::ggx_schlick_albedo(kCoatF0, mu_c, coat_.alpha())
          : 0.f;
  const float e_s = sheen_max_ > 0 ? std::min(shading::sheen_albedo(wo.z, sheen_alpha_), 1.f) : 0.f;
  const float sheen = (1 - coat) * sheen_max_ * e_s;
  const float rest = (1 - coat) * (1 - sheen_max_ * e_s) * base_albedo_;
  const float total = coat + sheen + rest;
  // Floors keep each present lobe sampled: a smooth coat's highlight is far brighter than its
  // albedo suggests, and grazing angles raise the sheen's share well above its estimate.
  if (coat > 0) c.coat = std::clamp(total > 0 ? coat / total : 0.5f, 0.1f, 0.9f);
  if (sheen_max_ > 0) {
    float share = sheen + rest > 0 ? sheen / (sheen + rest) : 0.5f;
    c.sheen = (1 - c.coat) * std::clamp(share, 0.1f, 0.9f);
  }
  return c;
}

float LayeredMetallicRoughnessBsdf::coat_pdf(Vector3f wo_c, Vector3f wi_c) const {
  Vector3f h = wo_c + wi_c;
  if (length_squared(h) == 0) return 0;
  h = normalize(h);
  float o_h = dot(wo_c, h);
  return o_h > 0 ? coat_.visible_D(wo_c, h) / (4 * o_h) : 0.f;
}

Rgb LayeredMetallicRoughnessBsdf::f(Vector3f wo, Vector3f wi) const {
  if (wo.z <= 0 || wi.z <= 0) return {};
  Rgb result = base.f(wo, wi);
  if (sheen_max_ > 0) {
    float e_o = shading::sheen_albedo(wo.z, sheen_alpha_);
    float e_i = shading::sheen_albedo(wi.z, sheen_alpha_);
    float scale =
        std::min(1 - sheen_max_ * std::min(e_o, 1.f), 1 - sheen_max_ * std::min(e_i, 1.f));
    float lobe = shading::charlie_sheen(wo.z, wi.z, normalize(wo + wi).z, sheen_alpha_) *
                 shading::sheen_energy_bound(e_o, e_i);
    result = result * scale + layers.sheen_color * lobe;
  }
  if (layers.clearcoat > 0) {
    Vector3f wo_c = to_coat(wo), wi_c = to_coat(wi);
    if (wo_c.z > 0) {
      const float alpha = coat_.alpha();
      result =
          result * (1 - layers.clearcoat * shading::ggx_schlick_albedo(kCoatF0, wo_c.z, alpha));
      if (wi_c.z > 0) {
        Vector3f h = normalize(wo_c + wi_c);
        float lobe = shading::ggx_specular(wo_c.z, wi_c.z, h.z, alpha) *
                     shading::fresnel_schlick(kCoatF0, dot(wo_c, h)) * layers.clearcoat;
        // The integrator weighs f by the base frame's cosine; the coat's own is what counts.
        if (coat_tilted_) lobe *= wi_c.z / wi.z;
        result += Rgb(lobe);
      }
    }
  }
  return result;
}

float LayeredMetallicRoughnessBsdf::pdf(Vector3f wo, Vector3f wi) const {
  if (wo.z <= 0 || wi.z <= 0) return 0;
  Choice c = choice(wo);
  float p = (1 - c.coat - c.sheen) * base.pdf(wo, wi);
  if (c.sheen > 0) p += c.sheen * uniform_hemisphere_pdf();
  if (c.coat > 0) p += c.coat * coat_pdf(to_coat(wo), to_coat(wi));
  return p;
}

std::optional<BsdfSample> LayeredMetallicRoughnessBsdf::sample(Vector3f wo, float uc,
                                                               Point2f u) const {
  if (wo.z <= 0) return std::nullopt;
  Choice c = choice(wo);
  Vector3f wi;
  if (uc < c.coat) {
    Vector3f wo_c = to_coat(wo);
    Vector3f wi_c = reflect(wo_c, coat_.sample_visible_normal(wo_c, u));
    wi = coat_tilted_ ? coat_frame_.to_world(wi_c) : wi_c;
  } else if (uc < c.coat + c.sheen) {
    wi = sample_uniform_hemisphere(u);
  } else {
    // The base's own lobe choice reuses uc, rescaled to [0, 1) (exactly uc without layers).
    float rest = 1 - c.coat - c.sheen;
    float uc_base = std::min((uc - c.coat - c.sheen) / rest, 0x1.fffffep-1f);
    std::optional<BsdfSample> s = base.sample(wo, uc_base, u);
    if (!s) return std::nullopt;
    wi = s->wi;
  }
  if (wi.z <= 0) return std::nullopt;
  float p = pdf(wo, wi);
  if (p <= 0) return std::nullopt;
  return BsdfSample{.f = f(wo, wi), .wi = wi, .pdf = p};
}

}  // namespace obscura
