"""Sweeps with an explicit coupling table (docs/model.md §1 "Extended couplings") against an
independent integration: the equations written out with numpy, a dense Jacobian, scipy's Radau
at rtol 1e-10 (the sweep agrees with it to about 1e-12, as with rtol 1e-12); D over the averaged
periods agrees to 1e-7 for members outside CP, periodic and open, and so do the row profiles (each
row's share of D, each link's alignment) carried as extra quadratures."""

import numpy as np
import pytest
import rotorsweep
from scipy.integrate import solve_ivp

A = 2.0
RELAX, AVERAGE = 1, 2  # periods relaxed, then averaged
TABLE = {"a": 1.7, "b": [1.1, 0.3, 0.12], "c": [0.9, 0.28, 0.1]}


def pair_arrays(n, open_rows):
    """Rows j, partners k and their b, c for every coupled pair, each once; a partner N/2 away on a
    ring is reached both ways round, so it enters with half its b and c."""
    js, ks, bs, cs = [], [], [], []
    for u, (b, c) in enumerate(zip(TABLE["b"], TABLE["c"]), start=1):
        weight = 0.5 if not open_rows and 2 * u == n else 1.0
        for j in range(n):
            if open_rows and j + u >= n:
                continue
            js.append(j)
            ks.append((j + u) % n)
            bs.append(weight * b)
            cs.append(weight * c)
    return np.array(js), np.array(ks), np.array(bs), np.array(cs)


def coupling_matrices(n, open_rows):
    """B and C, symmetric: B[j, k] the b of every pair (j, k), summed where a pair is listed both ways round."""
    j, k, b, c = pair_arrays(n, open_rows)
    B, C = np.zeros((n, n)), np.zeros((n, n))
    for M, v in ((B, b), (C, c)):
        np.add.at(M, (j, k), v)
        np.add.at(M, (k, j), v)
    return B, C


def reference_profiles(theta0, A, g, open_rows):
    """D, D_j per row and the links' mean alignment over the averaged periods (states: θ, then R, R_j and
    the link integrals as quadratures). A pair (j, k) adds b sin(θ_j − θ_k) − c sin(θ_j + θ_k) to
    f_j and b sin(θ_k − θ_j) − c sin(θ_j + θ_k) to f_k."""
    n = len(theta0)
    links = n - 1 if open_rows else n
    a = TABLE["a"]
    B, C = coupling_matrices(n, open_rows)
    left, right = np.arange(links), (np.arange(links) + 1) % n  # the links' rows

    def rhs(t, y):
        th = y[:n]
        lag = np.sin(th - t)
        f = (-2 * a * np.sin(2 * th) + A * lag + (B * np.sin(th[:, None] - th)).sum(1)
             - (C * np.sin(th[:, None] + th)).sum(1))
        link = np.cos(th[left] - th[right])
        return np.concatenate([f / g, [A * lag.sum()], A * lag, 0.5 + 0.5 * link])

    def jac(t, y):
        th = y[:n]
        J = np.zeros((2 * n + 1 + links, 2 * n + 1 + links))
        difference, total = B * np.cos(th[:, None] - th), C * np.cos(th[:, None] + th)
        J[:n, :n] = (-difference - total) / g
        J[range(n), range(n)] = (-4 * a * np.cos(2 * th) + A * np.cos(th - t) + difference.sum(1)
                                 - total.sum(1)) / g
        J[n, :n] = A * np.cos(th - t)
        J[range(n + 1, 2 * n + 1), range(n)] = A * np.cos(th - t)
        sin_link = np.sin(th[left] - th[right])
        rows = range(2 * n + 1, 2 * n + 1 + links)
        J[rows, left] = -0.5 * sin_link
        J[rows, right] = 0.5 * sin_link
        return J

    period = 2 * np.pi
    y = np.concatenate([theta0, np.zeros(n + 1 + links)])
    first = solve_ivp(rhs, (0, RELAX * period), y, method="Radau", rtol=1e-10, atol=1e-12, jac=jac)
    second = solve_ivp(rhs, (RELAX * period, (RELAX + AVERAGE) * period), first.y[:, -1], method="Radau",
                       rtol=1e-10, atol=1e-12, jac=jac)
    assert first.status == 0 and second.status == 0
    integrals = (second.y[n:, -1] - first.y[n:, -1]) / AVERAGE
    return integrals[0], integrals[1 : n + 1], integrals[n + 1 :] / period


@pytest.mark.parametrize("boundary", ["periodic", "open"])
def test_an_explicit_table_matches_an_independent_integration(boundary):
    scene = {
        "model": {"rows": 6, "coupling_table": TABLE, "boundary": boundary},
        "observables": {"row_profiles": True},
        "drive": {"g": [0.2]},
        "sweep": {"A": [A]},
        "schedule": {"relax_periods": RELAX, "average_periods": AVERAGE},
        "initial": {"kinds": ["random"]},
        "numerics": {"rtol": 1e-11, "atol": 1e-14},
    }
    ds = rotorsweep.members(rotorsweep.run(scene, progress=False))
    assert (ds.status.values == "ok").all()
    for i in range(ds.sizes["member"]):
        member = ds.isel(member=i)
        assert member.regime.item() != "CP"
        dissipation, rows, links = reference_profiles(member.theta_initial.values, float(member.A), 0.2,
                                                      boundary == "open")
        assert float(member.dissipation) == pytest.approx(dissipation, rel=1e-7, abs=1e-12), i
        scale = np.abs(rows).max()
        assert member.row_dissipation.values == pytest.approx(rows, rel=1e-7, abs=1e-9 * scale), i
        measured_links = member.link_alignment.values[: len(links)]
        assert measured_links == pytest.approx(links, rel=1e-9), i
