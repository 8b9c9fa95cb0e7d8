#!/usr/bin/python3
"""Robustness to the initial condition: D/N against A for each initial noise η (mean over the
replicas ± its standard error), one panel per initial kind (random and exact starts have no η: one
curve), a line per N, g and rtol where the file has several (never one line through them), with the FM→CP and CP→AFM transitions (where the CP fraction crosses 1/2) marked per η: between grid points by linear interpolation, or
with --bisect located by bisection in A, running the file's own scene (its replicas, schedule and
numerics) at one A at a time until the bracket is narrower than --tolerance.
Usage: plot_robustness.py RESULT.h5 OUT.png [--bisect] [--tolerance 1e-3]"""
import argparse
import sys
import tomllib
from pathlib import Path

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


def cp_fraction(scene, A, kind, eta, theta0, size, g, rtol):
    """The CP fraction of the scene's replicas at one A, one initial kind, noise η and offset θ0, one N, g
    and rtol."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "build" / "python"))
    import rotorsweep

    one = {section: dict(values) for section, values in scene.items()}
    one["sweep"]["A"] = [float(A)]
    one["initial"]["kinds"] = [kind]
    one["initial"]["noise"] = [float(eta)]
    one["initial"]["offset"] = [float(theta0)]
    one.setdefault("model", {})["rows"] = [int(size)]
    one.setdefault("drive", {})["g"] = [float(g)]
    one.setdefault("numerics", {})["rtol"] = [float(rtol)]
    one.pop("output", None)
    ds = rotorsweep.run(one, progress=False, quiet=True)
    regime = ds["regime"].values.astype(str)
    return float(np.mean(regime == "CP"))


def bisect(scene, low, high, f_low, curve, tolerance):
    """The A in [low, high] where the CP fraction of `curve` (kind, η, θ0, N, g, rtol) crosses 1/2 (f_low: its
    value at low), to tolerance; returns the bracket."""
    while high - low > tolerance:
        mid = 0.5 * (low + high)
        f_mid = cp_fraction(scene, mid, *curve)
        if (f_mid - 0.5) * (f_low - 0.5) > 0:
            low, f_low = mid, f_mid
        else:
            high = mid
    return low, high


def main(h5_path, png_path, bisection=False, tolerance=1e-3):
    with h5py.File(h5_path, "r") as f:
        if not f.attrs.get("complete", False):
            sys.exit(f"error: {h5_path} is incomplete (the run did not finish)")
        scene = tomllib.loads(f.attrs["scene"])
        c = f["curves"]
        A, noise, offset, rows = c["A"][:], c["noise"][:], c["offset"][:], c["rows"][:]
        g, rtol = c["g"][:], c["rtol"][:]
        ic = c["ic"].asstr()[:]
        d, sem = c["dissipation_mean"][:] / rows, c["dissipation_sem"][:] / rows
        cp = c["fraction_CP"][:] if "fraction_CP" in c else None
    kinds = sorted(set(ic))
    fig, axes = plt.subplots(1, len(kinds), figsize=(6.5 * len(kinds), 4.5), squeeze=False)
    lines = []
    for ax, kind in zip(axes[0], kinds):
        uses_noise = kind in ("FM", "AFM")  # random and exact starts have no η or θ0 (one curve)
        # a line per curve (η, θ0, N, g, rtol): never one through points of different sizes or tolerances
        starts = sorted({(e, o, n, gv, r) for e, o, n, gv, r, k in zip(noise, offset, rows, g, rtol, ic) if k == kind})
        several_offsets = len({o for _, o, *_ in starts}) > 1
        several = {i: len({start[i] for start in starts}) > 1 for i in (2, 3, 4)}
        for eta, theta0, size, g_value, tolerance_value in starts:
            sel = (ic == kind) & (noise == eta) & (offset == theta0) & (rows == size) & (g == g_value) & \
                (rtol == tolerance_value)
            order = np.argsort(A[sel])
            a = A[sel][order]
            parts = [f"η = {eta:g}"] + ([f"θ0 = {theta0:g}"] if several_offsets else []) if uses_noise else []
            parts += [text for i, text in ((2, f"N = {size}"), (3, f"g = {g_value:g}"), (4, f"rtol = {tolerance_value:g}"))
                      if several[i]]
            name = ", ".join(parts)
            line = ax.errorbar(a, d[sel][order], yerr=np.nan_to_num(sem[sel][order]), marker=".", ms=3, lw=1,
                               capsize=2, label=name or f"{kind} starts")
            what = f"{kind} {name}".strip()
            if cp is not None:
                fraction = cp[sel][order]
                for x in crossings(a, fraction):
                    if bisection:
                        i = int(np.searchsorted(a, x)) - 1
                        low, high = bisect(scene, a[i], a[i + 1], fraction[i],
                                           (kind, eta, theta0, size, g_value, tolerance_value), tolerance)
                        x = 0.5 * (low + high)
                        lines.append(f"{what}: CP fraction crosses 1/2 at A = {x:.4f} "
                                     f"(bisected to [{low:.4f}, {high:.4f}])")
                    else:
                        lines.append(f"{what}: CP fraction crosses 1/2 at A = {x:.3f} "
                                     f"(between grid points {a[int(np.searchsorted(a, x)) - 1]:g} and "
                                     f"{a[int(np.searchsorted(a, x))]:g}; --bisect locates it)")
                    ax.axvline(x, color=line[0].get_color(), ls=":", lw=1)
        ax.set_xlabel("A")
        ax.set_ylabel("d = D/N per period")
        ax.set_title(f"{kind} starts: friction against A" + (" for each noise η" if uses_noise else ""))
        ax.legend()
    fig.tight_layout()
    fig.savefig(png_path, dpi=120)
    print("\n".join(lines))
    print(f"wrote {png_path}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("result")
    parser.add_argument("png")
    parser.add_argument("--bisect", action="store_true", help="locate each transition by bisection in A")
    parser.add_argument("--tolerance", type=float, default=1e-3, help="width of the final A bracket")
    args = parser.parse_args()
    main(args.result, args.png, args.bisect, args.tolerance)
