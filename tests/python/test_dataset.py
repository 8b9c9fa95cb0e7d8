"""The result as an xarray.Dataset: the plan's axes as dimensions, the member plan as a stacked
coordinate, units and descriptions, and open() of a written file giving the same Dataset."""

import h5py
import numpy as np
import pytest
import rotorsweep
import xarray as xr
from conftest import identical

THREE_AXES = """
[model]
rows = 6
[drive]
g = [0.001, 0.002]
[sweep]
A = [1.0, 11.0, 12.0]
[initial]
kinds = ["AFM"]
noise = [0.0, 0.05]
replicas = 3
[schedule]
relax_periods = 1
average_periods = 1
[observables]
period_series = true
"""


def test_three_axes_become_dimensions_with_their_values():
    ds = rotorsweep.run(THREE_AXES, progress=False)
    assert dict(ds.dissipation.sizes) == {"A": 3, "g": 2, "noise": 2, "replica": 3}
    assert list(ds.A.values) == [1.0, 11.0, 12.0]
    assert list(ds.g.values) == [0.001, 0.002]
    assert list(ds.noise.values) == [0.0, 0.05]
    assert list(ds.replica.values) == [0, 1, 2]
    # axes with one value stay as scalar coordinates
    assert ds.rows.item() == 6 and ds.ic.item() == "AFM" and ds.offset.item() == 0.0
    assert dict(ds.theta_final.sizes) == {"A": 3, "g": 2, "noise": 2, "replica": 3, "row": 6}
    assert ds.period_dissipation.sizes["period"] == 2
    assert dict(ds.curve_dissipation_mean.sizes) == {"A": 3, "g": 2, "noise": 2}
    # every dataset says its units (UDUNITS spelling): the row model is dimensionless, angles in rad
    assert ds.dissipation.attrs["units"] == "1" and "mean" in ds.dissipation.attrs["description"]
    assert ds.attrs["scaled_units"].startswith("energies in ε")
    assert ds.theta_final.attrs["units"] == "rad" and ds.noise.attrs["units"] == "rad"
    assert ds.g.attrs["units"] == "1" and ds.A.attrs["units"] == "1"
    assert "units" not in ds.status.attrs  # text has none
    for name, variable in ds.data_vars.items():
        if variable.dtype.kind in "fiu":
            assert "units" in variable.attrs, name
    assert ds.status.dtype == object and set(np.unique(ds.status.values)) == {"ok"}
    # curves are the replica statistics of the members
    np.testing.assert_allclose(ds.curve_dissipation_mean, ds.dissipation.mean("replica"), rtol=1e-14)


def test_the_plan_is_a_stacked_coordinate_in_plan_order():
    ds = rotorsweep.run(THREE_AXES, progress=False)
    stacked = rotorsweep.members(ds)
    assert stacked.sizes["member"] == 36
    assert list(stacked.plan_index.values) == list(range(36))
    # plan order: A outermost, then g, noise, replica innermost
    assert list(stacked.A.values[:6]) == [1.0] * 6
    assert list(stacked.replica.values[:3]) == [0, 1, 2]
    assert int(ds.plan_index.sel(A=11.0, g=0.002, noise=0.05, replica=1)) == 12 + 6 + 3 + 1


RAGGED = """
[model]
rows = 6
[drive]
g = 0.01
[sweep]
A = [2.0, 11.0]
[initial]
kinds = ["random", "FM", "exact"]
noise = [0.01, 0.3]
offset = [0.0, 1.0]
angles = [0.0, 3.14159]
replicas = 3
[schedule]
relax_periods = 1
average_periods = 1
"""


def test_random_and_exact_starts_sit_once_on_the_noise_and_offset_grid(tmp_path):
    ds = rotorsweep.run(RAGGED, progress=False, output=tmp_path / "ragged.h5")
    # per A: random 3 + FM 3 + exact 1 at (η, θ0) = (0.01, 0), then FM 3 at each of three others
    with h5py.File(tmp_path / "ragged.h5") as f:
        assert f["members/A"].shape[0] == 2 * (3 + 3 + 1 + 3 * 3)
        assert f["curves/A"].shape[0] == 2 * (3 + 3)
        assert list(f["curves/members"][:6]) == [3, 3, 1, 3, 3, 3]
    random = ds.dissipation.sel(ic="random")
    assert np.isfinite(random.sel(noise=0.01, offset=0.0)).all()
    assert np.isnan(random.sel(noise=0.3)).all() and np.isnan(random.sel(offset=1.0)).all()
    exact = ds.dissipation.sel(ic="exact", noise=0.01, offset=0.0)
    assert np.isfinite(exact.sel(replica=0)).all() and np.isnan(exact.sel(replica=[1, 2])).all()
    assert np.isfinite(ds.dissipation.sel(ic="FM")).all()
    # curves stay over all axes but replica, with their points' member counts
    assert dict(ds.curve_members.sizes) == {"A": 2, "noise": 2, "offset": 2, "ic": 3}
    assert ds.curve_members.sel(ic="exact", noise=0.01, offset=0.0).values.tolist() == [1, 1]
    assert np.isnan(ds.curve_members.sel(ic="random", noise=0.3)).all()
    # the stacked plan leaves the empty cells out and keeps plan order
    stacked = rotorsweep.members(ds)
    assert list(stacked.plan_index.values) == list(range(32))
    assert rotorsweep.members(rotorsweep.open(tmp_path / "ragged.h5")).sizes["member"] == 32


