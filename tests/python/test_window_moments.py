"""The moments of R, W and S over each period (observables.moments, docs/model.md §3 "The paper's
window") against an independent integration: the nearest-neighbour equations written out with numpy,
scipy's Radau at rtol 1e-10 (the sweep agrees with it as closely as with rtol 1e-12), the integrands of
R, W, S and t times them as extra quadratures; every period of a relaxing member agrees to 1e-7, and the
paper's triangular window follows from them."""

import numpy as np
import pytest
import rotorsweep
from scipy.integrate import solve_ivp

G = 0.05
PERIODS = 2


def reference_periods(theta0, A):
    """Per period k: R_k, W_k, S_k and M_k = ∫ (t - t_k) q̇ dt of each (states: θ, then the three
    integrands and t times them as quadratures)."""
    n = len(theta0)
    following, preceding = (np.arange(n) + 1) % n, (np.arange(n) - 1) % n

    def rates(t, th):
        f = (-3 * np.sin(2 * th) + np.sin(th - th[following]) + np.sin(th - th[preceding])
             + A * np.sin(th - t)) / G
        lag = np.sin(th - t)
        return f, np.array([A * lag.sum(), A * (lag * f).sum(), G * (f * f).sum()])

    def rhs(t, y):
        f, q = rates(t, y[:n])
        return np.concatenate([f, q, t * q])

    period = 2 * np.pi
    y = np.concatenate([theta0, np.zeros(6)])
    rows = []
    for k in range(PERIODS):
        t0 = k * period
        sol = solve_ivp(rhs, (t0, t0 + period), y, method="Radau", rtol=1e-10, atol=1e-12)
        assert sol.status == 0
        end = sol.y[:, -1]
        integrals = end[n:n + 3] - y[n:n + 3]
        moments = end[n + 3:] - y[n + 3:] - t0 * integrals
        rows.append(np.concatenate([integrals, moments]))
        y = end
    return np.array(rows)


def test_period_moments_match_an_independent_integration():
    scene = {
        "model": {"rows": 4},
        "drive": {"g": [G]},
        "sweep": {"A": [2.0]},
        "initial": {"kinds": ["random"]},
        "schedule": {"relax_periods": 0, "average_periods": PERIODS},
        "observables": {"moments": True, "estimators": True, "period_series": True},
        "numerics": {"rtol": 1e-11, "atol": 1e-14},
    }
    ds = rotorsweep.members(rotorsweep.run(scene, progress=False, quiet=True))
    assert (ds.status.values == "ok").all()
    columns = ["period_dissipation", "period_dissipation_work", "period_dissipation_stokes",
               "period_dissipation_moment", "period_work_moment", "period_stokes_moment"]
    for i in range(ds.sizes["member"]):
        member = ds.isel(member=i)
        reference = reference_periods(member.theta_initial.values, float(member.A))
        measured = np.array([member[c].values for c in columns]).T
        for c, column in enumerate(columns):
            scale = np.abs(reference[:, c]).max()
            assert measured[:, c] == pytest.approx(reference[:, c], rel=1e-7, abs=1e-8 * scale), (i, column)
        # the members relax: the periods differ, so the window is a real choice
        assert abs(reference[0, 0] - reference[-1, 0]) > 1e-4 * abs(reference[-1, 0])
