"""scripts/plot_slider.py on a small slider scan and the row model of it (docs/slider.md "The experiment's
slider"): the figure is written, and a file of another kind is refused with a clear message."""

import pathlib
import subprocess
import sys

from conftest import run_cli

SCRIPT = pathlib.Path(__file__).resolve().parents[2] / "scripts" / "plot_slider.py"

#: a 3 × 2 slider over 9 × 9 magnets
SMALL = """
[slider]
columns = 3
rows = 2
[substrate]
columns = 9
rows = 9
"""

SLIDER = SMALL + """
[drive]
rest = 0.5
end = 2.5
[sweep]
separation = { from = 6e-3, to = 10e-3, count = 5 }
[initial]
replicas = 2
"""

ROWS = """
[model]
rows = 2
couplings = "dipolar"
range = "all"
row_length = 3
boundary = "open"
[drive]
g = [0.154]
[sweep]
A = { from = 0.5, to = 25.0, count = 12, spacing = "log" }
[initial]
kinds = ["AFM"]
[schedule]
relax_periods = 1
average_periods = 1
"""


def test_plot_slider_with_the_row_model(tmp_path, executable):
    (tmp_path / "slider.toml").write_text(SLIDER)
    slider = tmp_path / "slider.h5"
    completed = subprocess.run([executable, "slider", str(tmp_path / "slider.toml"), "-o", str(slider), "-q"],
                               capture_output=True, text=True)
    assert completed.returncode == 0, completed.stderr
    (tmp_path / "rows.toml").write_text(ROWS)
    rows = run_cli(executable, tmp_path / "rows.toml", tmp_path / "rows.h5")
    png = tmp_path / "slider.png"
    done = subprocess.run([sys.executable, str(SCRIPT), str(slider), str(png), "--rows", str(rows)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert png.stat().st_size > 10000


def test_plot_slider_refuses_a_row_model_file_of_several_curves(tmp_path, executable):
    (tmp_path / "slider.toml").write_text(SLIDER)
    slider = tmp_path / "slider.h5"
    subprocess.run([executable, "slider", str(tmp_path / "slider.toml"), "-o", str(slider), "-q"], check=True)
    (tmp_path / "rows.toml").write_text(ROWS.replace("g = [0.154]", "g = [0.154, 0.3]"))
    rows = run_cli(executable, tmp_path / "rows.toml", tmp_path / "rows.h5")
    done = subprocess.run([sys.executable, str(SCRIPT), str(slider), str(tmp_path / "x.png"), "--rows", str(rows)],
                          capture_output=True, text=True)
    assert done.returncode != 0 and "holds several row-model curves (g 0.154, 0.3)" in done.stderr, done.stderr
    assert not (tmp_path / "x.png").exists()


def test_plot_slider_refuses_a_row_model_file(tmp_path, executable):
    (tmp_path / "rows.toml").write_text(ROWS)
    rows = run_cli(executable, tmp_path / "rows.toml", tmp_path / "rows.h5")
    done = subprocess.run([sys.executable, str(SCRIPT), str(rows), str(tmp_path / "x.png")],
                          capture_output=True, text=True)
    assert done.returncode != 0
    assert "is not a slider result" in done.stderr


VELOCITY = SMALL + """
[drive]
rest = 0.2
periods = 2
speed = { from = 2e-3, to = 32e-3, count = 5, spacing = "log" }
[sweep]
separation = [6e-3, 10e-3]
[observables]
series = false
"""


def test_plot_slider_velocity_draws_friction_against_speed(tmp_path, executable):
    (tmp_path / "velocity.toml").write_text(VELOCITY)
    result = tmp_path / "velocity.h5"
    completed = subprocess.run([executable, "slider", str(tmp_path / "velocity.toml"), "-o", str(result), "-q"],
                               capture_output=True, text=True)
    assert completed.returncode == 0, completed.stderr
    png = tmp_path / "velocity.png"
    done = subprocess.run([sys.executable, str(SCRIPT), str(result), str(png), "--velocity", "--separations", "10"],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert png.stat().st_size > 10000
    refused = subprocess.run([sys.executable, str(SCRIPT), str(result), str(png)], capture_output=True, text=True)
    assert refused.returncode != 0 and "--velocity" in refused.stderr
    wrong = subprocess.run([sys.executable, str(SCRIPT), str(result), str(png), "--velocity", "--separations", "7"],
                           capture_output=True, text=True)
    assert wrong.returncode != 0 and "not in" in wrong.stderr
