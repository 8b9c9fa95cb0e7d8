#!/usr/bin/python3
"""Work-precision report: error of D against the stored reference (relative; max and median over
the members whose reference regime is not CP, CP members separately) against wall time per
member, for every method and tolerance in the given CSVs (ours.py, peers.py, cvode_members).
Writes a log-log plot, a CSV table per (method, rtol), the speed ratios at matched error (each
method's time over the fastest of our steppers at that error), and our steppers' step attempts per
member at matched error: a cost that does not depend on the machine or its load, for comparing
settings of one stepper (the cost of an attempt differs between steppers).
Usage: work_precision.py REFERENCE.csv OUT_DIR RESULTS.csv [RESULTS.csv ...]"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

OURS = ("rodas4", "rodas4p2", "rodas5p", "ros2", "dopri5", "rodas4+pi", "rodas4p2+pi", "rodas5p+pi")
# (measure, error): the max is bounded below by the reference's own spread (~3e-8, reference.csv),
# so the tight target uses the median
TARGETS = (("max_error", 1e-4), ("max_error", 1e-6), ("median_error", 1e-4), ("median_error", 1e-8))


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def summarise(reference, rows):
    ref = {int(r["member"]): r for r in reference}
    groups = {}
    for r in rows:
        groups.setdefault((r["method"], float(r["rtol"])), []).append(r)
    table = []
    for (method, rtol), members in sorted(groups.items()):
        err = {"settled": [], "CP": []}
        for r in members:
            truth = ref[int(r["member"])]
            D, D_ref = float(r["D"]), float(truth["D"])
            e = abs(D / D_ref - 1) if np.isfinite(D) else np.inf
            err["CP" if truth["regime"] == "CP" else "settled"].append(e)
        seconds = np.median([float(r["seconds"]) for r in members])
        attempts = np.mean([float(r["steps"]) for r in members]) if "steps" in members[0] else np.nan
        table.append(dict(method=method, rtol=rtol, members=len(members), seconds_per_member=seconds,
                          attempts_per_member=attempts,
                          max_error=max(err["settled"], default=np.nan),
                          median_error=float(np.median(err["settled"])) if err["settled"] else np.nan,
                          cp_median_error=float(np.median(err["CP"])) if err["CP"] else np.nan,
                          cp_max_error=max(err["CP"], default=np.nan)))
    return table


def time_at_error(points, target):
    """Cost (time or attempts) per member at error = target, interpolated in log-log between
    ladder rungs (the cheapest rung reaching the target if none is above it); None if never
    reached."""
    points = sorted((e, t) for e, t in points if np.isfinite(e) and e > 0)
    reached = [(e, t) for e, t in points if e <= target]
    if not reached:
        return None
    best = min(t for _, t in reached)
    above = [(e, t) for e, t in points if e > target]
    for (e1, t1) in reached:
        for (e0, t0) in above:
            if t0 < t1:  # a looser rung, cheaper: interpolate between the two
                w = (np.log(target) - np.log(e0)) / (np.log(e1) - np.log(e0))
                best = min(best, float(np.exp(np.log(t0) + w * (np.log(t1) - np.log(t0)))))
    return best


def main(reference_path, out_dir, result_paths):
    os.makedirs(out_dir, exist_ok=True)
    reference = read_csv(reference_path)
    rows = [r for p in result_paths for r in read_csv(p)]
    table = summarise(reference, rows)
    with open(os.path.join(out_dir, "work_precision.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(table[0]))
        writer.writeheader()
        writer.writerows(table)

    methods = sorted({t["method"] for t in table}, key=lambda m: (m not in OURS, m))
    fig, axes = plt.subplots(1, 2, figsize=(12, 5), sharex=True)
    for ax, measure, label in ((axes[0], "max_error", "max"), (axes[1], "median_error", "median")):
        for method in methods:
            pts = sorted(((t["seconds_per_member"], t[measure], t["rtol"]) for t in table if t["method"] == method),
                         key=lambda p: p[2], reverse=True)
            style = "-o" if method in OURS else "--s"
            ax.loglog([p[0] * 1e3 for p in pts], [max(p[1], 1e-16) for p in pts], style, ms=4,
                      label=f"{method} (rotorsweep, 1 thread)" if method in OURS else method)
        ax.set_xlabel("wall time per member [ms]  (N = 20, 4 drive periods)")
        ax.set_ylabel(f"{label} relative error of D over the non-CP members")
        ax.grid(alpha=0.3, which="both")
    axes[0].legend(fontsize=8)
    fig.suptitle("work-precision on the 40 reference members (g = 0.0011 and 1e-4); one point per rtol",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "work_precision.png"), dpi=120)

    heads = [f"{'max' if m == 'max_error' else 'median'} {e:g}" for m, e in TARGETS]
    lines = ["| method | " + " | ".join(f"ms/member, {h}" for h in heads) + " | " +
             " | ".join(f"÷ ours, {h}" for h in heads) + " |", "|---" * (1 + 2 * len(TARGETS)) + "|"]
    times = {m: [time_at_error([(t[measure], t["seconds_per_member"]) for t in table if t["method"] == m], e)
                 for measure, e in TARGETS] for m in methods}
    best = [min((times[m][k] for m in OURS if m in times and times[m][k]), default=None) for k in range(len(TARGETS))]
    for m in methods:
        cells = [f"{t * 1e3:.3g}" if t else "not reached" for t in times[m]]
        ratios = [f"{t / r:.3g}" if t and r else "—" for t, r in zip(times[m], best)]
        lines.append(f"| {m} | " + " | ".join(cells) + " | " + " | ".join(ratios) + " |")
    lines += ["", "| our method | " + " | ".join(f"step attempts/member, {h}" for h in heads) + " |",
              "|---" * (1 + len(TARGETS)) + "|"]
    for m in (m for m in methods if m in OURS):
        attempts = [time_at_error([(t[measure], t["attempts_per_member"]) for t in table if t["method"] == m], e)
                    for measure, e in TARGETS]
        lines.append(f"| {m} | " + " | ".join(f"{a:.4g}" if a else "not reached" for a in attempts) + " |")
    with open(os.path.join(out_dir, "matched_error.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    print(f"wrote {out_dir}/work_precision.png, work_precision.csv, matched_error.md")


if __name__ == "__main__":
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2], sys.argv[3:])
