"""Each catalogue effect as a family of forms (issue 12, DESIGN.md 5): measured data will not follow one formula.

``catalogue.CATALOGUE`` holds each effect's first form (the one the simulated bench was built with); this module
adds the other physically plausible forms of the same cause. The diagnosis fits every form of an effect on the
fitted half, keeps the one with the best evidence (BIC on the fitted half: the held-out half never chooses), and
names the effect by its signature; the form found is reported (``extended.form``).

| effect | forms |
|---|---|
| back_relaxation | single time constant; fractional (Cole-Cole) 1 - K2/(1 + (tau s)^beta), a spread of time constants; fast-slow pair |
| faradaic_current | odd polynomial; full polynomial g1 v + g2 v^2 + g3 v^3 (one-sided electrolysis: DC and even harmonics); asymmetric Butler-Volmer / Tafel exponential; Langmuir adsorption peaks; a transport-limited wave; a wave fading (or gathering) with the session's clock |
| hysteresis | play operator on the drive; Prandtl-Ishlinskii operators (a uniform density of plays) on the drive and in the displacement path; play operator in the displacement path (the sensor side); a pinched (flag) loop past a threshold there; a dry contact whose hold follows the tip's position; Bouc-Wen loop in the displacement path; a Preisach operator on the drive (relays with a density over coercivity and bias: preisach.py) |
| time_delay | pure delay; first-order lag (a sensor's output filter); each channel's own delay (the current's, or the drive monitor's); each channel's own first-order low-pass (a shunt amplifier's filter on the current); a low-pass of a few poles; the slow share of the reading late (a tracking stage's slow path); a logger's moving average run per sample (a lag of so many samples at each record's rate); each record re-aligned on the drive by cross-correlation within a window (aligned.py) |
| sensor_offset | the spot along the strip; a rigid flag at the tip read beyond it; a footprint read at its point nearest the sensor; the spot walking along the strip with session time |
| strain_resistance | the bench's gauge physics; an instantaneous gain loss with the bend (either or one side), linear, saturating or as a power of it |
| dehydration | exponential; linear; saturating; power of time t^n (n = 1/2: Fickian); falling rate; two-stage sorption; by charge; from an onset inside the session; set anew at each clamp setting |
| clamp_relaxation | exponential; log time; power of time (Nutting); two arms (generalised Maxwell); Norton creep; a screw shaken loose by the resonant records (Junker); a clamp breathing with the room's temperature cycles |
| large_deflection | the arc's cubic projection; the arc read around a rest curl (even and odd); the curl drifting through the session; a knee, the reading compressed by a power of itself |
| mains_pickup | 50/60 Hz lines of constant amplitude; their harmonics to the 7th per channel; the same at a level of each record's own (a load switched on and off, a coupling that changes) |

The slow effects' time shapes (drying, clamp creep) are in ``slow_forms``. The families whose cause sits at the clamp
also try their best form with its strength a law of the clamp pressure (``pressure_law``, fitted by the engine).
"""

from __future__ import annotations

import numpy as np
from scipy.signal import lfilter

from labrig.diagnose.catalogue import (CATALOGUE, Context, Extension, _drive, _play, _play_df, baseline, delayed,
                                      played_drive, sensor_read, step_through)
from labrig.diagnose import aligned, contact, flag, preisach, slow_forms as slow, station
from labrig.diagnose.arc import curled_arc, drifting_arc, knee
from labrig.diagnose.features import LINE_CHANNELS, LINE_HZ, specimen_for, step_grid
from labrig.physics import timeresp

_N = 64
_TH = 2 * np.pi * np.arange(_N) / _N


# ------------------------------------------------------------------------------------------ back relaxation


def _relax(B):
    """An extension multiplying the displacement path by B(s, theta) (FRF and the step from rest)."""

    def apply(th, ctx: Context):
        p = baseline(ctx)
        if th[0] == 0:
            return p
        f = np.array([s.f for s in ctx.sines])
        p.Hd = p.Hd * B(2j * np.pi * f, th)
        for k, st in enumerate(ctx.steps):
            p.step_d[k] = step_through(st, p.step_d[k], lambda s: B(s, th))
        return p

    return apply


def _cole_cole(s, th):
    k2, tau, beta = th
    return 1.0 - k2 / (1.0 + (tau * s) ** beta)


def _pair(s, th):
    k2, t1, t2, w = th
    return 1.0 - k2 * (w / (t1 * s + 1.0) + (1.0 - w) / (t2 * s + 1.0))


def lowpass_tf(s, tau: float, order: float):
    """(1 + s tau/n)^-n: unit gain at DC, group delay tau there; the time delay's ``lowpass`` form reads the
    displacement through it. n = 1 is the first-order lag; as n grows it tends to the pure delay exp(-s tau), since
    (1 + x/n)^-n -> e^-x. Between them it stands for a sensor's averaging, servo or anti-alias filter of a few poles
    (a boxcar over T has the phase of a delay T/2; a Bessel or critically damped filter of order n is this shape). On
    the imaginary axis it is the principal power of a number of positive real part, analytic in the right half plane:
    the step's response through it is causal."""
    return (1.0 + np.asarray(s, complex) * tau / order) ** (-order)


lowpass = _relax(lambda s, th: lowpass_tf(s, *th))


def band_delay_tf(s, delay: float, f_share: float):
    """1 + (exp(-s L) - 1)/(1 + s/w): a reading summed from two paths, the slow share of the bend (below f_share, a
    first-order split) read late by L and the fast share at once (a head on a tracking stage whose position is read
    late, a coarse-fine sensor pair, a servo's slow loop logged over a slower bus). Gain 1 at both ends; the phase lag
    of the delay below f_share, none far above it. f_share -> infinity: the pure delay."""
    s = np.asarray(s, complex)
    return 1.0 + (np.exp(-s * delay) - 1.0) / (1.0 + s / (2 * np.pi * f_share))


band_delay = _relax(lambda s, th: band_delay_tf(s, *th))


def ema_tf(s, alpha: float, fs: float):
    """An exponential moving average run per sample at fs, y[n] = y[n-1] + alpha (x[n] - y[n-1]): alpha / (1 - (1 -
    alpha) exp(-s/fs)), the sum of the sample delays k/fs weighted alpha (1 - alpha)^k (causal). Unit gain at DC, a
    lag of (1 - alpha)/alpha samples at low frequencies: a fixed number of samples, so a different time at each rate."""
    return alpha / (1.0 - (1.0 - alpha) * np.exp(-np.asarray(s, complex) / fs))


