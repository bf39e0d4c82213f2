"""The ``bicycleparameters`` export read by BicycleParameters (test extra) gives the same
canonical matrices as bikemass (relative 1e-12: the file holds every value at 17 digits)."""

import numpy as np
import pytest

from bikemass.scenario.scenario import parameters as scenario_parameters
from bikemass.models.parameter_export import format_parameters
from bikemass.models.canonical import canonical_matrices

bp = pytest.importorskip("bicycleparameters")


@pytest.mark.parametrize("bike, rider, name", [("benchmark", "none", "Benchmark"),
                                                ("jamis", "relaxed", "Jamis"),
                                                ("cargo-loaded-thesis", "aero-tuck-thesis", "Cargoload")])
def test_bicycleparameters_reads_the_export(tmp_path, bike, rider, name):
    params = scenario_parameters(bike, rider)
    folder = tmp_path / "bicycles" / name / "Parameters"
    folder.mkdir(parents=True)
    (folder / f"{name}Benchmark.txt").write_text(format_parameters(params, "bicycleparameters", name))
    theirs = bp.Bicycle(name, pathToData=str(tmp_path)).canonical(nominal=True)
    ours = canonical_matrices(params)
    for mine, other in zip((ours.M, ours.C1, ours.K0, ours.K2), theirs):
        np.testing.assert_allclose(np.asarray(other, dtype=float), mine, rtol=1e-12, atol=1e-12)
    assert params.to_dict() == {
        k: float(v) for k, v in bp.io.load_parameter_text_file(str(folder / f"{name}Benchmark.txt")).items()}
