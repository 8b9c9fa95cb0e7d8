"""scripts/studies/smooth_alternation.py: the quick run draws its figure and prints tables that parse; on the CP side
D/N at the smallest g lies within 10 % of J(A) at A = 6 and 8; inside the window D/N falls with g (exponent near 1 for
σ ≤ 1e-6, and D/N falls with g for σ = 1e-3 too) and D/(N g) grows with log10(1/σ); the escape from the strict-FM saddle
keeps a finite energy at A = 8 and loses it with g at A = 9."""

import pathlib
import re

from conftest import run_study_quick

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "scripts" / "studies" / "smooth_alternation.py"
NUMBER = r"[-+]?[0-9.]+(?:e[-+]?[0-9]+)?"


def run_quick(tmp_path):
    return run_study_quick(SCRIPT, tmp_path)


def table(out, title):
    """The rows of the table whose heading line starts with `title`: the first column → the numbers after it."""
    block = out.split(title, 1)[1].split("\n\n", 1)[0].splitlines()[2:]
    return {float(line.split()[0]): [float(x) for x in re.findall(NUMBER, line)[1:]] for line in block}


def test_quick_run_prints_the_laws_of_both_sides(tmp_path):
    out = run_quick(tmp_path)

    # the σ = 1e-3 friction table: D/N per g (decades 1e-6 … 1e-2), each with its slips per period in brackets
    rows = table(out, "D/N, σ_A = 0.001")
    assert set(rows) == {6.0, 8.0, 8.5, 9.0, 9.25, 9.5, 9.75, 10.0, 10.5}, out
    for A in (9.0, 9.5):
        friction = rows[A][0::2]
        assert len(friction) == 5 and all(a < b for a, b in zip(friction, friction[1:]))  # falls as g falls

    exponents = table(out, "exponent p of D/N")
    for A in (9.0, 9.25, 9.5):
        sigma_1e9, sigma_1e6 = exponents[A][2], exponents[A][3]  # columns σ = 0, 1e-12, 1e-9, 1e-6, 1e-3
        assert 0.85 < sigma_1e9 < 1.1 and 0.85 < sigma_1e6 < 1.1
    assert abs(exponents[6.0][3]) < 0.05  # the CP side keeps a finite friction

    law = table(out, "window: D/(N g)")
    assert set(law) == {9.0, 9.25, 9.5, 9.75}
    assert all(b > 1 for a, b, *rest in law.values())  # grows with log10(1/σ)
    assert law[9.0][1] > law[9.5][1]  # and less so towards A = 10

    cp = table(out, "CP side")
    for A in (6.0, 8.0):
        J, d, ratio = cp[A][:3]
        assert abs(d / J - 1) < 0.1 and abs(ratio - d / J) < 1e-3

    # the escape from the strict-FM saddle (the first slip of the half period): finite energy at A = 8, ∝ g at A = 9
    escape = rf"^(8|9) +1e-06 +{NUMBER} +1 +saddle {NUMBER} +1\.0000 +{NUMBER} +{NUMBER} +({NUMBER}) +(jump|smooth)$"
    escapes = re.findall(escape, out, re.M)
    found = {A: (float(ratio) > 0.5, cls) for A, ratio, cls in escapes}
    assert found == {"8": (True, "jump"), "9": (False, "smooth")}, out