def per_sample_smoothing(th, ctx: Context):
    """The displacement smoothed by a logger's moving average set per sample (``ema_tf`` at each record's own rate):
    sines by the filter at their record's rate, steps through it at theirs (a record of unknown rate as it was)."""
    (alpha,) = th
    p = baseline(ctx)
    if alpha >= 1.0:
        return p
    if ctx.sines:
        f, rate = np.array([[x.f, x.fs] for x in ctx.sines], float).T
        ok = np.isfinite(rate) & (rate > 0)
        g = np.ones(f.size, complex)
        g[ok] = ema_tf(2j * np.pi * f[ok], alpha, rate[ok])
        p.Hd = p.Hd * g
    for k, st in enumerate(ctx.steps):
        if st.fs_full > 0 and st.t.size > 1:
            p.step_d[k] = step_through(st, p.step_d[k], lambda s: ema_tf(s, alpha, st.fs_full))
    return p


# ------------------------------------------------------------------------------------------ faradaic branches


def _branch(fun, lagged: bool = False, transport: bool = False, fading: bool = False):
    """A parallel current branch i_b = fun(v, theta, dv/dt): harmonics 1-3 of each sine over one period of the
    measured drive's fundamental (numerically: any form), the step's current at the record's own rate (a charge
    drawn at the edge lands in the block it was drawn in), then block-averaged as the step is compared. ``lagged``:
    the branch sees the interface's potential, the drive through the double layer's charging, 1/(1 + s tau) with
    tau the last parameter (a Randles cell: the faradaic branch sits behind R_s, beside C_dl). ``transport``: the
    law's current passes through the diffusion layer's admittance (``diffusion_admittance``), its (tau_D, kappa)
    the two parameters before tau. ``fading``: the branch's strength follows the session's clock, exp(-k u) with u the
    session's time over its span and k the first parameter (k > 0: a contaminant the electrodes spend or that
    decomposes on the platinum, a tracer plated out; k < 0: one that builds up, carbon dioxide dissolving)."""

    def apply(th, ctx: Context):
        (k_u, *th) = th if fading else (0.0, *th)
        def strength(rec_t):  # rec_t: the record's times, called only when fading (a record without a clock otherwise)
            return np.exp(-k_u * ctx.feats.time_share(rec_t())) if fading else 1.0
        law_th, tau = (th[:-1], th[-1]) if lagged else (th, 0.0)
        Y = None
        if transport:
            law_th, (tau_d, kap) = law_th[:-2], law_th[-2:]
            Y = lambda z: diffusion_admittance(z, tau_d, kap)  # noqa: E731
        p = baseline(ctx)
        for k, s in enumerate(ctx.sines):
            a = _drive(s)
            ph = a / (1 + 2j * np.pi * s.f * tau) * np.exp(1j * _TH)
            c = np.fft.fft(fun(ph.real, law_th, (2j * np.pi * s.f * ph).real))[1:4] * 2 / _N * strength(lambda: s.t_start)
            if Y is not None:
                c = c * Y(2j * np.pi * s.f * np.arange(1, 4))
            x = np.array([p.Hi[k] * a, p.hi[k, 0] * p.Hi[k] * a, p.hi[k, 1] * p.Hi[k] * a]) + c
            p.Hi[k], p.hi[k] = x[0] / a, x[1:] / x[0]
        for k, st in enumerate(ctx.steps):
            v = st.v_full
            if tau > 0 and v.size > 1:
                v = lfilter([-np.expm1(-1 / (st.fs_full * tau))], [1, -np.exp(-1 / (st.fs_full * tau))], v - v[0]) + v[0]
            dv = np.gradient(v) * st.fs_full if v.size > 1 else np.zeros_like(v)
            i_b = st.decimate(fun(v, law_th, dv) * strength(lambda: st.t_start + np.arange(v.size) / max(st.fs_full, 1e-9)))
            if Y is not None and i_b.size > 1:
                i_b = timeresp.simulate(Y, i_b, st.fs_full / st.q)  # at the compared rate: Y is biproper, fast
            p.step_i[k] = p.step_i[k] + i_b
        return p

    return apply


def diffusion_admittance(s, tau_d: float, kappa: float):
    """A faradaic current's transport through a Nernst layer of finite thickness, normalised to 1 at DC (the steady
    wave): the finite Warburg W = sqrt(tau_D s) coth(sqrt(tau_D s)) (W(0) = 1, W ~ sqrt(tau_D s) fast: Cottrell's
    1/sqrt(t) spike after a potential step) in series with a charge transfer kappa times faster than the transport
    (a Randles cell), Y = W (1 + 1/kappa)/(1 + W/kappa): the edges draw up to 1 + kappa times the steady current."""
    q = np.sqrt(tau_d * np.asarray(s, complex))
    small = np.abs(q) < 1e-4
    W = np.where(small, 1.0 + q**2 / 3, q / np.tanh(np.where(small, 1.0, q)))
    return W * (1 + 1 / kappa) / (1 + W / kappa)


def _wave(v, th, dv=None):
    """A transport-limited faradaic wave on both electrodes, i_lim (tanh((v - E0)/2w) + tanh((v + E0)/2w))/2: a redox
    couple at 0 V (E0 = 0: Nernstian on both surfaces, i_lim tanh(v/2w)) or a reduction with its half-wave at E0 on
    whichever electrode is the cathode (oxygen: the Koutecky-Levich sigmoid k/(1 + k), k = exp((v - E0)/b), w = b)."""
    i_lim, e0, w = th
    return i_lim * 0.5 * (np.tanh((v - e0) / (2 * w)) + np.tanh((v + e0) / (2 * w)))


def _poly3(v, th, dv=None):
    g1, g2, g3 = th
    return g1 * v + g2 * v**2 + g3 * v**3


def _exponential(v, th, dv=None):
    """Butler-Volmer with transfer coefficient a (a = 0.5: sinh; a -> 1: Tafel, one-sided), i1 the current at 1 V."""
    i1, vt, a = th
    f = lambda x: np.exp(np.clip(a * x / vt, -60, 60)) - np.exp(np.clip(-(1 - a) * x / vt, -60, 60))  # noqa: E731
    return i1 * f(v) / f(np.array(1.0))


