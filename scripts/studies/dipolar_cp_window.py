#!/usr/bin/python3
"""The CP window in layer separation with dipolar couplings (docs/studies.md, "The CP window with dipolar couplings,
in layer separation"): is the separation interval of CP narrower, and its alignment more FM-like, with every pair?

For the experiment's slider (examples/experiment_7x7.toml, docs/model.md §9) the CP window of the row model's reductions
(nearest neighbours; point dipoles over M = 1, 2, 4, 8 and all rows of 7 rotors, docs/model.md §8) from the landscape
(A_−, A_*, and the quasi-static cycle's alignment) and from sweeps of N = 20 periodic and open rows at g = 0.001 and at
the slider's own g, turned into separations h with both mappings of A the slider file writes (A_paper, A_field), next to
the slider's own window from its order parameter across y. Prints the tables of docs/studies.md and draws the figure
(about 40 s on 2 cores; --quick: coarser grids, a shorter slide, fewer periods and sweeps, about 10 s).
Usage: dipolar_cp_window.py [--quick] [--out docs/figures/dipolar_cp_window.png] [--python build/python] [--threads 2]"""
import itertools
import pathlib
import sys
import tempfile
import tomllib

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import study_command_line

ROOT = pathlib.Path(__file__).resolve().parents[2]
SLIDER_SCENE = ROOT / "examples" / "experiment_7x7.toml"

ROWS = 20                      # rows of the sweeps (range 8 needs N ≥ 16 on a ring)
ROW_LENGTH = 7                 # the slider's rotors per row: the dipolar tables' sums over k
G_SMALL = 0.001                # the sweeps' quasi-static side
REDUCTIONS = [("nearest", {}), ("M = 1", {"range": 1}), ("M = 2", {"range": 2}), ("M = 4", {"range": 4}),
              ("M = 8", {"range": 8}), ("all", {"range": "all"})]
NEAREST = (1.5, 2.0, 0.0)      # (a_M, b_M, c_M) of nearest neighbours (docs/model.md §8)
SWITCHING = 1 / 3              # the slider switches when order_y swings by one of its 6 row pairs (2/6) while sliding
SETTLED_FROM = 2.5             # s: the slider's swing is read after its first period of sliding (0.5 s rest + 2 s)
DISORDER = 1e-3                # σ_A of the one disordered sweep (source "…,σA"), nearest neighbours only
MEAN_RULE = 0.9                # the check on the mean: CP-like where |order_y| < this

FULL = {"separations": 81, "slide_end": None, "schedule": {"relax_periods": 4, "average_periods": 4},
        "coarse_step": 0.25, "fine_step": 0.02, "numerics": {}, "cycle_points": 241, "slider_g_reductions": REDUCTIONS}
# the quick run: the slider's scan every 0.5 mm to t = 6.5 s (two periods of sliding after SETTLED_FROM); the sweeps'
# members over 1 + 1 periods and without shadow runs (these bound D's error, which no table uses, and change no regime
# or alignment): every window of the slider and of the sweeps at g = 0.001 stays where it was; the quasi-static cycles
# on 11 points (rho within 0.003); at the slider's g only the clean nearest neighbours (no CP) and the disordered ring,
# since each sweep costs about 0.1 s besides its members
QUICK = {"separations": 17, "slide_end": 6.5, "schedule": {"relax_periods": 1, "average_periods": 1},
         "coarse_step": 1.0, "fine_step": 0.25, "numerics": {"global_error": "local"}, "cycle_points": 11,
         "slider_g_reductions": REDUCTIONS[:1]}
A_RANGE = (2.5, 16.0)          # the sweeps' coarse grid spans every window


def progress(text):
    print(text, file=sys.stderr, flush=True)


# ---------------------------------------------------------------- the slider and the mappings of A


