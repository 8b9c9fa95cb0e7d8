#!/usr/bin/env bash
# Every benchmark into bench-results/ (about 15 minutes on 2 cores): kernel throughput against the
# sincos bound, work-precision of our steppers and of the peers (scipy Radau/BDF/LSODA, SUNDIALS
# CVODE) on the stored reference members, and the scaling of whole sweeps. Run on an idle machine.
set -euo pipefail
cd "$(dirname "$0")/../.."
out=bench-results
mkdir -p "$out"
scripts/setup.sh libsundials-dev
scripts/build.sh
cmake -S . -B build-bench -DROTORSWEEP_BUILD_BENCH=ON -DROTORSWEEP_BUILD_TESTS=OFF > /dev/null
cmake --build build-bench --target cvode_members -j "$(nproc)" > /dev/null
rs=build/bin/rotorsweep

echo "== kernels (one thread)"
$rs bench kernels --rows 20 --repeats 5 | tee "$out/kernels.txt"

echo "== work-precision: rotorsweep"
/usr/bin/python3 scripts/bench/ours.py $rs scripts/bench/reference.toml "$out/ours.csv" --workdir "$out/ours" \
  --ladder rodas4:1e-3,1e-4,1e-5,1e-6,1e-7,1e-8,1e-9,1e-10,1e-11 \
  rodas4p2:1e-3,1e-4,1e-5,1e-6,1e-7,1e-8,1e-9,1e-10,1e-11,1e-12 \
  rodas5p:1e-3,1e-4,1e-5,1e-6,1e-7,1e-8,1e-9,1e-10,1e-11,1e-12 ros2:1e-3,1e-4,1e-5,1e-6,1e-7 \
  dopri5:1e-3,1e-5
members=$out/ours/rodas4_0.001.h5

echo "== work-precision: SUNDIALS CVODE"
/usr/bin/python3 scripts/bench/peers.py "$members" "$out/members.txt" --text
build-bench/bin/cvode_members 1e-3,1e-4,1e-5,1e-6,1e-7,1e-8,1e-9,1e-10,1e-11 < "$out/members.txt" > "$out/cvode.csv"

echo "== work-precision: scipy"
/usr/bin/python3 scripts/bench/peers.py "$members" "$out/scipy.csv" --methods Radau,BDF,LSODA \
  --rtols 1e-3,1e-5,1e-7,1e-9 > "$out/scipy.log"

/usr/bin/python3 scripts/bench/work_precision.py scripts/bench/reference.csv "$out" \
  "$out/ours.csv" "$out/cvode.csv" "$out/scipy.csv"

echo "== scaling"
/usr/bin/python3 scripts/bench/scaling.py $rs "$out/scaling"
echo "done: $out/"
