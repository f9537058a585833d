"""A sixth held-out set for the diagnosis (issue 12), written without sight of the diagnosis (its code, its doc, its
tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py, bench/inject_fresh3.py,
bench/inject_fresh4.py and the simulated bench (mock_devices/effects.py); four structures outside the catalogue
(truth "unexplained": laser spikes, triboelectric cable bursts, a phone's GSM buzz, a time-interleaved ADC's
mismatch); clean sessions. All on three bases of new seeds (71-73: the paper strip, the seed-001 strip on its own
sweep, the paper strip 45 mm free) and on the earlier sets' protocol / data-shape variants plus one new here: the
time stamps in single precision (float32, as DAQ software that logs its clock as a 32-bit float: stamps quantised
to 0.12-0.24 ms late in the session, the values unchanged).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject,
inject_fresh2, inject_fresh3 and inject_fresh4 are reused (importing inject_fresh4 registers the earlier sets'
lookups too), and the forms, bases, preset and variant of this set are registered into inject's lookups at import.
Strengths are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it made
on one case, measured in memory against the clean base (relative RMS change over all series, form only).

Run: python bench/inject_fresh5.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Callable

import numpy as np

import inject
from inject import Case, Rec, Session, _dry, lti, lu, map_disp, play, ref_disp
from inject_fresh2 import _chrono, _drive_side, _map_through, _spec
from inject_fresh3 import _cat, _past, _resist, _sign, _through_x
from inject_fresh4 import _ratio_both

# the paper's strip 45 mm free (earlier sets used 30, 40, 25, 35 and 20 mm): registered in every process that imports this module
inject.register_free_length("paper_45", 0.045)

inject.BASES.update({
    "paper_71": ("paper-sweep", "paper", 71),
    "s001_72": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 72),
    "p45_73": ("paper-sweep", "paper_45", 73),
})


def _u(s: Session, t) -> np.ndarray:
    return (np.asarray(t, float) - s.t0) / (s.t1 - s.t0)


def _charge(r: Rec) -> np.ndarray:
    """The charge moved since the record's start, int i dt (trapezoid)."""
    i, t = r.cols["i_A"], r.cols["t_s"]
    return np.r_[0.0, np.cumsum(0.5 * (i[1:] + i[:-1]) * np.diff(t))]


def _ref_rec(s: Session) -> Rec:
    return next((r for kind in ("harmonic", "step") for r in s.series() if r.kind == kind), s.series()[0])


def _at(sp, x: float, z: np.ndarray) -> np.ndarray:
    from labrig.physics import transfer

    return transfer.displacement_tf(z, sp.with_(sensor_x=x))


# ------------------------------------------------------------------------------------------------ back relaxation


def br_warming(s: Session) -> None:
    """The bath warms through the session (a lamp, the amplifiers, a heated stage): 10-20 K towards its end with a
    time constant of 0.2-0.5 of the session. Water's diffusivity in Nafion is thermally activated (Ea 20-35 kJ/mol), so
    the back flow speeds up: one lag per record, 1 - K2/(tau(T) s + 1), tau = tau0 exp(Ea/R (1/T - 1/T0)) at the
    record's mid time, with the session's history. K2 0.9-1.3, tau0 4-12 s (log) at 293 K (tau falls 1.3-2.5x).
    Measured (paper_71): displacement RMS -73 % (residual 88 % of its RMS), current unchanged."""
    k2, tau0, ea, dT, tw = s.rng.uniform(0.9, 1.3), lu(s.rng, 4.0, 12.0), s.rng.uniform(2e4, 3.5e4), s.rng.uniform(10, 20), s.rng.uniform(0.2, 0.5)

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        T = 293.0 + dT * -math.expm1(-float(_u(s, np.mean(r.cols["t_s"]))) / tw)
        tau = tau0 * math.exp(ea / 8.314 * (1 / T - 1 / 293.0))
        return lambda z: 1 - k2 / (tau * z + 1)

    _map_through(s, H, 120.0)


def br_reservoir(s: Session) -> None:
    """The free water that can flow back is a finite reservoir (the cathode side's pores fill): the opposing flux
    follows the bend through a lag but saturates, d - K2 x_s tanh(LP(d)/x_s), x_s 1-3x the 1 V harmonic's amplitude:
    the sines see a linear back relaxation, the 1 V step's large bend gives back a bounded amount. K2 0.9-1.3, tau 3-12 s
    (log). Measured (s001_72): displacement RMS -50 % (residual 59 %)."""
    k2, tau, xs = s.rng.uniform(0.9, 1.3), lu(s.rng, 3.0, 12.0), s.rng.uniform(1.0, 3.0) * ref_disp(s)
    lag = _through_x(s, {id(r): r.cols["disp_m"] for r in s.series()}, lambda r: lambda z: 1 / (tau * z + 1), 120.0)
    map_disp(s, lambda r, d: d - k2 * xs * np.tanh(lag[id(r)] / xs))


# ------------------------------------------------------------------------------------------------ faradaic current


