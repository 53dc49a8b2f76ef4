// The renderers Obscura offers: one table (render/renderer.cpp), a row per back end
// (render/renderer_backend.h). A Renderer is a row, held by value; the command line, scene
// files and Python name them as the table does.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace obscura {

class RendererBackend;
struct RendererCapabilities;

class Renderer {
 public:
  Renderer();  // the table's first row: the path tracer
  explicit Renderer(const RendererBackend& backend) : backend_(&backend) {}

  const RendererBackend& backend() const { return *backend_; }
  const char* name() const;
  const RendererCapabilities& capabilities() const;

  bool operator==(const Renderer& other) const = default;

 private:
  const RendererBackend* backend_;
};

// Every renderer, in the order help texts list them.
std::span<const Renderer> renderers();
// The table's row named `name` ("path", "whitted", "direct", "raster"); nothing for another name.
std::optional<Renderer> parse_renderer(std::string_view name);
// As parse_renderer, for names known to be in the table: throws obscura::Error otherwise.
Renderer renderer_named(std::string_view name);
// "path, whitted, direct or raster": the names, for messages.
std::string renderer_names();

}  // namespace obscura
