"""A slider result file (docs/output.md "The slider's result file") as an xarray.Dataset: members over the
dimensions size, speed, damping, separation and replica (speed and damping only where the scan has
several; else scalar coordinates), their per-period values over period, their time series over time
(over sample, with time per speed, where the scan has several speeds), and /curve's replica statistics
and mappings of A as curve_<name> over the same axes (docs/model.md §9)."""

import numpy as np
import pandas as pd
import xarray as xr

from ._dataset import _attributes

#: SI units of the /members and /series datasets of files written before datasets carried their own
#: "units" attribute ("1": dimensionless)
_UNITS = {"separation": "m", "friction": "N", "period_friction": "N", "period_work": "J",
          "period_dissipation": "J", "period_stored": "J", "energy": "J", "time": "s"}

#: the plan's axes after size, in plan order, and their units (files before the speed and damping axes
#: have neither column)
_AXES = {"speed": "m/s", "damping": "kg m²/s", "separation": "m"}


def _attrs(name, dataset, text=False):
    """description and units (the file's own where it has them; none for text)."""
    attrs = {"description": dataset.attrs.get("description", "")}
    if not text:
        units = dataset.attrs.get("units", _UNITS.get(name, "1"))
        attrs["units"] = units.decode() if isinstance(units, bytes) else units
    return attrs


def _text(values):
    return np.array([v.decode() if isinstance(v, bytes) else str(v) for v in values])


def _index(group, extra=(), rows=slice(None)):
    """The MultiIndex of a table's rows (those of `rows`) over size, the axes the table has, and `extra`
    columns."""
    size = np.array([f"{c}x{r}" for c, r in zip(group["columns"][:][rows], group["rows"][:][rows])])
    names = [name for name in _AXES if name in group] + list(extra)
    return pd.MultiIndex.from_arrays([size] + [group[name][:][rows] for name in names], names=["size"] + names)


def _curve(group):
    """/curve (one row per size, speed, damping and separation) as curve_<name> variables over them."""
    index = _index(group)
    variables = {f"curve_{name}": xr.Variable(("point",), dataset[:], _attrs(name, dataset))
                 for name, dataset in group.items() if name not in set(index.names) | {"columns", "rows"}}
    # every (size, separation) is a row, so nothing is filled; integer columns stay integers
    fill = {name: (-1 if v.dtype.kind in "iu" else np.nan) for name, v in variables.items()}
    return xr.Dataset(variables, coords={"point": index}).unstack("point", fill_value=fill)


def from_hdf5(h5file, allow_incomplete=False):
    """The Dataset of an open slider result (attribute kind = "slider"). A partial file (complete = FALSE)
    raises ValueError unless allow_incomplete, which gives its members done (its /members/done rows); a
    shard raises ValueError, as a row shard does (it covers part of the plan: merge the shards first)."""
    attrs = _attributes(h5file)
    if "shard_index" in attrs:
        raise ValueError(f"'{h5file.filename}' is shard {attrs['shard_index']}/{attrs['shard_count']} of a plan: "
                         "join the shards with `rotorsweep merge` first")
    complete = bool(attrs.get("complete", False))
    if not complete and not allow_incomplete:
        raise ValueError(f"'{h5file.filename}' is not a complete result (attribute complete = FALSE)")
    members = h5file["members"]
    rows = slice(None) if complete or "done" not in members else members["done"][:] != 0
    index = _index(members, ("replica",), rows)
    variables = {}
    for name, dataset in members.items():
        if name in set(index.names) | {"columns", "rows", "done", "plan_index"}:
            continue
        values = dataset[:][rows]
        text = values.dtype.kind in "OS"
        if text:
            values = _text(values)
        dims = ("member",) if values.ndim == 1 else ("member", "period")
        variables[name] = xr.Variable(dims, values, _attrs(name, dataset, text))
    coords = {"member": index}
    times = None
    if "series" in h5file:
        series = h5file["series"]
        times = series["time"][:]
        # one speed: a time axis; several: a sample axis, with each speed's times (NaN before its first sample)
        sample = "time" if times.ndim == 1 else "sample"
        for name, dataset in series.items():
            if name == "time":
                continue
            dims = ("member", sample, "rotor")[: dataset.ndim]  # angles and torques: one per rotor
            variables[f"series_{name}"] = xr.Variable(dims, dataset[:][rows], _attrs(name, dataset))
        if times.ndim == 1:
            coords["time"] = ("time", times, {"units": "s"})
    dataset = xr.Dataset(variables, coords=coords, attrs=attrs).unstack("member")
    if "curve" in h5file and complete:  # a partial file's /curve is not written yet
        dataset = dataset.merge(_curve(h5file["curve"]))
    sizes = list(dict.fromkeys(index.get_level_values("size")))  # the scene's order
    dataset = dataset.reindex(size=sizes)
    dataset = dataset.assign_coords(columns=("size", [int(s.split("x")[0]) for s in sizes]),
                                    rows=("size", [int(s.split("x")[1]) for s in sizes]))
    if times is not None and times.ndim == 2:  # rows in drive.speed's order
        dataset = dataset.reindex(speed=list(dict.fromkeys(index.get_level_values("speed"))))
        dataset = dataset.assign_coords(time=(("speed", "sample"), times, {"units": "s"}))
    for name, units in _AXES.items():
        if name in dataset.coords:
            dataset[name].attrs["units"] = units
    # an axis of one value (one speed, one damping) is a scalar coordinate
    single = [name for name in ("speed", "damping") if name in dataset.dims and dataset.sizes[name] == 1]
    dataset = dataset.squeeze(single)
    axes = [name for name in ("size", "speed", "damping", "separation", "replica") if name in dataset.dims]
    return dataset.transpose(*axes, ...)
