#!/usr/bin/python3
"""Work-precision of the experiment's slider scan (examples/experiment_7x7.toml, 81 separations, docs/slider.md
"Speed and accuracy"): wall time of the whole scan against the largest relative error of the mean
friction over the separations, per stepper and tolerance (median of --repeats runs), against a reference
at rtol 1e-10 with the same table; and the error against the table's node spacing (reference: rtol 1e-10,
64 nodes per h). Prints the
table and draws docs/figures/slider_work_precision.png by default.
Usage: scripts/bench/slider.py [--repeats 3] [--threads 2] [--out DIR] [--png PATH] [--reference-seconds S]"""
import argparse
import pathlib
import re
import statistics
import subprocess

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCENE = ROOT / "examples" / "experiment_7x7.toml"
STEPPERS = {"rodas4": [1e-4, 1e-5, 1e-6, 1e-7, 1e-8], "rodas4p2": [1e-4, 1e-5, 1e-6, 1e-7, 1e-8],
            "rodas5p": [1e-4, 1e-5, 1e-6, 1e-7, 1e-8], "ros2": [1e-4, 1e-5]}
NODES = [4, 8, 16, 32]


def scene_text(stepper, rtol, nodes=16):
    text = SCENE.read_text()
    text = re.sub(r'(?m)^stepper = .*$', f'stepper = "{stepper}"', text)
    text = re.sub(r"(?m)^rtol = .*$", f"rtol = {rtol:g}", text)
    text = re.sub(r"(?m)^atol = .*$", f"atol = {rtol:g}", text)
    text = re.sub(r"(?m)^(moment = 5.03e-2.*)$", rf"\1\nnodes_per_depth = {nodes}", text)
    return text.replace("[observables]", "") + "\n[observables]\nseries = false\n"


def run(out, name, text, threads):
    scene = out / f"{name}.toml"
    scene.write_text(text)
    result = out / f"{name}.h5"
    subprocess.run([str(ROOT / "build" / "bin" / "rotorsweep"), "slider", str(scene), "-o", str(result), "-q",
                    "--force", "--threads", str(threads)], check=True, capture_output=True)
    with h5py.File(result, "r") as f:
        steps = f["members/steps_accepted"][:] + f["members/steps_rejected"][:]
        return f.attrs["wall_seconds"], f["members/friction"][:], float(np.mean(steps))


def main(args):
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    _, reference, _ = run(out, "reference", scene_text("rodas5p", 1e-10), args.threads)
    rows = []
    for stepper, rtols in STEPPERS.items():
        for rtol in rtols:
            runs = [run(out, f"{stepper}_{rtol:g}", scene_text(stepper, rtol), args.threads)
                    for _ in range(args.repeats)]
            seconds = statistics.median(r[0] for r in runs)
            error = np.max(np.abs(runs[0][1] - reference) / np.abs(reference))
            rows.append((stepper, rtol, seconds, error, runs[0][2]))
            print(f"{stepper:8s} rtol {rtol:7.0e}  {seconds:7.2f} s  max rel. error {error:.2e}  "
                  f"{runs[0][2]:8.0f} step attempts per separation", flush=True)
    _, table_reference, _ = run(out, "reference_nodes_64", scene_text("rodas5p", 1e-10, 64), args.threads)
    table_rows = []
    for nodes in NODES:
        _, friction, _ = run(out, f"nodes_{nodes}", scene_text("rodas5p", 1e-10, nodes), args.threads)
        error = np.max(np.abs(friction - table_reference) / np.abs(table_reference))
        table_rows.append((nodes, error))
        print(f"nodes per h {nodes:3d}: max rel. error of the friction {error:.2e}", flush=True)

    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.6))
    for stepper in STEPPERS:
        sel = [r for r in rows if r[0] == stepper]
        left.loglog([r[3] for r in sel], [r[2] for r in sel], "o-", label=stepper)
        for r in sel:
            left.annotate(f"{r[1]:g}", (r[3], r[2]), fontsize=7, textcoords="offset points", xytext=(3, 3))
    left.axhline(3, color="gray", ls="--", lw=1, label="target: 3 s")
    if args.reference_seconds:
        left.axhline(args.reference_seconds, color="black", ls=":", lw=1,
                     label=f"reference code (Verlet 0.3 ms): {args.reference_seconds / 3600:.0f} h")
    left.axvline(1e-3, color="gray", lw=0.5)
    left.set_xlabel("largest relative error of the mean friction over 81 separations")
    left.set_ylabel(f"wall time of the scan (s, {args.threads} threads)")
    left.set_title("work-precision of the 7 × 7 slider scan")
    left.legend(fontsize=8)
    right.loglog([n for n, _ in table_rows], [max(e, 1e-16) for _, e in table_rows], "o-")
    right.set_xlabel("table nodes per separation h (substrate.nodes_per_depth)")
    right.set_ylabel("largest relative error of the mean friction")
    right.set_title("substrate table (rodas5p, rtol 1e-10; against 64 nodes per h)")
    fig.tight_layout()
    fig.savefig(args.png, dpi=120)
    print(f"wrote {args.png}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--out", default=str(ROOT / "bench-results" / "slider"))
    parser.add_argument("--png", default=str(ROOT / "docs" / "figures" / "slider_work_precision.png"))
    parser.add_argument("--reference-seconds", type=float, default=81 * 665.0,
                        help="the reference code's time for the scan (measured in Octave 7.3 on this machine: "
                             "19 ms per 0.3 ms step, 665 s per separation; its README: 900 s in MATLAB)")
    main(parser.parse_args())
