#!/usr/bin/python3
"""Does the row reduction hold? (docs/studies.md, "The row reduction against the full array"): the experiment's slider,
every rotor with its own angle, every pair a point dipole, over a finite substrate (docs/model.md §9), against the row
model of the same geometry (docs/model.md §1, §8) as the array grows.

Square sliders of 4 … 64 rotors a side, overdamped (the row model's dynamics) at the experiment's speed and damping,
over substrates five times their extent (from 14 × 14 on matrix-free: FFT pair sums, conjugate gradients, box-sum
substrate tables), beside the row model of the same geometry: N open rows of N rotors, point dipoles between every
pair of rows, A(h) from the substrate field's first harmonic (the slider file's A_field; the paper's estimate A_paper
beside it) and the slider's g. Friction per rotor against the separation h and its gap per size and regime; how
uniform the rows stay and which rotors slip; the regimes in h against the row model's and the landscape's windows;
the large-N limit f_∞(h) fitted over the largest sizes with its residuals; the array over an infinite substrate
(no edges) beside the 5N × 5N one; the array at a slow speed against the quasi-static J(A); the 8 × 8 slider over
substrates 2 … 8 times its extent; the experiment's 7 × 7 array, overdamped and inertial, against the large-N limit.
Prints the tables of docs/studies.md and draws the figure (about 45 minutes on 2 cores; --quick: sizes 4 and 6 at
four separations, about 10 s).
Usage: row_reduction.py [--quick] [--out docs/figures/row_reduction.png] [--python build/python] [--threads 2]"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import study_command_line
from dipolar_cp_window import Mapping

SPEED = 8e-3                   # m/s: the experiment's (g = 0.154)
SLOW_SPEED = 0.25e-3           # m/s: 32 times slower (g = 0.0048), towards the quasi-static limit
REST = 0.5                     # s at rest before sliding, as the experiment
PERIODS = 5                    # substrate periods slid, as the experiment's 10 s
AVERAGED_FROM = 1              # friction, spreads, slips and order from period 2 on (the first is transient)
SAMPLES = 50                   # samples per period (the slider's default)
JUMP = 1.0                     # rad between two samples (8 times the drive's 2π/50): a rotor slips
SUBSTRATE_SCALE = 5            # the experiment's 35 × 35 magnets under 7 × 7 rotors
EXPERIMENT_SIZE = 7
ROW_SCHEDULE = {"relax_periods": AVERAGED_FROM, "average_periods": PERIODS - AVERAGED_FROM}
NOISE = np.pi / 24             # the slider's start: rows alternately near 0 and π, uniform noise of this full width
REGIMES = ("FM", "CP", "AFM")
PROFILE_H = (5.0, 6.0, 7.0, 8.0, 9.0, 10.0, 11.0, 12.0, 13.0)

# h in mm; "coarse": sizes run at every other h; "infinite_sizes": over an infinite substrate as well (at every other
# h); "slow_coarse": slow sizes at every other h of slow_h
FULL = {"sizes": (4, 6, 8, 12, 16, 24, 32, 48, 64), "h": np.linspace(5.0, 13.0, 33), "coarse": (24, 32, 48, 64),
        "infinite_sizes": (8, 16, 32, 64), "slow_sizes": (8, 16, 32), "slow_coarse": (32,),
        "slow_h": np.linspace(6.0, 11.0, 21), "substrate_size": 8, "substrate_scales": (2, 3, 5, 8)}
QUICK = {"sizes": (4, 6), "h": np.array([7.0, 8.5, 10.0, 11.5]), "coarse": (), "infinite_sizes": (4,),
         "slow_sizes": (4,), "slow_coarse": (), "slow_h": np.array([8.0, 9.5]), "substrate_size": 4,
         "substrate_scales": (2, 5)}


def progress(text):
    print(text, file=sys.stderr, flush=True)


# ---------------------------------------------------------------- the array and the row model


def run_array(rotorsweep, size, h_mm, threads, speed=SPEED, scale=SUBSTRATE_SCALE, dynamics="overdamped", seed=1,
              infinite=False):
    """One square slider over separations h_mm: friction per rotor f = F a/(N² ε_pair) per separation (averaged over
    periods 2 …), A_paper, A_field, g, and from period 2 on the order across y, every angle and the mean substrate
    field at the rotors. With `infinite` over an infinite substrate (no edges) instead of scale × the slider."""
    substrate = {"extent": "infinite"} if infinite else {"columns": scale * size, "rows": scale * size}
    scene = {"slider": {"columns": size, "rows": size, "dynamics": dynamics},
             "substrate": substrate,
             "drive": {"speed": speed, "rest": REST, "periods": PERIODS},
             "sweep": {"separation": [float(h) * 1e-3 for h in h_mm]},
             "initial": {"kind": "alternating_rows", "noise": NOISE, "seed": seed},
             "observables": {"samples_per_period": SAMPLES, "angles": True, "field": True},
             "numerics": {"global_error": "local"}}  # no quoted number needs friction's error
    ds = rotorsweep.slider(scene, threads=threads, progress=False).isel(size=0, replica=0)
    assert (ds.status.values == "ok").all(), ds.status.values
    force_unit = ds.attrs["energy_unit"] / ds.attrs["spacing"]   # ε_pair / a, N
    sliding = ds.time.values >= REST + AVERAGED_FROM * ds.attrs["spacing"] / speed - 1e-9
    return {"size": size, "h": ds.separation.values * 1e3,
            "f": ds.period_friction.values[:, AVERAGED_FROM:].mean(axis=1) / size ** 2 / force_unit,
            "A_paper": ds.curve_A_paper.values, "A_field": ds.curve_A_field.values,
            "g": float(ds.curve_g.values[0]), "order_y": ds.series_order_y.values[:, sliding],
            "angles": ds.series_angles.values[:, sliding, :],
            "field": (ds.series_field_axis.values[:, sliding], ds.series_field_z.values[:, sliding])}


def run_rows(rotorsweep, size, A, g, threads):
    """The row model of an N × N slider: N open rows of N rotors, point dipoles between every pair of rows, AFM starts
    (the slider's alternating rows) at each A: D/N (energy per row and period in ε = N ε_pair, so per rotor in
    ε_pair: the friction per rotor in ε_pair/a) and the regime label, in the order of A given."""
    scene = {"model": {"rows": size, "couplings": "dipolar", "range": "all", "row_length": size,
                       "boundary": "open"},
             "drive": {"g": [g]}, "sweep": {"A": [float(a) for a in A]},
             "initial": {"kinds": ["AFM"], "noise": NOISE / 2}, "schedule": ROW_SCHEDULE,
             "numerics": {"global_error": "local"}}  # D and the regime only: no shadows or probes
    m = rotorsweep.members(rotorsweep.run(scene, threads=threads, progress=False, quiet=True))
    at = {float(a): k for k, a in enumerate(m.A.values)}
    order = [at[float(a)] for a in A]
    return {"f": m.dissipation.values[order] / size, "regime": m.regime.values.astype(str)[order]}


def landscape(rotorsweep, size, A):
    """A_−, A_* and the quasi-static J at the given A of the two-angle reduction of a ring of N rows of N rotors with
    every row coupled (docs/model.md §8): the periodic counterpart of the same geometry."""
    k = rotorsweep.two_angle_coefficients("all", row_length=size, rows=size)
    J, _ = rotorsweep.quasi_static_friction(A, k)
    return {"window": rotorsweep.landscape.cp_interval(k), "J": np.asarray(J)}


def mapping(array):
    """h (mm) of a row model's A under both mappings of the array's scan."""
    return Mapping({"h_mm": array["h"], "A_paper": array["A_paper"], "A_field": array["A_field"]})


# ---------------------------------------------------------------- analysis


def row_deviations(angles, size):
    """Each rotor's angle less its row's circular mean, wrapped to (−π, π]: (..., row, column) from (..., rotor) with
    rotor = row · columns + column."""
    theta = angles.reshape(*angles.shape[:-1], size, size)
    mean = np.angle(np.exp(1j * theta).mean(axis=-1, keepdims=True))
    return np.angle(np.exp(1j * (theta - mean)))


def uniformity(angles, size):
    """The spread (max − min of the deviations from the row's mean) of each row: its mean and maximum over the
    samples (separation, row), and each rotor's mean |deviation| (separation, row, column)."""
    deviation = row_deviations(angles, size)
    spread = deviation.max(axis=-1) - deviation.min(axis=-1)          # (separation, sample, row)
    return {"mean": spread.mean(axis=1), "max": spread.max(axis=1), "rotor": np.abs(deviation).mean(axis=1)}


def slips(angles, size):
    """Slips per period of each rotor (separation, period, row, column): steps between consecutive samples in which it
    turns by more than JUMP."""
    step = np.abs(np.angle(np.exp(1j * np.diff(angles, axis=1))))
    fast = step[:, : (step.shape[1] // SAMPLES) * SAMPLES] > JUMP
    return fast.reshape(fast.shape[0], -1, SAMPLES, size, size).sum(axis=2)


def harmonics(series, count=3):
    """|c_k| of the first `count` harmonics of the substrate period of each row of series (separation, sample) over
    its whole periods."""
    periods = (series.shape[1] - 1) // SAMPLES
    spectrum = np.abs(np.fft.rfft(series[:, : periods * SAMPLES], axis=1))
    return spectrum[:, periods * np.arange(1, count + 1)]


def edge_and_bulk(values, axis=-1):
    """(mean over the two outermost entries, mean over the others) along an axis."""
    values = np.moveaxis(values, axis, -1)
    return values[..., [0, -1]].mean(axis=-1), values[..., 1:-1].mean(axis=-1)


def array_regimes(array):
    """The sweeper's rule on the array (docs/model.md §3): CP where some rotor slips in every averaged period, FM or
    AFM where none slips and the order across y keeps its sign (rows parallel or antiparallel), else unsettled."""
    per_period = slips(array["angles"], array["size"]).sum(axis=(2, 3))
    order = array["order_y"]
    calm = per_period.sum(axis=1) == 0
    return np.where((per_period > 0).all(axis=1), "CP",
                    np.where(calm & (order.min(axis=1) > 0), "FM",
                             np.where(calm & (order.max(axis=1) < 0), "AFM", "unsettled")))


def switching(array):
    """Where the rows switch: the order across y swings by at least 2/(N − 1) (one of the N − 1 row pairs turning
    between parallel and antiparallel; the rule of docs/studies.md "The CP window with dipolar couplings")."""
    order = array["order_y"]
    return order.max(axis=1) - order.min(axis=1) >= 2 / (array["size"] - 1)


def window(h, inside):
    """(lowest, highest) h where `inside`, or None."""
    return (float(h[inside].min()), float(h[inside].max())) if inside.any() else None


def gaps(h, f_array, f_rows, where=None):
    """The array against the row model over h (or the h where `where`): relative L1 gap ∫|f_a − f_r| dh / ∫f_r dh,
    the ratio of the integrals and of the peaks, and both peaks' positions."""
    if where is not None:
        h, f_array, f_rows = h[where], f_array[where], f_rows[where]
    integral = np.trapz(f_rows, h)
    return {"l1": float(np.trapz(np.abs(f_array - f_rows), h) / integral),
            "area": float(np.trapz(f_array, h) / integral),
            "peak": float(f_array.max() / f_rows.max()),
            "h_array": float(h[np.argmax(f_array)]), "h_rows": float(h[np.argmax(f_rows)])}


def regime_gaps(array, f_rows):
    """The relative L1 gap over the separations of each of the array's regimes (NaN for a regime with fewer than two)."""
    regime = array_regimes(array)
    return {label: gaps(array["h"], array["f"], f_rows, regime == label)["l1"] if (regime == label).sum() > 1
            else np.nan for label in REGIMES}


def power_law(N, gap):
    """gap ≈ c N^(−p) by least squares in log–log: (c, p)."""
    slope, intercept = np.polyfit(np.log(N), np.log(gap), 1)
    return float(np.exp(intercept)), float(-slope)


def in_inverse_size(N, values):
    """values ≈ v_∞ + c/N by least squares per column of values (sizes along axis 0): (v_∞, c)."""
    design = np.column_stack([np.ones(len(N)), 1.0 / np.asarray(N, dtype=float)])
    (limit, slope), *_ = np.linalg.lstsq(design, np.asarray(values, dtype=float), rcond=None)
    return limit, slope


def at(array_h, values, h):
    """values (over array_h) at the separations h, which the array ran."""
    index = [int(np.argmin(np.abs(array_h - x))) for x in h]
    assert np.allclose(array_h[index], h), (array_h, h)
    return values[index]


def large_size_limit(arrays, curves, count=3):
    """(sizes, h, f_∞(h), residuals) of curves {N: f over arrays[N]["h"]} from f = f_∞ + c/N over the `count` largest
    sizes, on the separations they all ran; residuals (size, h): each size's f less the fit."""
    sizes = sorted(curves)[-count:]
    h = min((arrays[n]["h"] for n in sizes), key=len)
    values = np.array([at(arrays[n]["h"], curves[n], h) for n in sizes])
    limit, slope = in_inverse_size(sizes, values)
    residuals = values - (limit + slope / np.array(sizes, dtype=float)[:, None])
    return sizes, h, limit, residuals


# ---------------------------------------------------------------- tables


def nearest(h, points):
    """The indices of the grid values nearest to the points, each once, in order."""
    return sorted({int(np.argmin(np.abs(h - x))) for x in points})


def fmt_window(w):
    return "none" if w is None else f"{w[0]:.2f}-{w[1]:.2f}"


def fits(sizes, values, name):
    """The two laws of a gap against N, as a line."""
    c, p = power_law(sizes, values)
    limit, slope = in_inverse_size(sizes, values)
    return f"{name}: {c:.3f} N^-{p:.3f}; {limit:.4f} + {slope:.3f}/N"


def friction_table(arrays, rows, rows_paper):
    print("\nfriction per rotor f = F a/(N^2 eps_pair) (periods 2-5) against the row model of the same geometry "
          "(N open rows of N rotors, all rows coupled, the slider's g), with A = A_field(h) and A = A_paper(h); "
          "h in mm; L1: relative L1 gap over 5-13 mm")
    print(f"{'size':>5} {'g':>6} {'peak':>6} {'at h':>5} | {'field: peak':>11} {'at h':>5} {'ratio':>6} {'area':>6} "
          f"{'L1':>6} | {'paper: peak':>11} {'at h':>5} {'ratio':>6} {'area':>6} {'L1':>6}")
    for size, array in arrays.items():
        line = f"{size:5d} {array['g']:6.4f} {array['f'].max():6.3f} {array['h'][np.argmax(array['f'])]:5.2f}"
        for model in (rows[size], rows_paper[size]):
            r = gaps(array["h"], array["f"], model["f"])
            line += f" | {model['f'].max():11.3f} {r['h_rows']:5.2f} {r['peak']:6.3f} {r['area']:6.3f} {r['l1']:6.3f}"
        print(line)
    sizes = np.array(list(arrays))
    l1 = np.array([gaps(a["h"], a["f"], rows[n]["f"])["l1"] for n, a in arrays.items()])
    print("fit of the L1 gap (A_field) against N: " + fits(sizes, l1, "L1"))


def regime_gap_table(arrays, rows):
    print("\nrelative L1 gap (A_field) over the separations of each of the array's regimes, and its fits against N")
    table = {size: regime_gaps(array, rows[size]["f"]) for size, array in arrays.items()}
    print(f"{'size':>5} " + " ".join(f"{label:>7}" for label in REGIMES))
    for size, row in table.items():
        print(f"{size:5d} " + " ".join(f"{row[label]:7.3f}" for label in REGIMES))
    sizes = np.array(list(table))
    for label in REGIMES:
        values = np.array([table[n][label] for n in sizes])
        if np.isfinite(values).all():
            print(f"fit {label:3}: " + fits(sizes, values, "gap"))


def profile_table(arrays, rows):
    print("\nthe array's friction per rotor over the row model's (A_field) at chosen h (mm), and its limit "
          "r_inf + c/N over the three largest sizes")
    h = np.array([x for x in PROFILE_H if all(np.isclose(a["h"], x).any() for a in arrays.values())])
    ratios = {size: at(array["h"], array["f"] / rows[size]["f"], h) for size, array in arrays.items()}
    print(f"{'size':>5} " + " ".join(f"{x:>7.2f}" for x in h))
    for size, ratio in ratios.items():
        print(f"{size:5d} " + " ".join(f"{r:7.3f}" for r in ratio))
    sizes = sorted(ratios)[-3:]
    limit, _ = in_inverse_size(sizes, np.array([ratios[n] for n in sizes]))
    print(f"{'inf':>5} " + " ".join(f"{r:7.3f}" for r in limit))


def limit_table(arrays, rows):
    """The large-N limits of the array's and of the row model's friction per rotor, their gap, and how well
    f = f_∞ + c/N holds: the fit's residuals over its three sizes, and the limit from four sizes against it."""
    sizes, h, limit, residuals = large_size_limit(arrays, {n: a["f"] for n, a in arrays.items()})
    _, _, limit_rows, residuals_rows = large_size_limit(arrays, {n: r["f"] for n, r in rows.items()})
    r = gaps(h, limit, limit_rows)
    print(f"\nlarge-N limits (f = f_inf + c/N over N = {', '.join(map(str, sizes))}): array peak {limit.max():.3f} at "
          f"h = {h[np.argmax(limit)]:.2f} mm, row model (A_field) peak {limit_rows.max():.3f} at {r['h_rows']:.2f} mm; "
          f"L1 gap {r['l1']:.3f}, area ratio {r['area']:.3f}")
    scale = limit.max()
    print(f"residuals of the array's fit over its sizes, relative to f_inf's peak: rms {np.sqrt(np.mean(residuals ** 2)) / scale:.4f}, "
          f"largest {np.abs(residuals).max() / scale:.4f} (at h = {h[np.unravel_index(np.argmax(np.abs(residuals)), residuals.shape)[1]]:.2f} mm); "
          f"the row model's: rms {np.sqrt(np.mean(residuals_rows ** 2)) / limit_rows.max():.4f}")
    if len(arrays) >= 4:
        sizes4, h4, limit4, _ = large_size_limit(arrays, {n: a["f"] for n, a in arrays.items()}, count=4)
        shared = at(h, limit, h4)
        print(f"the limit from N = {', '.join(map(str, sizes4))} against it: L1 difference "
              f"{gaps(h4, limit4, shared)['l1']:.4f}, peak {limit4.max():.3f} at {h4[np.argmax(limit4)]:.2f} mm")
    print(f"{'h':>6} " + " ".join(f"{'N=' + str(n):>8}" for n in sizes) + f" {'f_inf':>8} {'rows_inf':>8}")
    for k in nearest(h, PROFILE_H):
        values = [at(arrays[n]["h"], arrays[n]["f"], h[k:k + 1])[0] for n in sizes]
        print(f"{h[k]:6.2f} " + " ".join(f"{v:8.3f}" for v in values) + f" {limit[k]:8.3f} {limit_rows[k]:8.3f}")
    return {"sizes": sizes, "h": h, "f": limit, "rows": limit_rows}


def uniformity_table(arrays):
    print("\nrow uniformity from period 2 on, per regime of the array (its separations' mean; max: their largest): "
          "spread (max - min) of theta_ij within a row over the samples, bulk and edge rows (rad); mean "
          "|theta_ij - row mean| of bulk and edge columns; slips per rotor and period in the bulk, the edge rows "
          "(without corners) and the edge columns (without corners)")
    print(f"{'size':>5} {'regime':>6} {'h':>11} {'spread bulk':>11} {'edge':>6} {'max bulk':>8} {'edge':>6} "
          f"{'|dev| bulk col':>14} {'edge':>6} {'slips bulk':>10} {'edge rows':>9} {'edge cols':>9}")
    for size, array in arrays.items():
        u, regime = uniformity(array["angles"], size), array_regimes(array)
        edge_mean, bulk_mean = edge_and_bulk(u["mean"])
        edge_max, bulk_max = edge_and_bulk(u["max"])
        edge_col, bulk_col = edge_and_bulk(u["rotor"].mean(axis=1))
        per_rotor = slips(array["angles"], size).mean(axis=1)            # (separation, row, column)
        bulk_slips = per_rotor[:, 1:-1, 1:-1].mean(axis=(1, 2))
        edge_row_slips = per_rotor[:, [0, -1], 1:-1].mean(axis=(1, 2))
        edge_col_slips = per_rotor[:, 1:-1, [0, -1]].mean(axis=(1, 2))
        for label in REGIMES:
            sel = regime == label
            if not sel.any():
                continue
            print(f"{size:5d} {label:>6} {fmt_window(window(array['h'], sel)):>11} {bulk_mean[sel].mean():11.4f} "
                  f"{edge_mean[sel].mean():6.4f} {bulk_max[sel].max():8.3f} {edge_max[sel].max():6.3f} "
                  f"{bulk_col[sel].mean():14.4f} {edge_col[sel].mean():6.4f} {bulk_slips[sel].mean():10.2f} "
                  f"{edge_row_slips[sel].mean():9.2f} {edge_col_slips[sel].mean():9.2f}")


def onset_table(arrays):
    print("\nwhere the array slips first and last: at the smallest and largest h labelled CP, the share of rotors that "
          "slip (bulk, edge rows, edge columns, corners) and the rows with a slipping rotor")
    print(f"{'size':>5} {'end':>5} {'h':>5} {'bulk':>5} {'edge rows':>9} {'edge cols':>9} {'corners':>7}  rows")
    for size, array in arrays.items():
        regime = array_regimes(array)
        cp = np.flatnonzero(regime == "CP")
        if not cp.size:
            continue
        slipping = slips(array["angles"], size).sum(axis=1) > 0                 # (separation, row, column)
        for name, k in (("first", cp[0]), ("last", cp[-1])):
            s = slipping[k]
            rows_slipping = ",".join(str(j) for j in np.flatnonzero(s.any(axis=1)))
            print(f"{size:5d} {name:>5} {array['h'][k]:5.2f} {s[1:-1, 1:-1].mean():5.2f} {s[[0, -1], 1:-1].mean():9.2f} "
                  f"{s[1:-1, [0, -1]].mean():9.2f} {s[np.ix_([0, -1], [0, -1])].mean():7.2f}  {rows_slipping}")


def regime_table(arrays, rows, rows_paper, landscapes):
    print("\nregimes in h (mm): the array's (slips: the sweeper's rule; switching: rows turn), the row model's CP "
          "(its labels) under A_field and A_paper, and the landscape's [h(A_*), h(A_-)] (ring of N rows of N rotors) "
          "under both mappings")
    print(f"{'size':>5} {'array FM':>10} {'array CP':>11} {'array AFM':>11} {'switching':>11} {'rows field':>11} "
          f"{'rows paper':>11} {'A_-':>6} {'A_*':>6} {'land. field':>11} {'land. paper':>11}")
    for size, array in arrays.items():
        regime, h = array_regimes(array), array["h"]
        A_lo, A_hi = landscapes[size]["window"]
        mapped = mapping(array).window(A_lo, A_hi)
        print(f"{size:5d} {fmt_window(window(h, regime == 'FM')):>10} {fmt_window(window(h, regime == 'CP')):>11} "
              f"{fmt_window(window(h, regime == 'AFM')):>11} {fmt_window(window(h, switching(array))):>11} "
              f"{fmt_window(window(h, rows[size]['regime'] == 'CP')):>11} "
              f"{fmt_window(window(h, rows_paper[size]['regime'] == 'CP')):>11} {A_lo:6.3f} {A_hi:6.3f} "
              f"{fmt_window(mapped['field']):>11} {fmt_window(mapped['paper']):>11}")
        labels = ", ".join(f"{k} {v}" for k, v in zip(*np.unique(rows[size]["regime"], return_counts=True)))
        print(f"      row model labels under A_field: {labels}")


def slow_table(slow, slow_rows, landscapes):
    print("\nat the slow speed: the array, the row model at the same g and the quasi-static J(A_field(h)) of the "
          "landscape (friction per rotor; array/J, rows/J: sums over the h where J > 0)")
    print(f"{'size':>5} {'g':>7} {'peak array':>10} {'at h':>5} {'peak rows':>9} {'at h':>5} {'peak J':>7} {'at h':>5} "
          f"{'array/J':>8} {'rows/J':>7}")
    for size, array in slow.items():
        J, f_rows, h = landscapes[size]["J_slow"], slow_rows[size]["f"], array["h"]
        cp = J > 0
        print(f"{size:5d} {array['g']:7.4f} {array['f'].max():10.3f} {h[np.argmax(array['f'])]:5.2f} "
              f"{f_rows.max():9.3f} {h[np.argmax(f_rows)]:5.2f} {J.max():7.3f} {h[np.argmax(J)]:5.2f} "
              f"{array['f'][cp].sum() / J[cp].sum():8.3f} {f_rows[cp].sum() / J[cp].sum():7.3f}")


def substrate_table(substrates, substrate_rows, other_start):
    scales = sorted(substrates)
    largest = substrates[scales[-1]]
    size, h = largest["size"], largest["h"]
    chosen = nearest(h, (7.0, 9.0, 11.0))
    print(f"\nthe finite substrate: {size} x {size} over substrates s times its extent (L1: relative L1 gap against the "
          f"row model of each substrate's A_field, and against the array over the largest substrate); last line: "
          f"s = {SUBSTRATE_SCALE} from another draw of the start's noise")
    print(f"{'s':>3} {'magnets':>8} " + " ".join(f"{'A_field ' + format(h[k], '.0f'):>10}" for k in chosen)
          + f" {'peak':>6} {'at h':>5} {'area/s=' + str(scales[-1]):>10} {'L1 rows':>7} {'L1 vs s=' + str(scales[-1]):>9}")
    entries = [(s, substrates[s], substrate_rows[s]) for s in scales]
    for s, a, model in entries + [(SUBSTRATE_SCALE, other_start, substrate_rows[SUBSTRATE_SCALE])]:
        print(f"{s:3d} {(s * size) ** 2:8d} " + " ".join(f"{a['A_field'][k]:10.4f}" for k in chosen)
              + f" {a['f'].max():6.3f} {h[np.argmax(a['f'])]:5.2f} {gaps(h, a['f'], largest['f'])['area']:10.3f} "
              f"{gaps(h, a['f'], model['f'])['l1']:7.3f} {gaps(h, a['f'], largest['f'])['l1']:9.3f}")
    print(f"the two draws at s = {SUBSTRATE_SCALE}: L1 difference "
          f"{gaps(h, other_start['f'], substrates[SUBSTRATE_SCALE]['f'])['l1']:.2g}")


def infinite_table(arrays, infinite, limit):
    """The array over an infinite substrate (no edges) beside the 5N × 5N one, and the large-N limit of each."""
    print("\nthe array over an infinite substrate against 5N x 5N magnets (friction per rotor; L1: relative L1 "
          "difference over the separations both ran)")
    print(f"{'size':>5} {'peak inf':>8} {'at h':>5} {'peak 5N':>8} {'at h':>5} {'area inf/5N':>11} {'L1':>6}")
    for size, array in infinite.items():
        finite = arrays[size]
        f_finite = at(finite["h"], finite["f"], array["h"])
        r = gaps(array["h"], array["f"], f_finite)
        print(f"{size:5d} {array['f'].max():8.3f} {array['h'][np.argmax(array['f'])]:5.2f} {f_finite.max():8.3f} "
              f"{array['h'][np.argmax(f_finite)]:5.2f} {r['area']:11.3f} {r['l1']:6.3f}")
    if len(infinite) >= 3:
        sizes, h, limit_infinite, residuals = large_size_limit(infinite, {n: a["f"] for n, a in infinite.items()})
        shared = at(limit["h"], limit["f"], h) if all(np.isclose(limit["h"], x).any() for x in h) else None
        line = (f"large-N limit over an infinite substrate (N = {', '.join(map(str, sizes))}): peak "
                f"{limit_infinite.max():.3f} at {h[np.argmax(limit_infinite)]:.2f} mm, fit residuals rms "
                f"{np.sqrt(np.mean(residuals ** 2)) / limit_infinite.max():.4f}")
        if shared is not None:
            line += f"; against the 5N x 5N limit: L1 {gaps(h, limit_infinite, shared)['l1']:.4f}"
        print(line)
        return {"sizes": sizes, "h": h, "f": limit_infinite}
    return None


def field_table(array):
    """How far the substrate field at the rotors is from the row model's uniformly rotating one: the first harmonics
    of its mean along the rotors' axis and along z (their ratio e: 1 for a circular rotation; (A_z/A)² = (2e/(1 + e))²
    is the factor a friction driven by the z part alone, as a rotor's wobble about the easy axis is, takes on the row
    model's with A = A_field, the mean of both) and the second and third harmonics against the first."""
    along, z = harmonics(array["field"][0]), harmonics(array["field"][1])
    first = np.hypot(along[:, 0], z[:, 0])
    print(f"\nthe substrate field at the rotors ({array['size']} x {array['size']}, mean over the rotors, from period 2 "
          f"on): B_z1/B_x1 (1: the row model's circular rotation), |B_2|/|B_1|, |B_3|/|B_1|")
    print(f"{'h':>6} {'A_field':>8} {'B_z1/B_x1':>9} {'(A_z/A)^2':>9} {'B_2/B_1':>8} {'B_3/B_1':>8}")
    for k in nearest(array["h"], PROFILE_H):
        e = z[k, 0] / along[k, 0]
        print(f"{array['h'][k]:6.2f} {array['A_field'][k]:8.3f} {e:9.3f} {(2 * e / (1 + e)) ** 2:9.3f} "
              f"{np.hypot(along[k, 1], z[k, 1]) / first[k]:8.3f} {np.hypot(along[k, 2], z[k, 2]) / first[k]:8.3f}")


def experiment_table(experiment, arrays, limit):
    print(f"\nthe experiment's {EXPERIMENT_SIZE} x {EXPERIMENT_SIZE} array against the large-N limit of the array "
          f"(L1: relative L1 difference from f_inf)")
    print(f"{'array':>24} {'peak':>6} {'at h':>5} {'peak/f_inf':>10} {'area/f_inf':>10} {'L1':>6}")
    entries = [(f"{EXPERIMENT_SIZE}x{EXPERIMENT_SIZE} {name}", a) for name, a in experiment.items()]
    entries += [(f"{n}x{n} overdamped", arrays[n]) for n in limit["sizes"]]
    for name, a in entries:
        r = gaps(limit["h"], at(a["h"], a["f"], limit["h"]), limit["f"])
        print(f"{name:>24} {a['f'].max():6.3f} {r['h_array']:5.2f} {r['peak']:10.3f} {r['area']:10.3f} {r['l1']:6.3f}")
    inertial, overdamped = experiment["inertial"]["f"], experiment["overdamped"]["f"]
    print(f"inertia: the inertial friction over the overdamped, largest relative difference "
          f"{np.max(np.abs(inertial / overdamped - 1)):.4f}")


# ---------------------------------------------------------------- figure


def size_colors(sizes):
    return {n: plt.cm.viridis(k / max(len(sizes) - 1, 1) * 0.9) for k, n in enumerate(sizes)}


def plot_friction(axis, arrays, rows, limit, colors):
    for size, array in arrays.items():
        axis.plot(array["h"], array["f"], color=colors[size], label=f"{size} × {size}")
        axis.plot(array["h"], rows[size]["f"], color=colors[size], ls="--", lw=1)
    axis.plot(limit["h"], limit["f"], color="k", ls=":", label="array, N → ∞")
    axis.plot(limit["h"], limit["rows"], color="0.5", ls=":", label="row model, N → ∞")
    axis.set_xlabel("separation h (mm)")
    axis.set_ylabel("friction per rotor (ε_pair / a)")
    axis.set_title("array (solid), row model with A_field (dashed)")
    axis.legend(fontsize="x-small")


def plot_gaps(axis, arrays, rows):
    sizes = np.array(list(arrays))
    table = [regime_gaps(array, rows[size]["f"]) for size, array in arrays.items()]
    series = [("all h", np.array([gaps(a["h"], a["f"], rows[n]["f"])["l1"] for n, a in arrays.items()]))]
    series += [(f"{label} h", np.array([row[label] for row in table])) for label in REGIMES]
    for label, values in series:
        line, = axis.loglog(sizes, values, "o-", label=label)
        if np.isfinite(values).all():
            c, p = power_law(sizes, values)
            line.set_label(f"{label}: {c:.2f} N^{-p:+.2f}")
    axis.set_xlabel("rotors per side N")
    axis.set_ylabel("relative L1 gap, array against row model")
    axis.set_title("the gap against N, per regime of the array")
    axis.legend(fontsize="x-small")


def plot_uniformity(axis, arrays, colors):
    for size, array in arrays.items():
        edge, bulk = edge_and_bulk(uniformity(array["angles"], size)["mean"])
        axis.semilogy(array["h"], bulk, color=colors[size], label=f"{size} × {size}")
        axis.semilogy(array["h"], edge, color=colors[size], ls="--", lw=1)
    axis.set_xlabel("separation h (mm)")
    axis.set_ylabel("mean spread of θ_ij within a row (rad)")
    axis.set_title("row uniformity: bulk rows (solid), edge rows (dashed)")
    axis.legend(fontsize="x-small")


def plot_slip_maps(axis, arrays):
    """Slips per period of each rotor of the largest size at its first CP separation, its friction peak and its last
    CP separation, side by side."""
    size = max(arrays)
    array = arrays[size]
    cp = np.flatnonzero(array_regimes(array) == "CP")
    chosen = [cp[0], int(np.argmax(array["f"])), cp[-1]] if cp.size else [int(np.argmax(array["f"]))]
    per_rotor = slips(array["angles"], size).mean(axis=1)
    gap = np.full((size, 2), np.nan)
    image = np.hstack(sum(([per_rotor[k], gap] for k in chosen), [])[:-1])
    shown = axis.imshow(image, origin="lower", cmap="magma", aspect="auto")
    plt.colorbar(shown, ax=axis, label="slips per period", shrink=0.7)
    axis.set_xticks([(size + 2) * m + size / 2 - 0.5 for m in range(len(chosen))],
                    [f"h = {array['h'][k]:.2f}" for k in chosen])
    axis.set_ylabel("row j")
    axis.set_title(f"{size} × {size}: which rotors slip (columns along x)")


def plot_regimes(axis, arrays, rows, rows_paper, landscapes, colors):
    labels = []
    for y, (size, array) in enumerate(arrays.items()):
        h, mapped = array["h"], mapping(array).window(*landscapes[size]["window"])
        bars = [(window(h, array_regimes(array) == "CP"), 0.0, 1.0, "-"),
                (window(h, rows[size]["regime"] == "CP"), 0.2, 0.6, "-"),
                (mapped["field"], 0.35, 0.35, "-"),
                (window(h, rows_paper[size]["regime"] == "CP"), 0.5, 0.6, ":")]
        for w, dy, alpha, style in bars:
            if w is not None:
                axis.plot(w, [y + dy] * 2, lw=4, ls=style, color=colors[size], alpha=alpha, solid_capstyle="butt")
        labels.append(f"{size} × {size}")
    axis.set_yticks(range(len(labels)), labels)
    axis.set_xlabel("separation h (mm)")
    axis.set_title("CP: array; row model, landscape (A_field, paler); row model (A_paper, dotted)", fontsize="small")


def plot_slow(axis, slow, slow_rows, landscapes, colors):
    for size, array in slow.items():
        axis.plot(array["h"], array["f"], color=colors[size], label=f"{size} × {size}, g = {array['g']:.4f}")
        axis.plot(array["h"], slow_rows[size]["f"], color=colors[size], ls="--", lw=1)
        axis.plot(array["h"], landscapes[size]["J_slow"], color=colors[size], ls=":")
    axis.set_xlabel("separation h (mm)")
    axis.set_ylabel("friction per rotor (ε_pair / a)")
    axis.set_title("slow speed: array, row model (dashed), J(A_field) (dotted)")
    axis.legend(fontsize="x-small")


def plot_substrate(axis, substrates, substrate_rows, arrays, infinite, colors):
    for k, (s, array) in enumerate(sorted(substrates.items())):
        color = plt.cm.plasma(k / max(len(substrates) - 1, 1) * 0.8)
        axis.plot(array["h"], array["f"], color=color, label=f"substrate {s} × the slider")
        axis.plot(array["h"], substrate_rows[s]["f"], color=color, ls="--", lw=1)
    for size, array in infinite.items():
        axis.plot(array["h"], array["f"], color=colors[size], ls="-.", lw=1.2, label=f"{size} × {size}, infinite")
        if size != next(iter(substrates.values()))["size"]:
            axis.plot(arrays[size]["h"], arrays[size]["f"], color=colors[size], lw=0.8, alpha=0.6)
    size = next(iter(substrates.values()))["size"]
    axis.set_xlabel("separation h (mm)")
    axis.set_ylabel("friction per rotor (ε_pair / a)")
    axis.set_title(f"{size} × {size} over finite substrates (dashed: row model); infinite ones (dash-dot)", fontsize="small")
    axis.legend(fontsize="xx-small")


def plot_experiment(axis, experiment, arrays, limit):
    axis.plot(limit["h"], limit["f"], color="k", ls=":", label="array, N → ∞")
    for (name, array), style in zip(experiment.items(), ("-", "--")):
        axis.plot(array["h"], array["f"], ls=style, label=f"{EXPERIMENT_SIZE} × {EXPERIMENT_SIZE}, {name}")
    largest = max(arrays)
    axis.plot(arrays[largest]["h"], arrays[largest]["f"], color="0.6", label=f"{largest} × {largest}")
    axis.set_xlabel("separation h (mm)")
    axis.set_ylabel("friction per rotor (ε_pair / a)")
    axis.set_title("the experiment's array and the large-N limit")
    axis.legend(fontsize="x-small")


# ---------------------------------------------------------------- main


def main():
    args, rotorsweep = study_command_line.parse(__doc__, "row_reduction.png",
                                                "sizes 4 and 6 at four separations (the test suite's run)")
    grid = QUICK if args.quick else FULL
    arrays, rows, rows_paper, landscapes = {}, {}, {}, {}
    for size in grid["sizes"]:
        arrays[size] = run_array(rotorsweep, size, grid["h"][::2] if size in grid["coarse"] else grid["h"],
                                 args.threads)
        rows[size] = run_rows(rotorsweep, size, arrays[size]["A_field"], arrays[size]["g"], args.threads)
        rows_paper[size] = run_rows(rotorsweep, size, arrays[size]["A_paper"], arrays[size]["g"], args.threads)
        landscapes[size] = landscape(rotorsweep, size, arrays[size]["A_field"])
        progress(f"{size} x {size} done")
    infinite = {}
    for size in grid["infinite_sizes"]:
        infinite[size] = run_array(rotorsweep, size, grid["h"][::2] if len(grid["h"]) > 8 else grid["h"], args.threads,
                                   infinite=True)
        progress(f"{size} x {size} over an infinite substrate done")
    slow, slow_rows = {}, {}
    for size in grid["slow_sizes"]:
        slow_h = grid["slow_h"][::2] if size in grid["slow_coarse"] else grid["slow_h"]
        slow[size] = run_array(rotorsweep, size, slow_h, args.threads, speed=SLOW_SPEED)
        slow_rows[size] = run_rows(rotorsweep, size, slow[size]["A_field"], slow[size]["g"], args.threads)
        landscapes[size]["J_slow"] = landscape(rotorsweep, size, slow[size]["A_field"])["J"]
        progress(f"{size} x {size} at the slow speed done")
    substrates, substrate_rows = {}, {}
    size = grid["substrate_size"]
    for scale in grid["substrate_scales"]:
        if size in arrays and scale == SUBSTRATE_SCALE:
            substrates[scale], substrate_rows[scale] = arrays[size], rows[size]
        else:
            substrates[scale] = run_array(rotorsweep, size, grid["h"], args.threads, scale=scale)
            substrate_rows[scale] = run_rows(rotorsweep, size, substrates[scale]["A_field"], substrates[scale]["g"],
                                             args.threads)
        progress(f"substrate {scale} x done")
    # the start's noise alone: the same slider and substrate from another draw
    other_start = run_array(rotorsweep, size, grid["h"], args.threads, seed=2)
    experiment = {dynamics: run_array(rotorsweep, EXPERIMENT_SIZE, grid["h"], args.threads, dynamics=dynamics)
                  for dynamics in ("overdamped", "inertial")}
    progress("the experiment's size done")

    friction_table(arrays, rows, rows_paper)
    regime_gap_table(arrays, rows)
    profile_table(arrays, rows)
    limit = limit_table(arrays, rows)
    infinite_table(arrays, infinite, limit)
    uniformity_table(arrays)
    onset_table(arrays)
    regime_table(arrays, rows, rows_paper, landscapes)
    slow_table(slow, slow_rows, landscapes)
    field_table(arrays[max(arrays)])
    substrate_table(substrates, substrate_rows, other_start)
    experiment_table(experiment, arrays, limit)

    colors = size_colors(list(arrays))
    figure, axes = plt.subplots(2, 4, figsize=(20, 9))
    plot_friction(axes[0, 0], arrays, rows, limit, colors)
    plot_gaps(axes[0, 1], arrays, rows)
    plot_uniformity(axes[0, 2], arrays, colors)
    plot_slip_maps(axes[0, 3], arrays)
    plot_regimes(axes[1, 0], arrays, rows, rows_paper, landscapes, colors)
    plot_slow(axes[1, 1], slow, slow_rows, landscapes, colors)
    plot_substrate(axes[1, 2], substrates, substrate_rows, arrays, infinite, colors)
    plot_experiment(axes[1, 3], experiment, arrays, limit)
    study_command_line.save(figure, args.out, 60)


if __name__ == "__main__":
    main()