def _adsorption(v, th, dv):
    """Hydrogen adsorption on the platinum electrodes ahead of its evolution: a Langmuir pseudo-capacitance
    C(v) = c sech^2((v -+ E0)/(2 v_t)) drawing C(v) dv/dt (a peak of charge q = 4 v_t c at E0 on each polarity,
    c_pos and c_neg apart: the two electrodes differ), and the evolution's exponential tail past it on one side,
    i_t exp((|v| - 1 V)/v_e) (i_t > 0: positive drive, < 0: negative)."""
    c_pos, c_neg, e0, vt, i_t, ve = th
    peaks = c_pos / np.cosh((v - e0) / (2 * vt)) ** 2 + c_neg / np.cosh((v + e0) / (2 * vt)) ** 2
    side = np.where(i_t >= 0, v > 0, v < 0)
    return peaks * dv + i_t * np.exp(np.clip((np.abs(v) - 1.0) / ve, -60, 60)) * side


# ------------------------------------------------------------------------------------------ sensor-side memory


def _play_output(th, ctx: Context):
    """Play operator of half-width r on the displacement itself (memory in the sensor path, not the drive):
    y = (1 - w) d + w play_r(d); describing function at each sine's output amplitude."""
    w, r_um = th
    return played_output(w, [r_um * 1e-6], 1.0, ctx)


def _pi_output(th, ctx: Context):
    """Memory in the displacement path as a Prandtl-Ishlinskii operator: y = g ((1 - w) d + w P[d]), P the mean of
    plays of half-widths r_max (k + 1/2)/n on the tip's displacement (``_pi_radii``). Dry friction in the bending stiffness
    (elasto-slide elements in parallel with EI, the Maxwell-slip / Iwan model: d = x + sum k_i S_ri[x]) is the
    inverse of a PI operator of stops, itself a PI operator of plays: the strip stiffer while its elements stick
    (small motions), the linear gain once they slide, with loops between. w < 0: the opposite (softening)."""
    w, r_um, gain = th
    return played_output(w, _pi_radii(r_um * 1e-6), gain, ctx)


def played_output(w: float, radii, gain: float, ctx: Context):
    """The displacement read through g ((1 - w) d + w P[d]), P the mean of plays of the given half-widths (m) on it
    (``catalogue.played_drive``'s counterpart in the sensor path): sines by describing function at each sine's output
    amplitude, the step's prediction played as it stands."""
    p = baseline(ctx)
    if ctx.sines:
        y = p.Hd * np.array([_drive(s) for s in ctx.sines])
        a = np.abs(y)
        n1, n3 = (np.mean(x, axis=0) for x in zip(*(_play_df(a, r) for r in radii)))
        g1 = (1 - w) + w * n1
        p.hd[:, 1] = p.hd[:, 1] + w * n3 / g1 * (y / a) ** 2
        p.Hd = p.Hd * g1 * gain
    for k, d in enumerate(p.step_d):
        p.step_d[k] = gain * ((1 - w) * d + w * np.mean([_play(d, r) for r in radii], axis=0))
    return p


# The PI forms' plays: a uniform density of coercivities up to r_max, sampled at PI_PLAYS half-widths. Each play the
# amplitude passes adds its share to the gain at once, so a coarse sampling turns the density's smooth rise of gain
# with amplitude (Rayleigh's law for a uniform Preisach density) into steps of 1/n across the sines' amplitudes: with
# four, fresh23's Rayleigh loop (nickel films, seen) was fitted at 0.66 and bent frf_d from 1.25 to 6.2 x its
# accuracy; with sixteen, 0.22 and 1.44, the displacement's harmonics lowered (1.13 -> 0.57), ahead of the
# relaxation pair (0.26) that took it
PI_PLAYS = 16


def _pi_radii(r_max: float) -> np.ndarray:
    """The PI forms' plays: half-widths r_max (k + 1/2)/n, k = 0..n-1 (n = ``PI_PLAYS``), weighed alike."""
    return r_max * (np.arange(PI_PLAYS) + 0.5) / PI_PLAYS


def _pi_drive(th, ctx: Context):
    """Memory of the electromechanical coupling as a Prandtl-Ishlinskii operator: plays of half-widths r_max (k +
    1/2)/n, k = 0..n-1, weighed alike (``_pi_radii``: a density of coercivities, as a Preisach density's projection:
    loops that round off instead of the single play's corners). The weight is signed: (1 - w) v + w P[v] with w < 0 is, up to the
    gain, v - h P[v] = (1 - h) v + h S[v], S = v - P[v] the stop operators of the same radii (hysterons that
    saturate: a domain follows the drive until it is full), h = |w|/(1 + |w|). Plays lower the gain at small drive,
    stops at large drive; both loop and leave a remanence (the generalised PI operator, docs/diagnosis.md)."""
    w, r_max, gain = th
    return played_drive(w, _pi_radii(r_max), gain, ctx)


# ------------------------------------------------------------------------------------------ strain as a gain loss


def _read_as(H: np.ndarray, h: np.ndarray, k: int, drv: complex, y: np.ndarray) -> None:
    """Sine record k read as ``y`` over one period (at ``_TH``) instead of its linear fundamental: y's first three
    harmonics added to the baseline's own, written back as the FRF ``H[k]`` and the harmonic ratios ``h[k]``."""
    x1 = H[k] * drv
    x = np.array([0.0, h[k, 0] * x1, h[k, 1] * x1]) + np.fft.fft(y)[1:4] * 2 / _N
    H[k], h[k] = x[0] / drv, x[1:] / x[0]


def _strain_loss(law):
    """Electrode resistance rising with the bend, read as an instantaneous loss of gain on displacement and current:
    y = y_lin (1 - k law(e)), e = 2 (a max(d, 0) + (1 - a) max(-d, 0)) / L (a = 0.5: both electrodes alike; a -> 0
    or 1: one electrode, one side of the bend: even harmonics), ``law(e, shape)`` the resistance's law of the strain
    (the parameters after k_disp, k_cur and a). Harmonics over one period, the step sample by sample."""

    def apply(th, ctx: Context):
        kd, ki, a, *shape = th
        p = baseline(ctx)

        def bend(d):
            return law(2 * (a * np.clip(d, 0, None) + (1 - a) * np.clip(-d, 0, None)) / ctx.length, shape)

        for k, s in enumerate(ctx.sines):
            drv = _drive(s)
            e = bend(s.bend_m + (p.Hd[k] * drv * np.exp(1j * _TH)).real)
            for H, h, gain in ((p.Hd, p.hd, kd), (p.Hi, p.hi, ki)):
                _read_as(H, h, k, drv, (H[k] * drv * np.exp(1j * _TH)).real * (1 - gain * e))
        for k, d in enumerate(p.step_d):
            e = bend(d)
            p.step_d[k], p.step_i[k] = d * (1 - kd * e), p.step_i[k] * (1 - ki * e)
        return p

    return apply


