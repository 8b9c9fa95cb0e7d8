#!/usr/bin/python3
"""Integrates benchmark members with scipy's solve_ivp (Radau, BDF, LSODA): the row model of
model.md §1 with the R-estimator quadrature q' = A Σ sin(θ_j − t) as an extra state, the paper's
protocol (D = mean dissipation over periods 3 and 4), analytic dense Jacobian. Members (A, g,
θ(0)) come from a `rotorsweep run` result file (/members/theta_initial), so both sides start from
the same draws. One member at a time, one thread; wall time per member from perf_counter.

Usage: peers.py MEMBERS.h5 OUT.csv --methods Radau,BDF --rtols 1e-4,1e-6 [--members 0,5,9]
       [--atol-ratio 1e-3] [--atol X]    (atol = rtol × ratio unless --atol is given)
       peers.py MEMBERS.h5 OUT.txt --text  (the members as lines "index A g θ…" for cvode_members)"""
import argparse
import csv
import time

import h5py
import numpy as np
from scipy.integrate import solve_ivp

PERIOD = 2 * np.pi


def model(A, g, n):
    up, down = np.roll(np.arange(n), -1), np.roll(np.arange(n), 1)

    def rhs(t, y):
        th = y[:n]
        f = np.empty(n + 1)
        f[:n] = (-3 * np.sin(2 * th) + np.sin(th - th[up]) + np.sin(th - th[down]) + A * np.sin(th - t)) / g
        f[n] = A * np.sin(th - t).sum()
        return f

    def jac(t, y):
        th = y[:n]
        J = np.zeros((n + 1, n + 1))
        c_up, c_down = np.cos(th - th[up]), np.cos(th - th[down])
        J[np.arange(n), np.arange(n)] = (-6 * np.cos(2 * th) + c_up + c_down + A * np.cos(th - t)) / g
        J[np.arange(n), up] -= c_up / g
        J[np.arange(n), down] -= c_down / g
        J[n, :n] = A * np.cos(th - t)
        return J

    return rhs, jac


def dissipation(A, g, theta0, method, rtol, atol):
    """D over periods 3-4 and the number of RHS evaluations; None if the solver fails."""
    n = len(theta0)
    rhs, jac = model(A, g, n)
    y = np.append(theta0, 0.0)
    evaluations, q_mid = 0, 0.0
    for k, (t0, t1) in enumerate(((0, 2 * PERIOD), (2 * PERIOD, 4 * PERIOD))):
        sol = solve_ivp(rhs, (t0, t1), y, method=method, rtol=rtol, atol=atol, jac=jac)
        if sol.status != 0:
            return None, evaluations
        evaluations += sol.nfev
        y = sol.y[:, -1]
        if k == 0:
            q_mid = y[n]
    return (y[n] - q_mid) / 2, evaluations


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("members")
    parser.add_argument("out")
    parser.add_argument("--methods", default="Radau")
    parser.add_argument("--rtols", default="1e-6")
    parser.add_argument("--members", dest="subset", default="")
    parser.add_argument("--atol-ratio", type=float, default=1e-3)
    parser.add_argument("--atol", type=float, default=None)
    parser.add_argument("--text", action="store_true", help="write the members as text and stop")
    args = parser.parse_args()
    with h5py.File(args.members, "r") as f:
        m = f["members"]
        A, g, theta = m["A"][:], m["g"][:], m["theta_initial"][:]
    subset = [int(i) for i in args.subset.split(",")] if args.subset else range(len(A))
    if args.text:
        with open(args.out, "w") as out:
            for i in subset:
                angles = " ".join(repr(x) for x in theta[i][~np.isnan(theta[i])])
                out.write(f"{i} {A[i]!r} {g[i]!r} {angles}\n")
        return
    with open(args.out, "w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(["method", "rtol", "atol", "member", "A", "g", "D", "seconds", "rhs_evaluations"])
        for method in args.methods.split(","):
            for rtol in (float(r) for r in args.rtols.split(",")):
                atol = args.atol if args.atol is not None else rtol * args.atol_ratio
                for i in subset:
                    start = time.perf_counter()
                    D, nfev = dissipation(A[i], g[i], theta[i][~np.isnan(theta[i])], method, rtol, atol)
                    seconds = time.perf_counter() - start
                    writer.writerow([method, rtol, atol, i, A[i], g[i], "nan" if D is None else repr(D),
                                     f"{seconds:.6g}", nfev])
                    out.flush()
                    print(f"{method} rtol {rtol:g} member {i} (A = {A[i]:g}, g = {g[i]:g}): D = {D}, "
                          f"{seconds:.3g} s", flush=True)


if __name__ == "__main__":
    main()
