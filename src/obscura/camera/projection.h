// The closed set of projections a camera can have; code that depends on the kind dispatches
// once, with std::visit.
#pragma once

#include <string_view>
#include <variant>

#include "obscura/camera/calibrated_projection.h"
#include "obscura/camera/lens_system_projection.h"
#include "obscura/camera/orthographic.h"
#include "obscura/camera/perspective.h"
#include "obscura/camera/spherical.h"

namespace obscura {

using Projection = std::variant<Perspective, Orthographic, Equirectangular, Fisheye,
                                CalibratedProjection, LensSystemProjection>;

// "perspective", "orthographic", "spherical" (equirectangular), "fisheye", "calibrated" or
// "lens-system": the CLI's names.
std::string_view projection_name(const Projection& p);

// Helper for std::visit with one lambda per alternative.
template <typename... Fs>
struct Overloaded : Fs... {
  using Fs::operator()...;
};
template <typename... Fs>
Overloaded(Fs...) -> Overloaded<Fs...>;

}  // namespace obscura
