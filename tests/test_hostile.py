"""The hostile corpus (tests/hostile/cases.yaml): every malformed or absurd input gets one clear
line and exit status 2 (or a warning where it is legal), never a traceback, a hang, or a file
left behind."""

import pytest

from hostile.corpus import check, load_cases

CASES = load_cases()


def test_corpus_is_big_and_ids_unique():
    ids = [c["id"] for c in CASES]
    assert len(ids) == len(set(ids))
    assert len(CASES) >= 150


@pytest.mark.parametrize("case", CASES, ids=[c["id"] for c in CASES])
def test_case(case, tmp_path):
    outcome, problems = check(case, tmp_path)
    assert not problems, f"{problems}\nstderr: {outcome.stderr[-2000:]}\nstdout: {outcome.stdout[-500:]}"
