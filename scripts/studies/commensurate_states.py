#!/usr/bin/python3
"""Commensurate structured states (docs/studies.md, "Commensurate structured states"): which period-k patterns of
N ≤ 24 periodic rows (docs/model.md §1) are attractors, over which A, with what friction beside the reduction of §5.

Exact starts from every pattern of the families below on every ring they fit, the same patterns perturbed on every
row ("near" starts) and in rings with quenched disorder, and random starts on every N, all at g = 0.0011; each
member's final state is sorted into an outcome (kept, a two-sublattice state, another frozen pattern, slipping walls)
from its attractor label and its final angles. Prints the numbers of docs/studies.md and draws the figure (about
5 to 6 minutes on 2 cores; --quick: a few patterns and rings, seconds).
Usage: commensurate_states.py [--quick] [--out docs/figures/commensurate_states.png] [--python build/python]
                              [--threads 2]"""
import itertools
from collections import Counter
import sys
from dataclasses import dataclass

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import study_command_line


G = 0.0011                     # the paper's damping × speed
SCHEDULE = {"relax_periods": 4, "average_periods": 4}
NEAR_NOISE = 0.2               # near starts: the pattern plus U[−η, η] on every row
DISORDER = 1e-3                # σ of the rows' substrate strength in the disordered rings
ALL_ISING_UP_TO = 8            # every Ising pattern of period k ≤ this; the three families beyond
SLIPPING_ROW = 1.0             # a row whose share D_j of the friction exceeds this slips every period
Z = 1.959963984540054          # Wilson 95 % intervals, the z of /curves (docs/model.md §3)
A_MINUS = 4.634583466980286    # where the two-angle reduction's CP interval begins (docs/model.md §4)

FULL = {
    "rows": list(range(2, 25, 2)),
    # 0.25 steps to A = 4.5, 0.05 steps where the frozen patterns end, the edge of CP, and CP and FM sparsely
    "A": sorted({*np.round(np.arange(0.25, 4.51, 0.25), 2), 1.85, 1.9, 1.95, 2.05, 3.35, 3.4, 3.45, 3.55, 3.6, 3.65,
                 3.7, 4.6, 4.7, 5.0, 6.0, 8.0, 10.0, 12.0}),
    "random_A": [0.5, 1.0, 1.5, 1.75, 2.0, 2.25, 2.5, 3.0, 3.25, 3.5, 3.55, 3.6, 3.7, 4.0, 4.25, 4.5, 5.0, 6.0, 8.0,
                 10.0],
    "max_period": 24, "near_draws": 4, "disorder_replicas": 4, "random_replicas": 200, "wall_periods": 8,
    "J_points": 200, "numerics": {},
}
# the quick run: the patterns of period ≤ 3 (every family but blocks) on the small rings, one near draw each (each
# scene costs about 0.1 s besides its members); the walls followed over their last slip (in the first period) and two
# periods after it; J(A) drawn from 20 points (the landscape takes 0.01 s a point); no shadow runs (they bound D's
# error, which no table prints, and change no D, label or angle)
QUICK = {
    "rows": [2, 4, 6, 8], "A": [1.0, 3.0, 4.0, 6.0, 11.0], "random_A": [1.0, 3.0, 6.0, 11.0],
    "max_period": 3, "near_draws": 1, "disorder_replicas": 2, "random_replicas": 10, "wall_periods": 3,
    "J_points": 20, "numerics": {"global_error": "local"},
}
REDUCTION_A = np.round(np.arange(0.25, 12.01, 0.25), 2)  # N = 2 is cheap: its branches on a fine grid
# the A values the friction and basin tables quote (the quick grid has some of them)
FRICTION_A = (1.0, 3.0)
BASIN_A = (1.0, 2.5, 3.6, 4.25)


@dataclass(frozen=True)
class Pattern:
    name: str
    family: str              # FM, AFM, walls (longest parallel run 2), blocks (run ≥ 3), twisted
    angles: tuple            # one period of θ_j(0)
    bits: tuple | None       # Ising patterns: 0 for θ = 0, 1 for θ = π; None for twisted ones

    @property
    def period(self):
        return len(self.angles)


