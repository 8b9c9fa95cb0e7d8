#!/usr/bin/env bash
# `mpirun -np 2 rotorsweep run` and `... slider` against the single-process runs: every dataset equal
# byte for byte, both ranks took members from the shared counters, the ranks' files are gone, and
# --shard under mpirun is exit code 2. Stopped by SIGINT under mpirun, each command keeps the partial file
# (exit 130, the resume command named), which one process resumes to the single-process run's bytes; with a
# rank killed by SIGKILL, the ranks' files stay and --resume in one process joins them to the same bytes.
# Usage: mpi_run.sh ROTORSWEEP_EXECUTABLE SCRATCH_DIR
set -euo pipefail
exe=$1 scratch=$2

# mpirun -np 2 COMMAND SCENE into OUT, SIGINT to both ranks once their files exist; then the stop's
# report, exit 130 and no rank's file left, and `COMMAND SCENE --resume` in one process finishes OUT.
stopped_and_resumed() {
  local command=$1 scene=$2 out=$3 code=0
  mpirun -np 2 "$exe" "$command" "$scene" -q --threads 1 -o "$out" 2> "$out.log" &
  local launcher=$!
  for _ in $(seq 400); do
    [ "$(ls "$out".partial.rank-* 2> /dev/null | wc -l)" -ge 2 ] && break
    sleep 0.05
  done
  # the ranks, not mpirun: their first word is the binary (the launcher's choice of it, or $exe itself)
  pkill -INT -f "^[^ ]*rotorsweep[^ ]* $command $scene -q --threads 1 -o $out\$" || true
  wait "$launcher" || code=$?
  cat "$out.log"
  [ "$code" -eq 130 ] || { echo "$command stopped under mpirun: exit $code, not 130" >&2; exit 1; }
  grep -q "^stopped: .* members done (per rank: .*), kept in $out.partial (complete = FALSE)" "$out.log" &&
    grep -q "^resume with: .*--resume" "$out.log" || { echo "$command: no stop report" >&2; exit 1; }
  if ls "$out".partial.rank-* > /dev/null 2>&1; then echo "$command: a rank's file was left behind" >&2; exit 1; fi
  "$exe" "$command" "$scene" -q --resume -o "$out"
}
# mpirun -np 2 COMMAND SCENE into OUT, one rank killed by SIGKILL once rank 0's file holds a member: no
# joined file, the ranks' files left; a plain run refuses them (exit 2, naming --resume), and
# `COMMAND SCENE --resume` in one process joins them and finishes OUT.
killed_and_resumed() {
  local command=$1 scene=$2 out=$3 code=0 done=0
  # a row run writes its members in batches of 8 (the default is every 5 s): rank 0's file holds some soon
  local flush=""
  [ "$command" = run ] && flush="--flush-members 8 "
  mpirun -np 2 "$exe" "$command" "$scene" -q --threads 1 $flush-o "$out" 2> "$out.log" &
  local launcher=$!
  for _ in $(seq 2000); do
    done=$("$exe" info "$out.partial.rank-0" 2> /dev/null | sed -n 's/^partial *\([0-9]*\) of .*/\1/p' || true)
    [ "${done:-0}" -gt 0 ] && break
    kill -0 "$launcher" 2> /dev/null || break  # mpirun ended: the ranks stopped or finished first
    sleep 0.05
  done
  [ "${done:-0}" -gt 0 ] || { cat "$out.log"; echo "$command: rank 0's file never held a member" >&2; exit 1; }
  pkill -KILL -n -f "^[^ ]*rotorsweep[^ ]* $command $scene -q --threads 1 $flush-o $out\$" || true
  wait "$launcher" || code=$?
  [ "$code" -ne 0 ] || { echo "$command: mpirun exit 0 after a rank was killed" >&2; exit 1; }
  ls "$out".partial.rank-* > /dev/null 2>&1 || { echo "$command: the ranks' files are gone" >&2; exit 1; }
  [ ! -e "$out" ] || { echo "$command: a killed run wrote $out" >&2; exit 1; }
  code=0
  "$exe" "$command" "$scene" -q -o "$out" 2> "$out.refused.log" || code=$?
  [ "$code" -eq 2 ] && grep -q -- "--resume" "$out.refused.log" ||
    { cat "$out.refused.log"; echo "$command: a plain run over the ranks' files: exit $code" >&2; exit 1; }
  "$exe" "$command" "$scene" -q --resume -o "$out"
  if ls "$out".partial.rank-* > /dev/null 2>&1; then echo "$command: a rank's file outlived --resume" >&2; exit 1; fi
}
rm -rf "$scratch" && mkdir -p "$scratch"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
cat > "$scratch/curve.toml" <<'SCENE'
[model]
rows = [4, 20]
[drive]
g = [0.0011]
[sweep]
A = { from = 0.5, to = 12.0, count = 40 }
[initial]
kinds = ["AFM", "random"]
replicas = 5
SCENE
"$exe" run "$scratch/curve.toml" -q -o "$scratch/single.h5"
mpirun -np 2 "$exe" run "$scratch/curve.toml" -q --threads 1 -o "$scratch/mpi.h5" 2> "$scratch/mpi.log"
cat "$scratch/mpi.log"
if ls "$scratch"/*.rank-* > /dev/null 2>&1; then echo "a rank's file was left behind" >&2; exit 1; fi
shares=$(sed -n 's/.*members per rank: \([0-9]*\), \([0-9]*\);.*/\1 \2/p' "$scratch/mpi.log")
read -r first second <<< "$shares"
[ "${first:-0}" -gt 0 ] && [ "${second:-0}" -gt 0 ] || { echo "both ranks must take members: '$shares'" >&2; exit 1; }
set +e
mpirun -np 2 "$exe" run "$scratch/curve.toml" -q --shard 1/2 -o "$scratch/shard.h5" 2> "$scratch/shard.log"
code=$?
set -e
[ "$code" -eq 2 ] && grep -q "one process" "$scratch/shard.log" || { cat "$scratch/shard.log"; echo "--shard under mpirun: exit $code" >&2; exit 1; }
# the stopped and killed runs keep the members' own error only (their files' bookkeeping is the check;
# the shadow runs' bytes across ranks are checked above)
printf '[numerics]\nglobal_error = "local"\n' | cat "$scratch/curve.toml" - > "$scratch/curve-local.toml"
"$exe" run "$scratch/curve-local.toml" -q -o "$scratch/single-local.h5"
stopped_and_resumed run "$scratch/curve-local.toml" "$scratch/stopped.h5"
killed_and_resumed run "$scratch/curve-local.toml" "$scratch/killed.h5"
cat > "$scratch/slider.toml" <<'SCENE'
[slider]
columns = [3, 4]
rows = 3
[substrate]
columns = 11
rows = 11
[drive]
rest = 0.5
end = 4.5
[sweep]
separation = { from = 6e-3, to = 9e-3, count = 7 }
[initial]
replicas = 3
SCENE
"$exe" slider "$scratch/slider.toml" -q -o "$scratch/slider-single.h5"
mpirun -np 2 "$exe" slider "$scratch/slider.toml" -q --threads 1 -o "$scratch/slider-mpi.h5" 2> "$scratch/slider-mpi.log"
cat "$scratch/slider-mpi.log"
if ls "$scratch"/*.rank-* > /dev/null 2>&1; then echo "a rank's slider file was left behind" >&2; exit 1; fi
shares=$(sed -n 's/.*members per rank: \([0-9]*\), \([0-9]*\)).*/\1 \2/p' "$scratch/slider-mpi.log")
read -r first second <<< "$shares"
[ "${first:-0}" -gt 0 ] && [ "${second:-0}" -gt 0 ] && [ $((first + second)) -eq 42 ] ||
  { echo "both ranks must take slider members, 42 in all: '$shares'" >&2; exit 1; }