def far_active_passive(s: Session) -> None:
    """The clamp's metal jaws (steel, copper) touch the wet electrode: on the polarity where they are the anode the
    metal dissolves (Tafel, b 40-80 mV) until a passive film forms above the Flade potential E_pp 0.3-0.7 V (width
    30-60 mV): an active-passive current, a peak near E_pp then a small passive current (0.1-0.3 of the peak) at 1 V,
    at the interface's potential (double-layer lag 20-100 ms, log). Peak 0.3-1 mA (log: a few mA/cm2 on the jaws' wetted mm2). Current only.
    Measured (s001_72): current RMS +0.7 %, residual 2.4 % of the current's RMS; displacement unchanged."""
    side, ipk, epp = _sign(s), lu(s.rng, 3e-4, 1e-3), s.rng.uniform(0.3, 0.7)
    b, w, pas, taui = s.rng.uniform(0.04, 0.08), s.rng.uniform(0.03, 0.06), s.rng.uniform(0.1, 0.3), lu(s.rng, 0.02, 0.1)

    def law(v: np.ndarray) -> np.ndarray:
        act = np.exp(np.clip((v - epp) / b, -60, 60)) / (1 + np.exp(np.clip((v - epp) / w, -60, 60)))
        return act + pas * 0.5 * (1 + np.tanh((v - epp) / (2 * w)))

    scale = ipk / float(np.max(law(np.linspace(-1.5, 1.5, 3001))))
    for r in s.series():
        v = side * lti(r.cols["v_V"], r.fs, lambda z: 1 / (1 + taui * z))
        r.cols["i_A"] = r.cols["i_A"] + side * scale * law(v)


def far_h2_crossover(s: Session) -> None:
    """Electrolysis (symmetric Butler-Volmer, v_t 0.1-0.2 V, 0.1-0.4 mA at 1 V, log) whose hydrogen crosses the
    membrane and is oxidised on the other electrode while it stays the anode: a shuttle current in the drive's
    direction that builds over the crossover time tau_x 5-30 s (log) with the gas stored in the membrane (a share
    0.3-0.8 of what was made crosses, the rest vents over tau_v 30-120 s), so a step's DC current grows instead of
    decaying, and the gas made on one polarity is lost when the drive reverses. Current only.
    Measured (paper_71): current RMS +0.9 %, residual 4.1 % of the current's RMS."""
    i1, vt, fx = lu(s.rng, 1e-4, 4e-4), s.rng.uniform(0.1, 0.2), s.rng.uniform(0.3, 0.8)
    tx, tv = lu(s.rng, 5.0, 30.0), s.rng.uniform(30.0, 120.0)
    c, t_end = [0.0, 0.0], None  # gas made while v > 0 and while v < 0 (coulombs of its oxidation)
    for r in _chrono(s):
        t, dt = r.cols["t_s"], 1.0 / r.fs
        if t_end is not None:
            c = [x * math.exp(-(t[0] - t_end) / tv) for x in c]
        v = r.cols["v_V"]
        ie = i1 * np.sinh(v / vt) / math.sinh(1.0 / vt)
        out = np.empty(v.size)
        for n, (vn, ien) in enumerate(zip(v.tolist(), ie.tolist())):
            ox = [c[0] / tx if vn > 0.05 else 0.0, c[1] / tx if vn < -0.05 else 0.0]
            c = [c[0] + (fx * max(ien, 0.0) - ox[0] - c[0] / tv) * dt, c[1] + (fx * max(-ien, 0.0) - ox[1] - c[1] / tv) * dt]
            out[n] = ien + ox[0] - ox[1]
        r.cols["i_A"] = r.cols["i_A"] + out
        t_end = float(t[-1])


# ------------------------------------------------------------------------------------------------ hysteresis


def _per_record(s: Session, op: Callable[[np.ndarray, float], np.ndarray]) -> Callable[[np.ndarray], np.ndarray]:
    """A drive operator for inject_fresh2._drive_side run afresh on each record (its memory wiped over the rest before
    it: the pinned ions redistribute at 0 V), at the session's peak drive; the records in _drive_side's time order."""
    cuts = np.cumsum([r.cols["v_V"].size for r in _chrono(s)])[:-1]

    def gamma(v: np.ndarray) -> np.ndarray:
        vm = float(np.max(np.abs(v))) or 1.0
        return np.concatenate([op(x, vm) for x in np.split(v, cuts)])

    return gamma


def hy_dahl_drive(s: Session) -> None:
    """Dahl's friction law for the ions pinned in the clusters, on the drive: dF/dV = |1 - F sgn(dV)/F_c|^a, a 2-3 (a
    sharper knee than the Coleman-Hodgdon / Duhem form, a = 1), from rest at each record (_per_record), F_c 0.4-0.7 of the session's peak drive;
    Gamma = (1 - h) V + h F, h 0.2-0.4: the small-signal gain linear, falling at 1 V, loops. Through the strip's
    measured step response (inject_fresh2._drive_side); current untouched. Measured (paper_71, form only): displacement RMS -28 % (residual 29 %), 20 Hz record residual 23 %."""
    h, fc, a = s.rng.uniform(0.2, 0.4), s.rng.uniform(0.4, 0.7), s.rng.uniform(2.0, 3.0)

    def op(v: np.ndarray, vm: float) -> np.ndarray:
        Fc = fc * vm
        F, prev, out = 0.0, float(v[0]), np.empty_like(v)
        for k, vk in enumerate(v.tolist()):
            dv, prev = vk - prev, vk
            x = 1 - math.copysign(1.0, dv) * F / Fc
            F = min(max(F + dv * math.copysign(abs(x) ** a, x), -Fc), Fc)
            out[k] = F
        return (1 - h) * v + h * out

    _drive_side(s, _per_record(s, op))


