"""The live window: scrolling traces, the FRF filling in, the impedance spectrum, status and Stop.

Everything here runs in the GUI thread. A QTimer takes a ``LiveModel`` snapshot and redraws only
when the model changed; the runner (or a replay) never waits for it.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from typing import Callable

import numpy as np
import pyqtgraph as pg
from pyqtgraph.Qt import QtCore, QtWidgets

from labrig.estimate import sine_estimate
from labrig.live.model import LiveModel, Snapshot, envelope_decimate, minmax_decimate
from labrig.live.qtguard import top_up

# (column index in the daq snapshot, title, unit label, scale from SI to the plotted unit, colour)
TRACES = ((1, "drive voltage", "V", 1.0, "#1f77b4"), (2, "current", "mA", 1e3, "#d62728"),
          (3, "displacement", "mm", 1e3, "#2ca02c"))
PEN_W = 1.5
COLOURS = ("#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#8c564b", "#e377c2", "#17becf", "#bcbd22")


@dataclass
class FrfPoint:
    index: int
    f_Hz: float
    gain_mm_per_V: float
    phase_deg: float
    pressure_kPa: float | None


def frf_point(rec) -> FrfPoint:
    """Demodulate a finished sine record at its ``frequency_Hz`` (the seed's stepped-sine estimate)."""
    md = rec.metadata
    est = sine_estimate(rec.t, rec.v, rec.i, rec.d, float(md["frequency_Hz"]), float(md.get("settle_cycles", 0.0)), md.get("cycles"))
    h = est.H_disp
    return FrfPoint(rec.index, float(md["frequency_Hz"]), abs(h) * 1e3, math.degrees(math.atan2(h.imag, h.real)), md.get("pressure_kPa"))


def frf_curve(pts: list[FrfPoint]) -> tuple[np.ndarray, np.ndarray]:
    """Gain (mm/V) and phase (deg) of points sorted by frequency; the phase unwrapped along them, its first
    point kept in (-180, 180] (the lag of an IPMC grows past -180 deg with frequency)."""
    gain = np.array([p.gain_mm_per_V for p in pts])
    phase = np.degrees(np.unwrap(np.radians([p.phase_deg for p in pts])))
    return gain, phase


class LiveWindow(QtWidgets.QMainWindow):
    """Live plot of one run (or replay). ``on_stop`` is called by the Stop button (``runner.request_stop``)."""

    def __init__(self, model: LiveModel, on_stop: Callable[[], None] | None = None, *, title: str = "labrig live",
                 window_s: float = 60.0, fps: float = 40.0, bins: int = 1000):
        super().__init__()
        self.model, self.on_stop, self.window_s, self.bins = model, on_stop, window_s, bins
        self.setWindowTitle(title)
        self.resize(1400, 900)
        self.frf: list[FrfPoint] = []
        self.frames = 0  # frames drawn (the benchmark's fps)
        self._version = -1
        self._build()
        self.timer = QtCore.QTimer(self)
        self.timer.timeout.connect(self.refresh)
        self.timer.start(max(1, int(1000 / fps)))

    # ------------------------------------------------------------------ layout
    def _build(self) -> None:
        # exitCleanup=False: its atexit teardown of graphics items segfaults PySide6 6.12 at interpreter exit
        pg.setConfigOptions(antialias=False, background="w", foreground="k", exitCleanup=False)
        central = QtWidgets.QWidget()
        outer = QtWidgets.QVBoxLayout(central)
        bar = QtWidgets.QHBoxLayout()
        self.status = QtWidgets.QLabel("waiting for the run to start")
        self.status.setStyleSheet("font-size: 14px; font-weight: bold;")
        self.stop_button = QtWidgets.QPushButton("Stop")
        self.stop_button.setStyleSheet("QPushButton { background: #c62828; color: white; font-weight: bold; padding: 4px 18px; }"
                                       "QPushButton:disabled { background: #9e9e9e; }")
        self.stop_button.clicked.connect(self._stop_clicked)
        self.stop_button.setEnabled(self.on_stop is not None)
        bar.addWidget(self.status, 1)
        bar.addWidget(self.stop_button)
        outer.addLayout(bar)
        self.graphics = pg.GraphicsLayoutWidget()
        outer.addWidget(self.graphics, 1)
        self.setCentralWidget(central)

        g = self.graphics
        self.trace_plots, self.trace_curves = [], []
        rows = [*TRACES, (1, "clamp force", "N", 1.0, "#9467bd")]
        for r, (_, name, unit, _, colour) in enumerate(rows):
            p = g.addPlot(row=r, col=0, title=f"{name} ({unit})")
            # no grid here: grid lines are repainted with the scrolling axes and cost ~3x a whole frame
            # one time unit (s) in every pane: no automatic ks/ms prefixes that would differ between panes
            p.getAxis("bottom").enableAutoSIPrefix(False)
            if r == len(rows) - 1:
                p.setLabel("bottom", "rig time (s)")
            if self.trace_plots:
                p.setXLink(self.trace_plots[0])
            # we decimate ourselves (min/max per pixel column); clip to view keeps panning cheap
            c = p.plot(pen=pg.mkPen(colour, width=PEN_W))
            c.setClipToView(True)
            self.trace_plots.append(p)
            self.trace_curves.append(c)
        self.force_curve = self.trace_curves[-1]

        self.frf_mag = g.addPlot(row=0, col=1, title="FRF |displacement / drive| (mm/V)")
        self.frf_mag.setLogMode(x=True, y=True)
        self.frf_legend = self.frf_mag.addLegend(offset=(-10, 10))  # top right: names each pressure's curve
        self.frf_phase = g.addPlot(row=1, col=1, title="FRF phase (deg, unwrapped)")
        self.frf_phase.setLogMode(x=True, y=False)
        self.frf_phase.setXLink(self.frf_mag)
        self.frf_phase.setLabel("bottom", "frequency (Hz)")  # no units=: SI prefixes misread on log axes
        # one (magnitude, phase) curve per clamping pressure, in the order the pressures come
        self.frf_curves: dict[float | None, tuple[pg.PlotDataItem, pg.PlotDataItem]] = {}

        self.nyquist = g.addPlot(row=2, col=1, title="impedance, Nyquist (ohm)")
        self.nyquist.setLabel("bottom", "Z'", units="ohm")
        self.nyquist.setLabel("left", "-Z''", units="ohm")
        self.nyquist.setAspectLocked(True)
        self.nyquist.addLegend(offset=(-10, 10))  # the EIS curves are named by pressure
        self.bode = g.addPlot(row=3, col=1, title="impedance, Bode |Z| (ohm) and phase (deg, right)")
        self.bode.setLogMode(x=True, y=True)
        self.bode.setLabel("bottom", "frequency (Hz)")
        self.bode_phase_view = pg.ViewBox()
        self.bode.showAxis("right")
        self.bode.scene().addItem(self.bode_phase_view)
        self.bode.getAxis("right").linkToView(self.bode_phase_view)
        self.bode.getAxis("right").setLogMode(False, False)  # the phase is linear, unlike |Z|
        self.bode_phase_view.setXLink(self.bode)
        self.bode.vb.sigResized.connect(lambda: self.bode_phase_view.setGeometry(self.bode.vb.sceneBoundingRect()))
        self.eis_curves: list[tuple[pg.PlotDataItem, pg.PlotDataItem, pg.PlotDataItem]] = []
        for p in (self.frf_mag, self.frf_phase, self.nyquist, self.bode):
            p.showGrid(x=True, y=True, alpha=0.3)

    # ------------------------------------------------------------------ behaviour
    def _stop_clicked(self) -> None:
        if self.on_stop is not None:
            self.on_stop()
        self.stop_button.setEnabled(False)
        self.stop_button.setText("Stopping…")

    def refresh(self) -> bool:
        """Draw one frame if the model changed; True if something was drawn."""
        top_up()  # PySide6 6.12 leaks references to None/True on every repaint (see qtguard)
        if self.model.version == self._version:
            return False
        snap = self.model.snapshot(self.window_s)
        self._version = snap.version
        self.status.setText(snap.status)
        self._traces(snap)
        for rec in snap.frf:
            self.frf.append(frf_point(rec))
        if snap.frf:
            self._frf()
        if len(snap.eis) != len(self.eis_curves):
            self._eis(snap)
        if snap.finished:
            self.stop_button.setEnabled(False)
        self.frames += 1
        return True

    def _traces(self, snap: Snapshot) -> None:
        for k, ((col, _, _, scale, _), curve) in enumerate(zip(TRACES, self.trace_curves)):
            if snap.envelope is not None:
                e = snap.envelope
                x, y = envelope_decimate(e[0], e[1 + 2 * k], e[2 + 2 * k], self.bins)
            else:
                x, y = minmax_decimate(snap.daq[0], snap.daq[col], self.bins)
            curve.setData(x, y * scale, connect=self._connect(x))
        x, y = minmax_decimate(snap.force[0], snap.force[1], self.bins)
        self.force_curve.setData(x, y)
        # one time axis for all four (x-linked): span whatever the daq and the force windows hold
        ts = [a[0] for a in (snap.daq, snap.force, snap.envelope) if a is not None and a.shape[1]]
        if ts:
            lo, hi = min(float(t[0]) for t in ts), max(float(t[-1]) for t in ts)
            self.trace_plots[0].setXRange(lo, hi if hi > lo else lo + 1.0, padding=0.02)

    def _connect(self, x: np.ndarray) -> np.ndarray | str:
        """Do not draw a line across the pause between two records (a gap of > 0.5 s or 4 bins)."""
        if len(x) < 2:
            return "all"
        gap = max(0.5, 4.0 * (x[-1] - x[0]) / self.bins)
        return np.append(np.diff(x) <= gap, False)

    def _frf(self) -> None:
        """One curve per pressure, ascending in frequency, phase unwrapped along it."""
        by_p: dict[float | None, list[FrfPoint]] = {}
        for p in self.frf:
            by_p.setdefault(p.pressure_kPa, []).append(p)
        for k, (press, pts) in enumerate(by_p.items()):
            pts.sort(key=lambda p: p.f_Hz)
            f = np.array([p.f_Hz for p in pts])
            mag, phase = frf_curve(pts)
            if press not in self.frf_curves:
                c = COLOURS[len(self.frf_curves) % len(COLOURS)]
                name = f"{press:g} kPa" if press is not None else "no pressure"
                sym = dict(pen=pg.mkPen(c, width=PEN_W), symbol="o", symbolSize=6, symbolBrush=c, symbolPen=c)
                self.frf_curves[press] = (self.frf_mag.plot(name=name, **sym), self.frf_phase.plot(**sym))
            m, ph = self.frf_curves[press]
            m.setData(f, mag)
            ph.setData(f, phase)

    def _eis(self, snap: Snapshot) -> None:
        colours = COLOURS
        for k in range(len(self.eis_curves), len(snap.eis)):
            p, arr = snap.eis[k]
            f, zr, zi = arr
            c = colours[k % len(colours)]
            name = f"{p:g} kPa" if p is not None else f"spectrum {k + 1}"
            sym = dict(pen=pg.mkPen(c, width=PEN_W), symbol="o", symbolSize=5, symbolBrush=c, name=name)
            z = np.hypot(zr, zi)
            ny = self.nyquist.plot(zr, -zi, **sym)
            mag = self.bode.plot(f, z, **sym)
            ph = pg.PlotDataItem(np.log10(f), np.degrees(np.arctan2(zi, zr)), pen=pg.mkPen(c, width=1, style=QtCore.Qt.DashLine))
            self.bode_phase_view.addItem(ph)
            self.eis_curves.append((ny, mag, ph))

    def save_png(self, path: str) -> None:
        """Draw the newest state and save the whole window as a PNG."""
        self.refresh()
        QtWidgets.QApplication.processEvents()
        self.grab().save(str(path), "PNG")

    def wait_idle(self, seconds: float = 0.2) -> None:
        """Let Qt lay out and paint (offscreen tests)."""
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            QtWidgets.QApplication.processEvents()
            time.sleep(0.01)
