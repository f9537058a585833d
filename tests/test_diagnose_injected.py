"""Issue 12 in the suite: forms the simulator does not make, written into an exported clean sweep by the
validation set's injector (bench/inject.py), imported and diagnosed as a user would. The whole validation set
(every form x three seeds, structures outside the catalogue, protocol variants) is run by bench/diagnose.py; here
one structure outside the catalogue and one further faradaic form, on the suite's clean seed-1 sweep."""

import importlib.util
import sys
from pathlib import Path

import numpy as np
import pytest

from labrig.cli import main
from labrig.analysis import load_and_fit, run_diagnosis

BENCH_CASES = [("none", 1)]  # shared with test_fit and the coverage (conftest)
_spec = importlib.util.spec_from_file_location("inject", Path(__file__).parents[1] / "bench" / "inject.py")
inject = sys.modules.setdefault("inject", importlib.util.module_from_spec(_spec))  # its dataclasses look their module up
_spec.loader.exec_module(inject)


@pytest.fixture(scope="module")
def exported(bench_sessions, tmp_path_factory):
    folder = tmp_path_factory.mktemp("injected")
    assert main(["export", bench_sessions.get(BENCH_CASES)[0].path, "--out", str(folder / "clean")]) == 0
    return folder


def diagnosed(folder: Path, truth: str, form: str, seed: int = 0) -> dict:
    s = inject.read_export(folder / "clean", "paper")
    s.rng = np.random.default_rng(seed)
    inject.FORMS[truth][form](s)
    manifest = inject.write_import(s, folder / form)
    h5 = folder / f"{form}.h5"
    assert main(["import", str(manifest), "--out", str(h5)]) == 0
    return run_diagnosis(h5, load_and_fit(h5, "diagnose"))


def test_a_structure_outside_the_catalogue_is_unexplained_and_located(exported):
    """A fixture resonance in the displacement path: no catalogued extension removes it, the verdict says so and
    points at the displacement FRF in a band around the resonance (3-8 Hz drawn)."""
    out = diagnosed(exported, "unexplained", "fixture_resonance")
    assert out["verdict"] == "unexplained" and out["cause"] is None, (out["verdict"], out["cause"], out["residual"])
    top = out["residual"]["where"][0]
    assert top["block"] == "frf_d" and top["over_accuracy"] > out["residual"]["structure_margin"]
    assert 1.0 <= top["worst"] <= 20.0 and top["band"][0] <= top["worst"] <= top["band"][1]


def test_electrolysis_growing_exponentially_is_faradaic(exported):
    """The issue's probe: a one-sided exponential (Tafel) branch, named back_relaxation before the families."""
    out = diagnosed(exported, "faradaic_current", "tafel")
    assert (out["verdict"], out["cause"]) == ("effect", "faradaic_current"), out["candidates"]
    assert out["extended"]["form"] in ("polynomial", "exponential") and out["gain"]["heldout_nrmse_ratio"] < 0.5
