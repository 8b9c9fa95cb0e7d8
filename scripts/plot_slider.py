#!/usr/bin/python3
"""The slider scan of `rotorsweep slider` (docs/model.md §9): friction force against the layer separation h
(the experiment's curve), the order parameters against h, and the friction's time series at three
separations (the closest, the friction peak, the farthest). With --rows, the friction the row model
predicts for the same slider (a `rotorsweep run` result whose rows have as many rotors as the slider's
columns), its A mapped to h both ways of docs/model.md §9: the paper's (a/h)³ m_sub/m and the substrate
field's first harmonic.
Usage: plot_slider.py RESULT.h5 OUT.png [--rows ROWS.h5]"""
import argparse
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def row_model_curves(rows_path, h, A_paper, A_field, force_per_row_unit, slider_rows):
    """The row model's mean friction against h for both mappings of A, as the slider's total force."""
    with h5py.File(rows_path, "r") as f:
        if not f.attrs.get("complete", False):
            sys.exit(f"error: {rows_path} is incomplete (the run did not finish)")
        c = f["curves"]
        A, D, N = c["A"][:], c["dissipation_mean"][:], c["rows"][:]
    order = np.argsort(A)
    A, force = A[order], (D / N)[order] * force_per_row_unit * slider_rows
    curves = []
    for label, A_of_h in (("A = (a/h)³ m_sub/m", A_paper), ("A from the field's first harmonic", A_field)):
        inside = (h >= h.min()) & (A_of_h >= A.min()) & (A_of_h <= A.max())
        curves.append((label, h[inside], np.interp(A_of_h[inside], A, force)))
    return curves


def main(h5_path, png_path, rows_path=None):
    with h5py.File(h5_path, "r") as f:
        if f.attrs.get("kind", b"") not in ("slider", b"slider"):
            sys.exit(f"error: {h5_path} is not a slider result (rotorsweep slider writes those)")
        c = f["curve"]
        h = c["separation"][:] * 1e3
        friction, spread = c["friction"][:], c["friction_std"][:]
        order_x, order_y = c["order_x"][:], c["order_y"][:]
        A_paper, A_field = c["A_paper"][:], c["A_field"][:]
        # a row of `columns` rotors has the energy unit columns · μ0 m²/(4π a³); F = D ε / a
        force_per_row_unit = f.attrs["columns"] * f.attrs["energy_unit"] / f.attrs["spacing"]
        slider_rows = int(f.attrs["rows"])
        series = None
        if "series" in f:
            s = f["series"]
            time = s["time"][:]
            members_h = f["members/separation"][:] * 1e3
            series = (time, s["friction"][:], members_h)
        period = f.attrs["period"]
    fig, axes = plt.subplots(1, 3, figsize=(17, 4.6))
    ax = axes[0]
    ax.plot(h, friction, "o-", ms=3, color="tab:red", label="slider")
    if np.isfinite(spread).any():
        ax.fill_between(h, friction - spread, friction + spread, color="tab:red", alpha=0.25, label="± replica std")
    if rows_path:
        for (label, hh, force), style in zip(row_model_curves(rows_path, h, A_paper, A_field, force_per_row_unit,
                                                              slider_rows), ("--", ":")):
            ax.plot(hh, force, style, color="black", label="row model, " + label)
    ax.legend(fontsize=8)
    ax.set_xlabel("layer separation h (mm)")
    ax.set_ylabel("mean friction force (N)")
    ax.set_title("friction against separation")
    ax = axes[1]
    ax.plot(h, order_x, "o-", ms=3, label="x-neighbours (sliding direction)")
    ax.plot(h, order_y, "s-", ms=3, label="y-neighbours")
    ax.axhline(0, color="gray", lw=0.5)
    ax.set_ylim(-1.05, 1.05)
    ax.set_xlabel("layer separation h (mm)")
    ax.set_ylabel("mean cos(θ_i − θ_j)")
    ax.set_title("order parameters (+1 FM, −1 AFM)")
    ax.legend()
    ax = axes[2]
    if series is None:
        ax.text(0.5, 0.5, "no time series stored\n(observables.series = false)", ha="center", va="center")
    else:
        time, force, members_h = series
        peak = h[np.nanargmax(friction)]
        for target, colour in ((h.min(), "tab:blue"), (peak, "tab:red"), (h.max(), "tab:green")):
            member = int(np.argmin(np.abs(members_h - target)))
            ax.plot(time, force[member], lw=0.8, color=colour, label=f"h = {members_h[member]:.1f} mm")
        ax.set_xlabel("time (s)")
        ax.set_ylabel("friction force F(t) (N)")
        ax.set_title(f"time series (substrate period {period:g} s)")
        ax.legend()
    fig.tight_layout()
    fig.savefig(png_path, dpi=120)
    print(f"wrote {png_path}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("result")
    parser.add_argument("png")
    parser.add_argument("--rows", help="a row-model result of the same slider (rotorsweep run)")
    args = parser.parse_args()
    main(args.result, args.png, args.rows)
