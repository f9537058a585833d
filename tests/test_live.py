"""The live window (offscreen): during a simulated run, during a replay, the Stop button, the buffers."""

from __future__ import annotations

import gzip
import os
import sys
import time
from contextlib import contextmanager
from pathlib import Path

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")

import numpy as np
import pytest

import labrig.simulate
from labrig.events import Block, RunStart, StepPlan, daq_stream
from labrig.live import app as live_app
from labrig.live.model import LiveModel, Ring, minmax_decimate
from labrig.session_run import RunRequest, execute
from labrig.store.reader import SessionReader

DATA = Path(__file__).parent / "data" / "sessions"


@pytest.fixture
def windows():
    got: list = []
    live_app.WINDOW_HOOKS.append(got.append)
    yield got
    live_app.WINDOW_HOOKS.remove(got.append)


def daq_abs(path: Path) -> np.ndarray:
    """Every daq row of the session on the rig clock (t_start + t_s), as the window plots it."""
    with SessionReader(path) as r:
        parts = [(s.t_start + (d := r.stream(s, "daq"))["t_s"], d["v_V"], d["i_A"], d["disp_m"]) for s in r.steps() if "daq" in s.rows]
    return np.vstack([np.concatenate(c) for c in zip(*parts)])


def assert_traces_match(win, path: Path) -> None:
    """Each trace curve holds exactly the session's windowed, min/max-decimated data."""
    daq = daq_abs(path)
    daq = daq[:, np.searchsorted(daq[0], daq[0, -1] - win.window_s) :]
    for col, scale, curve in ((1, 1.0, win.trace_curves[0]), (2, 1e3, win.trace_curves[1]), (3, 1e3, win.trace_curves[2])):
        x, y = minmax_decimate(daq[0], daq[col], win.bins)
        assert len(x) < daq.shape[1]  # really decimated
        np.testing.assert_array_equal(curve.xData, x)
        np.testing.assert_array_equal(curve.yData, y * scale)


def coloured_pixels(win, plot, colour: str) -> int:
    """Pixels of ``colour`` (the curve's pen, within 40 per channel) inside ``plot``'s view box."""
    from pyqtgraph.Qt import QtGui

    img = win.graphics.grab().toImage().convertToFormat(QtGui.QImage.Format.Format_RGB888)
    w, h, bpl = img.width(), img.height(), img.bytesPerLine()
    arr = np.frombuffer(img.constBits(), np.uint8, count=h * bpl).reshape(h, bpl)[:, : w * 3].reshape(h, w, 3)
    r = win.graphics.mapFromScene(plot.vb.sceneBoundingRect()).boundingRect()
    dpr = img.width() / max(win.graphics.width(), 1)
    sub = arr[int(r.top() * dpr) : int(r.bottom() * dpr), int(r.left() * dpr) : int(r.right() * dpr)].astype(int)
    want = np.array(QtGui.QColor(colour).getRgb()[:3])
    return int(np.sum(np.all(np.abs(sub - want) <= 40, axis=2)))


