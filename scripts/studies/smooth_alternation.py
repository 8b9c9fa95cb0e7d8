#!/usr/bin/python3
"""The smooth-alternation window A_* < A ≲ 10 (docs/studies.md, "The smooth-alternation window"): is it CP, with energy
jumps whose friction D/N stays finite as g → 0, or a smooth alternation whose friction vanishes with g?

Sweeps the two-row ring (N = 2, the two-angle reduction exactly, docs/model.md §5) from an AFM start at A = 6 … 10.5 and
g = 1e-8 … 1e-2 with quenched disorder σ_A = 0 (rounding), 1e-12 … 1e-3 and at temperatures T = 1e-8, 1e-5 (g ≥ 1e-4);
fits D/N against g and ln σ; then follows single members with scipy's Radau and classifies each slip by the critical
point it starts at (its own energy's Hessian) and by how its dissipated energy scales with g. Prints the tables of
docs/studies.md and draws the figure (about 3 minutes on 2 cores; --quick: coarser grids, one replica, about 8 s).
Usage: smooth_alternation.py [--quick] [--out docs/figures/smooth_alternation.png] [--python build/python]
                             [--threads 2]"""
import concurrent.futures
import itertools
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import study_command_line
from scipy.integrate import solve_ivp


CP_SIDE = [6.0, 8.0, 8.5]                       # A_− < A < A_* = 8.778: J(A) > 0
WINDOW = [9.0, 9.25, 9.5, 9.75]                 # A_* < A < 10: the strict-FM minimum still turns into a saddle
FM_SIDE = [10.0, 10.5]                          # beyond the transverse strict-FM curve's end at A = 10
SIGMAS = [0.0, 1e-12, 1e-9, 1e-6, 1e-3]         # σ_A; 0: only rounding breaks the rows' symmetry
LOG_SIGMAS = [1e-12, 1e-9, 1e-6]                # where D/(N g) is fitted against log10(1/σ)
TEMPERATURES = [1e-8, 1e-5]
THERMAL_A = [6.0, 8.0, 9.0, 9.5, 10.0]
SCHEDULE = {"relax_periods": 2, "average_periods": 2}
TOLERANCE = {"rtol": 1e-12, "atol": 1e-15}      # below σ = 1e-9: D is converged (same to 4 digits at rtol 1e-10)
SLIP_A = [8.0, 9.0, 9.5]                        # members followed slip by slip
SLIP_SIGMAS = [1e-6, 1e-3]
FAST = 10.0                                     # the sweeper's slip_rate: a slip starts where max_j |dθ_j/dt| > FAST
CALM = 2.0                                      # ... and its energy is summed while the speed stays above CALM
NEAR = 0.1                                      # rad: a critical point this close to the slip's start is the one left
MATCH = 0.003                                   # periods: slips at different g starting this close are the same slip

FULL = {"g_exponents": np.arange(-8.0, -1.99, 0.5), "replicas": 8, "shadow": True, "thermal_g": [1e-2, 1e-3, 1e-4],
        "slip_g": [1e-4, 1e-5, 1e-6], "slip_A": SLIP_A, "slip_sigmas": SLIP_SIGMAS, "slip_rtol": 1e-10,
        "slip_periods": SCHEDULE["average_periods"]}
# the quick run: one replica; no shadow runs (they bound D's error, which no table prints, and leave D the same bit for
# bit); its members followed at rtol 1e-7 (their slips' start phases, ρ and classes are those at 1e-10, their energies
# the same to 3 digits, in a third of the time) and only over the first averaged half period, which the energy table
# reads
QUICK = {"g_exponents": np.arange(-6.0, -1.99, 1.0), "replicas": 1, "shadow": False, "thermal_g": [1e-2],
         "slip_g": [1e-4, 1e-5], "slip_A": [8.0, 9.0], "slip_sigmas": [1e-6], "slip_rtol": 1e-7, "slip_periods": 0.5}


def progress(text):
    print(text, file=sys.stderr, flush=True)


# ---------------------------------------------------------------- sweeps


def scene(A, g, replicas, sigma=0.0, temperature=0.0, shadow=True):
    """N = 2 from an AFM start; disorder of the substrate strength σ, or a temperature (fixed Langevin steps); at σ > 0
    shadow runs unless `shadow` is false."""
    table = {"model": {"rows": 2}, "drive": {"g": list(g)}, "sweep": {"A": list(A)},
             "initial": {"kinds": ["AFM"], "replicas": replicas}, "schedule": SCHEDULE}
    if temperature > 0:
        table["thermal"] = {"temperature": temperature}
    else:
        table["numerics"] = dict(TOLERANCE)
        if sigma > 0:
            table["disorder"] = {"A": sigma}
        # σ = 0 is symmetry-limited: its shadow run (docs/regimes.md "Errors in CP, and symmetry-limited
        # members") would cost a minute and bound nothing
        if sigma == 0 or not shadow:
            table["numerics"]["global_error"] = "local"
    return table


