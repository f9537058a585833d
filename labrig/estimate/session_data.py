"""What the fitter and the diagnosis need from a session, read only through the store's reader.

Finished steps only; each record grouped by its clamping pressure. Bad data (NaN, too short) is left out
with a note rather than crashing the fit. Per pressure: the stepped-sine estimates, the multisine BLA,
the FRF lines the fitter uses (``PressureData.frf_lines``) and the drift between and within records
(docs/estimation.md). Where a record's layout (a step's edges, a sine's settling cycles) is read, it is read
through ``step_onset``/``step_offset``/``sine_cycles``: the runner's metadata, or for an import, which cannot
say it, the record itself.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from labrig.errors import BadInput
from labrig.estimate.pieces import join_pieces
from labrig.records import HOLD_KINDS, SINE_KINDS, RecordKind
from labrig.estimate import (
    GAP,
    sample_spacing,
    BlaEstimate,
    DriftEstimate,
    combine_rates,
    ForceTrend,
    SineEstimate,
    excited_bins_from_drive,
    force_trend,
    gain_drift,
    multisine_bla,
    sine_estimate,
    sine_gain_rate,
    sine_segment_gains,
    template_gains,
)


@dataclass
class TimeRecord:
    name: str
    kind: str  # a labrig.records.RecordKind of TIME_KINDS
    meta: dict[str, Any]
    t: np.ndarray
    v: np.ndarray
    i: np.ndarray
    d: np.ndarray
    force_N: np.ndarray = field(default_factory=lambda: np.zeros(0))
    t_start: float = float("nan")  # rig clock at the step start (s)
    force_t: np.ndarray = field(default_factory=lambda: np.zeros(0))  # s from the step start, one per force_N
    # per sample: True where a gap of the time stamps was filled (regular_grid), not measured; empty: none filled
    filled: np.ndarray = field(default_factory=lambda: np.zeros(0, bool))

    @property
    def fs(self) -> float:
        return float(1.0 / sample_spacing(self.t))

    @property
    def force_times(self) -> np.ndarray:
        """s from the record's start, one per force reading (spread evenly over the record where none were stored)."""
        if self.force_t.size == self.force_N.size:
            return np.asarray(self.force_t, float)
        return np.linspace(0.0, float(np.ptp(self.t)), self.force_N.size)

    @property
    def force_trend(self) -> ForceTrend:
        """Load-cell force during the record: mean (N), slope (N/s) and the slope's standard deviation."""
        return force_trend(self.force_times, self.force_N)


@dataclass
class PressureData:
    pressure_kPa: float
    eis: tuple[np.ndarray, np.ndarray] | None = None  # (f_Hz, Z complex)
    eis_t_start: float = float("nan")  # rig clock at the spectrum's start (s): a strip drying between it and the sines
    records: list[TimeRecord] = field(default_factory=list)
    sines: list[SineEstimate] = field(default_factory=list)  # stepped-sine estimates, ascending f
    bla: BlaEstimate | None = None  # multisine BLA (the design with the most realisations x periods)
    blas: list[BlaEstimate] = field(default_factory=list)  # every multisine design at this pressure (e.g. per amplitude)
    # drift estimates by source: "multisine/realisations", "multisine/periods" (within records), "sine/within"
    # (each sine record's own rate of change, combined), "sine/repeats" and "step/repeats" (identical records repeated)
    drift: dict[str, DriftEstimate] = field(default_factory=dict)

    def of_kind(self, kind: str) -> list[TimeRecord]:
        return [r for r in self.records if r.kind == kind]

    @property
    def eis_time(self) -> float:
        """The spectrum's moment: its own start, or (not known) the pressure's first record's (nan: neither)."""
        if np.isfinite(self.eis_t_start):
            return float(self.eis_t_start)
        starts = [r.t_start for r in self.records if np.isfinite(r.t_start)]
        return min(starts) if starts else float("nan")

    def frf_lines(self, source: str = "all") -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray] | None:
        """The FRF points to fit: (f_Hz, H_disp in m/V, H_cur in A/V, sigma_disp in m/V), ascending f; None if none.

        ``source``: "all" (stepped sines and the multisine BLA together), "sines" (the stepped sines, exactly
        ``frf()``) or "multisine" (the BLA's excited lines). ``sigma_disp`` is the standard deviation of the
        complex estimate, sqrt(E|H_hat - H|^2) (each of the real and imaginary parts has sigma/sqrt 2):
        for a stepped sine the cycle-to-cycle scatter (as ``frf()``; it overstates the noise of the whole
        record, see docs/estimation.md), for the BLA the total variance over realisations (noise plus the
        stochastic nonlinear distortion; noise only with a single realisation).
        """
        if source not in ("all", "sines", "multisine"):
            raise ValueError(f"source must be all, sines or multisine, not {source!r}")
        parts = []
        if source in ("all", "sines") and self.sines:
            parts.append(self.frf())
        if source in ("all", "multisine") and self.bla is not None:
            b = self.bla
            parts.append((b.f_Hz, b.G_disp, b.G_cur, np.sqrt(b.total_var_disp)))
        if not parts:
            return None
        f, hd, hc, sd = (np.concatenate(c) for c in zip(*parts))
        o = np.argsort(f, kind="stable")
        return f[o], hd[o], hc[o], sd[o]

    def current_lines(self) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
        """The DAQ's current admittance: (f_Hz, H_cur in A/V, sigma_cur in A/V), stepped sines and the multisine
        BLA together, ascending f; None if none. The same admittance the analyser measures, but some 15x less
        noisy per point (8e-5 relative against 1.4e-3), so it pins what the spectrum leaves loose."""
        parts = []
        if self.sines:
            parts.append((np.array([s.frequency_Hz for s in self.sines]), np.array([s.H_cur for s in self.sines]), np.array([s.cur_noise for s in self.sines])))
        if self.bla is not None:
            parts.append((self.bla.f_Hz, self.bla.G_cur, np.sqrt(self.bla.total_var_cur)))
        if not parts:
            return None
        f, h, sig = (np.concatenate(c) for c in zip(*parts))
        o = np.argsort(f, kind="stable")
        return f[o], h[o], sig[o]

    def frf(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray] | None:
        """(f, H_disp, H_cur, sigma_disp) from the stepped sines, or None."""
        if not self.sines:
            return None
        f = np.array([s.frequency_Hz for s in self.sines])
        return f, np.array([s.H_disp for s in self.sines]), np.array([s.H_cur for s in self.sines]), np.array([s.disp_noise for s in self.sines])


