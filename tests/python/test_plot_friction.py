"""scripts/plot_friction.py: the line through each curve is the mean over its settled members only, error
bars stand where dissipation_error is a bound, symmetry-limited members are drawn apart, and the legend
stands beside the axes, clear of the data; one panel per (N, rtol), never averaged across them; the
nearest-neighbour reference curves only on files of that model, the title naming couplings and stepper."""

import importlib.util
import pathlib

import h5py
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


def drawn(tmp_path, executable, model, numerics="", jump=False):
    """The result file and the figure of AFM starts at A = 1, 3, g = 0.002 with the given [model] and
    [numerics] lines."""
    scene = tmp_path / "scene.toml"
    scene.write_text(f"[model]\n{model}[drive]\ng = [0.002]\n[sweep]\nA = [1.0, 3.0]\n[initial]\n"
                     f"kinds = [\"AFM\"]\n{numerics}[schedule]\nrelax_periods = 1\naverage_periods = 2\n")
    result = run_cli(executable, scene, tmp_path / "scene.h5")
    return result, plot_friction().figure(str(result), jump=jump)


def test_nothing_is_averaged_across_sizes_or_tolerances(tmp_path, executable):
    """A file over N = 4, 8 and rtol 1e-6, 1e-8: a panel each, every line the mean of its own panel's members."""
    result, fig = drawn(tmp_path, executable, "rows = [4, 8]\n", "[numerics]\nrtol = [1e-6, 1e-8]\n")
    titles = [ax.get_title() for ax in fig.axes]
    assert sorted(titles) == ["N = 4, rtol = 1e-06", "N = 4, rtol = 1e-08", "N = 8, rtol = 1e-06", "N = 8, rtol = 1e-08"]
    with h5py.File(result) as f:
        members = f["members"]
        rows, rtol, A, D = (members[name][:] for name in ("rows", "rtol", "A", "dissipation"))
        settled = (members["regime"][:].astype(str) != "unsettled") & (members["status"][:].astype(str) == "ok")
    for ax in fig.axes:
        size, tolerance = (float(part.split("= ")[1]) for part in ax.get_title().split(", "))
        line = next(l for l in ax.get_lines() if "mean over settled members" in l.get_label())
        for a, y in zip(line.get_xdata(), line.get_ydata()):
            own = (rows == size) & (rtol == tolerance) & (A == a) & settled
            assert own.any() and y == np.mean(D[own] / size)  # its own members only, never the other N's or rtol's
    assert "nearest neighbours, stepper rodas4p2, no disorder" in fig._suptitle.get_text()


def test_reference_curves_only_for_the_model_they_belong_to(tmp_path, executable):
    _, fig = drawn(tmp_path, executable, "rows = 4\ncouplings = \"dipolar\"\nboundary = \"open\"\n", jump=True)
    labels = [text.get_text() for ax in fig.axes for text in ax.get_legend().get_texts()]
    assert not any("small A" in label or "large A" in label or "J(A)" in label for label in labels)
    assert "dipolar couplings, open rows" in fig._suptitle.get_text()
    assert "no reference curves" in fig._suptitle.get_text()
