"""Fixtures of the Python module's tests: the command line beside the module (ctest sets
ROTORSWEEP_EXECUTABLE and PYTHONPATH), small scenes that run in well under a second, and the studies'
quick runs."""

import os
import pathlib
import subprocess
import sys

import h5py
import numpy as np
import pytest

SMALL_SCENE = """
[model]
rows = 8

[drive]
g = [0.0011]

[sweep]
A = [1.0, 6.0, 11.0]

[initial]
kinds = ["FM", "AFM"]
replicas = 2

[schedule]
relax_periods = 1
average_periods = 2
"""


@pytest.fixture
def small_scene():
    return SMALL_SCENE


@pytest.fixture
def executable():
    path = os.environ.get("ROTORSWEEP_EXECUTABLE")
    if not path:
        pytest.skip("ROTORSWEEP_EXECUTABLE is not set (ctest sets it)")
    return path


def python_words(message):
    """A refusal of the command line as the module words it (python/module.cpp: its options as the
    functions' arguments), without the leading "error: "."""
    message = message.strip().removeprefix("error: ")
    for cli, python in (("--force", "force=True"), (" (or --device gpu)", ""),
                        ("run with --device cpu", 'set numerics.device = "cpu"'), ("--threads", "threads"),
                        ("--A-cells", "A_cells"), ("--tau-cells", "tau_cells"), ("--samples", "count")):
        message = message.replace(cli, python)
    return message


def run_cli(executable, scene_path, output):
    completed = subprocess.run([executable, "run", str(scene_path), "-o", str(output), "-q"],
                               capture_output=True, text=True)
    assert completed.returncode == 0, completed.stderr
    return output


def hdf5_datasets(source):
    """{path: (dtype, shape, raw bytes)} of every dataset under /members and /curves."""
    found = {}

    def visit(name, item):
        if isinstance(item, h5py.Dataset) and name.startswith(("members", "curves")):
            values = item[()]
            raw = values.tobytes() if values.dtype.kind != "O" else repr(values.tolist()).encode()
            found[name] = (str(item.dtype), item.shape, raw)

    with h5py.File(source, "r") as h5file:
        h5file.visititems(visit)
    return found


def identical(a, b):
    """Bit for bit equal arrays (NaN equals NaN of the same bits)."""
    a, b = np.asarray(a), np.asarray(b)
    if a.shape != b.shape or a.dtype != b.dtype:
        return False
    if a.dtype.kind == "f":
        return a.tobytes() == b.tobytes()
    return bool(np.all(a == b))


def run_study_quick(script, tmp_path, threads=2):
    """A study's --quick run (scripts/studies/) with this module on `threads`, its figure checked for size; its
    stdout."""
    import rotorsweep

    figure = tmp_path / "figure.png"
    module = pathlib.Path(rotorsweep.__file__).resolve().parents[1]
    done = subprocess.run([sys.executable, str(script), "--quick", "--out", str(figure), "--python", str(module),
                           "--threads", str(threads)], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert 10_000 < figure.stat().st_size < 200_000
    return done.stdout
