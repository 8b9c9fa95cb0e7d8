#!/usr/bin/python3
"""Plots a sweep's friction curve: dissipation per period and row d = D/N against A, one panel per (N,
rtol) so that nothing is averaged across sizes or tolerances; members coloured by regime with their error
bars (dissipation_error / N, where it is a bound), unresolved members hollow, symmetry-limited ones (D
decided by the integration error: no bound) as triangles and members whose shadow run departed as
crosses; one line per (g, initial kind, noise, offset) through the mean over its settled members (regime
not unsettled, status ok). For periodic nearest-neighbour rows only (the model they belong to, named in
the legend): the small-A (AFM, dashed) and large-A (FM, dotted) limits of model.md §4 for each g in its
line's colour, and the quasi-static CP friction J(A) of the landscape (D/N → J as g → 0). The title
names the couplings, the stepper, the disorder and the temperature. The legends stand beside the axes.
Reads the file with the rotorsweep Python module (build/python).
Usage: plot_friction.py RESULT.h5 OUT.png [--no-jump]"""
import argparse
import sys
import tomllib
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "build" / "python"))
import rotorsweep  # noqa: E402

REGIME_COLOURS = {"AFM": "tab:blue", "CP": "tab:orange", "SA": "gold", "DW": "tab:purple", "FM": "tab:red",
                  "unsettled": "tab:gray"}
#: one per (g, initial kind) curve, apart from the regimes' colours and J(A)'s green
CURVE_COLOURS = ["tab:brown", "tab:olive", "tab:cyan", "tab:pink", "k", "tab:purple"]


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


def member_flags(m, count):
    """Each member's flags: its error a bound (resolved or too large), symmetry-limited, shadow departed."""
    def flag(name, absent):
        return m[name].values != 0 if name in m else np.full(count, absent)
    limited, departed = flag("symmetry_limited", False), flag("shadow_departed", False)
    resolved = flag("dissipation_resolved", True) & ~limited & ~departed
    return resolved, limited, departed


def settled_means(A, d, curve, settled):
    """Per curve and A, the mean of d over the settled members (NaN where none is settled)."""
    means = {}
    for key in sorted(set(curve)):
        on = curve == key
        values = np.unique(A[on])
        mean = np.array([np.mean(d[on & (A == a) & settled]) if (on & (A == a) & settled).any() else np.nan
                         for a in values])
        means[key] = (values, mean)
    return means


def scene_model(ds):
    """What the file's scene says of its model and integrator: its couplings in words, whether they are
    periodic nearest-neighbour rows (the model the limits of model.md §4 and J(A) belong to), the stepper,
    and its disorder and temperature (None where it has none)."""
    scene = tomllib.loads(ds.attrs["scene"])
    model = scene.get("model", {})
    if "coupling_table" in model:
        couplings = "a coupling table"
    else:
        couplings = "dipolar couplings" if model.get("couplings", "nearest") == "dipolar" else "nearest neighbours"
    open_rows = model.get("boundary", "periodic") == "open"
    nearest = couplings == "nearest neighbours" and not open_rows
    couplings += ", open rows" if open_rows else ""
    stepper = scene.get("numerics", {}).get("stepper", rotorsweep.default_stepper)
    disorder = ", ".join(f"σ_{key} = {value:g}" for key, value in scene.get("disorder", {}).items()
                         if key in ("A", "anisotropy", "coupling")) or None
    temperature = scene.get("thermal", {}).get("temperature")
    return couplings, nearest, stepper, disorder, temperature


def series_label(values, varying):
    """'g = 0.002, random start' from a series' (g, ic, noise, offset), naming only the axes the file varies
    (and always the start)."""
    g, kind, noise, offset = values
    parts = [f"g = {g:g}"] if varying["g"] else []
    parts.append(f"{kind} start")
    if varying["noise"]:
        parts.append(f"noise {noise:g}")
    if varying["offset"]:
        parts.append(f"offset {offset:g}")
    return ", ".join(parts)


