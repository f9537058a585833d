"""The HDF5 session store: round trip, a reader while it grows, kill -9, resume, analyses, ``labrig inspect``."""

import json
import os
import signal
import subprocess
import sys
import textwrap
import time

import h5py
import numpy as np
import pytest

from labrig.errors import BadInput
from labrig.events import Block, RunStart, RunStop, StepEnd, StepPlan, StepStart, Transcript, daq_stream, eis_stream, force_stream, new_uid
from labrig.store import SessionFile, SessionReader, SessionWriter, clear_write_flags

ROWS = 500  # rows per block in the subprocess writer


def plan(daq_rows=2000):
    return (
        StepPlan(0, "p612/clamp", "clamp", {"pressure_kPa": 612.0, "target_N": 9.8}, (force_stream(50),)),
        StepPlan(1, "p612/eis", "eis", {"pressure_kPa": 612.0, "points": 3, "bias": {"V": 0.0}}, (eis_stream(3),)),
        StepPlan(2, "p612/step", "step", {"pressure_kPa": 612.0, "amplitude_V": 1.0, "freqs_Hz": [1.0, 2.0]},
                 (daq_stream(daq_rows), force_stream(0))),
    )


def run_start(uid, resumed_from=None, daq_rows=2000):
    return RunStart(
        uid=uid, protocol="paper-sweep", config={"pressures_kPa": [612.0], "nested": {"a": 1}},
        rig={"instruments": {"keyence": {"model": "LK-G", "address": "socket://127.0.0.1:1", "calibration": {"mm_per_V": 2.0}},
                             "loadcell": {"model": "UMMA-K10"}}},
        sample={"length_m": 0.03, "width_m": 0.004, "medium": "water"}, software={"protocols": "x"},
        steps=plan(daq_rows), t=0.0, resumed_from=resumed_from,
    )


def daq_block(k, rows=ROWS):
    t = (k * rows + np.arange(rows)) / 1000.0
    return {"t_s": t, "v_V": np.sin(t), "i_A": 1e-3 * np.cos(t), "disp_m": 1e-4 * t}


def write_first_two_steps(w, uid):
    w(StepStart(uid, 0, 0.0))
    w(Block(uid, 0, "force", {"t_s": np.arange(50.0), "force_N": np.full(50, 9.8)}))
    w(StepEnd(uid, 0, "done", 50.0, {"mean_force_N": 9.8}))
    w(StepStart(uid, 1, 50.0))
    w(Block(uid, 1, "eis", {"f_Hz": np.array([1.0, 10.0, 100.0]), "z_re_ohm": np.array([30.0, 20.0, 10.0]),
                            "z_im_ohm": np.array([-5.0, -2.0, -1.0])}))
    w(StepEnd(uid, 1, "done", 60.0))