def test_live_run_plots_the_session_and_leaves_the_file_as_without_live(tmp_path, windows):
    from labrig.live.window import frf_point
    from labrig.live.model import FrfRecord

    proto = str(DATA / "stepped-sine.toml")
    live_path, plain_path = tmp_path / "live.h5", tmp_path / "plain.h5"
    res = execute(RunRequest(protocol=proto, path=live_path, seed=3, live=True))
    assert res.exit_status == "success"
    (win,) = windows
    win.bins = 150  # force the decimation path on these short records
    win._version = -1
    win.refresh()
    assert_traces_match(win, live_path)
    # the FRF: one point per record, demodulated at its frequency_Hz
    with SessionReader(live_path) as r:
        recs = [s for s in r.steps() if s.kind == "stepped_sine"]
        want = [frf_point(FrfRecord(s.index, s.name, s.metadata, *(r.stream(s, "daq")[c] for c in ("t_s", "v_V", "i_A", "disp_m")))) for s in recs]
    assert [p.f_Hz for p in win.frf] == [p.f_Hz for p in want]
    np.testing.assert_allclose([p.gain_mm_per_V for p in win.frf], [p.gain_mm_per_V for p in want], rtol=1e-12)
    ((mag, _),) = win.frf_curves.values()  # one pressure: one curve
    np.testing.assert_array_equal(mag.xData, sorted(p.f_Hz for p in want))
    win.resize(1400, 900)
    win.show()
    win.wait_idle(0.3)
    png = tmp_path / "live.png"
    win.save_png(str(png))
    assert png.stat().st_size > 10_000
    for plot, colour in zip(win.trace_plots[:3], ("#1f77b4", "#d62728", "#2ca02c")):
        assert coloured_pixels(win, plot, colour) > 200
    assert coloured_pixels(win, win.frf_mag, "#1f77b4") > 50  # the first pressure's colour
    win.close()

    # the same run without the window: the same file (the simulated bench is not bit-reproducible run to
    # run -- noise draws depend on timing -- so values are compared to within a few LSB of the DAQ)
    assert execute(RunRequest(protocol=proto, path=plain_path, seed=3)).exit_status == "success"
    with SessionReader(live_path) as a, SessionReader(plain_path) as b:
        assert [(s.name, s.status, s.rows.get("daq")) for s in a.steps()] == [(s.name, s.status, s.rows.get("daq")) for s in b.steps()]
        assert a.config == b.config and a.exit_status == b.exit_status
        for s in a.steps():
            if "daq" in s.rows:
                x, y = a.stream(s, "daq"), b.stream(s, "daq")
                np.testing.assert_array_equal(x["t_s"], y["t_s"])
                for c, lsb in (("v_V", 20 / 2**14), ("i_A", 1e-2 * 20 / 2**14), ("disp_m", 2e-3 * 20 / 2**14)):
                    assert np.max(np.abs(x[c] - y[c])) <= 8 * lsb, (s.name, c)
    if sys.version_info < (3, 12):  # qtguard: PySide6 6.12 leaks references to None/True per repaint
        assert sys.getrefcount(None) > 1 << 20 and sys.getrefcount(True) > 1 << 20


@contextmanager
def _capture_sims(box: dict):
    original = labrig.simulate.simulated_rig

    @contextmanager
    def wrapped(*a, **kw):
        with original(*a, **kw) as (rig, sims):
            box["sims"] = sims
            yield rig, sims

    labrig.simulate.simulated_rig = wrapped
    try:
        yield
    finally:
        labrig.simulate.simulated_rig = original


def test_stop_button_aborts_with_the_drive_at_zero(tmp_path, windows):
    from labrig.events import RunStop

    box: dict = {}
    seen: dict = {}

    def at_stop(ev):
        if isinstance(ev, RunStop):  # emitted after rig.safe(), with the simulators still up
            seen["ao"] = box["sims"].daq.ao_output_V()

    def click_when_recording(win):
        from pyqtgraph.Qt import QtCore

        timer = QtCore.QTimer(win)

        def poll():
            st = win.model.steps.get(win.model.current) if win.model.current is not None else None
            if st is not None and st.kind == "stepped_sine" and win.stop_button.isEnabled():
                seen["clicked_in"] = st.name
                win.stop_button.click()
                timer.stop()

        timer.timeout.connect(poll)
        timer.start(5)

    live_app.WINDOW_HOOKS.append(click_when_recording)
    path = tmp_path / "stopped.h5"
    try:
        with _capture_sims(box):
            req = RunRequest(protocol=str(DATA / "stepped-sine.toml"), path=path, seed=1, live=True, time_scale=25.0, extra_subscribers=[at_stop])
            res = execute(req)
    finally:
        live_app.WINDOW_HOOKS.remove(click_when_recording)
    # clicked while the first sine record played: the runner stops at the next safe point (after it)
    assert seen.get("clicked_in") == "stepped_sine_0.5Hz_0.5V"
    assert res.exit_status == "abort" and res.exit_code == 1
    assert seen["ao"] == 0.0
    with SessionReader(path) as r:
        assert r.exit_status == "abort" and "operator" in r.reason
        status = {s.name: s.status for s in r.steps()}
        assert status["stepped_sine_0.5Hz_0.5V"] == "done" and status["stepped_sine_8Hz_0.5V"] == "planned"


