"""A reading re-aligned on the drive by cross-correlation: the time delay family's ``aligned`` form.

A sensor streamed by its own software (a laser's controller, a camera) is often put on the DAQ's records by an export
script that aligns each record: it shifts the reading by the lag that maximises its cross-correlation with the
record's drive, searched over +-W in whole samples, as one aligns two copies of a signal. The bend is no copy of the
drive: it lags it by the strip's own dynamics, and the script takes that lag out too, up to W. What it leaves is a
delay of each record's own, set by the strip:

* a sine record of frequency f whose displacement lags the drive by phi (the model's phase) is shifted by the lag
  phi / (2 pi f) folded into half a period and rounded to the record's samples, or by W where that lies beyond the
  search: its phase pulled onto the drive's (a lead that grows with f up to W, then W);
* a step record is shifted by the lag (within +-W) at which the model's displacement, at the record's own rate,
  correlates best with the recorded drive (both without their means): W for a strip slower than the window.

One parameter, W (s). Unlike a delay, the shift differs record by record and does not follow exp(-s tau) across
frequency; unlike a filter it is a pure lead, the gain untouched. The mechanics are refitted with it, as for the
family's other forms (nuisance.py).
"""

from __future__ import annotations

import numpy as np

from labrig.diagnose.catalogue import Context, Prediction, baseline
from labrig.diagnose.features import specimen_for, step_grid
from labrig.physics import timeresp


def sine_lag(phase_lag: float, f: float, window: float, fs: float) -> float:
    """The lag (s, positive: the reading late) a cross-correlation over +-``window`` finds on a sine record whose
    reading lags its drive by ``phase_lag`` (rad) at ``f``: the lag folded into (-T/2, T/2], in whole samples at
    ``fs`` (none where fs is unknown), or the edge of the search nearest it in phase where it lies beyond."""
    period = 1.0 / f
    lag = (phase_lag / (2 * np.pi * f) + period / 2) % period - period / 2
    if abs(lag) <= window:
        return round(lag * fs) / fs if np.isfinite(fs) and fs > 0 else lag
    # beyond the search: the correlation cos(2 pi f (l - lag)) is largest at the edge nearer in phase
    return max((window, -window), key=lambda edge: np.cos(2 * np.pi * f * (edge - lag)))


def correlation(d: np.ndarray, v: np.ndarray) -> np.ndarray:
    """c[l] = sum_k v[k] d[k + l] of ``d`` and ``v`` without their means (l < 0 at the end), by FFT."""
    m = 1 << int(np.ceil(np.log2(2 * max(d.size, 2))))
    return np.fft.irfft(np.conj(np.fft.rfft(v - v.mean(), m)) * np.fft.rfft(d - d.mean(), m), m)


def step_lag(c: np.ndarray, n: int, fs: float, window: float) -> float:
    """The lag (s) within +-``window`` at which a record of ``n`` samples at ``fs`` correlates best with its drive
    (``c``: ``correlation``): the search's edge taken at ``window`` itself, not its whole sample, so that a fit
    moves it smoothly."""
    nw = min(int(np.ceil(window * fs)), n - 1)
    if n < 4 or nw < 1:
        return 0.0
    lags = np.r_[np.arange(0, nw + 1), np.arange(-nw, 0)]
    best = int(lags[int(np.argmax(c[lags]))])
    return float(np.sign(best) * window) if abs(best) >= window * fs else best / fs


def aligned(th, ctx: Context) -> Prediction:
    """The displacement of every record shifted back by the lag an alignment on the drive over +-W finds
    (``sine_lag``, ``step_lag``): exp(+j omega lag) on each sine's FRF, each step's response read ``lag`` earlier
    (its last value held)."""
    window = float(th[0])
    p = baseline(ctx)
    for k, s in enumerate(ctx.sines):
        lag = sine_lag(-float(np.angle(p.Hd[k])), s.f, window, s.fs)
        p.Hd[k] = p.Hd[k] * np.exp(2j * np.pi * s.f * lag)
    for k, st in enumerate(ctx.steps):
        if st.fs_full <= 0 or st.v_full.size < 4 or not np.any(st.v_full - st.v_full[0]):
            continue
        key = ("aligned", k)
        if key not in ctx.cache:  # the model's correlation with the drive: fixed while only W moves
            grid = step_grid(specimen_for(ctx.specimens, st.pressure_kPa), st.v_full.size, st.fs_full)
            d_full = timeresp.respond(st.v_full, st.fs_full, (grid[0], grid[1], grid[2][:1]))[0]
            ctx.cache[key] = correlation(d_full, st.v_full)
        lag = step_lag(ctx.cache[key], st.v_full.size, st.fs_full, window)
        p.step_d[k] = np.interp(st.t + lag, st.t, p.step_d[k])
    return p
