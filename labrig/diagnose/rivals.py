"""A rival outside the catalogue: the strip driven by a distorted copy of the drive the DAQ recorded.

A drive amplifier's crossover dead zone or its clipping, with the DAQ recording the command (or the amplifier's input)
rather than the voltage on the strip, distorts what the strip sees before any of its physics: the current and the
displacement then both follow v_eff = g(v) through the linear model, i = Y(s) v_eff and d = H(s) v_eff, the same
harmonics in both at the ratio Y(3 s)/Y(s) against H(3 s)/H(s). No catalogued cause does that: a faradaic branch in
parallel distorts the current alone, a large deflection or a sensor nonlinearity the displacement alone, memory on
the drive loops instead of mapping. The fresh12 set's class-B crossover (seen) was named ``faradaic_current``: an odd
nonlinearity between the recorded drive and the current, which a faradaic branch in parallel also is.

``drive_map`` is odd and static: g(v) = k (v - w z tanh(v/z) + c v^3), a dead zone of half-width z (depth w, 0 to 1:
a smooth crossover) and a cubic (c < 0: soft clipping, c > 0: expansion), gain k. Sines by its describing function
over one period of the recorded drive's fundamental (the 1st and 3rd harmonics), steps through the map at the record's
own rate. ``engine._rival`` says when it takes the verdict from a named cause (docs/diagnosis.md, "A rival outside the
catalogue").
"""

from __future__ import annotations

import numpy as np

from labrig.diagnose.catalogue import Context, Extension, _drive, baseline, cosine_harmonics, specimen_for
from labrig.diagnose.features import step_grid, predict_step
from labrig.physics import timeresp, transfer

_N = 64  # samples per cycle of the map's describing function


def drive_map(v, th):
    """g(v) = k (v - w z tanh(v/z) + c v^3) (module docstring)."""
    z, w, c, k = th
    v = np.asarray(v, float)
    return k * (v - w * z * np.tanh(v / max(z, 1e-9)) + c * v**3)


def _y3(ctx: Context) -> np.ndarray:
    """The baseline admittance at three times each sine's frequency (once per context: it reads the specimens only)."""
    hit = ctx.cache.get("rival_y3")
    if hit is None:
        hit = ctx.cache["rival_y3"] = np.array([transfer.admittance_tf(np.array([6j * np.pi * s.f]), specimen_for(ctx.specimens, s.pressure_kPa))[0]
                                                for s in ctx.sines], complex)
    return hit


def _drive_changed(p, ctx: Context, g1: np.ndarray, r3: np.ndarray) -> None:
    """Both channels of a strip whose drive was changed before it, in place: the fundamentals by g1 (the strip's drive
    over the recorded one), and the strip's drive's 3rd harmonic r3 (over its fundamental) through H(3 s) and Y(3 s)."""
    p.hd = p.hd.astype(complex)
    p.hi = p.hi.astype(complex)
    p.hd[:, 1] = p.hd[:, 1] + r3 * ctx.Hd3 / ctx.Hd
    p.hi[:, 1] = p.hi[:, 1] + r3 * _y3(ctx) / ctx.Hi
    p.Hd, p.Hi = p.Hd * g1, p.Hi * g1


def _steps_behind(ctx: Context, z_s):
    """(k, step record, its FFT grid for the strip behind a series impedance z_s(s): (nfft, sigma, [H G, Y G]), G = 1 /
    (1 + z_s Y)) for each step record sampled at a known rate."""
    for k, st in enumerate(ctx.steps):
        if st.fs_full <= 0 or st.v_full.size == 0:
            continue
        nfft, sigma, (h, y) = step_grid(specimen_for(ctx.specimens, st.pressure_kPa), st.v_full.size, st.fs_full)
        g = 1.0 / (1.0 + z_s(timeresp.grid_s(nfft, sigma, st.fs_full)) * y)
        yield k, st, (nfft, sigma, [h * g, y * g])


