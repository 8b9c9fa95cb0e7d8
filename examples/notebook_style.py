#!/usr/bin/python3
"""The paper's table and a friction curve from Python (PYTHONPATH=build/python; docs/python.md "Python")."""
import matplotlib.pyplot as plt
import numpy as np
import rotorsweep

t = rotorsweep.paper_table
scene = {"model": {"rows": t["rows"]}, "drive": {"g": [t["g"]]}, "initial": {"kinds": ["FM", "AFM"], "replicas": 1},
         "schedule": {"relax_periods": t["relax_periods"], "average_periods": t["average_periods"]},
         "numerics": {"rtol": 1e-8, "atol": 1e-11}, "sweep": {"A": sorted(set(t["A"]))}}
table = rotorsweep.run(scene, progress=False)
for A, ic, R, cp in zip(t["A"], t["ic"], t["R"], t["cp"]):
    D = table.dissipation.sel(A=A, ic=ic, replica=0).item()
    print(f"A = {A:4.1f} {ic:3}  D = {D:.6e}  paper {R:.6e}{'  (CP: depends on the draw)' if cp else ''}")
scene.update(sweep={"A": {"from": 0.25, "to": 14.0, "count": 56}}, initial={"kinds": ["AFM"], "replicas": 4})
curve = rotorsweep.run(scene).dissipation.mean("replica") / t["rows"]
A = np.linspace(rotorsweep.A_minus, rotorsweep.A_star, 500)
plt.semilogy(curve.A, curve, "o-", ms=3, label="D/N, mean of 4 AFM starts")
plt.semilogy(A, rotorsweep.jump_friction(A), label="quasi-static J(A)")
plt.xlabel("A"), plt.ylabel("D/N  [ε]"), plt.legend(), plt.savefig("notebook_style.png", dpi=120)
