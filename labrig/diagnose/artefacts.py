"""Recording artefacts no catalogued cause makes, read off the sine records' time series.

Every catalogued effect acts through the strip, the electrodes or the sensor's calibration, so its response to a
sine is periodic at the drive's frequency (harmonics, and a slow drift of their amplitudes), plus the mains' lines.
Two things in a recording are neither, and no block of the diagnosis looks for them, because each leaves the
demodulated features almost untouched:

* **bursts**: the reading leaves its signal for a few samples and comes back, as a laser that holds its last value
  while it has lost the spot, a reading clipped at the end of its range, a dropout to a sentinel value. After the
  record's periodic part, its slow trend and its amplitude drift are removed, the residual is beyond ``BURST_Z``
  robust standard deviations for ``BURST_RUN`` or more samples in a row (``BURST_GUARD`` samples at each end of the
  segment not searched: a filter's transient of the drive's switch), in ``MIN_RECORDS`` records or more.
* **foreign lines**: a narrow line at a frequency that is neither a harmonic of the drive nor near the mains' (50
  or 60 Hz and harmonics, their sidebands at the drive's harmonics), each taken with its alias at the record's
  rate: a pump's or fan's vibration, a switching amplifier's ripple aliased into the band, a second instrument's
  clock. A bin of the residual's Hann periodogram above ``LINE_POWER`` times its neighbours' mean power (their
  median / ln 2), in ``MIN_RECORDS`` records or more.

* **wander**: the residual is not white: its mean power in ``WANDER_BAND_HZ`` (0.1-3 Hz, clear of the drive's
  harmonics and the mains) over its mean power in the white band (an eighth to a quarter of the record's rate) above
  ``WANDER_POWER``, in ``MIN_RECORDS`` records or more. A laser's and a current amplifier's noise is white over the
  band a record spans; a wander that does not repeat from cycle to cycle (air currents steering the beam, a bath's
  surface moving, a sensor's own 1/f) raises the cycle-to-cycle scatter the diagnosis takes for the session's noise,
  and so hides inside it: none of the feature blocks can show it.

* **noise that follows the drive**: the residual's level is not the same at every phase of the cycle: the largest
  over the smallest robust variance among ``PHASE_BINS`` phase bins, its median over the session's records above
  ``PHASE_NOISE``. A sensor whose noise grows with the target's speed or its distance (a laser's speckle, a
  vibrometer's dropouts at the turning points) or a contact that chatters while the strip moves makes it; a white
  noise added to the reading does not.

* **spells and shifts** (spells.py): the residual's noise rises for a while and falls back (a draught, a vibration
  or a transmitter switched on and off), or the current's level steps and stays (a rectified radio carrier, a
  switched amplifier range), inside a record, in ``MIN_RECORDS`` records or more.

* **lines on the drive's lattice** (drive_locked.py): foreign lines that are the drive's harmonics past those read, or
  a multiple of its frequency apart, beyond chance in ``MIN_RECORDS`` records or more: the channel's reading of the
  drive's response is transformed (a quantiser after the monitor, a sensor's hold), and the recording takes the verdict.

No threshold of the first three kinds was set on a set of sessions: they are tails of the noise's own law. Gaussian noise exceeds 6
sigma with probability 2e-9 per sample; a periodogram bin of noise exceeds 25 times its mean with probability
e^-25 = 1.4e-11 (chi-square with two degrees of freedom), so a session of 10^7 samples and 10^6 bins has about
1e-5 expected false alarms before the two-record rule; the ratio of two means of 16 or more such bins exceeds 10 with
probability below 1e-6. The phase test's statistic has no closed law (a range of eight robust variances): for white
noise with 100 samples a bin the largest over the smallest is about 1.6 (log range ~2.9 standard deviations of
0.17), and the median record of every clean session of every set read 1.5-1.8 (docs/diagnosis.md); 4 is beyond 8
standard deviations of it. What they read on the clean sessions of every set is in
docs/diagnosis.md ("Recording artefacts"). Only the sine records are read: their periodic part is known.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from scipy.ndimage import median_filter

from labrig.diagnose import spells
from labrig.diagnose.arming import ARMING_Z, arming
from labrig.diagnose.clipping import CLIP_RUN, UNITS, WRAP_SHARE, clipping, run_lengths, wrapping
from labrig.diagnose.drive_locked import lattice_chance, locked
from labrig.diagnose.load_cell import RECORD_SHARE, follows_drive
from labrig.diagnose.detrended import detrended
from labrig.diagnose.frozen import FROZEN_RUN, frozen
from labrig.diagnose.precursor import precursor
from labrig.diagnose import spectra_axis as axis
from labrig.diagnose.reversed_blocks import reversed_blocks
from labrig.diagnose.spells import robust_sigma
from labrig.estimate import MAINS_HZ, folded
from labrig.estimate.session_data import SessionData, TimeRecord, sine_skip
from labrig.records import SINE_KINDS

BURST_Z = 6.0  # robust standard deviations
BURST_RUN = 3  # samples in a row
# the segment's ends are not searched for bursts: the drive is switched just past them, and a logger's anti-alias
# filter (a decimating FIR, a delta-sigma converter's; zero-phase once its delay is taken off) spreads the switch's
# current spike a few samples back into the record, a transient that does not "come back" (fresh16's decimated clean
# session: 11-63 sigma on the last 3 of 199 samples before the switch, in 3 records)
BURST_GUARD = (4, 0.02)  # samples: at least 4, or this share of the segment
LINE_POWER = 25.0  # times the neighbouring bins' mean power
MIN_RECORDS = 2  # an artefact of the recording recurs; one record's event may be a knock on the table
HARMONICS = 10  # drive harmonics fitted before the residual is read (the catalogue's forms reach 3f; corners more)
DRIFT_HARMONICS = 3  # of them, those whose amplitude may drift linearly through the record
ALIAS_ORDERS = 60  # drive harmonics whose aliases are excluded from the line search
GUARD_BINS = 5  # bins either side of an excluded frequency
MAINS_GUARD_HZ = 2.0  # either side of a mains harmonic: a modulated mains line spreads by its modulation
NEIGHBOURS = 30  # bins on each side for the local mean power
LOBE = 2  # bins either side of a line that its Hann window spreads it over
MERGE_REL = 0.01  # lines of several records this close (relative) are one line
LOW_BINS = 8  # the lowest bins carry the trend's leakage
SLOW_WINDOW_S = 1.0  # the running median's window: an excursion up to half this long stands out of it
WANDER_POWER = 10.0  # the residual's mean power in WANDER_BAND_HZ over its mean power in the white band
WANDER_BAND_HZ = (0.1, 3.0)  # where a non-repeatable wander sits (air currents, a bath's motion, a sensor's 1/f)
WHITE_BAND = (1 / 8, 1 / 4)  # of the record's rate: the noise floor, clear of the trend and of an anti-alias filter
MIN_BINS = 16  # periodogram bins each band needs for its mean power to be read
PHASE_BINS = 8  # the cycle's phase bins the noise's level is read in
PHASE_SAMPLES = 100  # samples each phase bin needs
PHASE_NOISE = 4.0  # the records' median of (largest / smallest noise variance over the phase bins)
MIN_PHASE_RECORDS = 4  # records the median needs
CHANNELS = ("displacement", "current")


def _segment(r: TimeRecord) -> tuple[np.ndarray, np.ndarray, np.ndarray, float, float] | None:
    """(t, d, i, f0, lead) of a sine record's whole cycles after its settling cycles, centred in time, and the time of
    their first sample from the record's start; None if too short.
    The sample that closes the last cycle is left out: the drive is switched there (the record's end, or the next)."""
    f0 = float(r.meta.get("frequency_Hz") or 0.0)
    if r.kind not in SINE_KINDS or not f0 > 0 or r.t.size < 64:
        return None
    start = r.t[0] + sine_skip(r) / f0
    whole = math.floor((r.t[-1] - start) * f0 + 0.01)
    dt = float(np.median(np.diff(r.t)))
    keep = (r.t >= start - 0.5 * dt) & (r.t < start + whole / f0 - 0.5 * dt)
    if whole < 1 or keep.sum() < 64 or not (np.all(np.isfinite(r.d[keep])) and np.all(np.isfinite(r.i[keep]))):
        return None
    t = r.t[keep] - float(np.mean(r.t[keep]))
    return t, r.d[keep].astype(float), r.i[keep].astype(float), f0, float(r.t[keep][0] - r.t[0])


def _design(t: np.ndarray, f0: float, fs: float) -> np.ndarray:
    """Trend (quadratic), drive harmonics below Nyquist, and a linear drift of the first few harmonics' amplitude."""
    span = max(float(np.ptp(t)), 1e-12)
    u = 2 * t / span
    cols = [np.ones_like(t), u, u**2]
    for k in range(1, HARMONICS + 1):
        if k * f0 >= fs / 2:
            break
        c, s = np.cos(2 * np.pi * k * f0 * t), np.sin(2 * np.pi * k * f0 * t)
        cols += [c, s] + ([u * c, u * s] if k <= DRIFT_HARMONICS else [])
    return np.column_stack(cols)


def _periodic_median(e: np.ndarray, t: np.ndarray, f0: float) -> np.ndarray:
    """The residual's periodic part at every harmonic, as the median per phase bin (robust to the bursts sought)."""
    cycles = float(np.ptp(t)) * f0
    per_cycle = e.size / max(cycles, 1e-9)
    if cycles < 3 or per_cycle < 8:
        return np.zeros_like(e)
    nb = int(min(256, per_cycle // 2))
    b = np.minimum((np.mod(t * f0, 1.0) * nb).astype(int), nb - 1)
    return group_medians(e, b, nb)[b]


def _run_medians(xs: np.ndarray, start: np.ndarray, count: np.ndarray, empty: float) -> np.ndarray:
    """The median of each sorted run ``xs[start:start + count]`` (``np.median``'s: the mean of the two middle values
    of an even count), ``empty`` for a run of none."""
    ok = count > 0
    out = np.full(start.size, empty)
    lo, hi = start[ok] + (count[ok] - 1) // 2, start[ok] + count[ok] // 2
    out[ok] = 0.5 * (xs[lo] + xs[hi])
    return out


def group_medians(x: np.ndarray, group: np.ndarray, n: int) -> np.ndarray:
    """The median of ``x`` in each of groups 0..n-1 (0 for an empty group), from one sort instead of a pass per
    group."""
    count = np.bincount(group, minlength=n)
    return _run_medians(x[np.lexsort((x, group))], np.cumsum(count) - count, count, 0.0)


def _running_median(e: np.ndarray, fs: float, f0: float, periodic_removed: bool) -> np.ndarray:
    """The residual's slow part (a start transient, a drift faster than the trend) as a running median: it follows
    any monotonic stretch exactly and ignores an excursion shorter than half its window. The window is
    ``SLOW_WINDOW_S``, and at most a quarter cycle while the periodic part is still in the residual."""
    w = fs * SLOW_WINDOW_S if periodic_removed else min(fs * SLOW_WINDOW_S, fs / f0 / 4)
    w = int(min(max(w, 9), e.size // 4)) | 1
    return median_filter(e, size=w, mode="nearest") if w >= 9 else np.zeros_like(e)


def _bursts(e: np.ndarray, quantum: float) -> tuple[int, int, float]:
    """(runs, longest, worst z) of ``BURST_RUN`` or more consecutive samples beyond ``BURST_Z`` robust sigmas; the
    worst z is the largest level that ``BURST_RUN`` samples in a row all exceed (the margin a clean record leaves)."""
    sigma = max(robust_sigma(e), quantum / math.sqrt(12.0), 1e-300)
    z = np.abs(e - np.median(e)) / sigma
    lengths = run_lengths(z > BURST_Z)
    runs = lengths >= BURST_RUN
    held = np.lib.stride_tricks.sliding_window_view(z, BURST_RUN).min(axis=1) if z.size >= BURST_RUN else z
    return int(runs.sum()), int(lengths.max(initial=0)), float(held.max(initial=0.0))


def _quantum(y: np.ndarray) -> float:
    """The reading's code step: the smallest nonzero difference between samples (0 for an unquantised reading)."""
    d = np.abs(np.diff(y))
    d = d[d > 0]
    return float(d.min()) if d.size else 0.0


def _neighbour_mean(p: np.ndarray) -> np.ndarray:
    """Each bin's expected noise power from its neighbours beyond a line's own lobe: the median of ``NEIGHBOURS``
    bins on each side / ln 2 (the mean of an exponential law), the larger side's, so that a spectrum falling
    steeply (a slow residual's leakage) does not make its upper edge a line."""
    pad = np.pad(p, (NEIGHBOURS + LOBE, NEIGHBOURS + LOBE), constant_values=np.nan)  # no neighbours past either end
    # each window sorted once (nan last): the median of its finite values, as np.nanmedian's, far faster
    win = np.sort(np.lib.stride_tricks.sliding_window_view(pad, NEIGHBOURS), axis=1)
    med = _run_medians(win.ravel(), NEIGHBOURS * np.arange(win.shape[0]), NEIGHBOURS - np.isnan(win).sum(axis=1), np.nan)
    n = p.size
    left = med[:n]  # bins k-LOBE-NEIGHBOURS .. k-LOBE-1
    right = med[NEIGHBOURS + 2 * LOBE + 1: NEIGHBOURS + 2 * LOBE + 1 + n]  # k+LOBE+1 .. k+LOBE+NEIGHBOURS
    return np.fmax(left, right) / math.log(2.0)  # one side where the other has none (a line at Nyquist)


def _local_max(x: np.ndarray) -> np.ndarray:
    """Bins that are the largest within ``LOBE`` bins either side: one frequency per line, not its lobe."""
    pad = np.pad(x, LOBE, mode="constant", constant_values=-np.inf)
    return x >= np.lib.stride_tricks.sliding_window_view(pad, 2 * LOBE + 1).max(axis=1)


def _merge(freqs: list[float]) -> list[float]:
    """Frequencies within ``MERGE_REL`` of each other (the same line in several records) as one, their median."""
    out: list[list[float]] = []
    for f in sorted(freqs):
        if out and f - out[-1][-1] <= MERGE_REL * f:
            out[-1].append(f)
        else:
            out.append([f])
    return [float(np.median(g)) for g in out]


def _guarded(f: np.ndarray, fs: float, f0: float, orders: int, sidebands: int = 0) -> np.ndarray:
    """Bins above the lowest ``LOW_BINS``, clear of the drive's first ``orders`` harmonics and of the mains' lines
    with ``sidebands`` drive harmonics either side (a line modulated by the drive stays the mains'), each taken
    where it aliases at the record's rate."""
    df = f[1] - f[0]
    ok = np.ones(f.size, bool)
    ok[:LOW_BINS] = False
    for g in folded(f0 * np.arange(1, orders + 1), fs):
        ok[np.abs(f - g) <= GUARD_BINS * df] = False
    for base in MAINS_HZ:
        lines = base * np.arange(1, int(fs / base) + 2)
        for g in folded((lines[:, None] + f0 * np.arange(-sidebands, sidebands + 1)).ravel(), fs):
            ok[np.abs(f - g) <= max(MAINS_GUARD_HZ, GUARD_BINS * df)] = False
    return ok


def _foreign_lines(e: np.ndarray, fs: float, f0: float) -> tuple[list[tuple[float, float]], float]:
    """(frequency Hz, power over the neighbours' mean) of each bin of a foreign line in residual ``e``, and the
    largest such ratio of any bin searched (the margin a clean record leaves)."""
    n = e.size
    w = np.hanning(n)
    p = np.abs(np.fft.rfft((e - e.mean()) * w)) ** 2
    f = np.fft.rfftfreq(n, 1.0 / fs)
    ratio = p / np.maximum(_neighbour_mean(p), 1e-300)
    ok = _guarded(f, fs, f0, ALIAS_ORDERS, sidebands=3)
    peak = _local_max(ratio)
    hit = ok & (ratio > LINE_POWER) & peak
    return [(float(f[k]), float(ratio[k])) for k in np.flatnonzero(hit)], float(ratio[ok].max(initial=0.0))


def _wander(e: np.ndarray, fs: float, f0: float) -> float:
    """The residual's mean periodogram power in ``WANDER_BAND_HZ`` over its mean power in ``WHITE_BAND`` (both clear
    of the drive's harmonics and the mains): 1 for white noise; nan where either band has fewer than ``MIN_BINS``
    bins (a short record: its low band is the trend's). For white noise each mean is a mean of M exponential powers:
    their ratio exceeds 10 with M >= 16 (Hann: about M/2 independent) with probability below 1e-6."""
    n = e.size
    p = np.abs(np.fft.rfft((e - e.mean()) * np.hanning(n))) ** 2
    f = np.fft.rfftfreq(n, 1.0 / fs)
    if f.size < 3:
        return float("nan")
    ok = _guarded(f, fs, f0, HARMONICS)
    low = ok & (f >= WANDER_BAND_HZ[0]) & (f <= WANDER_BAND_HZ[1]) & (f < WHITE_BAND[0] * fs)
    white = _guarded(f, fs, f0, ALIAS_ORDERS) & (f >= WHITE_BAND[0] * fs) & (f <= WHITE_BAND[1] * fs)
    if low.sum() < MIN_BINS or white.sum() < MIN_BINS:
        return float("nan")
    return float(np.mean(p[low]) / max(np.mean(p[white]), 1e-300))


def _without_mains(e: np.ndarray, t: np.ndarray, f0: float, fs: float) -> np.ndarray:
    """Residual ``e`` less the mains' lines below Nyquist and their first sidebands at the drive's frequency (least
    squares): a line amplitude-modulated by the drive is pickup, not a noise that follows the drive."""
    cols = []
    for base in MAINS_HZ:
        for m in range(1, int(fs / 2 / base) + 1):
            for g in (m * base - f0, m * base, m * base + f0):
                if 0 < g < fs / 2:
                    cols += [np.cos(2 * np.pi * g * t), np.sin(2 * np.pi * g * t)]
    if not cols or len(cols) > e.size // 4:
        return e
    X = np.column_stack(cols)
    # over the record's whole cycles the columns are near orthogonal (lines f0 apart or more): their projections
    # stand for the least-squares fit at a fraction of its cost
    return e - X @ (X.T @ e / np.einsum("ij,ij->j", X, X))


def _phase_noise(e: np.ndarray, t: np.ndarray, f0: float, fs: float) -> float:
    """The largest over the smallest robust variance of residual ``e`` (its periodic and slow parts off, then the
    mains' lines) among ``PHASE_BINS`` bins of the drive's phase; nan when a bin holds fewer than ``PHASE_SAMPLES``
    samples."""
    e = _without_mains(e, t, f0, fs)
    b = np.minimum((np.mod(t * f0, 1.0) * PHASE_BINS).astype(int), PHASE_BINS - 1)
    if np.bincount(b, minlength=PHASE_BINS).min() < PHASE_SAMPLES:
        return float("nan")
    v = np.array([robust_sigma(e[b == j]) ** 2 for j in range(PHASE_BINS)])
    return float(v.max() / max(v.min(), 1e-300))


def record_artefacts(r: TimeRecord) -> dict[str, Any] | None:
    """Bursts, foreign lines, wander and phase-following noise of one sine record, per channel; None if the record
    cannot be read."""
    seg = _segment(r)
    if seg is None:
        return None
    t, d, i, f0, lead = seg
    fs = float(1.0 / np.median(np.diff(t)))
    X = _design(t, f0, fs)
    out: dict[str, Any] = {"record": r.name, "frequency_Hz": f0}
    for ch, y in (("displacement", d), ("current", i)):
        coef, *_ = np.linalg.lstsq(X, y, rcond=None)
        e = y - X @ coef
        per = _periodic_median(e, t, f0)
        e_burst = e - per
        e_burst = e_burst - _running_median(e_burst, fs, f0, bool(np.any(per)))
        g = max(BURST_GUARD[0], math.ceil(BURST_GUARD[1] * e_burst.size))
        runs, longest, zmax = _bursts(e_burst[g:-g], _quantum(y))
        lines, top = _foreign_lines(e, fs, f0)
        slow = _without_mains(e - per, t, f0, fs)
        quiet = slow - _running_median(slow, fs, f0, bool(np.any(per)))
        sp, sp_t = spells.spell(quiet, t, f0, fs)
        sh, sh_t = spells.shift(slow, quiet, fs) if ch in spells.SHIFT_CHANNELS else (float("nan"), float("nan"))
        out[ch] = {"bursts": runs, "longest": longest, "z_max": zmax, "lines": lines, "line_max": top, "wander": _wander(e, fs, f0),
                   "lattice_p": lattice_chance([hz for hz, _ in lines], f0, fs / e.size),
                   "phase_noise": _phase_noise(e_burst, t, f0, fs), "spell": sp, "spell_t": lead + sp_t, "shift": sh, "shift_t": lead + sh_t}
    return out


def _timed(per: list[dict[str, Any]], key: str, limit: float) -> dict[str, Any]:
    """A window test's records over ``limit`` (per channel), the worst record and where in it."""
    hits = [(a, ch) for a in per for ch in CHANNELS if np.isfinite(a[ch][key]) and a[ch][key] > limit]
    worst = max(hits, key=lambda h: h[0][h[1]][key], default=None)
    records = len({id(a) for a, _ in hits})
    return {"records": records, "channels": sorted({ch for _, ch in hits}),
            "frequencies_Hz": sorted({a["frequency_Hz"] for a, _ in hits}),
            "worst": None if worst is None else {"record": worst[0]["record"], "channel": worst[1], "value": worst[0][worst[1]][key],
                                                 "time_s": worst[0][worst[1]][key + "_t"]},
            "flagged": records >= MIN_RECORDS}


def artefacts(sd: SessionData) -> dict[str, Any]:
    """The session's recording artefacts: per kind, the records that carry one, and whether it is flagged."""
    per = [a for a in (record_artefacts(r) for r in sd.all_records()) if a is not None]
    burst_recs = [a for a in per if any(a[ch]["bursts"] for ch in ("displacement", "current"))]
    line_recs = [a for a in per if any(a[ch]["lines"] for ch in ("displacement", "current"))]
    wander_recs = [a for a in per if any(a[ch]["wander"] > WANDER_POWER for ch in ("displacement", "current"))]
    lines: dict[str, list[float]] = {}
    for a in line_recs:
        for ch in ("displacement", "current"):
            for hz, _ in a[ch]["lines"]:
                lines.setdefault(ch, []).append(hz)
    out = {
        "records_read": len(per),
        "bursts": {"records": len(burst_recs), "runs": int(sum(a[ch]["bursts"] for a in burst_recs for ch in ("displacement", "current"))),
                   "channels": sorted({ch for a in burst_recs for ch in ("displacement", "current") if a[ch]["bursts"]}),
                   "flagged": len(burst_recs) >= MIN_RECORDS},
        "lines": {"records": len(line_recs), "frequencies_Hz": {ch: [float(f"{f:.4g}") for f in _merge(v)][:20] for ch, v in lines.items()},
                  "flagged": len(line_recs) >= MIN_RECORDS},
        "wander": {"records": len(wander_recs),
                   "channels": sorted({ch for a in wander_recs for ch in ("displacement", "current") if a[ch]["wander"] > WANDER_POWER}),
                   "frequencies_Hz": sorted({a["frequency_Hz"] for a in wander_recs}), "flagged": len(wander_recs) >= MIN_RECORDS},
        "burst_z": BURST_Z, "burst_run": BURST_RUN, "line_power": LINE_POWER, "wander_power": WANDER_POWER, "min_records": MIN_RECORDS,
        "phase_noise_limit": PHASE_NOISE,
    }
    phase = {}
    for ch in ("displacement", "current"):
        v = [a[ch]["phase_noise"] for a in per if np.isfinite(a[ch]["phase_noise"])]
        phase[ch] = float(np.median(v)) if len(v) >= MIN_PHASE_RECORDS else float("nan")
    out["phase_noise"] = {"median": phase, "channels": sorted(ch for ch, v in phase.items() if v > PHASE_NOISE),
                          "flagged": any(v > PHASE_NOISE for v in phase.values())}
    out["spells"] = _timed(per, "spell", spells.SPELL_POWER)
    out["shifts"] = _timed(per, "shift", spells.SHIFT_Z)
    out["spell_power"], out["shift_z"] = spells.SPELL_POWER, spells.SHIFT_Z
    out["clipped"] = clipping(sd, MIN_RECORDS)
    out["wrapped"] = wrapping(sd, MIN_RECORDS)
    out["arming"] = arming(sd, MIN_RECORDS)
    out["load_cell"] = follows_drive(sd)  # the force reading carries the drive's line (load_cell.py)
    out["reversed"] = reversed_blocks(sd)  # the reading's sign changed between the settings (reversed_blocks.py)
    out["locked"] = locked(per, CHANNELS, MIN_RECORDS)  # foreign lines on the drive's lattice (drive_locked.py)
    out["detrended"] = detrended(sd)  # the step records' displacement stored with its mean taken off (detrended.py)
    out["frozen"] = frozen(sd)  # a channel repeating one reading while the other goes on (frozen.py)
    out["precursor"] = precursor(sd)  # a reading that leaves its rest before the drive's edges (precursor.py)
    out["spectra_axis"] = axis.spectra_axis(sd)  # the spectra's frequency column out of step (spectra_axis.py)
    out["flagged"] = any(out[k]["flagged"] for k in ("load_cell", "reversed", "bursts", "lines", "wander", "phase_noise", "spells", "shifts",
                                                      "clipped", "wrapped", "arming", "locked", "detrended", "frozen",
                                                      "precursor", "spectra_axis"))
    wander = [a[ch]["wander"] for a in per for ch in ("displacement", "current") if np.isfinite(a[ch]["wander"])]
    out["max"] = {"burst_z": max((a[ch]["z_max"] for a in per for ch in ("displacement", "current")), default=0.0),
                  "line_power": max((a[ch]["line_max"] for a in per for ch in ("displacement", "current")), default=0.0),
                  "wander": max(wander, default=0.0),
                  "phase_noise": max((v for v in phase.values() if np.isfinite(v)), default=0.0),
                  "spell": _second(per, "spell"), "shift": _second(per, "shift"),
                  "clip_run": out["clipped"]["longest_run"] if out["clipped"]["flagged"] else 0, "arming_z": out["arming"]["second_z"],
                  "wrap_share": out["wrapped"]["largest_share"] if out["wrapped"]["flagged"] else 0.0,
                  "load_cell_share": len(out["load_cell"]["records"]) / max(out["load_cell"]["read"], 1) if out["load_cell"]["flagged"] else 0.0,
                  "reversed": 2.0 if out["reversed"]["flagged"] else 0.0, "locked": 2.0 if out["locked"]["flagged"] else 0.0,
                  "detrended": 2.0 if out["detrended"]["flagged"] else 0.0,
                  "frozen_run": out["frozen"]["longest_run"] if out["frozen"]["flagged"] else 0,
                  "precursor": out["precursor"]["largest"] if out["precursor"]["flagged"] else 0.0,
                  "spectra_axis": out["spectra_axis"]["mismatch"] / max(out["spectra_axis"]["shifted"], 1e-12) / axis.GAIN
                  if out["spectra_axis"]["flagged"] else 0.0}
    return out


def _second(per: list[dict[str, Any]], key: str) -> float:
    """The second largest record's value of a window test (the two-record rule's margin), per channel's worst."""
    v = sorted((max((a[ch][key] for ch in CHANNELS if np.isfinite(a[ch][key])), default=0.0) for a in per), reverse=True)
    return float(v[1]) if len(v) > 1 else 0.0


def level(a: dict[str, Any]) -> float:
    """The worst artefact over its threshold: the sustained burst level / ``BURST_Z``, the line power / ``LINE_POWER``,
    the wander / ``WANDER_POWER`` or the phase-following noise / ``PHASE_NOISE``, whichever is largest (> 1 for a
    flagged kind)."""
    m = a["max"]
    return float(max(m["burst_z"] / BURST_Z, m["line_power"] / LINE_POWER, m.get("wander", 0.0) / WANDER_POWER,
                     m.get("phase_noise", 0.0) / PHASE_NOISE, m.get("spell", 0.0) / spells.SPELL_POWER, m.get("shift", 0.0) / spells.SHIFT_Z,
                     m.get("clip_run", 0) / CLIP_RUN, m.get("arming_z", 0.0) / ARMING_Z, m.get("wrap_share", 0.0) / WRAP_SHARE, m.get("load_cell_share", 0.0) / RECORD_SHARE, m.get("reversed", 0.0),
                     m.get("locked", 0.0), m.get("detrended", 0.0), m.get("frozen_run", 0) / FROZEN_RUN,
                     m.get("precursor", 0.0), m.get("spectra_axis", 0.0)))


def _records(names: list[str], kind: str = "") -> str:
    """'n [kind]records (the first four, ...)'."""
    return f"{len(names)} {kind}records ({', '.join(names[:4])}{', ...' if len(names) > 4 else ''})"


def _by_channel(names: dict[str, list[str]]) -> list[str]:
    """The records a check named on any channel ({channel: records}), each once, sorted."""
    return sorted({n for v in names.values() for n in v})


def detail(a: dict[str, Any]) -> str:
    """One line for the report and the JSON's ``residual.where``: what the recording shows and where."""
    parts = []
    if a.get("clipped", {}).get("flagged"):
        c = a["clipped"]
        parts.append("; ".join(f"the {ch} reading held at {', '.join(f'{x:g} {UNITS[ch]}' for x in c['levels'][ch][:4])} (the end of its range) in "
                               f"{_records(c['records'][ch])}"
                               for ch in c["channels"])
                     + f", up to {c['longest_run']} readings in a row: a clipped channel, whose features are not the signal")
    if a.get("wrapped", {}).get("flagged"):
        w = a["wrapped"]
        parts.append("; ".join(f"the {ch} reading jumps by half its record's span or more in one sample and stays there, away from the drive's edges, in "
                               f"{_records(w['records'][ch])}"
                               for ch in w["channels"]) + ": a reading carried round its converter's or register's range, whose features are not the signal")
    if a["bursts"]["flagged"]:
        b = a["bursts"]
        parts.append(f"the {' and '.join(b['channels'])} reading leaves its signal for {BURST_RUN}+ samples ({b['runs']} times in "
                     f"{b['records']} sine records): held, clipped or dropped readings")
    if a["lines"]["flagged"]:
        fr = "; ".join(f"{ch} {', '.join(f'{x:g}' for x in v[:6])} Hz" for ch, v in a["lines"]["frequencies_Hz"].items())
        parts.append(f"narrow lines neither the drive's harmonics nor the mains' in {a['lines']['records']} sine records ({fr})")
    if a.get("locked", {}).get("flagged"):
        k = a["locked"]
        parts.append(f"the {' and '.join(k['channels'])} lines sit on the drive's frequency lattice (its harmonics past those read, or lines a "
                     f"multiple of it apart) in {k['records']} sine records (drives {', '.join(f'{x:g}' for x in k['frequencies_Hz'][:6])} Hz; "
                     f"chance at most 1e{k['worst_log10_p']:.0f}): the reading of the drive's response passes through something "
                     f"that is neither linear nor the strip's (a quantiser after the drive's monitor, a sensor's peak or sample hold)")
    if a["wander"]["flagged"]:
        w = a["wander"]
        parts.append(f"the {' and '.join(w['channels'])} wanders at {WANDER_BAND_HZ[0]:g}-{WANDER_BAND_HZ[1]:g} Hz up to "
                     f"{a['max']['wander']:.0f}x its white noise's power, not repeating from cycle to cycle ({w['records']} sine records, "
                     f"drives {', '.join(f'{x:g}' for x in w['frequencies_Hz'][:6])} Hz): air currents in the beam, a moving bath, a sensor's drift")
    if a["phase_noise"]["flagged"]:
        q = a["phase_noise"]
        parts.append(f"the {' and '.join(q['channels'])} noise follows the drive's phase (its variance up to "
                     f"{a['max']['phase_noise']:.1f}x from one part of the cycle to another, median over the sine records): a sensor's "
                     f"noise growing with the target's speed or range, a contact chattering while the strip moves")
    if a.get("reversed", {}).get("flagged"):
        r = a["reversed"]
        parts.append(f"the displacement reads the strip's bend reversed at {', '.join(f'{p:g}' for p in r['reversed_kPa'])} kPa and as the "
                     f"model does at the other settings (FRF phase agreement per setting {r['agreement']}): the sensor moved to the "
                     f"strip's other face, or the strip clamped the other way round, at a re-clamping")
    if a.get("detrended", {}).get("flagged"):
        t = a["detrended"]
        parts.append(f"the displacement has no mean in any of the {t['records']} step records (at most {t['largest_mean_share']:.1e} of its "
                     f"RMS, where a strip's step keeps a third of it or more): the records were detrended before they were stored (an export's "
                     f"drift correction, AC coupling in software), which moves each step's plateau and rest by about half the step")
    if a.get("frozen", {}).get("flagged"):
        z = a["frozen"]
        parts.append(f"the {' and '.join(z['channels'])} repeats one reading for up to {z['longest_run']} samples while the other channel "
                     f"goes on with its noise, in {_records(_by_channel(z['names']))}: a sensor's output held "
                     f"(a hold input wired to a trigger, a controller rebooting, a logger repeating its last frame), not the strip")
    if a.get("precursor", {}).get("flagged"):
        q = a["precursor"]
        parts.append(f"the {' and '.join(q['channels'])} leaves its rest before the drive's edges (by {q['z']:g}+ times its noise and "
                     f"{q['share']:.0%}+ of its response) in {_records(_by_channel(q['names']), 'step ')}: "
                     f"processing that is not causal (a filter run forward and backward, a centred or spline smoother, an FFT filter), "
                     f"not the strip, which cannot move before its drive")
    if a.get("spectra_axis", {}).get("flagged"):
        parts.append(axis.detail(a["spectra_axis"]))
    if a.get("load_cell", {}).get("flagged"):
        c = a["load_cell"]
        parts.append(f"the load cell's force carries the drive's frequency in {_records(c['records'], 'sine ')} of {c['read']} read, one "
                     f"sign of the current's: the current or the drive reaching the bridge (a shared ground, a cable beside the "
                     f"drive's leads), not a force the clamp or the strip makes")
    if a.get("arming", {}).get("flagged"):
        g = a["arming"]
        parts.append(f"the {' and '.join(g['channels'])} is not at rest for the first {g['window_s']:g} s of {_records(g['records'], 'step ')}, "
                     f"its scatter up to "
                     f"z = {a['max']['arming_z']:.0f} over the rest's before the edge: something switched as each record is armed "
                     f"(a relay ringing the sensor's stand, an amplifier settling)")
    for key, what in (("spells", "the {ch} noise rises {v:.0f}-fold for a while and falls back (a spell: a draught or a jet "
                                  "buffeting the strip, a vibration or a transmitter switched on and off)"),
                      ("shifts", "the {ch} level steps by {v:.0f} times its noise and stays (a rectified radio carrier, a "
                                 "switched amplifier range, a connector making and breaking)")):
        x = a.get(key, {})
        if x.get("flagged"):
            w = x["worst"]
            parts.append(what.format(ch=" and ".join(x["channels"]), v=w["value"]) + f" in {x['records']} sine records, worst "
                         f"{w['time_s']:.3g} s into {w['record']}")
    return "; ".join(parts)
