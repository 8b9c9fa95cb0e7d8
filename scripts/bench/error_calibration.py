#!/usr/bin/python3
"""Calibrates the reported error of D (channel dissipation_error, docs/numerics.md "The error of D")
for every stepper: runs one set of members (N = 20, A = 0.25 ... 14 in 56 values, AFM and FM starts
with noise 0.01, g = 1e-3 and 0.1, 2 relaxation + 2 averaged periods) at rtol 1e-4, 1e-6, 1e-8
(atol = rtol/1000) and prints, per stepper, g and rtol over the members that are not CP in the
reference run (rodas4 at rtol 1e-12, atol 1e-15; checked against rodas5p at the same tolerance):
the ratio of actual to estimated error (median, max), how many exceed 1, how many are flagged
unresolved, and how many with an actual error above 10 % are not.
Usage: error_calibration.py [--rotorsweep build/bin/rotorsweep] [--threads 2] [--workdir DIR]
       [--steppers rodas4 rodas4p2 rodas5p ros2] [--count 56 (A values)]"""
import argparse
import pathlib
import subprocess

import h5py
import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]
RTOLS = (1e-4, 1e-6, 1e-8)
# ros2 at rtol 1e-8 and dopri5 at small g take minutes per run; their ladders stop earlier
LADDERS = {"ros2": (1e-4, 1e-6), "dopri5": (1e-4, 1e-6)}

SCENE = """[model]
rows = 20
[drive]
g = [1e-3, 0.1]
[sweep]
A = {{ from = 0.25, to = 14.0, count = {count} }}
[initial]
kinds = ["AFM", "FM"]
noise = 0.01
seed = 1
[schedule]
relax_periods = 2
average_periods = 2
[observables]
dissipation = true
[numerics]
stepper = "{stepper}"
rtol = {rtol!r}
atol = {atol!r}
global_error = "{global_error}"
"""


def run(args, stepper, rtol, atol, global_error="shadow"):
    """The members of SCENE: "shadow" reports the error of D being calibrated; "local" for the reference runs, whose
    error is not used (shadow runs leave D as it is and cost a third of the reference's time)."""
    workdir = pathlib.Path(args.workdir)
    scene = workdir / f"{stepper}_{rtol:g}.toml"
    scene.write_text(SCENE.format(stepper=stepper, rtol=rtol, atol=atol, count=args.count, global_error=global_error))
    result = scene.with_suffix(".h5")
    subprocess.run([args.rotorsweep, "run", str(scene), "-o", str(result), "-q", "--force", "--threads",
                    str(args.threads)], check=True)
    with h5py.File(result, "r") as f:
        m = f["members"]
        return {k: m[k][:] for k in ("A", "g", "dissipation", "dissipation_error", "dissipation_resolved")} | {
            "regime": m["regime"].asstr()[:]}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--rotorsweep", default=str(ROOT / "build" / "bin" / "rotorsweep"))
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--workdir", default="calibration")
    parser.add_argument("--steppers", nargs="+", default=["rodas4", "rodas4p2", "rodas5p", "ros2"])
    parser.add_argument("--count", type=int, default=56)
    args = parser.parse_args()
    pathlib.Path(args.workdir).mkdir(parents=True, exist_ok=True)

    reference = run(args, "rodas4", 1e-12, 1e-15, "local")
    check = run(args, "rodas5p", 1e-12, 1e-15, "local")
    outside_cp = reference["regime"] != "CP"
    agreement = np.abs(check["dissipation"] / reference["dissipation"] - 1)[outside_cp]
    print(f"reference: {outside_cp.sum()} of {len(outside_cp)} members outside CP; rodas5p against rodas4 "
          f"at rtol 1e-12: median {np.median(agreement):.2g}, max {agreement.max():.2g} relative\n")
    print("| stepper | g | rtol | members | actual / estimate: median | max | above 1 | flagged |"
          " actual > 10 % unflagged |")
    print("|---|---|---|---|---|---|---|---|---|")
    for stepper in args.steppers:
        for rtol in LADDERS.get(stepper, RTOLS):
            r = run(args, stepper, rtol, rtol * 1e-3)
            for g in np.unique(reference["g"]):
                sel = outside_cp & (reference["g"] == g)
                actual = np.abs(r["dissipation"] - reference["dissipation"])[sel]
                ratio = actual / r["dissipation_error"][sel]
                resolved = r["dissipation_resolved"][sel].astype(bool)
                missed = resolved & (actual > 0.1 * np.abs(reference["dissipation"][sel]))
                print(f"| {stepper} | {g:g} | {rtol:g} | {sel.sum()} | {np.median(ratio):.2g} | {ratio.max():.2g} |"
                      f" {(ratio > 1).sum()} | {(~resolved).sum()} | {missed.sum()} |", flush=True)


if __name__ == "__main__":
    main()
