#!/usr/bin/python3
"""The slider scan of `rotorsweep slider` (docs/model.md §9): friction force against the layer separation h
(the experiment's curve, with the integration error's bars where the file has them), the order parameters
against h, and the friction's time series at three
separations (the closest, the friction peak, the farthest). With --rows, the friction the row model
predicts for the slider size whose columns equal its model.row_length (a `rotorsweep run` result), its
A mapped to h both ways of docs/model.md §9: the paper's (a/h)³ m_sub/m and the substrate
field's first harmonic. With --velocity, a scan over drive.speed (examples/friction_velocity.toml): the
friction against the sliding speed on log axes, one curve per separation (all, or --separations in mm)
and damping, with its slope d log F / d log v at the slowest speeds (1: viscous, 0: speed-independent),
and the order parameter across y against the speed.
Usage: plot_slider.py RESULT.h5 OUT.png [--rows ROWS.h5 | --velocity [--separations MM,MM,...]]"""
import argparse
import re
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def row_length(rows_path):
    """Rotors per row of a row-model result (its scene's model.row_length), or None."""
    with h5py.File(rows_path, "r") as f:
        if not f.attrs.get("complete", False):
            sys.exit(f"error: {rows_path} is incomplete (the run did not finish)")
        found = re.search(r"(?m)^\s*row_length\s*=\s*(\d+)", f.attrs.get("scene", ""))
    return int(found.group(1)) if found else None


def row_model_curves(rows_path, h, A_paper, A_field, force_per_row_unit, slider_rows):
    """The row model's mean friction against h for both mappings of A, as the slider's total force. The
    file must hold one curve (one N, g, rtol and start): several would be drawn as one line."""
    with h5py.File(rows_path, "r") as f:
        c = f["curves"]
        A, D, N = c["A"][:], c["dissipation_mean"][:], c["rows"][:]
        axes = {name: set((c[name].asstr()[:] if name == "ic" else c[name][:]).tolist())
                for name in ("rows", "g", "rtol", "ic", "noise", "offset")}
    several = {name: sorted(values) for name, values in axes.items() if len(values) > 1}
    if several:
        sys.exit(f"error: {rows_path} holds several row-model curves ("
                 + "; ".join(f"{name} {', '.join(str(v) for v in values)}" for name, values in several.items())
                 + "): --rows takes a run of one N, g, rtol and start")
    order = np.argsort(A)
    A, force = A[order], (D / N)[order] * force_per_row_unit * slider_rows
    curves = []
    for label, A_of_h in (("A = (a/h)³ m_sub/m", A_paper), ("A from the field's first harmonic", A_field)):
        inside = (h >= h.min()) & (A_of_h >= A.min()) & (A_of_h <= A.max())
        curves.append((label, h[inside], np.interp(A_of_h[inside], A, force)))
    return curves


def read_curve(f, h5_path):
    """/curve of a complete slider result, or exit with what is wrong."""
    if f.attrs.get("kind", b"") not in ("slider", b"slider"):
        sys.exit(f"error: {h5_path} is not a slider result (rotorsweep slider writes those)")
    if not f.attrs.get("complete", False) or "curve" not in f:
        sys.exit(f"error: {h5_path} is incomplete (the scan did not finish, or it is a shard: merge it first)")
    return f["curve"]


def legend_below(ax, fontsize):
    """The axis's legend under it, clear of its data (the figure is saved with bbox_inches="tight")."""
    ax.legend(fontsize=fontsize, loc="upper center", bbox_to_anchor=(0.5, -0.14), borderaxespad=0)


def order_axis(ax, xlabel, ylabel, title, fontsize):
    """Labels an axis of order parameters, from −1 (AFM) to +1 (FM)."""
    ax.axhline(0, color="gray", lw=0.5)
    ax.set_ylim(-1.05, 1.05)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(f"{title} (+1 FM, −1 AFM)")
    legend_below(ax, fontsize)


