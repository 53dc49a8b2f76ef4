// The back ends in the renderer table (render/renderer.cpp), one accessor per row; each is
// defined in its own back-end file.
#pragma once

namespace obscura {

class RendererBackend;

// render/tracer_backend.cpp: the tracer's integrators over one compiled Embree scene.
const RendererBackend& path_tracer_backend();
const RendererBackend& whitted_backend();
const RendererBackend& direct_lighting_backend();
// render/raster_backend.cpp: the software rasterizer.
const RendererBackend& rasterizer_backend();
// render/reyes_backend.cpp: REYES micropolygons.
const RendererBackend& reyes_backend();

}  // namespace obscura
