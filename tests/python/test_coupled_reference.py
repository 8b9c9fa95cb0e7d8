"""Sweeps with an explicit coupling table (docs/model.md §1 "Extended couplings") against an
independent integration: the equations written out with numpy, a dense Jacobian, scipy's Radau
at rtol 1e-12; D over the averaged periods agrees to 1e-7 for members outside CP, periodic and open,
and so do the row profiles (each row's share of D, each link's alignment) carried as extra quadratures."""

import numpy as np
import pytest
import rotorsweep
from scipy.integrate import solve_ivp

A_VALUES = [0.5, 2.0]
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


def reference_profiles(theta0, A, g, open_rows):
    """D, D_j per row and the links' mean alignment over periods 3 and 4 (states: θ, then R, R_j and
    the link integrals as quadratures)."""
    n = len(theta0)
    links = n - 1 if open_rows else n
    a = TABLE["a"]
    j, k, b, c = pair_arrays(n, open_rows)

    def rhs(t, y):
        th = y[:n]
        f = -2 * a * np.sin(2 * th) + A * np.sin(th - t)
        difference, total = np.sin(th[j] - th[k]), np.sin(th[j] + th[k])
        np.add.at(f, j, b * difference - c * total)
        np.add.at(f, k, -b * difference - c * total)
        link = np.cos(th[:links] - np.roll(th, -1)[:links])
        return np.concatenate([f / g, [A * np.sin(th - t).sum()], A * np.sin(th - t), 0.5 + 0.5 * link])

    def jac(t, y):
        th = y[:n]
        J = np.zeros((2 * n + 1 + links, 2 * n + 1 + links))
        diagonal = -4 * a * np.cos(2 * th) + A * np.cos(th - t)
        difference, total = np.cos(th[j] - th[k]), np.cos(th[j] + th[k])
        np.add.at(diagonal, j, b * difference - c * total)
        np.add.at(diagonal, k, b * difference - c * total)
        J[range(n), range(n)] = diagonal / g
        np.add.at(J, (j, k), (-b * difference - c * total) / g)
        np.add.at(J, (k, j), (-b * difference - c * total) / g)
        J[n, :n] = A * np.cos(th - t)
        J[range(n + 1, 2 * n + 1), range(n)] = A * np.cos(th - t)
        sin_link = np.sin(th[:links] - np.roll(th, -1)[:links])
        rows = range(2 * n + 1, 2 * n + 1 + links)
        J[rows, range(links)] = -0.5 * sin_link
        J[rows, [(i + 1) % n for i in range(links)]] = 0.5 * sin_link
        return J

    period = 2 * np.pi
    y = np.concatenate([theta0, np.zeros(n + 1 + links)])
    first = solve_ivp(rhs, (0, 2 * period), y, method="Radau", rtol=1e-12, atol=1e-14, jac=jac)
    second = solve_ivp(rhs, (2 * period, 4 * period), first.y[:, -1], method="Radau", rtol=1e-12,
                       atol=1e-14, jac=jac)
    assert first.status == 0 and second.status == 0
    integrals = (second.y[n:, -1] - first.y[n:, -1]) / 2
    return integrals[0], integrals[1 : n + 1], integrals[n + 1 :] / period


@pytest.mark.parametrize("boundary", ["periodic", "open"])
def test_an_explicit_table_matches_an_independent_integration(boundary):
    scene = {
        "model": {"rows": 6, "coupling_table": TABLE, "boundary": boundary},
        "observables": {"row_profiles": True},
        "drive": {"g": [0.2]},
        "sweep": {"A": A_VALUES},
        "initial": {"kinds": ["AFM", "random"]},
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
