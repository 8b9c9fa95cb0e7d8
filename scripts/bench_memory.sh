#!/usr/bin/env bash
# Peak memory of `rotorsweep run` against the plan size: the same N = 2 friction curve with 10^5
# and 10^6 members (A × replicas), peak RSS from GNU time -v (docs/scale.md "Memory").
set -euo pipefail
cd "$(dirname "$0")/.."
exe=${ROTORSWEEP:-build/bin/rotorsweep}
[ -x /usr/bin/time ] || { echo "needs GNU time (apt-get install time)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '%-10s %-12s %-10s %s\n' members peak_rss_MB wall_s file_MB
for replicas in 100 1000; do
  cat > "$work/curve.toml" <<SCENE
[model]
rows = 2
[drive]
g = [0.01]
[sweep]
A = { from = 0.5, to = 12.0, count = 1000 }
[initial]
kinds = ["random"]
replicas = $replicas
SCENE
  /usr/bin/time -v "$exe" run "$work/curve.toml" -q -o "$work/curve.h5" --force 2> "$work/time.txt"
  rss_kb=$(awk -F': ' '/Maximum resident set size/ {print $2}' "$work/time.txt")
  wall=$(awk -F': ' '/Elapsed \(wall clock\)/ {print $2}' "$work/time.txt")
  size=$(stat -c %s "$work/curve.h5")
  awk -v m=$((replicas * 1000)) -v rss="$rss_kb" -v wall="$wall" -v size="$size" \
    'BEGIN { printf "%-10s %-12.1f %-10s %.1f\n", m, rss / 1024, wall, size / 1048576 }'
done
