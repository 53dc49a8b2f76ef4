#include "obscura/math/sampler.h"

namespace obscura {

std::string_view sampler_type_name(SamplerType type) {
  return type == SamplerType::kSobol ? "sobol" : "independent";
}

}  // namespace obscura
