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
from labrig.store.reader import SessionReader

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
    assert "python tests/regenerate_sessions.py tests/data/sessions" in (DATA / "README.md").read_text()
    shutil.which("python")  # the command is run from the repository root


def test_transcripts_hold_each_daq_sample_once_and_check_still_compares_them(tmp_path):
    """Issue 14 item 5: a DAQ call's result is stored once (the rows); the transcript keeps the command, its
    arguments, where the rows are and their SHA-256, and replay --check rebuilds the result from the rows."""
    from labrig.session_run import RunRequest, execute

    path = tmp_path / "s.h5"
    assert execute(RunRequest(protocol=str(DATA / "step.toml"), path=path, seed=5)).exit_code == 0
    with SessionReader(path) as r:
        calls = [json.loads(x) for x in r.transcript("daq").splitlines() if '"op":"call"' in x]
        rec = next(s for s in r.steps() if "daq" in s.rows)
        daq_bytes = sum(r.stream(rec, "daq")[c].nbytes for c in ("t_s", "v_V", "i_A", "disp_m"))
        tr_bytes = len(r.transcript("daq"))
    finite = [c for c in calls if c["meta"]["method"] == "run_finite"]
    assert len(finite) == 1 and finite[0]["payload"] == ""
    ref = finite[0]["meta"]["result_rows"]
    assert (ref["step"], ref["stream"], ref["start"], ref["count"]) == (rec.index, "daq", 0, rec.rows["daq"])
    assert len(ref["sha256"]) == 64 and tr_bytes < 0.05 * daq_bytes  # no second copy of the samples
    assert check(path).ok
    with h5py.File(path, "r+") as f:  # a stored sample changed after the run: the digest says so
        ds = f[f"{rec.group}/daq/disp_m"]
        ds[17] = ds[17] + 1e-6
    res = check(path)
    assert not res.ok and f"step {rec.index} daq" in res.message and "SHA-256" in res.message


def test_stream_replay_releases_load_cell_frames_at_the_recorded_pace():
    """The clamp wait of a replay sees the frames it saw when recorded: not every frame up to the next
    command of another instrument at once (what made --check fail on clean paper sweeps)."""
    from drivers.transcript import Exchange, ReplayMessages
    from labrig.replay import StreamReplay, VirtualClock

    frames = [Exchange(0.001 * k, "loadcell", "read", b"ST,GS,+0001.00kg\r\n") for k in range(100)]  # 10 ms apart
    other = ReplayMessages([Exchange(0.0, "impedance", "write", b"*IDN?"), Exchange(0.5, "impedance", "write", b":INIT")])
    other.write("*IDN?")  # the sync point: recorded t = 0, replay clock 50 s
    clock = VirtualClock(50.0)
    port = StreamReplay(frames, [other], clock=clock, scale=1000.0)  # 1 ms recorded = 1 rig s
    assert port.in_waiting == len(frames[0].payload)  # only the frame at the sync point
    clock.sleep(9.5)
    assert port.in_waiting == 10 * len(frames[0].payload)  # frames 0..9 (t <= 9.5 rig s after the sync)
    clock.sleep(1000.0)
    assert port.in_waiting == 100 * len(frames[0].payload)  # all of them once the clock has passed them
