"""The verdict's tests and where a residual sits.

Each feature block's held-out residual is in units of that session's own noise (cycle-to-cycle scatter of the
demodulated sine records, the pre-step baseline of each step record, the neighbouring bins of a line's spectrum,
the load cell's counts) in quadrature with a relative model floor (``engine.FRF_FLOOR`` ...: documented priors).
A block is consistent with the session when its RMS level stays within the baseline's attainable accuracy
(``engine.CLEAN_ACCURACY``, a prior in those same session units) times ``STRUCTURE_MARGIN``; a block above that
carries structure the baseline does not explain. ``none`` needs every block consistent; a block above it with no
catalogued extension removing it is ``unexplained``, and ``where`` says in which band, harmonic order, record time
or line it sits.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from labrig.diagnose.features import LINE_CHANNELS

# A block's level above this many times its attainable accuracy is structure, not noise. Set on the tuning set's
# clean sessions (largest level / accuracy over ten clean paper sweeps: 0.93, docs/diagnosis.md); a level of 1.5 in
# a block of n >= 30 points is also far beyond the chi-square spread of noise alone (sqrt(1 + 3 sqrt(2/n)) ~ 1.3).
STRUCTURE_MARGIN = 1.5


def abscissa(name: str, ctx, size: int) -> tuple[np.ndarray, str, bool, np.ndarray]:
    """Where each residual of a block sits: frequency for sine blocks, time for steps, else its index.

    Follows the layout of ``engine.blocks`` (real parts then imaginary parts); when a block's size does not
    match that layout it falls back to the index rather than mislabelling points."""
    f = np.array([s.f for s in ctx.sines])
    x, x_label, log = f, "drive frequency (Hz)", True
    amp = np.array([s.amplitude_V for s in ctx.sines])
    if f.size > 1 and np.ptp(f) == 0 and np.ptp(amp) > 0:  # an amplitude series: one frequency, several drives
        x, x_label, log = amp, "drive amplitude (V)", False
    if name in ("frf_d", "frf_i") and size == 2 * f.size:
        return np.tile(x, 2), x_label, log, np.repeat(np.array(["Re", "Im"], dtype=object), f.size)
    if name in ("harm_d", "harm_i") and size == 4 * f.size:
        series = np.array([f"{k} {part}" for part in ("Re", "Im") for _ in f for k in ("2f", "3f")], dtype=object)
        return np.tile(np.repeat(x, 2), 2), x_label, log, series
    if name == "force" and size == f.size:
        return np.arange(size, dtype=float), "sine record (in order)", False, np.full(size, "", dtype=object)
    if name in ("step_d", "step_i") and size == sum(st.observed(st.t).size for st in ctx.steps):
        x = np.concatenate([st.observed(st.t - st.t[0]) for st in ctx.steps]) if ctx.steps else np.zeros(0)
        lab = np.concatenate([np.full(st.observed(st.t).size, _pressure_label(st.pressure_kPa), dtype=object) for st in ctx.steps]) if ctx.steps else x
        return x, "time from record start (s)", False, lab
    if name == "eis" and getattr(ctx, "spectra", None) and size == 2 * sum(sp.f.size for sp, _ in ctx.spectra):
        f = np.concatenate([sp.f for sp, _ in ctx.spectra])
        lab = np.concatenate([np.full(sp.f.size, _pressure_label(sp.pressure_kPa), dtype=object) for sp, _ in ctx.spectra])
        return np.tile(f, 2), "spectrum frequency (Hz)", True, np.tile(lab, 2)
    if name == "line":
        series = np.array([f"{LINE_CHANNELS[ch][0]} {hz:g} Hz" for line in ctx.lines
                           for (ch, hz), fl in line.floor.items() if np.isfinite(fl) and fl > 0], dtype=object)
        if series.size == size:  # the engine skips components without a finite noise floor
            return np.arange(size, dtype=float), "line component (record by record)", False, series
    return np.arange(size, dtype=float), "feature index", False, np.full(size, "", dtype=object)


def _pressure_label(p: float | None) -> str:
    return "no pressure" if p is None else f"{p:g} kPa"


# ``residual.where`` entries that are findings, not a block's residual: their level is not in units of an accuracy
FINDINGS = frozenset({"drive", "clock", "recording", "drive_monitor"})


def where_text(w: dict[str, Any], accuracy: str = "its attainable accuracy") -> str:
    """One ``residual.where`` entry in words: a block's level over its accuracy and where it sits, or a finding."""
    if w["block"] in FINDINGS:
        return f"{w['block']}: {w['detail']}"
    return f"{w['block']}: level {w['level']:.3g} ({w['over_accuracy']:.2f} x {accuracy}), {w['detail']}"


def structured(levels: dict[str, float], accuracy: dict[str, float]) -> dict[str, float]:
    """The blocks whose level exceeds STRUCTURE_MARGIN x their attainable accuracy, as level / accuracy."""
    out = {k: v / accuracy.get(k, 1.0) for k, v in levels.items()}
    return {k: r for k, r in out.items() if r > STRUCTURE_MARGIN}


def _span(x: np.ndarray, mag: np.ndarray) -> tuple[float, float, float]:
    """(low, high, worst) abscissa of the points carrying the residual: those above half the largest."""
    hot = mag >= 0.5 * mag.max()
    return float(x[hot].min()), float(x[hot].max()), float(x[int(np.argmax(mag))])


