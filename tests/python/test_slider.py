"""rotorsweep.slider and rotorsweep.open of slider files: the Dataset's layout, the command line's
numbers to the bit, bad keys as ValueError, and Ctrl-C leaving no file."""

import os
import signal
import subprocess
import sys
import time

import h5py
import numpy as np
import pytest

import rotorsweep
from conftest import python_words

SMALL = {"slider": {"columns": [3, 2], "rows": [2, 2]}, "substrate": {"columns": 11, "rows": 11},
         "drive": {"rest": 0.5, "end": 4.5}, "sweep": {"separation": [9e-3, 7e-3, 8e-3]},
         "initial": {"replicas": 2}, "observables": {"samples_per_period": 20}}


def command_line(scene_path, output):
    subprocess.run([os.environ["ROTORSWEEP_EXECUTABLE"], "slider", str(scene_path), "-o", str(output), "-q",
                    "--threads", "2"], check=True)


def test_the_dataset_holds_the_command_lines_members_in_plan_order(tmp_path):
    scene = tmp_path / "small.toml"
    scene.write_text(rotorsweep._scene.dict_to_toml(SMALL))
    cli = tmp_path / "cli.h5"
    command_line(scene, cli)
    ds = rotorsweep.slider(scene, threads=1, progress=False)
    assert dict(ds.sizes) == {"size": 2, "separation": 3, "replica": 2, "period": 2, "time": 46}
    assert list(ds["size"].values) == ["3x2", "2x2"]  # the scene's order, not sorted
    assert list(ds["columns"].values) == [3, 2] and list(ds["rows"].values) == [2, 2]
    assert ds["friction"].attrs["units"] == "N" and ds["separation"].attrs["units"] == "m"
    assert ds["series_energy"].attrs["units"] == "J" and "units" not in ds["status"].attrs
    with h5py.File(cli) as f:
        missing = []
        f.visititems(lambda name, obj: missing.append(name) if isinstance(obj, h5py.Dataset)
                     and obj.dtype.kind in "fiu" and "units" not in obj.attrs else None)
        assert not missing
        members = f["members"]
        for k in range(members["friction"].shape[0]):
            size = f"{members['columns'][k]}x{members['rows'][k]}"
            at = dict(size=size, separation=members["separation"][k], replica=members["replica"][k])
            assert ds["friction"].sel(at).item() == members["friction"][k]  # bits
            assert np.array_equal(ds["period_work"].sel(at).values, members["period_work"][k])
            assert np.array_equal(ds["series_friction"].sel(at).values, f["series"]["friction"][k])
            assert ds["status"].sel(at).item() == members["status"][k].decode()
    opened = rotorsweep.open(cli)
    assert opened["friction"].equals(ds["friction"])
    assert opened.attrs["kind"] == "slider"


def test_output_writes_the_command_lines_file(tmp_path):
    out = tmp_path / "py.h5"
    ds = rotorsweep.slider(SMALL, threads=2, progress=False, output=out)
    assert out.is_file() and ds.attrs["complete"]
    with pytest.raises(ValueError, match="exists"):
        (tmp_path / "not_hdf5.h5").write_text("text")
        rotorsweep.slider(SMALL, progress=False, output=tmp_path / "not_hdf5.h5")
    # a stopped scan's partial file is refused and kept as it is, unless force=True, as `rotorsweep slider` does
    partial = tmp_path / "again.h5.partial"
    partial.write_bytes(b"members of an earlier scan")
    with pytest.raises(ValueError, match="stopped early"):
        rotorsweep.slider(SMALL, progress=False, output=tmp_path / "again.h5")
    assert partial.read_bytes() == b"members of an earlier scan"
    rotorsweep.slider(SMALL, progress=False, output=tmp_path / "again.h5", force=True)
    assert not partial.exists()