def figure(h5_path, jump=True):
    """The figure of a result file (main() saves it): one panel per (N, rtol), so that nothing is averaged
    across sizes or tolerances; in each, one line per (g, start, noise, offset)."""
    ds = open_result(h5_path)
    couplings, nearest, stepper, disorder, temperature = scene_model(ds)
    m = rotorsweep.members(ds)
    shape = m.dissipation.shape
    A, g, rows, rtol, noise, offset = (np.broadcast_to(m[name].values, shape)
                                       for name in ("A", "g", "rows", "rtol", "noise", "offset"))
    d = m.dissipation.values / rows
    error = (m.dissipation_error.values if "dissipation_error" in m else np.full(len(A), np.nan)) / rows
    regime = m.regime.values.astype(str) if "regime" in m else np.full(len(A), "unsettled")
    status = m.status.values.astype(str)
    ic = np.broadcast_to(m.ic.values, shape).astype(str)
    ok = status == "ok"
    resolved, limited, departed = member_flags(m, len(A))
    bounded = ok & ~limited & ~departed & np.isfinite(error)
    varying = {"g": len(np.unique(g)) > 1, "noise": len(np.unique(noise)) > 1, "offset": len(np.unique(offset)) > 1}

    panels = sorted(set(zip(rows.tolist(), rtol.tolist())))
    fig, axes = plt.subplots(len(panels), 1, figsize=(11, 1.0 + 4.5 * len(panels)), sharex=True, squeeze=False)
    for (size, tolerance), ax in zip(panels, axes[:, 0]):
        here = (rows == size) & (rtol == tolerance)
        # one line per (g, start, noise, offset): the mean over its settled members at each A
        curve = np.array([f"{gv!r}|{k}|{nv!r}|{ov!r}" for gv, k, nv, ov in zip(g, ic, noise, offset)])
        g_colour = {}  # the limit laws of a g take the colour of its first line
        for k, (key, (values, mean)) in enumerate(
                settled_means(A[here], d[here], curve[here], (ok & (regime != "unsettled"))[here]).items()):
            g_text, kind, noise_text, offset_text = key.split("|")
            colour = CURVE_COLOURS[k % len(CURVE_COLOURS)]
            g_colour.setdefault(float(g_text), colour)
            label = series_label((float(g_text), kind, float(noise_text), float(offset_text)), varying)
            ax.plot(values, mean, color=colour, lw=1.0, alpha=0.8, label=f"{label}: mean over settled members")
        # error bars where the error is a bound (drawn first, under the markers)
        on = bounded & here
        ax.errorbar(A[on], d[on], yerr=error[on], fmt="none", ecolor="0.45", elinewidth=0.8,
                    capsize=1.5, zorder=2, label="dissipation_error / N (a bound)")
        for name, colour in REGIME_COLOURS.items():
            sel = (regime == name) & ok & here
            if not sel.any():
                continue
            ax.scatter(A[sel & resolved], d[sel & resolved], s=12, color=colour, zorder=3,
                       label=f"{name} ({sel.sum()} members)")
            ax.scatter(A[sel & ~resolved & ~limited & ~departed], d[sel & ~resolved & ~limited & ~departed],
                       s=14, facecolors="none", edgecolors=colour, zorder=3)
            ax.scatter(A[sel & limited & ~departed], d[sel & limited & ~departed], s=16, marker="^",
                       facecolors="none", edgecolors=colour, zorder=3)
            ax.scatter(A[sel & departed], d[sel & departed], s=18, marker="x", color=colour, zorder=4)
        # what the marker shapes say, in grey
        for count, marker, filled, text in (
                ((ok & here & resolved).sum(), "o", True, "resolved"),
                ((ok & here & ~resolved & ~limited & ~departed).sum(), "o", False, "not resolved (error >= 0.1 D)"),
                ((ok & here & limited & ~departed).sum(), "^", False, "symmetry-limited: no error bound"),
                ((ok & here & departed).sum(), "x", True, "shadow departed: no error estimate")):
            if count:
                ax.plot([], [], ls="none", marker=marker, ms=4, color="0.4",
                        markerfacecolor="0.4" if filled else "none", label=f"{text} ({count})")
        failed = ~ok & here
        if failed.any():
            ax.scatter(A[failed], np.full(failed.sum(), np.nanmin(d)), marker="X", color="k",
                       label=f"failed ({failed.sum()})", zorder=4)
        if nearest:  # model.md §4's laws and J(A) belong to periodic nearest-neighbour rows only
            A_line = np.linspace(max(A.min(), 1e-3), A.max(), 400)
            for g_value in np.unique(g[here]):
                colour = g_colour.get(float(g_value), "k")
                small = A_line <= 0.5 * A.max()
                ax.plot(A_line[small], small_A_limit(A_line[small], g_value), "--", color=colour, lw=1,
                        label=rf"nearest neighbours, small A: $\pi A^2 g/(100+g^2)$, g = {g_value:g}")
                large = A_line >= 0.5 * A.max()
                ax.plot(A_line[large], large_A_limit(A_line[large], g_value), ":", color=colour, lw=1.2,
                        label=rf"nearest neighbours, large A: $2\pi g + 36\pi g/A^2$, g = {g_value:g}")
            if jump and A.min() < rotorsweep.A_star and A.max() > rotorsweep.A_minus:
                A_J = np.linspace(rotorsweep.A_minus, rotorsweep.A_star, 2000)
                J = rotorsweep.jump_friction(A_J)
                keep = J > 0.5 * np.nanmin(d[d > 0])  # J → 0 at A_*: stay within the sweep's range
                ax.plot(A_J[keep], J[keep], color="tab:green", lw=1.5,
                        label=r"nearest neighbours, quasi-static CP: $J(A)$ on $[A_-, A_*]$ ($g \to 0$)")
        ax.set_yscale("log")
        ax.set_ylabel("D/N per period and row  [ε]")
        ax.set_title(f"N = {size}, rtol = {tolerance:g}", fontsize=10)
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)  # beside the data
    axes[-1, 0].set_xlabel("substrate strength A")
    conditions = [couplings, f"stepper {stepper}"]
    conditions.append(f"disorder {disorder}" if disorder else "no disorder")
    if temperature:
        conditions.append(f"T = {temperature:g}")
    if not nearest:
        conditions.append("no reference curves (they belong to periodic nearest-neighbour rows)")
    fig.suptitle("magnetic friction  ⟨F⟩ = −D ε / P:  " + ", ".join(conditions), fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 1 - 0.4 / fig.get_figheight()))  # the title above the first panel
    return fig


def main(h5_path, png_path, jump=True):
    figure(h5_path, jump).savefig(png_path, dpi=130, bbox_inches="tight")
    print(f"wrote {png_path}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("result", help="result file of `rotorsweep run`")
    parser.add_argument("png", help="figure to write")
    parser.add_argument("--no-jump", action="store_true", help="leave out the quasi-static J(A)")
    args = parser.parse_args()
    main(args.result, args.png, not args.no_jump)
