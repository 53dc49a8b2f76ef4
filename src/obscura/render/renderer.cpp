#include "obscura/render/renderer.h"

#include <string>

#include "obscura/math/error.h"
#include "obscura/render/backends.h"
#include "obscura/render/renderer_backend.h"

namespace obscura {

// The table: a row per renderer, the default first.
std::span<const Renderer> renderers() {
  static const Renderer table[] = {
      Renderer(path_tracer_backend()),
      Renderer(whitted_backend()),
      Renderer(direct_lighting_backend()),
      Renderer(rasterizer_backend()),
      Renderer(reyes_backend()),
  };
  return table;
}

Renderer::Renderer() : Renderer(renderers().front()) {}

const char* Renderer::name() const {
  return backend_->name();
}

const RendererCapabilities& Renderer::capabilities() const {
  return backend_->capabilities();
}

std::optional<Renderer> parse_renderer(std::string_view name) {
  for (const Renderer& r : renderers())
    if (name == r.name()) return r;
  return std::nullopt;
}

Renderer renderer_named(std::string_view name) {
  if (std::optional<Renderer> r = parse_renderer(name)) return *r;
  throw Error("renderer",
              "no renderer is named '" + std::string(name) + "'; there are " + renderer_names());
}

std::string renderer_names() {
  std::string names;
  const std::span<const Renderer> all = renderers();
  for (size_t i = 0; i < all.size(); ++i) {
    if (i > 0) names += i + 1 == all.size() ? " or " : ", ";
    names += all[i].name();
  }
  return names;
}

}  // namespace obscura