def test_open_reads_a_written_file_into_the_same_dataset(tmp_path):
    in_memory = rotorsweep.run(THREE_AXES, progress=False)
    rotorsweep.run(THREE_AXES, progress=False, output=tmp_path / "three.h5")
    opened = rotorsweep.open(tmp_path / "three.h5")
    assert set(opened.data_vars) == set(in_memory.data_vars)
    for name in in_memory.data_vars:
        assert identical(opened[name].values, in_memory[name].values), name
        assert opened[name].dims == in_memory[name].dims
    xr.testing.assert_equal(opened.coords.to_dataset(), in_memory.coords.to_dataset())
    assert opened.A.attrs == in_memory.A.attrs
    assert opened.attrs["scene"] == in_memory.attrs["scene"]


def test_open_refuses_an_incomplete_or_foreign_file(tmp_path):
    import h5py

    rotorsweep.run(THREE_AXES, progress=False, output=tmp_path / "three.h5")
    with h5py.File(tmp_path / "three.h5", "r+") as f:
        f.attrs["complete"] = np.bool_(False)
    with pytest.raises(ValueError, match="not a complete result"):
        rotorsweep.open(tmp_path / "three.h5")
    assert rotorsweep.open(tmp_path / "three.h5", allow_incomplete=True).sizes["A"] == 3
    with h5py.File(tmp_path / "other.h5", "w") as f:
        f.attrs["complete"] = np.bool_(True)
        f.attrs["scene"] = THREE_AXES
    with pytest.raises(ValueError, match="not a rotorsweep file"):
        rotorsweep.open(tmp_path / "other.h5")


def test_rows_not_done_of_a_partial_file_are_missing(tmp_path):
    import h5py

    rotorsweep.run(THREE_AXES, progress=False, output=tmp_path / "three.h5")
    with h5py.File(tmp_path / "three.h5", "r+") as f:
        f.attrs["complete"] = np.bool_(False)
        f["members/done"][:5] = False
        f["members/A"][:5] = -1.0  # rows not done hold whatever the disk held
    partial = rotorsweep.open(tmp_path / "three.h5", allow_incomplete=True)
    stacked = rotorsweep.members(partial)
    missing = stacked.plan_index.values < 5
    assert np.isnan(stacked.dissipation.values[missing]).all()
    assert np.isfinite(stacked.dissipation.values[~missing]).all()
    assert stacked.done.values[~missing].all()


def test_scene_helpers():
    axes = rotorsweep.plan_axes(THREE_AXES)
    assert list(axes) == ["rows", "rtol", "A", "g", "noise", "offset", "ic", "replica"]
    assert axes["noise"] == [0.0, 0.05]
    scene = {"model": {"rows": 4}, "sweep": {"A": {"from": 1.0, "to": 2.0, "count": 3}}, "drive": {"g": [1e-3]}}
    assert "A = { from = 1.0, to = 2.0, count = 3 }" in rotorsweep.scene_text(scene)
    scene["drive"]["g"] = np.array([1e-3])
    assert rotorsweep.plan_axes(scene)["A"] == [1.0, 1.5, 2.0]


def test_every_numeric_dataset_of_a_file_carries_units(tmp_path):
    path = tmp_path / "units.h5"
    rotorsweep.run(THREE_AXES, progress=False, quiet=True, output=str(path))
    missing = []
    with h5py.File(path, "r") as f:
        f.visititems(lambda name, obj: missing.append(name) if isinstance(obj, h5py.Dataset)
                     and obj.dtype.kind in "fiu" and "units" not in obj.attrs else None)
        assert f["members/theta_initial"].attrs["units"] in (b"rad", "rad")
    assert not missing
