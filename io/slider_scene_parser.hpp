// Reads a slider scene file (TOML, docs/model.md §9) into an ensemble::SliderScene, validating every key
// before any work: unknown keys, wrong types and out-of-range values end with one SceneError naming the key.
#pragma once

#include <string>
#include <string_view>

#include "ensemble/slider/slider_scene.hpp"
#include "io/scene_parser.hpp"

namespace rotorsweep::io {

/// Parses and validates the slider scene in `path` (its text is kept in SliderScene::text).
ensemble::SliderScene parse_slider_scene_file(const std::string& path);

/// Parses and validates slider scene text; `source` names it in messages.
ensemble::SliderScene parse_slider_scene_text(std::string_view text, std::string_view source);

/// With numerics.device = "gpu": a SceneError where the scene names an explicit stepper, which the
/// GPU's slider (linearly implicit steppers on teams) does not run; nothing on the CPU.
void check_slider_device(const ensemble::SliderScene& scene);

}  // namespace rotorsweep::io
