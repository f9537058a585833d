"""Issue 12 in the suite: a form the simulator does not make, written into an exported clean sweep by the
validation set's injector (bench/inject.py), imported and diagnosed as a user would. The whole validation set
(every form x three seeds, structures outside the catalogue, protocol variants) is run by bench/diagnose.py, and the
issue's further probes (an exponential electrolysis branch, hum on the drive monitor) by bench/diagnose_probes.py;
here the structure outside the catalogue, on the suite's clean seed-1 sweep."""

import pytest

from bench import diagnose_probes as probes
from labrig.cli import main

BENCH_CASES = [("none", 1)]  # shared with test_fit and the coverage (conftest)


@pytest.fixture(scope="module")
def exported(bench_sessions, tmp_path_factory):
    folder = tmp_path_factory.mktemp("injected")
    assert main(["export", bench_sessions.get(BENCH_CASES)[0].path, "--out", str(folder / "clean")]) == 0
    return folder


def test_a_structure_outside_the_catalogue_is_unexplained_and_located(exported):
    """A fixture resonance in the displacement path: no catalogued extension removes it, the verdict says so and
    points at the displacement FRF in a band around the resonance (3-8 Hz drawn)."""
    write, check = probes.PROBES["fixture_resonance"]
    out = probes.diagnosed(exported, "fixture_resonance", write)
    assert check(out) == "", (out["verdict"], out["cause"], out["residual"])
