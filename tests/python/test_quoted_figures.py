"""scripts/quoted_figures.py: every number README.md and docs/ quote for the examples is what a run of
them gives, and a quoted number that drifts is named."""

import pathlib
import shutil
import subprocess
import sys

SCRIPT = pathlib.Path(__file__).resolve().parents[2] / "scripts" / "quoted_figures.py"
ROOT = SCRIPT.parents[1]


def check(executable, *arguments):
    return subprocess.run([sys.executable, str(SCRIPT), "--check", "--rotorsweep", executable, *arguments],
                          capture_output=True, text=True, timeout=300)


def test_every_quoted_number_is_what_the_runs_give(executable):
    done = check(executable)
    assert done.returncode == 0, done.stdout + done.stderr


def test_a_number_that_drifts_is_named(executable, tmp_path):
    shutil.copy(ROOT / "README.md", tmp_path / "README.md")
    shutil.copytree(ROOT / "docs", tmp_path / "docs")
    readme = tmp_path / "README.md"
    text = readme.read_text()
    quoted = "For the demo scene this gives AFM up to A ≈ "
    at = text.index(quoted) + len(quoted)
    readme.write_text(text[:at] + "9" + text[at + 1:])  # 4.6 becomes 9.6
    done = check(executable, "--only", "demo", "--docs", str(tmp_path))
    assert done.returncode == 1
    assert "README.md: quoted '9.6', the run gives '4.6'" in done.stdout
