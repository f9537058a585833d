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


def test_a_form_on_the_spectras_values_stands_where_it_leaves_the_current_no_worse_than_on_the_join():
    """The spectra's values stand for a faradaic form where it leaves every current block within STRUCTURE_MARGIN of
    its accuracy, or leaves the current blocks (their squares summed, in accuracy units) no further off than the same
    form on the join's values: the form's own approximation error is not a disagreement with the spectra. A current
    worse on the spectra's strip than on the join's (a contact resistance the join took in) still fails."""
    from types import SimpleNamespace

    import numpy as np

    from labrig.diagnose.engine import Candidate, _Scorer
    from labrig.diagnose.verdict import STRUCTURE_MARGIN

    acc = {"frf_i": 0.13, "harm_i": 0.45, "step_i": 0.03, "frf_d": 0.35}
    scorer = SimpleNamespace(accuracy=acc)

    def cand(levels):  # held-out blocks whose RMS is ``levels`` x each block's accuracy
        return Candidate("faradaic_current", {}, -1e4, 1.0, 0.2, 1.0,
                         held={k: (np.full(10, x * acc[k]), None) for k, x in levels.items()})

    within = cand({"frf_i": 0.9 * STRUCTURE_MARGIN, "harm_i": 1.0, "step_i": 1.2, "frf_d": 30.0})
    assert _Scorer.reconciles(scorer, within) and _Scorer.reconciles(scorer, within, cand({"frf_i": 1.0, "harm_i": 1.0, "step_i": 1.0}))
    spectra = cand({"frf_i": 4.8, "harm_i": 2.4, "step_i": 1.2})  # fresh37's sealed cuvette, on the spectra's values
    assert not _Scorer.reconciles(scorer, spectra)  # absolutely: structure left
    assert _Scorer.reconciles(scorer, spectra, cand({"frf_i": 5.4, "harm_i": 2.3, "step_i": 0.8}))  # the join's no better
    assert not _Scorer.reconciles(scorer, spectra, cand({"frf_i": 2.0, "harm_i": 1.5, "step_i": 1.0}))  # the join's better
