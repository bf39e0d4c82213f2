"""Every name of the facade (``bikemass.__all__``) is documented in numpydoc, and its Examples run.

* Every function's docstring has the sections Parameters, Returns, Raises, See Also and Examples;
  every class's has Examples; every function's signature is annotated (the API reference shows
  typed signatures); every name has a one-line summary.
* The Examples of every function and class (and of a class's own methods) are doctests, run here
  in a scratch folder, with ELLIPSIS and NORMALIZE_WHITESPACE. Their printed numbers are rounded
  to the digits they show, and where a published value exists the example shows that (Meijaard et
  al. 2007's weave speed, Table 2's eigenvalues, the maker's chart of the BMC, ...).
* No public function names a thing with another keyword than the others do: a rear-frame
  stiffness is ``stiffness=``, a bicycle ``bicycle=`` (the old ``S=`` and ``bike=`` still work,
  with a DeprecationWarning).
"""

import doctest
import inspect
import warnings

import numpy as np
import pytest

import bikemass as bm

SECTIONS = ("Parameters", "Returns", "Raises", "See Also", "Examples")
"""The numpydoc sections every facade function's docstring has."""

FLAGS = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE

NAMES = [n for n in bm.__all__ if n != "__version__"]
FUNCTIONS = [n for n in NAMES if inspect.isfunction(getattr(bm, n))]
CLASSES = [n for n in NAMES if inspect.isclass(getattr(bm, n))]


def sections(doc):
    """The numpydoc section titles of docstring ``doc`` (a title underlined with dashes)."""
    lines = doc.splitlines()
    return {a.strip() for a, b in zip(lines, lines[1:]) if b.strip() and set(b.strip()) == {"-"}
            and len(b.strip()) == len(a.strip())}


def doctests(name):
    """The doctests of public ``name``: its own docstring's and, for a class, its own methods'."""
    value = getattr(bm, name)
    finder = doctest.DocTestFinder(recurse=False, exclude_empty=True)
    found = finder.find(value, f"bm.{name}", globs={})
    if inspect.isclass(value):
        for attribute, member in vars(value).items():
            if inspect.isfunction(member) or isinstance(member, property):
                target = member.fget if isinstance(member, property) else member
                found += finder.find(target, f"bm.{name}.{attribute}", globs={})
    return [t for t in found if t.examples]


def test_every_public_name_is_documented_and_counted():
    assert len(NAMES) == len(FUNCTIONS) + len(CLASSES) + 1          # PARAMETER_NAMES: data
    for name in NAMES:
        doc = inspect.getdoc(getattr(bm, name)) if name != "PARAMETER_NAMES" else "the 26 names"
        assert doc and doc.split("\n\n")[0].strip(), f"bm.{name} has no summary line"


@pytest.mark.parametrize("name", FUNCTIONS)
def test_function_docstring_has_the_numpydoc_sections_and_a_typed_signature(name):
    function = getattr(bm, name)
    missing = [s for s in SECTIONS if s not in sections(inspect.getdoc(function))]
    assert not missing, f"bm.{name}: no {', '.join(missing)} section"
    signature = inspect.signature(function)
    untyped = [p.name for p in signature.parameters.values() if p.annotation is inspect.Parameter.empty]
    assert not untyped and signature.return_annotation is not inspect.Signature.empty, \
        f"bm.{name}: unannotated {untyped or 'return'}"


@pytest.mark.parametrize("name", CLASSES)
def test_class_docstring_has_examples(name):
    assert "Examples" in sections(inspect.getdoc(getattr(bm, name))), f"bm.{name}: no Examples section"


@pytest.mark.parametrize("name", FUNCTIONS + CLASSES)
def test_examples_run(name, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    tests = doctests(name)
    assert tests, f"bm.{name}: no doctest"
    runner = doctest.DocTestRunner(optionflags=FLAGS)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", bm.BikemassWarning)        # examples that show warnings catch them
        for test in tests:
            runner.run(test, out=lambda text: pytest.fail(f"{test.name}:\n{text}"))
    assert runner.failures == 0 and runner.tries > 0


def test_the_doctests_are_counted():
    """How many examples run (the report quotes it): at least one per function and class."""
    count = sum(len(t.examples) for name in FUNCTIONS + CLASSES for t in doctests(name))
    assert count >= len(FUNCTIONS) + len(CLASSES)
    print(f"{count} doctest examples in {len(FUNCTIONS) + len(CLASSES)} docstrings")


def test_one_keyword_vocabulary():
    """The same thing has the same keyword in every public function."""
    used = {p for n in FUNCTIONS for p in inspect.signature(getattr(bm, n)).parameters}
    assert not used & {"S", "bike", "K", "material_name"}, used & {"S", "bike", "K", "material_name"}


def test_old_keywords_still_work_with_a_deprecation_warning():
    p = bm.parameters("benchmark")
    S = np.array([[6702.3435, 1237.0288], [1237.0288, 3634.7088]])
    with pytest.warns(DeprecationWarning, match=r"sensitivity\(S=...\) is deprecated; use stiffness="):
        old = bm.sensitivity(p, S=S, names=("c",))
    new = bm.sensitivity(p, stiffness=S, names=("c",))
    assert old.weave_speed == pytest.approx(new.weave_speed, abs=0) and old.d_stiffness is not None
    with pytest.warns(DeprecationWarning, match=r"uncertainty\(bike=...\) is deprecated; use bicycle="):
        spread = bm.uncertainty(bike="benchmark", spreads={"c": 0.001})
    assert spread.speeds["weave_speed"].nominal == pytest.approx(4.2923825363411040, abs=1e-9)  # Meijaard 2007
    with pytest.raises(TypeError, match="both S= and stiffness="):
        bm.sensitivity(p, S=S, stiffness=S)