# ---------------------------------------------------------------- the patterns


def primitive_period(bits):
    """The smallest k with bits[j + k] = bits[j] for every j (cyclically)."""
    n = len(bits)
    return next(k for k in range(1, n + 1) if n % k == 0 and bits == bits[k:] + bits[:k])


def canonical(bits):
    """One representative of the pattern under rotation, reflection and θ → θ + π (the last with t → t + π is a
    symmetry of the equation of motion, so those patterns have the same dynamics half a period apart)."""
    flipped = tuple(1 - b for b in bits)
    return min(c[s:] + c[:s] for c in (bits, bits[::-1], flipped, flipped[::-1]) for s in range(len(bits)))


def longest_run(bits):
    """The longest cyclic run of equal neighbours (rows of one FM block); 1 for AFM."""
    if len(set(bits)) == 1:
        return np.inf
    start = next(j for j in range(len(bits)) if bits[j] != bits[j - 1])
    rotated = bits[start:] + bits[:start]
    return max(len(list(run)) for _, run in itertools.groupby(rotated))


def ising_name(bits):
    return "".join("ud"[b] for b in bits)


def ising_bits(name):
    return tuple("ud".index(c) for c in name)


def ising_pattern(bits):
    run = longest_run(bits)
    family = {np.inf: "FM", 1: "AFM", 2: "walls"}.get(run, "blocks")
    return Pattern(ising_name(bits), family, tuple(float(np.pi * b) for b in bits), tuple(bits))


def all_ising(k):
    """Every Ising pattern of primitive period k, one per class of canonical()."""
    found = {canonical(bits) for bits in itertools.product((0, 1), repeat=k) if primitive_period(bits) == k}
    return sorted(found)


def rows_from_bonds(parallel):
    """The Ising rows whose bond j (rows j, j + 1) is parallel where parallel[j], antiparallel elsewhere."""
    bits = [0]
    for p in parallel[:-1]:
        bits.append(bits[-1] if p else 1 - bits[-1])
    return tuple(bits)