def run_slider(rotorsweep, grid, threads):
    """The slider scan's /curve and its order_y series (members in separation order; one size, one replica) over the
    grid's separations, to its slide_end (None: the scene's end)."""
    scene = tomllib.loads(SLIDER_SCENE.read_text())
    scene["sweep"]["separation"]["count"] = grid["separations"]
    if grid["slide_end"] is not None:
        scene["drive"]["end"] = grid["slide_end"]
    del scene["output"]
    scene["numerics"]["global_error"] = "local"  # the curve and the order only: no shadow runs
    with tempfile.TemporaryDirectory(prefix="dipolar-cp-window-") as scratch:
        path = pathlib.Path(scratch) / "slider.h5"
        rotorsweep.slider(scene, threads=threads, progress=False, output=path)
        with h5py.File(path, "r") as f:
            curve = {name: f["curve"][name][:] for name in ("separation", "order_y", "A_paper", "A_field", "friction")}
            time, series = f["series/time"][:], f["series/order_y"][:]
            assert np.array_equal(f["members/separation"][:], curve["separation"])
            curve["g"] = float(f.attrs["g"])
    settled = time >= SETTLED_FROM
    curve["order_y_min"] = series[:, settled].min(axis=1)
    curve["order_y_max"] = series[:, settled].max(axis=1)
    curve["h_mm"] = curve["separation"] * 1e3
    return curve


class Mapping:
    """h (mm) for a row model's A: the paper's A = (a/h)³ m_sub/m exactly (its constant A h³ from the slider's /curve),
    the field's first harmonic by interpolating ln A_field in h over the scan (NaN outside it)."""

    def __init__(self, curve):
        self.h = curve["h_mm"]
        self.paper_constant = float(np.median(curve["A_paper"] * self.h ** 3))
        self.log_field = np.log(curve["A_field"])

    def paper(self, A):
        return (self.paper_constant / np.asarray(A, dtype=float)) ** (1 / 3)

    def field(self, A):
        # ln A_field falls monotonically with h: interpolate h against it (np.interp wants it rising)
        return np.interp(np.log(A), self.log_field[::-1], self.h[::-1], left=np.nan, right=np.nan)

    def window(self, A_lo, A_hi):
        """The separation windows (h_lo, h_hi) of an A window under both mappings: large A is small h."""
        return {"paper": (float(self.paper(A_hi)), float(self.paper(A_lo))),
                "field": (float(self.field(A_hi)), float(self.field(A_lo)))}


def slider_window(curve):
    """The slider's CP window: the outermost separations whose order across y swings by at least SWITCHING while
    sliding (after the first period), i.e. rows switch between parallel and antiparallel; FM-like and AFM-like
    separations keep it near +1 or −1. Also the window of the mean rule |order_y| < MEAN_RULE, as a check."""
    h = curve["h_mm"]
    switching = curve["order_y_max"] - curve["order_y_min"] >= SWITCHING
    mean_rule = np.abs(curve["order_y"]) < MEAN_RULE
    rho = (1 + curve["order_y"][switching]) / 2  # the alignment ρ = cos²(Δθ/2) of a row pair
    return {"h": (h[switching].min(), h[switching].max()), "mean_rule": (h[mean_rule].min(), h[mean_rule].max()),
            "rho": float(rho.mean()), "rho_range": (float(rho.min()), float(rho.max()))}


# ---------------------------------------------------------------- the row model: landscape and sweeps


def coefficients(rotorsweep, model):
    """(a_M, b_M, c_M) of a reduction's two-angle landscape (periodic rows of ROW_LENGTH rotors)."""
    if not model:
        return NEAREST
    return tuple(rotorsweep.two_angle_coefficients(model["range"], row_length=ROW_LENGTH, rows=ROWS))


def in_separation(A):
    """Weights that turn a mean over A into a mean over h under the paper's mapping: |dh/dA| ∝ A^(−4/3)."""
    return np.asarray(A, dtype=float) ** (-4 / 3)


def landscape_window(rotorsweep, model, points):
    """A_−, A_* and the quasi-static cycle's mean alignment over [A_−, A_*], uniform in h (paper's mapping, A ∝ h⁻³)."""
    k = coefficients(rotorsweep, model)
    A_lo, A_hi = rotorsweep.landscape.cp_interval(k)
    A = np.linspace(A_hi ** (-1 / 3), A_lo ** (-1 / 3), points + 2)[1:-1] ** -3
    _, rho = rotorsweep.quasi_static_friction(A, k)
    infinite = NEAREST if not model else rotorsweep.two_angle_coefficients(model["range"], rows=ROWS)
    lo_inf, hi_inf = rotorsweep.landscape.cp_interval(infinite)
    return {"k": k, "A": (A_lo, A_hi), "rho": float(np.mean(rho)), "ratio_infinite": (hi_inf / lo_inf) ** (1 / 3),
            "cycle_A": A, "cycle_rho": np.asarray(rho)}


