#!/usr/bin/env bash
# The layers hold (docs/architecture.md "Layers"): no file under ensemble/engine/ includes a problem
# (ensemble/rows/, ensemble/slider/), an executor (ensemble/gpu/) or a model (kernels/models/), and no
# stepper, linear algebra or lane file includes a model (what they require of one are the LaneModel and
# TeamModel concepts, kernels/steppers/model_concept.hpp and team_model_concept.hpp); no problem
# (ensemble/rows/, ensemble/slider/) includes an executor (ensemble/gpu/): its caller passes the device in.
# Usage: layers_know_no_model.sh SOURCE_DIR
set -euo pipefail
engine="$1/ensemble/engine"
[ -d "$engine" ] || { echo "layers_know_no_model.sh: no folder $engine" >&2; exit 2; }
status=0
found=$(grep -rnE '#include "(ensemble/(rows|slider|gpu)/|kernels/models/)' "$engine" || true)
if [ -n "$found" ]; then
  echo "ensemble/engine/ includes what lies above it or a concrete model:"
  echo "$found"
  status=1
fi
problems=("$1/ensemble/rows" "$1/ensemble/slider")
found=$(grep -rnE '#include "ensemble/gpu/' "${problems[@]}" || true)
if [ -n "$found" ]; then
  echo "a problem (ensemble/rows/, ensemble/slider/) includes an executor:"
  echo "$found"
  status=1
fi
kernels=("$1/kernels/steppers" "$1/kernels/linear" "$1/kernels/lanes")
found=$(grep -rnE '#include "kernels/models/' "${kernels[@]}" || true)
if [ -n "$found" ]; then
  echo "a stepper, linear algebra or lane file includes a concrete model:"
  echo "$found"
  status=1
fi
[ "$status" = 0 ] &&
  echo "ensemble/engine/: $(find "$engine" -type f | wc -l) files, none includes a problem, an executor or a model;" \
    "ensemble/rows, slider: $(find "${problems[@]}" -type f | wc -l) files, none includes an executor;" \
    "kernels/steppers, linear, lanes: $(find "${kernels[@]}" -type f | wc -l) files, none includes a model"
exit "$status"
