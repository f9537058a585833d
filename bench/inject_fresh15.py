"""A sixteenth held-out set for the diagnosis (issue 12), fresh15, written without sight of the diagnosis (its code,
its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh14.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (the bath's cross-flow drag on a strip
bent out of a flow cell's stream, a push-pull pair of reflective sensors, a copper lead hardening as it yields, crack
growth only under fast straining, a voltage-to-frequency isolation link whose delay follows the reading), some on the
history (the back-flow's streaming current, friction contacts that age at rest, methanol poisoned and stripped on
the platinum), some on time or on the clamp pressure (a bath evaporating under a tilted laser, the sun crossing the
bench, a warming bath opening the film's cracks, the root squeezed at each tightening, the operator's warm fingers on
the clamp screw, a hydraulic clamp's oil warmed by the drive amplifier, evaporation through the cracks of the bent
face), some from the lab's wiring or settings (a grounded probe in the bath, video frames stamped on delivery, a
modal conversion of an inboard reading, an electromagnetic air pump, cables moved at each re-clamping). Four
structures outside the catalogue (truth "unexplained": the laser's minus sign dropped by a text parser, a relay's
click ringing the stand at each record's arming, the drive amplifier's thermal cut-outs, a two-wire impedance
measurement); clean sessions. All on three bases of new seeds (115-117: the paper strip, the seed-001 strip on its own
sweep, the paper strip 31 mm free) and on the earlier sets' protocol / data-shape variants plus one new here: a logger
with a logarithmic time base on the step records (``log_steps``).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh14 are reused (importing inject_fresh14 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import, none replaced. Strengths
are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it made on its case,
measured in memory against the clean base (relative RMS change over all series, form only, no variant; "noise": the
column's sample-to-sample noise at rest, std(diff)/sqrt(2) over the 200 samples before each step record's edge, the
median over the steps; the values for the three bases are in docs/effects.md).

Run: python bench/inject_fresh15.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np
from scipy import signal, special
from scipy.integrate import cumulative_trapezoid

import inject
import inject_fresh14  # noqa: F401  (registers every earlier set's forms, bases, presets and variants)
from inject import Case, Rec, Session, lu, map_disp, ref_disp
from inject_fresh2 import _chrono, _drive_side, _spec, _through
from inject_fresh3 import _resist, _sign
from inject_fresh4 import _clamp_law
from inject_fresh6 import _blocks
from inject_fresh7 import _ramp_env, _superpose
from inject_fresh8 import _hum
from inject_fresh9 import _dry_by, _gaps, _session_grid
from inject_fresh10 import _lag_varying, _lambda, _station
from inject_fresh11 import _walk
from inject_fresh12 import _line_f
from inject_fresh14 import _lagged, _largest, _series_cat

# the paper's strip 31 mm free (earlier sets used 20, 25, 27, 28, 30, 32-40, 42 and 45 mm; its 1 V step peaks near
# 9.4 mm, 8.8 mm x (31/30)^2, 9.4 mm measured, inside the laser's +-20 mm): registered in every process importing this
inject.register_free_length("paper_31", 0.031)

inject.BASES.update({
    "paper_115": ("paper-sweep", "paper", 115),
    "s001_116": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 116),
    "p31_117": ("paper-sweep", "paper_31", 117),
})


# ------------------------------------------------------------------------------------------------ tools


def _edges(v: np.ndarray) -> np.ndarray:
    """The samples where a step record's drive changes (its rise and its fall): a jump of over half its excursion."""
    amp = float(np.max(np.abs(v - v[0]))) or 1.0
    return np.flatnonzero(np.abs(np.diff(v)) > 0.5 * amp) + 1


def rest_noise(s: Session, col: str) -> float:
    """The column's sample-to-sample noise at rest: std(diff)/sqrt(2) over the 200 samples before each step record's
    edge, the median over the steps (the "noise" of the docstrings and of docs/effects.md)."""
    out = []
    for r in s.series():
        if r.kind == "step" and _edges(r.cols["v_V"]).size:
            e = int(_edges(r.cols["v_V"])[0])
            x = r.cols[col][max(e - 201, 0) : e - 1]
            if x.size > 10:
                out.append(float(np.std(np.diff(x))) / math.sqrt(2))
    return float(np.median(out)) if out else float("nan")


def _store(s: Session, tau: float) -> dict[int, np.ndarray]:
    """A first-order lag of the displacement (time constant tau) through the session in time order, carried over the
    rests (the displacement linear across them); the lag per record."""
    x, d_end, out = 0.0, 0.0, {}
    for r, gap in _gaps(s, 1.0):
        d = r.cols["disp_m"]
        for dt, u in gap:
            x += -math.expm1(-dt / tau) * (d_end + u * (float(d[0]) - d_end) - x)
        a = math.exp(-1.0 / (r.fs * tau))
        y, _ = signal.lfilter([1 - a], [1.0, -a], d, zi=[a * x])
        out[id(r)], x, d_end = y, float(y[-1]), float(d[-1])
    return out


def _first_step(s: Session) -> Rec | None:
    return next((r for r in _chrono(s) if r.kind == "step" and _edges(r.cols["v_V"]).size), None)


def _elastica(L: float, EI: float, kappa: np.ndarray, load: Callable, n: int = 240) -> np.ndarray:
    """The tip's height Y(L) of a cantilever clamped along x (theta(0) = 0) under a uniform eigen-curvature kappa
    (array) and a distributed load per length load(theta) -> (f_x, f_y) (N/m) set by the local angle, exact (large
    rotations): theta' = kappa + M/EI, M(s) = int_s^L (X(u) - X(s)) f_y - (Y(u) - Y(s)) f_x du; fixed-point iteration
    from the unloaded arc (the loads here are a fraction of the bending stiffness: it contracts)."""
    sv = np.linspace(0.0, L, n + 1)
    K = np.asarray(kappa, float)[:, None]
    th = K * sv

    def rint(g: np.ndarray) -> np.ndarray:  # int_s^L g du on the grid
        c = cumulative_trapezoid(g, sv, axis=1, initial=0.0)
        return c[:, -1:] - c

    for _ in range(60):
        X = cumulative_trapezoid(np.cos(th), sv, axis=1, initial=0.0)
        Y = cumulative_trapezoid(np.sin(th), sv, axis=1, initial=0.0)
        fx, fy = load(th)
        M = rint(X * fy) - X * rint(fy) - rint(Y * fx) + Y * rint(fx)
        new = K * sv + cumulative_trapezoid(M / EI, sv, axis=1, initial=0.0)
        done = float(np.max(np.abs(new - th))) < 1e-12
        th = 0.5 * (th + new)
        if done:
            break
    return cumulative_trapezoid(np.sin(th), sv, axis=1, initial=0.0)[:, -1]


def _phi1(xi: float) -> float:
    """The first mode shape of a clamped-free beam at xi = x/L (beta1 L 1.87510, sigma1 0.734096)."""
    b, sg = 1.8751040687 * xi, 0.7340955137
    return math.cosh(b) - math.cos(b) - sg * (math.sinh(b) - math.sin(b))


# ------------------------------------------------------------------------------------------------ back relaxation