def test_a_shard_is_refused_and_a_partial_file_opens_only_with_allow_incomplete(tmp_path):
    scene = tmp_path / "small.toml"
    scene.write_text(rotorsweep._scene.resolve(SMALL)[0])
    shard = tmp_path / "shard.h5"
    subprocess.run([os.environ["ROTORSWEEP_EXECUTABLE"], "slider", str(scene), "-o", str(shard), "-q", "--shard",
                    "1/3"], check=True)
    with pytest.raises(ValueError, match="merge"):
        rotorsweep.open(shard)
    # a partial file: the whole scan with its first two rows marked done, complete = FALSE
    whole = tmp_path / "whole.h5"
    command_line(scene, whole)
    partial = tmp_path / "whole.h5.partial"
    partial.write_bytes(whole.read_bytes())
    with h5py.File(partial, "r+") as f:
        f.attrs["complete"] = False
        done = f["members/done"][:]
        done[2:] = 0
        f["members/done"][:] = done
    with pytest.raises(ValueError, match="not a complete result"):
        rotorsweep.open(partial)
    members = rotorsweep.open(partial, allow_incomplete=True).friction.stack(member=("size", "separation", "replica"))
    finished = members.dropna("member")
    with h5py.File(whole, "r") as f:
        assert sorted(finished.values) == sorted(f["members/friction"][:2])


def test_a_missing_or_raising_stderr_leaves_no_job_running(tmp_path, monkeypatch, small_scene):
    monkeypatch.setattr(sys, "stderr", None)
    ds = rotorsweep.slider(SMALL, threads=2, output=tmp_path / "quiet.h5")
    assert ds.attrs["complete"]
    rotorsweep.run(small_scene, threads=2, output=tmp_path / "quiet_run.h5")
    assert (tmp_path / "quiet_run.h5").is_file()

    class Raising:
        def write(self, text):
            raise OSError("stderr is gone")

        def flush(self):
            raise OSError("stderr is gone")

        def isatty(self):
            return False

    monkeypatch.setattr(sys, "stderr", Raising())
    with pytest.raises(OSError, match="stderr is gone"):
        rotorsweep.run(small_scene, threads=2, output=tmp_path / "raised.h5")
    # nothing left running or writing: no output, partial, temporary or lock file, and the output's lock free
    leftovers = [p.name for p in tmp_path.iterdir() if p.name.startswith(("raised", ".raised"))]
    assert leftovers == []
    monkeypatch.setattr(sys, "stderr", None)
    rotorsweep.run(small_scene, threads=2, output=tmp_path / "raised.h5")


def test_a_bad_key_is_a_value_error_naming_it():
    with pytest.raises(ValueError, match="sweep.separation"):
        rotorsweep.slider({"sweep": {"separation": [0.1e-3]}}, progress=False)
    with pytest.raises(ValueError, match="slider.colums"):
        rotorsweep.slider({"slider": {"colums": 3}, "sweep": {"separation": 8e-3}}, progress=False)


SCRIPT = """
import sys, rotorsweep
print("started", flush=True)
try:
    rotorsweep.slider({"sweep": {"separation": {"from": 5e-3, "to": 13e-3, "count": 64}}},
                      progress=False, output=sys.argv[1], threads=1)
except KeyboardInterrupt:
    print("interrupted", flush=True)
    sys.exit(130)
print("finished", flush=True)
"""


def test_sigint_stops_a_slider_scan_keeping_its_finished_members(tmp_path):
    output = tmp_path / "long.h5"
    process = subprocess.Popen([sys.executable, "-c", SCRIPT, str(output)], stdout=subprocess.PIPE, text=True,
                               env=os.environ.copy())
    assert process.stdout.readline().strip() == "started"
    time.sleep(1.0)  # inside the scan
    sent = time.monotonic()
    process.send_signal(signal.SIGINT)
    out, _ = process.communicate(timeout=60)
    assert time.monotonic() - sent < 30  # the running lane block finishes first
    assert process.returncode == 130
    assert out.strip() == "interrupted"
    # as `rotorsweep slider`: the finished members in the partial file, no temporary or lock file
    assert list(tmp_path.iterdir()) == [tmp_path / "long.h5.partial"]
    with h5py.File(tmp_path / "long.h5.partial", "r") as f:
        assert not f.attrs["complete"]
        assert f.attrs["members_done"] == f["members/done"][:].sum() < 64


MU0_4PI = 1e-7


def dipole_field(m, r):
    """B (T) at displacements r (…, 3) from a moment m (A m²): μ0/4π [3 r̂ (m·r̂) − m] / r³."""
    d = np.linalg.norm(r, axis=-1, keepdims=True)
    rhat = r / d
    return MU0_4PI * (3 * rhat * (rhat @ m)[..., None] - m) / d**3


