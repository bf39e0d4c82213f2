"""``python -m bikemass.models.derive [COMBINATION ...]``: derive the model family, write the numeric code.

Every combination of :data:`~bikemass.models.derive.members.COMBINATIONS` (or only those named, e.g.
``rider-lean+tyre``; ``whipple`` is the bicycle alone) is derived and written to
``src/bikemass/models/generated/<module>.py``, replacing what was there.  Prints one line per module.
"""

import argparse
import sys
import time
from pathlib import Path

from ..registry import module_name, parse_model
from .build import derive
from .codegen import module_source
from .members import COMBINATIONS, members

GENERATED = Path(__file__).resolve().parent.parent / "generated"


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python -m bikemass.models.derive", description=__doc__.split("\n")[0])
    parser.add_argument("combinations", nargs="*", help="e.g. whipple, rider-lean, tyre, rider-lean+tyre (default: all)")
    parser.add_argument("--out", type=Path, default=GENERATED, help="folder to write to (default: %(default)s)")
    args = parser.parse_args(argv)
    wanted = [parse_model(c).members for c in args.combinations] or list(COMBINATIONS)
    for names in wanted:
        start = time.perf_counter()
        source = module_source(derive(members(names)))
        path = args.out / f"{module_name(names)}.py"
        path.write_text(source, encoding="utf-8")
        print(f"{path}: {time.perf_counter() - start:.1f} s", file=sys.stdout)
    return 0


if __name__ == "__main__":
    sys.exit(main())
