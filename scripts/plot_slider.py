#!/usr/bin/python3
"""The slider scan of `rotorsweep slider` (docs/model.md §9): friction force against the layer separation h
(the experiment's curve), the order parameters against h, and the friction's time series at three
separations (the closest, the friction peak, the farthest).
Usage: plot_slider.py RESULT.h5 OUT.png"""
import argparse
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def main(h5_path, png_path):
    with h5py.File(h5_path, "r") as f:
        if f.attrs.get("kind", b"") not in ("slider", b"slider"):
            sys.exit(f"error: {h5_path} is not a slider result (rotorsweep slider writes those)")
        c = f["curve"]
        h = c["separation"][:] * 1e3
        friction, spread = c["friction"][:], c["friction_std"][:]
        order_x, order_y = c["order_x"][:], c["order_y"][:]
        series = None
        if "series" in f:
            s = f["series"]
            time = s["time"][:]
            members_h = f["members/separation"][:] * 1e3
            series = (time, s["friction"][:], members_h)
        period = f.attrs["period"]
    fig, axes = plt.subplots(1, 3, figsize=(17, 4.6))
    ax = axes[0]
    ax.plot(h, friction, "o-", ms=3, color="tab:red")
    if np.isfinite(spread).any():
        ax.fill_between(h, friction - spread, friction + spread, color="tab:red", alpha=0.25, label="± replica std")
        ax.legend()
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
    args = parser.parse_args()
    main(args.result, args.png)