def sweep(rotorsweep, model, boundary, g, A, grid, threads, disorder=0.0):
    """(A, regime, alignment_mean) of AFM starts (the slider's start) at the given A values, on the grid's schedule
    and numerics."""
    section = {"rows": ROWS, "boundary": boundary}
    if model:
        section.update({"couplings": "dipolar", "row_length": ROW_LENGTH, **model})
    scene = {"model": section, "drive": {"g": [g]}, "sweep": {"A": [float(a) for a in A]},
             "initial": {"kinds": ["AFM"]}, "schedule": grid["schedule"], "numerics": grid["numerics"]}
    if disorder:
        scene["disorder"] = {"A": disorder}
    # one replica of one start at one g: the members lie along A (cheaper than stacking them with members())
    m = rotorsweep.run(scene, threads=threads, progress=False, quiet=True).isel(replica=0)
    return m.A.values, m.regime.values.astype(str), m.alignment_mean.values


def edges(A, cp):
    """The brackets (last non-CP, first CP) and (last CP, first non-CP) of the outermost CP values on a sorted grid."""
    inside = np.flatnonzero(cp)
    lo, hi = inside[0], inside[-1]
    return [(A[max(lo - 1, 0)], A[lo]), (A[hi], A[min(hi + 1, len(A) - 1)])]


def sweep_window(rotorsweep, model, boundary, g, grid, threads, disorder=0.0):
    """The sweep's CP window (the lowest and highest A labelled CP) on a coarse grid refined at both ends, and the mean
    alignment of its CP members (coarse grid, weighted to a mean uniform in h). None without CP."""
    coarse = np.round(np.arange(A_RANGE[0], A_RANGE[1] + 1e-9, grid["coarse_step"]), 6)
    A, regime, rho = sweep(rotorsweep, model, boundary, g, coarse, grid, threads, disorder)
    if not (regime == "CP").any():
        return None
    mean_rho = float(np.average(rho[regime == "CP"], weights=in_separation(A[regime == "CP"])))
    fine = np.concatenate([np.arange(lo, hi + 1e-9, grid["fine_step"]) for lo, hi in edges(A, regime == "CP")])
    A_fine, regime_fine, _ = sweep(rotorsweep, model, boundary, g, np.unique(np.round(fine, 6)), grid, threads,
                                   disorder)
    A_all, order = np.unique(np.concatenate([A, A_fine]), return_index=True)
    cp = np.concatenate([regime, regime_fine])[order] == "CP"
    return {"A": (float(A_all[cp].min()), float(A_all[cp].max())), "rho": mean_rho,
            "gaps": int(np.sum(~cp[np.argmax(cp):len(cp) - np.argmax(cp[::-1])]))}


# ---------------------------------------------------------------- tables


def fmt_window(window, digits=2):
    return f"{window[0]:.{digits}f}-{window[1]:.{digits}f}"


def width_and_ratio(window):
    return window[1] - window[0], window[1] / window[0]


def landscape_table(landscape, mapping):
    print("\nlandscape (periodic two-angle reduction, rows of 7 rotors; h in mm; ratio = h_hi/h_lo; ratio_inf: "
          "infinite rows; ratio_f: field's mapping; rho: the quasi-static cycle's mean alignment, uniform in h)")
    print(f"{'couplings':9} {'a_M':>6} {'b_M':>6} {'c_M':>6} {'A_-':>7} {'A_*':>7} {'ratio':>6} {'ratio_inf':>9} "
          f"{'h paper':>11} {'width':>5} {'h field':>11} {'width':>5} {'ratio_f':>7} {'rho':>5}")
    for name, w in landscape.items():
        h = mapping.window(*w["A"])
        a, b, c = w["k"]
        print(f"{name:9} {a:6.4f} {b:6.4f} {c:6.4f} {w['A'][0]:7.4f} {w['A'][1]:7.4f} "
              f"{(w['A'][1] / w['A'][0]) ** (1 / 3):6.4f} {w['ratio_infinite']:9.4f} {fmt_window(h['paper']):>11} "
              f"{width_and_ratio(h['paper'])[0]:5.2f} {fmt_window(h['field']):>11} {width_and_ratio(h['field'])[0]:5.2f} "
              f"{width_and_ratio(h['field'])[1]:7.4f} {w['rho']:5.3f}")