@dataclass
class SessionData:
    path: str
    sample: dict[str, Any]
    pressures: list[PressureData]
    notes: list[str] = field(default_factory=list)
    unpressured: list[TimeRecord] = field(default_factory=list)  # records without a pressure
    displacement_sign: int = 1  # -1: every displacement read with the opposite sign (labrig.fit.polarity)
    current_sign: int = 1  # -1: every current read with the opposite sign (labrig.fit.polarity)

    def all_records(self) -> list[TimeRecord]:
        return [r for p in self.pressures for r in p.records] + self.unpressured


# ------------------------------------------------------------------------------------------ record layout
# The runner's metadata says where a step's drive switches and how many cycles of a sine settle; an import's
# manifest cannot (DESIGN.md 6), so for imports these are read off the record. Every reader goes through here.


def _drive_edges(r: TimeRecord) -> tuple[float, float]:
    """(rising, falling) edge of a step drive, s of record time: the first sample where |v - v[0]| exceeds half
    the step (``amplitude_V``, or the drive's largest excursion if smaller or unknown), and the first after it
    back below; (t[0], inf) for a flat drive, inf for a drive that never returns."""
    dv = np.abs(np.asarray(r.v, float) - float(r.v[0]))
    amp = float(dv.max())
    if r.meta.get("amplitude_V"):
        amp = min(amp, abs(float(r.meta["amplitude_V"])))
    if not amp > 0:
        return float(r.t[0]), math.inf
    above = dv > 0.5 * amp
    on = int(np.argmax(above))
    back = ~above[on:]
    return float(r.t[on]), float(r.t[on + int(np.argmax(back))]) if back.any() else math.inf


def step_onset(r: TimeRecord) -> float:
    """When a step record's drive switches on (s of record time): the runner's ``pre_s``, else read off the drive."""
    if r.meta.get("pre_s") is not None:
        return float(r.meta["pre_s"])
    return _drive_edges(r)[0]


def step_offset(r: TimeRecord) -> float:
    """When it switches off: onset + the runner's ``on_s``, else read off the drive (inf if it never does)."""
    if r.meta.get("on_s") is not None:
        return step_onset(r) + float(r.meta["on_s"])
    return _drive_edges(r)[1]


