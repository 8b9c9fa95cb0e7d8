"""The two-angle energy landscape H_r(θe, θo; A, τ) (docs/model.md §4–5) as NumPy arrays and
xarray Datasets: critical points, the chamber map, bifurcation curves, J(A), A_− and A_*."""

import numpy as np
import xarray as xr

from . import _core

#: A_−, the smallest A of the CP interval (lower off-diagonal curve's minimum)
A_minus = _core.A_minus
#: A_*, where the lower off-diagonal curve meets the transverse strict-FM curve (J(A_*) = 0)
A_star = _core.A_star

MORSE_TYPES = ("minimum", "saddle", "maximum")
ALIGNMENT_CLASSES = ("strict_fm", "fm_like", "afm_like")


def critical_points(A, tau):
    """Every critical point of H_r at (A, τ): a dict of arrays even, odd (angles in [0, 2π)),
    energy, rho (alignment cos²((θe − θo)/2)), type and alignment (strings)."""
    points = _core.critical_points(float(A), float(tau))
    points["type"] = np.array(points["type"], dtype=str)
    points["alignment"] = np.array(points["alignment"], dtype=str)
    return points


def chamber_map(A_min=0.0, A_max=12.0, A_cells=400, tau_cells=300):
    """The chamber raster over (A, τ ∈ [0, π/2]) at cell centres, as an xarray.Dataset with
    counts of minima, saddles, maxima and degenerate points per cell, counts by Morse type and
    alignment class, and the zone and chamber labels (−1 on degenerate cells). Runs on all cores."""
    # the command line's bounds (`landscape chambers --A-cells, --tau-cells`); memory is checked before any work
    if not (2 <= A_cells <= 100000 and 2 <= tau_cells <= 100000 and A_max > A_min):
        raise ValueError(f"chamber_map: need 2 <= A_cells, tau_cells <= 100000 and A_max > A_min "
                         f"(got {A_cells}, {tau_cells}, {A_min}, {A_max})")
    raw = _core.chamber_map(float(A_min), float(A_max), int(A_cells), int(tau_cells))
    cell = ("A", "tau")
    described = {
        "minima": "minima on the torus (an exchange pair counts twice)",
        "saddles": "saddles on the torus",
        "maxima": "maxima on the torus",
        "degenerate": "degenerate critical points",
        "zone": "connected component of equal Morse signature (−1: degenerate cell)",
        "chamber": "connected component of equal signature and alignment classes (−1: degenerate cell)",
    }
    variables = {name: (cell, raw[name], {"description": text}) for name, text in described.items()}
    variables["by_type_and_class"] = (
        cell + ("type", "alignment"), raw["by_type_and_class"],
        {"description": "critical points by Morse type and alignment class"})
    return xr.Dataset(
        variables,
        coords={"A": raw["A"], "tau": raw["tau"], "type": list(MORSE_TYPES), "alignment": list(ALIGNMENT_CLASSES)},
        attrs={"zones": raw["zones"], "chambers": raw["chambers"]})


def bifurcation_curve(name, count=2000, A_max=np.inf):
    """`count` points of a curve in the folded (A, τ) plane: arrays A, tau, parameter. Names:
    fm_tangential, fm_transverse, off_diagonal_plus, off_diagonal_minus, alignment."""
    if not 2 <= count <= 10_000_000:  # the command line's bounds (`landscape curves --samples`)
        raise ValueError(f"bifurcation_curve: need 2 <= count <= 10000000 (got {count})")
    return _core.bifurcation_curve(name, int(count), float(min(A_max, 1e300)))


def jump_events(A):
    """The two jumps of half a drive period at A ∈ [A_−, A_*] (a dict; NaN outside)."""
    return _core.jump_events(float(A))


def _usable(coefficients):
    """(a, b, c) as floats; ValueError in the command line's words (`landscape --coefficients`) where they
    give no CP window, before any work."""
    a, b, c = (float(x) for x in coefficients)
    lo, hi = _core.cp_interval(a, b, c)
    if not (np.isfinite(lo) and np.isfinite(hi)):
        raise ValueError(f"coefficients: a, b, c = {a:g}, {b:g}, {c:g} give no CP window (A_- = {lo:g}, "
                         f"A_* = {hi:g}); give coefficients with a finite window, or leave them out (nearest "
                         "neighbours, or two_angle_coefficients)")
    return a, b, c


def jump_friction(A, coefficients=(1.5, 2.0, 0.0)):
    """The quasi-static CP friction J(A) = ΔH⊥ + ΔH_low per half period by the paper's recipe (array
    in, array out; NaN outside [A_−, A_*] and where its sequence of jumps does not occur). With
    `coefficients` (a_M, b_M, c_M) the landscape of a coupling table (two_angle_coefficients); ones without
    a CP window raise ValueError."""
    a, b, c = _usable(coefficients)
    return _core.jump_friction(np.asarray(A, dtype=float), a, b, c)


def quasi_static_friction(A, coefficients=(1.5, 2.0, 0.0)):
    """The friction J (energy per row and period, the g → 0 limit of D/N) and the mean alignment of
    the quasi-static cycle from the AFM state, for each A: a pair of arrays. It follows a minimum of
    H_r and jumps down the gradient flow where the minimum ends, so it holds also where the
    recipe's sequence does not occur (docs/model.md §8). Coefficients without a CP window raise ValueError."""
    a, b, c = _usable(coefficients)
    A = np.atleast_1d(np.asarray(A, dtype=float))
    return _core.quasi_static_cycle(A.tolist(), a, b, c)


def cp_interval(coefficients=(1.5, 2.0, 0.0)):
    """(A_−, A_*) of the landscape with coefficients (a, b, c): the minimum of the lower off-diagonal
    curve and its end on the transverse strict-FM curve."""
    a, b, c = (float(x) for x in coefficients)
    return _core.cp_interval(a, b, c)


def two_angle_coefficients(range, row_length="infinite", rows=None):
    """(a_M, b_M, c_M) of point-dipole rows up to `range` rows apart ("all": every row of a ring of
    `rows`), rows of `row_length` rotors (or "infinite"); with `rows`, the periodic ring of that many
    rows as a sweep builds it (a partner exactly rows/2 away counted once)."""
    all_rows = range == "all"
    if all_rows and not rows:
        raise ValueError("two_angle_coefficients: range 'all' needs rows")
    if not all_rows and not 1 <= int(range) <= 100000:  # the command line's bounds (`couplings --range`)
        raise ValueError(f"two_angle_coefficients: range must be 1 … 100000 or 'all' (got {range})")
    length = 0 if row_length == "infinite" else int(row_length)
    return _core.two_angle_coefficients(0 if all_rows else int(range), all_rows, length, int(rows or 0))