def test_replay_live_plots_the_recording_with_its_timing(tmp_path, windows):
    from labrig.replay import replay_live

    path = tmp_path / "eis.h5"
    path.write_bytes(gzip.decompress((DATA / "eis.h5.gz").read_bytes()))
    png = tmp_path / "replay.png"
    n = replay_live(path, speed=0, screenshot=png)
    assert n > 5 and png.stat().st_size > 10_000
    win = windows[-1]
    with SessionReader(path) as r:
        (s,) = [s for s in r.steps() if s.kind == "eis"]
        z = r.stream(s, "eis")
    ny, mag, _ = win.eis_curves[0]
    np.testing.assert_array_equal(ny.xData, z["z_re_ohm"])
    np.testing.assert_array_equal(ny.yData, -z["z_im_ohm"])
    np.testing.assert_array_equal(mag.yData, np.hypot(z["z_re_ohm"], z["z_im_ohm"]))
    assert "run success" in win.status.text()

    # stepped sine replay: traces equal the session's decimated data
    path2 = tmp_path / "ss.h5"
    path2.write_bytes(gzip.decompress((DATA / "stepped-sine.h5.gz").read_bytes()))
    live_app.WINDOW_HOOKS.append(lambda w: setattr(w, "bins", 150))
    try:
        replay_live(path2, speed=0, screenshot=tmp_path / "ss.png")
    finally:
        live_app.WINDOW_HOOKS.pop()
    assert_traces_match(windows[-1], path2)


def test_replay_keeps_the_recorded_timing_scaled_by_speed(tmp_path):
    from labrig.live.player import play, session_events

    path = tmp_path / "step.h5"
    path.write_bytes(gzip.decompress((DATA / "step.h5.gz").read_bytes()))
    evs = session_events(str(path))
    span = evs[-1][0] - evs[0][0]
    speed = span / 0.4  # 0.4 s of wall time
    t0 = time.monotonic()
    got: list = []
    play(evs, got.append, speed)
    took = time.monotonic() - t0
    assert len(got) == len(evs) and 0.35 <= took < 1.5


def test_model_never_drops_samples_and_ring_keeps_the_newest():
    m = LiveModel(capacity=5000)
    plan = StepPlan(0, "r", "step", {"fs_Hz": 1000.0}, (daq_stream(20000),))
    m(RunStart("u", "p", {}, {}, {}, {}, (plan,), t=0.0))
    from labrig.events import StepStart

    m(StepStart("u", 0, 10.0))
    total = 0
    for k in range(20):
        t = (np.arange(1000) + total) / 1000.0
        m(Block("u", 0, "daq", {"t_s": t, "v_V": np.sin(t), "i_A": t, "disp_m": -t}, seq=k))
        total += 1000
    assert m.daq.total == total and m.daq.size == 5000
    snap = m.snapshot(window_s=2.0)
    np.testing.assert_allclose(snap.daq[0], 10.0 + np.arange(total - 2001, total) / 1000.0)
    r = Ring(7, 1)
    for k in range(4):
        r.append([np.arange(3.0) + 3 * k])
    np.testing.assert_array_equal(r.ordered()[0], np.arange(5.0, 12.0))


def test_minmax_decimation_keeps_every_peak():
    rng = np.random.default_rng(0)
    y = rng.normal(size=100_003)
    y[54321] = 40.0
    y[777] = -40.0
    x, yd = minmax_decimate(np.arange(y.size, dtype=float), y, 500)
    assert len(x) <= 1002 and yd.max() == 40.0 and yd.min() == -40.0
    assert np.all(np.diff(x) >= 0)
    x2, y2 = minmax_decimate(np.arange(10.0), np.arange(10.0), 500)
    np.testing.assert_array_equal(y2, np.arange(10.0))