def sine_cycles(r: TimeRecord) -> tuple[float, float | None]:
    """(cycles to skip, cycles to use or None for every whole cycle after them) of a sine record.

    The runner's ``settle_cycles`` and ``cycles`` when it says them. An import cannot: a stepped sine then
    skips the first third of its whole cycles (the runner's design at its low frequencies: 2 settling + 4
    measured), a harmonic none (the runner's harmonic records have no settling cycles)."""
    m = r.meta
    cycles = float(m["cycles"]) if m.get("cycles") else None
    if m.get("settle_cycles") is not None:
        return float(m["settle_cycles"]), cycles
    if r.kind == RecordKind.STEPPED_SINE and m.get("frequency_Hz"):
        # + 0.01: a record of n cycles may end a rounding error short of n
        whole = math.floor((r.t[-1] - r.t[0]) * float(m["frequency_Hz"]) + 0.01)
        return float(round(whole / 3)), cycles
    return 0.0, cycles


def _finite(*arrays: np.ndarray) -> bool:
    return all(a.size > 0 and np.all(np.isfinite(a)) for a in arrays)


def regular_grid(t: np.ndarray, *cols: np.ndarray) -> tuple[int, int, np.ndarray, list[np.ndarray]]:
    """(samples filled, gaps, t, cols) on a uniform grid at the median spacing: a DAQ whose buffer overran loses whole
    packets while the rows kept carry their true time stamps. Every estimate downstream (the step simulated at the
    record's rate, block means, spectra) reads samples as evenly spaced; across a gap the columns are interpolated
    linearly (the samples are gone: nothing better is known). Records without gaps come back as they were."""
    if t.size < 3:
        return 0, 0, t, list(cols)
    dt = sample_spacing(t)
    gaps = int(np.sum(np.diff(t) > GAP * dt))
    if dt <= 0 or not gaps:
        return 0, 0, t, list(cols)
    n = int(round((t[-1] - t[0]) / dt)) + 1
    grid = t[0] + np.arange(n) * dt
    return n - t.size, gaps, grid, [np.interp(grid, t, c) for c in cols]


def _spacing(grid: np.ndarray) -> float:
    return float(grid[1] - grid[0]) if grid.size > 1 else 1.0


def filled_mask(t: np.ndarray, grid: np.ndarray) -> np.ndarray:
    """Per point of ``grid`` (``regular_grid``'s): True where no stamp of ``t`` fell within half a spacing of it, a value
    filled in rather than read."""
    near = np.clip(np.round((t - grid[0]) / _spacing(grid)).astype(int), 0, grid.size - 1)
    out = np.ones(grid.size, bool)
    out[near] = False
    return out


def held(t: np.ndarray, v: np.ndarray, grid: np.ndarray) -> np.ndarray:
    """``v`` read at the grid's points as its last value before each (a zero-order hold): a step's drive changes at
    an instant, so across a gap it holds until the next reading shows the change; a line drawn across the gap would
    be a ramp the strip never saw, and its current (C dv/dt over the gap) a current never drawn. A grid point within
    half a spacing of a stamp reads that stamp, as ``filled_mask`` counts it read (the grid is the stamps' own up to
    rounding, and the rounding of a median spacing grows along a long record: 7e-11 s at a minute's 60 000th sample)."""
    last = np.searchsorted(t, grid + 0.5 * _spacing(grid), side="right") - 1
    return v[np.clip(last, 0, v.size - 1)]


STAMP_LEVELS = 8  # distinct spacings (to 1 ppm of the median) at most for stamps rounded to a grid; jitter has many


def rounded_stamps(t: np.ndarray) -> np.ndarray | None:
    """The sampling clock's uniform grid under stamps that are it rounded (32-bit float stamps, a CSV's fixed decimals,
    whole milliseconds), or None. Such stamps step by a few distinct spacings and stay within half a spacing of
    their least-squares line; their median spacing is one of the rounded values, not the clock's (a 500 Hz record
    stamped in float32 at 1600 s into the session reads 512 Hz), and their scatter is not the samples' timing.
    Stamps with a continuous spread of spacings (a software-timed clock's jitter) are the samples' true times
    and are kept, as are uniform ones."""
    if t.size < 8:
        return None
    d = np.diff(t)
    dt = float(np.median(d))
    if not dt > 0:
        return None
    levels = np.unique(np.round(d / dt, 6))
    if not 2 <= levels.size <= STAMP_LEVELS:
        return None
    k = np.arange(t.size, dtype=float) - 0.5 * (t.size - 1)
    slope, mid = np.polyfit(k, t, 1)
    line = mid + slope * k
    return line if float(np.max(np.abs(t - line))) < 0.5 * slope else None


# a channel whose whole record spans less than this reads no signal: orders below any instrument's resolution (a
# Keyence LK-G's is 10-50 nm, a 24-bit DAQ's 1 uV), and above a float's rounding of a tared or rescaled reading
RESOLUTION_FLOOR = {"current": 1e-15, "displacement": 1e-12, "drive": 1e-12}  # A, m, V