def hy_kp_drive(s: Session) -> None:
    """Krasnosel'skii-Pokrovskii hysterons on the drive: each a ramp between its switching levels (a play of radius
    a_i whose output is capped at +-b_i: a domain that starts swelling only once the drive has moved by a_i and
    holds a limited charge b_i), six of them, from rest at each record, a_i 0.05-0.4 and b_i 0.3-0.8 of the peak drive, weights drawn; scaled
    to the drive's gain at the peak. Gamma = (1 - h) V + h K[V], h 0.25-0.45: small signals see (1 - h), a gain
    rising then capped with the amplitude, loops with a remanence. Through the measured step response.
    Measured (p45_73): displacement RMS +7.7 % (residual 14 %)."""
    h = s.rng.uniform(0.25, 0.45)
    a, b, w = s.rng.uniform(0.05, 0.4, 6), s.rng.uniform(0.3, 0.8, 6), s.rng.uniform(0.3, 1.0, 6)

    def op(v: np.ndarray, vm: float) -> np.ndarray:
        k = np.sum([wi * np.clip(play(v, ai * vm), -bi * vm, bi * vm) for ai, bi, wi in zip(a, b, w)], axis=0)
        norm = vm / float(np.sum(w * np.minimum(vm - a * vm, b * vm)))
        return (1 - h) * v + h * norm * k

    _drive_side(s, _per_record(s, op))


# ------------------------------------------------------------------------------------------------ time delay


def td_butterworth4(s: Session) -> None:
    """The displacement read by an eddy-current (or inductive) sensor whose demodulator ends in a 4th-order
    Butterworth low-pass, corner 30-120 Hz (log): flat gain in band, a group delay of 2.61/omega_c (3.5-14 ms) at low
    frequency that grows towards the corner. Measured (s001_72): displacement RMS -0.0 % over all (residual 0.3 %), 20 Hz record residual 108 % of its RMS."""
    wc = 2 * np.pi * lu(s.rng, 30.0, 120.0)
    _map_through(s, lambda r: lambda z: 1 / ((1 + 0.7654 * z / wc + (z / wc) ** 2) * (1 + 1.8478 * z / wc + (z / wc) ** 2)), 1.0)


def td_rolling_shutter(s: Session) -> None:
    """Video tracking with a rolling-shutter camera (100-400 fps, log, free running): each frame's rows are exposed
    one after another over 0.6-0.9 of the frame period, so the tip's row is sampled at t_k + T_read row, the row
    moving with the tip's height (0.5 +- 0.35 of the image); each frame arrives a frame period plus 2-10 ms (log)
    of processing after its start, and the track is linearly interpolated onto the DAQ's clock: a delay of 5-16 ms
    that changes with the displacement. Measured (paper_71): displacement RMS -0.0 % over all (residual 0.2 %), 20 Hz record residual 75 %."""
    F, rd, lat, side, ph = lu(s.rng, 100.0, 400.0), s.rng.uniform(0.6, 0.9), lu(s.rng, 2e-3, 1e-2), _sign(s), s.rng.uniform(0, 1)
    dmax = max(float(np.max(np.abs(r.cols["disp_m"]))) for r in s.series()) or 1.0
    new = {}
    for r in s.series():
        t, d = r.cols["t_s"], r.cols["disp_m"]
        past = _past(s, r, "disp_m", 0.3, r.fs)
        T = np.r_[t[0] - np.arange(past.size, 0, -1) / r.fs, t]
        D = np.r_[past, d]
        k = np.arange(math.floor((T[0] - ph / F) * F), math.ceil((t[-1] - ph / F) * F) + 1)
        tk = (k + ph) / F
        row = np.clip(0.5 + 0.35 * side * np.interp(tk + 0.5 * rd / F, T, D) / dmax, 0.05, 0.95)
        val = np.interp(tk + rd / F * row, T, D)
        new[id(r)] = np.interp(t, tk + 1 / F + lat, val)
    map_disp(s, lambda r, d: new[id(r)])


# ------------------------------------------------------------------------------------------------ sensor offset


