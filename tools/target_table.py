"""Print the target-cost table of docs/target.md: instructions per frame of
every gallery scene (and optionally the hard cases) on the no-FPU target.

    python tools/target_table.py [--size 96x72] [--hard]

Needs the target (gles.target.target_available()).
"""

from __future__ import annotations

import argparse
import sys

from gles import target
from gles.gallery import GALLERY
from gles.hardcases import HARD_CASES


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--size", default="96x72")
    parser.add_argument("--hard", action="store_true", help="the hard cases too")
    args = parser.parse_args()
    why = target.target_missing()
    if why is not None:
        print(why, file=sys.stderr)
        return 1
    w, h = (int(v) for v in args.size.split("x"))
    scenes = [(name, scene) for name, (_, scene) in GALLERY.items()]
    if args.hard:
        scenes += [(name, case.scene) for name, case in HARD_CASES.items()]
    print(f"| scene ({w}x{h}) | fixed (instructions) | float (instructions) | fixed / float |")
    print("|---|---:|---:|---:|")
    for name, scene in scenes:
        fixed = target.target_cost(scene, "fixed", (w, h))
        flt = target.target_cost(scene, "float", (w, h))
        print(f"| {name} | {fixed:,} | {flt:,} | {fixed / flt:.2f} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
