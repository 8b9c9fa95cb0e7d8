#!/usr/bin/env bash
# Installs the build into a scratch prefix, builds examples/cpp_library against it through
# find_package(rotorsweep), runs it, and checks its numbers against the paper's table and J(A_-).
# Usage: find_package_example.sh BUILD_DIR SOURCE_DIR SCRATCH_DIR
set -euo pipefail
build=$1 source=$2 scratch=$3
rm -rf "$scratch"
cmake --install "$build" --prefix "$scratch/prefix" > /dev/null
cmake -S "$source/examples/cpp_library" -B "$scratch/example" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$scratch/prefix" > "$scratch/configure.log"
cmake --build "$scratch/example" > "$scratch/build.log"
output=$("$scratch/example/friction_point")
echo "$output"
/usr/bin/env python3 - "$output" <<'PY'
import re, sys
text = sys.argv[1]
rows = re.findall(r"D = (\S+)  paper (\S+)", text)
assert len(rows) == 2, text
for D, paper in rows:
    assert abs(float(D) / float(paper) - 1) < 2e-3, (D, paper)
J = float(re.search(r"J\(A_-\) = (\S+)", text).group(1))
assert abs(J - 4.975766521411717) < 1e-9, J
print("find_package example: ok")
PY