def distorted_drive(th, ctx: Context):
    """The strip driven by ``drive_map`` of the recorded drive: both channels' fundamentals scaled by the map's gain at
    each sine's amplitude, its 3rd harmonic passed through H(3 s) and Y(3 s), the steps re-driven."""
    p = baseline(ctx)
    if ctx.sines:
        drv = np.array([_drive(s) for s in ctx.sines])
        a = np.abs(drv)
        ok = a > 0
        c = cosine_harmonics(lambda x: drive_map(x, th), a, _N)
        c1, c3 = np.where(ok, c[:, 0], 1.0), c[:, 2]
        g1 = np.where(ok, c1 / np.where(ok, a, 1.0), 1.0)
        turn = np.where(ok, drv / np.where(ok, a, 1.0), 1.0) ** 2
        _drive_changed(p, ctx, g1, c3 / c1 * turn)
    for k, st in enumerate(ctx.steps):
        p.step_d[k], p.step_i[k] = predict_step(specimen_for(ctx.specimens, st.pressure_kPa), st, drive_map(st.v_full, th))
    return p


DRIVE_PATH = Extension("drive_path", ("dead_zone_V", "depth", "cubic_per_V2", "gain"), (0.05, 0.5, 0.0, 1.0),
                       (1e-3, 0.0, -0.5, 0.5), (0.5, 1.0, 0.5, 2.0), distorted_drive,
                       "the strip driven by an odd static map of the recorded drive, k (v - w z tanh(v/z) + c v^3): an "
                       "amplifier's crossover or clipping before the strip (outside the catalogue)", form="static_map")


def series_element(th, ctx: Context):
    """The strip behind a series element in the drive line, Z_s(s) = R + S/s (a resistance R, an elastance S = 1/C),
    with the DAQ recording the drive before it and the analyser's spectra taken on the strip alone: both channels
    follow v_eff = G(s) v, G = 1 / (1 + Z_s(s) Y(s)), each by the strip's own admittance Y at its pressure. Sines
    scaled by G at their frequency; steps re-driven at the record's own rate through H G and Y G."""
    r, el = th
    p = baseline(ctx)
    if ctx.sines:
        s = 2j * np.pi * np.array([x.f for x in ctx.sines])
        g = 1.0 / (1.0 + (r + el / s) * ctx.Hi)
        p.Hd, p.Hi = p.Hd * g, p.Hi * g
    for k, st, grid in _steps_behind(ctx, lambda s: r + el / s):
        d, i = timeresp.respond(st.v_full, st.fs_full, grid)
        p.step_d[k], p.step_i[k] = st.decimate(d), st.decimate(i)
    return p


SERIES_ELEMENT = Extension("drive_path", ("series_ohm", "elastance_per_F"), (5.0, 10.0), (0.0, 0.0), (500.0, 1e4), series_element,
                           "the strip behind a series element in the drive line, R + 1/(C s), the DAQ recording the drive "
                           "before it: a sense resistor, a DC-blocking capacitor (outside the catalogue)", form="series_element")


def _harmonic(x: np.ndarray, k: int) -> np.ndarray:
    """The phasor X_k of x = Re(sum X_k e^{i k theta}) sampled at _N points a row (one cycle)."""
    return 2 * np.fft.fft(x, axis=1)[:, k] / x.shape[1]


def _drop(v: np.ndarray, i: np.ndarray, th) -> np.ndarray:
    """The varying part of the series element's drop, (c_v v^2 + c_i (i / 100 mA)^2) i."""
    _, cv, ci = th
    return (cv * v**2 + ci * (10.0 * i) ** 2) * i


