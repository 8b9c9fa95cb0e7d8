#!/usr/bin/python3
"""Summarises the stress study (scripts/stress/run_stress.sh): statuses and where the steps go
in the stress scene, steps per period as g → 0, and D against the tolerance, with the spread
over noise draws beside the spread over tolerances in the CP regime.
Usage: summarize_stress.py RESULTS_DIR"""
import sys
from pathlib import Path

import h5py
import numpy as np


def members(path):
    with h5py.File(path, "r") as f:
        if not f.attrs.get("complete", False):
            sys.exit(f"error: {path} is incomplete")
        m = f["members"]
        data = {k: m[k][:] for k in m if k != "periods" and m[k].ndim == 1}
        for k in ("ic", "regime", "status"):
            if k in data:
                data[k] = m[k].asstr()[:]
        data["wall"] = f.attrs["wall_seconds"]
    data["attempts"] = (data["steps_accepted"] + data["steps_rejected"]) / np.maximum(data["periods_run"], 1)
    return data


def stress(path):
    m = members(path)
    print(f"## {path.name}: {len(m['A'])} members in {m['wall']:.1f} s")
    statuses, counts = np.unique(m["status"], return_counts=True)
    print("statuses:", ", ".join(f"{s} {c}" for s, c in zip(statuses, counts)))
    ok = m["status"] == "ok"
    print(f"non-finite observables among ok members: {int((~np.isfinite(m['dissipation'][ok])).sum())}")
    print("\nstep attempts per period (median / max) by rtol and g:")
    for rtol in np.unique(m["rtol"]):
        cells = []
        for g in np.unique(m["g"]):
            s = (m["rtol"] == rtol) & (m["g"] == g)
            cells.append(f"g {g:.0e}: {np.median(m['attempts'][s]):.0f} / {m['attempts'][s].max():.0f}")
        print(f"  rtol {rtol:.0e}: " + "; ".join(cells))
    print("\nthe most expensive members:")
    for i in np.argsort(-m["attempts"])[:6]:
        print(f"  N {m['rows'][i]:4d} rtol {m['rtol'][i]:.0e} A {m['A'][i]:6g} g {m['g'][i]:.1e} {m['ic'][i]:6s} "
              f"{m['attempts'][i]:8.0f} attempts/period ({m['steps_rejected'][i] / m['periods_run'][i]:.0f} rejected), "
              f"regime {m['regime'][i]}")


def g_to_zero(path):
    m = members(path)
    print(f"\n## {path.name}: step attempts per period and D/N as g → 0 (N = 20, AFM start)")
    gs = np.unique(m["g"])
    print("  rtol   A  " + "".join(f"{g:>18.0e}" for g in gs))
    for rtol in np.unique(m["rtol"]):
        for A in np.unique(m["A"]):
            s = (m["rtol"] == rtol) & (m["A"] == A)
            order = np.argsort(m["g"][s])
            cells = [f"{a:6.0f} {d / 20:9.3g} {r[:3]:>3}" for a, d, r in
                     zip(m["attempts"][s][order], m["dissipation"][s][order], m["regime"][s][order])]
            print(f"  {rtol:.0e} {A:3g} " + " ".join(cells))


def tolerance(path):
    m = members(path)
    print(f"\n## {path.name}: D against rtol (N = 20, g = 0.0011, 8 noise draws per A)")
    tightest = m["rtol"].min()
    for A in np.unique(m["A"]):
        s = m["A"] == A
        regimes = ", ".join(sorted(set(m["regime"][s])))
        reference = {r: d for r, d, t in zip(m["replica"][s], m["dissipation"][s], m["rtol"][s]) if t == tightest}
        rows = []
        for rtol in sorted(np.unique(m["rtol"]), reverse=True):
            t = s & (m["rtol"] == rtol)
            D = m["dissipation"][t]
            deviation = np.max([abs(d / reference[r] - 1) for r, d in zip(m["replica"][t], D)])
            rows.append(f"rtol {rtol:.0e}: mean D {D.mean():.7g}, draw spread {D.std() / D.mean():.1e}, "
                        f"max |D/D(rtol {tightest:.0e}) - 1| {deviation:.1e}")
        by_replica = [m["dissipation"][s & (m["replica"] == r)] for r in np.unique(m["replica"][s])]
        tolerance_spread = np.mean([d.std() / d.mean() for d in by_replica])
        draw_spread = np.mean([m["dissipation"][s & (m["rtol"] == t)].std() / m["dissipation"][s & (m["rtol"] == t)].mean()
                               for t in np.unique(m["rtol"])])
        print(f"  A = {A:g} ({regimes}): spread over draws {draw_spread:.1e}, over tolerances {tolerance_spread:.1e}")
        for row in rows:
            print("    " + row)


def main(results):
    results = Path(results)
    stress(results / "stress.h5")
    g_to_zero(results / "stress_g_to_zero.h5")
    tolerance(results / "stress_tolerance.h5")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