def br_streaming_current(s: Session) -> None:
    """The back-flow carries the counter-ions of its pores' double layers (the streaming current, the reverse of the
    electro-osmotic drag that made the bend), and the strip, held at its drive voltage by the amplifier, passes that
    current through the external circuit: the returning water is seen in the current as well as in the bend. The store x
    of water flowing back follows the bend d through a lag (tau 4-15 s, log) through the session in time order (carried
    over the rests), the reading d - K2 x (K2 0.8-1.2), and the current gains -phi K2 (Q/d) dx/dt, phi 0.03-0.1 the
    share of the forward charge per unit of bend (Q/d, from the first step record: its charge over the plateau, the leak
    taken off, over its bend) that the returning water carries back. The spectra see its small-signal part, an
    admittance Y (1 - phi K2/(1 + tau s)). Measured (paper_115): displacement RMS -68 % (residual 93 %, 5400x its
    noise); the 1 V steps peak at 2.54 mm 5.8 s after their edges (8.82 mm clean), 1.18 mm by the plateaus' ends, -0.95
    mm 2 s after the falls (+6.64 mm clean); the current's streaming part -0.058 mA 5 s into the steps, -0.028 mA by
    their plateaus' ends (0.47 mA clean), +0.032 mA 10 s after the falls: current residual 0.76 % of its RMS (0.57x its
    noise); the spectra's |Z| at 0.1 Hz +0.35 %."""
    k2, tau, phi = s.rng.uniform(0.8, 1.2), lu(s.rng, 4.0, 15.0), s.rng.uniform(0.03, 0.1)
    r0 = _first_step(s)
    q_per_d = 0.0
    if r0 is not None:
        v, i, d = r0.cols["v_V"], r0.cols["i_A"], r0.cols["disp_m"]
        e = _edges(v)
        on, off = int(e[0]), int(e[1]) if e.size > 1 else v.size
        leak = float(np.mean(i[max(off - 50, on) : off]))
        q_per_d = float(np.sum(i[on:off] - leak)) / r0.fs / max(abs(float(d[off - 1] - d[max(on - 1, 0)])), 1e-9)
    x = _store(s, tau)
    for r in s.series():
        d, xs = r.cols["disp_m"], x[id(r)]
        r.cols["i_A"] = r.cols["i_A"] - phi * k2 * q_per_d * (d - xs) / tau
        r.cols["disp_m"] = d - k2 * xs
    for r in s.recs:
        if not r.series:
            back = phi * k2 / (1 + 2j * np.pi * r.cols["f_Hz"] * tau)  # the admittance's streaming share
            z = (r.cols["z_re_ohm"] + 1j * r.cols["z_im_ohm"]) / (1 - back)
            r.cols["z_re_ohm"], r.cols["z_im_ohm"] = z.real.copy(), z.imag.copy()