def sweep_table(sweeps, mapping, schedule):
    print(f"\nsweeps (N = {ROWS}, AFM starts, {schedule['relax_periods']} + {schedule['average_periods']} periods; "
          f"window: lowest to highest A labelled CP; h in mm; rho: mean alignment_mean of the CP members, uniform in h; "
          f"σA: quenched disorder σ_A = {DISORDER:g})")
    print(f"{'source':12} {'couplings':9} {'boundary':8} {'A window':>12} {'h paper':>11} {'width':>5} "
          f"{'h field':>11} {'width':>5} {'rho':>5} {'gaps':>4}")
    for (source, name, boundary), w in sweeps.items():
        if w is None:
            print(f"{source:12} {name:9} {boundary:8} {'no CP':>12}")
            continue
        h = mapping.window(*w["A"])
        print(f"{source:12} {name:9} {boundary:8} {fmt_window(w['A']):>12} {fmt_window(h['paper']):>11} "
              f"{width_and_ratio(h['paper'])[0]:5.2f} {fmt_window(h['field']):>11} "
              f"{width_and_ratio(h['field'])[0]:5.2f} {w['rho']:5.3f} {w['gaps']:4d}")


def slider_table(curve, window):
    h = window["h"]
    at = [int(np.argmin(np.abs(curve["h_mm"] - x))) for x in h]
    print(f"\nslider 7 x 7 (g = {curve['g']:.3f}): CP-like where order_y swings by >= {SWITCHING:.3f} after "
          f"t = {SETTLED_FROM} s")
    print(f"window h = {fmt_window(h)} mm, width {h[1] - h[0]:.2f} mm, ratio {h[1] / h[0]:.4f}; "
          f"A_paper {curve['A_paper'][at[1]]:.3f}-{curve['A_paper'][at[0]]:.3f}, "
          f"A_field {curve['A_field'][at[1]]:.3f}-{curve['A_field'][at[0]]:.3f}; "
          f"rho {window['rho']:.3f} ({window['rho_range'][0]:.3f}-{window['rho_range'][1]:.3f})")
    print(f"check: |order_y| < {MEAN_RULE} at h = {fmt_window(window['mean_rule'])} mm")


def predictions(landscape, sweeps, mapping):
    """Every reduction's predicted separation window per mapping: {(source, couplings, boundary, mapping): (lo, hi)}."""
    out = {}
    for name, w in landscape.items():
        for kind, h in mapping.window(*w["A"]).items():
            out[("landscape", name, "periodic", kind)] = h
    for (source, name, boundary), w in sweeps.items():
        if w is not None:
            for kind, h in mapping.window(*w["A"]).items():
                out[(source, name, boundary, kind)] = h
    return out


def comparison_table(predicted, window):
    """Each prediction's edge offsets from the slider's window (mm) and their sum, best first; sum_mean: the same sum
    against the mean rule's window."""
    lo, hi = window["h"]

    def miss(h, target):
        return abs(h[0] - target[0]) + abs(h[1] - target[1])

    scored = sorted(predicted.items(), key=lambda item: miss(item[1], window["h"]))
    print("\nagainst the slider's window (mm; offset = predicted - slider), best first")
    print(f"{'source':12} {'couplings':9} {'boundary':8} {'mapping':7} {'h window':>11} {'d_lo':>6} {'d_hi':>6} "
          f"{'sum':>5} {'sum_mean':>8}")
    for (source, name, boundary, kind), h in scored:
        print(f"{source:12} {name:9} {boundary:8} {kind:7} {fmt_window(h):>11} {h[0] - lo:+6.2f} {h[1] - hi:+6.2f} "
              f"{miss(h, window['h']):5.2f} {miss(h, window['mean_rule']):8.2f}")


def coefficient_table(rotorsweep):
    """Which coefficient widens the window: the landscape with nearest-neighbour coefficients, each replaced by the
    all-rows table's value alone and together."""
    full = coefficients(rotorsweep, {"range": "all"})
    print("\nwhich coefficient: nearest-neighbour (a, b, c) with the all-rows table's values swapped in")
    print(f"{'swapped':9} {'a_M':>6} {'b_M':>6} {'c_M':>6} {'A_-':>7} {'A_*':>7} {'ratio':>6}")
    for mask in itertools.product((False, True), repeat=3):
        k = np.where(mask, full, NEAREST)
        A_lo, A_hi = rotorsweep.landscape.cp_interval(k)
        name = "".join(letter for letter, on in zip("abc", mask) if on) or "none"
        print(f"{name:9} {k[0]:6.4f} {k[1]:6.4f} {k[2]:6.4f} {A_lo:7.4f} {A_hi:7.4f} {(A_hi / A_lo) ** (1 / 3):6.4f}")