def held_channels(r: TimeRecord) -> list[str]:
    """The record's channels that read one value throughout (a sine: after its settling cycles), up to a float's
    rounding (``RESOLUTION_FLOOR``): the responses (current, displacement) of any record, and a sine's drive. A live
    sensor's reading always changes by its noise or at least its last digit, so a reading that never does is held (a
    frozen logger, a sensor out of range, a hold-last-value export), not measured: its estimate would carry no noise,
    and every misfit weighed by it is 0/0. The loader leaves out a record whose displacement or drive is held, and
    keeps one whose current alone is."""
    used = slice(None)
    if r.kind in SINE_KINDS and r.meta.get("frequency_Hz"):  # a sine is estimated after its settling cycles only
        used = r.t >= r.t[0] + sine_cycles(r)[0] / float(r.meta["frequency_Hz"])
    chans = [("current", r.i), ("displacement", r.d)] + ([("drive", r.v)] if r.kind in SINE_KINDS else [])
    return [name for name, x in chans if not float(np.ptp(x[used])) >= RESOLUTION_FLOOR[name]]


# a logger's own scan clock faster than the samples repeats each until the next arrives: a row in five or more repeating
# the one before on every channel. A record read as sampled repeats far fewer: the simulated bench's quantised rests
# give at most 3.6 % (the tuning set's 40 sessions), a strip held still by a granular bed 7.5 % (fresh19)
HELD_SCAN_SHARE = 0.2


def held_scan(r: TimeRecord) -> np.ndarray | None:
    """The rows that carry a new sample (the first of each run of rows repeating every channel: drive, current,
    displacement), or None when fewer than ``HELD_SCAN_SHARE`` of the rows repeat. A scan-table logger or a historian
    exporting at a fixed rate faster than the DAQ writes, at each tick, the latest sample it has of every channel: the
    repeats are no measurements, and read as samples they make a staircase (its steps' images and the hold's beat with
    the sample clock read as lines in the spectrum, and each sample counts several times over in a fit). The rows kept
    are the ticks at which each sample arrived, late by under one tick on every channel alike; their stamps then step by
    a few whole ticks about the sample period, and ``rounded_stamps`` reads them on the sample clock's grid."""
    if r.t.size < 3:
        return None
    same = (np.diff(r.v) == 0) & (np.diff(r.i) == 0) & (np.diff(r.d) == 0)
    return np.r_[True, ~same] if np.mean(same) >= HELD_SCAN_SHARE else None


# readings of one clamp setting lie closer than this (in ln kPa) to their neighbours: a relaxing clamp read record by
# record drifts by a percent or two between records, while a sweep's settings stand 30 % (seed 001's 1300 -> 1700 kPa)
# to 200 % apart
SETTING_GAP = 0.08


def clamp_settings(readings: list[float]) -> dict[float, float]:
    """Each record's clamp pressure (kPa) -> its setting's: a lab that writes the load cell's reading on each record,
    not the setpoint, gives a new value on every record of a setting as the clamp relaxes. Sorted, readings within
    ``SETTING_GAP`` of the next (in ln p) are one setting; ``readings`` in the records' order, its pressure is the first
    record's reading, the clamp as it was set (every clamp form of the diagnosis counts its loss from the setting's
    force: a median, the force halfway through the creep, read a relaxing clamp 1-2 % above its setting at first and
    left no form able to start there). Exact setpoints map to themselves."""
    if not readings:
        return {}
    vals = np.sort(np.asarray(readings, float))
    logs = np.log(np.maximum(vals, 1e-9))
    group = np.r_[0, np.cumsum(np.diff(logs) > SETTING_GAP)]
    out: dict[float, float] = {}
    for g in np.unique(group):
        members = set(vals[group == g].tolist())
        first = next(float(r) for r in readings if r in members)
        out.update({float(v): first for v in members})
    return out


SPECTRUM_REPEAT_SHARE = 0.5  # a second spectrum sharing more of its frequencies than this is a repeat, not a band


def merged_repeats(f: np.ndarray, z: np.ndarray) -> tuple[np.ndarray, np.ndarray, int]:
    """A spectrum ascending in frequency, the values at one frequency measured more than once (an analyser that sweeps
    twice and writes both passes, a point re-measured, two bands that overlap) averaged: (f, Z, how many repeats were
    merged)."""
    f, z = np.asarray(f, float), np.asarray(z, complex)
    order = np.argsort(f, kind="stable")
    f, z = f[order], z[order]
    same = np.r_[False, np.diff(f) <= 1e-9 * f[1:]]  # the same frequency again
    group = np.cumsum(~same) - 1
    n = int(group[-1]) + 1
    count = np.bincount(group, None, n)
    f_out = np.bincount(group, f, n) / count
    z_out = (np.bincount(group, z.real, n) + 1j * np.bincount(group, z.imag, n)) / count
    return f_out, z_out, int(same.sum())


