#!/usr/bin/python3
"""The CP friction against the size of the rows' disorder and against temperature (docs/model.md
§7): runs examples/disorder_curve.toml for σ = 0, 1e-9, 1e-6, 1e-3 and, without disorder, at
T = 1e-4, and plots D/N against A (mean over the realizations, with its standard error), then D
at A = 6 and 8 against σ from 1e-12 to 1e-2. Writes results/disorder_study.png and
results/disorder_study.csv (about a minute on 2 cores).
Usage: disorder_study.py [--rotorsweep build/bin/rotorsweep] [--out results]"""
import argparse
import pathlib
import re
import subprocess
import tempfile

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

ROOT = pathlib.Path(__file__).resolve().parent.parent
SCENE = ROOT / "examples" / "disorder_curve.toml"


def run(rotorsweep, text, path):
    """Runs one scene text; returns A, D/N per member and the replica index."""
    scene = path.with_suffix(".toml")
    scene.write_text(text)
    subprocess.run([rotorsweep, "run", str(scene), "-o", str(path), "-q"], check=True)
    with h5py.File(path, "r") as f:
        m = f["members"]
        return m["A"][:], m["dissipation"][:] / m["rows"][:]


def with_sigma(text, sigma, A=None):
    """The scene with disorder.A = σ (σ = 0: no disorder) and optionally another A list."""
    text = re.sub(r"^A = 1e-6$", f"A = {sigma!r}" if sigma > 0 else "A = 0.0", text, flags=re.M)
    if A is not None:
        text = re.sub(r"^A = \{[^}]*\}$", f"A = {list(A)!r}", text, flags=re.M)
    return text


def with_temperature(text, temperature):
    """The scene without disorder, at temperature T (Langevin dynamics)."""
    return with_sigma(text, 0.0) + f"\n[thermal]\ntemperature = {temperature!r}\n"


def mean_and_error(A, d):
    values = np.unique(A)
    means = np.array([d[A == a].mean() for a in values])
    errors = np.array([d[A == a].std(ddof=1) / np.sqrt((A == a).sum()) if (A == a).sum() > 1 else 0 for a in values])
    return values, means, errors


def main(rotorsweep, out):
    out.mkdir(parents=True, exist_ok=True)
    text = SCENE.read_text()
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.5))
    rows = ["kind,sigma_or_T,A,d_mean,d_standard_error"]
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        for sigma in [0.0, 1e-9, 1e-6, 1e-3]:
            A, d = run(rotorsweep, with_sigma(text, sigma), tmp / f"curve_{sigma}.h5")
            a, mean, err = mean_and_error(A, d)
            left.errorbar(a, mean, yerr=err, marker=".", ms=3, lw=1, capsize=2, label=f"σ = {sigma:g}")
            rows += [f"curve,{sigma:g},{x:g},{y:.9g},{e:.3g}" for x, y, e in zip(a, mean, err)]
        temperature = 1e-4
        A, d = run(rotorsweep, with_temperature(text, temperature), tmp / "thermal.h5")
        a, mean, err = mean_and_error(A, d)
        left.errorbar(a, mean, yerr=err, marker=".", ms=3, lw=1, capsize=2, color="k", ls="--",
                      label=f"σ = 0, T = {temperature:g}")
        rows += [f"thermal,{temperature:g},{x:g},{y:.9g},{e:.3g}" for x, y, e in zip(a, mean, err)]
        sigmas = 10.0 ** np.arange(-12, -1)
        for A_value in (6.0, 8.0):
            means, errors = [], []
            for sigma in sigmas:
                A, d = run(rotorsweep, with_sigma(text, sigma, [A_value]), tmp / f"scan_{A_value}_{sigma}.h5")
                means.append(d.mean())
                errors.append(d.std(ddof=1) / np.sqrt(len(d)))
                rows.append(f"scan,{sigma:g},{A_value:g},{means[-1]:.9g},{errors[-1]:.3g}")
            right.errorbar(sigmas, means, yerr=errors, marker="o", capsize=2, label=f"A = {A_value:g}")
    left.set_xlabel("A")
    left.set_ylabel("d = D/N per period")
    left.set_title("friction curve, N = 20, g = 1e-3: CP part against disorder σ and T")
    left.legend()
    right.set_xscale("log")
    right.set_xlabel("σ (relative spread of the rows' A_j)")
    right.set_ylabel("d = D/N per period")
    right.set_title("CP friction against σ (mean of 4 realizations ± s.e.)")
    right.legend()
    fig.tight_layout()
    fig.savefig(out / "disorder_study.png", dpi=120)
    (out / "disorder_study.csv").write_text("\n".join(rows) + "\n")
    print(f"wrote {out / 'disorder_study.png'} and {out / 'disorder_study.csv'}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rotorsweep", default=str(ROOT / "build" / "bin" / "rotorsweep"))
    parser.add_argument("--out", default=str(ROOT / "results"), type=pathlib.Path)
    args = parser.parse_args()
    main(args.rotorsweep, args.out)