def br_squeeze_swelling(s: Session) -> None:
    """Each tightening squeezes water out of the clamped root into the free part beside it (Nafion gives up water under
    a mechanical pressure of a MPa), whose extra free water flows back with the bend's and then equilibrates with the
    bath over tau_b 150-500 s (log): the back-flow's share K2 is raised right after each re-clamping, in proportion to
    the pressure added there, K2 = K0 (1 + sum_k a (dp_k/p_top) exp(-(t - t_k)/tau_b)) (K0 0.6-0.9, a 0.4-0.9, the
    squeeze 20-60 s before each block's first record), its lag tau 5-15 s (log) unchanged. Sample by sample through the
    session in time order (inject_fresh10._lag_varying); displacement only. Measured (p31_117): displacement RMS -58 %
    (residual 78 %, 4900x its noise); K0 0.80, the squeeze 54 s before each block, tau_b 467 s: the 1 V steps' peaks
    -60.5 % in the first block (612 kPa added), -62.2 to -62.3 % in the later ones (1225 kPa each), their plateaus' ends
    at 3.30 mm and 2.85-2.88 mm (9.40 mm clean), their records' ends -0.3 to -0.6 mm (+3.35 mm clean)."""
    k0, tau, a = s.rng.uniform(0.6, 0.9), lu(s.rng, 5.0, 15.0), s.rng.uniform(0.4, 0.9)
    tb, lead = lu(s.rng, 150.0, 500.0), s.rng.uniform(20.0, 60.0)
    p_top, prev, kicks = max(s.pressures()), 0.0, []
    for p, (t_first, _) in sorted(_blocks(s).items(), key=lambda kv: kv[1][0]):
        kicks.append((t_first - lead, a * max(p - prev, 0.0) / p_top))
        prev = p

    def state(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        t = np.asarray(t, float)
        boost = sum(b * np.exp(-np.clip(t - tk, 0, None) / tb) * (t >= tk) for tk, b in kicks)
        return k0 * (1 + boost), np.full(t.shape, tau)

    _lag_varying(s, state)


# ------------------------------------------------------------------------------------------------ faradaic current


def far_methanol_residue(s: Session) -> None:
    """Methanol left in the membrane from a methanol-water pretreatment (a usual way to swell Nafion before plating or
    soaking): the platinum oxidises it on whichever face is the anode, the faces' mixed potentials shifted by the drive,
    a current 2 sinh(v/2v_t) (v_t 0.08-0.14 V), 0.1-0.4 mA at 1 V (log) on a fresh surface at the session's start.
    Methanol poisons platinum with adsorbed CO, which the faces strip only above v_co 0.55-0.8 V (a step of width
    0.04-0.08 V, the coverage following its equilibrium with a lag of 1-5 s, log): the current is next to nothing at
    rest and on the 0.5 V sines, and grows through each held 1 V drive as the CO is stripped. The methanol leaves the
    strip (evaporating in air, leaching in water) as exp(-t/tau_e), tau_e 0.5-2 sessions (log). The analyser at 0 V bias
    sees a poisoned surface (spectra untouched): the current only. Measured (s001_116): current residual 2.9 % of its
    RMS (8.0x its noise); on the first 1 V step +0.015 mA 0.2 s after the edge, +0.066 mA at 1 s, +0.15 mA at 3 s, +0.25
    mA by the plateau's end (0.62 mA clean), on the later blocks' +0.22, +0.19, +0.17 mA; the 1 V harmonics' current
    +1.3 to +0.9 % block by block, the 0.5 V sines' +0.01 %."""
    i_m, vt = lu(s.rng, 1e-4, 4e-4), s.rng.uniform(0.08, 0.14)
    v_co, w_co, tau_co = s.rng.uniform(0.55, 0.8), s.rng.uniform(0.04, 0.08), lu(s.rng, 1.0, 5.0)
    tau_e = lu(s.rng, 0.5, 2.0) * (s.t1 - s.t0)
    eq = lambda v: 1 / (1 + math.exp((abs(v) - v_co) / w_co))  # noqa: E731  the CO coverage at equilibrium
    th0 = eq(0.0)
    theta = _walk(s, lambda th, v, dt: eq(v) + (th - eq(v)) * math.exp(-dt / tau_co), "v_V", th0,
                  lambda th, sec: th0 + (th - th0) * math.exp(-sec / tau_co))
    free1 = 1 - eq(1.0)
    for r in s.series():
        t, v = r.cols["t_s"], r.cols["v_V"]
        shape = np.sinh(v / (2 * vt)) / math.sinh(1 / (2 * vt))
        r.cols["i_A"] = r.cols["i_A"] + i_m * np.exp(-(t - s.t0) / tau_e) * shape * (1 - theta[id(r)]) / free1


def far_grounded_probe(s: Session) -> None:
    """A grounded metal probe in the bath (a thermostat's stainless sensor, a thermocouple's sheath, earthed through its
    instrument) with the strip driven single-ended (the current sensed in the drive line, the other face at ground): the
    driven face exchanges a faradaic current with the probe through the bath. With the face positive the probe is the
    cathode and reduces the bath's dissolved oxygen, a wave of half-wave potential 0.45-0.75 V and width 0.04-0.08 V,
    diffusion-limited at 0.1-0.4 mA (log) by the probe's area, in series with the bath between them (0.5-3 kOhm, log): i
    = i_lim (sigma((v - i R_b - E_h)/b) - sigma0)/(1 - sigma0), solved by bisection; with the face negative the passive
    steel gives 0.5-2 uA at most. One polarity only, saturating; the analyser floats (spectra untouched): the current
    only. Measured (p31_117): current residual 1.7 % of its RMS (1.3x its noise); the wave at 0.72 V, limited at 0.125
    mA, 590 Ohm of bath: +0.12 mA on the 1 V steps' plateaus (0.47-0.49 mA clean), nothing after their falls; the 1 V
    harmonics' current +0.7 %, the 0.5 V sines' +0.03 %."""
    i_lim, e_h, b = lu(s.rng, 1e-4, 4e-4), s.rng.uniform(0.45, 0.75), s.rng.uniform(0.04, 0.08)
    rb, i_p = lu(s.rng, 500.0, 3000.0), lu(s.rng, 5e-7, 2e-6)
    s0 = float(special.expit(-e_h / b))
    for r in s.series():
        v = r.cols["v_V"]
        lo, hi = np.full(v.size, -i_lim), np.full(v.size, i_lim)
        for _ in range(50):
            mid = 0.5 * (lo + hi)
            f = mid - i_lim * (special.expit((v - mid * rb - e_h) / b) - s0) / (1 - s0)
            lo, hi = np.where(f < 0, mid, lo), np.where(f < 0, hi, mid)
        r.cols["i_A"] = r.cols["i_A"] + 0.5 * (lo + hi) + i_p * np.expm1(np.minimum(v, 0.0) / 0.05)


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_contact_aging(s: Session) -> None:
    """The pinned cations' friction with the contacts' ageing (Dieterich's state law, the rate-and-state friction of
    rocks and of polymers in contact): a share h 0.2-0.35 of the drive moves the strip through a play whose radius grows
    with the contacts' age theta, r = r0 (1 + beta ln(1 + theta/theta_c)) (r0 0.05-0.12 V, beta 0.15-0.35, theta_c 0.5-3
    s, log); theta grows with the time stuck and is renewed by slip, theta exp(-slip/D_c) (D_c 0.005-0.02 V). After each
    rest the contacts are old and the play wide, during sustained motion young and narrow: the first cycle of each
    record and the fall after each held step lag more than the later cycles. Gamma = (1 - h) v + h z through the session
    in time order (the ages growing over the rests, the strip mounted 300-1800 s before), through the strip's measured
    step response (inject_fresh2._drive_side); current untouched. Measured (paper_115): displacement residual 3.6 % of
    its RMS (210x its noise); h 0.30, r0 0.059 V, beta 0.26: the 0.5 V sines' swing -1.6 % at 0.1 Hz and -2.0 % at 1.4
    Hz with 2.2 deg of lag, the 1 V harmonics' -0.5 % with 1.3 deg; the first 1 V step's peak -1.8 %, the later steps
    held back after their falls (+0.09 mm 2 s after, +0.31 mm at their records' ends); the 20 Hz records (5 um of
    signal) drift by 8-10x their swing as the play held since the record before is released."""
    h, r0, beta = s.rng.uniform(0.2, 0.35), s.rng.uniform(0.05, 0.12), s.rng.uniform(0.15, 0.35)
    th_c, dc, age0 = lu(s.rng, 0.5, 3.0), s.rng.uniform(0.005, 0.02), lu(s.rng, 300.0, 1800.0)
    t, _ = _series_cat(s, "v_V")
    dts = np.diff(t, prepend=t[0]).tolist()

    def gamma(v: np.ndarray) -> np.ndarray:
        z, age, out = 0.0, age0, np.empty(v.size)
        for k, (u, dt) in enumerate(zip(v.tolist(), dts)):
            age += dt
            rad = r0 * (1 + beta * math.log1p(age / th_c))
            zn = min(max(z, u - rad), u + rad)
            if zn != z:
                age *= math.exp(-abs(zn - z) / dc)  # slip renews the contacts
            z = out[k] = zn
        return (1 - h) * v + h * out

    _drive_side(s, gamma)


def hy_lead_hardening(s: Session) -> None:
    """A fine copper lead (30-60 um, annealed) glued along the strip's root to bring the drive onto the electrode past
    the jaws (a strip too short for contacts in the clamp, or jaws kept insulating): it bends with the root, yields at a
    small strain and work-hardens. As an elasto-plastic element in parallel with the strip (a share w 0.1-0.25 of the
    root's bending stiffness): the reading d - w (d - x), x following d through a play whose radius, the lead's yield in
    tip units (r0 0.1-0.3 of the session's largest bend), hardens with the accumulated plastic path p (Voce: r = r0 +
    (r_inf - r0)(1 - exp(-p/p_c)), r_inf 1.5-2.5 r0, p_c 0.5-2 largest bends): wide plastic loops early in the session,
    narrower later while the lead's elastic share stays. Sample by sample through the session in time order (the lead
    held over the rests); displacement only. Measured (s001_116): displacement residual 4.9 % of its RMS (160x its
    noise); w 0.15, r0 0.12 of the largest bend: the 0.5 V sines' swing -14.6 % (the lead elastic), the 1 V harmonic's
    -12.1 % with a 2.0 deg loop in the first block, -13.5 % and 1.2 deg in the last (the lead hardened); the 1 V steps'
    peaks -2.3 to -2.9 %, +0.11 to +0.14 mm left at their records' ends."""
    w, big = s.rng.uniform(0.1, 0.25), _largest(s)
    r0 = s.rng.uniform(0.1, 0.3) * big
    r_inf, pc = s.rng.uniform(1.5, 2.5) * r0, s.rng.uniform(0.5, 2.0) * big
    x, p = 0.0, 0.0
    for r in _chrono(s):
        d = r.cols["disp_m"]
        out = np.empty(d.size)
        for k, dk in enumerate(d.tolist()):
            rad = r_inf - (r_inf - r0) * math.exp(-p / pc)
            xn = min(max(x, dk - rad), dk + rad)
            p += abs(xn - x)
            x = out[k] = xn
        r.cols["disp_m"] = d - w * (d - out)


# ------------------------------------------------------------------------------------------------ time delay


def td_frame_stamps(s: Session) -> None:
    """Video tracking of the tip with a global-shutter camera (150-300 frames/s, log, free running): each frame's
    position is the tip's mean over its exposure (0.3-0.8 of the frame period), and the frame is stamped when the driver
    delivers it, after its readout (0.3-0.8 of a period) and 1-2 frames queued in the driver's buffer; the logger
    interpolates the frames linearly onto the DAQ's rows by those stamps. A delay of half the exposure + readout + queue
    (1.45-3.2 frame periods, 5-21 ms) with the exposure's and the interpolation's small droop (sinc and sinc^2 of
    f/f_frame). Each record with the tip held at its first value before it; displacement only. Measured (p31_117):
    displacement residual 0.20 % of its RMS (12.5x its noise); 294 frames/s, exposure and readout 0.41 of a frame each,
    2 frames queued (9.6 ms): a lag of 8.5 ms on the 0.1 Hz and 1.4 Hz sines, 8.9 ms at 20 Hz (-64 deg, gain 0.98,
    residuals 70-88 %); the steps' peaks -0.02 %."""
    fc = lu(s.rng, 150.0, 300.0)
    T = 1.0 / fc
    te, tr = s.rng.uniform(0.3, 0.8) * T, s.rng.uniform(0.3, 0.8) * T
    nq, ph = int(s.rng.integers(1, 3)), s.rng.uniform(0, T)
    lag = te + tr + nq * T

    def read(r: Rec, d: np.ndarray) -> np.ndarray:
        t = r.cols["t_s"]
        k0, k1 = math.floor((t[0] - lag - 2 * T - ph) / T), math.ceil((t[-1] - ph) / T)
        tk = ph + T * np.arange(k0, k1 + 1)  # the exposures' starts
        cum = np.r_[0.0, np.cumsum(0.5 * (d[1:] + d[:-1]) * np.diff(t))]

        def area(u: np.ndarray) -> np.ndarray:  # int d from t[0], d held at its ends beyond the record
            return np.where(u < t[0], d[0] * (u - t[0]),
                            np.where(u > t[-1], cum[-1] + d[-1] * (u - t[-1]), np.interp(u, t, cum)))

        return np.interp(t, tk + lag, (area(tk + te) - area(tk)) / te)

    map_disp(s, read)


def td_vfc_link(s: Session) -> None:
    """The laser's analogue output carried to the DAQ over an isolating voltage-to-frequency link (a V/F converter at
    the laser, a fibre or an opto-coupler, a period-counting F/V converter at the DAQ: a usual way to break a ground
    loop): the pulse rate is f_mid (1 + y/y_fs) over the laser's +-20 mm (f_mid 200-800 Hz, log), and the F/V converter
    outputs at each pulse the mean of the reading over the last period, held until the next. A delay of about one period
    that follows the reading itself: longer for the readings on the negative side (slower pulses), shorter on the
    positive, 1.3-5 ms at rest. Each record from its own first value held before it (the link's phase drawn per record);
    displacement only. Measured (s001_116): displacement residual 0.12 % of its RMS (4.0x its noise); f_mid 334 Hz (a
    period of 3.0 ms at rest, 2.4 ms at the 1 V steps' 4.7 mm): a lag of 2.6-2.8 ms on the sines below 2 Hz, 3.0 ms at
    20 Hz (-21 deg, gain 0.985, residuals 38 %)."""
    f_mid, y_fs = lu(s.rng, 200.0, 800.0), 0.02

    def read(r: Rec, d: np.ndarray) -> np.ndarray:
        t = r.cols["t_s"]
        pre = 3.0 / (f_mid * (1 + min(float(d[0]), 0.0) / y_fs))  # a few periods of rest before the record
        tt, dd = np.r_[t[0] - pre, t], np.r_[d[0], d]
        f = f_mid * (1 + np.clip(dd, -0.95 * y_fs, 0.95 * y_fs) / y_fs)
        phase = s.rng.uniform(0, 1) + np.r_[0.0, np.cumsum(0.5 * (f[1:] + f[:-1]) * np.diff(tt))]
        ks = np.arange(math.ceil(phase[0]), math.floor(phase[-1]) + 1)
        pulses = np.interp(ks, phase, tt)
        cum = np.r_[0.0, np.cumsum(0.5 * (dd[1:] + dd[:-1]) * np.diff(tt))]
        A = np.interp(pulses, tt, cum)
        vals = np.diff(A) / np.diff(pulses)  # the mean over each period, shown from its closing pulse
        j = np.searchsorted(pulses[1:], t, side="right") - 1
        return np.where(j >= 0, vals[np.clip(j, 0, vals.size - 1)], d[0])

    map_disp(s, read)


# ------------------------------------------------------------------------------------------------ sensor offset


def so_level_refraction(s: Session) -> None:
    """A laser head tilted 20-35 deg off the vertical (so that the bath's mirror reflection misses its receiver),
    looking down through the free surface of an open warm bath at a station x0 0.8-0.9 L (aimed inboard so that the spot
    stays on the strip as it draws back): refraction at the surface moves the beam's landing point along the strip by
    the water's depth above the strip times (tan theta - tan theta_w), and the bath evaporates (0.5-1.5 mm/h, log, from
    its filling 0-600 s before the first record), so the station walks along the strip through the session (outboard or
    inboard with the head's tilt, drawn). The strip read at the moving station (inject_fresh10._station); displacement
    only. Measured (paper_115): displacement RMS -34 % (residual 34 %, 2000x its noise); the head tilted 32.5 deg, aimed
    at 0.808 L, the bath losing 1.0 mm/h: the station walks out to 0.818 L by the session's end; the 0.1 Hz sines' gain
    0.666 in the first block, 0.677 in the last, 0.18-0.25 at 20 Hz; the 1 V steps' peaks -34.3 % to -33.1 % block by
    block."""
    L = float(s.specimen["length_m"])
    x0, th = s.rng.uniform(0.8, 0.9), math.radians(s.rng.uniform(20.0, 35.0))
    k = math.tan(th) - math.tan(math.asin(math.sin(th) / 1.333))
    rate, lead, side = lu(s.rng, 0.5, 1.5) / 3.6e6, s.rng.uniform(0.0, 600.0), _sign(s)
    frac = lambda t: x0 + side * k * rate * (np.asarray(t) - s.t0 + lead) / L  # noqa: E731
    fa = float(min(frac(s.t0), frac(s.t1)))
    _station(s, lambda r: frac(r.cols["t_s"]), fa)


def so_modal_scaling(s: Session) -> None:
    """The laser at an inboard station x_m 0.6-0.85 L (a head on a fixed post that cannot reach the tip, or a ragged tip
    end), its reading converted to the tip's by the first mode's shape ratio phi1(L)/phi1(x_m) of a clamped-free beam (a
    vibrometer user's habit: the ratio that holds at resonance), not by the static (x_m/L)^2: the conversion is right at
    f1, too high below it (the static bend is not the mode's shape) and wrong above, where the second mode reads
    differently inboard. Through the beam's own transfer functions (displacement_tf with sensor_x over the tip's) with
    the session's history (inject_fresh2._through); displacement only. Measured (p31_117): displacement RMS -20 %
    (residual 20 %, 1250x its noise); the station at 0.632 L, the ratio 1.99 (the static bend read at 0.80 of the
    tip's): the 0.1 Hz sines' gain 0.823, 1.11-1.26 at 4.4 Hz (near f1), 0.83-0.89 at 20 Hz with the phase turned by
    154-170 deg (residuals 120-150 %); the steps' peaks -19.7 %."""
    from labrig.physics import transfer

    xm = s.rng.uniform(0.6, 0.85)
    ratio = _phi1(1.0) / _phi1(xm)

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        sp = _spec(s, r)
        sa = sp.with_(sensor_x=xm * sp.geometry.length)

        def h(z: np.ndarray) -> np.ndarray:
            with np.errstate(divide="ignore", invalid="ignore"):
                q = transfer.displacement_tf(z, sa) / transfer.displacement_tf(z, sp)
            return ratio * np.where(np.isfinite(q), q, xm**2)

        return h

    out = _through(s, H, 10.0)
    map_disp(s, lambda r, d: out[id(r)])


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_hand_warmth(s: Session) -> None:
    """A hand-set screw clamp: at each re-clamping the operator holds the knob and its steel screw for the half minute
    the setting takes, warming the screw by a few kelvin, so the force is set on a lengthened screw; released (10-40 s
    before the block's first record) the screw cools (tau_c 100-400 s, log) and shortens, and the force rises by A(p) (1
    - exp(-u/tau_c)), beside the pads' slow relaxation (1 - c ln(1 + u/tau_p), c 0.3-0.8 %, tau_p 20-100 s, log), u the
    time since the release. The same contraction is a larger share of a light setting's compression: A = A_low
    (p_min/p)^n, A_low 4-10 %, n 0.6-1. Through the preset's clamp law (inject_fresh4._clamp_law). Measured (paper_115):
    A_low 8.4 %, tau_c 137 s: the load cell at 1.010 of the setting at the first block's first record, 1.070 at most
    (+0.69 N), 1.060 by its end; at most 1.025, 1.014 and 1.009 in the later blocks (+0.6-0.74 N each); displacement
    residual 0.010 % (0.58x its noise), current 0.15 % (0.12x), the top block's 20 Hz record's 1.4 %."""
    a_low, n = s.rng.uniform(0.04, 0.1), s.rng.uniform(0.6, 1.0)
    tau_c, lead = lu(s.rng, 100.0, 400.0), s.rng.uniform(10.0, 40.0)
    c, tau_p = s.rng.uniform(0.003, 0.008), lu(s.rng, 20.0, 100.0)
    p_min = min(s.pressures())

    def rel(t: np.ndarray, p: float, t_set: float) -> np.ndarray:
        u = np.clip(t - (t_set - lead), 0, None)
        return (1 + a_low * (p_min / p) ** n * -np.expm1(-u / tau_c)) * (1 - c * np.log1p(u / tau_p))

    _clamp_law(s, rel)


def cr_hydraulic_warmth(s: Session) -> None:
    """A small hydraulic clamp (a syringe-type cylinder set by a hand pump and closed by its valve) whose cylinder sits
    against the drive amplifier's heatsink: the amplifier dissipates roughly its rail voltage times the current it
    delivers, and the oil in the closed cylinder follows the heatsink's temperature (a lag of 300-900 s, log) and
    expands, raising the held force. The oil's pressure rise is the same at every setting, so the force's relative rise
    is b_low (p_min/p) at the session's hottest (b_low 4-10 %): a force that climbs through each block's fast sines (the
    largest currents) and sinks over the slow records after them. Through the preset's clamp law
    (inject_fresh4._clamp_law). Measured (s001_116): b_low 4.3 %, the oil's lag 620 s: the load cell up to 1.039 of its
    setting in the lowest block (+0.98 N on 25 N), 1.015, 1.0075 and 1.0046 in the later ones (+0.4-0.7 N), each rise
    through the block's fast sines; displacement residual 0.0033 % (0.11x its noise), current 0.060 % (0.17x)."""
    tau, b_low = lu(s.rng, 300.0, 900.0), s.rng.uniform(0.04, 0.1)
    tg = _session_grid(s, 1.0, 600.0)  # the amplifier idle before the first record
    t, i = _series_cat(s, "i_A")
    cell = np.clip(((t - tg[0]) // 1.0).astype(int), 0, tg.size - 1)
    n = np.bincount(cell, minlength=tg.size)
    power = np.bincount(cell, weights=np.abs(i), minlength=tg.size) / np.maximum(n, 1)  # mean |i| per second, 0 at rest
    heat = _lagged(tg, power, tau)
    heat = heat / max(float(np.max(heat)), 1e-30)
    p_min = min(s.pressures())
    _clamp_law(s, lambda tt, p, t_set: 1 + b_low * (p_min / p) * (np.interp(tt, tg, heat) - np.interp(t_set, tg, heat)))


# ------------------------------------------------------------------------------------------------ dehydration


def dh_crack_evaporation(s: Session) -> None:
    """A strip in air losing its water through its electrodes' mud cracks, which open on whichever face is in tension:
    the evaporation rate is a still part (through the closed film) plus a part growing with the bend, k0 + k1
    abs(d)/ref, so the strip dries most during the large records (the 1 V steps and harmonics) and slowly over the rests
    and the small sines. The loss at the session's end 8-20 % of the water, 50-80 % of it through the opened cracks; the
    gain as the water, the conductance as its 1.5-2.5th power (inject_fresh9._dry_by). Measured (s001_116): 11.5 % of
    the water lost, 67 % of it through the opened cracks: displacement RMS -5.0 % (residual 6.0 %, 190x its noise),
    current -15 % (46x); the 1 V steps' peaks -0.8, -3.6, -6.5, -9.5 % block by block, the current at their plateaus'
    ends -2, -9, -15, -22 %; the later spectra's |Z| +7.5, +16, +25 %."""
    total, crack, gc = s.rng.uniform(0.08, 0.2), s.rng.uniform(0.5, 0.8), s.rng.uniform(1.5, 2.5)
    ref = ref_disp(s)
    t, d = _series_cat(s, "disp_m")
    dt = np.diff(t, prepend=t[0])
    starts = np.cumsum([0] + [r.cols["t_s"].size for r in _chrono(s)])[:-1]
    dt[starts] = 0.0  # the rests: no opened cracks (the strip at rest)
    bent = np.cumsum(np.abs(d) / ref * dt)
    still = (t - s.t0) / (s.t1 - s.t0)
    share = total * ((1 - crack) * still + crack * bent / max(float(bent[-1]), 1e-30))
    loss = lambda tt: np.interp(tt, t, share)  # noqa: E731
    _dry_by(s, loss, lambda tt: 1 - (1 - loss(tt)) ** gc)


def dh_sun_patch(s: Session) -> None:
    """A strip in air on a bench by a window: the afternoon sun's patch crosses the bench, reaching the strip 15-45 %
    into the session and leaving it 20-40 % of the session later (its edge taking 5-10 min to pass, a raised cosine). In
    the sun the strip's surface is 3-8 K above the room, so its local humidity falls to exp(-0.06 dT) of the room's
    40-60 %, and its water follows the isotherm (inject_fresh10._lambda) through the sorption lag, drying 150-500 s
    (log) and re-wetting 1.5-3x more slowly once the sun has passed: a loss that begins inside the session, deepens
    while the sun is on the strip and is only partly made up by its end. The gain as the water, the conductance as its
    1.5-2.5th power (inject_fresh9._dry_by). Measured (s001_116): a room at 44 %, the strip 5.6 K warmer in the sun from
    32 % to 52 % into the session: displacement RMS -3.3 % (residual 5.9 %, 190x its noise), current -4.7 % (22x);
    nothing in the first block, the second block's 20 Hz record -10 % (the sun arriving), the third block's 1 V step
    -11.7 % (its current -21 %), the fourth's -1.9 % (-3.7 %); the third block's spectrum's |Z| +26 %, the fourth's +3.8
    %."""
    a_room, dtk = s.rng.uniform(0.4, 0.6), s.rng.uniform(3.0, 8.0)
    span = s.t1 - s.t0
    ta = s.t0 + s.rng.uniform(0.15, 0.45) * span
    tb, edge = ta + s.rng.uniform(0.2, 0.4) * span, s.rng.uniform(300.0, 600.0)
    tau_d, slow, gc = lu(s.rng, 150.0, 500.0), s.rng.uniform(1.5, 3.0), s.rng.uniform(1.5, 2.5)
    tg = _session_grid(s, 1.0, 600.0)
    sun = _ramp_env(tg, [(ta, tb)], edge)
    lam0 = float(_lambda(np.array([a_room]))[0])
    lam = _lagged(tg, _lambda(a_room * np.exp(-0.06 * dtk * sun)), tau_d, tau_d * slow)
    rel = lam / lam0
    _dry_by(s, lambda t: 1 - np.interp(t, tg, rel), lambda t: 1 - np.interp(t, tg, rel) ** gc)


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_thermal_mismatch(s: Session) -> None:
    """The bath warms through the session (a lamp, the amplifiers: 5-15 K, 1 - exp(-t/tau), tau 0.3-1 session, from its
    filling 0-600 s before), and the swollen polymer expands some ten times more than the platinum film on it: the films
    on both faces are stretched by the substrate, which pulls their plating cracks towards opening. Each face's
    resistance rises once its tension passes the cracks' closure, (e + tau_T(t) - c)+ for the face in tension (e the
    bend over the displacement scale, c 0.3-0.6), and the thermal pre-strain tau_T grows to 0.5-0.9 c: the dead zone of
    the crack gauge shrinks through the session, the same bend costing more late than early. Gains fall by 0.01-0.03
    (displacement) and 0.03-0.08 (current) per unit (inject_fresh3._resist). Measured (paper_115): displacement RMS -6.3
    % (residual 6.6 %, 390x its noise), current residual 3.4 % (2.6x); closure 0.38 of the scale, the pre-strain
    reaching 0.67 of it: the 1 V steps' peaks -8.8, -9.0, -9.1, -9.2 % block by block, the current at their plateaus'
    ends -19 %; the 1 V harmonics' swing -1.1 % in the first block, -3.3 to -3.5 % in the later ones; the 0.5 V sines'
    -0.25 % to -0.6 %."""
    c, f_end = s.rng.uniform(0.3, 0.6), s.rng.uniform(0.5, 0.9)
    tau, lead = s.rng.uniform(0.3, 1.0) * (s.t1 - s.t0), s.rng.uniform(0.0, 600.0)
    warm = lambda t: -np.expm1(-(np.asarray(t) - s.t0 + lead) / tau)  # noqa: E731
    norm = float(warm(s.t1))

    def shape(r: Rec, e: np.ndarray) -> np.ndarray:
        pre = c * f_end * warm(r.cols["t_s"]) / norm
        return np.clip(e + pre - c, 0, None) + np.clip(-e + pre - c, 0, None)

    _resist(s, shape, (0.01, 0.03), (0.03, 0.08))


def sr_rate_cracking(s: Session) -> None:
    """The plated film cracks under fast straining and not under slow: strained slowly, the soft polymer under it
    relaxes the film's stress and the cracks do not grow; strained fast (faster than r_c 0.5-1.5 displacement scales per
    second) the film is loaded before the substrate can give and new cracks run. Each face's gauge g = g0 + D (g0
    0.1-0.3 the fresh film's) grows by the tensile increments made faster than r_c, D normalised to 0.5-1.5 by the
    session's end: the steps' edges and the resonant sines crack the film, the slow sines and harmonics do not, and the
    resistance change (g e+ per face) grows through the session in jumps at the fast records. Gains fall by 0.015-0.04
    (displacement) and 0.04-0.1 (current) per unit of g e+ (inject_fresh3._resist). Measured (p31_117): displacement RMS
    -4.8 % (residual 5.8 %, 370x its noise), current residual 4.1 % (3.1x); r_c 1.2 scales/s: the 1 V steps' peaks -1.7,
    -4.9, -8.3, -12.2 % block by block (the gauge grown by the earlier edges and resonant sines), the current at their
    plateaus' ends -5 to -37 %; the 1 V harmonics' swing -0.8, -2.4, -4.1, -3.0 %."""
    g0, rc, d_end = s.rng.uniform(0.1, 0.3), s.rng.uniform(0.5, 1.5), s.rng.uniform(0.5, 1.5)
    ref = ref_disp(s)
    recs = _chrono(s)
    inc = {}
    for r in recs:
        e = r.cols["disp_m"] / ref
        de = np.diff(e, prepend=e[0])
        inc[id(r)] = [np.clip(sg * de, 0, None) * (sg * de * r.fs > rc) * (sg * e > 0) for sg in (1.0, -1.0)]
    tot = [sum(float(np.sum(inc[id(r)][k])) for r in recs) for k in (0, 1)]
    scale = d_end / max(max(tot), 1e-30)
    gain, acc = {}, [0.0, 0.0]
    for r in recs:
        g = []
        for k in (0, 1):
            c = acc[k] + scale * np.cumsum(inc[id(r)][k])
            acc[k] = float(c[-1])
            g.append(g0 + c)
        gain[id(r)] = g
    _resist(s, lambda r, e: gain[id(r)][0] * np.clip(e, 0, None) + gain[id(r)][1] * np.clip(-e, 0, None),
            (0.015, 0.04), (0.04, 0.1))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_perfusion_drag(s: Session) -> None:
    """The strip in a flow cell perfused by a circulating thermostat, the stream running along the strip from its root
    to its tip (3-8 cm/s, log): straight, the strip meets the flow edge-on and feels next to nothing, but bent, each
    element stands at its angle theta to the stream and takes the cross-flow drag of its normal velocity, 1/2 rho C_D b
    (U sin theta)^2 (C_D 1.8-2.2, the flat plate's), pushing it back towards the stream: a restoring load that grows as
    the angle squared, nothing for small bends. The tip's height on the exact elastica under the actuation's uniform
    eigen-curvature and that load (quasi-static; the preset's E and the manifest's width and thickness), mapped from the
    linear reading; displacement only. Measured (p31_117): 5.0 cm/s, C_D 1.92: displacement RMS -3.1 % (residual 3.3 %,
    210x its noise); the 1 V steps' peaks -4.9 % (the arc alone -3.0 %), the 1 V harmonics' crests -1.9 % (their troughs
    -0.04 %), the 0.5 V sines' -0.1 %."""
    u, cd = lu(s.rng, 0.03, 0.08), s.rng.uniform(1.8, 2.2)
    from labrig.physics import presets

    sp = presets.get(s.preset).specimen()
    b, h, L = (float(s.specimen[k]) for k in ("width_m", "thickness_m", "length_m"))
    EI = sp.mechanics.E * b * h**3 / 12
    c = 0.5 * 1000.0 * cd * b * u**2
    dmax = 1.05 * _largest(s)
    kap = np.linspace(-1.0, 1.0, 161) * 2 * dmax / L**2

    def load(th: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        q = c * np.sin(th) * np.abs(np.sin(th))
        return q * np.sin(th), -q * np.cos(th)

    y = _elastica(L, EI, kap, load)
    map_disp(s, lambda r, d: np.interp(d, kap * L**2 / 2, y))


def ld_reflective_pair(s: Session) -> None:
    """No laser: the tip read by a push-pull pair of reflective optical sensors (a collimated LED and a lensed
    photodiode each, one facing each face of the strip at g0 3-5 times the session's largest bend, log), the lab's
    software taking the ratio (I1 - I2)/(I1 + I2) to cancel the LEDs' drift and the surface's reflectance, calibrated by
    its slope at rest. Each return falls as the gap to the power n 1.8-2.2 (the spot filling the strip, the photodiode's
    solid angle), so the ratio is tanh(n atanh(y/g0)) and the reading (g0/n) of it: odd, compressed at the large bends;
    the pair mounted 0-5 % off centre adds a small even part, its rest value zeroed. Displacement only. Measured
    (paper_115): g0 3.6 times the largest bend, n 2.05: displacement RMS -4.5 % (residual 5.1 %, 300x its noise); the 1
    V steps' peaks -7.9 %, the 1 V harmonics' crests -0.9 % and troughs -0.2 %, the 0.5 V sines' -0.03 %."""
    g0, n, off = lu(s.rng, 3.0, 5.0) * _largest(s), s.rng.uniform(1.8, 2.2), s.rng.uniform(-0.05, 0.05)

    def ratio(y: np.ndarray) -> np.ndarray:
        a, b = (g0 * (1 - off) - y) ** -n, (g0 * (1 + off) + y) ** -n
        return (a - b) / (a + b)

    slope = float((ratio(np.array([1e-3 * g0])) - ratio(np.array([-1e-3 * g0])))[0]) / (2e-3 * g0)
    zero = float(ratio(np.array([0.0]))[0])
    map_disp(s, lambda r, d: (ratio(d) - zero) / slope)


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_aquarium_pump(s: Session) -> None:
    """An aquarium air pump bubbling the bath (to keep it mixed and aerated): an electromagnetic diaphragm pump whose
    armature is a magnet driven by a coil on the mains, so it vibrates at the line frequency (50 or 60 Hz) with a 2nd
    harmonic from its pull's asymmetry (0.2-0.6 of it) and a 3rd (0.05-0.2); standing on the bench, it shakes the
    laser's stand against the strip's clamp, 1-4 um (log) at the line in the reading, phase locked to the mains.
    Mechanical: the displacement only. Measured (paper_115): 2.7 um at 50 Hz, 1.4 um at 100 Hz, 0.37 um at 150 Hz;
    displacement residual 0.065 % of its RMS (3.8x its noise)."""
    f0, a = _line_f(s), lu(s.rng, 1e-6, 4e-6)
    h2, h3, ph = s.rng.uniform(0.2, 0.6), s.rng.uniform(0.05, 0.2), s.rng.uniform(0, 2 * np.pi)
    map_disp(s, lambda r, d: d + a * _hum(r.cols["t_s"], f0, {2: h2, 3: h3}, ph))


def mp_cable_routing(s: Session) -> None:
    """Hum whose coupling the operator changes at each re-clamping: the current amplifier's input leads and the laser's
    cable run past the clamp, and handling it moves them, so the loops they form with the building's wiring change area
    and orientation block by block: the hum (the line at 50 or 60 Hz with the wiring's 3rd, 0.2-0.5, and 5th, 0.05-0.2)
    has a new amplitude and phase in each pressure block, 5-30 uA on the current and 0.5-3 um on the displacement (log,
    independently). Measured (p31_117): the current's hum at 50 Hz 7.0, 7.1, 7.2, 5.1 uA block by block (with new
    phases), the displacement's 1.24, 0.81, 1.03, 0.57 um; current residual 0.16 % of its RMS (0.12x its noise),
    displacement 0.020 % (1.3x)."""
    f0, h3, h5 = _line_f(s), s.rng.uniform(0.2, 0.5), s.rng.uniform(0.05, 0.2)
    blocks = _blocks(s)
    per_block = {p: (lu(s.rng, 5e-6, 3e-5), s.rng.uniform(0, 2 * np.pi), lu(s.rng, 5e-7, 3e-6),
                     s.rng.uniform(0, 2 * np.pi)) for p in sorted(blocks, key=lambda q: blocks[q][0])}
    for r in s.series():
        ai, pi_, ad, pd = per_block[float(r.entry["pressure_kPa"])]
        t = r.cols["t_s"]
        r.cols["i_A"] = r.cols["i_A"] + ai * _hum(t, f0, {3: h3, 5: h5}, pi_)
        r.cols["disp_m"] = r.cols["disp_m"] + ad * _hum(t, f0, {3: h3, 5: h5}, pd)


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_dropped_sign(s: Session) -> None:
    """The laser's readings reach the logger as text (the controller's ASCII output, "+01.2345" / "-01.2345" in mm) and
    the logger's parser takes the number with a pattern written for its digits ([0-9.]+): the minus sign is dropped and
    every negative reading is logged as its magnitude. The displacement is abs(d): the steps (positive) as they were,
    every swing below zero folded up, and the noise at rest rectified. Displacement only. Measured: (paper_115) 24 % of
    the samples below zero, the 1 V harmonics' troughs (-1.79 mm) folded up: displacement residual 15 % of its RMS (860x
    its noise); (s001_116) 27 %, 14 % (450x)."""
    map_disp(s, lambda r, d: np.abs(d))


def out_relay_click(s: Session) -> None:
    """A signal relay (the multiplexer routing the strip to the DAQ's drive or to the impedance analyser) switched by
    the logger at each record's arming, 5-30 ms after its first sample: the armature's impact knocks the bench, and the
    laser's stand rings against the clamp at its own resonance (65-85 Hz, Q 8-20), 8-30 um (log, the same sign at every
    click, +-20 % from click to click), decaying over 30-100 ms. A transient at the start of every record, unrelated to
    the drive; displacement only. Measured: (paper_115) 80.7 Hz, Q 8.3, -9.7 um: 5-10.5 um as sampled, 3.7-6.2x the
    noise over the first 100 ms of each record, 0.39x over all; (p31_117) 74.1 Hz, Q 19, -15.5 um: 11-18 um, 9-14x over
    the first 100 ms, 1.0x over all."""
    fr, q, a = s.rng.uniform(65.0, 85.0), s.rng.uniform(8.0, 20.0), lu(s.rng, 8e-6, 3e-5) * _sign(s)
    wn = 2 * np.pi * fr
    zeta = 1 / (2 * q)
    wd = wn * math.sqrt(1 - zeta**2)
    for r in s.series():
        t = r.cols["t_s"] - r.cols["t_s"][0] - s.rng.uniform(0.005, 0.03)
        amp = a * s.rng.uniform(0.8, 1.2)
        tp = np.clip(t, 0, None)
        r.cols["disp_m"] = r.cols["disp_m"] + (t >= 0) * amp * np.exp(-zeta * wn * tp) * np.sin(wd * tp)


def out_thermal_cutout(s: Session) -> None:
    """The drive amplifier (a power op-amp on too small a heatsink) trips its thermal shutdown: its die heats with its
    dissipation (its rails' 12 V less the output, times the current) through a thermal lag of 3-10 s (log) and at a
    threshold (0.8-0.92 of the session's hottest) the output stage switches off until the die has cooled by 5-15 %; the
    DAQ logs the drive it commands (v_V), so the recorded drive runs on while the strip, open-circuited, holds the
    voltage it had and passes next to no current, then is driven back to the command at the restore. The held voltage
    enters the current and the displacement through the strip's measured step responses (inject_fresh7._superpose); v_V
    untouched. Cut-outs of 0.1-2 s in the records of largest current. Measured: (s001_116) tau 3.8 s, the trip at 0.90
    of the hottest: cut-outs over the last 0.14-0.64 s of every block's 9.4-20 Hz records and for 0.9 s in two 1 V
    harmonics; current residual 25 % of its RMS (69x its noise), displacement 1.0 % (32x), up to 0.3 mm held; (p31_117)
    1.5 s in each block's 1 V harmonic: current 2.0 % (1.5x), displacement 0.47 % (30x), up to 0.49 mm."""
    tau, q, hys = lu(s.rng, 3.0, 10.0), s.rng.uniform(0.9, 0.97), s.rng.uniform(0.1, 0.25)
    recs = _chrono(s)

    def heat(cut: bool) -> tuple[float, dict[int, np.ndarray]]:
        T, t_end, top, mask, off = 0.0, None, 0.0, {}, False
        for r in recs:
            t, v, i = r.cols["t_s"], r.cols["v_V"], r.cols["i_A"]
            if t_end is not None:
                T *= math.exp(-max(float(t[0]) - t_end, 0.0) / tau)  # cooling over the rest (still off, if it was)
            a = math.exp(-1.0 / (r.fs * tau))
            pw = ((12.0 - np.abs(v)) * np.abs(i)).tolist()
            m = np.zeros(t.size, bool)
            for k, p in enumerate(pw):
                if cut and not off and T > trip:
                    off = True
                elif cut and off and T < trip * (1 - hys):
                    off = False
                T = T * a + (1 - a) * (0.0 if off else p)
                top, m[k] = max(top, T), off
            mask[id(r)], t_end = m, float(t[-1])
        return top, mask

    trip = 0.0
    top, _ = heat(False)
    trip = q * top
    _, mask = heat(True)
    e = {}
    for r in s.series():
        v, m = r.cols["v_V"], mask[id(r)]
        hold = v.copy()
        starts = np.flatnonzero(m & ~np.r_[False, m[:-1]])
        for k in starts:
            end = k + int(np.argmax(~m[k:])) if np.any(~m[k:]) else v.size
            hold[k:end] = v[k - 1] if k > 0 else v[0]
        e[id(r)] = np.where(m, hold - v, 0.0)
    _superpose(s, e)


def out_two_wire_eis(s: Session) -> None:
    """The impedance analyser wired two-terminal: its four terminals (HCUR/HPOT and LPOT/LCUR) joined at the instrument
    and two leads run to the clamp, so the spectra include the leads' and the contacts' resistance (0.8-3 Ohm, log) and
    the leads' inductance (0.5-2 uH, log) in series, which the DAQ's time series (driven and monitored at the strip) do
    not: the spectra's high-frequency end sits above the strip's series resistance the steps' edges show. Spectra only.
    Measured: (paper_115) 1.87 Ohm and 0.77 uH: |Z| +6.6 % at 10 kHz, +0.6 % at 0.1 Hz; (p31_117) 1.83 Ohm and 1.78 uH:
    +6.4 % and +0.65 %."""
    rl, ll = lu(s.rng, 0.8, 3.0), lu(s.rng, 5e-7, 2e-6)
    for r in s.recs:
        if not r.series:
            r.cols["z_re_ohm"] = r.cols["z_re_ohm"] + rl
            r.cols["z_im_ohm"] = r.cols["z_im_ohm"] + 2 * np.pi * r.cols["f_Hz"] * ll


FRESH15_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"streaming_current": br_streaming_current, "squeeze_swelling": br_squeeze_swelling},
    "faradaic_current": {"methanol_residue": far_methanol_residue, "grounded_probe": far_grounded_probe},
    "hysteresis": {"contact_aging": hy_contact_aging, "lead_hardening": hy_lead_hardening},
    "time_delay": {"frame_stamps": td_frame_stamps, "vfc_link": td_vfc_link},
    "sensor_offset": {"level_refraction": so_level_refraction, "modal_scaling": so_modal_scaling},
    "clamp_relaxation": {"hand_warmth": cr_hand_warmth, "hydraulic_warmth": cr_hydraulic_warmth},
    "dehydration": {"crack_evaporation": dh_crack_evaporation, "sun_patch": dh_sun_patch},
    "strain_resistance": {"thermal_mismatch": sr_thermal_mismatch, "rate_cracking": sr_rate_cracking},
    "large_deflection": {"perfusion_drag": ld_perfusion_drag, "reflective_pair": ld_reflective_pair},
    "mains_pickup": {"aquarium_pump": mp_aquarium_pump, "cable_routing": mp_cable_routing},
    "unexplained": {"dropped_sign": out_dropped_sign, "relay_click": out_relay_click,
                    "thermal_cutout": out_thermal_cutout, "two_wire_eis": out_two_wire_eis},
}
inject.register_forms(FRESH15_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def v_log_steps(s: Session) -> None:
    """A logger with a logarithmic time base on the step records (a potentiostat's chronoamperometry "log sampling",
    or a datalogger's creep-test schedule): the samples before the rise, and for the first 0.5-2 s (log) after each
    change of the drive (the rise and the fall), at the full rate; beyond, one row per interval growing in proportion
    to the time since that change (30-60 rows a decade), each the mean of the samples it stands for (an averaging
    converter) stamped at their mean time, never straddling a change. The sines, the spectra and the manifest as they
    were, the session clock kept. ``labrig import`` takes it (t_s strictly increasing, unevenly spaced)."""
    t_full, per_dec = lu(s.rng, 0.5, 2.0), int(s.rng.integers(30, 61))
    grow = math.log(10) / per_dec
    for r in s.series():
        e = _edges(r.cols["v_V"]) if r.kind == "step" else np.zeros(0, int)
        if not e.size:
            continue
        n, fs = r.cols["t_s"].size, r.fs
        starts = list(range(int(e[0])))  # each row before the rise its own
        for a, b in zip(e.tolist(), np.r_[e[1:], n].tolist()):
            j = min(a + int(round(t_full * fs)), b)
            starts += list(range(a, j))  # the full rate just after the change
            while j < b:  # then intervals growing with the time since it, never past the next change
                starts.append(j)
                j = min(j + max(1, int(round(grow * (j - a)))), b)
        st = np.array(starts)
        size = np.diff(np.r_[st, n])
        r.cols = {k: np.add.reduceat(x, st) / size for k, x in r.cols.items()}


inject.VARIANTS.update({"log_steps": v_log_steps})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_115", "s001_116", "p31_117"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 6 / 7 effect cases on seeds 115-117
    "back_relaxation": [("streaming_current", 115, P, "log_steps"), ("squeeze_swelling", 117, T, "asrun")],
    "faradaic_current": [("methanol_residue", 116, S, "rate07"), ("grounded_probe", 117, T, "eis_descending")],
    "hysteresis": [("contact_aging", 115, P, "tared_records"), ("lead_hardening", 116, S, "settled_sines")],
    "time_delay": [("frame_stamps", 117, T, "dropped_packets"), ("vfc_link", 116, S, "float32_time")],
    "sensor_offset": [("level_refraction", 115, P, "shortened_shuffled"), ("modal_scaling", 117, T, "coherent_sines")],
    "clamp_relaxation": [("hand_warmth", 115, P, "merged_loadcell"), ("hydraulic_warmth", 116, S, "asrun")],
    "dehydration": [("crack_evaporation", 116, S, "host_timed"), ("sun_patch", 116, S, "log_steps")],
    "strain_resistance": [("thermal_mismatch", 115, P, "steps_sines"), ("rate_cracking", 117, T, "two_pressures")],
    "large_deflection": [("perfusion_drag", 117, T, "short_pretrigger"), ("reflective_pair", 115, P, "resampled")],
    "mains_pickup": [("aquarium_pump", 115, P, "asrun"), ("cable_routing", 117, T, "trigger_clock")],
    "unexplained": [("dropped_sign", 115, P, "log_steps"), ("dropped_sign", 116, S, "asrun"),
                    ("relay_click", 115, P, "own_clock"), ("relay_click", 117, T, "asrun"),
                    ("thermal_cutout", 116, S, "decimated3"), ("thermal_cutout", 117, T, "asrun"),
                    ("two_wire_eis", 115, P, "asrun"), ("two_wire_eis", 117, T, "no_loadcell")],
}
CLEAN = [(115, P, "asrun"), (115, P, "log_steps"), (116, S, "asrun"), (116, S, "no_spectra"),
         (117, T, "asrun"), (117, T, "log_steps")]


def fresh15_cases(only: str | None = None) -> list[Case]:
    """The sixteenth held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds 115-117).
    """
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh15_cases, "inject_fresh15", "fresh15")
