"""The diagnosis: two hidden effects at once, imported data, bad input (coverage over the catalogue: test_diagnose_coverage.py)."""

import json
import subprocess
import sys
from pathlib import Path

from labrig.store import SessionFile

DATA = Path(__file__).parent / "data"

TWO_EFFECTS = ("back_relaxation+mains_pickup", 3)
BENCH_CASES = [TWO_EFFECTS]  # a paper sweep run, fitted and diagnosed as `labrig run ... --fit --diagnose` (conftest)

def test_two_hidden_effects_are_both_named_and_the_result_is_stored(bench_sessions):
    case = bench_sessions.get([TWO_EFFECTS])[0]
    path, out = case.path, case.output
    assert out["verdict"] == "effect"
    assert set(out["effects"][:2]) == {"back_relaxation", "mains_pickup"}
    stored = json.loads(SessionFile(path).read_analysis("diagnosis")["result_json"])
    assert stored["cause"] == out["cause"] and stored["effects"] == out["effects"]

def test_imported_data_is_diagnosed_like_a_session(tmp_path):
    out_h5 = tmp_path / "imported.h5"
    r = subprocess.run([sys.executable, "-m", "labrig", "import", str(DATA / "import_example" / "manifest.toml"), "--out", str(out_h5)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    r = subprocess.run([sys.executable, "-m", "labrig", "diagnose", str(out_h5), "--json"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    out = json.loads(r.stdout)
    assert out["verdict"] in ("effect", "none", "unexplained") and len(out["candidates"]) == 10

def test_diagnose_missing_file_is_bad_input(tmp_path):
    r = subprocess.run([sys.executable, "-m", "labrig", "diagnose", str(tmp_path / "nope.h5")], capture_output=True, text=True)
    assert r.returncode == 2 and "nope.h5" in r.stderr and len(r.stderr.strip().splitlines()) == 1


def test_play_operator_follows_its_recursion():
    """The hysteresis extension's phase-wise play operator against y_k = clip(y_{k-1}, x_k - r, x_k + r) from 0."""
    import numpy as np

    from labrig.diagnose.catalogue import _play

    rng = np.random.default_rng(3)
    drives = [rng.normal(0, 1, 300), np.cumsum(rng.normal(0, 0.2, 300)),
              np.repeat([0.0, 1.0, -1.0, 0.5, 0.0], 60) + rng.normal(0, 1e-3, 300)]
    for x in drives:
        for r in (0.0, 0.05, 0.3, 2.0):
            y, prev = np.empty_like(x), 0.0
            for k, xk in enumerate(x):
                prev = min(max(prev, xk - r), xk + r)
                y[k] = prev
            np.testing.assert_allclose(_play(x, r), y, rtol=0, atol=1e-12)