def test_substrate_field_torques_energies_and_sublattices_equal_plain_dipole_sums(tmp_path):
    """At the first sample (the slider at rest, the given start) every rotor observable against vector
    sums of dipole fields written here from the definitions, and the energies against the total."""
    a, h, m, m_sub, columns, rows, substrate = 16e-3, 8e-3, 4.57e-2, 5.03e-2, 3, 2, 9
    angles = [0.1, -0.2, 0.4, 3.0, 2.9, 3.3]
    scene = {"slider": {"columns": columns, "rows": rows}, "substrate": {"columns": substrate, "rows": substrate},
             "drive": {"rest": 0.5, "end": 2.5}, "sweep": {"separation": [h]},
             "initial": {"kind": "given", "angles": angles},
             "observables": {"samples_per_period": 10, "angles": True, "energies": True, "field": True,
                             "sublattices": True, "torques": True}}
    ds = rotorsweep.slider(scene, progress=False, output=tmp_path / "observed.h5")
    with h5py.File(tmp_path / "observed.h5") as f:
        s = {name: f["series"][name][0, 0] for name in f["series"] if name != "time"}
    theta = np.asarray(angles)
    i, j = np.arange(columns * rows) % columns, np.arange(columns * rows) // columns
    sites = np.stack([i * a, j * a, np.zeros_like(i, dtype=float)], axis=-1)
    offset = lambda n, big: 0.5 * (n - 1) - 0.5 * (big - 1)  # noqa: E731 (substrate centred under the slider)
    k, l = np.meshgrid(np.arange(substrate), np.arange(substrate), indexing="ij")
    magnets = np.stack([(offset(columns, substrate) + k.ravel()) * a, (offset(rows, substrate) + l.ravel()) * a,
                        np.full(k.size, -h)], axis=-1)
    B = np.array([dipole_field(np.array([m_sub, 0, 0]), site - magnets).sum(axis=0) for site in sites])
    moments = m * np.stack([np.cos(theta), np.zeros_like(theta), -np.sin(theta)], axis=-1)
    torque = m * (-np.sin(theta) * B[:, 0] - np.cos(theta) * B[:, 2])  # ∂(m·B)/∂θ
    np.testing.assert_allclose(s["torques"], torque, rtol=1e-6)
    np.testing.assert_allclose([s["field_axis"], s["field_z"]], [B[:, 0].mean(), B[:, 2].mean()], rtol=1e-6,
                               atol=1e-12)  # B_z averages to 0 over a centred slider
    np.testing.assert_allclose(s["substrate_energy"], -np.sum(moments * B), rtol=1e-6)
    pairs = 0.0
    for p in range(len(theta)):
        for q in range(p + 1, len(theta)):
            pairs -= moments[p] @ dipole_field(moments[q], sites[p] - sites[q])
    np.testing.assert_allclose(s["pair_energy"], pairs, rtol=1e-9)
    np.testing.assert_allclose(s["energy"], s["substrate_energy"] + s["pair_energy"], rtol=1e-12)  # at rest
    even, odd = j % 2 == 0, j % 2 == 1
    np.testing.assert_allclose([s["moment_axis_even"], s["moment_z_even"], s["torque_even"]],
                               [np.cos(theta[even]).mean(), -np.sin(theta[even]).mean(), torque[even].mean()],
                               rtol=1e-6)
    np.testing.assert_allclose([s["moment_axis_odd"], s["moment_z_odd"], s["torque_odd"]],
                               [np.cos(theta[odd]).mean(), -np.sin(theta[odd]).mean(), torque[odd].mean()],
                               rtol=1e-6)
    # the Dataset carries them as series over time, per rotor where they are
    assert ds["series_torques"].dims[-2:] == ("time", "rotor") and ds["series_angles"].dims[-1] == "rotor"
    assert ds["series_field_axis"].attrs["units"] == "T" and ds["series_torques"].attrs["units"] == "N m"