def join_spectra(a: tuple[np.ndarray, np.ndarray], b: tuple[np.ndarray, np.ndarray]) -> tuple[np.ndarray, np.ndarray] | None:
    """One spectrum from two bands of it (e.g. a potentiostat's FRA below some frequency, an impedance analyser
    above): the union of their frequencies, ascending, the two values averaged where both measured one. None where
    they share most of their frequencies (over ``SPECTRUM_REPEAT_SHARE`` of the shorter): that is the spectrum
    measured again, a moment of its own, not a band of it."""
    f, z, shared = merged_repeats(np.concatenate([a[0], b[0]]), np.concatenate([a[1], b[1]]))
    if shared > SPECTRUM_REPEAT_SHARE * min(a[0].size, b[0].size):
        return None
    return f, z


def _add_spectrum(b: PressureData, f: np.ndarray, z: np.ndarray, t_start: float, name: str, notes: list[str]) -> None:
    """A pressure's spectrum, or its next band: joined to one already read (its moment the earlier start), or, where it
    repeats that one, the later measurement kept with a note. A record that holds its frequencies more than once (the
    analyser's passes written into one file) is read as their average at each frequency."""
    f, z, repeats = merged_repeats(f, z)
    if repeats:
        notes.append(f"step {name}: {repeats} of the spectrum's frequencies measured more than once; each read as their average")
    if b.eis is None:
        b.eis, b.eis_t_start = (f, z), t_start
        return
    joined = join_spectra(b.eis, (f, z))
    if joined is None:
        notes.append(f"step {name}: spectrum repeats the one before it at {b.pressure_kPa:g} kPa; the later one used")
        b.eis, b.eis_t_start = (f, z), t_start
    else:
        b.eis = joined
        b.eis_t_start = min(b.eis_t_start, t_start) if np.isfinite(b.eis_t_start) else t_start