def so_root_reference(s: Session) -> None:
    """A differential reading (two laser heads, or video tracking of two markers) whose reference marker sits on the
    strip just out of the jaws (x_r 0.15-0.3 L) instead of on the clamp: the reading is w(L) - w(x_r), through the
    beam's transfer functions (quasi-static gain 1 - (x_r/L)^2 and the root point's own modal shares above f1).
    Measured (p45_73): displacement RMS -6.0 %, 20 Hz record residual 20 %."""
    fr = s.rng.uniform(0.15, 0.3)

    def ratio(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        sp = _spec(s, r)
        L = sp.geometry.length

        def h(z: np.ndarray) -> np.ndarray:
            with np.errstate(divide="ignore", invalid="ignore"):
                tip = _at(sp, L, z)
                return (tip - _at(sp, fr * L, z)) / tip

        return h

    _map_through(s, ratio, 2.0)


def so_eddy_footprint(s: Session) -> None:
    """An eddy-current (or capacitive) proximity probe facing the strip near its tip instead of a laser: it reads
    the mean gap over its circular footprint (radius R 1-2.5 mm, chord-weighted), calibrated on a large flat target,
    with its centre R (0-0.8) inboard of the tip so that part of the footprint overhangs the end and sees no target.
    Through the beam's transfer functions at nine stations. Measured (paper_71): displacement RMS -36 %, 20 Hz record residual 40 %."""
    R, off = s.rng.uniform(1e-3, 2.5e-3), s.rng.uniform(0.0, 0.8)

    def ratio(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        sp = _spec(s, r)
        L = sp.geometry.length
        xc = L - off * R
        xs = xc + R * np.linspace(-1, 1, 11)[1:-1]
        w = np.sqrt(np.clip(R**2 - (xs - xc) ** 2, 0, None))
        w /= w.sum()

        def h(z: np.ndarray) -> np.ndarray:
            with np.errstate(divide="ignore", invalid="ignore"):
                return sum(wi * _at(sp, x, z) for wi, x in zip(w, xs) if x <= L) / _at(sp, L, z)

        return h

    _map_through(s, ratio, 2.0)


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_mittag_leffler(s: Session) -> None:
    """The pads as a fractional standard linear solid (a spring-pot, the power-law memory of polymers): under the
    held jaw gap F/F0 = 1 - r + r E_b(-(t/tau)^b), E_b the Mittag-Leffler function (a stretched start, a power-law
    tail t^-b), b 0.3-0.7, r 0.1-0.25, tau 50-500 s (log), from each pressure's first record; the load cell (its
    0.01 kgf) and the displacement gain following F^b, b 0.5-1.5 (inject._clamp). Measured (s001_72): load cell down to 0.81 of its setting, displacement RMS -11 %."""
    r0, b, tau = s.rng.uniform(0.1, 0.25), s.rng.uniform(0.3, 0.7), lu(s.rng, 50.0, 500.0)
    sg = np.logspace(-8, 8, 3000)  # E_b(-x^b) = int K(s) exp(-s x) ds, K the spectrum of the Mittag-Leffler relaxation
    K = sg ** (b - 1) * math.sin(b * math.pi) / math.pi / (sg ** (2 * b) + 2 * sg**b * math.cos(b * math.pi) + 1)
    xg = np.r_[0.0, np.logspace(-4, 3, 300)]
    Eg = np.trapezoid(K * sg * np.exp(-np.outer(xg, sg)), np.log(sg), axis=1)
    Eg /= Eg[0]
    inject._clamp(s, lambda t: 1 - r0 + r0 * np.interp(np.clip(t, 0, None) / tau, xg, Eg))


def cr_servo_deadband(s: Session) -> None:
    """A motorised clamp that re-tightens only when its load cell falls below a deadband (2-5 % under the set
    force): the pads relax (1 - r (1 - exp(-t/tau)), r 0.1-0.25, tau 100-600 s, log) until the servo adds a gap
    increment, which relaxes in turn (Boltzmann superposition): a sawtooth force whose teeth lengthen through the
    block. The displacement gain follows F^b, b 0.5-1.5. Measured (paper_71): load cell sawtooth down to 0.96, displacement RMS -2.8 %."""
    db, r0, tau, b = s.rng.uniform(0.02, 0.05), s.rng.uniform(0.1, 0.25), lu(s.rng, 100.0, 600.0), s.rng.uniform(0.5, 1.5)
    G = lambda t: 1 - r0 * -np.expm1(-np.clip(t, 0, None) / tau) * (np.asarray(t) >= 0)  # noqa: E731
    span: dict[float, list[float]] = {}
    for r in s.series():
        p = float(r.entry["pressure_kPa"])
        lo, hi = span.get(p, [np.inf, -np.inf])
        span[p] = [min(lo, float(r.cols["t_s"][0])), max(hi, float(r.cols["t_s"][-1]))]
    inc = {}
    for p, (t0, t1) in span.items():
        steps = [(t0, 1.0)]
        for tg in np.arange(t0, t1 + 1.0, 0.5):
            F = sum(du * float(G(tg - tj)) for tj, du in steps)
            if F < 1 - db:
                steps.append((float(tg), 1.0 - F))
        inc[p] = steps
    for r in s.series():
        p = float(r.entry["pressure_kPa"])
        rel = sum(du * G(r.cols["t_s"] - tj) * (r.cols["t_s"] >= tj) for tj, du in inc[p])
        if "force_N" in r.cols:
            r.cols["force_N"] = np.round(r.cols["force_N"] * rel / 0.0980665) * 0.0980665
        r.cols["disp_m"] = r.cols["disp_m"] * rel**b


# ------------------------------------------------------------------------------------------------ dehydration


def dh_drive_heating(s: Session) -> None:
    """Drive-induced drying: the power the strip dissipates (|i v|) heats its surface film and drives water out, which
    comes back only slowly at rest (re-uptake time 200-800 s, log): the loss follows the power through that lag,
    rising through the busy parts of the session, easing in the pauses (not a function of the time alone). Scaled so
    the largest loss is 0.15-0.3; through inject._dry (conductance and spectra follow). Measured (paper_71): displacement RMS -11 %, current -10 %."""
    total, tau = s.rng.uniform(0.15, 0.3), lu(s.rng, 200.0, 800.0)
    recs = _chrono(s)
    T = np.concatenate([r.cols["t_s"] for r in recs])
    P = np.concatenate([np.abs(r.cols["i_A"] * r.cols["v_V"]) for r in recs])
    P /= max(float(np.mean(P)), 1e-30)
    x, prev, X = 0.0, T[0], np.empty_like(T)
    for n, (tn, pn) in enumerate(zip(T.tolist(), P.tolist())):
        x = pn + (x - pn) * math.exp(-(tn - prev) / tau) if tn - prev < 5.0 else x * math.exp(-(tn - prev) / tau)
        X[n], prev = x, tn
    X *= total / max(float(np.max(X)), 1e-30)
    _dry(s, lambda u: np.interp(s.t0 + u * (s.t1 - s.t0), T, X))


def dh_two_pool_cpe(s: Session) -> None:
    """A strip in air loses its free water quickly (tau1 0.05-0.15 of the session) and its bound water slowly (tau2
    1-3 sessions), share w 0.3-0.6 free: x = total-normalised biexponential, total 0.15-0.3. Per record the specimen
    with alpha (1 - x), Q0 (1 - c x), R_p/(1 - c x) and the CPE index n (1 - e x) (the drying interface grows more
    distributed), through the strip's transfer functions (displacement and admittance; spectra follow). c 0.3-0.8,
    e 0.1-0.3. Measured (s001_72): displacement RMS -14 % (residual 17 %), current -3.6 % (residual 4.8 %)."""
    from labrig.physics import transfer

    total, t1, t2, w = s.rng.uniform(0.15, 0.3), s.rng.uniform(0.05, 0.15), s.rng.uniform(1.0, 3.0), s.rng.uniform(0.3, 0.6)
    c, e = s.rng.uniform(0.3, 0.8), s.rng.uniform(0.1, 0.3)
    shape = lambda u: w * -np.expm1(-u / t1) + (1 - w) * -np.expm1(-u / t2)  # noqa: E731
    loss = lambda t: total * shape(np.clip(_u(s, t), 0, 1)) / shape(1.0)  # noqa: E731

    def dried(sp, x: float):
        m, ln = sp.mechanics, sp.line
        return sp.with_(mechanics=replace(m, alpha=m.alpha * (1 - x)),
                        line=replace(ln, Q0=ln.Q0 * (1 - c * x), R_p=ln.R_p / (1 - c * x), n=ln.n * (1 - e * x)))

    for j, r in enumerate(s.recs):  # a spectrum at the start of the series after it
        if r.series:
            continue
        after = next((q for q in s.recs[j + 1 :] if q.series), None)
        sp = _spec(s, r)
        z = 2j * np.pi * r.cols["f_Hz"]
        zz = (r.cols["z_re_ohm"] + 1j * r.cols["z_im_ohm"]) * transfer.admittance_tf(z, sp) / transfer.admittance_tf(
            z, dried(sp, float(loss(after.cols["t_s"][0] if after else s.t1))))
        r.cols["z_re_ohm"], r.cols["z_im_ohm"] = zz.real, zz.imag
    _ratio_both(s, lambda r: dried(_spec(s, r), float(loss(np.mean(r.cols["t_s"])))))


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_first_crack(s: Session) -> None:
    """The first large bend cracks the tensioned electrode for good: its resistance carries an irreversible part set
    by the largest tension so far (a running maximum through the session, over its final value, share 0.3-1) beside the reversible opening
    with the present tension, dR/R ~ c M(t) + e+. Gains as inject._strain (displacement 0.02-0.06, current 0.05-0.15
    per unit of the displacement scale). Measured (p45_73): displacement RMS -16 %, current -7.4 % (residual 11 %)."""
    side, ci = _sign(s), s.rng.uniform(0.3, 1.0)
    recs, e, cuts = _cat(s, "disp_m")
    ep = np.clip(side * e / ref_disp(s), 0, None)
    M = np.maximum.accumulate(ep)
    part = dict(zip([id(r) for r in recs], np.split(ci * M / max(float(M[-1]), 1e-30) + ep, cuts)))
    _resist(s, lambda r, x: part[id(r)], (0.02, 0.06), (0.05, 0.15))


def sr_swelling_strain(s: Session) -> None:
    """The electrodes are strained in their plane by the polymer's swelling, not by the bend: the cathode side takes
    the water the moved charge carries and stretches (its cracks open), the anode side shrinks (cracks close, a
    falling resistance, 0.2-0.5 of the opening's gauge); the other face's gauge 0.3-0.8 of the first's. Driven by the
    charge moved since each record's start (Q = int i dt over the 1 V harmonic's charge amplitude, capped at 4),
    which keeps growing through a step while the bend relaxes. Gains 0.02-0.05 (displacement), 0.05-0.12 (current).
    Measured (s001_72): displacement RMS -7.5 %, current -1.0 % (residual 3.5 %)."""
    side, gb, kc = _sign(s), s.rng.uniform(0.3, 0.8), s.rng.uniform(0.2, 0.5)
    qref = max(0.5 * float(np.ptp(_charge(_ref_rec(s)))), 1e-12)

    def shape(r: Rec, x: np.ndarray) -> np.ndarray:
        q = np.clip(side * _charge(r) / qref, -4, 4)
        qp, qm = np.clip(q, 0, None), np.clip(-q, 0, None)
        return qp * (1 - kc * gb) + qm * (gb - kc)

    _resist(s, shape, (0.02, 0.05), (0.05, 0.12))


# ------------------------------------------------------------------------------------------------ large deflection


def _arc(d: np.ndarray, L: float) -> tuple[np.ndarray, np.ndarray]:
    """The tip of the exact uniform-curvature arc (k = 2 d/L^2): its height Y and its draw-back L - X."""
    k = 2 * d / L**2
    small = np.abs(k * L) < 1e-6
    ks = np.where(small, 1.0, k)
    Y = np.where(small, d, (1 - np.cos(k * L)) / ks)
    B = np.where(small, k**2 * L**3 / 6, L - np.sin(k * L) / ks)
    return Y, B


def ld_oblique_camera(s: Session) -> None:
    """Video tracking from a camera whose axis is not square to the bending plane's height axis: tilted by 8-20 deg
    in the plane of the strip (towards or away from the tip, drawn), it sees the tip's height and its draw-back along
    the strip, Y - B tan(phi) (calibrated on a scale at rest): the arc's odd compression plus an even term from the
    draw-back that shifts both sides the same way. Measured (p45_73): displacement RMS +3.2 %."""
    tphi = math.tan(math.radians(s.rng.uniform(8.0, 20.0))) * _sign(s)
    L = float(s.specimen["length_m"])

    def f(r: Rec, d: np.ndarray) -> np.ndarray:
        Y, B = _arc(d, L)
        return Y - tphi * B

    map_disp(s, f)


def ld_chord_angle(s: Session) -> None:
    """The tip deflection reported from the chord's angle (video: the line from a reference mark l0 0-0.2 L behind
    the clamp edge to the tip marker), converted with the small-deflection rule d = (L + l0) tan(phi): on the exact
    arc tan(phi) = Y/(X + l0), so the report reads MORE than d (L tan(d/L) for l0 = 0), an odd expansion.
    Measured (p45_73): displacement RMS +2.6 % (residual 2.9 %)."""
    l0 = s.rng.uniform(0.0, 0.2)
    L = float(s.specimen["length_m"])

    def f(r: Rec, d: np.ndarray) -> np.ndarray:
        Y, B = _arc(d, L)
        return (1 + l0) * L * Y / (L - B + l0 * L)

    map_disp(s, f)


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_six_pulse(s: Session) -> None:
    """A variable-frequency drive (pump, HVAC) on the building's supply: its six-pulse rectifier draws current in
    blocks, so the field near the bench carries the line's 5th and 7th harmonics (7th 0.5-0.8 of the 5th, 11th
    0.1-0.3, 13th 0.05-0.2) over a small fundamental (0.1-0.3); grid 50 or 60 Hz (+-0.05), phase locked to the
    session clock, on both lines. Peak 1-5 um, 2-10 uA (log). Measured (s001_72):
    residual RMS 1.0 um on the displacement (2x its 0.5 um noise), 1.7 uA on the current (0.9x its 2 uA noise), 20 Hz
    record residual 4 %."""
    ad, ai = lu(s.rng, 1e-6, 5e-6), lu(s.rng, 2e-6, 1e-5)
    f = (50.0 if s.rng.random() < 0.5 else 60.0) + s.rng.uniform(-0.05, 0.05)
    n = np.array([1, 5, 7, 11, 13])
    amp = np.array([s.rng.uniform(0.1, 0.3), 1.0, s.rng.uniform(0.5, 0.8), s.rng.uniform(0.1, 0.3), s.rng.uniform(0.05, 0.2)])
    phd, phi = s.rng.uniform(0, 2 * np.pi, (2, n.size))
    th = np.linspace(0, 2 * np.pi, 2048, endpoint=False)
    pk = lambda ph: float(np.max(np.abs(np.cos(np.outer(th, n) + ph) @ amp)))  # noqa: E731
    kd, ki = ad / pk(phd), ai / pk(phi)
    for r in s.series():
        w = 2 * np.pi * f * r.cols["t_s"]
        r.cols["disp_m"] = r.cols["disp_m"] + kd * (np.cos(np.outer(w, n) + phd) @ amp)
        r.cols["i_A"] = r.cols["i_A"] + ki * (np.cos(np.outer(w, n) + phi) @ amp)


def mp_diode_rectified(s: Session) -> None:
    """Mains pickup distorted by the input stage it reaches: the amplifiers' input protection (diode junctions) and
    the laser's input conduct a little on one half-wave, y = (exp(kappa x) - 1)/kappa for the picked-up 50 Hz
    x = cos(w t + p): even harmonics (100, 200 Hz) and a DC shift beside the 50 Hz. kappa 1.5-3 on the current line,
    0.5-1.5 on the displacement's; grid off nominal by up to 0.05 Hz, phase locked to the session clock. Peak 1-5 um,
    2-10 uA (log). Measured (p45_73): residual RMS 0.6 um (1.2x noise) and 1.8 uA (0.9x noise), DC shift included."""
    ad, ai, f = lu(s.rng, 1e-6, 5e-6), lu(s.rng, 2e-6, 1e-5), 50.0 + s.rng.uniform(-0.05, 0.05)
    kd, ki = s.rng.uniform(0.5, 1.5), s.rng.uniform(1.5, 3.0)
    pd, pi = s.rng.uniform(0, 2 * np.pi, 2)
    g = lambda x, k: np.expm1(k * x) / np.expm1(k)  # noqa: E731  peak 1 at x = 1
    for r in s.series():
        w = 2 * np.pi * f * r.cols["t_s"]
        r.cols["disp_m"] = r.cols["disp_m"] + ad * g(np.cos(w + pd), kd)
        r.cols["i_A"] = r.cols["i_A"] + ai * g(np.cos(w + pi), ki)


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_spikes(s: Session) -> None:
    """The triangulation laser's outliers: a particle or a bubble crossing the beam, or speckle, makes its peak
    detector lock on a false image for one to three samples: isolated spikes of 30-300 um (log, either sign) at
    0.2-1 per s (log, Poisson over the records' time); displacement only. Measured (paper_71): 0.4 % of the samples hit, residual there 138 um RMS (276x the noise), displacement residual
        0.26 % of its RMS, 20 Hz record 67 %."""
    rate = lu(s.rng, 0.2, 1.0)
    for r in s.series():
        t, d = r.cols["t_s"], r.cols["disp_m"].copy()
        for _ in range(s.rng.poisson(rate * (t[-1] - t[0]))):
            k = int(s.rng.integers(0, t.size))
            d[k : k + int(s.rng.integers(1, 4))] += lu(s.rng, 3e-5, 3e-4) * _sign(s)
        r.cols["disp_m"] = d


def out_tribo(s: Session) -> None:
    """Triboelectric charge from the current amplifier's input cable when it flexes (the operator's hand, the
    table's vibration): bursts (0.05-0.2 per s, log) of 0.2-1 s, each 3-15 charge pulses of random sign, 10-60 uA
    (log) decaying through the input's RC (2-10 ms); current only. Measured (s001_72): 3.4 % of the current's samples touched, residual there 8.6 uA RMS (4x the noise), peaks 87
        uA."""
    rate, tau = lu(s.rng, 0.05, 0.2), s.rng.uniform(2e-3, 1e-2)
    for r in s.series():
        t, i = r.cols["t_s"], r.cols["i_A"].copy()
        for _ in range(s.rng.poisson(rate * (t[-1] - t[0]))):
            tb, dur = s.rng.uniform(t[0], t[-1]), s.rng.uniform(0.2, 1.0)
            for tk in tb + np.sort(s.rng.uniform(0, dur, int(s.rng.integers(3, 16)))):
                on = t >= tk
                i[on] += lu(s.rng, 1e-5, 6e-5) * _sign(s) * np.exp(-(t[on] - tk) / tau)
        r.cols["i_A"] = i


def out_gsm_buzz(s: Session) -> None:
    """A GSM phone near the bench: its TDMA bursts (one 577 us slot per 4.615 ms frame, 216.7 Hz) are demodulated by
    the amplifiers' inputs into a pulse train (its first eight harmonics), present only while the phone talks to its
    cell: 4-7 windows of 40-120 s starting inside recorded series. Sampled without an anti-alias filter (aliased by
    each record's rate). RMS in a window: current 3-8 uA, displacement 1.5-4 um (log). Measured (p45_73): 3.2 % of the samples in a window, current residual there 4.8 uA RMS (2.4x the noise), peaks
        16 uA."""
    ai, ad, f = lu(s.rng, 3e-6, 8e-6), lu(s.rng, 1.5e-6, 4e-6), 1 / 4.615e-3
    n = np.arange(1, 9)
    c = np.sin(np.pi * n / 8) / (np.pi * n)
    ser = s.series()
    win = []
    for _ in range(int(s.rng.integers(4, 8))):
        r = ser[int(s.rng.integers(0, len(ser)))]
        t0 = s.rng.uniform(r.cols["t_s"][0], r.cols["t_s"][-1])
        win.append((t0, t0 + s.rng.uniform(40.0, 120.0)))
    ph = s.rng.uniform(0, 2 * np.pi)
    train = lambda t: np.cos(np.outer(2 * np.pi * f * t + ph, n)) @ c / math.sqrt(0.5 * np.sum(c**2))  # noqa: E731  unit RMS
    for r in ser:
        t = r.cols["t_s"]
        env = np.zeros(t.size)
        for a, b in win:
            env = np.maximum(env, np.clip((t - a) / 0.05, 0, 1) * np.clip((b - t) / 0.05, 0, 1))
        if np.any(env > 0):
            x = env * train(t)
            r.cols["i_A"] = r.cols["i_A"] + ai * x
            r.cols["disp_m"] = r.cols["disp_m"] + ad * x


def out_interleave(s: Session) -> None:
    """A DAQ whose converter is two time-interleaved ADCs: even and odd samples differ by an offset (1-3 um, 2-6 uA)
    and a gain (0.2-1 %, log) mismatch, so each channel carries a line at fs/2 and the signal's image mirrored about
    fs/4. Measured (paper_71): displacement residual 7.1 um RMS (14x the noise) on every sample, current 12 uA RMS."""
    od, oi, gd, gi = s.rng.uniform(1e-6, 3e-6), s.rng.uniform(2e-6, 6e-6), lu(s.rng, 2e-3, 1e-2), lu(s.rng, 2e-3, 1e-2)
    for r in s.series():
        alt = np.where(np.arange(r.cols["t_s"].size) % 2 == 0, 0.5, -0.5)
        r.cols["disp_m"] = r.cols["disp_m"] * (1 + gd * alt) + od * alt
        r.cols["i_A"] = r.cols["i_A"] * (1 + gi * alt) + oi * alt


FRESH5_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"warming": br_warming, "reservoir": br_reservoir},
    "faradaic_current": {"active_passive": far_active_passive, "h2_crossover": far_h2_crossover},
    "hysteresis": {"dahl_drive": hy_dahl_drive, "kp_drive": hy_kp_drive},
    "time_delay": {"butterworth4": td_butterworth4, "rolling_shutter": td_rolling_shutter},
    "sensor_offset": {"root_reference": so_root_reference, "eddy_footprint": so_eddy_footprint},
    "clamp_relaxation": {"mittag_leffler": cr_mittag_leffler, "servo_deadband": cr_servo_deadband},
    "dehydration": {"drive_heating": dh_drive_heating, "two_pool_cpe": dh_two_pool_cpe},
    "strain_resistance": {"first_crack": sr_first_crack, "swelling_strain": sr_swelling_strain},
    "large_deflection": {"oblique_camera": ld_oblique_camera, "chord_angle": ld_chord_angle},
    "mains_pickup": {"six_pulse": mp_six_pulse, "diode_rectified": mp_diode_rectified},
    "unexplained": {"spikes": out_spikes, "tribo": out_tribo, "gsm_buzz": out_gsm_buzz, "interleave": out_interleave},
}
inject.register_forms(FRESH5_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def v_float32_time(s: Session) -> None:
    """DAQ software that logs its clock as a 32-bit float: every series' t_s rounded to float32 (stamps quantised to
    0.12-0.24 ms at 1000-4000 s into the session, the values untouched)."""
    for r in s.series():
        r.cols["t_s"] = r.cols["t_s"].astype(np.float32).astype(np.float64)


inject.VARIANTS.update({"float32_time": v_float32_time})

# ------------------------------------------------------------------------------------------------ the cases

P71, S72, T73 = "paper_71", "s001_72", "p45_73"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 7 / 6 effect cases on seeds 71 / 72 / 73
    "back_relaxation": [("warming", 71, P71, "asrun"), ("reservoir", 72, S72, "dropped_packets")],
    "faradaic_current": [("h2_crossover", 71, P71, "no_spectra"), ("active_passive", 72, S72, "asrun")],
    "hysteresis": [("dahl_drive", 71, P71, "two_pressures"), ("kp_drive", 73, T73, "asrun")],
    "time_delay": [("rolling_shutter", 71, P71, "own_clock"), ("butterworth4", 72, S72, "shortened_shuffled")],
    "sensor_offset": [("eddy_footprint", 71, P71, "float32_time"), ("root_reference", 73, T73, "resampled")],
    "clamp_relaxation": [("servo_deadband", 71, P71, "asrun"), ("mittag_leffler", 72, S72, "asrun")],
    "dehydration": [("drive_heating", 71, P71, "rate07"), ("two_pool_cpe", 72, S72, "float32_time")],
    "strain_resistance": [("swelling_strain", 72, S72, "asrun"), ("first_crack", 73, T73, "two_pressures")],
    "large_deflection": [("oblique_camera", 73, T73, "asrun"), ("chord_angle", 73, T73, "steps_sines")],
    "mains_pickup": [("six_pulse", 72, S72, "decimated3"), ("diode_rectified", 73, T73, "no_spectra")],
    "unexplained": [("spikes", 71, P71, "asrun"), ("spikes", 73, T73, "float32_time"),
                    ("tribo", 72, S72, "asrun"), ("tribo", 71, P71, "dropped_packets"),
                    ("gsm_buzz", 73, T73, "asrun"), ("gsm_buzz", 72, S72, "rate07"),
                    ("interleave", 71, P71, "no_spectra"), ("interleave", 72, S72, "own_clock")],
}
CLEAN = [(71, P71, "asrun"), (71, P71, "float32_time"), (72, S72, "asrun"), (73, T73, "asrun")]


def fresh5_cases(only: str | None = None) -> list[Case]:
    """The sixth held-out set: 20 effect cases (every form once), 8 outside the catalogue, 4 clean (seeds 71-73)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh5_cases, "inject_fresh5", "fresh5")
