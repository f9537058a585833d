"""The simulated bench ("world"): one IPMC strip from labrig.physics in a clamp, in water or air, with a
load cell and a clamp that a simulated operator or motor tightens. Every simulated instrument asks this
one object, so the laser, the DAQ, the load cell and the impedance analyser agree with each other.

Linear physics comes from ``labrig.physics`` (the single home of the equations). The strip's electrical
and mechanical memory carries across records: each record is simulated together with the drive history of
the last ``memory_s`` seconds (older drive is forgotten; the CPE's slow tail from it is below the noise).

Hidden effects (the diagnosis scenarios) plug in as ``Effect`` objects; their truth stays here and never
reaches a session file.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass, field

import numpy as np

from labrig.physics import impedance as imp
from labrig.physics import presets, timeresp, transfer
from labrig.physics.params import Specimen
from mock_devices.world_api import SimClock as Clock

# the strip's time responses over a record's window (history + record + tail): zero padding, as a multiple of the
# window, and the exponential window's damping. Its error at time t is lifted by damping^(t / T_fft): with the
# defaults (1, 1e9) a block at the end of 120 s of history read the current 4.8e-5 A off, an alternating current
# the spell test rightly flagged on the clean bench. These keep both channels under a quarter of their noise at 1.5
# times the default's cost (docs/model.md 6)
SIM_PAD = 2.0
SIM_DAMPING = 1e5


def window_response(tfs: list, u: np.ndarray, fs: float) -> list[np.ndarray]:
    """Responses of ``tfs`` to a record's whole window ``u`` (its history first), as the bench simulates them."""
    return timeresp.simulate_many(tfs, u, fs, SIM_PAD, SIM_DAMPING)


@dataclass
class Noise:
    """Physical noise of the bench (what a good real bench shows), all standard deviations."""

    displacement_m: float = 0.5e-6  # laser head noise
    current_A: float = 2e-6  # current amplifier input noise
    voltage_V: float = 0.2e-3
    force_N: float = 0.01
    impedance_rel: float = 0.002


class Effect:
    """Something the baseline model leaves out. Each hook defaults to "no change"."""

    name = "none"

    def specimen(self, sp: Specimen, t: float, bench: "World") -> Specimen:
        return sp

    def drive(self, v: np.ndarray, t: np.ndarray, bench: "World") -> np.ndarray:
        """The voltage the strip sees, given the commanded drive (before the linear model)."""
        return v

    def outputs(self, out: dict[str, np.ndarray], t: np.ndarray, v: np.ndarray, bench: "World") -> dict[str, np.ndarray]:
        """Measured signals after the linear model (current_A, displacement_m)."""
        return out

    def force(self, f: float, t: float, bench: "World") -> float:
        return f

    def impedance(self, z: np.ndarray, f: np.ndarray, bench: "World") -> np.ndarray:
        return z


@dataclass
class _Segment:
    t0: float
    fs: float
    v: np.ndarray  # the voltage the strip saw (after drive effects)

    @property
    def t1(self) -> float:
        return self.t0 + self.v.size / self.fs


@dataclass
class RecordWindow:
    """Everything simulated for the latest record: remembered history, the record, then a tail at rest.

    Effects with memory (filters, delays, hysteresis) read it so they see the drive history, not only
    the record; they may replace ``displacement``/``current`` so that effects later in the list build on
    theirs. The record is ``[k0, k0 + n)``; sample j is at ``t0 + (j - k0) / fs``.
    """

    t0: float
    fs: float
    k0: int
    n: int
    u: np.ndarray  # volts the strip saw
    displacement: np.ndarray  # m, linear model (then earlier effects)
    current: np.ndarray  # A
    specimen: Specimen

    @property
    def t(self) -> np.ndarray:
        return self.t0 + (np.arange(self.u.size) - self.k0) / self.fs

    def record(self, x: np.ndarray) -> np.ndarray:
        return x[self.k0 : self.k0 + self.n]


@dataclass
class _Trace:
    """The latest computed response, kept for instruments that sample "now" (the laser)."""

    t0: float
    fs: float
    displacement: np.ndarray = field(default_factory=lambda: np.zeros(0))


