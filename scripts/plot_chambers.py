#!/usr/bin/python3
"""Draws the chamber map of the two-angle energy landscape: one colour per Morse signature
(minima/saddles/maxima on the torus), hatching for the alignment classes of the minima, and the
bifurcation and alignment curves on top.
Usage: plot_chambers.py CHAMBERS.h5 CURVES.h5 OUT.png
(CHAMBERS.h5 from `rotorsweep landscape chambers`, CURVES.h5 from `rotorsweep landscape curves`)"""
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.colors import ListedColormap
from matplotlib.patches import Patch

CURVE_STYLES = {
    "fm_tangential": ("k", "-", r"$B_{FM}^{\parallel}$ (tangential strict FM)"),
    "fm_transverse": ("tab:red", "-", r"$B_{FM}^{\perp}$ (transverse strict FM)"),
    "off_diagonal_plus": ("tab:blue", "-", r"$B_{off}^{+}$"),
    "off_diagonal_minus": ("tab:purple", "-", r"$B_{off}^{-}$"),
    "alignment": ("w", "--", r"$L_{1/2}$ (alignment, $\rho = 1/2$)"),
}
# (dataset, hatch, label): alignment classes of the minima present in a cell
MINIMUM_HATCHES = [("minima_afm_like", "////", "AFM-like minimum"),
                   ("minima_fm_like", "....", "FM-like minimum")]


def read_complete(path):
    f = h5py.File(path, "r")
    if not f.attrs.get("complete", False):
        sys.exit(f"error: {path} is incomplete")
    return f


def main(chambers_path, curves_path, png_path):
    with read_complete(chambers_path) as f:
        A, tau = f["A"][:], f["tau"][:]
        signature = np.stack([f["minima"][:], f["saddles"][:], f["maxima"][:]], axis=-1)
        hatch_masks = [(f[name][:] > 0, hatch, label) for name, hatch, label in MINIMUM_HATCHES]
        zone = f["zone"][:]
        zones, chambers = int(f.attrs["zones"]), int(f.attrs["chambers"])
        A_minus, A_star = f.attrs["A_minus"], f.attrs["A_star"]
    keys, index = np.unique(signature.reshape(-1, 3), axis=0, return_inverse=True)
    index = index.reshape(signature.shape[:2])
    palette = plt.get_cmap("Set3").colors + plt.get_cmap("Pastel1").colors

    fig, ax = plt.subplots(figsize=(9, 5.5))
    extent = [A[0] - 0.5 * (A[1] - A[0]), A[-1] + 0.5 * (A[1] - A[0]), 0, np.pi / 2]
    ax.imshow(index.T, origin="lower", aspect="auto", extent=extent, interpolation="nearest",
              cmap=ListedColormap(palette[:len(keys)]), vmin=-0.5, vmax=len(keys) - 0.5)
    A_grid, tau_grid = np.meshgrid(A, tau, indexing="ij")
    for mask, hatch, _ in hatch_masks:
        ax.contourf(A_grid, tau_grid, mask.astype(float), levels=[0.5, 1.5], colors="none", hatches=[hatch])
    with read_complete(curves_path) as f:
        for name, (colour, style, label) in CURVE_STYLES.items():
            g = f[name]
            ax.plot(g["A"][:], g["tau"][:], style, color=colour, lw=1.2, label=label)
    # label the largest component of every signature with its counts
    for k, key in enumerate(keys):
        labels, sizes = np.unique(zone[index == k], return_counts=True)
        biggest = labels[np.argmax(sizes)]
        i, j = np.nonzero(zone == biggest)
        ax.text(A[int(np.median(i))], tau[int(np.median(j))], "{}/{}/{}".format(*key), fontsize=8,
                ha="center", va="center", bbox=dict(fc="w", alpha=0.7, lw=0, pad=1))
    for value, name in ((A_minus, r"$A_-$"), (A_star, r"$A_*$")):
        ax.axvline(value, color="0.3", lw=0.6, ls=":")
        ax.text(value + 0.05, 0.03, name, ha="left", va="bottom", fontsize=9)
    ax.set_xlim(extent[0], extent[1])
    ax.set_ylim(0, np.pi / 2)
    ax.set_xlabel("substrate strength A")
    ax.set_ylabel(r"drive phase $\tau = \tilde v t$ (folded into $[0, \pi/2]$)")
    ax.set_title(f"chamber map of $H_r$: {zones} zones of constant Morse signature and {chambers} chambers\n"
                 "labels: minima/saddles/maxima on the torus; unhatched: strict-FM minima only", fontsize=9)
    handles, _ = ax.get_legend_handles_labels()
    handles += [Patch(facecolor="w", edgecolor="k", hatch=h, label=l) for _, h, l in hatch_masks]
    ax.legend(handles=handles, fontsize=7, loc="upper right", framealpha=0.9)
    fig.tight_layout()
    fig.savefig(png_path, dpi=130)
    print(f"wrote {png_path}")


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
