"""scripts/quoted_figures.py: every number README.md and docs/ quote for the examples is what a run of
them gives, and a quoted number that drifts is named (one check of a copy of the docs with one number
drifted: the examples run once)."""

import pathlib
import shutil
import subprocess
import sys

SCRIPT = pathlib.Path(__file__).resolve().parents[2] / "scripts" / "quoted_figures.py"
ROOT = SCRIPT.parents[1]


def check(executable, *arguments):
    return subprocess.run([sys.executable, str(SCRIPT), "--check", "--rotorsweep", executable, *arguments],
                          capture_output=True, text=True, timeout=300)


def test_every_quoted_number_is_what_the_runs_give_and_one_that_drifts_is_named(executable, tmp_path):
    shutil.copy(ROOT / "README.md", tmp_path / "README.md")
    shutil.copytree(ROOT / "docs", tmp_path / "docs")
    readme = tmp_path / "README.md"
    text = readme.read_text()
    quoted = "For the demo scene this gives AFM up to A ≈ "
    at = text.index(quoted) + len(quoted)
    number = text[at:].split(",", 1)[0]
    assert number[0] != "9", number
    readme.write_text(text[:at] + "9" + text[at + 1:])  # 4.6 becomes 9.6
    done = check(executable, "--docs", str(tmp_path))
    assert done.returncode == 1, done.stdout + done.stderr
    # the drifted number is named beside what the run gives, which the project's README quotes, and it is
    # the only one: every other number quoted in the copy, the project's own, is what the runs give
    assert f"README.md: quoted '9{number[1:]}', the run gives '{number}'" in done.stdout, done.stdout
    assert done.stdout.splitlines()[-1] == "1 quoted numbers differ", done.stdout
