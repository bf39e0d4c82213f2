"""Run the whole hostile corpus outside pytest and print the counts the issue asks for.

    PYTHONPATH=src:tests /usr/bin/time -v python -m hostile.run_corpus

Prints one line per case that breaks its promise, then: clean errors (exit 2, one line),
warnings (exit 0, warning lines), tracebacks, hangs, other failures, the slowest case and
the peak resident memory of this process (the whole corpus, so an upper bound on the
worst case).
"""

import resource
import sys
import tempfile

from .corpus import check, load_cases


def main():
    counts = {"clean errors": 0, "warnings": 0, "tracebacks": 0, "hangs": 0, "other failures": 0}
    slowest = (0.0, "")
    for case in load_cases():
        with tempfile.TemporaryDirectory() as folder:
            outcome, problems = check(case, folder)
        slowest = max(slowest, (outcome.seconds, case["id"]))
        if outcome.hung:
            counts["hangs"] += 1
        elif outcome.crash or "Traceback" in outcome.stderr or "internal error" in outcome.stderr:
            counts["tracebacks"] += 1
        elif problems:
            counts["other failures"] += 1
        elif case["exit"] == 2:
            counts["clean errors"] += 1
        else:
            counts["warnings"] += 1
        if problems:
            print(f"FAIL {case['id']}: {problems}")
    peak_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    print(f"{len(load_cases())} cases: " + ", ".join(f"{k} {v}" for k, v in counts.items()))
    print(f"slowest case: {slowest[1]} ({slowest[0]:.2f} s); peak memory of the whole run: {peak_mb:.0f} MB")
    return 1 if counts["tracebacks"] or counts["hangs"] or counts["other failures"] else 0


if __name__ == "__main__":
    sys.exit(main())
