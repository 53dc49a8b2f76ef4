#include "obscura/shading/surface_material.h"

#include <algorithm>
#include <variant>

#include "obscura/shading/fresnel.h"
#include "obscura/shading/ggx_energy.h"

namespace obscura::shading {

namespace {

float ggx_alpha(float roughness) {
  float r = std::clamp(roughness, 0.f, 1.f);
  return r * r;
}

Rgb min(Rgb a, float b) {
  return {std::min(a.r, b), std::min(a.g, b), std::min(a.b, b)};
}

}  // namespace

void set_metallic_roughness(SurfacePoint& p, const MetallicRoughnessPoint& mr, bool layered) {
  p.base = mr.base_color;
  p.metallic = mr.metallic;
  // The tracer's floor on α (twice its mirror threshold) keeps D finite in float.
  p.alpha = std::max(ggx_alpha(mr.roughness), 2e-3f);
  p.specular_strength = mr.specular;
  p.ior = mr.ior;
  const float f0 = ((mr.ior - 1) / (mr.ior + 1)) * ((mr.ior - 1) / (mr.ior + 1));
  p.specular = min(mr.specular_color * f0, 1.f);
  p.transmission = std::clamp(mr.transmission, 0.f, 1.f);
  // Layers only where the model has them (not over transmission, as in the tracer).
  p.clearcoat = layered ? std::clamp(mr.clearcoat, 0.f, 1.f) : 0.f;
  p.coat_alpha = std::max(ggx_alpha(layered ? mr.clearcoat_roughness : 0.f), 2e-3f);
  p.sheen = layered ? mr.sheen_color : Rgb();
  p.sheen_alpha = sheen_alpha(layered ? mr.sheen_roughness : 0.f);
}

SurfaceMaterial compile_surface_material(const Material& material) {
  SurfaceMaterial s;
  s.emission = material.emission;
  s.emission_texture = material.emission_texture;
  s.normal_texture = material.normal_texture;
  s.normal_scale = material.normal_scale;
  s.double_sided = material.double_sided;
  struct Visitor {
    SurfaceMaterial& s;
    void operator()(const DiffuseMaterial& m) const {
      s.model = SurfaceModel::kLambert;
      s.base = m.reflectance;
      s.base_texture = m.reflectance_texture;
    }
    void operator()(const obscura::PhongMaterial& m) const {
      s.model = m.blinn ? SurfaceModel::kBlinnPhong : SurfaceModel::kPhong;
      s.base = m.diffuse;
      s.specular = m.specular;
      s.shininess = std::max(0.f, m.shininess);
      s.base_texture = m.diffuse_texture;
    }
    void operator()(const ConductorMaterial& m) const {
      s.model = SurfaceModel::kConductor;
      s.eta = m.eta, s.k = m.k;
      s.alpha = std::max(ggx_alpha(m.roughness), kMinHighlightAlpha);
      s.multiple_scattering = multiple_scattering_color(
          fresnel_average([&](float mu) { return fresnel_conductor(mu, m.eta, m.k); }), s.alpha);
    }
    void operator()(const DielectricMaterial& m) const {
      s.model = SurfaceModel::kDielectric;
      s.ior = m.ior;
      s.transmittance = m.transmittance;
      s.alpha = std::max(ggx_alpha(m.roughness), kMinHighlightAlpha);
    }
    void operator()(const MetallicRoughnessMaterial& m) const {
      s.base = m.base_color;
      s.base_texture = m.base_color_texture;
      s.occlusion_texture = m.occlusion_texture;
      s.metallic_roughness = m;
      if (m.unlit) {
        s.model = SurfaceModel::kUnlit;
        return;
      }
      // KHR_materials_specular with a zero specular: a plain Lambertian surface (as the tracer).
      s.model = m.purely_diffuse() ? SurfaceModel::kLambert : SurfaceModel::kMetallicRoughness;
      // KHR_materials_clearcoat and _sheen (as the tracer: not over transmission).
      if (s.model == SurfaceModel::kMetallicRoughness && m.transmission == 0 &&
          (m.has_clearcoat() || m.has_sheen()))
        s.model = SurfaceModel::kLayeredMetallicRoughness;
    }
    void operator()(const EmissiveMaterial&) const { s.model = SurfaceModel::kBlack; }
  };
  std::visit(Visitor{s}, material.model);
  if (const auto* mr = std::get_if<MetallicRoughnessMaterial>(&material.model)) {
    s.alpha_mode = material.alpha_mode;
    s.alpha_cutoff = material.alpha_cutoff;
    s.base_alpha = mr->alpha;
    s.alpha_texture = mr->base_color_texture;
  }
  return s;
}

}  // namespace obscura::shading