def test_the_force_on_the_slider_equals_the_gradient_of_plain_dipole_sums(tmp_path):
    """F = Σ_r ∇(m_r·B)(p_r) at the first sample, by central differences of vector sums of dipole fields
    written here; F_x is minus the drive's force, bit for bit."""
    a, h, m, m_sub, columns, rows, substrate = 16e-3, 8e-3, 4.57e-2, 5.03e-2, 3, 2, 9
    angles = [0.1, -0.2, 0.4, 3.0, 2.9, 3.3]
    scene = {"slider": {"columns": columns, "rows": rows, "shift_y": 2e-3}, "substrate": {"columns": substrate,
             "rows": substrate}, "drive": {"rest": 0.5, "end": 2.5}, "sweep": {"separation": [h]},
             "initial": {"kind": "given", "angles": angles},
             "observables": {"samples_per_period": 10, "forces": True}}
    ds = rotorsweep.slider(scene, progress=False)
    theta = np.asarray(angles)
    i, j = np.arange(columns * rows) % columns, np.arange(columns * rows) // columns
    sites = np.stack([i * a, j * a + 2e-3, np.zeros_like(i, dtype=float)], axis=-1)
    offset = lambda n, big: 0.5 * (n - 1) - 0.5 * (big - 1)  # noqa: E731
    k, l = np.meshgrid(np.arange(substrate), np.arange(substrate), indexing="ij")
    magnets = np.stack([(offset(columns, substrate) + k.ravel()) * a, (offset(rows, substrate) + l.ravel()) * a,
                        np.full(k.size, -h)], axis=-1)
    moments = m * np.stack([np.cos(theta), np.zeros_like(theta), -np.sin(theta)], axis=-1)

    def energy(shift):
        return -sum(moment @ dipole_field(np.array([m_sub, 0, 0]), site + shift - magnets).sum(axis=0)
                    for moment, site in zip(moments, sites))

    e = 1e-7
    force = [-(energy(e * unit) - energy(-e * unit)) / (2 * e) for unit in np.eye(3)]
    first = {name: float(ds[f"series_{name}"].values.ravel()[0]) for name in ("force_x", "force_y", "force_z")}
    np.testing.assert_allclose([first["force_x"], first["force_y"], first["force_z"]], force, rtol=1e-6)
    np.testing.assert_array_equal(ds["series_force_x"].values, -ds["series_friction"].values)
    assert ds["period_force_y"].sizes["period"] == 1 and ds["series_force_z"].attrs["units"] == "N"


def test_the_curve_with_both_mappings_of_A_is_in_the_dataset(tmp_path):
    ds = rotorsweep.slider(SMALL, threads=1, progress=False, output=tmp_path / "small.h5")
    with h5py.File(tmp_path / "small.h5") as f:
        curve = f["curve"]
        for k in range(len(curve["separation"])):
            size, h = f"{curve['columns'][k]}x{curve['rows'][k]}", curve["separation"][k]
            point = ds.sel(size=size, separation=h)
            assert float(point["curve_A_paper"]) == curve["A_paper"][k]
            assert float(point["curve_friction"]) == curve["friction"][k]
    np.testing.assert_allclose(ds["curve_friction"], ds["friction"].mean("replica"), rtol=1e-12)
    assert ds["curve_A_field"].dims == ("size", "separation") and ds["curve_friction"].attrs["units"] == "N"


