"""scripts/plot_robustness.py: the figure is written, and with --bisect each transition lies inside
the grid bracket the crossing of 1/2 was found in, located to the tolerance, with the CP fraction on
either side of the final bracket on either side of 1/2; random starts are one curve, without η; sizes are
never one line."""

import pathlib
import re
import subprocess
import sys
import tomllib

from conftest import run_cli

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "scripts" / "plot_robustness.py"
sys.path.insert(0, str(ROOT / "scripts"))
import plot_robustness  # noqa: E402

SCENE = """
[model]
rows = 20
[drive]
g = [0.0011]
[sweep]
A = { from = 3.5, to = 5.5, count = 5 }
[initial]
kinds = ["AFM"]
noise = [0.01]
replicas = 2
[schedule]
relax_periods = 2
average_periods = 2
"""


def test_bisection_locates_the_transition_inside_its_grid_bracket(tmp_path, executable):
    (tmp_path / "robust.toml").write_text(SCENE)
    result = run_cli(executable, tmp_path / "robust.toml", tmp_path / "robust.h5")
    png = tmp_path / "robust.png"
    done = subprocess.run([sys.executable, str(SCRIPT), str(result), str(png), "--bisect", "--tolerance", "0.01"],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert png.stat().st_size > 10000
    found = re.findall(r"at A = ([0-9.]+) \(bisected to \[([0-9.]+), ([0-9.]+)\]\)", done.stdout)
    assert len(found) == 1, done.stdout  # the AFM-CP transition between A = 4.5 and 5
    x, low, high = (float(v) for v in found[0])
    assert 4.5 <= low < x < high <= 5.0
    assert high - low <= 0.01
    scene = tomllib.loads(SCENE)
    curve = ("AFM", 0.01, 0.0, 20, 0.0011, 1e-6)
    below = plot_robustness.cp_fraction(scene, low, *curve)
    above = plot_robustness.cp_fraction(scene, high, *curve)
    assert (below - 0.5) * (above - 0.5) < 0


RAGGED = """
[model]
rows = 6
[drive]
g = [0.01]
[sweep]
A = [2.0, 6.0, 11.0]
[initial]
kinds = ["random", "AFM"]
noise = [0.01, 0.3]
replicas = 2
[schedule]
relax_periods = 1
average_periods = 1
"""


def test_random_starts_are_one_curve_without_a_noise_axis(tmp_path, executable):
    (tmp_path / "ragged.toml").write_text(RAGGED)
    result = run_cli(executable, tmp_path / "ragged.toml", tmp_path / "ragged.h5")
    done = subprocess.run([sys.executable, str(SCRIPT), str(result), str(tmp_path / "ragged.png")],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    transitions = [line.split(":")[0] for line in done.stdout.splitlines() if "crosses" in line]
    assert any(t.startswith("AFM η = 0.3") for t in transitions), done.stdout
    assert {t for t in transitions if t.startswith("random")} == {"random"}, done.stdout


def test_each_size_is_a_line_of_its_own(tmp_path, executable):
    (tmp_path / "sizes.toml").write_text(RAGGED.replace("rows = 6", "rows = [4, 6]"))
    result = run_cli(executable, tmp_path / "sizes.toml", tmp_path / "sizes.h5")
    done = subprocess.run([sys.executable, str(SCRIPT), str(result), str(tmp_path / "sizes.png")],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    transitions = {line.split(":")[0] for line in done.stdout.splitlines() if "crosses" in line}
    assert transitions and all(", N = " in t or t.startswith("random N = ") for t in transitions), done.stdout
