#!/usr/bin/python3
"""Combines the reference runs into scripts/bench/reference.csv: D from rotorsweep's rodas4 at
rtol 1e-12 (the reference) next to scipy Radau at rtol 1e-12, atol 1e-14, with their relative
difference, the member's start kind and regime.
Usage: reference_table.py OURS.h5 RADAU.csv OUT.csv"""
import csv
import sys

import h5py
import numpy as np


def main(ours_path, radau_path, out_path):
    with h5py.File(ours_path, "r") as f:
        m = f["members"]
        A, g, D = m["A"][:], m["g"][:], m["dissipation"][:]
        ic, regime = m["ic"].asstr()[:], m["regime"].asstr()[:]
        revision = f.attrs["revision"]
    with open(radau_path) as f:
        radau = {int(r["member"]): float(r["D"]) for r in csv.DictReader(f)}
    with open(out_path, "w", newline="") as out:
        out.write("# Benchmark reference: scripts/bench/reference.toml (N = 20, relax 2 + average 2 periods,\n"
                  "# seed 1) run by `rotorsweep run` with rodas4, rtol 1e-12, atol 1e-15 (column D, revision "
                  f"{revision}),\n# and by scipy solve_ivp Radau, rtol 1e-12, atol 1e-14 (column D_radau) via "
                  "scripts/bench/peers.py;\n# regenerate with scripts/bench/make_reference.sh.\n")
        writer = csv.writer(out)
        writer.writerow(["member", "A", "g", "ic", "regime", "D", "D_radau", "relative_difference"])
        for i in range(len(A)):
            r = radau.get(i, np.nan)
            writer.writerow([i, A[i], g[i], ic[i], regime[i], repr(D[i]), repr(r), f"{abs(r / D[i] - 1):.3g}"])
    print(f"wrote {out_path}")


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
