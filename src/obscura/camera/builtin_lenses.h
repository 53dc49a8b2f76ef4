// The lens prescriptions built into Obscura (data/lenses/, with their published sources), by
// name: "double-gauss-50mm", "telephoto-250mm", "fisheye-10mm".
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "obscura/camera/lens_system.h"

namespace obscura {

std::vector<std::string> builtin_lens_names();

// The named lens system, made once per process and shared. Throws obscura::Error listing the
// names when there is none of that name.
std::shared_ptr<const LensSystem> builtin_lens(const std::string& name);

}  // namespace obscura
