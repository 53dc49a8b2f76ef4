#include "obscura/raster/draw_modes.h"

#include "obscura/math/error.h"

namespace obscura::raster {

DepthFunc parse_depth_func(const std::string& name) {
  if (name == "NEVER") return DepthFunc::kNever;
  if (name == "LESS") return DepthFunc::kLess;
  if (name == "EQUAL") return DepthFunc::kEqual;
  if (name == "LEQUAL") return DepthFunc::kLessEqual;
  if (name == "GREATER") return DepthFunc::kGreater;
  if (name == "NOTEQUAL") return DepthFunc::kNotEqual;
  if (name == "GEQUAL") return DepthFunc::kGreaterEqual;
  if (name == "ALWAYS") return DepthFunc::kAlways;
  throw Error("depth function", "unknown '" + name +
                                    "'; expected NEVER, LESS, EQUAL, LEQUAL, GREATER, NOTEQUAL, "
                                    "GEQUAL or ALWAYS");
}

CullMode parse_cull_mode(const std::string& name) {
  if (name == "none") return CullMode::kNone;
  if (name == "back") return CullMode::kBack;
  if (name == "front") return CullMode::kFront;
  throw Error("cull mode", "unknown '" + name + "'; expected none, back or front");
}

}  // namespace obscura::raster
