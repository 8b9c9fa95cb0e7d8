"""rotorsweep.run: scenes as dict, text or path; bad scenes raise ValueError naming the key; the
results equal the command line's file bit for bit; output paths; thread-count invariance."""

import io
import os
import subprocess
import sys

import h5py
import numpy as np
import pytest
import rotorsweep
from conftest import hdf5_datasets, identical, python_words, run_cli


def as_dict():
    return {
        "model": {"rows": 8},
        "drive": {"g": [0.0011]},
        "sweep": {"A": [1.0, 6.0, 11.0]},
        "initial": {"kinds": ["FM", "AFM"], "replicas": 2},
        "schedule": {"relax_periods": 1, "average_periods": 2},
    }


def test_dict_text_and_path_give_the_same_results(small_scene, tmp_path):
    path = tmp_path / "small.toml"
    path.write_text(small_scene)
    from_text = rotorsweep.run(small_scene, progress=False)
    from_path = rotorsweep.run(path, progress=False)
    from_str_path = rotorsweep.run(str(path), progress=False)
    from_dict = rotorsweep.run(as_dict(), progress=False)
    for other in (from_path, from_str_path, from_dict):
        for name in from_text.data_vars:
            assert identical(from_text[name].values, other[name].values), name
    assert from_path.attrs["scene_path"] == str(path)
    assert from_dict.attrs["scene_path"] == "<python>"


def test_a_bad_key_raises_value_error_naming_it(small_scene):
    with pytest.raises(ValueError, match="sweep.A"):
        rotorsweep.run(small_scene.replace("A = [1.0, 6.0, 11.0]", "A = [-1.0]"), progress=False)
    with pytest.raises(ValueError, match="numerics.stepper"):
        rotorsweep.run({**as_dict(), "numerics": {"stepper": "euler"}}, progress=False)
    with pytest.raises(ValueError, match="initial.replica"):
        rotorsweep.run({**as_dict(), "initial": {"replica": 3}}, progress=False)
    with pytest.raises(FileNotFoundError):
        rotorsweep.run("no-such-scene.toml", progress=False)
    with pytest.raises(TypeError):
        rotorsweep.run(42, progress=False)


def test_results_equal_the_command_line_file_bit_for_bit(small_scene, tmp_path, executable):
    scene = tmp_path / "small.toml"
    scene.write_text(small_scene)
    cli = hdf5_datasets(run_cli(executable, scene, tmp_path / "cli.h5"))
    written = rotorsweep.run(scene, progress=False, output=tmp_path / "module.h5")
    assert hdf5_datasets(tmp_path / "module.h5") == cli
    assert written.attrs["complete"]
    assert written.attrs["isa"] == rotorsweep.instruction_set  # the command line's widest set too, here
    assert h5py.File(tmp_path / "cli.h5", "r").attrs["isa"] == rotorsweep.instruction_set
    # the in-memory result holds the same datasets as well
    job = rotorsweep._core.SweepJob(str(scene), True, 0, "", False, "test", "test")
    assert job.wait(-1)
    in_memory = hdf5_datasets(io.BytesIO(job.take_image()))
    assert in_memory == cli
    assert len(cli) > 40


