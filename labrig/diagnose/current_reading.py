"""A rival outside the catalogue: the current read through an amplifier that compresses its large readings.

A transimpedance amplifier with antiparallel diodes across its feedback resistor (the usual guard against overload),
a log amplifier, or a current amplifier running into its rails reads large currents short: the reading is an odd,
static, compressive map of the strip's current, r(i) = i / (1 + |i/a|^n)^(1/n) here (a the current it saturates
towards, n how sharply: 2 soft, 8 nearly a clip), linear at the small currents. Sines lose their crests (the
fundamental's gain falls with the current's amplitude, a 3rd harmonic opposing the crest, at three times the
current's phase, not the drive's), every step's charging spike reads short and its plateau does not, and the
analyser's small-signal spectra are untouched. A faradaic branch in parallel distorts the current alone too, by a
map of the *voltage*, and always adds current at the large drives; fresh37's amplifier with feedback diodes (seen)
read ``faradaic_current`` (the transport form at 0.474 of the baseline's held-out error) with the current's third
harmonic left 27x its accuracy.

``engine._rival`` fits it where the named cause is one of ``CHALLENGED`` (a cause of the current's distortion) and the
baseline leaves ``harm_i`` structured, and lets it take the verdict when it halves the named cause's held-out error
(``SHARE``, as a second resonator does). docs/diagnosis.md, "A current read short".
"""

from __future__ import annotations

import numpy as np

from labrig.diagnose.catalogue import Context, Extension, _drive, baseline, cosine_harmonics, specimen_for
from labrig.diagnose.challenger import Challenger
from labrig.diagnose.features import step_grid
from labrig.physics import timeresp

CHALLENGED = frozenset({"faradaic_current", "strain_resistance"})
SHARE = 0.5  # as second_mode.SHARE: the standard a named cause meets against the baseline
_N = 64  # samples per cycle of the map's describing function


def compress(i, th):
    """r(i) = i / (1 + |i/a|^n)^(1/n) (module docstring)."""
    a, n = th
    i = np.asarray(i, float)
    return i / (1.0 + np.abs(i / max(a, 1e-12)) ** n) ** (1.0 / n)


def _step_currents(ctx: Context) -> list[np.ndarray | None]:
    """Each step record's linear current at its own full rate (once per context: it reads the specimens only)."""
    hit = ctx.cache.get("current_reading_steps")
    if hit is None:
        hit = []
        for st in ctx.steps:
            if st.fs_full <= 0 or st.v_full.size == 0:
                hit.append(None)
                continue
            nfft, sigma, (_, y) = step_grid(specimen_for(ctx.specimens, st.pressure_kPa), st.v_full.size, st.fs_full)
            (i,) = timeresp.respond(st.v_full, st.fs_full, (nfft, sigma, [y]))
            hit.append(i)
        ctx.cache["current_reading_steps"] = hit
    return hit


def compressed_current(th, ctx: Context):
    """The baseline with its current read through ``compress``: each sine's fundamental scaled by the map's describing
    function at the current's amplitude and given the map's 3rd harmonic at three times the current's phase; each
    step's current mapped at the record's own rate (the spike before the block averages), the change added."""
    p = baseline(ctx)
    if ctx.sines:
        i1 = p.Hi * np.array([_drive(s) for s in ctx.sines])
        a = np.abs(i1)
        ok = a > 0
        c = cosine_harmonics(lambda x: compress(x, th), a, _N)
        c1 = np.where(ok, c[:, 0], 1.0)
        turn = np.where(ok, i1 / np.where(ok, a, 1.0), 1.0) ** 2
        p.hi = p.hi.astype(complex)
        p.hi[:, 1] = p.hi[:, 1] + np.where(ok, c[:, 2] / c1, 0.0) * turn
        p.Hi = p.Hi * np.where(ok, c1 / np.where(ok, a, 1.0), 1.0)
    for k, (st, i) in enumerate(zip(ctx.steps, _step_currents(ctx))):
        if i is not None:
            p.step_i[k] = p.step_i[k] + st.decimate(compress(i, th) - i)
    return p


def _start(ctx: Context) -> np.ndarray:
    """A knee at the session's largest current, sharp: where a guard against overload is set."""
    peaks = [float(np.max(np.abs(i))) for i in _step_currents(ctx) if i is not None and i.size]
    if ctx.sines:
        peaks.append(float(np.max(np.abs(ctx.Hi * np.array([_drive(s) for s in ctx.sines])))))
    return np.array([1.2 * max(peaks, default=0.01), 4.0])


CURRENT_READING = Extension("current_reading", ("sat_A", "sharpness"), (0.01, 2.0), (1e-5, 1.0), (2.0, 10.0), compressed_current,
                            "the current read through an amplifier that compresses its large readings, i / (1 + |i/a|^n)^(1/n): "
                            "feedback diodes, a log amplifier, an amplifier at its rails (outside the catalogue)",
                            form="compressed", start=_start)


def describe(params: dict) -> str:
    """What read the current, by the fitted parameters."""
    return (f"the current was read through an amplifier that compresses its large readings (saturating towards "
            f"{1e3 * params['sat_A']:.3g} mA, sharpness {params['sharpness']:.2g}: feedback diodes, a log amplifier, an "
            f"amplifier at its rails)")


CHALLENGER = Challenger(CURRENT_READING, CHALLENGED, "harm_i", "current_reading", describe, "sat_A", SHARE)
detail = CHALLENGER.detail  # its residual.where entry, by the JSON it is reported under