def friction(rotorsweep, table, threads):
    """D/N per (A, g) averaged over replicas, slips per period, and replica 0's drawn deviations of A_j."""
    ds = rotorsweep.run(table, threads=threads, progress=False, quiet=True).squeeze(drop=True)
    ds = ds.expand_dims([axis for axis in ("A", "g", "replica") if axis not in ds.dims])  # also of one value
    d = (ds.dissipation / 2).transpose("A", "g", "replica")
    slips = ds.slips_per_period.transpose("A", "g", "replica").mean("replica")
    drawn = ds.get("disorder_A")
    return {"A": ds.A.values, "g": ds.g.values, "mean": d.mean("replica").values, "slips": slips.values,
            "deviations": None if drawn is None else drawn.isel(A=0, g=0, replica=0).values}


def deterministic_sweeps(rotorsweep, config, threads):
    A = CP_SIDE + WINDOW + FM_SIDE
    g = 10.0 ** config["g_exponents"]
    results = {}
    for sigma in SIGMAS:
        progress(f"sweep σ = {sigma:g}: {len(A)} A × {len(g)} g × {config['replicas']} replicas")
        results[sigma] = friction(rotorsweep, scene(A, g, config["replicas"], sigma=sigma, shadow=config["shadow"]),
                                   threads)
    return results


def thermal_sweeps(rotorsweep, config, threads):
    results = {}
    for T in TEMPERATURES:
        progress(f"sweep T = {T:g}: {len(THERMAL_A)} A × {len(config['thermal_g'])} g × 2 replicas")
        results[T] = friction(rotorsweep, scene(THERMAL_A, config["thermal_g"], 2, temperature=T), threads)
    return results


# ---------------------------------------------------------------- fits


def local_power(g, d, lo, hi):
    """The exponent p of D/N ∝ g^p from a least-squares line in log-log over lo ≤ g ≤ hi."""
    keep = (g >= lo * 0.999) & (g <= hi * 1.001) & (d > 0)
    return float(np.polyfit(np.log10(g[keep]), np.log10(d[keep]), 1)[0])


def sigma_law(results, A_index, g_index):
    """D/(N g) at one g against log10(1/σ) over LOG_SIGMAS: intercept a, slope b (per decade of σ) of the least-squares
    line D/(N g) = a + b log10(1/σ), and its largest relative residual."""
    x = -np.log10(LOG_SIGMAS)
    y = np.array([results[s]["mean"][A_index, g_index] / results[s]["g"][g_index] for s in LOG_SIGMAS])
    b, a = np.polyfit(x, y, 1)
    return float(a), float(b), float(np.max(np.abs(a + b * x - y) / y))


# ---------------------------------------------------------------- single members, slip by slip


def torque(theta, t, Aj):
    """−∂H/∂θ_j of the two-row ring (each row's neighbour on both sides is the other row); θ may hold a column per
    time of an array t."""
    rows = (slice(None),) + (None,) * (np.ndim(theta) - 1)
    d = theta[0] - theta[1]
    return -3 * np.sin(2 * theta) + 2 * np.sin(d) * np.array([1.0, -1.0])[rows] + Aj[rows] * np.sin(theta - t)


def hessian(theta, t, Aj):
    d = theta[0] - theta[1]
    h = np.diag(6 * np.cos(2 * theta) - 2 * np.cos(d) - Aj * np.cos(theta - t))
    h[0, 1] = h[1, 0] = 2 * np.cos(d)
    return h


def nearest_critical_point(theta, t, Aj):
    """Newton's method on ∇H at the frozen drive phase t from θ: (its smallest Hessian eigenvalue, type), or None when
    it does not converge within NEAR of θ (the minimum the member sat in has vanished)."""
    x = theta.copy()
    for _ in range(60):
        step = np.linalg.solve(hessian(x, t, Aj), torque(x, t, Aj))
        x = x + step
        if np.max(np.abs(step)) < 1e-12:
            break
    else:
        return None
    if np.max(np.abs(np.angle(np.exp(1j * (x - theta))))) > NEAR:
        return None
    eigenvalues = np.linalg.eigvalsh(hessian(x, t, Aj))
    kind = "minimum" if eigenvalues[0] > 0 else "saddle" if eigenvalues[1] > 0 else "maximum"
    return float(eigenvalues[0]), kind


