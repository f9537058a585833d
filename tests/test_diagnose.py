"""The diagnosis on simulated paper sweeps with hidden effects, on a clean bench, and on imported data."""

import json
import subprocess
import sys
from pathlib import Path

import pytest

from labrig.cli.diagnose_cmd import run_diagnosis
from labrig.session_run import RunRequest, execute
from labrig.store import SessionFile
from mock_devices import scenarios

DATA = Path(__file__).parent / "data"


def _sweep(tmp_path, scenario, seed):
    path = tmp_path / f"{scenario.replace('+', '_')}_{seed}.h5"
    assert execute(RunRequest("paper-sweep", path, effects=scenarios.effects_for(scenario, seed), seed=seed)).exit_code == 0
    return path


def test_clean_bench_is_none_and_the_json_contract_holds(tmp_path):
    path = _sweep(tmp_path, "none", 3)
    out = run_diagnosis(path)
    assert out["verdict"] == "none" and out["cause"] is None
    for c in out["candidates"]:
        assert {"name", "delta_bic", "heldout_nrmse"} <= set(c)
    assert {c["name"] for c in out["candidates"]} == set(scenarios.names()) - {"none"}
    assert "heldout_nrmse" in out["baseline"]
    assert {"heldout_nrmse", "params"} <= set(out["extended"])
    assert {"heldout_nrmse_ratio", "delta_bic"} <= set(out["gain"])
    json.dumps(out)
    assert json.loads(SessionFile(path).read_analysis("diagnosis")["result_json"])["verdict"] == "none"


def test_two_hidden_effects_are_both_named(tmp_path):
    out = run_diagnosis(_sweep(tmp_path, "back_relaxation+mains_pickup", 3))
    assert out["verdict"] == "effect"
    assert set(out["effects"][:2]) == {"back_relaxation", "mains_pickup"}


def test_faradaic_current_is_found_and_its_extension_halves_the_heldout_error(tmp_path):
    out = run_diagnosis(_sweep(tmp_path, "faradaic_current", 3))
    assert out["verdict"] == "effect" and out["cause"] == "faradaic_current"
    assert out["gain"]["heldout_nrmse_ratio"] < 0.5
    assert out["gain"]["delta_bic"] < -25
    assert out["split"]["fit"] != out["split"]["heldout"]  # scored on other pressures than fitted


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