# the stopped scan drives ten times longer, so that the signal reaches the ranks before its end, and
# keeps the members' own error only
sed 's/^end = 4.5$/end = 44.5/' "$scratch/slider.toml" > "$scratch/slider-long.toml"
printf '[numerics]\nglobal_error = "local"\n' >> "$scratch/slider-long.toml"
"$exe" slider "$scratch/slider-long.toml" -q -o "$scratch/slider-long.h5"
stopped_and_resumed slider "$scratch/slider-long.toml" "$scratch/slider-stopped.h5"
killed_and_resumed slider "$scratch/slider-long.toml" "$scratch/slider-killed.h5"
/usr/bin/python3 - "$scratch/single.h5" "$scratch/mpi.h5" "$scratch/slider-single.h5" "$scratch/slider-mpi.h5" \
  "$scratch/single-local.h5" "$scratch/stopped.h5" "$scratch/slider-long.h5" "$scratch/slider-stopped.h5" \
  "$scratch/single-local.h5" "$scratch/killed.h5" "$scratch/slider-long.h5" "$scratch/slider-killed.h5" <<'PY'
import sys, h5py
def datasets(f):
    names = []
    f.visititems(lambda name, obj: names.append(name) if isinstance(obj, h5py.Dataset) else None)
    return names
for single_path, mpi_path in zip(sys.argv[1::2], sys.argv[2::2]):
    single, mpi = h5py.File(single_path, "r"), h5py.File(mpi_path, "r")
    names = datasets(single)
    assert names == datasets(mpi), "different datasets"
    differing = [n for n in names if single[n][()].tobytes() != mpi[n][()].tobytes()]
    assert not differing, differing
    assert mpi.attrs["complete"]
    print(f"{len(names)} datasets of {mpi_path} equal to the single-process run")
PY
