// obscura.RenderSession: a snapshot of a scene that keeps what renderers compiled of it across
// render() calls (render/render_session.h). render() takes one wherever it takes a Scene.
#pragma once

#include <memory>
#include <mutex>

#include "obscura/render/render_session.h"
#include "obscura/scene/scene.h"

namespace obscura::python {

struct PythonSession {
  // A copy of the scene as it was when the session was made: changing the Python Scene
  // afterwards changes neither what the session renders nor memory it reads.
  std::shared_ptr<const Scene> scene;
  std::unique_ptr<RenderSession> session;
  std::mutex busy;  // one render at a time: the compiled scene is rebuilt between frames
};

}  // namespace obscura::python
