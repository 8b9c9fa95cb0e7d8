"""A result file (docs/output.md "Output file") as an xarray.Dataset: the plan's axes become dimensions,
/members columns variables over them, /curves columns `curve_*` variables over all axes but replica
(docs/architecture.md "Python module")."""

import numpy as np
import xarray as xr

from . import _core

#: the columns that hold the plan's axes, in plan order (outermost first)
AXES = ("rows", "rtol", "A", "g", "noise", "offset", "ic", "replica")
#: axes that stay dimensions even with one value (a friction curve is over A, averages over replica)
ALWAYS_DIMENSIONS = ("A", "replica")

ANGLE = "rad"


def _units(name, values=None):
    """The units of a file written before datasets carried their own "units" attribute (None for text)."""
    if values is not None and values.dtype.kind in "OSU":
        return None
    bare = name.removeprefix("curve_").removeprefix("period_")
    if bare.startswith(("theta_", "sublattice_angles", "sublattice_deviation")) or bare in ("noise", "offset"):
        return ANGLE
    return "1"


def _second_dimension(name):
    if name.startswith(("theta_", "disorder_")) or name == "row_dissipation":
        return "row"
    if name == "link_alignment":
        return "link"
    if name == "sublattice_angles":
        return "sublattice"
    return name + "_index"


def _read(dataset):
    """A dataset's values (strings decoded), its description and its units (None where it has none)."""
    description, units = dataset.attrs.get("description", ""), dataset.attrs.get("units")
    if isinstance(description, bytes):
        description = description.decode()
    if isinstance(units, bytes):
        units = units.decode()
    if dataset.dtype.kind in "OS":
        values = np.array(dataset.asstr()[()], dtype=object)
    else:
        values = dataset[()]
    return values, description, units


def _attributes(h5file):
    attrs = {}
    for key, value in h5file.attrs.items():
        if isinstance(value, bytes):
            value = value.decode()
        elif isinstance(value, np.generic):
            value = value.item()
        attrs[key] = value
    return attrs


def check_result_file(h5file):
    """ValueError unless the open file is a result of `rotorsweep run` or `rotorsweep slider`: the
    attributes version, complete and scene, and /members (C++: io::is_rotorsweep_file)."""
    name = h5file.filename
    kind = h5file.attrs.get("kind", "")
    kind = kind.decode() if isinstance(kind, bytes) else str(kind)
    if kind.startswith("landscape"):
        raise ValueError(f"'{name}' is a `rotorsweep {kind}` file, not a run or slider result: read it with h5py")
    missing = [f"attribute {a}" for a in ("version", "complete", "scene") if a not in h5file.attrs]
    missing += [] if "members" in h5file else ["/members"]
    if missing:
        raise ValueError(f"'{name}' is not a rotorsweep file (it has no {', '.join(missing)})")


