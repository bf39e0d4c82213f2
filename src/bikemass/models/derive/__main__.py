"""``python -m bikemass.models.derive [COMBINATION ...]``: derive the model family, write the numeric code.

Every combination of :data:`~bikemass.models.derive.members.COMBINATIONS` (or only those named, e.g.
``rider-lean+tyre``; ``whipple`` is the bicycle alone) is derived and written to
``src/bikemass/models/generated/<module>.py``, replacing what was there; ``nonlinear`` names the
nonlinear Whipple bicycle (:mod:`~bikemass.models.derive.nonlinear`, written to
``nonlinear_whipple.py``), derived too when no name is given.  Prints one line per module.
"""

import argparse
import sys
import time
from pathlib import Path

from ..registry import module_name, parse_model
from .build import derive
from .codegen import module_source
from .members import COMBINATIONS, members
from .nonlinear import MODULE as NONLINEAR_MODULE
from .nonlinear import derive_nonlinear, module_source_nonlinear

GENERATED = Path(__file__).resolve().parent.parent / "generated"


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python -m bikemass.models.derive", description=__doc__.split("\n")[0])
    parser.add_argument("combinations", nargs="*", help="e.g. whipple, rider-lean, tyre, rider-lean+tyre, nonlinear (default: all)")
    parser.add_argument("--out", type=Path, default=GENERATED, help="folder to write to (default: %(default)s)")
    args = parser.parse_args(argv)
    nonlinear = not args.combinations or "nonlinear" in args.combinations
    named = [c for c in args.combinations if c != "nonlinear"]
    wanted = [parse_model(c).members for c in named] or ([] if args.combinations else list(COMBINATIONS))
    if nonlinear:
        start = time.perf_counter()
        path = args.out / f"{NONLINEAR_MODULE}.py"
        path.write_text(module_source_nonlinear(derive_nonlinear()), encoding="utf-8")
        print(f"{path}: {time.perf_counter() - start:.1f} s", file=sys.stdout)
    for names in wanted:
        start = time.perf_counter()
        source = module_source(derive(members(names)))
        path = args.out / f"{module_name(names)}.py"
        path.write_text(source, encoding="utf-8")
        print(f"{path}: {time.perf_counter() - start:.1f} s", file=sys.stdout)
    return 0


if __name__ == "__main__":
    sys.exit(main())
