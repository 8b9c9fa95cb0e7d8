#!/usr/bin/python3
"""The numbers README.md and docs/ quote for the examples, regenerated from runs of them. Each quoted
number is declared once below: the file, the words around it (a regular expression whose one group
is the number) and how it is computed from a run of the example it describes. Numbers quoted in
several places share one declaration, so they cannot disagree.

  quoted_figures.py --check     exit 1 listing every quoted number that is not what the runs give
  quoted_figures.py --write     put what the runs give into the text
  quoted_figures.py --write --timings   also measure the quoted run times (medians of --repeats)

Run times are never checked against a measurement (they depend on the machine); --check only checks
that every place quoting one run time says the same. Sources, each run once: the demo
(examples/friction_curve.toml), `rotorsweep table` (its defaults, CSV and draws), the paper's own table
(its W, S, R in the table's CSV), the experiment's slider scan (examples/experiment_7x7.toml).
Usage: quoted_figures.py [--check|--write] [--timings] [--only SOURCE,...] [--rotorsweep build/bin/rotorsweep]
                         [--docs DIR (a copy of the project's README.md and docs/; default: the project)]"""
import argparse
import csv
import functools
import pathlib
import re
import subprocess
import sys
import tempfile
import time

import h5py
import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]


class Runs:
    """The example runs, each made once, on demand."""

    def __init__(self, executable, workdir, threads, repeats=5):
        self.exe, self.workdir, self.threads, self.repeats = executable, pathlib.Path(workdir), threads, repeats

    def run(self, *arguments):
        return subprocess.run([self.exe, *arguments], check=True, capture_output=True, text=True)

    def example(self, command, scene, shadows=True):
        """The result file of `rotorsweep COMMAND examples/SCENE` (without shadows: global_error "local",
        where no quoted number depends on them)."""
        out = self.workdir / (pathlib.Path(scene).stem + ".h5")
        path = ROOT / "examples" / scene
        if not shadows:
            path = self.workdir / scene
            path.write_text((ROOT / "examples" / scene).read_text().replace(
                "[numerics]\n", "[numerics]\nglobal_error = \"local\"\n"))
        self.run(command, str(path), "-o", str(out), "-q", "--force", "--threads", str(self.threads))
        return out

    @functools.cached_property
    def demo(self):
        with h5py.File(self.example("run", "friction_curve.toml")) as f:
            m = f["members"]
            return {k: (m[k].asstr()[()] if m[k].dtype.kind in "SO" else m[k][()]) for k in
                    ("A", "regime", "slips_per_period", "status", "symmetry_limited", "shadow_departed")}

    @functools.cached_property
    def table(self):
        out = self.workdir / "table.csv"
        # W and S outside CP (the --estimator-rtol run) are quoted nowhere here: a looser run saves its time
        printed = self.run("table", "--estimator-rtol", "1e-9", "-o", str(out)).stdout
        with open(out, newline="") as f:
            rows = list(csv.DictReader(line for line in f if not line.startswith("#")))  # past provenance
        below = printed[printed.index("CP entries over"):]  # the noise draws' lines, after the table
        draws = [line.split() for line in below.splitlines() if re.match(r"\s+[68]\s+A?FM\s+\d", line)]
        return {"rows": rows, "draws": draws}

    @functools.cached_property
    def slider(self):
        with h5py.File(self.example("slider", "experiment_7x7.toml", shadows=False)) as f:
            h = f["members/separation"][:] * 1e3
            time_axis = f["series/time"][:]
            late = time_axis > 2.5
            window_force = np.nanmean(f["series/friction"][:][:, late], axis=1)
            window_order = np.nanmean(f["series/order_y"][:][:, late], axis=1)
            friction = f["members/friction"][:]
        at = [int(np.argmin(np.abs(h - target))) for target in (6.5, 8.5, 11.0)]
        return {"window_force": window_force[at], "window_order": window_order[at], "friction": friction[at]}

    def seconds(self, scenes, command="run", repeats=5):
        """The median wall time of `rotorsweep COMMAND SCENE` for each scene (text) over `repeats` runs
        of each, the scenes alternating."""
        paths = []
        for k, scene in enumerate(scenes):
            paths.append(self.workdir / f"timed{k}.toml")
            paths[-1].write_text(scene)
        times = [[] for _ in scenes]
        for _ in range(repeats):
            for path, taken in zip(paths, times):
                start = time.perf_counter()
                self.run(command, str(path), "-o", str(self.workdir / "timed.h5"), "-q", "--force", "--threads",
                         str(self.threads))
                taken.append(time.perf_counter() - start)
        return [float(np.median(taken)) for taken in times]

    @functools.cached_property
    def timings(self):
        """Median run times: the demo with its shadow runs and with the local estimate alone (alternating),
        and the slider's scan over speeds."""
        demo = (ROOT / "examples/friction_curve.toml").read_text()
        local = demo.replace("[numerics]\n", '[numerics]\nglobal_error = "local"\n')
        shadow_seconds, local_seconds = self.seconds([demo, local], repeats=self.repeats)
        velocity, = self.seconds([(ROOT / "examples/friction_velocity.toml").read_text()], "slider", self.repeats)
        return {"demo": shadow_seconds, "demo_local": local_seconds, "velocity": velocity}