def sparse_walls(k):
    """AFM with the fewest domain walls (parallel bonds) a period k allows: one for odd k, two as far apart as the
    primitive period allows for even k."""
    for second in ([] if k % 2 else [k // 2, k // 2 - 1]) or [None]:
        parallel = [j == 0 or j == second for j in range(k)]
        bits = rows_from_bonds(parallel)
        if sum(not p for p in parallel) % 2 == 0 and primitive_period(bits) == k:
            return bits
    raise ValueError(f"no sparse wall pattern of period {k}")


def family_patterns(k):
    """Beyond ALL_ISING_UP_TO: the balanced block u^⌈k/2⌉ d^⌊k/2⌋, a single reversed row u^(k−1) d, and the sparse
    walls."""
    block = tuple([0] * ((k + 1) // 2) + [1] * (k // 2))
    flip = tuple([0] * (k - 1) + [1])
    return sorted({canonical(b) for b in (block, flip, sparse_walls(k))})


def twisted(k):
    """θ_j = 2π q j / k (k ≥ 3) for q = 1 (one turn per period) and the largest q < k/2 coprime to k (the twist
    nearest to AFM)."""
    coprime = [q for q in range(1, (k + 1) // 2) if np.gcd(q, k) == 1]
    return [Pattern(f"twist {q}/{k}", "twisted", tuple(float(2 * np.pi * q * j / k) for j in range(k)), None)
            for q in sorted({coprime[0], coprime[-1]})]


def patterns(max_period, rows):
    """Every pattern of the study whose period divides some N of rows."""
    out = []
    for k in range(1, max_period + 1):
        if not any(n % k == 0 for n in rows):
            continue
        ising = all_ising(k) if k <= ALL_ISING_UP_TO else family_patterns(k)
        out += [ising_pattern(bits) for bits in ising]
        out += twisted(k) if k >= 3 else []
    return out


# ---------------------------------------------------------------- runs and outcomes


def sweep(rotorsweep, rows, A, initial, threads, disorder=0.0, row_profiles=False, numerics=None):
    """The members (stacked Dataset) of one scene at g = G."""
    scene = {"model": {"rows": rows}, "drive": {"g": [G]}, "sweep": {"A": [float(a) for a in A]},
             "initial": initial, "schedule": SCHEDULE, "observables": {"row_profiles": row_profiles},
             "numerics": numerics or {}}
    if disorder:
        scene["disorder"] = {"A": disorder}
    return rotorsweep.members(rotorsweep.run(scene, threads=threads, progress=False, quiet=True))


def projection(theta):
    """The Ising pattern nearest to the angles (0: cos θ > 0)."""
    return tuple(int(np.cos(x) < 0) for x in theta)


def outcome(label, theta, slips, start_bits=None):
    """The kind of final state. Without slips, on an orbit of one period and with every row near the easy axis at the
    period's end, a state is frozen into an Ising pattern: 'kept' when that is the start's own (or its θ + π image),
    else 'frozen repeating' or 'frozen non-repeating' (with or without a period shorter than the ring). Otherwise
    '<regime> 2SL' for a two-sublattice state, 'slipping walls' for one that slips every period with domain walls, or
    'other'. The regime alone does not tell a frozen state: one with as many parallel as antiparallel bonds has ρ̄
    swinging across 1/2, which the regime rule calls unsettled."""
    regime, structure, period = label.split(":") if label.count(":") == 2 else ("failed", "", "")
    frozen = slips == 0 and period == "p1" and np.max(np.abs(np.sin(theta))) < 0.5
    pattern = projection(theta)
    if start_bits is not None and frozen:
        start = np.tile(start_bits, len(theta) // len(start_bits))
        if pattern in (tuple(start), tuple(1 - start)):
            return "kept"
    if structure == "2SL":
        return f"{regime} 2SL"
    if regime == "CP":
        return "slipping walls"
    if frozen:
        return "frozen repeating" if primitive_period(pattern) < len(theta) else "frozen non-repeating"
    return "other"


@dataclass
class Member:
    pattern: str
    family: str
    rows: int
    A: float
    ring: str                # clean, disordered
    start: str               # exact, near, random
    label: str               # the attractor label (docs/model.md §3)
    outcome: str
    final: str               # a frozen state's Ising pattern, one period in canonical form ('' when not frozen)
    friction: float          # D/N
    slipping_rows: int       # rows with D_j > SLIPPING_ROW (−1 without row profiles)


def collect(m, pattern, ring, start, bits=None):
    """Member records of a stacked Dataset (pattern None: random starts)."""
    theta = m.theta_final.transpose("member", "row").values
    profile = m.row_dissipation.transpose("member", "row").values if "row_dissipation" in m else None
    rows = np.broadcast_to(m.rows.values, (m.sizes["member"],))  # a scalar coordinate when the scene has one N
    name, family = (pattern.name, pattern.family) if pattern else ("random", "random")
    out = []
    for i in range(m.sizes["member"]):
        n, label = int(rows[i]), str(m.attractor.values[i])
        kind = outcome(label, theta[i, :n], m.slips_per_period.values[i], bits)
        final = projection(theta[i, :n])
        final = ising_name(canonical(final[:primitive_period(final)])) if kind.startswith("frozen") else ""
        out.append(Member(name, family, n, float(m.A.values[i]), ring, start, label, kind, final,
                          float(m.dissipation.values[i]) / n,
                          int(np.sum(profile[i, :n] > SLIPPING_ROW)) if profile is not None else -1))
    return out


def run_patterns(rotorsweep, grid, threads):
    """Exact starts in clean rings of every N the period divides; on the largest of them also exact starts in
    disordered rings (several realizations) and near starts in the clean ring."""
    found = patterns(grid["max_period"], grid["rows"])
    rng = np.random.default_rng(1)
    members = []
    for i, p in enumerate(found):
        rows = [n for n in grid["rows"] if n % p.period == 0]
        bits = np.array(p.bits) if p.bits else None
        exact = {"kinds": ["exact"], "angles": list(p.angles)}
        members += collect(sweep(rotorsweep, rows, grid["A"], exact, threads, numerics=grid["numerics"]), p, "clean",
                           "exact", bits)
        n = max(rows)
        members += collect(sweep(rotorsweep, [n], grid["A"], {**exact, "replicas": grid["disorder_replicas"]},
                                 threads, disorder=DISORDER, row_profiles=True, numerics=grid["numerics"]),
                           p, "disordered", "exact", bits)
        for _ in range(grid["near_draws"]):
            angles = np.tile(p.angles, n // p.period) + rng.uniform(-NEAR_NOISE, NEAR_NOISE, n)
            near = {"kinds": ["exact"], "angles": angles.tolist()}
            members += collect(sweep(rotorsweep, [n], grid["A"], near, threads, numerics=grid["numerics"]), p,
                               "clean", "near", bits)
        if (i + 1) % 10 == 0 or i + 1 == len(found):
            print(f"patterns: {i + 1}/{len(found)} done", file=sys.stderr, flush=True)
    return found, members


def run_random(rotorsweep, grid, threads):
    """Random starts on every N, clean and disordered."""
    members = []
    for ring, disorder in (("clean", 0.0), ("disordered", DISORDER)):
        initial = {"kinds": ["random"], "replicas": grid["random_replicas"]}
        m = sweep(rotorsweep, grid["rows"], grid["random_A"], initial, threads, disorder, row_profiles=True,
                  numerics=grid["numerics"])
        members += collect(m, None, ring, "random")
        print(f"random starts: {ring} rings done", file=sys.stderr, flush=True)
    return members


def run_reduction(rotorsweep, A, threads, replicas, numerics):
    """The two-angle reduction at the same g: N = 2 from FM and AFM starts, clean and with the disordered rings' σ;
    {(ring, regime, A): mean D/N}."""
    sums = {}
    for ring, disorder in (("clean", 0.0), ("disordered", DISORDER)):
        m = sweep(rotorsweep, [2], A, {"kinds": ["FM", "AFM"], "replicas": replicas}, threads, disorder,
                  numerics=numerics)
        for label, a, d in zip(m.attractor.values, m.A.values, m.dissipation.values):
            sums.setdefault((ring, str(label).split(":")[0], float(a)), []).append(float(d) / 2)
    return {key: float(np.mean(values)) for key, values in sums.items()}


WALL_A = 4.0                   # the wall-motion diagnostic: above the frozen walls' end, below A_−


def wall_motion(rotorsweep, rows, threads, periods, numerics):
    """Sparse walls of period N = rows at A = WALL_A, clean and disordered: the slipping rows (D_j > SLIPPING_ROW) and
    the attractor label in each of the first periods, from runs that average period p after p − 1 of relaxation."""
    angles = [float(np.pi * b) for b in sparse_walls(rows)]
    print(f"\nwalls of {ising_name(sparse_walls(rows))} at A = {WALL_A:g}: slipping rows per period")
    for ring, disorder in (("clean", 0.0), ("disordered", DISORDER)):
        steps = []
        for p in range(1, periods + 1):
            scene = {"model": {"rows": rows}, "drive": {"g": [G]}, "sweep": {"A": [WALL_A]},
                     "initial": {"kinds": ["exact"], "angles": angles},
                     "schedule": {"relax_periods": p - 1, "average_periods": 1}, "observables": {"row_profiles": True},
                     "numerics": numerics}
            if disorder:
                scene["disorder"] = {"A": disorder}
            m = rotorsweep.members(rotorsweep.run(scene, threads=threads, progress=False, quiet=True))
            profile = m.row_dissipation.transpose("member", "row").values[0]
            steps.append(str(np.flatnonzero(profile > SLIPPING_ROW).tolist()).replace(" ", ""))
        print(f"{ring:10s} " + " ".join(steps) + f"   then {m.attractor.values[0]}")


# ---------------------------------------------------------------- numbers


def wilson(count, n):
    """The Wilson 95 % interval of count successes in n, as /curves computes it (docs/model.md §3): exactly 0 at
    count 0 and 1 at count n, always around the fraction; NaN for n = 0."""
    if n == 0:
        return np.nan, np.nan
    p = count / n
    centre = (p + Z * Z / (2 * n)) / (1 + Z * Z / n)
    half = Z / (1 + Z * Z / n) * np.sqrt(p * (1 - p) / n + Z * Z / (4 * n * n))
    low = 0.0 if count == 0 else min(p, max(0.0, centre - half))
    high = 1.0 if count == n else max(p, min(1.0, centre + half))
    return low, high


def linear_friction(bits, rows, A):
    """D/N of a pinned Ising pattern to order A²: with s the rows' signs and K the Hessian of H at A = 0
    (K_jj = 6 − b_{j−1} − b_j, K_{j,j+1} = b_j, b_j = s_j s_{j+1}), the periodic response to the rotating field gives
    D = π A² g sᵀ (K² + g²)⁻¹ s; for AFM it is docs/model.md §4's N π A² g / (100 + g²)."""
    s = np.where(np.tile(np.asarray(bits), rows // len(bits)) == 0, 1.0, -1.0)
    bond = s * np.roll(s, -1)
    K = np.diag(6 - bond - np.roll(bond, 1))
    for j in range(rows):
        K[j, (j + 1) % rows] += bond[j]
        K[(j + 1) % rows, j] += bond[j]
    return np.pi * A * A * G * s @ np.linalg.solve(K @ K + G * G * np.eye(rows), s) / rows


def survival(members, pattern, ring, start):
    """(A values of the grid, fraction of the pattern's members that kept it at each)."""
    own = [m for m in members if m.pattern == pattern and m.ring == ring and m.start == start]
    A = sorted({m.A for m in own})
    return np.array(A), np.array([np.mean([m.outcome == "kept" for m in own if m.A == a]) for a in A])


def intervals(A, ok):
    """The grid values where ok, as runs of neighbouring grid points: 'a-b, c-d' ('none' when empty)."""
    runs = [list(group) for value, group in itertools.groupby(zip(A, ok), key=lambda pair: pair[1]) if value]
    return ", ".join(f"{run[0][0]:g}-{run[-1][0]:g}" if len(run) > 1 else f"{run[0][0]:g}" for run in runs) or "none"


def survival_table(found, members):
    """Per family and kind of start: the A where every pattern, and where some pattern, was kept by all its starts;
    and what the near starts that lost their pattern ended in."""
    print("\nsurvival: A where all starts kept their pattern, for every pattern of the family and for some")
    print(f"{'family':8s} {'patterns':>8s} {'starts':17s} {'every pattern':24s} {'some pattern':24s}")
    for family in ("FM", "AFM", "walls", "blocks", "twisted"):
        names = [p.name for p in found if p.family == family]
        if not names:
            continue
        for ring, start in (("clean", "exact"), ("clean", "near"), ("disordered", "exact")):
            curves = [survival(members, name, ring, start) for name in names]
            A = curves[0][0]
            every = np.all([kept == 1 for _, kept in curves], axis=0)
            some = np.any([kept == 1 for _, kept in curves], axis=0)
            print(f"{family:8s} {len(names):8d} {start + ' ' + ring:17s} {intervals(A, every):24s} "
                  f"{intervals(A, some):24s}")
        lost = {}
        for m in members:
            if m.family == family and m.start == "near" and m.outcome != "kept":
                lost[m.outcome] = lost.get(m.outcome, 0) + 1
        total = sum(lost.values())
        print(f"{'':8s} {'':8s} near starts that lost it: " + ", ".join(
            f"{k} {v / total:.0%}" for k, v in sorted(lost.items(), key=lambda kv: -kv[1])[:5]))


def invariant(m):
    """An exact FM start in a clean ring: it stays in the strict-FM set for ever (docs/model.md §2), so its orbit
    is no test of attraction."""
    return m.family == "FM" and m.start == "exact" and m.ring == "clean"


def friction_table(members, reduction):
    """Friction of each kind of attractor against the two-angle reduction of the same ring at the same A, and of the
    frozen patterns against their order-A² law."""
    print("\nfriction D/N against the two-angle reduction (N = 2, same g and ring)")
    print(f"{'outcome':22s} {'A':>6s} {'members':>8s} {'D/N':>19s} {'/ reduction AFM':>17s} {'/ order-A² law':>15s}")
    for a in FRICTION_A:
        for family in ("AFM", "walls", "blocks"):
            kept = [m for m in members if m.family == family and m.outcome == "kept" and m.start == "exact"
                    and m.ring == "clean" and m.A == a]
            if not kept:
                continue
            d = np.array([m.friction for m in kept])
            afm = reduction.get(("clean", "AFM", a), np.nan)
            law = np.array([m.friction / linear_friction(ising_bits(m.pattern), m.rows, a) for m in kept])
            print(f"{'frozen ' + family:22s} {a:6.2f} {len(kept):8d} {d.min():9.3g}-{d.max():<9.3g} "
                  f"{d.min() / afm:7.2f}-{d.max() / afm:<7.2f}  {law.min():6.3f}-{law.max():<6.3f}")
    for regime in ("AFM", "CP", "FM"):
        same = [m for m in members if m.ring == "clean" and m.label.startswith(f"{regime}:2SL:") and not invariant(m)
                and ("clean", regime, m.A) in reduction]
        if same:
            deviation = np.abs([m.friction / reduction[("clean", regime, m.A)] - 1 for m in same])
            print(f"{regime + ' 2SL':22s} {'all':>6s} {len(same):8d}   relative deviation from the reduction: "
                  f"median {np.median(deviation):.1e}, 90 % below {np.quantile(deviation, 0.9):.1e}, "
                  f"largest {np.max(deviation):.1e}")
    for ring in ("clean", "disordered"):
        slipping = [m for m in members if m.ring == ring and m.outcome == "slipping walls" and m.slipping_rows > 0]
        if slipping:
            per_row = np.array([m.friction * m.rows / m.slipping_rows for m in slipping])
            A = np.array([m.A for m in slipping])
            ratio = np.array([m.friction / reduction.get((ring, "AFM", m.A), np.nan) for m in slipping])
            print(f"{'slipping walls, ' + ring:22s} {A.min():.2f}-{A.max():.2f} {len(slipping):5d}   "
                  f"D per slipping row {per_row.min():.2f}-{per_row.max():.2f}, D/N / reduction AFM "
                  f"{np.nanmin(ratio, initial=np.inf):.0f}-{np.nanmax(ratio, initial=0):.0f}")


RANDOM_CLASSES = ("2SL", "frozen repeating", "frozen non-repeating", "slipping walls", "other")


def random_class(m):
    """The outcome of a random start, its two-sublattice states in one class."""
    return "2SL" if m.outcome.endswith("2SL") else m.outcome


def quoted_A(grid):
    """The A values of BASIN_A that the grid's random starts ran at (all of them where it has none)."""
    return [a for a in BASIN_A if a in grid["random_A"]] or grid["random_A"]


def basin_fractions(members, ring, rows, A):
    """{class: (count, n)} of the random starts at (ring, N, A)."""
    own = [m for m in members if m.start == "random" and m.ring == ring and m.rows == rows and m.A == A]
    return {c: (sum(random_class(m) == c for m in own), len(own)) for c in RANDOM_CLASSES}


def basin_table(members, grid):
    """Random starts on a few N at the quoted A: the fraction per final state with its Wilson interval."""
    print("\nrandom starts: fraction per final state, Wilson 95 % interval in brackets")
    print(f"{'ring':10s} {'N':>3s} {'A':>5s} " + " ".join(f"{c:>22s}" for c in RANDOM_CLASSES[:4]))
    for ring in ("clean", "disordered"):
        for rows in [n for n in grid["rows"] if n in (6, 8, 12, 24) or len(grid["rows"]) < 6]:
            for a in quoted_A(grid):
                cells = []
                for c in RANDOM_CLASSES[:4]:
                    count, n = basin_fractions(members, ring, rows, a)[c]
                    low, high = wilson(count, n)
                    cells.append(f"{count / n:.3f} [{low:.3f},{high:.3f}]")
                print(f"{ring:10s} {rows:3d} {a:5.2f} " + " ".join(f"{c:>22s}" for c in cells))
    for ring in ("clean", "disordered"):
        above = [m for m in members if m.start == "random" and m.ring == ring and m.A > A_MINUS]
        two_sublattice = sum(random_class(m) == "2SL" for m in above)
        print(f"{ring:10s} all N, A > A_−: 2SL {two_sublattice} of {len(above)}")


def repeating_table(members, grid):
    """Random starts that end frozen in a repeating pattern (primitive period 2 < k < N), per N: count of the N's
    replicas, and the most common such pattern where there is one."""
    print(f"\nrandom starts frozen in a repeating pattern, count of {grid['random_replicas']} per N; most common one")
    print(f"{'ring':10s} {'A':>5s} " + " ".join(f"{n:>4d}" for n in grid["rows"]))
    for ring in ("clean", "disordered"):
        for a in quoted_A(grid):
            counts, common = [], []
            for n in grid["rows"]:
                found = [m.final for m in members if m.start == "random" and m.ring == ring and m.rows == n
                         and m.A == a and m.outcome == "frozen repeating"]
                counts.append(len(found))
                if found:  # ties go to the pattern met first in plan order
                    common.append(f"{n}:{Counter(found).most_common(1)[0][0]}")
            print(f"{ring:10s} {a:5.2f} " + " ".join(f"{c:4d}" for c in counts) + "   " + " ".join(common))


def outcome_counts(members):
    """Every outcome per family and start, one line each: the machine-readable summary."""
    print("\noutcomes (family start ring: outcome=count ...)")
    keys = sorted({(m.family, m.start, m.ring) for m in members})
    for key in keys:
        counts = {}
        for m in members:
            if (m.family, m.start, m.ring) == key:
                counts[m.outcome] = counts.get(m.outcome, 0) + 1
        print(" ".join(key) + ": " + " ".join(f"{k.replace(' ', '_')}={v}" for k, v in sorted(counts.items())))


# ---------------------------------------------------------------- figure


FAMILY_COLOURS = {"FM": "tab:red", "AFM": "tab:blue", "walls": "tab:green", "blocks": "tab:orange"}


def plot_survival(axis, found, members):
    """Fraction of starts that keep their pattern, averaged over each family, against A."""
    for family, colour in FAMILY_COLOURS.items():  # twisted states never keep their pattern
        names = [p.name for p in found if p.family == family]
        if not names:
            continue
        for (ring, start), style in ((("clean", "near"), "-"), (("disordered", "exact"), "--")):
            curves = [survival(members, n, ring, start) for n in names]
            axis.plot(curves[0][0], np.mean([c[1] for c in curves], axis=0), style, color=colour, marker=".",
                      ms=3, label=f"{family} ({len(names)})" if style == "-" else None)
    axis.set_xlabel("A")
    axis.set_ylabel("fraction that keeps its pattern")
    axis.set_title("period-k Ising patterns (solid: near starts, dashed: disordered)", fontsize=9)
    axis.set_xlim(0, 12)
    axis.legend(fontsize=7, title="family (patterns)", title_fontsize=7)


def plot_friction(axis, rotorsweep, members, reduction, J_points):
    """D/N of the exact starts' attractors against the clean reduction's branches (broken where a branch is absent)
    and J(A) on J_points points."""
    A = np.array(sorted({a for ring, _, a in reduction if ring == "clean"}))
    for regime, colour in (("AFM", "tab:blue"), ("CP", "black"), ("FM", "tab:red")):
        d = np.array([reduction.get(("clean", regime, a), np.nan) for a in A])
        axis.plot(A, d, color=colour, lw=1.5, zorder=3, label=f"reduction (N = 2): {regime}")
    fine = np.linspace(4.5, 9.0, J_points)
    J, _ = rotorsweep.quasi_static_friction(fine)
    axis.plot(fine[J > 0], J[J > 0], "k--", lw=1, zorder=3, label="J(A), g → 0")
    styles = (("kept", "o", None, "frozen in its own pattern"), ("frozen repeating", "s", "grey", "frozen in another"),
              ("frozen non-repeating", "s", "grey", None), ("slipping walls", "^", "tab:brown", "slipping walls"))
    for name, marker, colour, label in styles:
        own = [m for m in members if m.outcome == name and m.start == "exact" and m.family in ("walls", "blocks")]
        if own:
            axis.scatter([m.A for m in own], [m.friction for m in own], s=6, marker=marker, alpha=0.5, label=label,
                         c=[FAMILY_COLOURS[m.family] for m in own] if colour is None else colour)
    axis.set_yscale("log")
    axis.set_xlabel("A")
    axis.set_ylabel("D / N per period (ε)")
    axis.set_title(f"friction of the attractors of walls and blocks (exact starts), g = {G}", fontsize=9)
    axis.legend(fontsize=7, loc="lower right")


def plot_basins(axis, members, grid, rows):
    """Random starts on N = rows: fraction per final state against A, Wilson bands; solid clean, dashed disordered."""
    colours = dict(zip(RANDOM_CLASSES, ("tab:blue", "tab:orange", "tab:green", "tab:brown", "grey")))
    A = np.array(grid["random_A"])
    for ring, style in (("clean", "-"), ("disordered", "--")):
        for c in RANDOM_CLASSES[:4]:
            counts = [basin_fractions(members, ring, rows, a)[c] for a in A]
            fraction = np.array([k / n for k, n in counts])
            band = np.array([wilson(k, n) for k, n in counts])
            axis.plot(A, fraction, style, color=colours[c], label=c if ring == "clean" else None)
            axis.fill_between(A, band[:, 0], band[:, 1], color=colours[c], alpha=0.15, lw=0)
    axis.set_xlabel("A")
    axis.set_ylabel("fraction of random starts")
    axis.set_title(f"random starts, N = {rows} (solid: clean, dashed: σ_A = {DISORDER:g})", fontsize=9)
    axis.legend(fontsize=7)


def plot_repeating(axis, members, grid):
    """Fraction of random starts ending in a repeating structured state (2 < k < N), against N."""
    for a, colour in zip(quoted_A(grid), ("tab:blue", "tab:orange", "tab:green", "tab:red")):
        for ring, marker in (("clean", "o"), ("disordered", "x")):
            counts = [basin_fractions(members, ring, n, a)["frozen repeating"] for n in grid["rows"]]
            fraction = np.array([k / n for k, n in counts])
            band = np.array([wilson(k, n) for k, n in counts])
            axis.errorbar(grid["rows"], fraction, yerr=[fraction - band[:, 0], band[:, 1] - fraction], fmt=marker,
                          color=colour, ms=4, capsize=2, label=f"A = {a:g}" if ring == "clean" else None)
    axis.set_xlabel("N")
    axis.set_ylabel("fraction in a repeating state, 2 < k < N")
    axis.set_title("random starts reaching a commensurate structured state (o clean, x disordered)", fontsize=9)
    axis.legend(fontsize=7)


def main():
    args, rotorsweep = study_command_line.parse(__doc__, "commensurate_states.png", "a few patterns and rings (the test suite's run)")

    grid = QUICK if args.quick else FULL
    reduction = run_reduction(rotorsweep, sorted(set(grid["A"]) | set(grid["random_A"]) | set(REDUCTION_A)),
                              args.threads, grid["disorder_replicas"], grid["numerics"])
    found, members = run_patterns(rotorsweep, grid, args.threads)
    members += run_random(rotorsweep, grid, args.threads)
    wall_motion(rotorsweep, max(grid["rows"]), args.threads, grid["wall_periods"], grid["numerics"])

    survival_table(found, members)
    friction_table(members, reduction)
    basin_table(members, grid)
    repeating_table(members, grid)
    outcome_counts(members)

    figure, axes = plt.subplots(2, 2, figsize=(11, 8))
    plot_survival(axes[0, 0], found, members)
    plot_friction(axes[0, 1], rotorsweep, members, reduction, grid["J_points"])
    plot_basins(axes[1, 0], members, grid, max(grid["rows"]))
    plot_repeating(axes[1, 1], members, grid)
    study_command_line.save(figure, args.out, 90)


if __name__ == "__main__":
    main()
