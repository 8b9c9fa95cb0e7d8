#!/usr/bin/python3
"""Throughput and scaling of `rotorsweep run`: wall time per member against N (2 … 512), against
the number of members (1 … 16384, lane refill on and off), against threads (1, 2), with lane
occupancy; and the demo scene's wall time. Medians of --repeats runs (one run above 4096 members).
Usage: scaling.py ROTORSWEEP OUT_DIR [--repeats 3]"""
import argparse
import os

from timed_run import timed_run

SCENE = """[model]
rows = {rows}
[drive]
g = [0.0011]
[sweep]
A = {{ from = 0.5, to = 14, count = {count} }}
[initial]
kinds = ["AFM"]
[schedule]
refill = {refill}
[numerics]
rtol = 1e-6
"""


def case(args, name, rows, count, refill, threads):
    path = os.path.join(args.out_dir, "scenes", f"{name}.toml")
    with open(path, "w") as f:
        f.write(SCENE.format(rows=rows, count=count, refill=str(refill).lower()))
    repeats = args.repeats if count <= 4096 else 1
    wall, occupancy = timed_run(args.rotorsweep, path, path[:-5] + ".h5", threads, repeats)
    row = dict(case=name, rows=rows, members=count, refill=refill, threads=threads, wall_s=wall,
               ms_per_member=1e3 * wall / count, lane_occupancy=occupancy)
    print(f"{name}: {row['ms_per_member']:.3g} ms/member, occupancy {occupancy:.1%}", flush=True)
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("rotorsweep")
    parser.add_argument("out_dir")
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    os.makedirs(os.path.join(args.out_dir, "scenes"), exist_ok=True)
    rows = []
    for n in (2, 8, 32, 128, 512):
        rows.append(case(args, f"rows_{n}", n, 64, True, 1))
    for count in (1, 16, 256, 4096, 16384):
        for refill in (True, False):
            rows.append(case(args, f"members_{count}_refill_{refill}", 20, count, refill, 2))
    for threads in (1, 2):
        rows.append(case(args, f"threads_{threads}", 20, 4096, True, threads))
    demo = os.path.join(args.out_dir, "scenes", "demo.h5")
    wall, occupancy = timed_run(args.rotorsweep, "examples/friction_curve.toml", demo, 2, max(args.repeats, 5))
    rows.append(dict(case="demo", rows=20, members=281, refill=True, threads=2, wall_s=wall,
                     ms_per_member=1e3 * wall / 281, lane_occupancy=occupancy))
    print(f"demo: {wall:.3g} s, occupancy {occupancy:.1%}")
    with open(os.path.join(args.out_dir, "scaling.md"), "w") as f:
        f.write("| case | N | members | refill | threads | wall [s] | ms per member | lane occupancy |\n")
        f.write("|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            f.write(f"| {r['case']} | {r['rows']} | {r['members']} | {r['refill']} | {r['threads']} | "
                    f"{r['wall_s']:.3g} | {r['ms_per_member']:.3g} | {r['lane_occupancy']:.1%} |\n")
    print(f"wrote {args.out_dir}/scaling.md")


if __name__ == "__main__":
    main()
