#!/usr/bin/python3
"""Friction curves against the range of the dipolar couplings (docs/model.md §1 "Extended
couplings", §8): N = 20, g = 0.0011, AFM starts (4 noise draws), for nearest neighbours and point
dipoles over M = 1, 2, 4, 8 and all rows, periodic and open. Plots D/N against A and writes the CP
interval (the A values where at least half the members slip) and the friction peak per curve; for
open rows also the row profile: D_j against j at A = PROFILE_A, and the edge rows' D_j and the
bulk's against A. Writes results/range_study.png, results/range_profiles.png and
results/range_study.csv (about a minute on 2 cores).
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
ROWS = 20
PROFILE_A = 6.0
BULK = slice(5, 15)  # rows 5 .. 14: five rows from either edge
EDGE_CURVES = ("nearest", "M = 4", "all")


def curve(model, boundary, threads):
    section = {"rows": ROWS, "boundary": boundary}
    if model:
        section.update({"couplings": "dipolar", **model})
    scene = {
        "model": section,
        "drive": {"g": [0.0011]},
        "sweep": {"A": A_GRID},
        "initial": {"kinds": ["AFM"], "replicas": 4},
        "schedule": {"relax_periods": 4, "average_periods": 4},
    }
    ds = rotorsweep.run(scene, threads=threads or None, progress=False)  # 0: every core
    A = ds.A.values
    per_row = ds.curve_dissipation_mean.squeeze().values / ROWS
    cp = ds.curve_fraction_CP.squeeze().values >= 0.5
    profile = ds.row_dissipation.mean("replica").values if boundary == "open" else None
    return A, per_row, cp, profile


def edge_and_bulk(profile):
    """Mean D_j of the two edge rows and mean D_j of the bulk rows, per A."""
    return 0.5 * (profile[:, 0] + profile[:, ROWS - 1]), profile[:, BULK].mean(axis=1)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", default="results")
    parser.add_argument("--threads", type=int, default=0)
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    figure, axes = plt.subplots(1, 2, figsize=(11, 4.2), sharey=True)
    profile_figure, profile_axes = plt.subplots(1, 2, figsize=(11, 4.2))
    rows = ["couplings,boundary,cp_from,cp_to,peak_A,peak_D_per_row,a_M,b_M,c_M,A_minus,A_star,J_M_peak_A,"
            "J_M_peak,edge_over_bulk_at_profile_A,edge_over_bulk_at_peak"]
    A_fine = np.linspace(A_GRID["from"], A_GRID["to"], 621)
    for axis, boundary in zip(axes, ("periodic", "open")):
        for name, model in MODELS:
            A, d, cp, profile = curve(model, boundary, args.threads)
            line, = axis.semilogy(A, np.maximum(d, 1e-8), marker=".", label=name)
            peak = int(np.nanargmax(d))
            edges = ","
            if profile is not None:
                at = int(np.argmin(np.abs(A - PROFILE_A)))
                line, = profile_axes[0].plot(np.arange(ROWS), profile[at] / d[at], marker=".", label=name)
                edge, bulk = edge_and_bulk(profile)
                if name in EDGE_CURVES:
                    profile_axes[1].plot(A, bulk, color=line.get_color(), label=f"{name}, bulk")
                    profile_axes[1].plot(A, edge, color=line.get_color(), ls="--", label=f"{name}, edge")
                edges = f"{edge[at] / bulk[at]:.4g},{edge[peak] / bulk[peak]:.4g}"
            cp_from, cp_to = (A[cp].min(), A[cp].max()) if cp.any() else (np.nan, np.nan)
            landscape = ",,,,,,"
            if boundary == "periodic":
                k = (1.5, 2.0, 0.0) if not model else rotorsweep.two_angle_coefficients(model["range"], rows=20)
                J, _ = rotorsweep.quasi_static_friction(A_fine, k)
                axis.semilogy(A_fine[J > 0], J[J > 0], ls="--", lw=1, color=line.get_color())
                lo, hi = rotorsweep.landscape.cp_interval(k)
                j_peak = int(np.argmax(J))
                landscape = f"{k[0]:.4f},{k[1]:.4f},{k[2]:.4f},{lo:.4f},{hi:.4f},{A_fine[j_peak]:.3f},{J[j_peak]:.5g}"
            rows.append(f"{name},{boundary},{cp_from:.2f},{cp_to:.2f},{A[peak]:.2f},{d[peak]:.5g},{landscape},"
                        f"{edges}")
            print(rows[-1], flush=True)
        axis.set_title(f"{boundary} rows, N = 20, g = 0.0011")
        axis.set_xlabel("A")
    axes[0].set_ylabel("D / N per period (ε)")
    axes[0].legend(title="couplings")
    figure.tight_layout()
    figure.savefig(out / "range_study.png", dpi=120)
    profile_axes[0].set_title(f"open rows at A = {PROFILE_A:g}: each row's share of D")
    profile_axes[0].set_xlabel("row j")
    profile_axes[0].set_ylabel("D_j / (D / N)")
    profile_axes[0].legend(title="couplings")
    profile_axes[1].set_title("open rows: D_j of the edge rows and of the bulk (rows 5-14)")
    profile_axes[1].set_xlabel("A")
    profile_axes[1].set_ylabel("D_j per period (ε)")
    profile_axes[1].set_yscale("symlog", linthresh=1e-2)
    profile_axes[1].axhline(0.0, color="grey", lw=0.8)
    profile_axes[1].legend(fontsize="small")
    profile_figure.tight_layout()
    profile_figure.savefig(out / "range_profiles.png", dpi=120)
    (out / "range_study.csv").write_text("\n".join(rows) + "\n")
    print(f"wrote {out / 'range_study.png'}, {out / 'range_profiles.png'} and {out / 'range_study.csv'}")


if __name__ == "__main__":
    main()