def significant(x, digits=2):
    return f"{x:.{digits}g}"


def scientific(x):
    """1.3e-3, as the docs write small numbers."""
    mantissa, exponent = f"{x:.1e}".split("e")
    return f"{mantissa}e{int(exponent)}"


def percent(x):
    """A percentage: one decimal from 1 % on, two significant digits below."""
    return f"{x:.1f}" if x >= 1 else significant(x)


def percent_range(values):
    return f"{percent(100 * min(values))}–{percent(100 * max(values))}"


def force(x):
    """A friction in N as the docs write it: three decimals, two significant digits below 0.01 N."""
    return f"{x:.3f}" if x >= 0.01 else significant(x)


def demo_regime_edges(runs):
    """'AFM up to A ≈ x, CP to A ≈ y': where the labels change, halfway between the last AFM member and
    the first CP member above it, and between the last CP member and the first FM member above it."""
    d = runs.demo
    A, regime = d["A"], d["regime"]
    afm_end = A[regime == "AFM"].max()
    cp_end = A[regime == "CP"].max()
    return (afm_end + A[A > afm_end].min()) / 2, (cp_end + A[A > cp_end].min()) / 2


def demo_cp_slips(runs):
    """The slips per period of the demo's CP members: the common count, and the exceptions by count."""
    d = runs.demo
    cp = d["regime"] == "CP"
    A, counts = d["A"][cp], d["slips_per_period"][cp]
    common = float(np.median(counts))
    text = f"{common:g} slips per period in CP"
    others = sorted(set(counts[counts != common]))
    if others:
        text += " (" + "; ".join(f"{n:g} at A = " + ", ".join(f"{a:.2f}" for a in A[counts == n])
                                 for n in others) + ")"
    return text


def table_entries(runs, A):
    return [row for row in runs.table["rows"] if float(row["A"]) == A]


def table_deviation(runs, A):
    return percent_range([abs(float(row["relative_deviation"])) for row in table_entries(runs, A)])


def estimator_spread(rows, prefix=""):
    """The largest |W − R| or |S − R| over R among the CP entries (the paper's, with prefix 'paper_')."""
    cp = [row for row in rows if float(row["A"]) in (6.0, 8.0)]
    return max(abs(float(row[prefix + x]) / float(row[prefix + "R"]) - 1) for row in cp for x in ("W", "S"))


def draws_range(runs):
    """Where the paper's value lies in units of the draws' spread: |(paper − mean)/sd| over the CP entries."""
    values = [abs(float(fields[5])) for fields in runs.table["draws"]]
    return f"{min(values):.2f}–{max(values):.2f}"


#: (file, pattern with one group, source, value) for every quoted number; timing figures are marked.
FIGURES = [
    ("README.md", r"For the demo scene this gives AFM up to A ≈ ([0-9.]+),", "demo",
     lambda r: f"{demo_regime_edges(r)[0]:.1f}"),
    ("README.md", r"For the demo scene this gives AFM up to A ≈ [0-9.]+, CP to A ≈ ([0-9.]+)", "demo",
     lambda r: f"{demo_regime_edges(r)[1]:.1f}"),
    ("README.md", r"and FM above, with ([\s\S]*?)\. With N = 20", "demo", demo_cp_slips),
    ("docs/numerics.md", r"`examples/friction_curve.toml`, 281 members, (\d+) CP\)", "demo",
     lambda r: str(int((r.demo["regime"] == "CP").sum()))),
    ("docs/cli.md", r"inside it\s+by ([0-9.–]+) % \(A = 6\)", "table", lambda r: table_deviation(r, 6.0)),
    ("docs/cli.md", r"\(A = 6\) and ([0-9.–]+) % \(A = 8\)", "table", lambda r: table_deviation(r, 8.0)),
    ("docs/cli.md", r"paper's do \(by up to ([0-9.e-]+) here", "table",
     lambda r: scientific(estimator_spread(r.table["rows"]))),
    ("docs/numerics.md", r"differ from each other \(by up to ([0-9.e-]+) at A = 8 FM\)", "table",
     lambda r: scientific(estimator_spread(r.table["rows"]))),
    ("docs/cli.md", r"here, ([0-9.]+) % in the paper\)", "table",
     lambda r: significant(100 * estimator_spread(r.table["rows"], "paper_"))),
    ("docs/model.md", r"the paper's own three estimators differ there by up to ([0-9.]+) %", "table",
     lambda r: significant(100 * estimator_spread(r.table["rows"], "paper_"))),
    ("docs/numerics.md", r"paper's three do \(by up to ([0-9.]+) %\)", "table",
     lambda r: significant(100 * estimator_spread(r.table["rows"], "paper_"))),
    ("docs/cli.md", r"in units of the spread \(([0-9.–]+) below the mean", "table", draws_range),
    ("docs/slider.md", r"come out\s+as ([0-9., N−-]+?) and [0-9.]+, [0-9.]+, [−-][0-9.]+ \(", "slider",
     lambda r: ", ".join(force(x) for x in r.slider["window_force"]) + " N"),
    ("docs/slider.md", r"over its averaged periods — the same window —, gives ([0-9., N]+)\)", "slider",
     lambda r: ", ".join(force(x) for x in r.slider["friction"]) + " N"),
    ("docs/model.md", r"the same window ([0-9.]+ N and [0-9.]+, [0-9.]+ N and\s+[0-9.]+, [0-9.]+ N and [−-][0-9.]+)",
     "slider", lambda r: "{} N and {:.3f}, {} N and {:.3f}, {} N and −{:.3f}".format(
         force(r.slider["window_force"][0]), r.slider["window_order"][0], force(r.slider["window_force"][1]),
         r.slider["window_order"][1], force(r.slider["window_force"][2]), -r.slider["window_order"][2])),
    ("docs/model.md", r"over its averaged periods, the same window \(([0-9., N]+)\)", "slider",
     lambda r: ", ".join(force(x) for x in r.slider["friction"]) + " N"),
]