def test_round_trip_values_units_nexus_and_statuses(tmp_path):
    path, uid = tmp_path / "s.h5", new_uid()
    w = SessionWriter(path)
    w(run_start(uid))
    write_first_two_steps(w, uid)
    w(StepStart(uid, 2, 60.0))
    for k in range(4):
        w(Block(uid, 2, "daq", daq_block(k)))
    w(Transcript(uid, "keyence", '{"device":"keyence","op":"write"}\n{"device":"keyence","op":"read"}'))
    w(Transcript(uid, "clamp", '{"device":"clamp","op":"write"}\n'))  # not in the rig: goes to _other
    with pytest.raises(ValueError, match="columns"):
        w(Block(uid, 2, "daq", {"t_s": np.zeros(3)}))
    with pytest.raises(ValueError, match="run"):
        w(Block("another-run", 2, "daq", daq_block(0)))
    w(StepEnd(uid, 2, "aborted", 62.0, {"why": "operator"}))
    w(RunStop(uid, "abort", "operator pressed stop", 62.0))

    with SessionReader(path) as r:
        assert (r.uid, r.protocol, r.exit_status, r.reason) == (uid, "paper-sweep", "abort", "operator pressed stop")
        assert r.sample == {"length_m": 0.03, "width_m": 0.004, "medium": "water"}
        assert r.config == {"pressures_kPa": [612.0], "nested": {"a": 1}}
        assert r.instruments["keyence"]["calibration"] == {"mm_per_V": 2.0}
        steps = r.steps()
        assert [(s.index, s.name, s.kind, s.status) for s in steps] == [
            (0, "p612/clamp", "clamp", "done"), (1, "p612/eis", "eis", "done"), (2, "p612/step", "step", "aborted")]
        assert steps[1].metadata == {"pressure_kPa": 612.0, "points": 3, "bias": {"V": 0.0}}
        assert (steps[2].t_start, steps[2].t_end, steps[2].summary) == (60.0, 62.0, {"why": "operator"})
        daq = r.stream("p612/step", "daq")
        want = {c: np.concatenate([daq_block(k)[c] for k in range(4)]) for c in daq}
        assert all(np.array_equal(daq[c], want[c]) for c in want)
        assert daq.units == {"t_s": "s", "v_V": "V", "i_A": "A", "disp_m": "m"} and (daq.signal, daq.axis) == ("disp_m", "t_s")
        assert r.stream(1, "eis")["z_re_ohm"].tolist() == [30.0, 20.0, 10.0]
        assert r.transcript("keyence").splitlines() == ['{"device":"keyence","op":"write"}', '{"device":"keyence","op":"read"}']
        assert r.transcript("clamp") == '{"device":"clamp","op":"write"}\n'
        assert r.incomplete() == ["run ended with exit status abort: operator pressed stop", "step 2 p612/step: aborted"]

    with h5py.File(path, "r") as f:  # what a NeXus viewer sees
        assert f.attrs["NX_class"] == "NXroot" and f["entry"].attrs["NX_class"] == "NXentry"
        assert f["entry/sample"].attrs["NX_class"] == "NXsample" and f["entry/sample/length_m"].attrs["units"] == "m"
        assert f["entry/instrument"].attrs["NX_class"] == "NXinstrument"
        assert json.loads(f["entry/instrument/keyence"].attrs["calibration"]) == {"mm_per_V": 2.0}
        g = f["entry/steps/002_p612_step"]
        assert g.attrs["name"] == "p612/step" and g.attrs["pressure_kPa"] == 612.0 and list(g.attrs["freqs_Hz"]) == [1.0, 2.0]
        assert g["daq"].attrs["NX_class"] == "NXdata" and g["daq"].attrs["signal"] == "disp_m" and g["daq"].attrs["axes"] == "t_s"
        missing = []
        f.visititems(lambda n, o: missing.append(n) if isinstance(o, h5py.Dataset) and "units" not in o.attrs else None)
        assert missing == []


def test_analysis_written_after_the_run_and_overwritten(tmp_path):
    path, uid = tmp_path / "s.h5", new_uid()
    w = SessionWriter(path)
    w(run_start(uid))
    w(RunStop(uid, "fail", "no", 0.0))
    sf = SessionFile(path)
    sf.write_analysis("fit/seed000", {"f1_Hz": 3.3, "R_cont_ohm": np.array([1.0, 2.0]), "verdict": "none",
                                      "cause": None, "per_pressure": {"p612": {"Kt_bar": 4.17}}})
    sf.write_analysis("fit/seed000", {"f1_Hz": 3.5, "cause": "hysteresis"})
    got = sf.read_analysis("fit/seed000")
    assert got == {"f1_Hz": 3.5, "cause": "hysteresis"}
    sf.write_analysis("diagnosis", {"per_pressure": {"p612": {"Kt_bar": 4.17}}, "cause": None, "R_cont_ohm": [1.0, 2.0]})
    d = sf.read_analysis("diagnosis")
    assert d["per_pressure"] == {"p612": {"Kt_bar": 4.17}} and d["cause"] is None and d["R_cont_ohm"].tolist() == [1.0, 2.0]
    assert sf.analyses() == ["diagnosis", "fit/seed000"]
    with h5py.File(path, "r") as f:
        assert f["entry/analysis/fit/seed000/f1_Hz"].attrs["units"] == "Hz"
        assert f["entry/analysis/diagnosis/R_cont_ohm"].attrs["units"] == "ohm"



def test_a_session_read_then_written_is_walked_once_and_a_change_between_is_walked_again(tmp_path, monkeypatch):
    """The diagnosis stores into the session it has just read: HDF5's read-write open rewrites the superblock, and
    the hostile-file walk is not repeated for a file unchanged since it was read; a file changed in between is."""
    from labrig.store import validate

    path, uid = tmp_path / "s.h5", new_uid()
    w = SessionWriter(path)
    w(run_start(uid))
    w(RunStop(uid, "success", "", 0.0))
    walks = []
    real = validate._walk
    monkeypatch.setattr(validate, "_walk", lambda f, where: (walks.append(str(where)), real(f, where))[1])
    with SessionReader(path):
        pass
    SessionFile(path).write_analysis("fit/seed000", {"f1_Hz": 3.3})
    assert len(walks) == 1, walks  # read, then written: one walk
    with h5py.File(path, "a") as f:  # changed by another hand between a read and the next write: a soft link
        f["entry"]["alias"] = h5py.SoftLink("/entry/analysis")
    with pytest.raises(BadInput, match="soft link"):
        SessionFile(path).write_analysis("fit/seed000", {"f1_Hz": 3.4})
    assert len(walks) == 2

