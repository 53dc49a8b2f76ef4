// The lens prescription file: a table with one row per surface, object side first, as lens
// design books and patents print them (docs/camera.md, "Lens prescription files").
//
//   # comment (anywhere after '#')
//   radius_mm  thickness_mm  n_d  aperture_diameter_mm  [V_d]  [key=value …]
//
// Fields are separated by tabs or spaces. The four leading numbers are required; a fifth bare
// number is the Abbe number V_d of the medium after the surface (0: no dispersion). Then any of
// V_d=…, conic=…, A4=…, A6=…, … A16=… (an even asphere's conic constant and coefficients). The
// aperture stop is the row with radius 0 and n_d 0 ("air, stop"); its aperture is the stop's
// full opening. Radius 0 with n_d ≥ 1 is a flat refracting surface.
#pragma once

#include <string>
#include <string_view>

#include "obscura/camera/lens_prescription.h"

namespace obscura {

// Parses `text`; errors throw obscura::Error naming `source:line`, the field and what was
// expected. The prescription is validated (lens_prescription.h) and named `name`.
LensPrescription parse_lens_prescription(std::string_view text, const std::string& source,
                                         const std::string& name);

// Reads and parses the file at `path`; the lens is named after the file (without folder and
// extension). Throws obscura::Error when the file cannot be read.
LensPrescription load_lens_prescription(const std::string& path);

}  // namespace obscura