def locate(name: str, r: np.ndarray, ctx) -> dict[str, Any]:
    """Where a block's residual ``r`` (noise units, ``engine.blocks`` layout) concentrates."""
    x, label, _, series = abscissa(name, ctx, r.size)
    if name in ("frf_d", "frf_i") and label != "feature index":
        n = r.size // 2
        mag = np.hypot(r[:n], r[n:])
        lo, hi, worst = _span(x[:n], mag)
        unit = "Hz" if "frequency" in label else "V"
        return {"detail": f"{lo:.3g}-{hi:.3g} {unit}, worst at {worst:.3g} {unit}", "band": [lo, hi], "worst": worst}
    if name == "eis" and label != "feature index":
        n = r.size // 2
        mag = np.hypot(r[:n], r[n:])
        lo, hi, worst = _span(x[:n], mag)
        return {"detail": f"{lo:.3g}-{hi:.3g} Hz of the spectra, worst at {worst:.3g} Hz ({series[int(np.argmax(mag))]})",
                "band": [lo, hi], "worst": worst}
    if name in ("harm_d", "harm_i") and label != "feature index":
        n = r.size // 2
        mag = np.hypot(r[:n], r[n:])  # (sine, order) interleaved: 2f, 3f per sine
        per_order = {k: float(np.sqrt(np.mean(mag[j::2] ** 2))) for j, k in enumerate((2, 3))}
        order = max(per_order, key=per_order.get)
        m = mag[(order - 2)::2]
        lo, hi, worst = _span(x[:n][(order - 2)::2], m)
        return {"detail": f"harmonic {order}f, drive {lo:.3g}-{hi:.3g} Hz, worst at {worst:.3g} Hz", "harmonic": order,
                "band": [lo, hi], "worst": worst}
    if name in ("step_d", "step_i") and label != "feature index":
        mag = np.abs(r)
        lo, hi, worst = _span(x, mag)
        where = str(series[int(np.argmax(mag))])
        return {"detail": f"{lo:.3g}-{hi:.3g} s into the step record, worst at {worst:.3g} s ({where})", "time_s": [lo, hi], "worst": worst}
    if name == "line" and label != "feature index":
        comp = {}
        for s, v in zip(series, np.abs(r)):
            comp[s] = max(comp.get(s, 0.0), float(v))
        top = max(comp, key=comp.get)
        return {"detail": f"{top} (largest of {len(comp)} components)", "component": top}
    if r.size:
        k = int(np.argmax(np.abs(r)))
        return {"detail": f"{label} {x[k]:g} is the largest", "worst": float(x[k])}
    return {"detail": ""}


def where(bl: dict, ctx, accuracy: dict[str, float]) -> list[dict[str, Any]]:
    """The blocks of ``bl`` (``engine.blocks`` output) above their attainable accuracy, worst first, each with its
    level in units of the session's noise (and model floor), that level over the accuracy, and where it sits."""
    out = []
    for name, (r, _) in bl.items():
        if not r.size:
            continue
        level = float(np.sqrt(np.mean(r**2)))
        acc = accuracy.get(name, 1.0)
        if level > acc:
            out.append({"block": name, "level": level, "over_accuracy": level / acc, **locate(name, r, ctx)})
    return sorted(out, key=lambda w: -w["over_accuracy"])


# A displacement recorded on a clock off the drive's: its phase against the drive walks by 2 pi eps per cycle. No
# catalogued cause does that (each one's response is periodic at the drive's frequency), so a session whose sine
# records agree on a significant eps is outside the catalogue. Two tests, neither set on a set of sessions: the
# weighted mean eps over the records is beyond CLOCK_Z of its standard error, scaled up by the records' own
# scatter about it (sqrt(chi2/dof) when > 1); and the phase error it makes over a median record's half-length,
# pi eps cycles, is beyond the FRF's model floor (``engine.FRF_FLOOR``, rad): below that no block can see it.
CLOCK_Z = 5.0


def clock_offset(sines, floor_rad: float) -> dict[str, Any]:
    """The displacement's clock against the drive's from the sine records' phase trends (``SineEstimate``)."""
    e = np.array([s.est.phase_drift for s in sines], float) / (2 * np.pi)
    sg = np.array([s.est.phase_drift_sigma for s in sines], float) / (2 * np.pi)
    ok = np.isfinite(sg) & (sg > 0) & np.isfinite(e)
    if ok.sum() < 3:
        return {"relative_offset": 0.0, "z": 0.0, "phase_error_rad": 0.0, "records": int(ok.sum()), "flagged": False}
    w = 1 / sg[ok] ** 2
    m = float(np.sum(w * e[ok]) / np.sum(w))
    scatter = math.sqrt(max(float(np.sum(w * (e[ok] - m) ** 2)) / (ok.sum() - 1), 1.0))
    z = m / (scatter / math.sqrt(float(np.sum(w))))
    cycles = float(np.median([s.est.noise_dof / 2 + 1 for s, k in zip(sines, ok) if k]))  # whole cycles demodulated
    phase = math.pi * abs(m) * cycles
    return {"relative_offset": m, "z": float(z), "phase_error_rad": phase, "records": int(ok.sum()),
            "flagged": bool(abs(z) > CLOCK_Z and phase > floor_rad)}