def test_speed_and_damping_axes_are_dimensions_with_each_speeds_times(tmp_path):
    scene = dict(SMALL, slider={"columns": 3, "rows": 2, "damping": [2.5e-6, 5e-6]},
                 drive={"rest": 0.5, "periods": 2, "speed": [16e-3, 4e-3]}, initial={"replicas": 1},
                 observables={"samples_per_period": 20, "forces": True})
    out = tmp_path / "axes.h5"
    ds = rotorsweep.slider(scene, threads=2, progress=False, output=out)
    assert dict(ds.sizes) == {"size": 1, "speed": 2, "damping": 2, "separation": 3, "replica": 1, "period": 2,
                              "sample": 51}
    assert ds["speed"].attrs["units"] == "m/s" and ds["damping"].attrs["units"] == "kg m²/s"
    # times per speed, in drive.speed's order: 16 mm/s samples 0.5 s of rest 10 times, 4 mm/s 3 times
    assert list(ds["speed"].values) == [16e-3, 4e-3] and ds["time"].dims == ("speed", "sample")
    fast, slow = ds["time"].sel(speed=16e-3).values, ds["time"].sel(speed=4e-3).values
    assert fast[0] == 0.0 and fast[-1] == pytest.approx(2.5)
    assert np.isnan(slow[:7]).all() and slow[7] == 0.0 and slow[-1] == pytest.approx(8.5)
    series = ds["series_force_x"].sel(speed=4e-3, damping=5e-6, separation=7e-3, replica=0, size="3x2")
    assert np.isnan(series.values[:7]).all() and np.isfinite(series.values[7:]).all()
    with h5py.File(out) as f:
        members = f["members"]
        for k in range(members["friction"].shape[0]):
            at = dict(size="3x2", speed=members["speed"][k], damping=members["damping"][k],
                      separation=members["separation"][k], replica=0)
            assert ds["friction"].sel(at).item() == members["friction"][k]
            assert np.array_equal(ds["series_friction"].sel(at).values, f["series"]["friction"][k], equal_nan=True)
        assert "period" not in f.attrs and "g" not in f.attrs  # per speed and damping: in /curve
        curve = f["curve"]
        for k in range(len(curve["speed"])):
            point = ds.sel(size="3x2", speed=curve["speed"][k], damping=curve["damping"][k],
                           separation=curve["separation"][k])
            assert float(point["curve_friction"]) == curve["friction"][k]
            assert float(point["curve_g"]) == curve["g"][k]
    # g = γ/(E0 T0) grows with the damping and the speed (T0 = a/(2π v))
    g = ds["curve_g"].sel(size="3x2", separation=7e-3)
    assert float(g.sel(speed=16e-3, damping=5e-6)) == pytest.approx(8 * float(g.sel(speed=4e-3, damping=2.5e-6)))


def test_one_speed_and_damping_are_scalar_coordinates(tmp_path):
    ds = rotorsweep.slider(dict(SMALL, slider={"columns": 3, "rows": 2}), threads=1, progress=False)
    assert "speed" not in ds.dims and float(ds["speed"]) == 8e-3 and float(ds["damping"]) == 2.5e-6
    assert ds["time"].dims == ("time",)


#: slider scenes `rotorsweep slider` refuses before any work (memory under a 3 GB address-space limit),
#: and the words it says
REFUSED = {
    "memory": ('[slider]\ncolumns = 100\nrows = 100\n[sweep]\nseparation = 8e-3\n[numerics]\n'
               'linear_solver = "dense"\n', "GiB to work in"),
    "disk": ("[sweep]\nseparation = { from = 5e-3, to = 13e-3, count = 1000 }\n[initial]\nreplicas = 1000\n"
             "[observables]\nsamples_per_period = 1000\n", "on disk"),
    "gpu": ('[sweep]\nseparation = 8e-3\n[numerics]\ndevice = "gpu"\n', 'numerics.device = "gpu"'),
}

LIMITED = """
import resource, sys, rotorsweep
resource.setrlimit(resource.RLIMIT_AS, (3 << 30, 3 << 30))
try:
    rotorsweep.slider(sys.argv[1], output=sys.argv[2], progress=False)
except ValueError as error:
    print(error)
"""


@pytest.mark.parametrize("case", sorted(REFUSED))
def test_slider_refuses_what_the_command_line_refuses_in_its_words_before_any_work(case, tmp_path):
    text, words = REFUSED[case]
    scene = tmp_path / "scene.toml"
    scene.write_text(text)
    out = tmp_path / "out.h5"
    limit = "ulimit -v 3145728; " if case == "memory" else ""
    cli = subprocess.run(f"{limit}'{os.environ['ROTORSWEEP_EXECUTABLE']}' slider '{scene}' -q -o '{out}'",
                         shell=True, capture_output=True, text=True)
    if case == "gpu" and cli.returncode == 0:
        pytest.skip("this machine has a GPU")
    assert cli.returncode == 2 and words in cli.stderr, cli.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.toml"]
    expected = python_words(cli.stderr)
    # the same limit on the interpreter (the memory case): the module raises before any work
    python = subprocess.run([sys.executable, "-c", LIMITED, str(scene), str(out)], capture_output=True, text=True,
                            env=dict(os.environ, OPENBLAS_NUM_THREADS="1"))
    assert python.returncode == 0, python.stderr
    assert python.stdout.strip() == expected
    assert sorted(p.name for p in tmp_path.iterdir()) == ["scene.toml"]
