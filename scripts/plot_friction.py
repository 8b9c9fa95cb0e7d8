#!/usr/bin/python3
"""Plots a sweep's friction curve: dissipation per period and row d = D/N against A, one curve
per (g, initial kind), members coloured by regime, with the small-A (AFM) and large-A (FM)
limits of model.md §4 drawn over it, and optionally the quasi-static CP friction J(A) from
`rotorsweep landscape jump-friction` (D/N → J as g → 0).
Usage: plot_friction.py RESULT.h5 OUT.png [--jump JUMP.h5]"""
import argparse
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

REGIME_COLOURS = {"AFM": "tab:blue", "CP": "tab:orange", "FM": "tab:red", "unsettled": "tab:gray"}


def small_A_limit(A, g):
    """AFM state, small A: d = π A² g / (100 + g²)."""
    return np.pi * A**2 * g / (100 + g**2)


def large_A_limit(A, g):
    """FM state, large A: d = 2π g + 36 π g / A²."""
    return 2 * np.pi * g + 36 * np.pi * g / A**2


def main(h5_path, png_path, jump_path=None):
    with h5py.File(h5_path, "r") as f:
        if not f.attrs.get("complete", False):
            sys.exit(f"error: {h5_path} is incomplete (the run did not finish)")
        m = f["members"]
        if "dissipation" not in m:
            sys.exit(f"error: {h5_path} has no dissipation (observables.dissipation = false)")
        A, g, rows = m["A"][:], m["g"][:], m["rows"][:]
        d = m["dissipation"][:] / rows
        ic = m["ic"].asstr()[:]
        regime = m["regime"].asstr()[:] if "regime" in m else np.full(len(A), "unsettled")
        status = m["status"].asstr()[:]

    fig, ax = plt.subplots(figsize=(8, 5))
    for g_value in np.unique(g):
        for kind in np.unique(ic):
            sel = (g == g_value) & (ic == kind) & (status == "ok")
            order = np.argsort(A[sel])
            # mean over replicas at each A
            A_sel, d_sel = A[sel][order], d[sel][order]
            A_points = np.unique(A_sel)
            d_mean = np.array([d_sel[A_sel == a].mean() for a in A_points])
            ax.plot(A_points, d_mean, color="k", lw=0.8, alpha=0.6, label=f"g = {g_value:g}, {kind} start")
    for name, colour in REGIME_COLOURS.items():
        sel = (regime == name) & (status == "ok")
        if sel.any():
            ax.scatter(A[sel], d[sel], s=9, color=colour, label=f"{name} ({sel.sum()} members)", zorder=3)
    failed = status != "ok"
    if failed.any():
        ax.scatter(A[failed], np.full(failed.sum(), np.nanmin(d)), marker="x", color="k",
                   label=f"failed ({failed.sum()})", zorder=4)

    A_line = np.linspace(max(A.min(), 1e-3), A.max(), 400)
    for g_value in np.unique(g):
        small = A_line <= 0.5 * A.max()
        ax.plot(A_line[small], small_A_limit(A_line[small], g_value), "--", color="tab:blue", lw=1,
                label=r"small A: $\pi A^2 g/(100+g^2)$" if g_value == g.min() else None)
        large = A_line >= 0.5 * A.max()
        ax.plot(A_line[large], large_A_limit(A_line[large], g_value), "--", color="tab:red", lw=1,
                label=r"large A: $2\pi g + 36\pi g/A^2$" if g_value == g.min() else None)
    if jump_path:
        with h5py.File(jump_path, "r") as f:
            if not f.attrs.get("complete", False):
                sys.exit(f"error: {jump_path} is incomplete")
            A_J, J = f["A"][:], f["J"][:]
            keep = J > 0.5 * np.nanmin(d[d > 0])  # J → 0 at A_*: stay within the sweep's range
            ax.plot(A_J[keep], J[keep], color="tab:green", lw=1.5,
                    label=r"quasi-static CP: $J(A)$ on $[A_-, A_*]$ ($g \to 0$)")
    ax.set_yscale("log")
    ax.set_xlabel("substrate strength A")
    ax.set_ylabel("dissipated energy per period and row  D/N  [ε]")
    ax.set_title(f"magnetic friction  ⟨F⟩ = −D ε / P,  N = {rows[0]}")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7, loc="lower right")
    fig.tight_layout()
    fig.savefig(png_path, dpi=130)
    print(f"wrote {png_path}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("result", help="result file of `rotorsweep run`")
    parser.add_argument("png", help="figure to write")
    parser.add_argument("--jump", help="file of `rotorsweep landscape jump-friction` to overlay J(A)")
    args = parser.parse_args()
    main(args.result, args.png, args.jump)
