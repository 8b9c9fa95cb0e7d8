#!/usr/bin/python3
"""The full array at any size (docs/performance.md "The full array at any size"): the cost of a step attempt of an
N × N slider against its n = N² rotors, for the dense stage solve (numerics.linear_solver = "dense": LDLᵀ of the
n × n stage matrix, direct pair sums) and the matrix-free one ("krylov": pair sums and K's products by FFT, conjugate
gradients), one member on one thread; its power law n^p fitted per solver; the targets (64 × 64 and 128 × 128
through the full protocol) and the crossover where "auto" switches (full SIMD lanes of dense members against
krylov members one per thread). The protocol is the row-reduction study's: overdamped, h = 9 mm, the experiment's
speed, a substrate of 5N × 5N magnets, 0.5 s at rest and --periods periods of sliding. Wall times are the result
files' (`wall_seconds`, the substrate table's build included), medians of --repeats runs. Prints the tables and
draws docs/figures/slider_scaling.png.
Usage: scripts/bench/slider_scaling.py [--rotorsweep build/bin/rotorsweep] [--repeats 3] [--periods 1] [--dense 8,12,16,24]
       [--krylov 8,12,16,24,32,48,64,96,128] [--targets] [--crossover] [--out DIR] [--png PATH]"""
import argparse
import pathlib
import statistics
import subprocess

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]


def scene_text(size, solver, periods, separations="separation = 9e-3", substrate_scale=5):
    return (f"[slider]\ncolumns = {size}\nrows = {size}\ndynamics = \"overdamped\"\n"
            f"[substrate]\ncolumns = {substrate_scale * size}\nrows = {substrate_scale * size}\n"
            f"[drive]\nrest = 0.5\nperiods = {periods}\n[sweep]\n{separations}\n"
            f"[observables]\nseries = false\n[numerics]\nlinear_solver = \"{solver}\"\n")


ROTORSWEEP = [str(ROOT / "build" / "bin" / "rotorsweep")]


def run(out, name, text, threads=1):
    """Wall seconds, mean step attempts per member and the frictions of one run of a scene."""
    scene = out / f"{name}.toml"
    scene.write_text(text)
    result = out / f"{name}.h5"
    subprocess.run([ROTORSWEEP[0], "slider", str(scene), "-o", str(result), "-q", "--force", "--threads",
                    str(threads)], check=True, capture_output=True)
    with h5py.File(result, "r") as f:
        steps = f["members/steps_accepted"][:] + f["members/steps_rejected"][:]
        return float(f.attrs["wall_seconds"]), float(np.mean(steps)), f["members/friction"][:]


def median_run(out, name, text, repeats, threads=1):
    runs = [run(out, name, text, threads) for _ in range(repeats)]
    return statistics.median(r[0] for r in runs), runs[0][1], runs[0][2]


def scaling(args, out):
    """Seconds per step attempt against n for each solver, and the fitted exponents."""
    rows = {}
    for solver, sizes in (("dense", args.dense), ("krylov", args.krylov)):
        for size in sizes:
            seconds, attempts, friction = median_run(out, f"{solver}_{size}", scene_text(size, solver, args.periods),
                                                     args.repeats)
            rows.setdefault(solver, []).append((size, seconds, attempts, friction[0]))
            print(f"{solver:6s} {size:4d} x {size:<4d} n = {size * size:6d}: {seconds:8.2f} s, {attempts:6.0f} "
                  f"attempts, {1e3 * seconds / attempts:9.3f} ms per attempt", flush=True)
    fits = {}
    for solver, data in rows.items():
        n = np.array([d[0] ** 2 for d in data], dtype=float)
        cost = np.array([d[1] / d[2] for d in data])
        large = n >= 64 if np.count_nonzero(n >= 64) >= 2 else n > 0
        p = np.polyfit(np.log(n[large]), np.log(cost[large]), 1)[0] if np.count_nonzero(large) >= 2 else np.nan
        fits[solver] = p
        print(f"{solver}: cost per attempt ∝ n^{p:.2f} over n = {int(n[large].min())} … {int(n[large].max())}")
    both = {d[0]: d[3] for d in rows.get("dense", [])}
    for size, _, _, friction in rows.get("krylov", []):
        if size in both:
            print(f"{size} x {size}: krylov's friction over dense's − 1 = {friction / both[size] - 1:.2e}")
    return rows, fits


def targets(args, out):
    """64 × 64 and 128 × 128 through the full protocol (5 periods), one member on one and on two threads (the
    second takes the member's Q convolutions)."""
    for size in (64, 128):
        for threads in (1, 2):
            seconds, attempts, friction = median_run(out, f"target_{size}_{threads}", scene_text(size, "auto", 5), 1,
                                                     threads)
            print(f"target {size} x {size}, 5 periods, {threads} thread(s): {seconds:.1f} s, {attempts:.0f} attempts, "
                  f"friction {friction[0]:.6g} N", flush=True)


def crossover(args, out):
    """Per member, 8 separations of each size on one thread: dense (SIMD lanes full) against krylov."""
    separations = "separation = { from = 7e-3, to = 10.5e-3, count = 8 }"
    for size in (8, 10, 12, 14, 16, 20):
        times = {solver: median_run(out, f"cross_{solver}_{size}",
                                    scene_text(size, solver, 2, separations, 3), args.repeats)[0]
                 for solver in ("dense", "krylov")}
        print(f"crossover {size:3d} x {size:<3d}: dense {times['dense'] / 8:7.3f} s per member, krylov "
              f"{times['krylov'] / 8:7.3f} s per member (ratio {times['dense'] / times['krylov']:.2f})", flush=True)


def plot(rows, fits, path):
    fig, ax = plt.subplots(figsize=(6, 4.2))
    for solver, marker in (("dense", "s"), ("krylov", "o")):
        data = rows.get(solver, [])
        if not data:
            continue
        n = np.array([d[0] ** 2 for d in data], dtype=float)
        cost = np.array([1e3 * d[1] / d[2] for d in data])
        ax.loglog(n, cost, marker + "-", label=f"{solver} (∝ n^{fits[solver]:.2f} from n = 64)")
    ax.set_xlabel("rotors n = N²")
    ax.set_ylabel("wall time per step attempt, ms (one thread)")
    ax.set_title("slider step cost: dense LDLᵀ against matrix-free (FFT + CG)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rotorsweep", default=ROTORSWEEP[0], help="the executable")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--periods", type=int, default=1)
    sizes = lambda text: [int(v) for v in text.split(",") if v]
    parser.add_argument("--dense", type=sizes, default=[8, 12, 16, 24])
    parser.add_argument("--krylov", type=sizes, default=[8, 12, 16, 24, 32, 48, 64, 96, 128])
    parser.add_argument("--targets", action="store_true", help="64 x 64 and 128 x 128 through 5 periods")
    parser.add_argument("--crossover", action="store_true", help="dense SIMD lanes against krylov per member")
    parser.add_argument("--out", default="bench-results/slider_scaling")
    parser.add_argument("--png", default=str(ROOT / "docs" / "figures" / "slider_scaling.png"))
    args = parser.parse_args()
    ROTORSWEEP[0] = args.rotorsweep
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    rows, fits = scaling(args, out)
    plot(rows, fits, args.png)
    if args.targets:
        targets(args, out)
    if args.crossover:
        crossover(args, out)


if __name__ == "__main__":
    main()
