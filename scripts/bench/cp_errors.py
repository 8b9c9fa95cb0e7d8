#!/usr/bin/python3
"""The global error of D (docs/numerics.md "The global error of D").

Default: the CP table. N = 20, g = 0.0011, A = 6 and 8, AFM and FM starts with noise 0.01, 32
replicas, 2 relaxation + 2 averaged periods, without and with quenched disorder σ_A = 1e-6, at rtol
1e-8, 1e-9, 1e-10 (atol = rtol/1000) with numerics.global_error = "local" and "shadow", against the
same members at rtol 1e-12. Prints a Markdown table: per set the median actual deviation
|D − D_ref| / D, the median reported dissipation_error / D with each estimate, the fraction of members
whose reported error covers the deviation, and the fraction flagged symmetry_limited; then the demo's
wall time with either estimate (medians of --repeats runs, the same machine, alternating).

--coverage: what the flag dissipation_resolved promises. N = 8 and 14, g = 5e-4, 1e-3, 3e-3,
A = 2.5, 5.2, 6.6, 7.9, 11.5 (AFM, CP, CP, CP near A_*, FM), FM and AFM starts with noise 0.01 and
random starts, --replicas each, 2 + 2 periods, without and with σ_A = 1e-6, at rtol 1e-7 and 1e-9
with the default shadow estimate, against the same members at rtol 1e-12 with "local". Prints per
(σ_A, rtol, start) the members flagged resolved, the fraction of them within 2 × dissipation_error of
the reference (and within 1 ×), the largest |D − D_ref| / dissipation_error, and the members
symmetry-limited and with a departed shadow; then the same per g and the totals.

Usage: cp_errors.py [--coverage [--replicas 3]] [--rotorsweep build/bin/rotorsweep] [--threads 2]
                    [--workdir DIR] [--repeats 5]"""
import argparse
import pathlib
import re
import subprocess
import tempfile

import h5py
import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCENE = """[model]
rows = 20
[drive]
g = [0.0011]
[sweep]
A = [6.0, 8.0]
[initial]
kinds = ["AFM", "FM"]
noise = 0.01
replicas = 32
[disorder]
A = {sigma!r}
[schedule]
relax_periods = 2
average_periods = 2
[observables]
slips = true
[numerics]
rtol = {rtol!r}
atol = {atol!r}
global_error = "{estimate}"
"""


def run(exe, workdir, threads, sigma, rtol, estimate):
    path = workdir / f"cp-{sigma:g}-{rtol:g}-{estimate}"
    path.with_suffix(".toml").write_text(SCENE.format(sigma=sigma, rtol=rtol, atol=rtol / 1000, estimate=estimate))
    subprocess.run([exe, "run", "-q", "--force", "--threads", str(threads), str(path.with_suffix(".toml")),
                    "-o", str(path.with_suffix(".h5"))], check=True, stderr=subprocess.DEVNULL)
    with h5py.File(path.with_suffix(".h5")) as f:
        m = f["members"]
        return {k: m[k][()] for k in m if m[k].ndim == 1}


COVERAGE_SCENE = """[model]
rows = [8, 14]
[drive]
g = [5e-4, 1e-3, 3e-3]
[sweep]
A = [2.5, 5.2, 6.6, 7.9, 11.5]
[initial]
kinds = ["FM", "AFM", "random"]
noise = 0.01
replicas = {replicas}
[disorder]
A = {sigma!r}
[schedule]
relax_periods = 2
average_periods = 2
[numerics]
rtol = {rtol!r}
atol = {atol!r}
global_error = "{estimate}"
"""
COVERAGE_COLUMNS = ("A", "g", "rows", "ic", "dissipation", "dissipation_error", "dissipation_resolved",
                    "symmetry_limited", "shadow_departed", "regime")


def run_coverage_set(exe, workdir, threads, replicas, sigma, rtol, estimate):
    path = workdir / f"coverage-{sigma:g}-{rtol:g}-{estimate}"
    path.with_suffix(".toml").write_text(COVERAGE_SCENE.format(replicas=replicas, sigma=sigma, rtol=rtol,
                                                               atol=rtol / 1000, estimate=estimate))
    subprocess.run([exe, "run", "-q", "--force", "--threads", str(threads), str(path.with_suffix(".toml")),
                    "-o", str(path.with_suffix(".h5"))], check=True, stderr=subprocess.DEVNULL)
    with h5py.File(path.with_suffix(".h5")) as f:
        m = f["members"]
        return {k: (m[k].asstr()[()] if m[k].dtype.kind in "SO" else m[k][()]) for k in COVERAGE_COLUMNS
                if k in m}


