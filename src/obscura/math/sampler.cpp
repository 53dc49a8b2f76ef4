#include "obscura/math/sampler.h"

namespace obscura {

std::string_view sampler_type_name(SamplerType type) {
  return type == SamplerType::kSobol ? "sobol" : "independent";
}

std::optional<SamplerType> parse_sampler_type(std::string_view name) {
  for (SamplerType type : {SamplerType::kSobol, SamplerType::kIndependent})
    if (name == sampler_type_name(type)) return type;
  return std::nullopt;
}

}  // namespace obscura