def test_no_file_is_written_unless_asked(small_scene, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    rotorsweep.run(small_scene + '\n[output]\npath = "scene_asks.h5"\n', progress=False)
    assert list(tmp_path.iterdir()) == []
    rotorsweep.run(small_scene + '\n[output]\npath = "scene_asks.h5"\n', progress=False, output=True)
    assert [p.name for p in tmp_path.iterdir()] == ["scene_asks.h5"]
    with pytest.raises(ValueError, match="output.path"):
        rotorsweep.run(small_scene, progress=False, output=True)


def test_an_unusable_output_path_is_a_value_error_before_any_work(small_scene, tmp_path):
    (tmp_path / "notes.txt").write_text("keep me")
    with pytest.raises(ValueError, match="not an HDF5 file"):
        rotorsweep.run(small_scene, progress=False, output=tmp_path / "notes.txt")
    assert (tmp_path / "notes.txt").read_text() == "keep me"
    with pytest.raises(ValueError):
        rotorsweep.run(small_scene, progress=False, output=tmp_path)


def test_thread_count_does_not_change_a_bit(small_scene):
    one = rotorsweep.run(small_scene, threads=1, progress=False)
    two = rotorsweep.run(small_scene, threads=2, progress=False)
    for name in one.data_vars:
        assert identical(one[name].values, two[name].values), name
    assert one.attrs["threads"] == 1 and two.attrs["threads"] == 2


def test_the_paper_members_through_the_module():
    """The paper's non-CP members (A = 1, 4, 11; N = 20) against its table, as in the C++ tests."""
    paper = {(1.0, "FM"): 2.018948e-3, (1.0, "AFM"): 7.184589e-4, (11.0, "FM"): 1.654868e-1,
             (11.0, "AFM"): 1.654868e-1}
    ds = rotorsweep.run({
        "model": {"rows": 20}, "drive": {"g": [0.0011]}, "sweep": {"A": [1.0, 11.0]},
        "initial": {"kinds": ["FM", "AFM"], "replicas": 1, "noise": 0.01},
        "schedule": {"relax_periods": 2, "average_periods": 2},
        "numerics": {"rtol": 1e-8, "atol": 1e-11}}, progress=False)
    for (A, ic), R in paper.items():
        D = float(ds.dissipation.sel(A=A, ic=ic, replica=0))
        assert D == pytest.approx(R, rel=2e-3), (A, ic)


def test_thread_counts_outside_1_to_4096_raise_value_error(monkeypatch):
    scene = {"model": {"rows": 4}, "drive": {"g": 0.01}, "sweep": {"A": 1}}
    # also what Python would quietly turn into a count: 0 and False (every core), 2.5 (2), "2", 2**80
    for bad in (-1, 5000, 100000, 0, "0", "2", False, True, 2.5, 2**80):
        with pytest.raises(ValueError, match="threads"):
            rotorsweep.run(scene, threads=bad, progress=False)
        with pytest.raises(ValueError, match="threads"):
            rotorsweep.slider({"sweep": {"separation": 9e-3}}, threads=bad, progress=False)
    monkeypatch.setenv("OMP_NUM_THREADS", "100000")
    with pytest.raises(ValueError, match="OMP_NUM_THREADS"):
        rotorsweep.run(scene, progress=False)


def test_output_paths_behave_as_the_command_lines(tmp_path):
    scene = {"model": {"rows": 4}, "drive": {"g": 0.01}, "sweep": {"A": 1}}
    with pytest.raises(ValueError, match="output path is empty"):
        rotorsweep.run(scene, output="", progress=False)
    text = tmp_path / "notes.h5"
    text.write_text("not a result")
    with pytest.raises(ValueError, match=r"force=True") as refused:
        rotorsweep.run(scene, output=text, progress=False)
    assert "--force" not in str(refused.value)
    # an interrupted run's partial file is kept unless force=True, as `rotorsweep run` does
    out = tmp_path / "y.h5"
    partial = tmp_path / "y.h5.partial"
    partial.write_bytes(b"members of an earlier run")
    with pytest.raises(ValueError, match="stopped early"):
        rotorsweep.run(scene, output=out, progress=False)
    assert partial.read_bytes() == b"members of an earlier run" and not out.exists()
    rotorsweep.run(scene, output=out, force=True, progress=False)
    assert out.exists() and not partial.exists()


def test_open_names_a_file_that_is_not_a_result(tmp_path):
    path = tmp_path / "foreign.h5"
    with h5py.File(path, "w") as f:
        f.attrs["complete"] = True
        f.create_group("members").create_dataset("A", data=[1.0])
    with pytest.raises(ValueError, match="not a rotorsweep file"):
        rotorsweep.open(path)
    # HDF5 files rotorsweep did not write, or that lack a dataset its files have: ValueError, never KeyError
    with h5py.File(tmp_path / "empty.h5", "w"):
        pass
    with h5py.File(tmp_path / "complete.h5", "w") as f:
        f.attrs["complete"] = True
    with h5py.File(tmp_path / "slider.h5", "w") as f:
        f.attrs.update({"complete": True, "kind": "slider", "version": "x", "scene": ""})
    for foreign in ("empty.h5", "complete.h5", "slider.h5"):
        with pytest.raises(ValueError, match="not a rotorsweep file"):
            rotorsweep.open(tmp_path / foreign)
    with h5py.File(tmp_path / "slider.h5", "a") as f:
        f.create_group("members")
    with pytest.raises(ValueError, match="is missing"):
        rotorsweep.open(tmp_path / "slider.h5")


def test_run_prints_the_command_lines_first_and_last_lines_unless_quiet(small_scene, capsys):
    rotorsweep.run(small_scene, progress=False)
    err = capsys.readouterr().err
    assert err.startswith("rotorsweep run <python>: ")
    assert " members (" in err and "threads × " in err
    assert "rotorsweep.run: " in err and "lane occupancy" in err
    rotorsweep.run(small_scene, quiet=True)
    assert capsys.readouterr().err == ""


def test_a_thermal_runs_header_names_the_langevin_stepper(capsys):
    scene = {"model": {"rows": 2}, "drive": {"g": [1.0]}, "sweep": {"A": [0.0]}, "initial": {"kinds": ["random"]},
             "thermal": {"temperature": 0.5}, "schedule": {"relax_periods": 1, "average_periods": 1}}
    rotorsweep.run(scene, progress=False)
    first = capsys.readouterr().err.splitlines()[0]
    assert "Langevin" in first and "T = 0.5" in first and "rtol 1e" not in first


def test_slip_kinds_gives_the_window_its_label_and_counts():
    """N = 2 at g = 1e-5 with σ_A = 1e-6: A = 8 jumps (CP), A = 9 slips smoothly (SA); the curves count SA."""
    table = {"model": {"rows": 2}, "drive": {"g": [1e-5]}, "sweep": {"A": [8.0, 9.0]},
             "initial": {"kinds": ["AFM"], "noise": 0.0, "replicas": 2}, "disorder": {"A": 1e-6},
             "observables": {"slip_kinds": True}, "numerics": {"rtol": 1e-12, "atol": 1e-15}}
    ds = rotorsweep.run(table, threads=2, progress=False, quiet=True)
    assert list(ds["regime"].sel(A=8.0).values.ravel()) == ["CP", "CP"]
    assert list(ds["regime"].sel(A=9.0).values.ravel()) == ["SA", "SA"]
    assert (ds["slip_jumps"].sel(A=8.0) == 4).all() and (ds["slip_smooth"].sel(A=9.0) == 4).all()
    assert float(ds["curve_fraction_SA"].sel(A=9.0).squeeze()) == 1.0
    plain = rotorsweep.run(dict(table, observables={}), threads=2, progress=False, quiet=True)
    assert "slip_jumps" not in plain and "curve_fraction_SA" not in plain
    assert list(plain["regime"].sel(A=9.0).values.ravel()) == ["CP", "CP"]


def test_a_range_axis_meets_its_exact_points_so_sel_finds_them():
    """A = 0.25 … 11 in 44 points is 0.25 + k/4: sel(A=6.0) finds the member at k = 23."""
    scene = {"model": {"rows": 2}, "drive": {"g": [0.1]}, "sweep": {"A": {"from": 0.25, "to": 11.0, "count": 44}},
             "schedule": {"relax_periods": 0, "average_periods": 1}}
    ds = rotorsweep.run(scene, progress=False, quiet=True)
    assert list(ds.A.values) == [0.25 + k / 4 for k in range(44)]
    assert float(ds.dissipation.sel(A=6.0).squeeze()) == float(ds.dissipation.isel(A=23).squeeze())


def test_the_progress_line_shows_the_periods_closed(capsys, monkeypatch):
    line = rotorsweep._progress.ProgressLine(10, True)
    monkeypatch.setattr(line, "last", line.last - 60)  # as if the last line were a minute old
    line.update(3, 42)
    err = capsys.readouterr().err
    assert "3/10 members" in err and "(42 periods closed)" in err


def test_a_sweep_job_counts_the_periods_its_members_close(small_scene):
    job = rotorsweep._core.SweepJob(small_scene, False, 1, "", False, "test", "test")
    assert job.wait(-1)
    assert job.done == job.total == 12
    with h5py.File(io.BytesIO(job.take_image()), "r") as f:
        shadows = int(np.isfinite(f["members/dissipation_shadow"][:]).sum())
        probes = int(np.isfinite(f["members/dissipation_probe"][:]).sum())
    assert shadows > 0  # the CP members at A = 6 run their 2 averaged periods again
    assert probes > 0  # and members that slip or end on a symmetric set run their symmetry probe
    assert job.periods == 12 * 3 + 2 * (shadows + probes)  # relax 1 + average 2 each


def test_the_last_lines_count_symmetry_limited_members_apart(small_scene, capsys):
    """A = 6 without disorder: 4 CP members whose D the integration error decides, none merely unresolved."""
    ds = rotorsweep.run(small_scene, progress=False)
    err = capsys.readouterr().err
    limited = int(ds.symmetry_limited.sum())
    assert limited == 4 and int(ds.dissipation_resolved.where(ds.symmetry_limited == 1).sum()) == 0
    assert f"warning: {limited} members whose D an asymmetry of the rows below rtol decides" in err
    assert "not resolved" not in err and "tighten" not in err


#: scenes `rotorsweep run` refuses before any work, and the words it says
REFUSED = {
    # a dense coupling table at N = 20000: tens of GiB per thread
    "memory": ('[model]\nrows = 20000\ncouplings = "dipolar"\nrange = "all"\n[drive]\ng = 0.01\n'
               '[sweep]\nA = 1\n', "GiB to work in"),
    # within the member limit, but terabytes of results
    "disk": ("[model]\nrows = 4096\n[drive]\ng = { from = 0.001, to = 1, count = 10000 }\n"
             "[sweep]\nA = { from = 1, to = 2, count = 10000 }\n", "on disk"),
    # a GPU this machine may not have (skipped where it has one)
    "gpu": ('[model]\nrows = 8\n[drive]\ng = 0.01\n[sweep]\nA = 1\n[numerics]\ndevice = "gpu"\n',
            'numerics.device = "gpu"'),
}


@pytest.mark.parametrize("case", sorted(REFUSED))
def test_run_refuses_what_the_command_line_refuses_in_its_words_before_any_work(case, tmp_path, executable):
    text, words = REFUSED[case]
    scene = tmp_path / "scene.toml"
    scene.write_text(text)
    cli = subprocess.run([executable, "run", str(scene), "-q", "-o", str(tmp_path / "out.h5")],
                         capture_output=True, text=True)
    if case == "gpu" and cli.returncode == 0:
        pytest.skip("this machine has a GPU")
    assert cli.returncode == 2 and words in cli.stderr, cli.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.toml"]
    with pytest.raises(ValueError) as raised:
        rotorsweep.run(scene, output=tmp_path / "out.h5", progress=False, quiet=True)
    assert str(raised.value) == python_words(cli.stderr)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.toml"]  # nothing made, nothing locked


def test_a_refusal_under_an_address_space_limit_leaves_the_interpreter_whole(small_scene, tmp_path):
    """Under ulimit -v 4 GB a sweep that needs more raises ValueError; the next run works and the
    interpreter ends cleanly (no crash at exit)."""
    script = (
        "import resource, rotorsweep\n"
        "resource.setrlimit(resource.RLIMIT_AS, (4 << 30, 4 << 30))\n"
        f"big = {REFUSED['memory'][0]!r}\n"
        "try:\n"
        "    rotorsweep.run(big, threads=2, progress=False, quiet=True)\n"
        "except ValueError as error:\n"
        "    print('refused:', error)\n"
        f"print(float(rotorsweep.run({small_scene!r}, threads=1, progress=False, quiet=True)['regime'].size) > 0)\n")
    completed = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                               env=dict(os.environ, OPENBLAS_NUM_THREADS="1"), cwd=tmp_path)
    assert completed.returncode == 0, completed.stderr
    assert "refused: the sweep needs about" in completed.stdout
    assert completed.stdout.strip().endswith("True")
