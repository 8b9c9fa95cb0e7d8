#!/usr/bin/python3
"""Plots a sweep's friction curve: dissipation per period and row d = D/N against A, one coloured
curve per (g, initial kind), members coloured by regime, with the small-A (AFM, dashed) and
large-A (FM, dotted) limits of model.md §4 for each g in its curve's colour, and the quasi-static CP friction J(A) of the landscape
(D/N → J as g → 0). Reads the file with the rotorsweep Python module (build/python).
Usage: plot_friction.py RESULT.h5 OUT.png [--no-jump]"""
import argparse
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "build" / "python"))
import rotorsweep  # noqa: E402

REGIME_COLOURS = {"AFM": "tab:blue", "CP": "tab:orange", "SA": "gold", "FM": "tab:red", "unsettled": "tab:gray"}
#: one per (g, initial kind) curve, apart from the regimes' colours and J(A)'s green
CURVE_COLOURS = ["tab:purple", "tab:brown", "tab:olive", "tab:cyan", "tab:pink", "k"]


def small_A_limit(A, g):
    """AFM state, small A: d = π A² g / (100 + g²)."""
    return np.pi * A**2 * g / (100 + g**2)


def large_A_limit(A, g):
    """FM state, large A: d = 2π g + 36 π g / A²."""
    return 2 * np.pi * g + 36 * np.pi * g / A**2


def open_result(h5_path):
    """The result as a Dataset stacked into plan order (rotorsweep module, built into build/python)."""
    try:
        ds = rotorsweep.open(h5_path)
    except ValueError as error:
        sys.exit(f"error: {error}")
    if "dissipation" not in ds:
        sys.exit(f"error: {h5_path} has no dissipation (observables.dissipation = false)")
    return ds


def main(h5_path, png_path, jump=True):
    ds = open_result(h5_path)
    m = rotorsweep.members(ds)
    A, g, rows = (np.broadcast_to(m[name].values, m.dissipation.shape) for name in ("A", "g", "rows"))
    d = m.dissipation.values / rows
    regime = m.regime.values.astype(str) if "regime" in m else np.full(len(A), "unsettled")
    status = m.status.values.astype(str)

    fig, ax = plt.subplots(figsize=(8, 5))
    # the replica mean of each curve point (/curves), one line per (g, initial kind)
    points = ds.curve_dissipation_mean / ds.rows
    lines = [d for d in points.dims if d != "A"]
    palette = CURVE_COLOURS
    g_colour = {}  # the limit laws of a g take the colour of its first curve
    for k, (_, line) in enumerate(points.stack(line=lines).groupby("line") if lines else [(None, points)]):
        g_value, kind = np.atleast_1d(line.g.values)[0], np.atleast_1d(line.ic.values)[0]
        colour = palette[k % len(palette)]
        g_colour.setdefault(float(g_value), colour)
        ax.plot(line.A.values, np.ravel(line.values), color=colour, lw=1.0, alpha=0.8,
                label=f"g = {g_value:g}, {kind} start")
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
        colour = g_colour.get(float(g_value), "k")
        small = A_line <= 0.5 * A.max()
        ax.plot(A_line[small], small_A_limit(A_line[small], g_value), "--", color=colour, lw=1,
                label=rf"small A: $\pi A^2 g/(100+g^2)$, g = {g_value:g}")
        large = A_line >= 0.5 * A.max()
        ax.plot(A_line[large], large_A_limit(A_line[large], g_value), ":", color=colour, lw=1.2,
                label=rf"large A: $2\pi g + 36\pi g/A^2$, g = {g_value:g}")
    if jump and A.min() < rotorsweep.A_star and A.max() > rotorsweep.A_minus:
        A_J = np.linspace(rotorsweep.A_minus, rotorsweep.A_star, 2000)
        J = rotorsweep.jump_friction(A_J)
        keep = J > 0.5 * np.nanmin(d[d > 0])  # J → 0 at A_*: stay within the sweep's range
        ax.plot(A_J[keep], J[keep], color="tab:green", lw=1.5,
                label=r"quasi-static CP: $J(A)$ on $[A_-, A_*]$ ($g \to 0$)")
    ax.set_yscale("log")
    ax.set_xlabel("substrate strength A")
    ax.set_ylabel("dissipated energy per period and row  D/N  [ε]")
    ax.set_title(f"magnetic friction  ⟨F⟩ = −D ε / P,  N = {', '.join(str(n) for n in np.unique(rows))}")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7, loc="lower right")
    fig.tight_layout()
    fig.savefig(png_path, dpi=130)
    print(f"wrote {png_path}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("result", help="result file of `rotorsweep run`")
    parser.add_argument("png", help="figure to write")
    parser.add_argument("--no-jump", action="store_true", help="leave out the quasi-static J(A)")
    args = parser.parse_args()
    main(args.result, args.png, not args.no_jump)