WRITER = textwrap.dedent(
    """
    import sys, time
    sys.path[:0] = [{tests!r}]
    from test_store import *
    path, uid, blocks, pause = sys.argv[1], sys.argv[2], int(sys.argv[3]), float(sys.argv[4])
    w = SessionWriter(path)
    w(run_start(uid, daq_rows=10**9))
    write_first_two_steps(w, uid)
    w(StepStart(uid, 2, 60.0))
    k = 0
    while blocks < 0 or k < blocks:
        w(Block(uid, 2, "daq", daq_block(k)))
        k += 1
        print(k, flush=True)  # after the block is flushed
        time.sleep(pause)
    w(StepEnd(uid, 2, "done", 70.0))
    w(RunStop(uid, "success", "", 70.0))
    print("stopped", flush=True)
    """
)


def start_writer(tmp_path, blocks, pause):
    script = tmp_path / "writer.py"
    script.write_text(WRITER.format(tests=os.path.dirname(__file__)))
    path, uid = tmp_path / "s.h5", new_uid()
    proc = subprocess.Popen([sys.executable, str(script), str(path), uid, str(blocks), str(pause)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    return proc, path, uid


def wait_for_blocks(proc, n):
    for _ in range(n):
        line = proc.stdout.readline()
        assert line, proc.stderr.read()
    return int(line)


def assert_daq_intact(r, at_least):
    daq = r.stream(2, "daq")
    assert daq.rows >= at_least * ROWS and daq.rows % ROWS == 0
    want = {c: np.concatenate([daq_block(k)[c] for k in range(daq.rows // ROWS)]) for c in daq}
    assert all(np.array_equal(daq[c], want[c]) for c in want)
    return daq.rows


def test_second_process_reads_while_the_file_grows(tmp_path):
    proc, path, uid = start_writer(tmp_path, blocks=-1, pause=0.02)
    try:
        wait_for_blocks(proc, 2)
        with SessionReader(path) as r:  # one open, refreshed: as a live plot would read
            assert r.swmr, "a file being written must be read with SWMR"
            first = assert_daq_intact(r, 2)
            assert r.step(2).status == "running" and r.exit_status is None
            # the writer's lines can sit in the pipe: wait for one reporting a block the first read cannot have seen
            # (on a loaded machine the writer runs ahead of its reports, and a fixed count of lines may all be old)
            while wait_for_blocks(proc, 1) * ROWS <= first:
                pass
            later = assert_daq_intact(r, first // ROWS + 1)
            assert later > first
        with pytest.raises(BadInput, match="live process"):
            SessionWriter.resume(path)  # clearing the write flags under a live writer would corrupt it
        wait_for_blocks(proc, 1)  # and the writer goes on
    finally:
        proc.kill()
        proc.wait()


@pytest.fixture
def killed_session(tmp_path):
    proc, path, uid = start_writer(tmp_path, blocks=-1, pause=0.0)
    try:
        seen = wait_for_blocks(proc, 20)
    finally:
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait()
    return path, uid, seen


def test_sigkill_mid_run_leaves_a_file_that_opens(killed_session):
    path, uid, seen = killed_session
    with pytest.raises(OSError, match="already open for write"):
        h5py.File(path, "r")  # HDF5 2.0: a plain open refuses the killed writer's file; SWMR read does not
    with SessionReader(path) as r:  # no live writer: labrig clears the stale flags (h5clear -s) and says so
        assert r.cleared_flags and not r.swmr
        assert r.exit_status is None and r.uid == uid
        assert [s.status for s in r.steps()] == ["done", "done", "running"]
        assert assert_daq_intact(r, seen) >= seen * ROWS  # every block the writer reported flushed is there
        assert r.stream(1, "eis")["f_Hz"].tolist() == [1.0, 10.0, 100.0]
        lines = r.incomplete()
        assert lines[0].startswith("no RunStop") and "step 2 p612/step: interrupted while running" in lines
    with h5py.File(path, "r") as f:  # now any HDF5 tool opens it
        assert f["entry/steps/002_p612_step/status"][()] == b"running"
    SessionFile(path).write_analysis("note", {"x_m": 1.0})
    with h5py.File(path, "r") as f:
        assert f["entry/analysis/note/x_m"][()] == 1.0
    with SessionReader(path) as r:
        assert not r.cleared_flags  # cleared once


def test_clear_write_flags_refuses_a_file_that_is_not_hdf5(tmp_path):
    bad = tmp_path / "x.h5"
    bad.write_bytes(b"\x89HDF\r\n\x1a\n" + bytes(56))
    with pytest.raises(BadInput, match="superblock"):
        clear_write_flags(bad)


def test_resume_keeps_done_steps_and_redoes_the_interrupted_one(killed_session):
    path, uid, _ = killed_session
    w = SessionWriter.resume(path)
    assert (w.done_steps, w.previous_uid) == ([0, 1], uid)
    with SessionReader(path) as r:
        assert r.step(2).status == "planned" and r.step(2).rows == {"daq": 0, "force": 0}
        assert r.unfinished_steps() == [2] and r.done_steps() == [0, 1]
    with pytest.raises(ValueError, match="resumed_from"):
        w(run_start(new_uid(), resumed_from="someone-else"))
    uid2 = new_uid()
    w(run_start(uid2, resumed_from=uid, daq_rows=10**9))
    w(StepStart(uid2, 2, 100.0))
    for k in range(3):
        w(Block(uid2, 2, "daq", daq_block(k)))
    w(StepEnd(uid2, 2, "done", 101.5))
    w(RunStop(uid2, "success", "", 101.5))
    with SessionReader(path) as r:
        assert not r.swmr and r.exit_status == "success"
        assert [s.status for s in r.steps()] == ["done", "done", "done"]
        assert assert_daq_intact(r, 3) == 3 * ROWS
        assert r.stream(0, "force")["force_N"].tolist() == [9.8] * 50  # the first run's data is kept
        assert [x["uid"] for x in r.resumes] == [uid2] and r.resumes[0]["resumed_from"] == uid
        assert r.incomplete() == ["step 2 p612/step: stream daq has 1500 of 1000000000 rows"]
        assert (r.uid, r.last_uid) == (uid, uid2)
    w = SessionWriter.resume(path)  # a second resume: everything is done, the first run's uid is accepted too
    assert (w.done_steps, w.previous_uid) == ([0, 1, 2], uid2)
    uid3 = new_uid()
    w(run_start(uid3, resumed_from=uid, daq_rows=10**9))
    w(RunStop(uid3, "success", "nothing left", 102.0))
    with SessionReader(path) as r:
        assert [x["uid"] for x in r.resumes] == [uid2, uid3] and r.exit_status == "success"
        assert r.stream(2, "daq").rows == 3 * ROWS


def test_resume_refuses_a_different_plan(tmp_path):
    path, uid = tmp_path / "s.h5", new_uid()
    w = SessionWriter(path)
    w(run_start(uid))
    w.close()  # no RunStop: interrupted
    with SessionReader(path) as r:
        assert r.incomplete() == ["no RunStop: the run did not finish (crashed, killed or still running)",
                                  "steps 0-2 (3 steps, p612/clamp .. p612/step): never started"]
    w = SessionWriter.resume(path)
    other = run_start(new_uid(), resumed_from=uid)
    other = RunStart(**{**other.__dict__, "steps": other.steps[:2]})
    with pytest.raises(ValueError, match="plan differs"):
        w(other)
    w.close()


def run_cli(*args):
    return subprocess.run([sys.executable, "-m", "labrig", *map(str, args)], capture_output=True, text=True)


def test_inspect_text_and_json(killed_session):
    path, uid, _ = killed_session
    r = run_cli("inspect", path)
    assert r.returncode == 0, r.stderr
    assert uid in r.stdout and "paper-sweep" in r.stdout and "exit status none" in r.stdout
    step_lines = [line for line in r.stdout.splitlines() if "p612/" in line and "kPa" in line]
    assert len(step_lines) == 3 and "running" in step_lines[2] and "daq" in step_lines[2]
    assert "interrupted while running" in r.stdout
    r = run_cli("inspect", path, "--json")
    out = json.loads(r.stdout)
    assert out["run_uid"] == uid and out["exit_status"] is None and out["sample"]["medium"] == "water"
    assert [s["status"] for s in out["steps"]] == ["done", "done", "running"]
    assert out["steps"][0]["rows"] == {"force": 50} and out["steps"][0]["pressure_kPa"] == 612.0
    assert set(out["instruments"]) == {"keyence", "loadcell"} and out["incomplete"]


@pytest.mark.parametrize("kind", ["missing", "text", "foreign_hdf5", "directory"])
def test_inspect_bad_files_exit_2_with_one_line(tmp_path, kind):
    path = tmp_path / "x.h5"
    if kind == "text":
        path.write_text("not hdf5\n")
    elif kind == "foreign_hdf5":
        with h5py.File(path, "w") as f:
            f["data"] = [1, 2]
    elif kind == "directory":
        path.mkdir()
    r = run_cli("inspect", path)
    assert r.returncode == 2 and r.stdout == ""
    assert len(r.stderr.strip().splitlines()) == 1 and str(path) in r.stderr, r.stderr


def test_reader_never_returns_a_torn_block(tmp_path):
    path, uid = tmp_path / "s.h5", new_uid()
    w = SessionWriter(path)
    w(run_start(uid))
    w(Block(uid, 2, "daq", daq_block(0)))
    w.close()
    with h5py.File(path, "a") as f:  # what a kill between a column's resize and the commit mark leaves
        f["entry/steps/002_p612_step/daq/t_s"].resize((ROWS + 7,))
        assert np.isnan(f["entry/steps/002_p612_step/daq/t_s"][-1])  # unwritten rows are NaN, never 0
    with SessionReader(path) as r:
        assert r.step(2).rows["daq"] == ROWS and r.step(2).status == "running"
        assert np.array_equal(r.stream(2, "daq")["t_s"], daq_block(0)["t_s"])


def test_a_plan_the_layout_cannot_hold_is_refused_before_any_file(tmp_path):
    start = run_start(new_uid())
    dup = RunStart(**{**start.__dict__, "steps": start.steps + (start.steps[0],)})
    with pytest.raises(ValueError, match="twice"):
        SessionWriter(tmp_path / "s.h5")(dup)
    assert not (tmp_path / "s.h5").exists()


LAYOUT_WRITER = textwrap.dedent(
    """
    import sys
    sys.path[:0] = [{tests!r}]
    from test_store import *
    from labrig.events import StepPlan, daq_stream, force_stream
    path, uid = sys.argv[1], sys.argv[2]
    ev = run_start(uid)
    big = tuple(StepPlan(i, f"p{{i}}/step", "step", {{"pressure_kPa": 612.0}}, (daq_stream(1000), force_stream(0)))
                for i in range(40))  # a layout long enough to be killed in the middle of
    w = SessionWriter(path)
    w(RunStart(**{{**ev.__dict__, "steps": big}}))
    print("laid out", flush=True)
    import time
    time.sleep(60)
    """
)


@pytest.mark.parametrize("delay_s", [0.0, 0.2, None])
def test_a_kill_at_any_moment_of_the_layout_leaves_no_session_or_one_that_resumes(tmp_path, delay_s):
    """Issue 17 item 3: the session appears under its name only once laid out (None: kill after that)."""
    script = tmp_path / "layout.py"
    script.write_text(LAYOUT_WRITER.format(tests=os.path.dirname(__file__)))
    path, uid = tmp_path / "s.h5", new_uid()
    partial = tmp_path / ".s.h5.partial"
    proc = subprocess.Popen([sys.executable, str(script), str(path), uid], stdout=subprocess.PIPE, text=True)
    try:
        if delay_s is None:
            assert proc.stdout.readline() == "laid out\n"
        else:
            deadline = time.time() + 30
            while not partial.exists() and time.time() < deadline:
                time.sleep(0.001)
            time.sleep(delay_s)
    finally:
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait()
    if delay_s is None:
        assert path.exists() and not partial.exists()
    if path.exists():  # a whole session: it opens (any tool, once labrig cleared the flags) and resumes
        with SessionReader(path) as r:
            assert r.uid == uid and len(r.steps()) == 40 and r.exit_status is None
        h5py.File(path, "r").close()
        w = SessionWriter.resume(path)
        assert w.previous_uid == uid and w.done_steps == []
        w.close()
    else:  # no session: the name is free for the next run, and the partial file is not a session
        w = SessionWriter(path)
        w(run_start(new_uid()))
        w.close()
        with SessionReader(path) as r:
            assert len(r.steps()) == 3