def coverage_row(label, r, deviation, keep):
    """A Markdown row over the members `keep` of result r: resolved, covered within 2× and 1×, worst ratio."""
    resolved = keep & (r["dissipation_resolved"] == 1)
    ratio = deviation[resolved] / r["dissipation_error"][resolved]
    n = int(resolved.sum())
    within2 = f"{np.mean(ratio <= 2):.3f}" if n else "—"
    within1 = f"{np.mean(ratio <= 1):.3f}" if n else "—"
    worst = f"{ratio.max():.2g}" if n else "—"
    return (f"| {label} | {int(keep.sum())} | {n} | {within2} | {within1} | {worst} "
            f"| {int((keep & (r['symmetry_limited'] == 1)).sum())} | {int((keep & (r['shadow_departed'] == 1)).sum())} |")


def coverage(args, workdir):
    header = ("| set | members | resolved | within 2 × error | within 1 × | largest deviation / error "
              "| symmetry-limited | shadow departed |\n|---|---|---|---|---|---|---|---|")
    totals = {}
    for sigma in (0.0, 1e-6):
        ref = run_coverage_set(args.rotorsweep, workdir, args.threads, args.replicas, sigma, 1e-12, "local")
        for rtol in (1e-7, 1e-9):
            r = run_coverage_set(args.rotorsweep, workdir, args.threads, args.replicas, sigma, rtol, "shadow")
            deviation = np.abs(r["dissipation"] - ref["dissipation"])
            everyone = np.ones(len(deviation), bool)
            print(f"\nσ_A = {sigma:g}, rtol {rtol:g}:\n{header}")
            for start in ("FM", "AFM", "random"):
                print(coverage_row(f"{start} starts", r, deviation, r["ic"] == start))
            for g in np.unique(r["g"]):
                print(coverage_row(f"g = {g:g}", r, deviation, r["g"] == g))
            print(coverage_row("all", r, deviation, everyone))
            totals[(sigma, rtol)] = (r, deviation)
    print(f"\nall sets:\n{header}")
    for (sigma, rtol), (r, deviation) in totals.items():
        print(coverage_row(f"σ_A = {sigma:g}, rtol {rtol:g}", r, deviation, np.ones(len(deviation), bool)))


def demo_seconds(exe, workdir, threads, repeats):
    text = (ROOT / "examples/friction_curve.toml").read_text()
    times = {"local": [], "shadow": []}
    for estimate in times:
        scene = workdir / f"demo-{estimate}.toml"
        scene.write_text(text.replace("[numerics]\n", f'[numerics]\nglobal_error = "{estimate}"\n'))
    for _ in range(repeats):
        for estimate in times:
            out = subprocess.run([exe, "run", "-q", "--force", "--threads", str(threads),
                                  str(workdir / f"demo-{estimate}.toml"), "-o", str(workdir / "demo.h5")],
                                 check=True, capture_output=True, text=True).stderr
            value, unit = re.search(r"members in ([0-9.]+) (ms|s)", out).groups()
            times[estimate].append(float(value) / (1000 if unit == "ms" else 1))
    return {k: float(np.median(v)) for k, v in times.items()}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rotorsweep", default=str(ROOT / "build/bin/rotorsweep"))
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--workdir", default=None)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--coverage", action="store_true", help="the coverage of dissipation_resolved")
    parser.add_argument("--replicas", type=int, default=3, help="replicas per start with --coverage")
    args = parser.parse_args()
    workdir = pathlib.Path(args.workdir or tempfile.mkdtemp(prefix="cp-errors-"))
    workdir.mkdir(parents=True, exist_ok=True)
    if args.coverage:
        coverage(args, workdir)
        return
    print("| σ_A | rtol | A | start | actual / D | local error / D | covered | shadow error / D | covered |"
          " symmetry-limited |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for sigma in (0.0, 1e-6):
        ref = run(args.rotorsweep, workdir, args.threads, sigma, 1e-12, "local")
        for rtol in (1e-8, 1e-9, 1e-10):
            local = run(args.rotorsweep, workdir, args.threads, sigma, rtol, "local")
            shadow = run(args.rotorsweep, workdir, args.threads, sigma, rtol, "shadow")
            deviation = np.abs(local["dissipation"] - ref["dissipation"])
            for A in (6.0, 8.0):
                for start in (b"AFM", b"FM"):
                    s = (local["A"] == A) & (local["ic"] == start)
                    D = local["dissipation"][s]
                    print(f"| {sigma:g} | {rtol:g} | {A:g} | {start.decode()} | {np.median(deviation[s] / D):.1e} "
                          f"| {np.median(local['dissipation_error'][s] / D):.1e} "
                          f"| {np.mean(local['dissipation_error'][s] >= deviation[s]):.2f} "
                          f"| {np.median(shadow['dissipation_error'][s] / D):.1e} "
                          f"| {np.mean(shadow['dissipation_error'][s] >= deviation[s]):.2f} "
                          f"| {np.mean(shadow['symmetry_limited'][s]):.2f} |")
    seconds = demo_seconds(args.rotorsweep, workdir, args.threads, args.repeats)
    print(f"\ndemo (examples/friction_curve.toml), medians of {args.repeats}: local {seconds['local']:.3f} s, "
          f"shadow {seconds['shadow']:.3f} s, ratio {seconds['shadow'] / seconds['local']:.2f}")


if __name__ == "__main__":
    main()
