"""Issue 6's coverage on the simulated bench, end to end (run -> session file -> fit -> diagnosis): every
catalogue effect hidden in a paper-sweep with three seeds, and the clean bench with ten seeds.

All 40 sessions are made once for the module, two at a time (about 7 minutes on two cores); the bench's
truth stays in the worker process that ran it. bench/diagnose.py prints the same matrix as a table.
"""

import json

import pytest

from labrig.diagnose.catalogue import CATALOGUE
from labrig.diagnose.coverage import confusion, run_cases
from mock_devices import scenarios

EFFECTS = sorted(CATALOGUE)
CASES = [(n, s) for n in EFFECTS for s in (1, 2, 3)] + [("none", s) for s in range(1, 11)]
# on a paper-sweep at the bench's plausible strengths these two are a few 1e-4 of the response (docs/effects.md):
# named, but the extension cannot halve an error that is mostly noise
WEAK = {"large_deflection", "strain_resistance"}


@pytest.fixture(scope="module")
def matrix(tmp_path_factory):
    return run_cases(CASES, tmp_path_factory.mktemp("coverage"))


def test_the_hidden_effect_is_named_in_at_least_95_percent_of_sessions(matrix):
    table = confusion(matrix, scenarios.names())
    right = sum(r.right for r in matrix)
    assert right >= 0.95 * len(matrix), table
    for name in EFFECTS:  # and no effect is missed in more than one seed of three
        assert sum(r.right for r in matrix if r.scenario == name) >= 2, table


def test_the_clean_bench_is_none_in_at_least_95_percent_of_ten_seeds(matrix):
    none = [r for r in matrix if r.scenario == "none"]
    assert len(none) == 10
    assert sum(r.verdict == "none" for r in none) >= 0.95 * len(none), [(r.seed, r.answer) for r in none]


def test_the_named_extension_at_least_halves_the_heldout_error(matrix):
    for r in matrix:
        if r.scenario in CATALOGUE and r.right:
            limit = 1.0 if r.scenario in WEAK else 0.5
            assert r.heldout_ratio < limit, (r.scenario, r.seed, r.heldout_ratio)
            assert r.delta_bic < -25
            assert r.output["split"]["fit"] != r.output["split"]["heldout"]  # scored on other pressures than fitted


def test_the_json_contract_holds_for_every_verdict(matrix):
    for r in matrix:
        out = r.output
        assert out["verdict"] in ("effect", "none", "unexplained")
        assert (out["cause"] is None) == (out["verdict"] != "effect")
        assert {c["name"] for c in out["candidates"]} == set(EFFECTS)
        assert all({"name", "delta_bic", "heldout_nrmse"} <= set(c) for c in out["candidates"])
        assert "heldout_nrmse" in out["baseline"] and {"heldout_nrmse", "params"} <= set(out["extended"])
        assert {"heldout_nrmse_ratio", "delta_bic"} <= set(out["gain"])
        json.dumps(out)

