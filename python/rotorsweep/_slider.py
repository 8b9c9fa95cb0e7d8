"""A slider result file (README "The experiment's slider") as an xarray.Dataset: members over the
dimensions size, separation and replica, their per-period values over period, their time
series over time, and /curve's replica statistics and mappings of A as curve_<name> over size and
separation (docs/model.md §9)."""

import numpy as np
import pandas as pd
import xarray as xr

from ._dataset import _attributes

#: SI units of the /members and /series datasets of files written before datasets carried their own
#: "units" attribute ("1": dimensionless)
_UNITS = {"separation": "m", "friction": "N", "period_friction": "N", "period_work": "J",
          "period_dissipation": "J", "period_stored": "J", "energy": "J", "time": "s"}


def _attrs(name, dataset, text=False):
    """description and units (the file's own where it has them; none for text)."""
    attrs = {"description": dataset.attrs.get("description", "")}
    if not text:
        units = dataset.attrs.get("units", _UNITS.get(name, "1"))
        attrs["units"] = units.decode() if isinstance(units, bytes) else units
    return attrs


def _text(values):
    return np.array([v.decode() if isinstance(v, bytes) else str(v) for v in values])


def _curve(group):
    """/curve (one row per size and separation) as curve_<name> variables over size and separation."""
    size = np.array([f"{c}x{r}" for c, r in zip(group["columns"][:], group["rows"][:])])
    index = pd.MultiIndex.from_arrays([size, group["separation"][:]], names=["size", "separation"])
    variables = {f"curve_{name}": xr.Variable(("point",), dataset[:], _attrs(name, dataset))
                 for name, dataset in group.items() if name not in ("separation", "columns", "rows")}
    # every (size, separation) is a row, so nothing is filled; integer columns stay integers
    fill = {name: (-1 if v.dtype.kind in "iu" else np.nan) for name, v in variables.items()}
    return xr.Dataset(variables, coords={"point": index}).unstack("point", fill_value=fill)


def from_hdf5(h5file):
    """The Dataset of an open slider result (attribute kind = "slider")."""
    attrs = _attributes(h5file)
    if not attrs.get("complete", False):
        raise ValueError(f"'{h5file.filename}' is not a complete result (attribute complete = FALSE)")
    members = h5file["members"]
    columns, rows = members["columns"][:], members["rows"][:]
    size = np.array([f"{c}x{r}" for c, r in zip(columns, rows)])
    index = pd.MultiIndex.from_arrays([size, members["separation"][:], members["replica"][:]],
                                      names=["size", "separation", "replica"])
    variables = {}
    for name, dataset in members.items():
        if name in ("separation", "replica", "columns", "rows", "done", "plan_index"):
            continue
        values = dataset[:]
        text = values.dtype.kind in "OS"
        if text:
            values = _text(values)
        dims = ("member",) if values.ndim == 1 else ("member", "period")
        variables[name] = xr.Variable(dims, values, _attrs(name, dataset, text))
    series = h5file["series"]
    for name, dataset in series.items():
        if name == "time":
            continue
        dims = ("member", "time", "rotor")[: dataset.ndim]  # angles and torques: one per rotor
        variables[f"series_{name}"] = xr.Variable(dims, dataset[:], _attrs(name, dataset))
    coords = {"member": index, "time": ("time", series["time"][:], {"units": "s"})}
    dataset = xr.Dataset(variables, coords=coords, attrs=attrs).unstack("member")
    if "curve" in h5file:
        dataset = dataset.merge(_curve(h5file["curve"]))
    sizes = list(dict.fromkeys(size))  # the scene's order
    dataset = dataset.reindex(size=sizes)
    dataset = dataset.assign_coords(columns=("size", [int(s.split("x")[0]) for s in sizes]),
                                    rows=("size", [int(s.split("x")[1]) for s in sizes]))
    dataset["separation"].attrs["units"] = "m"
    return dataset.transpose("size", "separation", "replica", ...)
