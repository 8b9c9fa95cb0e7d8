#!/usr/bin/env bash
# The engine's layer holds (docs/architecture.md "Layers"): no file under ensemble/engine/ includes a
# problem (ensemble/rows/, ensemble/slider/), an executor (ensemble/gpu/) or a model (kernels/models/;
# what steppers and engine require of any model, the LaneModel concept, is kernels/steppers/model_concept.hpp).
# Usage: engine_knows_no_model.sh SOURCE_DIR
set -euo pipefail
engine="$1/ensemble/engine"
[ -d "$engine" ] || { echo "engine_knows_no_model.sh: no folder $engine" >&2; exit 2; }
found=$(grep -rnE '#include "(ensemble/(rows|slider|gpu)/|kernels/models/)' "$engine" || true)
if [ -n "$found" ]; then
  echo "ensemble/engine/ includes what lies above it or a concrete model:"
  echo "$found"
  exit 1
fi
echo "ensemble/engine/: $(find "$engine" -type f | wc -l) files, none includes a problem, an executor or a model"