def velocity_plot(h5_path, png_path, separations_mm=None):
    """Friction and order across y against the sliding speed, per separation and damping."""
    with h5py.File(h5_path, "r") as f:
        c = read_curve(f, h5_path)
        if "speed" not in c or len(np.unique(c["speed"][:])) < 2:
            sys.exit(f"error: {h5_path} has one sliding speed; --velocity needs a scan over drive.speed "
                     "(examples/friction_velocity.toml)")
        curve = {name: c[name][:] for name in ("speed", "damping", "separation", "columns", "rows", "friction",
                                                "friction_std", "order_y")}
    h_mm = curve["separation"] * 1e3
    chosen = sorted(set(np.round(h_mm, 6)))
    if separations_mm:
        missing = [h for h in separations_mm if not np.isclose(h_mm, h).any()]
        if missing:
            sys.exit(f"error: --separations {missing} mm are not in {h5_path} (it has {chosen} mm)")
        chosen = separations_mm
    sizes = sorted(set(zip(curve["columns"], curve["rows"])), key=lambda size: size[0] * size[1])
    dampings = sorted(set(curve["damping"]))
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.6))
    styles = ["o-", "s--", "^:", "d-."]
    for (columns, rows), h, (d, damping) in [(s, h, d) for s in sizes for h in chosen
                                              for d in enumerate(dampings)]:
        sel = ((curve["columns"] == columns) & (curve["rows"] == rows) & np.isclose(h_mm, h)
               & (curve["damping"] == damping))
        order = np.argsort(curve["speed"][sel])
        v = curve["speed"][sel][order] * 1e3
        friction, spread = curve["friction"][sel][order], curve["friction_std"][sel][order]
        slope = np.log(friction[1] / friction[0]) / np.log(v[1] / v[0])
        label = f"h = {h:g} mm" + (f", {columns} × {rows}" if len(sizes) > 1 else "")
        label += f", γ = {damping:g} kg m²/s" if len(dampings) > 1 else ""
        line, = left.loglog(v, friction, styles[d % len(styles)], ms=3,
                            label=f"{label} (slope {slope:.2f} at the slowest speeds)")
        if np.isfinite(spread).any():
            left.fill_between(v, friction - spread, friction + spread, color=line.get_color(), alpha=0.25)
        right.semilogx(v, curve["order_y"][sel][order], styles[d % len(styles)], ms=3, color=line.get_color(),
                       label=label)
    left.set_xlabel("sliding speed v (mm/s)")
    left.set_ylabel("mean friction force (N)")
    left.set_title("friction against speed (slope 1: viscous; 0: speed-independent)")
    legend_below(left, 7)
    order_axis(right, "sliding speed v (mm/s)", "mean cos(θ_i − θ_j), y-neighbours", "order across y", 7)
    fig.tight_layout()
    fig.savefig(png_path, dpi=120, bbox_inches="tight")
    print(f"wrote {png_path}")


