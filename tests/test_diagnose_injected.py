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


def test_hum_on_the_drive_monitor_alone_is_mains_pickup(exported):
    """Pickup on the DAQ's voltage-monitor input only (a ground loop on a single-ended channel): the recorded drive
    carries a 50 Hz line and its 3rd harmonic that the strip never saw, displacement and current are untouched. The
    lines are read on the monitor too, so the cause is named and located there."""
    s = inject.read_export(exported / "clean", "paper")
    for r in s.series():
        w = 2 * np.pi * 50.0 * r.cols["t_s"]
        r.cols["v_V"] = r.cols["v_V"] + 1.5e-3 * np.cos(w + 0.3) + 4e-4 * np.cos(3 * w + 1.1)
    h5 = exported / "monitor_hum.h5"
    assert main(["import", str(inject.write_import(s, exported / "monitor_hum")), "--out", str(h5)]) == 0
    out = run_diagnosis(h5, load_and_fit(h5, "diagnose"))
    assert (out["verdict"], out["cause"]) == ("effect", "mains_pickup"), out["candidates"][:3]
    assert out["gain"]["heldout_nrmse_ratio"] < 0.5
    before = out["baseline"]["blocks"]
    assert "line" in out["baseline"]["missed"] and before["frf_d"] < 1.5 * out["baseline"]["accuracy"]["frf_d"]
    params = out["extended"]["params"]
    assert params.get("volt50_mV", 0.0) > 1.0 and params.get("volt150_mV", 0.0) > 0.2, params