def load_session(path: str | Path, displacement_sign: int = 1, current_sign: int = 1) -> SessionData:
    """A session's records grouped by clamp setting, with what they give once loaded (``add_derived``);
    ``displacement_sign`` (``current_sign``) -1: every displacement (current) read with the opposite sign (a rig whose
    laser reads the strip's bend reversed, a potentiostat that counts the other current positive: labrig.fit.polarity).
    Spectra written as -Z'' (``spectra_convention``) are read as Z."""
    from labrig.store import SessionReader

    p = Path(path)
    if not p.exists():
        raise BadInput(f"{path}: no such session file")
    by_p: dict[float, PressureData] = {}
    notes: list[str] = []
    loose: list[TimeRecord] = []
    rounded = scanned = held_rows = 0
    groups: dict[int, tuple[PressureData | None, list[TimeRecord]]] = {}  # the records read, by clamp setting
    with SessionReader(p) as r:
        sample = dict(r.sample)
        steps = r.steps()  # read once: the clamp settings are grouped from all of them before any is bucketed
        readings = [float(st.metadata["pressure_kPa"]) for st in steps if st.metadata.get("pressure_kPa") is not None]
        setting = clamp_settings(readings)
        if len(set(setting.values())) < len(setting):
            notes.append(f"{len(setting)} distinct clamp pressures read on the records, grouped into "
                         f"{len(set(setting.values()))} clamp settings (each the median of its readings)")
        for st in steps:
            if st.status not in ("done",) or st.kind in HOLD_KINDS:
                if st.status not in ("done", "skipped") and st.kind not in HOLD_KINDS:
                    notes.append(f"step {st.name}: {st.status}, not used")
                continue
            pk = st.metadata.get("pressure_kPa")
            bucket = None
            if pk is not None:
                key = setting[float(pk)]
                bucket = by_p.setdefault(key, PressureData(key))
            streams = r.streams(st)
            if st.kind == RecordKind.EIS and "eis" in streams:
                s = r.stream(st, "eis")
                f, z = s["f_Hz"], s["z_re_ohm"] + 1j * s["z_im_ohm"]
                if not _finite(f, z.real, z.imag) or f.size < 3:
                    notes.append(f"step {st.name}: impedance spectrum has NaN or < 3 points, not used")
                elif bucket is not None:
                    _add_spectrum(bucket, f, z, float(st.t_start), st.name, notes)
                continue
            if "daq" not in streams:
                continue
            s = r.stream(st, "daq")
            fs_ = r.stream(st, "force") if "force" in streams else {"force_N": np.zeros(0), "t_s": np.zeros(0)}
            rec = TimeRecord(st.name, st.kind, dict(st.metadata), s["t_s"], s["v_V"], current_sign * s["i_A"], displacement_sign * s["disp_m"], fs_["force_N"], st.t_start, fs_["t_s"])
            if bucket is not None and bucket.pressure_kPa != float(pk):
                # the record belongs to its setting (what every reader groups by: the features, the split, the fits),
                # the load cell's reading on it kept beside
                rec.meta["pressure_read_kPa"], rec.meta["pressure_kPa"] = float(pk), bucket.pressure_kPa
            if not _finite(rec.t, rec.v, rec.i, rec.d) or rec.t.size < 8:
                notes.append(f"step {st.name}: record has NaN or too few samples, not used")
                continue
            groups.setdefault(id(bucket), (bucket, []))[1].append(rec)
    # a record written in pieces (a logger's file rotated mid-record) is read as the one record it was (pieces.py):
    # its pieces share a clamp setting
    for bucket, recs in groups.values():
        for rec in join_pieces(recs, notes):
            flat = held_channels(rec)
            if set(flat) - {"current"}:
                notes.append(f"step {rec.name}: {' and '.join(flat)} constant through the record (a reading held, "
                             "frozen or out of range: no noise to weigh it by), not used")
                continue
            if flat:  # the displacement is still a measurement: a lab that logs no current may write it as zeros
                notes.append(f"step {rec.name}: current constant through the record (not logged, or held): its current "
                             "carries no noise to weigh it by")
            fresh = held_scan(rec)
            if fresh is not None:  # a faster scan clock's repeats of each sample left out: the samples as they arrived
                held_rows += int(fresh.size - fresh.sum())
                rec.t, rec.v, rec.i, rec.d = rec.t[fresh], rec.v[fresh], rec.i[fresh], rec.d[fresh]
                scanned += 1
            grid = rounded_stamps(rec.t)
            if grid is not None:
                rounded += 1
                rec.t = grid
            filled = 0
            if rec.kind not in SINE_KINDS:  # a sine is demodulated at its samples' own times: gaps cost it nothing
                t_read = rec.t
                filled, gaps, rec.t, (rec.i, rec.d) = regular_grid(rec.t, rec.i, rec.d)
                if filled:
                    # the drive held across a gap, the responses interpolated and marked: the diagnosis compares the
                    # model where samples were read (a logger that thins a step's plateau, a buffer's lost packets)
                    rec.v, rec.filled = held(t_read, rec.v, rec.t), filled_mask(t_read, rec.t)
            if filled:
                notes.append(f"step {rec.name}: {filled} samples missing in {gaps} gaps of its time stamps, interpolated (the drive held)")
            if bucket is None:
                loose.append(rec)
                continue
            bucket.records.append(rec)
            if rec.kind == RecordKind.STEPPED_SINE:
                bucket.sines.append(sine_estimate(rec.t, rec.v, rec.i, rec.d, float(rec.meta["frequency_Hz"]), *sine_cycles(rec)))
    if scanned:
        notes.append(f"{scanned} records logged on a scan clock faster than their samples, each sample repeated until the next "
                     f"arrived: the {held_rows} repeated rows left out")
    if rounded:
        notes.append(f"{rounded} records' time stamps are a uniform clock rounded to a grid: read on that clock's grid")
    spectra_convention(list(by_p.values()), notes)
    for b in by_p.values():
        add_derived(b, notes)
    return SessionData(str(p), sample, [by_p[k] for k in sorted(by_p)], notes, loose, displacement_sign, current_sign)


# the share of a session's spectrum points with a positive imaginary part beyond which the spectra are -Z'': the strip
# is a passive RC line with constant-phase elements (seed 000, eqs. 5-12), capacitive at every frequency it is
# measured at (Im Z < 0); a cable's inductance may turn the top few points of a band, never most of the session's
MINUS_Z_SHARE = 0.8


def spectra_convention(buckets: list[PressureData], notes: list[str]) -> None:
    """Read spectra exported as -Z'' (the Nyquist plot's axis, a common export) as Z: where more than ``MINUS_Z_SHARE``
    of all the session's spectrum points have Im > 0, every spectrum is conjugated, with a note."""
    zs = [b.eis[1] for b in buckets if b.eis is not None]
    if not zs or np.mean(np.concatenate(zs).imag > 0) <= MINUS_Z_SHARE:
        return
    for b in buckets:
        if b.eis is not None:
            b.eis = (b.eis[0], np.conj(b.eis[1]))
    notes.append(f"the spectra's imaginary parts are positive at more than {MINUS_Z_SHARE:.0%} of their points, where the strip "
                 "is capacitive: read as -Z'' (a Nyquist plot's axis) and taken as Z")