def follow(A, g, Aj, periods, rtol):
    """One member from the sweeper's AFM start without noise (rows 0 and π), Radau at `rtol`."""
    def rhs(t, y):
        return torque(y, t, Aj) / g

    def jacobian(t, y):
        return -hessian(y, t, Aj) / g

    return solve_ivp(rhs, (0.0, 2 * np.pi * periods), np.array([0.0, np.pi]), method="Radau", jac=jacobian,
                     rtol=rtol, atol=rtol * 1e-2, dense_output=True)


def slips_of(A, g, Aj, rtol, averaged):
    """Every slip of the first `averaged` averaged periods: drive phase at its start (in periods), the critical point
    the member sits at there, and the energy the slip dissipates, g ∫ |dθ/dt|² while the speed exceeds CALM."""
    solution = follow(A, g, Aj, SCHEDULE["relax_periods"] + averaged, rtol)

    def speeds_at(times):
        return np.max(np.abs(torque(solution.sol(times), times, Aj)), axis=0) / g

    steps = solution.t
    speeds = speeds_at(steps)
    events = []
    for k in np.flatnonzero((speeds[1:] > FAST) & (speeds[:-1] <= FAST)) + 1:
        if steps[k] < 2 * np.pi * SCHEDULE["relax_periods"]:
            continue
        fine = np.linspace(steps[k - 1], steps[k], 201)
        start = fine[np.argmax(speeds_at(fine) > FAST)]
        # the slip runs between the solver's last calm step before it and its first calm step after it
        calm = speeds <= CALM
        lo = k - 1 - np.argmax(calm[k - 1::-1]) if calm[:k].any() else 0
        hi = k + np.argmax(calm[k:]) if calm[k:].any() else len(steps) - 1
        span = np.union1d(np.linspace(steps[lo], steps[hi], 20001), steps[lo:hi + 1])
        velocity = torque(solution.sol(span), span, Aj) / g
        energy = g * np.trapz(np.sum(velocity ** 2, axis=0), span)
        theta = solution.sol(start)
        events.append({"phase": start / (2 * np.pi), "point": nearest_critical_point(theta, start, Aj),
                       "energy": float(energy), "episode": (lo, hi),
                       "rho": float(np.cos((theta[0] - theta[1]) / 2) ** 2)})
    return events


def slip_table(config, deviations, threads):
    """Slips of one member per (A, σ, g): the disorder realization of replica 0 of the sweeps; `threads` members
    followed at once, each in a process of its own (scipy's Radau holds the interpreter)."""
    keys = list(itertools.product(config["slip_A"], config["slip_sigmas"], config["slip_g"]))
    progress(f"slips of {len(keys)} members on {threads} processes")
    with concurrent.futures.ProcessPoolExecutor(threads) as pool:
        members = [pool.submit(slips_of, A, g, A * (1 + deviations[sigma]), config["slip_rtol"],
                               config["slip_periods"]) for A, sigma, g in keys]
        return {key: member.result() for key, member in zip(keys, members)}


# ---------------------------------------------------------------- output


def print_friction(results, label):
    g = results["g"]
    print(f"\nD/N, {label} (mean over replicas; slips per period in brackets)")
    print("A      " + " ".join(f"{x:>16.0e}" for x in g))
    for i, A in enumerate(results["A"]):
        cells = [f"{results['mean'][i, j]:.3e} [{results['slips'][i, j]:.1f}]" for j in range(len(g))]
        print(f"{A:<6g} " + " ".join(f"{c:>16}" for c in cells))


