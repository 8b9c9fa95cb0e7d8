#!/usr/bin/python3
"""Plots `rotorsweep table` output: dissipation per period D against A for FM and AFM starts,
the three estimators (work W, Stokes S, drive R) beside the paper's values."""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def main(csv_path, png_path):
    data = np.genfromtxt(csv_path, delimiter=",", names=True, dtype=None, encoding="utf-8")
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for ic, shift, colour in (("FM", -0.12, "tab:red"), ("AFM", 0.12, "tab:blue")):
        rows = data[data["ic"] == ic]
        A = rows["A"] + shift
        ax.scatter(A, rows["R"], marker="o", s=40, color=colour, label=f"{ic} start: R (drive)")
        ax.scatter(A, rows["S"], marker="x", s=40, color=colour, label=f"{ic} start: S (Stokes)")
        ax.scatter(A, rows["W"], marker="+", s=60, color=colour, label=f"{ic} start: W (work)")
        ax.scatter(A, rows["paper_R"], marker="s", s=90, facecolors="none", edgecolors="k",
                   label="paper" if ic == "FM" else None)
    ax.set_yscale("log")
    ax.set_xlabel("substrate strength A")
    ax.set_ylabel("dissipated energy per period D  [ε]")
    ax.set_title("N = 20, g = 0.0011: rotorsweep vs the paper's table")
    ax.legend(fontsize=7, ncol=2, loc="lower right")
    ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(png_path, dpi=130)
    print(f"plot written to {png_path}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: plot_table.py TABLE.csv OUT.png")
    main(sys.argv[1], sys.argv[2])
