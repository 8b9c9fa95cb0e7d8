"""Runs `rotorsweep run` on a scene a few times and returns the median wall time and lane
occupancy read back from the result file (shared by ours.py and scaling.py)."""
import statistics
import subprocess

import h5py


def timed_run(rotorsweep, scene, result, threads, repeats, once_above=float("inf")):
    """Median wall_seconds and lane_occupancy over `repeats` runs; a run longer than
    `once_above` seconds is not repeated (its noise is small against its length)."""
    walls, occupancy = [], []
    for _ in range(repeats):
        if walls and walls[0] > once_above:
            break
        run = subprocess.run([rotorsweep, "run", scene, "-o", result, "-q", "--threads", str(threads)],
                             capture_output=True, text=True)
        if run.returncode != 0:
            raise SystemExit(f"error: {scene}: {run.stderr}")
        with h5py.File(result, "r") as f:
            walls.append(f.attrs["wall_seconds"])
            occupancy.append(f.attrs["lane_occupancy"])
    return statistics.median(walls), statistics.median(occupancy)
