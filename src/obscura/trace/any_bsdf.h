// The closed set of BSDFs as one value type (std::variant), with the one dispatch point the
// integrators use. Each alternative follows the contract in bsdf.h.
#pragma once

#include <variant>

#include "obscura/trace/conductor_bsdf.h"
#include "obscura/trace/dielectric_bsdf.h"
#include "obscura/trace/lambertian_bsdf.h"
#include "obscura/trace/metallic_roughness_bsdf.h"
#include "obscura/trace/phong_bsdf.h"

namespace obscura {

class AnyBsdf {
 public:
  using Model =
      std::variant<LambertianBsdf, PhongBsdf, ConductorBsdf, DielectricBsdf, MetallicRoughnessBsdf>;
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
  bool is_transmissive() const { return std::holds_alternative<DielectricBsdf>(model_); }
  const Model& model() const { return model_; }

 private:
  Model model_;
};

}  // namespace obscura
