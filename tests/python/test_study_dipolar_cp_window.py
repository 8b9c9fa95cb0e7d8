"""scripts/studies/dipolar_cp_window.py: the quick run draws its figure and prints tables that parse; the landscape's
nearest-neighbour window has the h-ratio (A_*/A_−)^{1/3} = 1.237 and every dipolar window is wider in h under both
mappings, in the landscape and in the sweeps at small g; the slider's window lies inside the scan with its sharp AFM-side
edge near 10.1 mm; the paper's mapping of A is h ∝ A^(−1/3) exactly."""

import pathlib
import re
import sys

import numpy as np
from conftest import run_study_quick
import rotorsweep

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "scripts" / "studies" / "dipolar_cp_window.py"
sys.path.insert(0, str(SCRIPT.parent))
import dipolar_cp_window as study  # noqa: E402

COUPLINGS = r"(nearest|M = \d|all)"
WINDOW = r"([0-9.]+)-([0-9.]+)"


def run_quick(tmp_path):
    # one thread: the sweeps of a few members each take as long on two, and the slider's scan as much CPU time
    return run_study_quick(SCRIPT, tmp_path, threads=1)


def test_quick_run_prints_windows_that_parse_and_order_as_found(tmp_path):
    out = run_quick(tmp_path)

    landscape = {}
    for m in re.finditer(rf"^{COUPLINGS} +([0-9. ]+?) +{WINDOW} +([0-9.]+) +{WINDOW} +([0-9.]+) ", out, re.M):
        numbers = [float(x) for x in m.group(2).split()]
        landscape[m.group(1)] = {"ratio": numbers[5], "paper_width": float(m.group(5)), "field_width": float(m.group(8))}
    assert set(landscape) == {name for name, _ in study.REDUCTIONS}, out
    assert f"{landscape['nearest']['ratio']:.3f}" == "1.237"
    assert f"{(rotorsweep.landscape.cp_interval()[1] / rotorsweep.landscape.cp_interval()[0]) ** (1 / 3):.3f}" == "1.237"
    for name, w in landscape.items():
        if name != "nearest":  # dipolar windows are wider, not narrower, in either mapping
            assert w["ratio"] > 1.35
            assert w["paper_width"] > landscape["nearest"]["paper_width"] + 0.5
            assert w["field_width"] > landscape["nearest"]["field_width"] + 0.3

    sweeps = {}
    for m in re.finditer(rf"^(g=0\.001) +{COUPLINGS} +(periodic|open) +{WINDOW} +{WINDOW} +([0-9.]+) ", out, re.M):
        lo, hi = float(m.group(4)), float(m.group(5))
        assert lo < hi
        sweeps[(m.group(2), m.group(3))] = float(m.group(8))  # width in h, paper's mapping
    assert len(sweeps) == 2 * len(study.REDUCTIONS), out
    for boundary in ("periodic", "open"):
        assert all(sweeps[(name, boundary)] > sweeps[("nearest", boundary)] for name, _ in study.REDUCTIONS[1:])

    slider = re.search(rf"^window h = {WINDOW} mm", out, re.M)
    lo, hi = float(slider.group(1)), float(slider.group(2))
    assert 7.0 < lo < 8.0 and 9.9 <= hi <= 10.3, out
    mean_rule = re.search(rf"at h = {WINDOW} mm", out)
    assert lo <= float(mean_rule.group(1)) < float(mean_rule.group(2)) <= hi

    # the coefficient table: c alone widens the window, a and b alone leave it within 0.02 of nearest neighbours'
    ratios = {m.group(1): float(m.group(2)) for m in re.finditer(r"^(none|a|b|c|ab|ac|bc|abc) .* ([0-9.]+)$", out, re.M)}
    assert len(ratios) == 8
    assert ratios["c"] > 1.35 and abs(ratios["a"] - ratios["none"]) < 0.02 and abs(ratios["b"] - ratios["none"]) < 0.02


def test_paper_mapping_is_a_cube_law_and_the_field_mapping_inverts_the_scan():
    h = np.linspace(5.0, 13.0, 9)
    curve = {"h_mm": h, "A_paper": 36.0 * (5.0 / h) ** 3, "A_field": 23.0 * np.exp(-(h - 5.0) / 2.5)}
    mapping = study.Mapping(curve)
    assert np.allclose(mapping.paper(curve["A_paper"]), h, rtol=1e-12)
    assert np.allclose(mapping.field(curve["A_field"]), h, rtol=1e-12)
    assert np.isnan(mapping.field(100.0))  # beyond the scan: no separation
    window = mapping.window(4.5, 9.0)
    assert abs(window["paper"][1] / window["paper"][0] - 2 ** (1 / 3)) < 1e-12  # (A_hi/A_lo)^(1/3)