def varying_series(th, ctx: Context):
    """The strip behind a series element whose resistance varies with the voltage it switches and the current through
    it, R(v, i) = R + c_v v^2 + c_i (i/100 mA)^2: an analogue switch's or a FET's on-resistance falling away from mid
    supply (c_v < 0), a PTC fuse or a contact heating with the current (c_i > 0). The strip gets v_eff = G (v - e),
    G = 1 / (1 + R Y), e = (c_v v^2 + c_i i^2) i to first order in e, i the current behind the linear part. Sines: e
    over one cycle of the recorded drive gives the fundamental's change and a 3rd harmonic in both channels, through
    Y(3 s) and H(3 s) as the drive's own would be; steps re-driven at the record's own rate with e from the step's
    own current (the charging spike at full drive). Odd in the drive, but not a static map of it: the drop follows the
    current, which leads the drive on a capacitive strip."""
    r = th[0]
    p = baseline(ctx)
    if ctx.sines:
        drv = np.array([_drive(s) for s in ctx.sines])
        y = ctx.Hi
        g = 1.0 / (1.0 + r * y)
        wt = 2 * np.pi * np.arange(_N) / _N
        turn = np.exp(1j * wt)[None, :]
        v = (drv[:, None] * turn).real
        i = ((y * g * drv)[:, None] * turn).real
        e = _drop(v, i, th)
        e1, e3 = _harmonic(e, 1), _harmonic(e, 3)
        ok = np.abs(drv) > 0
        safe = np.where(ok, drv, 1.0)
        fac = np.where(ok, g * (1.0 - e1 / safe), g)
        third = np.where(ok, -e3 / (1.0 + r * _y3(ctx)) / (g * (safe - e1)), 0.0)
        _drive_changed(p, ctx, fac, third)
    for k, st, (nfft, sigma, hy) in _steps_behind(ctx, lambda s: r):
        (i,) = timeresp.respond(st.v_full, st.fs_full, (nfft, sigma, hy[1:]))  # the current behind the linear part
        d, i = timeresp.respond(st.v_full - _drop(st.v_full, i, th), st.fs_full, (nfft, sigma, hy))
        p.step_d[k], p.step_i[k] = st.decimate(d), st.decimate(i)
    return p


VARYING_SERIES = Extension("drive_path", ("series_ohm", "ohm_per_V2", "ohm_at_100mA"), (0.0, 0.0, 0.0), (-50.0, -200.0, -200.0),
                           (500.0, 200.0, 200.0), varying_series,
                           "the strip behind a series element whose resistance varies with the voltage and the current, "
                           "R + c_v v^2 + c_i (i/100 mA)^2: an analogue switch's or FET's on-resistance, a PTC fuse or a "
                           "heating contact, the DAQ recording the drive before it (outside the catalogue)",
                           form="varying_series")


def _what(r: dict) -> str:
    """What the strip saw, by the rival's form and parameters."""
    q = r["params"]
    if r["form"] == VARYING_SERIES.form:
        return (f"the strip sat behind a series element whose resistance varies ({q['series_ohm']:.3g} ohm "
                f"{q['ohm_per_V2']:+.3g} ohm/V^2 {q['ohm_at_100mA']:+.3g} ohm (i/100 mA)^2: an analogue switch's on-resistance, a "
                f"PTC fuse, a heating contact, the DAQ recording the drive before it)")
    if r["form"] == SERIES_ELEMENT.form:
        c = "no capacitance" if q["elastance_per_F"] <= 0 else f"{1e3 / q['elastance_per_F']:.3g} mF"
        return (f"the strip sat behind a series element in the drive line ({q['series_ohm']:.3g} ohm, {c}: a sense resistor "
                f"or a DC-blocking capacitor, the DAQ recording the drive before it)")
    return (f"the strip saw a distorted copy of the recorded drive (a dead zone of {1e3 * q['dead_zone_V']:.1f} mV at depth "
            f"{q['depth']:.2f}, cubic {q['cubic_per_V2']:+.3f}/V^2: an amplifier's crossover or clipping before the strip)")


def rival_detail(r: dict) -> dict:
    """The ``residual.where`` entry saying where the drive-path rival sits and what it took the verdict from (``r``:
    the JSON's ``drive_path``)."""
    return {"block": "drive", "level": r["heldout_ratio"], "over_accuracy": r["its_ratio"] / max(r["heldout_ratio"], 1e-12),
            "detail": f"{_what(r)}: it predicts the held-out half at {r['heldout_ratio']:.3f} of the baseline's error against "
                      f"{r['its_ratio']:.3f} for {r['instead_of']}, and lowers {', '.join(r['blocks_it_lowers'])}, which "
                      f"{r['instead_of']} leaves where the baseline put it",
            "blocks": list(r["blocks_it_lowers"])}
