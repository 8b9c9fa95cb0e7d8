#!/usr/bin/python3
"""Friction curves against the range of the dipolar couplings (docs/model.md §1 "Extended
couplings", §8): N = 20, g = 0.0011, AFM starts (4 noise draws), for nearest neighbours and point
dipoles over M = 1, 2, 4, 8 and all rows, periodic and open. Plots D/N against A and writes the CP
interval (the A values where at least half the members slip) and the friction peak per curve.
Writes results/range_study.png and results/range_study.csv (under a minute on 2 cores).
Usage: range_study.py [--out results] [--threads 0]"""
import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import rotorsweep

A_GRID = {"from": 0.5, "to": 16.0, "count": 63}
MODELS = [("nearest", {}), ("M = 1", {"range": 1}), ("M = 2", {"range": 2}), ("M = 4", {"range": 4}),
          ("M = 8", {"range": 8}), ("all", {"range": "all"})]


def curve(model, boundary, threads):
    section = {"rows": 20, "boundary": boundary}
    if model:
        section.update({"couplings": "dipolar", **model})
    scene = {
        "model": section,
        "drive": {"g": [0.0011]},
        "sweep": {"A": A_GRID},
        "initial": {"kinds": ["AFM"], "replicas": 4},
        "schedule": {"relax_periods": 4, "average_periods": 4},
    }
    ds = rotorsweep.run(scene, threads=threads, progress=False)
    A = ds.A.values
    per_row = ds.curve_dissipation_mean.squeeze().values / 20
    cp = ds.curve_fraction_CP.squeeze().values >= 0.5
    return A, per_row, cp


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", default="results")
    parser.add_argument("--threads", type=int, default=0)
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    figure, axes = plt.subplots(1, 2, figsize=(11, 4.2), sharey=True)
    rows = ["couplings,boundary,cp_from,cp_to,peak_A,peak_D_per_row,a_M,b_M,c_M,A_minus,A_star,J_M_peak_A,"
            "J_M_peak"]
    A_fine = np.linspace(A_GRID["from"], A_GRID["to"], 621)
    for axis, boundary in zip(axes, ("periodic", "open")):
        for name, model in MODELS:
            A, d, cp = curve(model, boundary, args.threads)
            line, = axis.semilogy(A, np.maximum(d, 1e-8), marker=".", label=name)
            peak = int(np.nanargmax(d))
            cp_from, cp_to = (A[cp].min(), A[cp].max()) if cp.any() else (np.nan, np.nan)
            landscape = ",,,,,,"
            if boundary == "periodic":
                k = (1.5, 2.0, 0.0) if not model else rotorsweep.two_angle_coefficients(model["range"], rows=20)
                J, _ = rotorsweep.quasi_static_friction(A_fine, k)
                axis.semilogy(A_fine[J > 0], J[J > 0], ls="--", lw=1, color=line.get_color())
                lo, hi = rotorsweep.landscape.cp_interval(k)
                j_peak = int(np.argmax(J))
                landscape = f"{k[0]:.4f},{k[1]:.4f},{k[2]:.4f},{lo:.4f},{hi:.4f},{A_fine[j_peak]:.3f},{J[j_peak]:.5g}"
            rows.append(f"{name},{boundary},{cp_from:.2f},{cp_to:.2f},{A[peak]:.2f},{d[peak]:.5g},{landscape}")
            print(rows[-1], flush=True)
        axis.set_title(f"{boundary} rows, N = 20, g = 0.0011")
        axis.set_xlabel("A")
    axes[0].set_ylabel("D / N per period (ε)")
    axes[0].legend(title="couplings")
    figure.tight_layout()
    figure.savefig(out / "range_study.png", dpi=120)
    (out / "range_study.csv").write_text("\n".join(rows) + "\n")
    print(f"wrote {out / 'range_study.png'} and {out / 'range_study.csv'}")


if __name__ == "__main__":
    main()
