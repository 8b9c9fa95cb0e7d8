"""scripts/plot_friction.py: the line through each curve is the mean over its settled members only, error
bars stand where dissipation_error is a bound, symmetry-limited members are drawn apart, and the legend
stands beside the axes, clear of the data."""

import importlib.util
import pathlib

import numpy as np

from conftest import run_cli

SCRIPT = pathlib.Path(__file__).resolve().parents[2] / "scripts" / "plot_friction.py"


def plot_friction():
    spec = importlib.util.spec_from_file_location("plot_friction", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_line_is_the_mean_over_settled_members_only():
    module = plot_friction()
    A = np.array([1.0, 1.0, 1.0, 2.0, 2.0])
    d = np.array([1.0, 3.0, 100.0, 5.0, 7.0])
    curve = np.array(["a"] * 5)
    settled = np.array([True, True, False, False, False])
    values, mean = module.settled_means(A, d, curve, settled)["a"]
    assert list(values) == [1.0, 2.0]
    assert mean[0] == 2.0 and np.isnan(mean[1])  # no settled member at A = 2: no point


def test_the_figure_marks_the_flags_and_keeps_its_legend_beside_the_data(small_scene, tmp_path, executable):
    scene = tmp_path / "small.toml"
    scene.write_text(small_scene)  # A = 1 (AFM), 6 (CP, symmetry-limited), 11 (FM)
    result = run_cli(executable, scene, tmp_path / "small.h5")
    fig = plot_friction().figure(str(result), jump=False)
    ax = fig.axes[0]
    labels = [text.get_text() for text in ax.get_legend().get_texts()]
    assert any("mean over settled members" in label for label in labels)
    assert any(label.startswith("symmetry-limited: no error bound") for label in labels)
    assert any(label.startswith("dissipation_error / N") for label in labels)
    fig.canvas.draw()
    legend, axes = ax.get_legend().get_window_extent(), ax.get_window_extent()
    assert legend.x0 >= axes.x1  # beside the axes, over no data
    fig.savefig(tmp_path / "friction.png")
    assert (tmp_path / "friction.png").stat().st_size > 10_000