def _linear_law(e, shape):
    """dR/R linear in the strain (a gauge factor)."""
    return e


def _saturating_law(e, shape):
    """The loss saturating, tanh(e / e_s) (k then the saturated loss): the cracks' density reaches the film's minimum
    spacing (Punning et al.) and the resistance stops rising."""
    (e_s,) = shape
    return np.tanh(e / e_s)


E_REF = 0.2  # the bend's strain proxy 2 d / L at a tip deflection of a tenth of the length


def _power_law(e, shape):
    """dR/R as a power of the strain, (e / E_REF)^n (k then the loss at E_REF): cracks that open beyond a strain and
    widen faster than it (n > 1: a crack's opening goes as the strain past its onset, their number grows with it; the
    metal bridges across them narrow), or a film whose overlaps or contacts give way gently (n < 1)."""
    (n,) = shape
    return (e / E_REF) ** n


_strain_modulation = _strain_loss(_linear_law)  # the family's first form, "modulation"


# ------------------------------------------------------------------------------------------ smooth memory, sensor side


def _bouc_wen(d: np.ndarray, z_u: float, q: float) -> np.ndarray:
    """Bouc-Wen state (n = 1) driven by d along its last axis, from z = 0: dz = dd (1 - |z| (b sgn(dd z) + g)) with
    b + g = 1/z_u (z saturates at z_u) and q = (b - g)/(b + g) the loop's shape (q = 1: z stays on d while the
    reading unloads, q = 0: the same law both ways). Forward Euler in the drive's own increments."""
    b, g = (1 + q) / (2 * z_u), (1 - q) / (2 * z_u)
    dd = np.diff(d, axis=-1, prepend=d[..., :1])
    z = np.zeros(d.shape[:-1])
    out = np.empty_like(d)
    for k in range(d.shape[-1]):
        step = dd[..., k]
        z = z + step * np.maximum(1 - np.abs(z) * (b * np.sign(step * z) + g), 0.0)
        out[..., k] = z
    return out


def _bouc_wen_output(th, ctx: Context):
    """Memory in the displacement path as a smooth loop: the spot's mount (or its contact on the tip) takes up a
    part z of the tip's motion until friction lets it slip, z the Bouc-Wen state of the tip's displacement bounded
    by z_u; the reading is y = d - w z. Small motions lose a share w of the gain, large ones an error bounded by
    w z_u, with a loop in between (the smooth kin of a play in the sensor path). The sines' fundamental and 3rd
    harmonic over the second of two periods at each sine's amplitude (describing function), the step at its
    compared rate."""
    w, zu_um, q = th
    z_u = zu_um * 1e-6
    p = baseline(ctx)
    if ctx.sines:
        y = p.Hd * np.array([_drive(s) for s in ctx.sines])
        a = np.abs(y)
        ph = np.linspace(0, 4 * np.pi, 2 * _N, endpoint=False)
        z = _bouc_wen(a[:, None] * np.cos(ph)[None, :], z_u, q)[:, _N:]
        c = np.fft.fft(z, axis=1)[:, [1, 3]] * 2 / _N
        g1 = 1 - w * c[:, 0] / a
        p.hd[:, 1] = p.hd[:, 1] - w * c[:, 1] / a / g1 * (y / a) ** 2
        p.Hd = p.Hd * g1
    for k, d in enumerate(p.step_d):
        p.step_d[k] = d - w * _bouc_wen(d, z_u, q)
    return p


# ------------------------------------------------------------------------------------------ lag


def _lag(th, ctx: Context):
    (tau,) = th
    p = baseline(ctx)
    f = np.array([s.f for s in ctx.sines])
    p.Hd = p.Hd / (1 + 2j * np.pi * f * tau)
    for k, st in enumerate(ctx.steps):
        p.step_d[k] = step_through(st, p.step_d[k], lambda s: 1 / (1 + s * tau))
    return p


def _channel_lags(th, ctx: Context):
    """Each channel read through a first-order low-pass of its own, 1/(1 + s tau_d) on the displacement and
    1/(1 + s tau_i) on the current: a sensor's output filter, a shunt amplifier's RFI or anti-alias filter on the
    current's sense. Unlike a delay it rounds the steps' charging spike as well as lagging the sines; the steps are
    re-driven at the record's own rate (the spike lives inside the first block the features average)."""
    tau_d, tau_i = th
    p = baseline(ctx)
    if ctx.sines:
        s = 2j * np.pi * np.array([x.f for x in ctx.sines])
        p.Hd, p.Hi = p.Hd / (1 + s * tau_d), p.Hi / (1 + s * tau_i)
    for k, st in enumerate(ctx.steps):
        if st.fs_full <= 0 or st.v_full.size == 0:
            continue
        nfft, sigma, (h, y) = step_grid(specimen_for(ctx.specimens, st.pressure_kPa), st.v_full.size, st.fs_full)
        z = timeresp.grid_s(nfft, sigma, st.fs_full)
        d, i = timeresp.respond(st.v_full, st.fs_full, (nfft, sigma, [h / (1 + z * tau_d), y / (1 + z * tau_i)]))
        p.step_d[k], p.step_i[k] = st.decimate(d), st.decimate(i)
    return p


def _skew(th, ctx: Context):
    """Each channel read with its own delay after the recorded drive: tau_d on the displacement, tau_i on the
    current (an ADC's or a filter's latency on one channel, a multiplexer's skew). Equal and negative, the drive's
    monitor is the late one (an isolation amplifier or a filter on the voltage record): both responses lead it."""
    tau_d, tau_i = th
    return delayed(ctx, tau_d, tau_i)


def _flag(th, ctx: Context):
    """The laser reads a rigid flag or reflective tab fixed at the tip, ``lever`` beyond it along the tangent:
    w(L) + e w'(L) (``Specimen.sensor_lever``); negative e reads along the tangent towards the root."""
    (e,) = th
    return sensor_read(ctx, sensor_lever=e * ctx.length)


