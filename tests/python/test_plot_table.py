"""scripts/plot_table.py: the title carries the table's provenance lines (two tables made differently get
different titles), R's error bars stand only where R_error bounds R, and symmetry-limited entries are
drawn hollow and named."""

import importlib.util
import pathlib

import numpy as np

SCRIPT = pathlib.Path(__file__).resolve().parents[2] / "scripts" / "plot_table.py"
HEADER = "A,ic,W,S,R,paper_R,relative_deviation,steps_per_period,paper_W,paper_S,R_error,R_error_kind\n"


def plot_table():
    spec = importlib.util.spec_from_file_location("plot_table", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def write_table(path, disorder, kind_at_6):
    path.write_text(
        "# rotorsweep table: the paper's dissipation integrals (N = 20, g = 0.0011; docs/model.md §3)\n"
        "# written by rotorsweep 0.1.0 (revision abc)\n"
        "# stepper rodas4p2, rtol 1e-09 (W and S outside CP at rtol 1e-12), triangular window over periods 3 and 4\n"
        f"# disorder: {disorder}\n"
        "# R_error: the estimate for the mean of periods 3 and 4\n" + HEADER +
        "1,FM,2e-3,2e-3,2e-3,2e-3,1e-8,100,2e-3,2e-3,1e-10,resolved\n"
        f"6,FM,1.5,1.6,1.4,1.5,-0.06,300,1.5,1.5,1e-2,{kind_at_6}\n"
        "1,AFM,1e-3,1e-3,1e-3,1e-3,1e-8,100,1e-3,1e-3,1e-11,resolved\n"
        f"6,AFM,1.3,1.2,1.3,1.4,-0.07,300,1.4,1.4,2e-2,{kind_at_6}\n")
    return path


def test_the_title_is_the_tables_provenance_and_error_bars_stand_only_where_they_bound(tmp_path):
    module = plot_table()
    plain = module.figure(write_table(tmp_path / "plain.csv", "none", "symmetry-limited"))
    disordered = module.figure(write_table(tmp_path / "disordered.csv", "sigma_A = 1e-05, seed 1 (realization 0)",
                                           "resolved"))
    plain_title, disordered_title = (fig.axes[0].get_title() for fig in (plain, disordered))
    assert "stepper rodas4p2, rtol 1e-09" in plain_title and "disorder: none" in plain_title
    assert "disorder: sigma_A = 1e-05, seed 1" in disordered_title and plain_title != disordered_title
    labels = [text.get_text() for text in plain.axes[0].get_legend().get_texts()]
    assert "FM start: R, error no bound (symmetry-limited)" in labels
    # error bars: one per entry whose error is a bound (2 of 4 in the plain table, 4 of 4 with disorder)
    bars = [sum(len(c.get_segments()) for c in fig.axes[0].collections if c.__class__.__name__ == "LineCollection")
            for fig in (plain, disordered)]
    assert bars == [2, 4]
    plain.savefig(tmp_path / "table.png")
    assert (tmp_path / "table.png").stat().st_size > 10_000
    assert np.isfinite(float(module.read_table(tmp_path / "plain.csv")[1][0]["R"]))