def _sine_sweep_events(pressures=(612.0, 3062.0), freqs=(0.5, 1.0, 2.0, 4.0), delay_s=(0.2, 0.15)):
    """Events of a stepped sine at several pressures; the displacement lags by ``delay_s`` (its phase passes
    -180 deg), and the force pane gets ~20 minutes of rig time (what a sweep's force log spans)."""
    from labrig.events import RunStop, StepEnd, StepStart, force_stream

    fs, uid = 200.0, "synthetic"
    plans, data = [], []
    for p, delay in zip(pressures, delay_s):
        for f in freqs:
            n = int(fs * 6 / f)
            t = np.arange(n) / fs
            v = 0.5 * np.sin(2 * np.pi * f * t)
            gain = 1e-3 * (1.0 + p / 3062.0) / (1.0 + f)  # a different curve per pressure
            d = 0.5 * gain * np.sin(2 * np.pi * f * (t - delay))
            md = {"pressure_kPa": p, "frequency_Hz": f, "amplitude_V": 0.5, "cycles": 4.0, "settle_cycles": 2.0, "fs_Hz": fs}
            plans.append(StepPlan(len(plans), f"p{p:g}/stepped_sine_{f:g}Hz", "stepped_sine", md, (daq_stream(n), force_stream(0))))
            data.append({"t_s": t, "v_V": v, "i_A": 1e-3 * v, "disp_m": d})
    evs = [RunStart(uid, "stepped-sine", {}, {}, {}, {}, tuple(plans), t=0.0)]
    t0 = 0.0
    for plan, cols in zip(plans, data):
        evs.append(StepStart(uid, plan.index, t0))
        evs.append(Block(uid, plan.index, "daq", cols))
        ft = np.arange(0.0, 60.0, 1.0)
        evs.append(Block(uid, plan.index, "force", {"t_s": ft, "force_N": np.full(ft.size, 6.0 + plan.index)}))
        t0 += 150.0
        evs.append(StepEnd(uid, plan.index, "done", t0))
    evs.append(RunStop(uid, "success", "all steps done", t0))
    return evs, delay_s


def test_live_window_one_frf_curve_per_pressure_unwrapped_phase_seconds_everywhere(tmp_path, windows):
    """Issue 14 item 7: the FRF panes draw one curve per pressure with a legend, the phase unwrapped, and
    every time axis in seconds (the force pane read ks). The screenshot is saved for a person to look at."""
    from labrig.live.app import new_window

    events, delays = _sine_sweep_events()
    model = LiveModel()
    for ev in events:
        model(ev)
    win = new_window(model, None, "synthetic sweep")
    win.resize(1400, 900)
    win.show()
    win.window_s = 1e5  # the whole run in the time panes
    win.refresh()
    win.wait_idle(0.3)
    assert sorted(win.frf_curves) == [612.0, 3062.0]
    legend = [item[1].text for item in win.frf_legend.items]
    assert legend == ["612 kPa", "3062 kPa"]
    for (press, (mag, ph)), delay in zip(win.frf_curves.items(), delays):
        f = np.asarray(mag.xData)
        assert np.all(np.diff(f) > 0)  # never running back from the highest frequency to the lowest
        want = -360.0 * f * delay  # a pure delay: -72 deg at 1 Hz, -288 deg at 4 Hz
        np.testing.assert_allclose(ph.yData, want, atol=2.0)
    for plot in win.trace_plots:  # one time unit: no SI prefix on any time axis (the force pane said ks)
        ax = plot.getAxis("bottom")
        assert ax.autoSIPrefixScale == 1.0 and ax.labelUnitPrefix == ""
    assert "(s)" in win.trace_plots[-1].getAxis("bottom").labelText
    force_x = win.force_curve.xData
    assert force_x.max() > 1000.0  # rig seconds on the force axis, as on the others
    png = Path(os.environ.get("LABRIG_SCREENSHOT_DIR", tmp_path)) / "live_frf.png"
    win.save_png(str(png))
    assert png.stat().st_size > 10_000
    for (mag, _), colour in zip(win.frf_curves.values(), ("#1f77b4", "#d62728")):
        assert coloured_pixels(win, win.frf_mag, colour) > 30
    win.close()


def test_a_missing_optional_package_is_one_line_naming_what_to_install(tmp_path):
    import subprocess

    path = tmp_path / "eis.h5"
    path.write_bytes(gzip.decompress((DATA / "eis.h5.gz").read_bytes()))
    code = ("import sys; sys.modules['pyqtgraph'] = None; from labrig.cli import main; "
            f"sys.exit(main(['replay', {str(path)!r}, '--live']))")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert r.returncode == 2
    assert r.stderr.strip().splitlines() == ["labrig: error: the optional package 'pyqtgraph' is not installed: pip install 'pyqtgraph'"]
