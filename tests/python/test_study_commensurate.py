"""scripts/studies/commensurate_states.py: the quick run draws its figure and prints tables that parse, each basin
fraction inside its Wilson interval; exact AFM and FM starts keep their pattern where it is the only attractor and
a period-3 pattern of walls stays frozen at small A and falls into the AFM state above its end; the script's Wilson
interval is the one /curves/attractors writes."""

import pathlib
import re
import sys

import numpy as np
from conftest import run_study_quick
import rotorsweep

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "scripts" / "studies" / "commensurate_states.py"
sys.path.insert(0, str(SCRIPT.parent))
import commensurate_states as study  # noqa: E402

CELL = re.compile(r"([0-9.]+) \[([0-9.]+),([0-9.]+)\]")


def test_quick_run_draws_the_figure_and_prints_tables_that_parse(tmp_path):
    stdout = run_study_quick(SCRIPT, tmp_path)

    survival = {(line[:8].strip(), line[18:35].strip()): line[35:].split()[0]
                for line in stdout.splitlines() if re.match(r"^(FM|AFM|walls|blocks|twisted) +\d+ ", line)}
    for start in ("exact clean", "near clean", "exact disordered"):
        assert survival[("AFM", start)] == "1-4", stdout  # AFM kept up to A = 4, lost to CP at 6
        assert survival[("twisted", start)] == "none", stdout  # no twisted state is a stationary pattern

    basins = [line for line in stdout.splitlines() if re.match(r"^(clean|disordered) +\d+ +[0-9.]+ ", line)]
    assert len(basins) >= 2 * len(study.QUICK["rows"])  # both rings, every N, at least one A
    for line in basins:
        cells = [tuple(float(x) for x in cell) for cell in CELL.findall(line)]
        assert len(cells) == 4, line
        assert all(low <= fraction <= high for fraction, low, high in cells), line
        assert sum(fraction for fraction, _, _ in cells) <= 1 + 1e-9, line

    # exact AFM starts (A = 1 … 11) keep AFM, or end in the CP or FM two-sublattice state: nothing else
    outcomes = dict(line.split(": ", 1) for line in stdout.splitlines() if " exact clean: " in line)
    counts = dict(pair.split("=") for pair in outcomes["AFM exact clean"].split())
    assert set(counts) == {"kept", "CP_2SL", "FM_2SL"}, outcomes["AFM exact clean"]


def exact_members(bits, rows, A):
    """Member records of exact starts from an Ising pattern in clean rings."""
    pattern = study.ising_pattern(tuple(bits))
    m = study.sweep(rotorsweep, rows, A, {"kinds": ["exact"], "angles": list(pattern.angles)}, 2)
    return study.collect(m, pattern, "clean", "exact", np.array(bits))


def test_exact_starts_keep_ferro_and_antiferromagnetic_order_where_it_is_the_only_attractor():
    afm = {(m.rows, m.A): m.outcome for m in exact_members((0, 1), [2, 6], [1.0, 11.0])}
    assert afm == {(2, 1.0): "kept", (6, 1.0): "kept", (2, 11.0): "FM 2SL", (6, 11.0): "FM 2SL"}
    fm = {(m.rows, m.A): m.outcome for m in exact_members((0,), [2, 6], [11.0])}
    assert fm == {(2, 11.0): "kept", (6, 11.0): "kept"}


def test_walls_stay_frozen_at_small_A_and_fall_into_the_AFM_state_above_their_end():
    walls = {m.A: (m.outcome, m.friction) for m in exact_members((0, 0, 1), [6], [1.0, 4.0])}
    assert walls[1.0][0] == "kept"
    assert walls[4.0][0] == "AFM 2SL"
    # a frozen pattern's friction is its order-A² linear response to within the A² corrections
    assert abs(walls[1.0][1] / study.linear_friction((0, 0, 1), 6, 1.0) - 1) < 0.1


def test_wilson_intervals_are_those_of_the_attractor_table():
    ds = rotorsweep.run({"model": {"rows": 8}, "drive": {"g": [0.0011]}, "sweep": {"A": [1.0]},
                         "initial": {"kinds": ["random"], "replicas": 30}}, threads=1, progress=False, quiet=True)
    n = int(ds.curve_members.values.reshape(-1)[0])
    table = (ds[f"curve_attractor_{name}"].values.reshape(-1) for name in ("count", "low", "high"))
    for count, low, high in zip(*table):
        assert np.allclose(study.wilson(int(count), n), (low, high), rtol=0, atol=1e-12)
