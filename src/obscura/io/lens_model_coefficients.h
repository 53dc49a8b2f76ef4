// Lens models as a name and a list of coefficients: how the command line (--distortion), the JSON
// scene ("lens") and calibration files spell them. The names are lens_model_name()'s; the orders
// are the toolboxes' (camera/lens_distortion.h).
#pragma once

#include <string>
#include <vector>

#include "obscura/camera/lens_distortion.h"

namespace obscura {

// "opencv" with 4, 5, 8, 12 or 14 coefficients (k1 k2 p1 p2 [k3 [k4 k5 k6 [s1 s2 s3 s4 [τx τy]]]],
// as cv::calibrateCamera returns them), "kannala-brandt" with 4 (k1..k4), "ftheta" with 1 to 6
// (c1..c6), "equidistant", "equisolid", "stereographic" or "orthographic-fisheye" with none.
// Throws obscura::Error (without a location; callers add theirs) naming the expected count or
// the known names.
LensModel lens_model_from_coefficients(const std::string& name,
                                       const std::vector<double>& coefficients);

// The coefficients of `model` in its toolbox's order: opencv the shortest of 5, 8, 12 or 14 that
// holds every non-zero coefficient (5, as cv::calibrateCamera, for a pinhole without
// distortion); ftheta without trailing zeros; none for the classic fisheyes.
std::vector<double> lens_model_coefficients(const LensModel& model);

}  // namespace obscura
