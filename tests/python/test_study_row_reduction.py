"""scripts/studies/row_reduction.py: the quick run draws its figure and prints tables that parse, the inertial and the
overdamped 7 × 7 slider agree (I/γ = 0.3 ms against a 2 s period), rows stay uniform where nothing slips, and the CP
window lies inside the scan; the study's row model is the array with uniform rows (its coupling table against the
array's pair sum); the helpers' spreads, slips, regimes, gaps and fits against hand-made series."""

import pathlib
import re
import subprocess
import sys

import numpy as np
from conftest import run_study_quick

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "scripts" / "studies" / "row_reduction.py"
sys.path.insert(0, str(SCRIPT.parent))
import row_reduction as study  # noqa: E402

NUMBER = r"[-+]?[0-9.]+(?:e[-+]?[0-9]+)?"


def table(out, title):
    """The lines of the table under the heading that starts with `title` (up to the next blank line)."""
    return out.split(title, 1)[1].split("\n\n", 1)[0].splitlines()[2:]


def test_quick_run_prints_tables_that_parse(tmp_path):
    out = run_study_quick(SCRIPT, tmp_path)

    friction = {int(line.split()[0]): [float(x) for x in re.findall(NUMBER, line)[1:]]
                for line in table(out, "friction per rotor f =") if re.match(r"^ +\d+ ", line)}
    assert sorted(friction) == list(study.QUICK["sizes"]), out
    for size, (g, peak, h, *models) in friction.items():
        assert abs(g - 0.154) < 1e-3 and peak > 1 and h in study.QUICK["h"]
        field_ratio, paper_ratio = models[2], models[7]
        assert 0.5 < field_ratio < 2 and 0.5 < paper_ratio < 2, out  # the row model's peak has the array's size

    inertia = float(re.search(rf"largest relative difference ({NUMBER})", out).group(1))
    assert inertia < 0.02, out  # inertia acts for 0.3 ms only: the overdamped array is the experiment's

    uniform = [line.split() for line in table(out, "row uniformity") if re.match(r"^ +\d+ +AFM ", line)]
    assert uniform and all(float(cells[3]) < 0.2 for cells in uniform), out  # AFM rows: spread below 0.2 rad

    windows = {int(line.split()[0]): line.split()[2] for line in table(out, "regimes in h") if re.match(r"^ +\d+ ", line)}
    for size, cp in windows.items():
        lo, hi = (float(x) for x in cp.split("-"))
        assert study.QUICK["h"][0] < lo <= hi < study.QUICK["h"][-1], out


def test_the_row_model_is_the_array_with_uniform_rows(executable):
    """The study's row model (N open rows of N rotors, every row coupled) has, for any uniform rows, the array's pair
    energy per rotor (docs/model.md §9: P = (1 − 3 d_x²/d²)/d³, Q = 1/d³) up to a constant."""
    size = 6
    printed = subprocess.run([executable, "couplings", "--range", str(size - 1), "--row-length", str(size)],
                             check=True, capture_output=True, text=True).stdout
    a = float(re.search(rf"^a = ({NUMBER})$", printed, re.M).group(1))
    b, c = np.array([[float(x) for x in line.split()[1:]]
                     for line in printed.splitlines() if re.match(r"^ +\d+ ", line)]).T
    assert len(b) == size - 1
    column, row = (x.ravel() for x in np.meshgrid(np.arange(size), np.arange(size)))
    dx, dy = column[:, None] - column[None, :], row[:, None] - row[None, :]
    d2 = np.where(dx ** 2 + dy ** 2 > 0, dx ** 2 + dy ** 2, 1.0)
    P = np.where(dx ** 2 + dy ** 2 > 0, (1 - 3 * dx ** 2 / d2) / d2 ** 1.5, 0.0)
    Q = np.where(dx ** 2 + dy ** 2 > 0, 1 / d2 ** 1.5, 0.0)
    differences = []
    for theta in np.random.default_rng(3).uniform(0, 2 * np.pi, (4, size)):
        rows = -a * np.cos(2 * theta).sum() + sum(
            b[u - 1] * np.cos(theta[j] - theta[j + u]) - c[u - 1] * np.cos(theta[j] + theta[j + u])
            for j in range(size) for u in range(1, size - j))
        t = theta[row]
        pairs = 0.5 * (np.cos(t) @ P @ np.cos(t) + np.sin(t) @ Q @ np.sin(t))
        differences.append(rows - pairs / size)
    assert np.ptp(differences) < 1e-8, differences  # the table is printed to 10 decimals; the sums agree to that


