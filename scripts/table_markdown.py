#!/usr/bin/python3
"""The paper's reference table as docs/numerics.md prints it, from the binary: runs `rotorsweep table
-o CSV` and prints a Markdown table of W, S, R beside the paper's W, S, R with R/paper − 1, the steps
per period, R's error and what it is, so that the documented table can be regenerated rather than edited.
Usage: table_markdown.py [--rotorsweep build/bin/rotorsweep] [--stepper rodas4p2] [--rtol 1e-9]
                         [--disorder SIGMA]"""
import argparse
import csv
import pathlib
import subprocess
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[1]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rotorsweep", default=str(ROOT / "build/bin/rotorsweep"))
    parser.add_argument("--stepper", default="rodas4p2")
    parser.add_argument("--rtol", default="1e-9")
    parser.add_argument("--disorder", default="0", help="σ_A of the table's quenched disorder (0: none)")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as scratch:
        path = pathlib.Path(scratch) / "table.csv"
        footer = subprocess.run([args.rotorsweep, "table", "--stepper", args.stepper, "--rtol", args.rtol, "--replicas", "1",
                                 "--disorder", args.disorder, "-o", str(path)],
                                check=True, capture_output=True, text=True).stdout.splitlines()[-1]
        rows = list(csv.DictReader(line for line in path.open() if not line.startswith("#")))  # past provenance
    print("| A | IC | W | S | R | paper W | paper S | paper R | R/paper − 1 | steps/period | R error | R error is |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['A']} | {r['ic']} | {float(r['W']):.7e} | {float(r['S']):.7e} | {float(r['R']):.7e} "
              f"| {float(r['paper_W']):.6e} | {float(r['paper_S']):.6e} | {float(r['paper_R']):.6e} "
              f"| {float(r['relative_deviation']):.1e} | {float(r['steps_per_period']):.0f} "
              f"| {float(r['R_error']):.1e} | {r['R_error_kind']} |")
    print(f"\n({footer.strip()})")


if __name__ == "__main__":
    main()