def _nearest(th, ctx: Context):
    """A ranger whose footprint covers the strip from an inboard edge x_e to the tip and reports the footprint's point
    nearest it (an ultrasonic ranger's first echo, a line-beam head set to its "peak", a capacitive probe's near
    edge): bending towards it, the tip; bending away, the edge, which moves less. q = 1 - x_e/L signed by the side the
    sensor faces (q > 0: it reads the tip while the displacement is positive; q = 0: the tip on both sides). The
    reading the nearer of w(L) and w(x_e) towards the sensor: the sines over one period (fundamental and harmonics:
    a gain of each half of its own, even harmonics), the step sample by sample."""
    (q,) = th
    side, p = (1.0 if q >= 0 else -1.0), baseline(ctx)
    edge = sensor_read(ctx, sensor_x=(1 - abs(q)) * ctx.length)
    for k, s in enumerate(ctx.sines):
        drv = _drive(s)
        tip, inb = ((H * drv * np.exp(1j * _TH)).real for H in (p.Hd[k], edge.Hd[k]))
        _read_as(p.Hd, p.hd, k, drv, side * np.maximum(side * tip, side * inb))
    for k, (d, e) in enumerate(zip(p.step_d, edge.step_d)):
        p.step_d[k] = side * np.maximum(side * d, side * e)
    return p


def _form(base: str, form: str, params, x0, lo, hi, apply, describe, **kw) -> Extension:
    return Extension(base, params, x0, lo, hi, apply, describe, form=form, **kw)


