#!/usr/bin/python3
"""Runs the benchmark members through `rotorsweep run` for each stepper and tolerance, one thread
(SIMD lanes), and writes one CSV row per member: D and the wall time per member (the run's
wall_seconds / members, median over repeats; runs over 5 s only once).
Usage: ours.py ROTORSWEEP SCENE.toml OUT.csv --ladder rodas4:1e-3,1e-5 dopri5:1e-3 [--repeats 3]
       [--threads 1] [--workdir DIR]   (atol = rtol × 1e-3; a method "rodas4+pi" runs the stepper with
       numerics.controller = "pi")"""
import argparse
import csv
import os
import re

import h5py
from timed_run import timed_run


def scene_with(scene_text, method, rtol):
    stepper, _, controller = method.partition("+")
    text = re.sub(r'(?m)^stepper = .*$', f'stepper = "{stepper}"' + (f'\ncontroller = "{controller}"' if controller else ""),
                  scene_text)
    text = re.sub(r'(?m)^rtol = .*$', f"rtol = {rtol!r}", text)
    return re.sub(r'(?m)^atol = .*$', f"atol = {rtol * 1e-3!r}", text)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("rotorsweep")
    parser.add_argument("scene")
    parser.add_argument("out")
    parser.add_argument("--ladder", nargs="+", required=True)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--workdir", default=".")
    args = parser.parse_args()
    scene_text = open(args.scene).read()
    os.makedirs(args.workdir, exist_ok=True)
    with open(args.out, "w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(["method", "rtol", "atol", "member", "A", "g", "D", "seconds", "steps"])
        for rung in args.ladder:
            stepper, rtols = rung.split(":")
            for rtol in (float(r) for r in rtols.split(",")):
                scene = os.path.join(args.workdir, f"{stepper}_{rtol:g}.toml")
                result = scene[:-5] + ".h5"
                with open(scene, "w") as f:
                    f.write(scene_with(scene_text, stepper, rtol))
                wall, _ = timed_run(args.rotorsweep, scene, result, args.threads, args.repeats, once_above=5)
                with h5py.File(result, "r") as f:
                    m = f["members"]
                    A, g, D = m["A"][:], m["g"][:], m["dissipation"][:]
                    steps = m["steps_accepted"][:] + m["steps_rejected"][:]
                per_member = wall / len(A)
                for i in range(len(A)):
                    writer.writerow([stepper, rtol, rtol * 1e-3, i, A[i], g[i], repr(D[i]), f"{per_member:.6g}",
                                     steps[i]])
                out.flush()
                print(f"{stepper} rtol {rtol:g}: {per_member * 1e3:.3g} ms per member", flush=True)


if __name__ == "__main__":
    main()