def print_laws(deterministic, J):
    """The exponent of D/N in g per A and σ; inside the window the σ law of D/(N g) at g = 1e-6; outside it D/N at the
    smallest g against the quasi-static J(A)."""
    g = deterministic[1e-6]["g"]
    smallest = (g.min(), g.min() * 10.001)
    print("\nexponent p of D/N ∝ g^p, least squares over g = 1e-6 … 1e-4 (and over the two smallest g for σ = 1e-3)")
    print("A      " + " ".join(f"{f'σ={s:g}':>9}" for s in SIGMAS) + "  σ=1e-3,small-g")
    for i, A in enumerate(deterministic[1e-6]["A"]):
        p = [local_power(g, deterministic[s]["mean"][i], 1e-6, 1e-4) for s in SIGMAS]
        print(f"{A:<6g} " + " ".join(f"{x:>9.3f}" for x in p)
              + f"  {local_power(g, deterministic[1e-3]['mean'][i], *smallest):>14.3f}")
    A_values = deterministic[1e-6]["A"]
    j6 = int(np.argmin(np.abs(g - 1e-6)))
    print("\nwindow: D/(N g) at g = 1e-6 = a + b log10(1/σ), fitted over σ = 1e-12, 1e-9, 1e-6;"
          " σ = 0 and 1e-3 beside it")
    print("A      a        b/decade  residual  σ=0      σ=1e-3")
    for i, A in enumerate(A_values):
        if A in WINDOW:
            a, b, residual = sigma_law(deterministic, i, j6)
            level = [deterministic[s]["mean"][i, j6] / g[j6] for s in (0.0, 1e-3)]
            print(f"{A:<6g} {a:<8.1f} {b:<9.2f} {residual:<9.3f} {level[0]:<8.1f} {level[1]:.1f}")
    print(f"\nCP side: D/N at g = {g.min():.0e} against J(A) (σ = 1e-6, 1e-3)")
    print("A      J(A)        D/N σ=1e-6  ratio    D/N σ=1e-3  ratio")
    for i, A in enumerate(A_values):
        if A in CP_SIDE:
            d = [deterministic[s]["mean"][i, 0] for s in (1e-6, 1e-3)]
            print(f"{A:<6g} {J[i]:<11.5e} {d[0]:<11.5e} {d[0] / J[i]:<8.4f} {d[1]:<11.5e} {d[1] / J[i]:.4f}")


def print_slips(slips):
    print("\nslips of one member (replica 0), averaged periods: start phase (periods), the critical point left "
          "(λ_min of its Hessian), ρ at the start, energy dissipated")
    print("A      σ       g        phase   point              ρ        energy")
    for (A, sigma, g), events in slips.items():
        for e in events:
            if e["phase"] >= SCHEDULE["relax_periods"] + 1:  # period 4 repeats period 3
                break
            point = "vanished" if e["point"] is None else f"{e['point'][1]} {e['point'][0]:+.3f}"
            print(f"{A:<6g} {sigma:<7.0e} {g:<8.0e} {e['phase']:.4f}  {point:<18} {e['rho']:.4f}   {e['energy']:.3e}")


def first_half_period(events):
    """The slips of the first averaged half period (the second half repeats them by the symmetry t → t + π)."""
    start = SCHEDULE["relax_periods"]
    return [e for e in events if start <= e["phase"] < start + 0.5]


def matched(events, phase):
    """The slip of `events` that starts within MATCH periods of `phase`, or None."""
    near = [e for e in events if abs(e["phase"] - phase) < MATCH]
    return near[0] if near else None


def slip_energy_scaling(slips, config):
    """Per (A, σ), every slip of the first averaged half period at the smallest g (slips with no calm solver step
    between them as one, with their number), matched by its start phase to the slips at the larger g: its energy
    against g. A slip is a jump when its energy keeps its size as g falls tenfold
    (ratio > 1/2), smooth when it falls with g."""
    g = config["slip_g"]
    rows = []
    for A in config["slip_A"]:
        for sigma in config["slip_sigmas"]:
            episodes = {}  # slips that follow one another without a calm step between them share their energy
            for e in first_half_period(slips[(A, sigma, g[-1])]):
                episodes.setdefault(e["episode"], []).append(e)
            for group in episodes.values():
                e = group[0]
                partners = [matched(first_half_period(slips[(A, sigma, x)]), e["phase"]) for x in g]
                energies = [np.nan if p is None else p["energy"] for p in partners]
                point = "vanished" if e["point"] is None else f"{e['point'][1]} {e['point'][0]:+.3f}"
                ratio = energies[-1] / energies[-2]
                kind = "—" if np.isnan(ratio) else "jump" if ratio > 0.5 else "smooth"
                rows.append({"A": A, "sigma": sigma, "phase": e["phase"], "slips": len(group), "point": point,
                             "rho": e["rho"],
                             "energies": energies, "ratio": ratio, "class": kind})
    print("\nslip energy against g (first averaged half period, slips matched by start phase): a jump keeps its size as g"
          " falls tenfold, a smooth slip's energy falls with g")
    print("A      σ       phase   slips  starts at (λ_min)  ρ        " + " ".join(f"g={x:<9.0e}" for x in g)
          + "  last ratio  class")
    for r in rows:
        print(f"{r['A']:<6g} {r['sigma']:<7.0e} {r['phase']:.4f}  {r['slips']:<5d}  {r['point']:<18} {r['rho']:.4f}   "
              + " ".join(f"{x:<11.3e}" for x in r["energies"]) + f"  {r['ratio']:<10.3f}  {r['class']}")
    return rows