#: run times, each quoted in one or more places: (places as (file, pattern), value)
TIMINGS = [
    ([("docs/performance.md", r"the demo's 281 members\s+take ([0-9.]+) s"),
      ("docs/numerics.md", r"281 members, \d+ CP\) takes ([0-9.]+) s against")],
     lambda r: f"{r.timings['demo']:.3g}"),
    ([("docs/numerics.md", r"takes [0-9.]+ s against ([0-9.]+) s with")], lambda r: f"{r.timings['demo_local']:.3g}"),
    ([("docs/numerics.md", r"2 threads, this machine\): ([0-9.]+)×")],
     lambda r: f"{r.timings['demo'] / r.timings['demo_local']:.2f}"),
    ([("README.md", r"examples/friction_velocity.toml\s+# 17 speeds × 3 separations, ([0-9.]+) s"),
      ("docs/performance.md", r"four periods each\) takes ([0-9.]+) s with its shadow runs")],
     lambda r: f"{r.timings['velocity']:.2g}"),
]


def find(docs, path, pattern):
    text = (docs / path).read_text()
    found = list(re.finditer(pattern, text))
    if len(found) != 1:
        sys.exit(f"{path}: the pattern {pattern!r} matches {len(found)} times (it must match once)")
    return text, found[0]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rotorsweep", default=str(ROOT / "build/bin/rotorsweep"))
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--check", action="store_true", help="exit 1 if a quoted number differs")
    parser.add_argument("--write", action="store_true", help="write the numbers the runs give into the text")
    parser.add_argument("--timings", action="store_true", help="with --write: also measure the run times")
    parser.add_argument("--repeats", type=int, default=5, help="runs per measured time (their median)")
    parser.add_argument("--only", default="", help="sources to run (demo, table, slider), comma-separated")
    parser.add_argument("--docs", default=str(ROOT), help="the directory holding README.md and docs/")
    args = parser.parse_args()
    docs = pathlib.Path(args.docs)
    sources = set(args.only.split(",")) if args.only else {"demo", "table", "slider"}
    with tempfile.TemporaryDirectory() as workdir:
        runs = Runs(args.rotorsweep, workdir, args.threads, args.repeats)
        drifted = []
        for path, pattern, source, value in FIGURES:
            if source not in sources:
                continue
            text, match = find(docs, path, pattern)
            quoted, now = match.group(1), value(runs)
            if " ".join(quoted.split()) != now:  # a quoted number may wrap across lines
                drifted.append(f"{path}: quoted {quoted!r}, the run gives {now!r} ({pattern})")
                if args.write:
                    (docs / path).write_text(text[:match.start(1)] + now + text[match.end(1):])
        for places, value in TIMINGS:
            quoted = {find(docs, path, pattern)[1].group(1) for path, pattern in places}
            if args.write and args.timings:
                now = value(runs)
                for path, pattern in places:
                    text, match = find(docs, path, pattern)
                    (docs / path).write_text(text[:match.start(1)] + now + text[match.end(1):])
            elif len(quoted) > 1:
                drifted.append(f"{' and '.join(p for p, _ in places)} quote different times for one run: "
                               f"{sorted(quoted)}")
    for line in drifted:
        print(line)
    print(f"{len(drifted)} quoted numbers {'rewritten' if args.write else 'differ'}")
    sys.exit(1 if drifted and args.check else 0)


if __name__ == "__main__":
    main()