def add_derived(b: PressureData, notes: list[str] | None = None) -> None:
    """What a pressure's records give once loaded: the stepped sines in frequency order, the multisine BLA, the drift."""
    b.sines.sort(key=lambda s: s.frequency_Hz)
    _add_multisine(b, [] if notes is None else notes)
    _add_drift(b)


# ------------------------------------------------------------------------------------------ multisine


def _design_key(r: TimeRecord) -> tuple:
    """Realisations of one multisine design share this (imports: period, rate and amplitude)."""
    m = r.meta
    return tuple(m.get(k) for k in ("period_s", "rms_V", "amplitude_V", "seed", "lead_in_s", "periods", "series")) + (round(r.fs, 3),)


def _multisine_layout(recs: list[TimeRecord]) -> dict[str, Any]:
    """Period grid, excited lines and transient handling of one design: from the runner's metadata, or
    for imported records (period_s only) from the drive's spectrum (DESIGN.md 6)."""
    m, fs = recs[0].meta, recs[0].fs
    period = float(m["period_s"])
    if "excited_bins" in m:  # the runner's design (older sessions drew lines per realisation: keep the common ones)
        each = [np.asarray(r.meta["excited_bins"], int) for r in recs]
        ex, anyex = functools.reduce(np.intersect1d, each), np.unique(np.concatenate(each))
        lead = int(round(float(m.get("lead_in_s", 0.0)) * fs))
        return {"period": period, "fs": fs, "excited": ex, "other": np.setdiff1d(anyex, ex), "periods": int(m["periods"]),
                "drop": int(m.get("transient_periods", 1)), "lead": lead}
    n = period * fs
    if abs(n - round(n)) > 0.02:
        raise ValueError(f"period_s = {period:g} s is not a whole number of samples at {fs:g} Hz")
    n = int(round(n))
    each = [excited_bins_from_drive(r.v, n) for r in recs]
    ex, anyex = functools.reduce(np.intersect1d, each), np.unique(np.concatenate(each))
    if ex.size == 0:
        raise ValueError("no excited lines in the drive's spectrum")
    g = int(np.gcd.reduce(ex))  # every line a multiple of g: the drive repeats every period / g
    n //= g
    N = min(r.v.size for r in recs)
    periods = N // n
    if periods < 1:
        raise ValueError(f"record shorter than one period ({period:g} s)")
    lead = _periodic_start(recs[0], n, periods) if periods > 1 else N - n
    return {"period": period / g, "fs": fs, "excited": ex // g, "other": np.setdiff1d(anyex, ex) // g, "periods": periods,
            "drop": 1 if periods >= 3 else 0, "lead": lead}


def _periodic_start(r: TimeRecord, n: int, periods: int) -> int:
    """Where ``periods`` whole periods sit best in an imported record with extra samples (pre-trigger,
    lead-in, a return to 0 V): the offset o whose first two periods differ least, summed over drive and
    displacement, each relative to its power (the response's start transient and any non-periodic samples
    raise the mismatch). Sliding sums make it O(N)."""
    N = r.v.size
    extra = N - periods * n
    if extra <= 0:
        return 0
    cost = np.zeros(extra + 1)
    for x in (r.v, r.d):
        x = np.asarray(x, float) - np.mean(x)
        sq = np.concatenate([[0], np.cumsum(x**2)])
        cross = np.concatenate([[0], np.cumsum(x[:-n] * x[n:])])
        o = np.arange(extra + 1)
        a, b, c = sq[o + n] - sq[o], sq[o + 2 * n] - sq[o + n], cross[o + n] - cross[o]
        cost += (a + b - 2 * c) / max(float(sq[-1]) / N * n, 1e-300)
    return int(np.argmin(cost))


def _add_multisine(b: PressureData, notes: list[str]) -> None:
    groups: dict[tuple, list[TimeRecord]] = {}
    for r in b.of_kind(RecordKind.MULTISINE):
        groups.setdefault(_design_key(r), []).append(r)
    for recs in groups.values():
        try:
            lay = _multisine_layout(recs)
            data = [{"v": r.v, "i": r.i, "d": r.d, "t0": r.t_start} for r in recs]
            b.blas.append(multisine_bla(data, lay["excited"], None, lay["period"], lay["periods"], lay["drop"], fs=lay["fs"], lead_in=lay["lead"], other_bins=lay["other"]))
        except (ValueError, KeyError, IndexError) as exc:
            notes.append(f"multisine {recs[0].name} at {b.pressure_kPa:g} kPa: no BLA ({exc})")
    if b.blas:
        b.bla = max(b.blas, key=lambda e: e.realisations * e.periods)


