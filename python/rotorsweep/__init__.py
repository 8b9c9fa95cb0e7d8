"""rotorsweep from Python: run scenes, read result files as xarray Datasets, and explore the
two-angle energy landscape (docs/python.md "Python"; docs/architecture.md "Python module").

    import rotorsweep
    ds = rotorsweep.run({"sweep": {"A": [1.0, 4.0]}, "initial": {"replicas": 2}})
    ds.dissipation.mean("replica")
"""

import contextlib
import io
import numbers
import os
import signal
import sys
import tempfile
import threading

import h5py
import numpy as np

from . import _core, _dataset, _progress, _scene, _slider
from .landscape import (A_minus, A_star, bifurcation_curve, chamber_map, critical_points, jump_events, jump_friction,
                        quasi_static_friction, two_angle_coefficients)

__version__ = _core.version
#: the instruction set this module's sweeps were compiled for (the widest the building machine
#: runs); result files written from Python record it as the attribute "isa"
instruction_set = _core.instruction_set
#: the paper's table of dissipation integrals: its members (rows, g, relax_periods,
#: average_periods; per entry A, ic, R and whether it is in CP, where R depends on the draw)
paper_table = _core.paper_table
#: the steppers a scene can name (numerics.stepper), and the one a scene that names none runs
steppers = list(_core.steppers)
default_stepper = _core.default_stepper
__all__ = ["run", "slider", "open", "members", "scene_text", "plan_axes", "critical_points", "chamber_map",
           "bifurcation_curve", "jump_events", "jump_friction", "quasi_static_friction", "two_angle_coefficients",
           "A_minus", "A_star", "paper_table", "steppers", "default_stepper"]

#: how often run() and slider() look at their job (progress line, Ctrl-C), in seconds
_POLL_SECONDS = 0.1


def run(scene, threads=None, progress=True, output=None, force=False, quiet=False):
    """Runs a scene and returns its results as an xarray.Dataset (see open()).

    scene: TOML text, a path to a scene file, or a dict of tables ({"sweep": {"A": [...]}, ...});
        validated by the command line's parser: a bad key raises ValueError naming it.
    threads: OpenMP threads, 1 to 4096 (None: OMP_NUM_THREADS, else all cores); others raise ValueError.
    progress: draw a progress line on stderr.
    quiet: print nothing (without it, stderr gets the command line's first lines and a last line with
        the time taken and the warnings `rotorsweep run` gives).
    output: None keeps the result in memory only; a path writes that file exactly as
        `rotorsweep run -o PATH` does; True writes to the scene's output.path.
    force: replace an existing file at output that is not an HDF5 file.

    The sweep runs on its own thread without the GIL; Ctrl-C (KeyboardInterrupt) stops it within
    one step and is raised again, and so does SIGTERM (as SystemExit(143)) where nothing else handles it.
    Without output nothing is written; with output the finished members are kept in OUTPUT.partial, as
    `rotorsweep run` keeps them (continue with `rotorsweep run SCENE -o OUTPUT --resume`).
    """
    text, is_path = _scene.resolve(scene)
    count = _thread_count(threads)
    if output is True:
        output = _core.scene_info(text, is_path)["output_path"]
        if not output:
            raise ValueError("output=True: the scene has no output.path; give output a path")
    path = "" if output is None or output is False else _output_path(output)
    if not quiet:  # before the job: a stream that raises leaves nothing running
        _progress.write(_core.run_description(text, is_path, count))
    job = _core.SweepJob(text, is_path, count, path, bool(force), _core.version, _core.revision)
    _follow(job, progress and not quiet, path if not quiet else "", "run")
    image = job.take_image()
    with h5py.File(path if path else io.BytesIO(image), "r") as h5file:
        if not quiet:
            _progress.report(h5file, path)
        return open(path) if path else _dataset.from_hdf5(h5file)


def slider(scene, threads=None, progress=True, output=None, force=False):
    """Runs a slider scene (`rotorsweep slider`) and returns its results as an xarray.Dataset.

    scene: TOML text, a path to a scene file, or a dict of tables ({"sweep": {"separation": [...]}});
        validated by the command line's parser: a bad key raises ValueError naming it.
    threads, progress, force: as for run(). output: None keeps the result in memory only; a path
        writes that file exactly as `rotorsweep slider -o PATH` does; True the scene's output.path.

    Dimensions: size ("7x7", with coordinates columns and rows), separation (m), replica; period
    (the per-period values period_*) and time (the series series_friction, series_order_x,
    series_order_y, series_energy). Ctrl-C (and SIGTERM, as for run()) stops the scan within one step
    and is raised again; with output the finished members are kept in OUTPUT.partial, as `rotorsweep
    slider` keeps them.
    """
    text, is_path = _scene.resolve(scene)
    count = _thread_count(threads)
    if output is True:
        output = _core.slider_scene_info(text, is_path)["output_path"]
        if not output:
            raise ValueError("output=True: the scene has no output.path; give output a path")

    def run_into(path, replace, keep):
        job = _core.SliderJob(text, is_path, count, path, replace, keep, _core.version, _core.revision)
        _follow(job, progress, path if keep else "", "slider")
        job.finish()

    if output is not None and output is not False:
        path = _output_path(output)
        run_into(path, bool(force), True)
        return open(path)
    with tempfile.TemporaryDirectory(prefix="rotorsweep-slider-") as scratch:
        path = os.path.join(scratch, "slider.h5")
        run_into(path, True, False)
        with h5py.File(path, "r") as h5file:
            return _slider.from_hdf5(h5file).load()


