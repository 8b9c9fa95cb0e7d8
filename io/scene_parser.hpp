// Reads a scene file (TOML) into an ensemble::Scene and validates every key before any work:
// unknown keys, wrong types and out-of-range values end with one SceneError naming the key.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

#include "ensemble/rows/scene.hpp"

namespace rotorsweep::io {

/// A scene that cannot be run; what() is the whole message for the user.
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Parses and validates the scene in `path` (its text is kept in Scene::text).
ensemble::Scene parse_scene_file(const std::string& path);

/// Parses and validates scene text; `source` names it in messages.
ensemble::Scene parse_scene_text(std::string_view text, std::string_view source);

/// Throws SceneError, naming the key, where the scene asks for a device that cannot run it
/// (numerics.device = "gpu" with a model the GPU backend lacks). Parsing calls it; so does a
/// command line that changes the device.
void check_device(const ensemble::Scene& scene);

}  // namespace rotorsweep::io
