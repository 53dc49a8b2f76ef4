// Fresnel reflectance: how much light an interface reflects (the rest is transmitted or, in a
// conductor, absorbed). Unpolarized light; cosines are measured against the interface normal.
#pragma once

#include "obscura/color/rgb.h"

namespace obscura {

// Dielectric interface with relative index eta = η_inside / η_outside. A negative cos_theta_i
// means light arrives from inside. Returns 1 under total internal reflection.
float fresnel_dielectric(float cos_theta_i, float eta);

// Conductor with complex index η + ik (per channel), light arriving from a medium of index 1.
float fresnel_conductor(float cos_theta_i, float eta, float k);
Rgb fresnel_conductor(float cos_theta_i, Rgb eta, Rgb k);

// Schlick's approximation F0 + (1 − F0)(1 − cos θ)⁵, the form glTF's material model uses.
Rgb fresnel_schlick(Rgb f0, float cos_theta);
float fresnel_schlick(float f0, float cos_theta);

// Reflectance at normal incidence of a dielectric of relative index eta: ((η − 1)/(η + 1))².
float fresnel_f0(float eta);

}  // namespace obscura
