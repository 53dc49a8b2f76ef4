// The closed set of BSDFs as one value type (std::variant), with the one dispatch point the
// integrators use. Each alternative follows the contract in bsdf.h.
#pragma once

#include <variant>

#include "obscura/shading/fresnel.h"
#include "obscura/trace/conductor_bsdf.h"
#include "obscura/trace/dielectric_bsdf.h"
#include "obscura/trace/lambertian_bsdf.h"
#include "obscura/trace/layered_metallic_roughness_bsdf.h"
#include "obscura/trace/metallic_roughness_bsdf.h"
#include "obscura/trace/phong_bsdf.h"
#include "obscura/trace/transmissive_metallic_roughness_bsdf.h"

namespace obscura {

class AnyBsdf {
 public:
  using Model =
      std::variant<LambertianBsdf, PhongBsdf, ConductorBsdf, DielectricBsdf, MetallicRoughnessBsdf,
                   TransmissiveMetallicRoughnessBsdf, LayeredMetallicRoughnessBsdf>;
  template <class B>
  AnyBsdf(B bsdf) : model_(std::move(bsdf)) {}

  Rgb f(Vector3f wo, Vector3f wi) const {
    return std::visit([&](const auto& b) { return b.f(wo, wi); }, model_);
  }
  float pdf(Vector3f wo, Vector3f wi) const {
    return std::visit([&](const auto& b) { return b.pdf(wo, wi); }, model_);
  }
  std::optional<BsdfSample> sample(Vector3f wo, float uc, Point2f u) const {
    return std::visit([&](const auto& b) { return b.sample(wo, uc, u); }, model_);
  }
  // Tells the BSDF the local frame integrators evaluate it in (world ↔ local), once they have
  // built it: a BSDF with a direction of its own (a clear coat's normal) expresses it there.
  void orient(const ShadingFrame& frame) {
    if (auto* layered = std::get_if<LayeredMetallicRoughnessBsdf>(&model_)) layered->orient(frame);
  }
  // Only delta lobes: light sampling cannot help, f() is always zero.
  bool is_delta() const {
    return std::visit(
        [](const auto& b) {
          if constexpr (requires { b.is_delta(); }) return b.is_delta();
          return false;
        },
        model_);
  }
  // Transmits light to the other side, so the frame must not be flipped towards the viewer.
  bool is_transmissive() const {
    return std::holds_alternative<DielectricBsdf>(model_) ||
           std::holds_alternative<TransmissiveMetallicRoughnessBsdf>(model_);
  }
  // The surface's colour for the albedo AOV (what a denoiser wants): reflectance at normal
  // incidence, roughly.
  Rgb albedo() const;
  const Model& model() const { return model_; }

 private:
  Model model_;
};

inline Rgb AnyBsdf::albedo() const {
  struct Visitor {
    Rgb operator()(const LambertianBsdf& b) const { return b.reflectance; }
    Rgb operator()(const PhongBsdf& b) const { return b.diffuse + b.specular; }
    Rgb operator()(const ConductorBsdf& b) const {
      return shading::fresnel_conductor(1, b.eta, b.k);
    }
    Rgb operator()(const DielectricBsdf& b) const { return b.transmittance; }
    Rgb operator()(const MetallicRoughnessBsdf& b) const { return b.params.base_color; }
    Rgb operator()(const TransmissiveMetallicRoughnessBsdf& b) const { return b.base_color(); }
    Rgb operator()(const LayeredMetallicRoughnessBsdf& b) const { return b.base.params.base_color; }
  };
  return std::visit(Visitor{}, model_);
}

}  // namespace obscura
