// obscura.RenderSession: a snapshot of a scene that keeps what renderers compiled of it across
// render() calls (render/render_session.h). render() takes one wherever it takes a Scene.
#pragma once

#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "obscura/render/render_session.h"
#include "obscura/scene/scene.h"

namespace obscura::python {

struct PythonSession {
  // A copy of the scene as it was when the session was made: changing the Python Scene
  // afterwards changes neither what the session renders nor memory it reads. Only pose()
  // changes it (under `busy`).
  std::shared_ptr<Scene> scene;
  std::unique_ptr<RenderSession> session;
  std::mutex busy;  // one render at a time: the compiled scene is rebuilt between frames
};

// When load_scene(..., time=, shutter=) poses skins and morph targets: the shutter (`shutter` as
// --shutter, else the default one) centred on `time` when one is given.
Shutter pose_shutter(std::optional<double> time, const std::optional<std::string>& shutter);

}  // namespace obscura::python
