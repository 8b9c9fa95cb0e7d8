#!/usr/bin/python3
"""Basin fractions against A: per curve point the fraction of members in each regime (FM, AFM,
CP, DW, SA where observables.slip_kinds is on, unsettled) and failed, each as its own line with its
Wilson 95 % interval drawn as an error bar at the fraction's own value; one panel per curve (initial
kind, noise and offset, N, g, rtol: never mixed), the legend beside the panels (docs/model.md §3, "Basin
fractions").
Usage: plot_basins.py RESULT.h5 OUT.png [--kind random]"""
import argparse
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

CATEGORIES = [("AFM", "tab:blue"), ("CP", "tab:orange"), ("SA", "gold"), ("DW", "tab:purple"),
              ("FM", "tab:red"), ("unsettled", "tab:gray"), ("failed", "black")]


def figure(h5_path, kind):
    """The figure of a result file (main() saves it)."""
    with h5py.File(h5_path, "r") as f:
        if not f.attrs.get("complete", False):
            sys.exit(f"error: {h5_path} is incomplete (the run did not finish)")
        c = f["curves"]
        if "fraction_CP" not in c:
            sys.exit(f"error: {h5_path} has no regime fractions (observables.alignment and slips are needed)")
        ic = c["ic"].asstr()[:]
        keep = ic == kind if kind else np.ones(len(ic), bool)
        if not keep.any():
            sys.exit(f"error: no curve points with initial kind {kind!r} (kinds: {sorted(set(ic))})")
        A = c["A"][:][keep]
        # a panel per curve: its start (kind, noise, offset) and its N, g and rtol, never mixed
        axes_of = {name: (c[name].asstr()[:] if name == "ic" else c[name][:])[keep]
                   for name in ("ic", "noise", "offset", "rows", "g", "rtol")}
        data = {name: (c[f"fraction_{name}"][:][keep], c[f"fraction_{name}_low"][:][keep],
                       c[f"fraction_{name}_high"][:][keep]) for name, _ in CATEGORIES
                if f"fraction_{name}" in c}  # SA: only with observables.slip_kinds
        members = c["members"][:][keep]
    keys = list(zip(*(axes_of[name].tolist() for name in axes_of)))
    panels = sorted(set(keys))
    varying = {name: len(set(values.tolist())) > 1 for name, values in axes_of.items()}
    fig, axes = plt.subplots(1, len(panels), figsize=(6.5 * len(panels) + 1.6, 4.5), squeeze=False)
    for ax, panel in zip(axes[0], panels):
        sel = np.array([key == panel for key in keys])
        order = np.argsort(A[sel])
        a = A[sel][order]
        for name, colour in CATEGORIES:
            if name not in data:
                continue
            frac, low, high = (x[sel][order] for x in data[name])
            if not frac.any():
                continue
            ax.errorbar(a, frac, yerr=[frac - low, high - frac], fmt="o-", ms=3, lw=1, color=colour, capsize=2,
                        label=name)
        ax.set_xlabel("A")
        ax.set_ylabel("fraction of members")
        ax.set_ylim(-0.02, 1.02)
        start, eta, theta0, size, g, rtol = panel
        parts = [f"{start} starts"]
        if start in ("FM", "AFM"):  # random and exact starts have no η or θ0
            parts.append(f"η = {eta:g}")
            if varying["offset"]:
                parts.append(f"θ0 = {theta0:g}")
        parts += [text for name, text in (("rows", f"N = {size}"), ("g", f"g = {g:g}"), ("rtol", f"rtol = {rtol:g}"))
                  if varying[name]]
        ax.set_title(", ".join(parts) + f", {int(members[sel][0])} per A (Wilson 95 %)", fontsize=9)
    axes[0][-1].legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    fig.tight_layout()
    return fig


def main(h5_path, png_path, kind):
    figure(h5_path, kind).savefig(png_path, dpi=120, bbox_inches="tight")
    print(f"wrote {png_path}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("result")
    parser.add_argument("png")
    parser.add_argument("--kind", default="random", help="initial kind to draw ('' for all points)")
    args = parser.parse_args()
    main(args.result, args.png, args.kind)