def _follow(job, progress, kept_path, command):
    """Polls a job (SweepJob, SliderJob: the C++ side runs and streams, Python draws the progress line)
    until it ends. Ctrl-C and SIGTERM (as SystemExit(143), see _stop_on_sigterm) cancel it, wait for it
    to stop within one step, and are raised again, after saying what the partial file at kept_path
    (where given) kept, as the command line (`command`) does."""
    try:
        line = _progress.ProgressLine(job.total, progress)
        with _stop_on_sigterm():
            while not job.wait(_POLL_SECONDS):
                line.update(job.done, job.periods)
        line.finish()
    except BaseException:
        # the job never outlives the call: stopped and waited for before anything else can raise
        job.cancel()
        job.wait(-1)
        with contextlib.suppress(Exception):
            line.finish()
            if kept_path:
                _progress.report_kept(job.kept, job.total, kept_path, command)
        raise


def _thread_count(threads):
    """threads= as the engine takes it: None (0: OMP_NUM_THREADS, else every core) or an integer from 1 to
    4096; anything else (0, a bool, a float, a string) raises ValueError, as --threads is an exit code 2."""
    if threads is None:
        return 0
    if isinstance(threads, bool) or not isinstance(threads, numbers.Integral) or not 1 <= threads <= 4096:
        raise ValueError(f"threads = {threads!r}: must be an integer from 1 to 4096 "
                         "(or None: OMP_NUM_THREADS, else every core)")
    return int(threads)


@contextlib.contextmanager
def _stop_on_sigterm():
    """While a run or scan runs: SIGTERM raises SystemExit(143) (128 + SIGTERM, the command line's exit
    code), so that it stops as on Ctrl-C: the finished members kept, temporary and lock files removed. Only
    in the main thread, and only where SIGTERM would otherwise end the process at once."""
    if threading.current_thread() is not threading.main_thread() or \
            signal.getsignal(signal.SIGTERM) is not signal.SIG_DFL:
        yield
        return

    def stop(number, frame):
        raise SystemExit(128 + number)

    signal.signal(signal.SIGTERM, stop)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, signal.SIG_DFL)


def _output_path(output):
    """A path given as output=, refused when empty like the command line's -o ''."""
    path = os.fspath(output)
    if not path:
        raise ValueError("output='': the output path is empty; give a path, or None to keep the result in memory")
    return path


def open(path, allow_incomplete=False):  # noqa: A001 (rotorsweep.open, like xarray.open_dataset)
    """A result file as an xarray.Dataset.

    Dimensions: the plan's axes rows, rtol, A, g, noise, offset, ic, replica (an axis with one
    value becomes a scalar coordinate, except A and replica; random and exact starts occupy only the
    first noise and offset, the other cells are NaN with plan_index -1), plus row (per-row angles), period
    (observables.period_series), sublattice and attractor_label (/curves/attractors). Variables: every /members column over
    the axes; every /curves column as curve_<name> over the axes but replica; per-period series
    as period_<channel>. Each carries description and units attributes; the file's attributes
    (scene, version, revision, complete, wall_seconds, ...) are the Dataset's. The coordinate
    plan_index gives each member's row in /members; members(ds) stacks the Dataset back into
    plan order. A file that is not complete raises ValueError unless allow_incomplete (a slider's partial
    file then gives its members done), and so does a shard (join the shards with `rotorsweep merge`). A slider
    file (`rotorsweep slider`) gives slider()'s Dataset.
    """
    with _read(os.fspath(path)) as h5file:
        _dataset.check_result_file(h5file)
        try:
            if h5file.attrs.get("kind") in ("slider", b"slider"):
                return _slider.from_hdf5(h5file, allow_incomplete)
            return _dataset.from_hdf5(h5file, allow_incomplete)
        except KeyError as missing:  # a dataset a result file has
            raise ValueError(f"'{h5file.filename}' is not a rotorsweep result: {missing} is missing") from None


def _read(path):
    """An HDF5 file opened for reading; where a run still writes it (it holds HDF5's file lock), without the
    lock: the writer changes only bytes in place and marks a row done once it is written."""
    try:
        return h5py.File(path, "r")
    except OSError as locked:
        if "lock" not in str(locked):
            raise
        return h5py.File(path, "r", locking=False)


def members(dataset):
    """The Dataset stacked into one `member` dimension in plan order (a MultiIndex over the axes); the
    grid's empty cells (noise and offset of random and exact starts) are left out."""
    dims = [axis for axis in _dataset.AXES if axis in dataset.dims]
    stacked = dataset.stack(member=dims)
    return stacked.isel(member=np.flatnonzero(stacked["plan_index"].values >= 0)).sortby("plan_index")


def scene_text(scene):
    """The scene's TOML text as the engine reads it (a dict written out, a file read), validated."""
    text, is_path = _scene.resolve(scene)
    return _core.scene_info(text, is_path)["text"]


def plan_axes(scene):
    """The scene's plan axes (dict: axis name -> values, outermost first), validated."""
    text, is_path = _scene.resolve(scene)
    return _core.plan_axes(text, is_path)