FAMILIES: dict[str, list[Extension]] = {name: [ext] for name, ext in CATALOGUE.items()}
FAMILIES["back_relaxation"] += [
    _form("back_relaxation", "fractional", ("K2", "tau2_s", "beta"), (0.8, 8.0, 0.7), (-0.5, 0.2, 0.2), (2.5, 300.0, 1.0),
          _relax(_cole_cole), "H(s)(1 - K2/(1 + (tau2 s)^beta)): a spread of time constants (Cole-Cole)"),
    _form("back_relaxation", "pair", ("K2", "tau_fast_s", "tau_slow_s", "w_fast"), (0.8, 2.0, 20.0, 0.5), (-0.5, 0.1, 2.0, 0.0),
          (2.5, 20.0, 300.0, 1.0), _relax(_pair), "H(s)(1 - K2 (w/(tau_f s + 1) + (1 - w)/(tau_s s + 1))): a fast-slow pair"),
]
FAMILIES["faradaic_current"] += [
    _form("faradaic_current", "polynomial", ("g1_S", "g2_S_per_V", "g3_S_per_V2"), (0.0, 0.0, 0.0), (-0.05,) * 3, (0.05,) * 3,
          _branch(_poly3), "parallel branch i = g1 v + g2 v^2 + g3 v^3 (one-sided electrolysis: DC and even harmonics)"),
    _form("faradaic_current", "exponential", ("i_at_1V_A", "v_t_V", "alpha"), (3e-4, 0.15, 0.5), (-0.05, 0.03, 0.0), (0.05, 2.0, 1.0),
          _branch(_exponential), "Butler-Volmer branch i ~ exp(a v/v_t) - exp(-(1 - a) v/v_t) (a -> 1: Tafel, growing exponentially)"),
    _form("faradaic_current", "adsorption", ("c_pos_F", "c_neg_F", "e0_V", "v_t_V", "i_tail_A", "v_e_V", "interface_tau_s"),
          (2e-4, 2e-4, 0.4, 0.06, 1e-4, 0.2, 0.03), (0.0, 0.0, 0.05, 0.01, -0.05, 0.03, 0.0), (0.05, 0.05, 1.5, 0.3, 0.05, 1.0, 0.5),
          _branch(_adsorption, lagged=True),
          "Langmuir adsorption peaks C(v) dv/dt at +-E0 and the evolution's exponential tail on one side, at the interface's potential"),
    _form("faradaic_current", "transport", ("i_lim_A", "e_half_V", "wave_V", "diffusion_tau_s", "kinetic_ratio", "interface_tau_s"),
          (1e-4, 0.0, 0.07, 3.0, 3.0, 0.05), (0.0, 0.0, 0.01, 0.05, 0.1, 0.0), (0.02, 1.5, 0.5, 100.0, 50.0, 0.5),
          _branch(_wave, lagged=True, transport=True),
          "a transport-limited wave (a redox couple at 0 V, or a reduction at +-E_half) through the Nernst layer's finite "
          "diffusion and the charge transfer: Cottrell spikes at the edges, a steady wave after"),
    # a reactant spent (or gathered) over the session: the held-out pressures ran at other times, where a steady branch
    # fitted on the others has the wrong strength (fresh30's peroxide left from a cleaning, decomposing on the platinum)
    _form("faradaic_current", "fading", ("fade_per_span", "i_lim_A", "e_half_V", "wave_V"), (1.0, 2e-4, 0.0, 0.07),
          (-3.0, -0.02, 0.0, 0.01), (12.0, 0.02, 1.5, 0.5), _branch(_wave, fading=True),
          "a wave (a redox couple at 0 V, or a reduction at +-E_half) whose strength follows the session's clock, "
          "exp(-k u): a contaminant the electrodes spend or that decomposes, or one that gathers (k < 0)"),
]
FAMILIES["hysteresis"] += [
    _form("hysteresis", "pi_drive", ("weight", "play_max_V", "gain"), (0.3, 0.3, 1.0), (-1.0, 1e-3, 0.2), (1.0, 1.5, 5.0), _pi_drive,
          "Prandtl-Ishlinskii operator on the drive, plays (weight > 0) or stops (weight < 0) of half-widths spread evenly "
          "up to r_max: smooth loops and a remanent bend, the gain rising or falling with the drive"),
    # r_max up to 30 mm, past the laser's range: a density reaching a long strip's largest bend (fresh23's 43 mm strip:
    # 18 mm; the Rayleigh loop's fit wanted 6-7.5 mm, the old bound 5 mm)
    _form("hysteresis", "pi_output", ("weight", "play_max_um", "gain"), (0.3, 100.0, 1.0), (-1.0, 0.1, 0.2), (1.0, 30000.0, 5.0),
          _pi_output, "Prandtl-Ishlinskii operator in the displacement path: dry friction in the bending stiffness "
          "(Maxwell-slip elements), stiffer for small motions, loops and a remanent bend"),
    # the baseline's mechanics took in the gain and phase the play costs at each pressure's amplitudes: refitted with it
    _form("hysteresis", "play_output", ("weight", "play_um"), (0.3, 50.0), (0.0, 0.1), (1.0, 5000.0), _play_output,
          "play operator in the displacement path, y = (1 - w) d + w play_r(d): memory on the sensor side"),
]
_DRY = ("gain_level", "gain_loss", "conductance_level", "conductance_loss")
FAMILIES["dehydration"] += [
    _form("dehydration", "linear", _DRY, (1.0, 0.2, 1.0, 0.1), (0.5, -0.5, 0.5, -0.5), (2.0, 0.9, 2.0, 0.9), slow.session_time(slow.linear),
          "gain and conductance falling linearly with session time from levels of their own (zero-order evaporation)"),
    _form("dehydration", "saturating", (*_DRY, "tau_spans"), (1.0, 0.2, 1.0, 0.1, 0.3), (0.5, -0.5, 0.5, -0.5, 0.03), (2.0, 0.9, 2.0, 0.9, 5.0),
          slow.session_time(slow.saturating), "gain and conductance falling as 1 - exp(-t/tau) towards an equilibrium (first-order drying)"),
    _form("dehydration", "power", (*_DRY, "exponent"), (1.0, 0.2, 1.0, 0.1, 0.5), (0.5, -0.5, 0.5, -0.5, 0.2), (2.0, 0.9, 2.0, 0.9, 3.0),
          slow.session_time(slow.power), "gain and conductance falling as a power of session time, t^n (n = 1/2: diffusion through a drying skin)"),
    _form("dehydration", "falling_rate", (*_DRY, "critical_u", "removable_ratio"), (1.0, 0.2, 1.0, 0.1, 0.4, 0.5),
          (0.5, -0.5, 0.5, -0.5, 0.05, 0.05), (2.0, 0.9, 2.0, 0.9, 0.95, 5.0), slow.session_time(slow.falling_rate),
          "a constant drying rate up to the critical moisture, then a falling rate towards the removable water (the drying curve)"),
    _form("dehydration", "two_stage", (*_DRY, "tau_spans", "slow_ratio", "fast_share"), (1.0, 0.2, 1.0, 0.1, 0.1, 10.0, 0.5),
          (0.5, -0.5, 0.5, -0.5, 0.005, 2.0, 0.0), (2.0, 0.9, 2.0, 0.9, 2.0, 200.0, 1.0), slow.session_time(slow.two_stage),
          "gain and conductance falling in two first-order stages, a fast share then a slow one (sorption by diffusion, then "
          "the network's relaxation)"),
    _form("dehydration", "charge", (*_DRY, "charge_share"), (1.0, 0.2, 1.0, 0.1, 0.7), (0.5, -0.5, 0.5, -0.5, 0.0), (2.0, 0.9, 2.0, 0.9, 1.0),
          slow.drying(slow.by_charge), "gain and conductance falling with the charge passed (electro-osmotic drag), beside the clock's evaporation"),
    _form("dehydration", "onset", (*_DRY, "onset_u", "tau_spans"), (1.0, 0.2, 1.0, 0.1, 0.4, 0.3), (0.5, -0.5, 0.5, -0.5, 0.0, 0.01),
          (2.0, 0.9, 2.0, 0.9, 0.95, 5.0), slow.session_time(slow.from_onset),
          "gain and conductance steady until a moment inside the session, then falling first order (the room's air changed)"),
    _form("dehydration", "per_setting", (*_DRY, "setting_share", "setting_tau_s"), (1.0, 0.2, 1.0, 0.1, 0.5, 200.0),
          (0.5, -0.5, 0.5, -0.5, -1.0, 5.0), (2.0, 0.9, 2.0, 0.9, 1.0, 3000.0), slow.drying(slow.per_setting),
          "water set anew at each clamp setting and followed through the block with a sorption lag, beside the clock's trend"),
]
_CREEP = ("force_loss", "creep_tau_s", "kt_exponent", "gain_exponent")
FAMILIES["clamp_relaxation"] += [
    _form("clamp_relaxation", "log_creep", _CREEP, (0.02, 30.0, 1.0, 0.0), (-0.2, 0.5, -10.0, -10.0), (0.6, 1e4, 10.0, 10.0),
          slow.creep(slow.log_creep), "clamp force creeping with log time, F = F0 (1 - r ln(1 + t/tau)); K_t bar and gain follow it"),
    _form("clamp_relaxation", "power_creep", (*_CREEP, "exponent"), (0.03, 600.0, 1.0, 0.0, 0.4), (-0.2, 20.0, -10.0, -10.0, 0.05),
          (0.6, 1e4, 10.0, 10.0, 1.0), slow.creep(slow.power_creep), "clamp force creeping as a power of time (Nutting), F = F0 (1 - r (t/tau)^n)"),
    _form("clamp_relaxation", "two_arm", (*_CREEP, "slow_ratio", "fast_share"), (0.05, 60.0, 1.0, 0.0, 20.0, 0.5),
          (-0.2, 5.0, -10.0, -10.0, 3.0, 0.0), (0.6, 1e4, 10.0, 10.0, 300.0, 1.0), slow.creep(slow.two_arm_creep),
          "clamp force relaxing in two arms, F = F0 (1 - r (w (1 - e^-t/tau) + (1 - w)(1 - e^-t/(k tau)))); K_t bar and gain follow it"),
    _form("clamp_relaxation", "norton", (*_CREEP, "norton_n"), (0.3, 600.0, 1.0, 0.0, 3.0), (-0.2, 5.0, -10.0, -10.0, 1.05),
          (1.0, 1e5, 10.0, 10.0, 8.0), slow.norton,
          "power-law (Norton) creep, sigma/sigma0 = (1 + (n - 1) t/tau_p)^(-1/(n - 1)), tau_p = tau (p/p_top)^(1 - n): the high "
          "pressures relax most and first; K_t bar and gain follow it"),
    _form("clamp_relaxation", "shaken_loose", ("force_loss", "dose_share", "slip_threshold", "creep_share", "creep_tau_s",
                                               "kt_exponent", "gain_exponent"),
          (0.05, 0.3, 0.3, 0.0, 30.0, 1.0, 0.0), (-0.2, 0.01, 0.0, -0.1, 0.5, -10.0, -10.0), (0.6, 10.0, 0.95, 0.2, 1e4, 10.0, 10.0),
          slow.shaken_loose, "a screw clamp loosened by the records that shake it, F = F0 (1 - r (1 - e^-D/D0) - r_c ln(1 + t/tau_c)), "
          "D the tip acceleration's dose past a slip threshold since the setting (Junker), beside the pads' creep; K_t bar and gain follow it"),
    _form("clamp_relaxation", "room_cycle", ("cycle_sin", "cycle_cos", "cycle_period_s", "creep_share", "creep_tau_s",
                                             "kt_exponent", "gain_exponent"),
          (0.0, 0.0, 1800.0, 0.0, 30.0, 1.0, 0.0), (-0.3, -0.3, 300.0, -0.1, 0.5, -10.0, -10.0), (0.3, 0.3, 2e4, 0.2, 1e4, 10.0, 10.0),
          slow.room_cycle, "a clamp breathing with the room's temperature cycles, F = F0 (1 - [a (sin wt - sin wt_s) + b (cos wt "
          "- cos wt_s)] - r_c ln(1 + t/tau_c)): the screw's and the frame's metals expanding apart, one cycle through the session; "
          "K_t bar and gain follow it"),
]
FAMILIES["hysteresis"] += [
    _form("hysteresis", "flag_output", ("weight", "threshold_um", "reverse_share", "travel_um"), (0.05, 2000.0, 0.5, 5000.0),
          (-1.0, 1.0, 0.0, 1.0), (1.0, 30000.0, flag.REVERSE_SHARE_MAX, 30000.0), flag.flag_output,
          "a pinched (flag) loop in the displacement path, past a threshold x_f and back at x_r: a superelastic element "
          "bent with the strip, a contact that slips only once loaded (flag.py)", start=flag.flag_start),
    _form("hysteresis", "contact_output", ("preload_um", "liftoff_um", "load_slope", "gain"), (100.0, 3000.0, 0.02, 1.0),
          (0.0, 10.0, 0.0, 0.2), (10000.0, 30000.0, 0.5, 5.0), contact.contact_output,
          "a dry contact on the tip whose hold follows where the tip is: a preload the bend relieves (a floor it lifts "
          "off), a load the bend builds (a guide's walls): contact.py", start=contact.contact_start),
    _form("hysteresis", "bouc_wen_output", ("weight", "z_sat_um", "shape_q"), (0.3, 100.0, 0.0), (0.0, 1.0, -1.0), (1.0, 5000.0, 1.0),
          _bouc_wen_output, "Bouc-Wen loop in the displacement path, y = d - w z(d), |z| <= z_sat: smooth memory on the sensor side",
          refit_mechanics=True),
    _form("hysteresis", "preisach_drive", preisach.PARAMS, (0.2, 0.25, 0.15, 0.0, 0.3, 1.0, 0.0), (-1.0, 0.02, 0.05, -0.8, 0.1, 0.2, -2.0),
          (1.0, 1.0, 1.0, 0.8, 2.0, 5.0, 2.0), preisach.preisach_drive,
          "Preisach operator on the drive: relays with a Gaussian density over coercivity and bias (units of the largest "
          "drive), loops that saturate past the relays' thresholds and sit off zero with the bias (preisach.py)"),
]
FAMILIES["large_deflection"] += [
    _form("large_deflection", "curled_arc", ("theta0_rad", "length_factor"), (0.2, 1.0), (-1.2, 0.02), (1.2, 5.0), curled_arc,
          "the arc read around a rest curl or a tilted beam, y = l [f(theta0 + 2 d/l) - f(theta0)]/(2 f'(theta0)), "
          "f(x) = (1 - cos x)/x: even and odd distortion tied by one geometry"),
    _form("large_deflection", "drifting_curl", ("theta_start_rad", "theta_end_rad", "length_factor"), (0.1, 0.3, 1.0), (-1.2, -1.2, 0.02),
          (1.2, 1.2, 5.0), drifting_arc, "the curled arc with its rest curl moving through the session, theta0 from theta_start "
          "to theta_end: a strip curling as it dries or takes a set"),
    _form("large_deflection", "knee", ("fold_over_length", "knee_power"), (1.0, 4.0), (0.02, 2.0), (50.0, 16.0), knee,
          "the reading compressed by a power of itself, y = d (1 - |d/(k L)|^n): a bend stiffening sharply towards its largest, "
          "a reading saturating near its range's end (n = 2: the cubic)"),
]
_MAINS_KEYS = [(ch, f) for ch in LINE_CHANNELS for f in LINE_HZ]
_MAINS_SCALE = np.array([LINE_CHANNELS[ch][3] for ch, _ in _MAINS_KEYS])


