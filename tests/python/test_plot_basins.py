"""scripts/plot_basins.py: each regime's fraction is drawn at its own value with its Wilson 95 % interval
around it (read back from /curves), and the legend stands beside the panels."""

import importlib.util
import pathlib

import h5py
import numpy as np

from conftest import run_cli

SCRIPT = pathlib.Path(__file__).resolve().parents[2] / "scripts" / "plot_basins.py"

SCENE = """
[model]
rows = 6
[drive]
g = [0.01]
[sweep]
A = [1.0, 6.0, 11.0]
[initial]
kinds = ["random"]
replicas = 6
[schedule]
relax_periods = 1
average_periods = 1
"""


def test_each_fraction_and_its_interval_at_its_own_value(tmp_path, executable):
    scene = tmp_path / "basins.toml"
    scene.write_text(SCENE)
    result = run_cli(executable, scene, tmp_path / "basins.h5")
    spec = importlib.util.spec_from_file_location("plot_basins", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    fig = module.figure(str(result), "random")
    ax = fig.axes[0]
    with h5py.File(result) as f:
        c = f["curves"]
        order = np.argsort(c["A"][:])
        curves = {name: (c[f"fraction_{name}"][:][order], c[f"fraction_{name}_low"][:][order],
                         c[f"fraction_{name}_high"][:][order]) for name in ("AFM", "CP", "FM", "unsettled")}
    drawn = {container.get_label(): container for container in ax.containers}
    checked = 0
    for name, (fraction, low, high) in curves.items():
        if not fraction.any():
            continue
        line, _, (bars,) = drawn[name]
        np.testing.assert_array_equal(line.get_ydata(), fraction)
        for segment, lo, hi in zip(bars.get_segments(), low, high):
            assert np.isclose(segment[0][1], lo, atol=1e-15) and np.isclose(segment[1][1], hi, atol=1e-15)
        checked += 1
    assert checked >= 2
    fig.canvas.draw()
    assert ax.get_legend().get_window_extent().x0 >= ax.get_window_extent().x1  # beside the panel


def test_sizes_are_never_mixed_in_one_line(tmp_path, executable):
    """A file over N = 4 and 6: a panel each, every fraction the curve point's of its own N."""
    scene = tmp_path / "two.toml"
    scene.write_text(SCENE.replace("rows = 6", "rows = [4, 6]").replace("replicas = 6", "replicas = 2"))
    result = run_cli(executable, scene, tmp_path / "two.h5")
    spec = importlib.util.spec_from_file_location("plot_basins", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    fig = module.figure(str(result), "random")
    titles = [ax.get_title() for ax in fig.axes]
    assert [title.split(", ")[:2] for title in titles] == [["random starts", "N = 4"], ["random starts", "N = 6"]]
    with h5py.File(result) as f:
        c = f["curves"]
        rows, A = c["rows"][:], c["A"][:]
        fractions = {name: c[f"fraction_{name}"][:] for name in ("AFM", "CP", "FM", "unsettled")}
    for ax, size in zip(fig.axes, (4, 6)):
        own = rows == size
        for container in ax.containers:
            line = container[0]
            expected = fractions[container.get_label()][own][np.argsort(A[own])]
            np.testing.assert_array_equal(line.get_ydata(), expected)
