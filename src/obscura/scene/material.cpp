#include "obscura/scene/material.h"

namespace obscura {

namespace {

struct TypeName {
  std::string_view operator()(const DiffuseMaterial&) const { return "diffuse"; }
  std::string_view operator()(const PhongMaterial&) const { return "phong"; }
  std::string_view operator()(const ConductorMaterial&) const { return "conductor"; }
  std::string_view operator()(const DielectricMaterial&) const { return "dielectric"; }
  std::string_view operator()(const MetallicRoughnessMaterial&) const {
    return "metallic-roughness";
  }
  std::string_view operator()(const EmissiveMaterial&) const { return "emissive"; }
};

}  // namespace

std::string_view material_type_name(const MaterialModel& model) {
  return std::visit(TypeName{}, model);
}

const TextureRef& tangent_space_texture(const Material& material) {
  const auto* mr = std::get_if<MetallicRoughnessMaterial>(&material.model);
  return !material.normal_texture.valid() && mr && mr->has_clearcoat()
             ? mr->clearcoat_normal_texture
             : material.normal_texture;
}

Material diffuse_material(std::string name, Rgb reflectance, Rgb emission) {
  Material m;
  m.name = std::move(name);
  m.model = DiffuseMaterial{.reflectance = reflectance, .reflectance_texture = {}};
  m.emission = emission;
  return m;
}

float DielectricMaterial::ior_at(float wavelength_nm) const {
  if (!disperses()) return ior;
  constexpr double kD = 587.56, kF = 486.13, kC = 656.27;  // Fraunhofer d, F, C lines (nm)
  double b = (double(ior) - 1) / (abbe_number * (1 / (kF * kF) - 1 / (kC * kC)));
  double a = ior - b / (kD * kD);
  return float(a + b / (double(wavelength_nm) * wavelength_nm));
}

}  // namespace obscura