def _mains_harmonics(th, ctx: Context):
    """A constant-amplitude line at every mains frequency and harmonic read (``features.LINE_HZ``), each channel's
    own: a chopped (triac, rectifier) or saturating (transformer) current couples its harmonics in too."""
    p = baseline(ctx)
    p.line = dict(zip(_MAINS_KEYS, np.asarray(th) * _MAINS_SCALE))
    return p


def _mains_start(ctx: Context) -> np.ndarray:
    """Each line's amplitude as the records show it: the mean power less the noise's (1.25 x the floor, as
    ``engine.blocks`` reads it), in its channel's unit (um, uA, mV)."""
    out = []
    for key in _MAINS_KEYS:
        pw = [line.amp[key] ** 2 - (1.25 * line.floor[key]) ** 2 for line in ctx.lines
              if key in line.amp and np.isfinite(line.floor[key]) and line.floor[key] > 0]
        out.append(np.sqrt(max(float(np.mean(pw)), 0.0)) if pw else 0.0)
    return np.array(out) / _MAINS_SCALE


def _mains_varying(th, ctx: Context):
    """The lines of ``_mains_harmonics`` scaled in each record by a level of its own (``line_levels.line_levels``): a load
    switched on and off (a thermostat's heater, a compressor, a burst-fire controller) or a coupling that changes
    (someone's hand near the leads), its spectrum and its couplings into the channels fixed."""
    p = _mains_harmonics(th, ctx)
    p.line_level = True
    return p


