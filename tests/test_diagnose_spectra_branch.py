"""Issue 12 in the suite, end to end: a faradaic branch the spectra do not see, judged on their own electrical values.

A reduction wave past an onset, its reactant spent through the session, written into the DAQ's current of the suite's
clean seed-1 sweep exported once (bench/diagnose_probes.py ``spent_reduction``), imported and diagnosed as a user would.
A module of its own beside tests/test_diagnose_injected.py, so that the suite's two workers share their diagnoses
(pytest-xdist hands out whole modules)."""

from bench import diagnose_probes as probes
from test_diagnose_injected import exported  # noqa: F401  (the fixture: the suite's clean sweep exported, once per module)

BENCH_CASES = [("none", 1)]  # shared with test_fit and the coverage (conftest)


def test_a_spent_reduction_wave_is_faradaic_on_the_spectras_own_values(exported):
    """A reduction wave past an onset whose reactant the session spends, in the DAQ's current alone (the analyser's
    small signal about 0 V does not reach the onset): the join of the current and the spectra takes the branch into the
    electrical values and puts the spectra beyond their noise, so the branch is judged on the spectra's values too, and
    named there in the form that fades with the session's clock, its strength found."""
    write, check = probes.PROBES["spent_reduction"]
    out = probes.diagnosed(exported, "spent_reduction", write)
    assert check(out) == "", (out["verdict"], out["cause"], out["residual"])
    p = out["effects_detail"][0]["params"]
    assert out["extended"]["form"] == "fading" and p.get("spectra_electrical") == 1.0
    assert 2e-4 < p["i_lim_A"] < 8e-4 and 0.1 < p["e_half_V"] < 0.5  # 0.4 mA drawn, its half-wave at 0.3 V
