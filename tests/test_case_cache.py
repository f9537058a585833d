"""The suite's shared paper sweeps (bench/coverage.py CaseCache): one case's fault fails only the tests that read it."""

import pytest

from bench.coverage import CaseCache


def test_a_case_that_raises_is_reported_by_name_once_and_not_run_again(tmp_path):
    cache = CaseCache(tmp_path, expected={("no_such_scenario", 7): False}, jobs=1)
    with pytest.raises(RuntimeError, match="no_such_scenario seed 7") as first:
        cache.get([("no_such_scenario", 7)], diagnosed=False)
    assert isinstance(first.value.__cause__, KeyError)  # the worker's own error, carried across the process
    with pytest.raises(RuntimeError) as again:
        cache.get([("no_such_scenario", 7)])
    assert again.value.__cause__ is first.value.__cause__  # remembered, not run a second time
