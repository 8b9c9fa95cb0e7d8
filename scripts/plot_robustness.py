#!/usr/bin/python3
"""Robustness to the initial condition: D/N against A for each initial noise η (mean over the
replicas ± its standard error), one panel per initial kind, with the FM→CP and CP→AFM transitions
(where the CP fraction crosses 1/2) marked per η.
Usage: plot_robustness.py RESULT.h5 OUT.png"""
import argparse
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def crossings(A, fraction):
    """A values where the fraction crosses 1/2 (linear interpolation between points)."""
    out = []
    for i in range(len(A) - 1):
        f0, f1 = fraction[i] - 0.5, fraction[i + 1] - 0.5
        if f0 * f1 < 0:
            out.append(A[i] + (A[i + 1] - A[i]) * f0 / (f0 - f1))
    return out


def main(h5_path, png_path):
    with h5py.File(h5_path, "r") as f:
        if not f.attrs.get("complete", False):
            sys.exit(f"error: {h5_path} is incomplete (the run did not finish)")
        c = f["curves"]
        A, noise, rows = c["A"][:], c["noise"][:], c["rows"][:]
        ic = c["ic"].asstr()[:]
        d, sem = c["dissipation_mean"][:] / rows, c["dissipation_sem"][:] / rows
        cp = c["fraction_CP"][:] if "fraction_CP" in c else None
    kinds = sorted(set(ic))
    fig, axes = plt.subplots(1, len(kinds), figsize=(6.5 * len(kinds), 4.5), squeeze=False)
    lines = []
    for ax, kind in zip(axes[0], kinds):
        for eta in np.unique(noise):
            sel = (ic == kind) & (noise == eta)
            order = np.argsort(A[sel])
            a = A[sel][order]
            line = ax.errorbar(a, d[sel][order], yerr=np.nan_to_num(sem[sel][order]), marker=".", ms=3, lw=1,
                               capsize=2, label=f"η = {eta:g}")
            if cp is not None:
                for x in crossings(a, cp[sel][order]):
                    ax.axvline(x, color=line[0].get_color(), ls=":", lw=1)
                    lines.append(f"{kind} η = {eta:g}: CP fraction crosses 1/2 at A = {x:.3f}")
        ax.set_xlabel("A")
        ax.set_ylabel("d = D/N per period")
        ax.set_title(f"{kind} starts: friction against A for each noise η")
        ax.legend()
    fig.tight_layout()
    fig.savefig(png_path, dpi=120)
    print("\n".join(lines))
    print(f"wrote {png_path}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("result")
    parser.add_argument("png")
    args = parser.parse_args()
    main(args.result, args.png)