_MAINS_PARAMS = tuple(f"{LINE_CHANNELS[ch][1]}{f:g}_{LINE_CHANNELS[ch][2]}" for ch, f in _MAINS_KEYS)
FAMILIES["mains_pickup"] += [
    _form("mains_pickup", "harmonics", _MAINS_PARAMS, (0.0,) * len(_MAINS_KEYS), (0.0,) * len(_MAINS_KEYS), (1e4,) * len(_MAINS_KEYS),
          _mains_harmonics, "a constant line at each mains frequency and its harmonics to the 7th (50/60 Hz grids), per channel "
          "(the sensors and the drive's monitor): a chopped or saturating load's pickup", start=_mains_start),
    _form("mains_pickup", "varying", _MAINS_PARAMS, (0.0,) * len(_MAINS_KEYS), (0.0,) * len(_MAINS_KEYS), (1e4,) * len(_MAINS_KEYS),
          _mains_varying, "the lines of 'harmonics' at a level of each record's own: a load switched on and off or a coupling "
          "that changes between records, its spectrum fixed (a level per record, counted in DeltaBIC)", start=_mains_start,
          # the spectrum and the levels are one product: a line no record reads (its column ~0 at the start) wandered far
          # under the Jacobian's scale while the others slid, and held the one record reading it at its floor at level 0
          # (fresh37's heat trace: 180 Hz from 0 to 1 um, 0.512); in the lines' own units it stays
          inner_dof=lambda ctx: len(ctx.lines), x_scale=1.0),
]
FAMILIES["time_delay"] += [
    _form("time_delay", "lag", ("tau_s",), (0.005,), (0.0,), (0.1,), _lag, "first-order lag 1/(1 + s tau) on the displacement",
          refit_mechanics=True),
    _form("time_delay", "skew", ("tau_disp_s", "tau_cur_s"), (0.005, 0.0), (-0.2, -0.2), (0.2, 0.2), _skew,
          "each channel's own delay after the recorded drive, exp(-s tau_d) and exp(-s tau_i) (equal and negative: the "
          "drive's monitor late)", refit_mechanics=True),
    _form("time_delay", "channel_lags", ("tau_disp_s", "tau_cur_s"), (0.002, 0.002), (0.0, 0.0), (0.1, 0.1), _channel_lags,
          "each channel through a first-order low-pass of its own, 1/(1 + s tau_d) and 1/(1 + s tau_i): a sensor's output "
          "filter, a shunt amplifier's RFI filter on the current", refit_mechanics=True),
    _form("time_delay", "lowpass", ("tau_s", "order"), (0.005, 2.0), (0.0, 1.0), (0.1, 30.0), lowpass,
          "the displacement read through (1 + s tau/n)^-n: a sensor's averaging, servo or anti-alias filter of a few poles "
          "(n = 1: the lag; n large: the delay)", refit_mechanics=True),
    _form("time_delay", "band", ("delay_s", "f_share_Hz"), (0.02, 1.0), (0.0, 0.02), (0.3, 50.0), band_delay,
          "the slow share of the reading (below f_share) late by L, the fast share at once: 1 + (exp(-s L) - 1)/(1 + s/w) "
          "(a tracking stage's or a coarse-fine pair's slow path read late)", refit_mechanics=True),
    _form("time_delay", "per_sample", ("alpha",), (0.5,), (0.02,), (1.0,), per_sample_smoothing,
          "the displacement through a moving average run per sample, alpha/(1 - (1 - alpha) e^{-s/fs}) at each record's "
          "own rate: a logger's smoothing, its lag a number of samples and so a different time at each rate", refit_mechanics=True),
    _form("time_delay", "aligned", ("window_s",), (0.05,), (0.0,), (0.5,), aligned.aligned,
          "each record's displacement shifted by the lag that best correlates it with the drive within +-W (an export "
          "script aligning the reading on the drive): the strip's own lag taken out record by record, up to W (aligned.py)",
          refit_mechanics=True),
]
FAMILIES["sensor_offset"] += [
    _form("sensor_offset", "flag", ("lever_over_L",), (0.1,), (-0.5,), (1.0,), _flag,
          "a rigid flag at the tip read lever e beyond it, w(L) + e w'(L) (alpha, gamma, K_t bar refitted)", refit_mechanics=True),
    _form("sensor_offset", "nearest", ("edge_inboard_over_L",), (0.15,), (-0.7,), (0.7,), _nearest,
          "a footprint from the tip to an edge q L inboard, read at its point nearest the sensor: the tip bending towards "
          "it, the edge bending away (q's sign: the side it faces; alpha, gamma, K_t bar refitted)", refit_mechanics=True,
          needs=frozenset({"harm_d"})),  # a gain of each half its own: a 2nd harmonic of (1 - k) 4/(3 pi (1 + k)), 5 % at k 0.8
    _form("sensor_offset", "walking", ("x_over_L", "walk_over_L", "tau_spans"), (0.97, 0.02, 0.5), (0.3, -0.3, 0.03), (1.0, 0.3, 5.0),
          station.walking, "the spot walking along the strip with session time, x_m = L (x0 - walk (1 - e^-u/tau)) (a laser "
          "head warming up, a stand settling): read through the mode shapes there (alpha, gamma, K_t bar refitted)",
          refit_mechanics=True),
]
FAMILIES["strain_resistance"] += [
    _form("strain_resistance", "modulation", ("k_disp", "k_cur", "asymmetry"), (0.05, 0.1, 0.5), (-2.0, -2.0, 0.0), (2.0, 2.0, 1.0),
          _strain_modulation, "gain of displacement and current falling with the bend, y (1 - k e(d)): resistance up with curvature"),
    _form("strain_resistance", "saturating", ("loss_disp", "loss_cur", "asymmetry", "strain_sat"), (0.02, 0.05, 0.5, 0.02),
          (-0.9, -0.9, 0.0, 1e-3), (0.9, 0.9, 1.0, 0.5), _strain_loss(_saturating_law),
          "gain loss with the bend saturating, y (1 - k tanh(e(d)/e_s)): the crack density at its limit"),
    _form("strain_resistance", "power", ("k_disp", "k_cur", "asymmetry", "exponent"), (0.05, 0.1, 0.5, 1.5),
          (-2.0, -2.0, 0.0, 0.5), (2.0, 2.0, 1.0, 4.0), _strain_loss(_power_law),
          "gain loss growing as a power of the bend, y (1 - k (e(d)/e_ref)^n): cracks that open past an onset and widen"),
]


def form(name: str, form_name: str | None) -> Extension:
    """The extension of effect ``name`` in form ``form_name`` (its first form when None or unknown)."""
    for ext in FAMILIES.get(name, []):
        if ext.form == form_name:
            return ext
    return CATALOGUE[name]