def figure(deterministic, thermal, J, rows, config, out):
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.3))
    colors = {0.0: "k", 1e-12: "tab:cyan", 1e-9: "tab:blue", 1e-6: "tab:green", 1e-3: "tab:red"}
    ax = axes[0]
    for i, A in enumerate(deterministic[1e-6]["A"]):
        if A not in (6.0, 8.0, 9.0, 9.5):
            continue
        style = "-" if A in WINDOW else "--"
        for sigma in SIGMAS:
            r = deterministic[sigma]
            ax.loglog(r["g"], r["mean"][i], style, color=colors[sigma], lw=1,
                      label=f"σ={sigma:g}" if A == 9.0 else None)
        if J[i] > 0:
            ax.axhline(J[i], color="grey", lw=0.6, ls=":")
            ax.text(1.2e-8, J[i] * 1.15, f"J({A:g})", fontsize=7, color="grey")
        ax.text(2e-2, deterministic[1e-6]["mean"][i, -1], f"A={A:g}", fontsize=7, va="center")
    for T, marker in zip(TEMPERATURES, "os"):
        r = thermal[T]
        for i, A in enumerate(r["A"]):
            if A in (9.0, 9.5):
                ax.loglog(r["g"], r["mean"][i], marker, color="tab:purple", ms=4, mfc="none",
                          label=f"T={T:g}" if A == 9.0 else None)
    ax.set_xlabel("g")
    ax.set_ylabel("D/N")
    ax.set_title("D/N against g (solid: window A = 9, 9.5; dashed: CP side)", fontsize=8)
    ax.legend(fontsize=7, loc="lower right")

    ax = axes[1]
    g = deterministic[1e-6]["g"]
    for i, A in enumerate(deterministic[1e-6]["A"]):
        if A not in WINDOW:
            continue
        for sigma in SIGMAS:
            r = deterministic[sigma]
            ax.semilogx(g, r["mean"][i] / g, color=colors[sigma], lw=1, marker=".",
                        label=f"σ={sigma:g}" if A == WINDOW[0] else None)
        ax.text(g[0], deterministic[1e-9]["mean"][i, 0] / g[0], f"A={A:g}", fontsize=7, ha="right")
    ax.set_yscale("log")
    ax.set_xlabel("g")
    ax.set_ylabel("D/(N g)")
    ax.set_title("inside the window: D/(N g) levels off (σ ≤ 1e-6)", fontsize=8)
    ax.legend(fontsize=7)

    ax = axes[2]
    for r in rows:
        marker = {"saddle": "o", "minimum": "^"}.get(r["point"].split()[0], "x")
        label = f"A={r['A']:g}, σ={r['sigma']:g}, {r['point'].split()[0]}"
        ax.loglog(config["slip_g"], r["energies"], marker + "-", color=colors[r["sigma"]], ms=4, lw=0.8,
                  alpha=1.0 if r["A"] in WINDOW else 0.45, label=label)
    ax.set_xlabel("g")
    ax.set_ylabel("energy dissipated by one slip")
    ax.set_title("per slip: finite (jump) or ∝ g (smooth)", fontsize=8)
    ax.legend(fontsize=6)
    study_command_line.save(fig, out, 80)


def main():
    args, rotorsweep = study_command_line.parse(__doc__, "smooth_alternation.png",
                                                "coarser grids, one replica (about 8 s)")

    config = QUICK if args.quick else FULL
    deterministic = deterministic_sweeps(rotorsweep, config, args.threads)
    thermal = thermal_sweeps(rotorsweep, config, args.threads)
    J = rotorsweep.landscape.quasi_static_friction(deterministic[1e-6]["A"])[0]

    print(f"A_* = {rotorsweep.landscape.A_star:.4f}; N = 2, AFM start, {SCHEDULE['relax_periods']} + "
          f"{SCHEDULE['average_periods']} periods")
    for sigma in SIGMAS:
        print_friction(deterministic[sigma], f"σ_A = {sigma:g}" if sigma else "no disorder (rounding)")
    for T in TEMPERATURES:
        print_friction(thermal[T], f"T = {T:g}")
    print_laws(deterministic, J)

    deviations = {s: deterministic[s]["deviations"] for s in config["slip_sigmas"]}
    slips = slip_table(config, deviations, args.threads)
    print_slips(slips)
    rows = slip_energy_scaling(slips, config)

    figure(deterministic, thermal, J, rows, config, args.out)


if __name__ == "__main__":
    main()