def test_spreads_and_deviations_wrap_around():
    size = 3
    angles = np.array([[np.pi - 0.1, -np.pi + 0.1, np.pi,    # row 0 around π: spread 0.2, not 2π − 0.2
                        0.0, 0.3, -0.3,                       # row 1: spread 0.6
                        1.0, 1.0, 1.0]])                      # row 2: uniform
    deviation = study.row_deviations(angles, size)
    assert np.allclose(deviation[0, 0], [-0.1, 0.1, 0.0]) and np.allclose(deviation[0, 1], [0.0, 0.3, -0.3])
    u = study.uniformity(angles[None], size)  # one separation, one sample
    assert np.allclose(u["mean"], [[0.2, 0.6, 0.0]]) and np.allclose(u["max"], u["mean"])
    edge, bulk = study.edge_and_bulk(u["mean"][0])
    assert np.isclose(edge, 0.1) and np.isclose(bulk, 0.6)


def test_slips_and_regimes_from_samples():
    size, periods = 2, 2
    samples = periods * study.SAMPLES + 1
    drive = np.linspace(0, periods * 2 * np.pi, samples)
    following = np.repeat(drive[None, :, None], size * size, axis=2)            # every rotor turns with the drive
    jumping = following.copy()
    jumping[:, 10:, 3] += 2.0                                                     # rotor 3 jumps once in period 1 …
    jumping[:, 60:, 3] += 2.0                                                     # … and once in period 2
    once = following.copy()
    once[:, 10:, 0] += 2.0                                                        # one slip, first period only
    angles = np.concatenate([following, jumping, once])
    per_period = study.slips(angles, size)
    assert per_period.shape == (3, periods, size, size)
    assert per_period[0].sum() == 0 and per_period[1, :, 1, 1].tolist() == [1, 1] and per_period[1].sum() == 2
    order = np.ones((3, samples))
    regimes = study.array_regimes({"size": size, "angles": angles, "order_y": order})
    assert regimes.tolist() == ["FM", "CP", "unsettled"]
    calm = {"size": size, "angles": following[[0, 0]], "order_y": np.stack([-np.ones(samples), np.cos(drive)])}
    assert study.array_regimes(calm).tolist() == ["AFM", "unsettled"]
    assert study.switching({"size": 3, "order_y": np.stack([np.full(samples, -1.0), np.cos(drive)])}).tolist() == [
        False, True]


def test_gaps_and_fits():
    h = np.linspace(5.0, 13.0, 33)
    rows = np.exp(-((h - 8.0) ** 2))
    r = study.gaps(h, 1.25 * rows, rows)
    assert np.isclose(r["l1"], 0.25) and np.isclose(r["area"], 1.25) and np.isclose(r["peak"], 1.25)
    assert r["h_array"] == r["h_rows"] == 8.0
    N = np.array([4, 8, 16, 32])
    c, p = study.power_law(N, 3.0 * N ** -0.75)
    assert np.isclose(c, 3.0) and np.isclose(p, 0.75)
    limit, slope = study.in_inverse_size(N, np.column_stack([2.0 + 5.0 / N, -1.0 + 0.5 / N]))
    assert np.allclose(limit, [2.0, -1.0]) and np.allclose(slope, [5.0, 0.5])
    arrays = {n: {"h": np.array([8.0, 8.5, 9.0] if n == 12 else [8.0, 8.25, 8.5, 8.75, 9.0])} for n in (4, 6, 8, 12)}
    curves = {n: 7.0 - 4.0 / n + arrays[n]["h"] for n in arrays}
    sizes, h, f, residuals = study.large_size_limit(arrays, curves)
    assert sizes == [6, 8, 12] and h.tolist() == [8.0, 8.5, 9.0] and np.allclose(f, 7.0 + h)  # on the common h
    assert residuals.shape == (3, 3) and np.allclose(residuals, 0.0, atol=1e-12)  # the law is exact here
    curves[4] = curves[4] + 0.1  # off the law: a fit over 4, 6, 8, 12 leaves residuals
    assert np.abs(study.large_size_limit(arrays, curves, count=4)[3]).max() > 0.01
    series = 2.0 + 3.0 * np.cos(2 * np.pi * np.arange(4 * study.SAMPLES + 1) / study.SAMPLES) \
        + 0.5 * np.sin(4 * np.pi * np.arange(4 * study.SAMPLES + 1) / study.SAMPLES)
    c = study.harmonics(series[None])[0]
    assert np.allclose(c / (2 * study.SAMPLES), [3.0, 0.5, 0.0], atol=1e-12)  # rfft's |c_k| over 4 periods: 4·50·amp/2