def from_hdf5(h5file, allow_incomplete=False):
    """The Dataset of an open h5py.File."""
    attrs = _attributes(h5file)
    name = h5file.filename
    if not attrs.get("complete", False) and not allow_incomplete:
        raise ValueError(f"'{name}' is not a complete result (attribute complete = FALSE)")
    if "shard_index" in attrs:
        raise ValueError(f"'{name}' is shard {attrs['shard_index']}/{attrs['shard_count']} of a plan: "
                         "join the shards with `rotorsweep merge` first")
    if "members" not in h5file:
        raise ValueError(f"'{name}' holds no /members (not a rotorsweep result)")
    if "scene" not in attrs:
        raise ValueError(f"'{name}' has no scene attribute (not a rotorsweep result file)")
    axes = _core.plan_axes(attrs["scene"])
    shape = tuple(len(values) for values in axes.values())
    dims = tuple(axes)
    members = h5file["members"]
    # each member's cell on the full grid: noise and offset do not multiply random and exact starts,
    # whose cells at other noise and offset values stay empty (docs/output.md "Output file")
    positions = _core.plan_positions(attrs["scene"])
    count, cells = len(positions), int(np.prod(shape))
    if members["A"].shape[0] != count:
        raise ValueError(f"'{name}': /members holds {members['A'].shape[0]} members, its scene plans {count}")

    def on_grid(values, at, grid_shape):
        """values (one row per planned member or point) on the grid, empty cells filled."""
        if len(at) == int(np.prod(grid_shape)):
            return values.reshape(grid_shape + values.shape[1:])
        fill = {"f": np.nan, "b": False, "O": ""}.get(values.dtype.kind, 0)
        out = np.full((int(np.prod(grid_shape)),) + values.shape[1:], fill, dtype=values.dtype)
        out[at] = values
        return out.reshape(grid_shape + values.shape[1:])

    # rows not marked done (a run that stopped early) hold nothing: they are checked and shown as missing
    done = np.asarray(members["done"][()], dtype=bool) if "done" in members else np.ones(count, dtype=bool)
    coords = {axis: (axis, np.asarray(values)) for axis, values in axes.items()}
    variables = {}
    axis_units = {}  # the plan axes' units, from their /members columns

    def add(var_name, values, description, at, grid_shape, trailing=(), units=None):
        values = on_grid(values, at, grid_shape)
        var_dims = dims[: len(grid_shape)] + tuple(trailing)
        attrs = {"description": description}
        units = units if units is not None else _units(var_name, values)
        if units is not None:
            attrs["units"] = units
        variables[var_name] = xr.Variable(var_dims, values, attrs)

    for column, dataset in members.items():
        if not hasattr(dataset, "dtype"):
            continue
        values, description, units = _read(dataset)
        if column in AXES:
            axis_units[column] = units if units is not None else _units(column, values)
            grid = np.broadcast_to(
                np.asarray(axes[column]).reshape([-1 if a == column else 1 for a in dims]), shape)
            if not np.array_equal(values[done], grid.reshape(-1)[positions][done]):
                raise ValueError(f"'{name}': /members/{column} does not follow the scene's plan")
            continue
        add(column, values, description, positions, shape,
            [_second_dimension(column)] if values.ndim == 2 else [], units)
    if "periods" in members:
        for channel, dataset in members["periods"].items():
            values, description, units = _read(dataset)
            add("period_" + channel, values, description, positions, shape, ["period"], units)

    # a curve point's cell: the cell of its replica 0 (replica is the innermost axis)
    points = positions[positions % shape[-1] == 0] // shape[-1]
    if "curves" in h5file:
        curves = h5file["curves"]
        point_shape = shape[:-1]
        for column, dataset in curves.items():
            if not hasattr(dataset, "dtype") or column in AXES:
                continue
            values, description, units = _read(dataset)
            add("curve_" + column, values, description, points, point_shape, (), units)
        if "attractors" in curves:
            group = curves["attractors"]
            labels, _, _ = _read(group["labels"])
            coords["attractor_label"] = ("attractor_label", labels.astype(str))
            for column, dataset in group.items():
                if column == "labels":
                    continue
                values, description, units = _read(dataset)
                add("curve_attractor_" + column, values, description, points, point_shape, ["attractor_label"],
                    units)

    plan_index = np.full(cells, -1, dtype=np.int64)
    plan_index[positions] = np.arange(count)
    coords["plan_index"] = (dims, plan_index.reshape(shape))
    dataset = xr.Dataset(variables, coords=coords, attrs=attrs)
    dataset["plan_index"].attrs["description"] = ("the member's index in the plan (row of /members); -1 where "
                                                  "the plan has no member (a kind without that noise or offset)")
    for axis, units in axis_units.items():
        if units is not None:
            dataset[axis].attrs["units"] = units
    for index in ("row", "link"):
        if index in dataset.dims:
            dataset = dataset.assign_coords({index: np.arange(dataset.sizes[index])})
    if "sublattice" in dataset.dims:
        dataset = dataset.assign_coords(sublattice=["even", "odd"])
    if not done.all() or count != cells:  # members not run and cells without a member become NaN
        present = np.zeros(cells, dtype=bool)
        present[positions[done]] = True
        present = xr.DataArray(present.reshape(shape), dims=dims)
        planned_points = None
        for var in list(dataset.data_vars):
            if "replica" in dataset[var].dims:
                dataset[var] = dataset[var].where(present)
            elif count != cells:
                if planned_points is None:
                    planned_points = np.zeros(cells // shape[-1], dtype=bool)
                    planned_points[points] = True
                    planned_points = xr.DataArray(planned_points.reshape(shape[:-1]), dims=dims[:-1])
                dataset[var] = dataset[var].where(planned_points)
    single = [axis for axis in AXES if dataset.sizes[axis] == 1 and axis not in ALWAYS_DIMENSIONS]
    return dataset.squeeze(single)