def main(h5_path, png_path, rows_path=None):
    with h5py.File(h5_path, "r") as f:
        c = read_curve(f, h5_path)
        for axis in ("speed", "damping"):
            if axis in c and len(np.unique(c[axis][:])) > 1:
                sys.exit(f"error: {h5_path} scans {axis}s: draw it with --velocity (friction against speed)")
        curve = {name: c[name][:] for name in ("separation", "columns", "rows", "friction", "friction_std",
                                                "order_x", "order_y", "A_paper", "A_field")}
        # the integration error's bound (numerics.global_error = "shadow"); absent with "local"
        curve["friction_bias"] = c["friction_bias"][:] if "friction_bias" in c else None
        curve["separation"] = curve["separation"] * 1e3
        energy_unit, spacing, period = f.attrs["energy_unit"], f.attrs["spacing"], f.attrs["period"]
        series = None
        if "series" in f:
            m = f["members"]
            series = (f["series/time"][:], f["series/friction"][:], m["separation"][:] * 1e3, m["columns"][:],
                      m["rows"][:])
    sizes = sorted(set(zip(curve["columns"], curve["rows"])), key=lambda size: size[0] * size[1])
    compared = None  # the size the row model stands for: rows as long as the slider's
    if rows_path:
        length = row_length(rows_path)
        matching = [size for size in sizes if size[0] == length]
        if not matching:
            sys.exit(f"error: {rows_path} has rows of {length} rotors (model.row_length); the slider has "
                     f"{sorted(int(c) for c, _ in sizes)} columns")
        compared = matching[-1]
    fig, axes = plt.subplots(1, 3, figsize=(17, 4.6))
    for columns, rows in sizes:
        sel = (curve["columns"] == columns) & (curve["rows"] == rows)
        h, friction, spread = curve["separation"][sel], curve["friction"][sel], curve["friction_std"][sel]
        label = f"slider {columns} × {rows}"
        line, = axes[0].plot(h, friction, "o-", ms=3, label=label)
        if np.isfinite(spread).any():
            axes[0].fill_between(h, friction - spread, friction + spread, color=line.get_color(), alpha=0.25)
        if curve["friction_bias"] is not None:
            bias = curve["friction_bias"][sel]
            axes[0].errorbar(h, friction, yerr=bias, fmt="none", ecolor=line.get_color(), elinewidth=0.8,
                             capsize=2, label=f"{label}: integration error (largest {np.nanmax(bias):.1e} N)")
        axes[1].plot(h, curve["order_x"][sel], "o-", ms=3, color=line.get_color(), label=f"{label}: x-neighbours")
        axes[1].plot(h, curve["order_y"][sel], "s--", ms=3, color=line.get_color(), label=f"{label}: y-neighbours")
        if (columns, rows) == compared:
            # a row of `columns` rotors has the energy unit columns · μ0 m²/(4π a³); F = D ε / a
            for (name, hh, force), style in zip(
                    row_model_curves(rows_path, h, curve["A_paper"][sel], curve["A_field"][sel],
                                     columns * energy_unit / spacing, rows), ("--", ":")):
                axes[0].plot(hh, force, style, color="black", label=f"row model ({columns} × {rows}), {name}")
    ax = axes[0]
    ax.set_xlabel("layer separation h (mm)")
    ax.set_ylabel("mean friction force (N)")
    ax.set_title("friction against separation")
    legend_below(ax, 8)
    order_axis(axes[1], "layer separation h (mm)", "mean cos(θ_i − θ_j)", "order parameters", 8)
    ax = axes[2]
    if series is None:
        ax.text(0.5, 0.5, "no time series stored\n(observables.series = false)", ha="center", va="center")
    else:
        time, force, members_h, members_columns, members_rows = series
        columns, rows = sizes[-1]
        sel = (curve["columns"] == columns) & (curve["rows"] == rows)
        h, friction = curve["separation"][sel], curve["friction"][sel]
        peak = h[np.nanargmax(friction)] if np.isfinite(friction).any() else h[0]
        of_size = np.flatnonzero((members_columns == columns) & (members_rows == rows))
        for target, colour in ((h.min(), "tab:blue"), (peak, "tab:red"), (h.max(), "tab:green")):
            member = of_size[int(np.argmin(np.abs(members_h[of_size] - target)))]
            ax.plot(time, force[member], lw=0.8, color=colour, label=f"h = {members_h[member]:.1f} mm")
        ax.set_xlabel("time (s)")
        ax.set_ylabel("friction force F(t) (N)")
        ax.set_title(f"time series, {columns} × {rows} (substrate period {period:g} s)")
        legend_below(ax, 8)
    fig.tight_layout()
    fig.savefig(png_path, dpi=120, bbox_inches="tight")
    print(f"wrote {png_path}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("result")
    parser.add_argument("png")
    parser.add_argument("--rows", help="a row-model result of the same slider (rotorsweep run)")
    parser.add_argument("--velocity", action="store_true",
                        help="friction against sliding speed (a scan over drive.speed)")
    parser.add_argument("--separations", help="with --velocity: the separations to draw, mm, comma-separated")
    args = parser.parse_args()
    if args.separations and not args.velocity:
        parser.error("--separations goes with --velocity")
    if args.velocity:
        if args.rows:
            parser.error("--rows goes with the separation plot, not --velocity")
        chosen = None
        if args.separations:
            try:
                chosen = [float(h) for h in args.separations.split(",")]
            except ValueError:
                parser.error(f"--separations must be numbers in mm, comma-separated (got {args.separations!r})")
        velocity_plot(args.result, args.png, chosen)
    else:
        main(args.result, args.png, args.rows)
