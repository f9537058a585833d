"""Recorded sessions replayed through the runner (``labrig replay --check``) and the fitter."""

from __future__ import annotations

import gzip
import json
import math
import shutil
from pathlib import Path

import h5py
import numpy as np
import pytest

from labrig.cli import main
from labrig.replay import check
from labrig.store_reader import SessionReader

DATA = Path(__file__).parent / "data" / "sessions"
NAMES = ("step", "eis", "stepped-sine")


def cli(args: list[str]) -> int:
    """``labrig ARGS`` exit code (a failing check leaves through SystemExit)."""
    try:
        return main(args)
    except SystemExit as exc:
        return int(exc.code)


def session(tmp_path: Path, name: str) -> Path:
    out = tmp_path / f"{name}.h5"
    out.write_bytes(gzip.decompress((DATA / f"{name}.h5.gz").read_bytes()))
    return out


@pytest.mark.parametrize("name", NAMES)
def test_check_passes_on_recorded_sessions(tmp_path, name, capsys):
    path = session(tmp_path, name)
    assert cli(["replay", str(path), "--check"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("PASS"), out
    assert "force compared loosely" in out


def _tamper_transcript(path: Path, device: str, old: bytes, new: bytes) -> None:
    with h5py.File(path, "r+") as f:
        ds = f[f"entry/transcripts/{device}"]
        raw = ds[()].tobytes()
        i = raw.index(old)
        ds[i : i + len(old)] = np.frombuffer(new, np.uint8)


def test_check_names_the_command_when_a_drive_argument_was_changed(tmp_path, capsys):
    path = session(tmp_path, "step")
    with h5py.File(path, "r") as f:
        text = f["entry/transcripts/daq"][()].tobytes()
    key = b'"drive_sha256":"'
    j = text.index(key) + len(key)
    first = text[j : j + 1]
    _tamper_transcript(path, "daq", key + first, key + (b"0" if first != b"0" else b"1"))
    assert cli(["replay", str(path), "--check"]) == 1
    out = capsys.readouterr().out
    assert out.startswith("FAIL"), out
    assert "step 2 (step_1V)" in out and "run_finite" in out and "recording expects" in out


def test_check_names_the_step_and_stream_when_a_sample_was_changed(tmp_path, capsys):
    path = session(tmp_path, "stepped-sine")
    with SessionReader(path) as r:
        rec = [s for s in r.steps() if s.kind == "stepped_sine"][1]
    with h5py.File(path, "r+") as f:
        ds = f[f"{rec.group}/daq/disp_m"]
        ds[17] = ds[17] + 1e-6
    assert cli(["replay", str(path), "--check"]) == 1
    out = capsys.readouterr().out
    assert f"step {rec.index} ({rec.name}), stream daq: disp_m[17]" in out, out


def test_check_notices_a_changed_impedance_point(tmp_path):
    path = session(tmp_path, "eis")
    with SessionReader(path) as r:
        rec = [s for s in r.steps() if s.kind == "eis"][0]
    with h5py.File(path, "r+") as f:
        f[f"{rec.group}/eis/z_re_ohm"][3] *= 1.0000001
    res = check(path)
    assert not res.ok and "stream eis: z_re_ohm[3]" in res.message


def test_check_refuses_bad_input(tmp_path, capsys):
    assert cli(["replay", str(tmp_path / "missing.h5"), "--check"]) == 2
    bad = tmp_path / "x.h5"
    with h5py.File(bad, "w") as f:
        f["a"] = 1
    assert cli(["replay", str(bad), "--check"]) == 2
    assert "not a labrig session" in capsys.readouterr().err


def _close(a, b, path="") -> None:
    """Stored fit JSON vs a new fit: every stored key, null and number (within 1e-6 relative) again.

    Keys the fitter added since the JSON was stored (a new analysis) are allowed; regenerate to pin them.
    """
    if isinstance(a, dict):
        assert set(a) <= set(b), f"{path}: keys gone: {sorted(set(a) - set(b))}"
        for k in a:
            _close(a[k], b[k], f"{path}.{k}")
    elif isinstance(a, list):
        assert len(a) == len(b), path
        for k, (x, y) in enumerate(zip(a, b)):
            _close(x, y, f"{path}[{k}]")
    elif isinstance(a, float) and isinstance(b, (int, float)):
        assert math.isclose(a, b, rel_tol=1e-6, abs_tol=1e-12) or (math.isnan(a) and math.isnan(b)), f"{path}: {a} vs {b}"
    else:
        assert a == b, f"{path}: {a!r} vs {b!r}"


@pytest.mark.parametrize("name", NAMES)
def test_fit_matches_the_stored_result(tmp_path, name, capsys):
    path = session(tmp_path, name)
    assert main(["fit", str(path), "--json"]) == 0
    got = json.loads(capsys.readouterr().out)
    _close(json.loads((DATA / f"{name}.fit.json").read_text()), got)


def test_replay_events_rebuild_the_stored_streams(tmp_path):
    """The player's events carry every stored row once, in order, at the step's rig times."""
    from labrig.events import Block, StepStart
    from labrig.live.player import session_events

    path = session(tmp_path, "step")
    evs = session_events(str(path))
    times = [t for t, _ in evs]
    assert times == sorted(times)
    with SessionReader(path) as r:
        for s in r.steps():
            for name in s.rows:
                blocks = [e for _, e in evs if isinstance(e, Block) and e.index == s.index and e.stream == name]
                want = r.stream(s, name)
                for col in want:
                    assert np.array_equal(np.concatenate([b.data[col] for b in blocks]), want[col])
            start = [t for t, e in evs if isinstance(e, StepStart) and e.index == s.index]
            assert start == [s.t_start]


def test_regenerate_is_documented():
    assert "python -m labrig.replay --regenerate tests/data/sessions" in (DATA / "README.md").read_text()
    shutil.which("python")  # the command is run from the repository root
