"""The command line every study under scripts/studies/ shares (docs/studies.md): --quick, --out (its figure
under docs/figures/), --python (the rotorsweep module's directory, default build/python) and --threads."""

import argparse
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]


def parse(doc, figure, quick_help):
    """The study's arguments and the rotorsweep module imported from --python."""
    parser = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--quick", action="store_true", help=quick_help)
    parser.add_argument("--out", type=pathlib.Path, default=ROOT / "docs" / "figures" / figure)
    parser.add_argument("--python", type=pathlib.Path, default=ROOT / "build" / "python",
                        help="directory of the rotorsweep Python module")
    parser.add_argument("--threads", type=int, default=2)
    args = parser.parse_args()
    sys.path.insert(0, str(args.python))
    import rotorsweep

    return args, rotorsweep


def save(figure, out, dpi):
    """Lays the study's figure out and writes it to `out` (its directory made)."""
    figure.tight_layout()
    out.parent.mkdir(parents=True, exist_ok=True)
    figure.savefig(out, dpi=dpi)
    print(f"\nwrote {out}")
