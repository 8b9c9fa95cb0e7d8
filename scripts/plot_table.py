#!/usr/bin/python3
"""Plots `rotorsweep table` output: dissipation per period D against A for FM and AFM starts, the three
estimators (work W, Stokes S, drive R) beside the paper's values, R's error bars where R_error bounds R
(resolved or unresolved) and hollow R markers where it does not (symmetry-limited, shadow departed); the
title carries the table's provenance (stepper, rtol, window, disorder, program) from its "# " lines."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

#: R_error kinds whose error bounds R
BOUNDS = ("resolved", "unresolved")


def read_table(csv_path):
    """The table's provenance lines (without "# ") and its rows as dicts of columns."""
    with open(csv_path, newline="") as f:
        lines = f.read().splitlines()
    provenance = [line[2:] for line in lines if line.startswith("# ")]
    rows = list(csv.DictReader(line for line in lines if not line.startswith("#")))
    return provenance, rows


def title(provenance):
    """The plot's title: what the table is, then how it was made (stepper, tolerances, window; disorder)."""
    how = [line for line in provenance if line.startswith(("stepper", "disorder", "written by"))]
    return "N = 20, g = 0.0011: rotorsweep vs the paper's table\n" + "\n".join(how)


def figure(csv_path):
    provenance, rows = read_table(csv_path)
    fig, ax = plt.subplots(figsize=(8, 5.5))
    for ic, shift, colour in (("FM", -0.12, "tab:red"), ("AFM", 0.12, "tab:blue")):
        mine = [r for r in rows if r["ic"] == ic]
        A = np.array([float(r["A"]) for r in mine]) + shift
        R, S, W, paper = (np.array([float(r[name]) for r in mine]) for name in ("R", "S", "W", "paper_R"))
        error = np.array([float(r["R_error"]) for r in mine])
        bound = np.array([r["R_error_kind"] in BOUNDS for r in mine])
        ax.errorbar(A[bound], R[bound], yerr=error[bound], fmt="none", ecolor=colour, elinewidth=0.8, capsize=2)
        ax.scatter(A[bound], R[bound], marker="o", s=40, color=colour, label=f"{ic} start: R (drive), error a bound")
        if (~bound).any():
            ax.scatter(A[~bound], R[~bound], marker="o", s=40, facecolors="none", edgecolors=colour,
                       label=f"{ic} start: R, error no bound (" +
                             ", ".join(sorted({r["R_error_kind"] for r, b in zip(mine, bound) if not b})) + ")")
        ax.scatter(A, S, marker="x", s=40, color=colour, label=f"{ic} start: S (Stokes)")
        ax.scatter(A, W, marker="+", s=60, color=colour, label=f"{ic} start: W (work)")
        ax.scatter(A, paper, marker="s", s=90, facecolors="none", edgecolors="k",
                   label="paper" if ic == "FM" else None)
    ax.set_yscale("log")
    ax.set_xlabel("substrate strength A")
    ax.set_ylabel("dissipated energy per period D  [ε]")
    ax.set_title(title(provenance), fontsize=8)
    ax.legend(fontsize=7, ncol=2, loc="lower right")
    ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    return fig


def main(csv_path, png_path):
    figure(csv_path).savefig(png_path, dpi=130)
    print(f"plot written to {png_path}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: plot_table.py TABLE.csv OUT.png")
    main(sys.argv[1], sys.argv[2])