# ---------------------------------------------------------------- figure


def plot_slider(axis, curve, window, landscape, mapping):
    """The slider's order across y (mean and its swing) with its window, and the alignment 2ρ − 1 of the quasi-static
    cycle and of the sweeps' CP windows under the paper's mapping."""
    h = curve["h_mm"]
    axis.fill_between(h, curve["order_y_min"], curve["order_y_max"], color="0.85", label="slider: swing (t ≥ 2.5 s)")
    axis.plot(h, curve["order_y"], color="k", label="slider: mean order_y")
    axis.axvspan(*window["h"], color="0.6", alpha=0.25, label="slider CP window")
    for name, color in (("nearest", "tab:blue"), ("all", "tab:red")):
        w = landscape[name]
        axis.plot(mapping.paper(w["cycle_A"]), 2 * w["cycle_rho"] - 1, color=color, ls="--",
                  label=f"{name}: quasi-static 2ρ − 1 (A_paper)")
    axis.set_xlabel("separation h (mm)")
    axis.set_ylabel("order across y")
    axis.set_title("the slider's order and the cycles' alignment")
    axis.legend(fontsize="x-small", loc="lower left")


def plot_windows(axis, predicted, window, kind):
    """Each reduction's window in h as a bar, the slider's as a band."""
    labels = []
    entries = [(key, h) for key, h in predicted.items() if key[3] == kind]
    sources = list(dict.fromkeys(source for (source, *_), _ in entries))
    for y, ((source, name, boundary, _), h) in enumerate(entries):
        axis.plot(h, [y, y], lw=5, color=f"C{sources.index(source)}", alpha=0.5 if boundary == "open" else 1.0,
                  solid_capstyle="butt")
        labels.append(f"{source} {name} {boundary}")
    axis.axvspan(*window["h"], color="0.6", alpha=0.25)
    for h in window["mean_rule"]:
        axis.axvline(h, color="0.3", ls=":", lw=1)
    axis.set_yticks(range(len(labels)), labels, fontsize=6)
    axis.invert_yaxis()
    axis.set_xlabel("separation h (mm)")
    axis.set_title(f"CP windows, A_{kind} mapping (band: slider; dotted: its mean rule)")


# ---------------------------------------------------------------- main


def main():
    args, rotorsweep = study_command_line.parse(__doc__, "dipolar_cp_window.png", "coarser grids (the test suite's run)")

    grid = QUICK if args.quick else FULL
    curve = run_slider(rotorsweep, grid, args.threads)
    progress(f"slider: {grid['separations']} separations done")
    mapping = Mapping(curve)
    window = slider_window(curve)

    landscape = {name: landscape_window(rotorsweep, model, grid["cycle_points"]) for name, model in REDUCTIONS}
    progress("landscape done")
    sweeps = {}
    slider_g = f"g={curve['g']:.3g}"
    for source, g, reductions in ((f"g={G_SMALL:g}", G_SMALL, REDUCTIONS),
                                  (slider_g, curve["g"], grid["slider_g_reductions"])):
        for boundary in ("periodic", "open"):
            for name, model in reductions:
                sweeps[(source, name, boundary)] = sweep_window(rotorsweep, model, boundary, g, grid, args.threads)
            progress(f"sweeps at {source}, {boundary} rows done")
    # a clean ring of nearest neighbours leaves the strict-FM saddle only as fast as rounding errors grow: at the
    # slider's g this needs a physical perturbation, here quenched disorder of the substrate strength
    sweeps[(f"{slider_g},σA", "nearest", "periodic")] = sweep_window(rotorsweep, {}, "periodic", curve["g"], grid,
                                                                      args.threads, disorder=DISORDER)

    landscape_table(landscape, mapping)
    sweep_table(sweeps, mapping, grid["schedule"])
    slider_table(curve, window)
    comparison_table(predictions(landscape, sweeps, mapping), window)
    coefficient_table(rotorsweep)

    figure = plt.figure(figsize=(12, 9))
    layout = figure.add_gridspec(2, 2, height_ratios=(1, 1.6))
    plot_slider(figure.add_subplot(layout[0, :]), curve, window, landscape, mapping)
    predicted = predictions(landscape, sweeps, mapping)
    for column, kind in enumerate(("paper", "field")):
        plot_windows(figure.add_subplot(layout[1, column]), predicted, window, kind)
    study_command_line.save(figure, args.out, 80)


if __name__ == "__main__":
    main()