class World:
    """The simulated bench. Thread-safe: instruments run on their own server threads."""

    def __init__(
        self,
        clock: Clock,
        preset: str = "paper",
        pressure_kPa: float | None = None,
        seed: int = 0,
        effects: list[Effect] | None = None,
        noise: Noise | None = None,
        memory_s: float = 120.0,
        clamp_tau_s: float = 3.0,
        specimen_changes: dict | None = None,
    ):
        self.clock = clock
        self.preset = presets.get(preset)
        self.rng = np.random.default_rng(seed)
        self.effects = list(effects or [])
        self.noise = noise or Noise()
        self.memory_s = memory_s
        self.clamp_tau_s = clamp_tau_s
        self._changes = dict(specimen_changes or {})
        p = self.preset.default_pressure_kPa if pressure_kPa is None else pressure_kPa
        self._area = self.preset.base.geometry.clamp_area
        self._force_target = p * 1e3 * self._area
        self._force_from = self._force_target
        self._force_t0 = -1e9
        self._history: list[_Segment] = []
        self._trace = _Trace(0.0, 1.0)
        self.window: RecordWindow | None = None  # the latest record with its history (for effects)
        self._lock = threading.RLock()

    # ---------------------------------------------------------------------------------- clamp
    def set_clamp_force(self, target_N: float) -> None:
        """Motorised clamp / operator: the force moves exponentially towards ``target_N``."""
        with self._lock:
            now = self.clock.now()
            self._force_from = self._true_force(now)
            self._force_target = float(target_N)
            self._force_t0 = now

    @property
    def clamp_set_at(self) -> float:
        """Simulated time of the latest clamp setting (what a creeping clamp relaxes from)."""
        return self._force_t0

    def _true_force(self, t: float) -> float:
        a = np.exp(-max(t - self._force_t0, 0.0) / self.clamp_tau_s)
        f = self._force_target + (self._force_from - self._force_target) * a
        for e in self.effects:
            f = e.force(f, t, self)
        return float(f)

    def clamp_force_now(self) -> float:
        with self._lock:
            return self._true_force(self.clock.now()) + self.noise.force_N * self.rng.standard_normal()

    def pressure_kPa(self, t: float | None = None) -> float:
        t = self.clock.now() if t is None else t
        return max(self._true_force(t), 1e-3) / self._area / 1e3

    def specimen(self, t: float | None = None) -> Specimen:
        """The strip as it is at time t (clamp state, then any effect's drift)."""
        t = self.clock.now() if t is None else t
        # round the pressure so a steady clamp reuses the cached modes
        sp = self.preset.specimen(round(self.pressure_kPa(t), 1), **self._changes)
        for e in self.effects:
            sp = e.specimen(sp, t, self)
        return sp

    # ---------------------------------------------------------------------------------- signals
    def run_record(self, t0: float, fs: float, drive_V: np.ndarray) -> dict[str, np.ndarray]:
        """Apply ``drive_V`` from ``t0`` at ``fs``; return voltage_V, current_A, displacement_m (world_api)."""
        drive = np.asarray(drive_V, float)
        n = drive.size
        t = t0 + np.arange(n) / fs
        with self._lock:
            v = drive
            for e in self.effects:
                v = e.drive(v, t, self)
            self._forget_before(t0 - self.memory_s)
            self._history = [h for h in self._history if h.t1 <= t0 + 1e-12]
            sp = self.specimen(t0)
            # drive history resampled onto this record's grid, then the record, then a tail at rest
            # on this record's own sample grid (sample j at t0 + (j - k0) / fs): a grid counted from the oldest segment
            # sits up to a sample off the record, and the strip then sees the history shifted against the record, a
            # glitch at every block boundary whose place depends on how the DAQ happened to block the record
            start = self._history[0].t0 if self._history else t0
            k0 = int(np.ceil((t0 - start) * fs - 1e-9))
            tail = min(max(n, int(fs)), int(30 * fs))
            u = np.zeros(k0 + n + tail)
            grid = t0 + (np.arange(k0) - k0) / fs
            for h in self._history:
                sel = (grid >= h.t0 - 1e-6 / fs) & (grid < h.t1 - 1e-6 / fs)  # contiguous blocks' ends differ by rounding
                if sel.any():
                    u[:k0][sel] = np.interp(grid[sel], h.t0 + np.arange(h.v.size) / h.fs, h.v)
            u[k0 : k0 + n] = v
            disp, cur = window_response([lambda s: transfer.displacement_tf(s, sp), lambda s: transfer.admittance_tf(s, sp)], u, fs)
            self._history.append(_Segment(t0, fs, v.copy()))
            self._trace = _Trace(t0, fs, disp[k0:].copy())
            self.window = RecordWindow(t0, fs, k0, n, u, disp, cur, sp)
            out = {"i_A": cur[k0 : k0 + n], "disp_m": disp[k0 : k0 + n]}
            for e in self.effects:
                out = e.outputs(out, t, v, self)
            nz = self.noise
            return {
                "v_V": v + nz.voltage_V * self.rng.standard_normal(n),
                "i_A": out["i_A"] + nz.current_A * self.rng.standard_normal(n),
                "disp_m": out["disp_m"] + nz.displacement_m * self.rng.standard_normal(n),
            }

    def _forget_before(self, t: float) -> None:
        self._history = [h for h in self._history if h.t1 > t]

    def displacement_now(self) -> float:
        """Tip displacement at the laser spot now: from the latest record's trace (with its tail at rest)."""
        with self._lock:
            tr = self._trace
            now = self.clock.now()
            if tr.displacement.size == 0:
                d = 0.0
            else:
                k = int((now - tr.t0) * tr.fs)
                d = float(tr.displacement[min(max(k, 0), tr.displacement.size - 1)]) if k >= 0 else 0.0
            return d + self.noise.displacement_m * self.rng.standard_normal()

    def impedance(self, freqs_Hz: np.ndarray, ac_V: float, bias_V: float) -> np.ndarray:
        """Z the analyser measures at the present clamp state (small-signal: ac_V and bias_V only add effects)."""
        f = np.asarray(freqs_Hz, float)
        with self._lock:
            z = imp.impedance(2j * np.pi * f, self.specimen())
            for e in self.effects:
                z = e.impedance(z, f, self)
            scale = 1.0 + self.noise.impedance_rel * (self.rng.standard_normal(f.size) + 1j * self.rng.standard_normal(f.size)) / np.sqrt(2)
            return z * scale