# ------------------------------------------------------------------------------------------ drift


def _stack(columns: list[tuple[np.ndarray, np.ndarray, np.ndarray]]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(t, G, var) columns of unequal length as M x L arrays, NaN where a column has no entry."""
    M = max(len(c[0]) for c in columns)
    out = [np.full((M, len(columns)), np.nan, dtype=d) for d in (float, complex, float)]
    for j, col in enumerate(columns):
        for a, c in zip(out, col):
            a[: len(c), j] = c
    return out[0], out[1], out[2]


def sine_skip(r: TimeRecord) -> float:
    """Cycles to skip for a rate of change: the settling cycles, at least one cycle of a harmonic record (its
    start transient would read as drift)."""
    return sine_cycles(r)[0] or (1.0 if r.kind == RecordKind.HARMONIC else 0.0)


def _add_drift(b: PressureData) -> None:
    """Drift of the gains at this pressure, from every source the records allow (see PressureData.drift)."""
    est = {**_multisine_drift(b.bla), **_sine_drift(b.records), **_step_drift(b.of_kind(RecordKind.STEP))}
    b.drift = {k: v for k, v in est.items() if v is not None}


def _multisine_drift(e: BlaEstimate | None) -> dict[str, DriftEstimate | None]:
    if e is None:
        return {}
    R, P, L = e.G_disp_rp.shape
    out = {}
    if R > 1:  # realisation means against record time (nonlinear scatter is absorbed by the Birge ratio)
        out["multisine/realisations"] = gain_drift(e.t_rp.mean(1), e.G_disp_rp.mean(1), e.var_disp_p / P)
    if P > 1:  # periods within each record: same phases, so the same distortion: noise only. Lines x records as columns
        t = np.repeat(e.t_rp[:, :, None], L, axis=2).transpose(1, 0, 2).reshape(P, R * L)
        var = np.broadcast_to(e.var_disp_p[None], (P, R, L)).reshape(P, R * L)
        out["multisine/periods"] = gain_drift(t, e.G_disp_rp.transpose(1, 0, 2).reshape(P, R * L), var)
    return out


def _sine_drift(records: list[TimeRecord]) -> dict[str, DriftEstimate | None]:
    """The gain's rate of change within each sine record (all records' rates combined); and identical sine
    records (kind, f, amplitude) repeated."""
    within, groups = [], {}
    for r in records:
        if r.kind in SINE_KINDS and "frequency_Hz" in r.meta:
            f = float(r.meta["frequency_Hz"])
            within.append(sine_gain_rate(r.t, r.v, r.d, f, sine_skip(r)))
            groups.setdefault((r.kind, f, r.meta.get("amplitude_V")), []).append(r)
    repeats = []
    for recs in (g for g in groups.values() if len(g) > 1):
        whole = [sine_segment_gains(r.t, r.v, r.d, float(r.meta["frequency_Hz"]), sine_skip(r), segments=1) for r in recs]
        # each segment's moment on the session clock: from the record's own first stamp, as the steps' (an import
        # stored as written keeps its CSV's clock in t)
        repeats.append(tuple(np.concatenate(c) for c in zip(*[(r.t_start + tm - r.t[0], g, var) for r, (tm, g, var) in zip(recs, whole)])))
    return {"sine/within": combine_rates(*(np.array(c) for c in zip(*within))) if within else None,
            "sine/repeats": gain_drift(*_stack(repeats)) if repeats else None}


def _step_drift(steps: list[TimeRecord]) -> dict[str, DriftEstimate | None]:
    """Identical step records (amplitude, on, off, pre) repeated: each one's scale onto their mean."""
    groups: dict[tuple, list[TimeRecord]] = {}
    for r in steps:
        groups.setdefault(tuple(r.meta.get(k) for k in ("amplitude_V", "on_s", "off_s", "pre_s")), []).append(r)
    cols = []
    for recs in (g for g in groups.values() if len(g) > 1):
        g, var = template_gains([r.d for r in recs])
        cols.append((np.array([r.t_start + np.mean(r.t) - r.t[0] for r in recs]), g.astype(complex), var))
    return {"step/repeats": gain_drift(*_stack(cols)) if cols else None}
