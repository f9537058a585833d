"""A third held-out set for the diagnosis (issue 12), written without sight of the diagnosis' model families.

Two forms per catalogue effect, each from the physics of the effect's cause and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS) and of the simulated bench (mock_devices/effects.py); three
structures outside the catalogue (truth "unexplained"); clean sessions. All on three bases of new seeds (41-43:
the paper strip, the seed-001 strip on its own sweep, the paper strip 40 mm free) and on protocol / data-shape
variants, two of them new here: the time series block-averaged by 3 (another DAQ's rate), and every CSV on its own
clock from 0 (no shared session clock, as many labs export).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); its tools are reused, and the
forms, bases and variants of this set are registered into inject's lookups at import.

Run: python bench/inject_fresh2.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME]
(the diagnosis of these cases: bench/diagnose.py --set fresh2)
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np

import inject
from inject import Case, Rec, Session, _clamp, _dry, _strain, lti, lu, map_disp, play, ref_disp

inject.BASES.update({
    "paper_41": ("paper-sweep", "paper", 41),
    "s001_42": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 42),
    "long_43": ("paper-sweep", "paper_long", 43),
})


def _chrono(s: Session) -> list[Rec]:
    return sorted(s.series(), key=lambda r: float(r.cols["t_s"][0]))


def _through(s: Session, H: Callable[[Rec], Callable[[np.ndarray], np.ndarray]], memory_s: float) -> dict[int, np.ndarray]:
    """Each record's displacement through the linear operator H(r)(s), with the session's history: the record is
    preceded by memory_s of what was measured before it (the records before it in time, linear across the rests
    between them, zero before the session), so a record that starts on a still-bent strip carries no false
    transient; and followed by its own last value held (a ratio of the beam's transfer functions is not strictly
    causal: the padding's drop to zero would leak back into the record's last samples). Returns the new columns."""
    recs = _chrono(s)
    T = np.concatenate([r.cols["t_s"] for r in recs])
    D = np.concatenate([r.cols["disp_m"] for r in recs])
    out = {}
    for r in recs:
        d, n, k = r.cols["disp_m"], r.cols["disp_m"].size, int(memory_s * r.fs)
        past = np.interp(r.cols["t_s"][0] - np.arange(k, 0, -1) / r.fs, T, D, left=0.0)
        out[id(r)] = lti(np.r_[past, d, np.full(n, d[-1])], r.fs, H(r))[k : k + n]
    return out


def _map_through(s: Session, H: Callable[[Rec], Callable[[np.ndarray], np.ndarray]], memory_s: float) -> None:
    new = _through(s, H, memory_s)
    map_disp(s, lambda r, d: new[id(r)])


def _spec(s: Session, r: Rec):
    from labrig.physics import presets

    return presets.get(s.preset).specimen(float(r.entry["pressure_kPa"]))


# ------------------------------------------------------------------------------------------------ back relaxation


def br_havriliak_negami(s: Session) -> None:
    """Back-diffusion of water with an asymmetric spread of diffusion times (a polydisperse cluster network): the
    opposing flux follows the bending through a Havriliak-Negami kernel 1/(1 + (tau s)^a)^b, a 0.6-0.9, b 0.4-0.7
    (Cole-Cole is b = 1, Cole-Davidson a = 1). K2 0.7-1.1 (its broad fast tail gives back more than a
    single lag of the same K2), tau 3-15 s (log)."""
    k2, tau, a, b = s.rng.uniform(0.7, 1.1), lu(s.rng, 3.0, 15.0), s.rng.uniform(0.6, 0.9), s.rng.uniform(0.4, 0.7)
    _map_through(s, lambda r: lambda z: 1 - k2 / (1 + (tau * z + 0j) ** a) ** b, 120.0)


def br_two_stage(s: Session) -> None:
    """Back relaxation that needs a pressure gradient to build first: the cathode side swells, its pore pressure
    rises (first lag), and only then does water flow back (second lag). Two first-order stages in series, kernel
    1/(tau s + 1)^2 (a gamma-shaped t exp(-t/tau) response): the strip holds its peak longer, then relaxes and, with
    K2 1.0-1.4, overshoots past zero. tau 2-8 s (log)."""
    k2, tau = s.rng.uniform(1.0, 1.4), lu(s.rng, 2.0, 8.0)
    _map_through(s, lambda r: lambda z: 1 - k2 / (tau * z + 1) ** 2, min(12 * tau, 120.0))


# ------------------------------------------------------------------------------------------------ faradaic current


def _add_current(s: Session, law: Callable[[Rec], np.ndarray]) -> None:
    for r in s.series():
        r.cols["i_A"] = r.cols["i_A"] + law(r)


def far_her_onset(s: Session) -> None:
    """Hydrogen evolution on one electrode only (one polarity): nothing below an onset V_on 0.3-0.6 V, then a
    current limited by the solution and electrode resistance, a soft onset of width v_w 30-80 mV:
    i = G v_w ln(1 + exp((+-v - V_on)/v_w)). Scaled to 0.15-0.6 mA at 1 V (log)."""
    von, vw, sign = s.rng.uniform(0.3, 0.6), s.rng.uniform(0.03, 0.08), (1.0 if s.rng.random() < 0.5 else -1.0)
    soft = lambda x: vw * np.logaddexp(0.0, (sign * x - von) / vw)  # noqa: E731
    g = lu(s.rng, 1.5e-4, 6e-4) / soft(np.array([sign]))[0]
    _add_current(s, lambda r: sign * g * soft(r.cols["v_V"]))


def far_adsorption(s: Session) -> None:
    """Hydrogen adsorption on Pt (a Langmuir pseudocapacitance) beside the evolution current it precedes: a
    charge-transfer current C_ad(V) dV/dt, C_ad a sech^2 peak (Langmuir isotherm, width v_t 40-80 mV) centred at
    E0 0.3-0.6 V on one polarity, plus the evolution's exponential tail exp((|V| - 1 V)/v_e), v_e 0.12-0.25 V, on
    that side; both at the interface's potential, the terminal voltage through the double layer's charging lag
    (20-100 ms, log).
    The steady part scaled to 0.1-0.5 mA at 1 V (log); the adsorbed charge gives a peak of 0.3-1 times that."""
    e0, vt, ve = s.rng.uniform(0.3, 0.6), s.rng.uniform(0.04, 0.08), s.rng.uniform(0.12, 0.25)
    sign = 1.0 if s.rng.random() < 0.5 else -1.0
    i1, tau_i = lu(s.rng, 1e-4, 5e-4), lu(s.rng, 0.02, 0.1)
    q_ad = s.rng.uniform(0.3, 1.0) * i1 * 4 * vt / (2 * np.pi * 0.1 * 1.0)  # peak ~ (0.3-1) i1 on the 1 V / 0.1 Hz sine

    def law(r: Rec) -> np.ndarray:
        v = sign * lti(r.cols["v_V"], r.fs, lambda z: 1 / (1 + tau_i * z))  # the interface's own potential
        steady = i1 * np.exp((v - 1.0) / ve) * (v > 0)
        c_ad = q_ad / (4 * vt) / np.cosh((v - e0) / (2 * vt)) ** 2
        return sign * (steady + c_ad * np.gradient(v, r.cols["t_s"]))

    _add_current(s, law)


# ------------------------------------------------------------------------------------------------ hysteresis


def _step_response(r: Rec) -> tuple[np.ndarray, np.ndarray]:
    """A step record's measured unit-step response: the displacement from the drive's rise to its fall, per volt."""
    v, d, t = r.cols["v_V"], r.cols["disp_m"], r.cols["t_s"]
    amp = float(v[np.argmax(np.abs(v))])
    on = int(np.argmax(v / amp > 0.5))
    off = on + int(np.argmax(v[on:] / amp < 0.5)) or v.size
    off = off if off > on else v.size
    return t[on:off] - t[on], (d[on:off] - d[max(on - 1, 0)]) / amp


def _drive_side(s: Session, gamma: Callable[[np.ndarray], np.ndarray]) -> None:
    """Hysteresis of the electromechanical coupling: the strip bends from Gamma[V] instead of V, the current and
    the recorded (commanded) voltage untouched. The operator runs over the whole session in time order (its memory
    carries between records); the change of Gamma[V] - V within each record reaches the displacement through the
    strip's own linear response, its measured unit-step response at that pressure (superposition of steps: the
    response to e is the sum over samples of de_j S(t - t_j)). The part of Gamma - V already there at a record's
    start is taken as settled into the rest the record starts from."""
    recs = _chrono(s)
    v = np.concatenate([r.cols["v_V"] for r in recs])
    extra = np.split(gamma(v) - v, np.cumsum([r.cols["v_V"].size for r in recs])[:-1])
    steps = {float(r.entry["pressure_kPa"]): _step_response(r) for r in reversed(recs) if r.kind == "step"}  # the first step of each pressure
    for r, e in zip(recs, extra):
        if float(r.entry["pressure_kPa"]) not in steps:
            continue
        ts, S = steps[float(r.entry["pressure_kPa"])]
        n = e.size
        m = 1 << int(math.ceil(math.log2(2 * n)))
        kern = np.interp(np.arange(n) / r.fs, ts, S)  # held at its last value beyond the step's length
        de = np.diff(e - e[0], prepend=0.0)
        r.cols["disp_m"] = r.cols["disp_m"] + np.fft.irfft(np.fft.rfft(de, m) * np.fft.rfft(kern, m), m)[:n]


def hy_preisach_drive(s: Session) -> None:
    """A Preisach model of the coupling (relay hysterons switching up at alpha, down at beta < alpha) with a
    Gaussian density over coercivity (alpha - beta)/2 ~ 0.15-0.35 V and a bias field (alpha + beta)/2 centred
    off zero by 0.05-0.15 V: unequal weights, loops not symmetric, a remanent bend. Weight h 0.1-0.25 of the drive
    (most relays outlast a return to 0 V, so a small h already gives a loop 8-15 % of its span wide at 0 V on a
    1 V sine, the 5-20 % reported for IPMC V-delta loops)."""
    h, hc, sc = s.rng.uniform(0.1, 0.25), s.rng.uniform(0.15, 0.35), s.rng.uniform(0.08, 0.15)
    hb, sb = s.rng.uniform(0.05, 0.15) * (1 if s.rng.random() < 0.5 else -1), s.rng.uniform(0.2, 0.4)

    def gamma(v: np.ndarray) -> np.ndarray:
        vmax = float(np.max(np.abs(v))) or 1.0
        grid = np.linspace(-vmax, vmax, 14)
        al, be = np.meshgrid(grid, grid, indexing="ij")
        keep = al > be
        al, be = al[keep], be[keep]
        w = np.exp(-(((al - be) / 2 - hc * vmax) ** 2) / (2 * (sc * vmax) ** 2) - (((al + be) / 2 - hb * vmax) ** 2) / (2 * (sb * vmax) ** 2))
        w /= w.sum()
        state = np.where(al + be < 0, 1.0, -1.0)  # the demagnetised staircase
        p0, out = float(w @ state), np.empty_like(v)
        for k, x in enumerate(v):
            state[x >= al] = 1.0
            state[x <= be] = -1.0
            out[k] = w @ state
        return (1 - h) * v + h * vmax * (out - p0)

    _drive_side(s, gamma)


def hy_asym_pi_drive(s: Session) -> None:
    """A generalised Prandtl-Ishlinskii on the drive: six plays whose up and down thresholds differ (r (1 + a),
    r (1 - a), a 0.3-0.6: the coupling lags more when charging than discharging), radii 0.05-0.6 of the drive's
    span, weights falling as exp(-k/kappa), kappa 1.5-4. Weight h 0.3-0.6 of the drive."""
    h, a, kappa = s.rng.uniform(0.3, 0.6), s.rng.uniform(0.3, 0.6), s.rng.uniform(1.5, 4.0)

    def gamma(v: np.ndarray) -> np.ndarray:
        vmax = float(np.max(np.abs(v))) or 1.0
        radii = np.linspace(0.05, 0.6, 6) * vmax
        w = np.exp(-np.arange(6) / kappa)
        w /= w.sum()
        y, out = np.zeros(6), np.empty_like(v)
        up, dn = radii * (1 + a), radii * (1 - a)
        for k, x in enumerate(v):
            y = np.minimum(np.maximum(y, x - up), x + dn)
            out[k] = w @ y
        return (1 - h) * v + h * out

    _drive_side(s, gamma)


# ------------------------------------------------------------------------------------------------ time delay


def td_rc_skew(s: Session) -> None:
    """The laser's analogue output through a first-order RC anti-aliasing filter (corner 6-25 Hz, log: a group delay
    of 6-27 ms at low frequency), read by a multiplexed DAQ half a sample period after the voltage channel."""
    tau = 1 / (2 * np.pi * lu(s.rng, 6.0, 25.0))
    _map_through(s, lambda r: lambda z: np.exp(-z * 0.5 / r.fs) / (1 + z * tau), 1.0)


def td_sample_hold(s: Session) -> None:
    """The laser controller updates its analogue output every T_L 4-16 ms (its own free-running clock, phase drawn)
    after a processing latency of 3-20 ms, holding the value between updates (zero-order hold): the DAQ sees a
    staircase of the tip's past, a mean delay of latency + T_L/2."""
    tl, lat, ph = lu(s.rng, 4e-3, 16e-3), lu(s.rng, 3e-3, 20e-3), s.rng.uniform(0, 1)

    def f(r: Rec, d: np.ndarray) -> np.ndarray:
        t = r.cols["t_s"]
        held = (np.floor((t - lat) / tl - ph) + ph) * tl  # the laser's last update before t - lat
        return np.interp(held, t, d, left=d[0])

    map_disp(s, f)


# ------------------------------------------------------------------------------------------------ sensor offset


def so_tilted_laser(s: Session) -> None:
    """The laser aimed inboard of the tip (x0 = 0.75-0.95 L) and tilted by 8-20 deg from the strip's normal: the
    reading is the beam's path length, w(x0)/cos(theta), and the spot walks along the strip by w tan(theta), where
    the bent strip's slope 2 w/x0 adds 2 tan(theta) w^2/x0 (sign by the tilt's side). w(x0) through the beam's own
    transfer function at x0."""
    from labrig.physics import transfer

    f, th, side = s.rng.uniform(0.75, 0.95), math.radians(s.rng.uniform(8, 20)), (1 if s.rng.random() < 0.5 else -1)

    def ratio(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        sp = _spec(s, r)
        return lambda z: transfer.displacement_tf(z, sp.with_(sensor_x=f * sp.geometry.length)) / transfer.displacement_tf(z, sp)

    new = _through(s, ratio, 2.0)
    x0 = f * float(s.specimen["length_m"])
    map_disp(s, lambda r, d: (new[id(r)] + side * 2 * math.tan(th) * new[id(r)] ** 2 / x0) / math.cos(th))


def so_line_spot(s: Session) -> None:
    """A line laser (profiler) whose line lies along the strip: it reports the mean height over the length it
    covers, from the tip inboard by l = 0.2-0.45 L, i.e. the mean of the beam's transfer functions over x in
    [L - l, L] (its quasi-static gain and its shape above the first resonance both differ from the tip's)."""
    from labrig.physics import transfer

    frac = s.rng.uniform(0.2, 0.45)

    def mean_ratio(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        sp = _spec(s, r)
        xs = np.linspace(sp.geometry.length * (1 - frac), sp.geometry.length, 6)
        return lambda z: np.mean([transfer.displacement_tf(z, sp.with_(sensor_x=x)) for x in xs], axis=0) / transfer.displacement_tf(z, sp)

    _map_through(s, mean_ratio, 2.0)


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_seat_in(s: Session) -> None:
    """The clamp's pads seat in once after each new setting (a stick-slip of the screw's thread as the polymer
    under the pad first yields): a step drop of 3-8 % at 5-40 s into the block, on top of a slow first-order
    relaxation of 3-10 % (tau 150-600 s, log)."""
    cs, ts, c, tau = s.rng.uniform(0.03, 0.08), s.rng.uniform(5.0, 40.0), s.rng.uniform(0.03, 0.1), lu(s.rng, 150.0, 600.0)
    _clamp(s, lambda t: 1 - cs * (t >= ts) + c * np.expm1(-np.clip(t, 0, None) / tau))


def cr_fretting(s: Session) -> None:
    """Vibration loosening (fretting) of the clamp: each bending cycle works the pads loose, so the force falls
    with the path the strip has bent through since the setting, not with time: F/F0 = 1 - c (1 - exp(-k W/W_blk)),
    W the accumulated |d delta| over the block's records in time order (through a 10 um play: micro-slip needs a
    real motion), c 5-15 %, k 1-3. The gain follows F^b."""
    c, k, b = s.rng.uniform(0.05, 0.15), s.rng.uniform(1.0, 3.0), s.rng.uniform(0.5, 1.5)
    walked: dict[float, float] = {}
    rel = {}
    for r in _chrono(s):
        p = float(r.entry["pressure_kPa"])
        moved = play(r.cols["disp_m"], 1e-5)  # the pads slip only once the tip has moved 10 um (noise never counts)
        w = walked.get(p, 0.0) + np.cumsum(np.abs(np.diff(moved, prepend=moved[0])))
        walked[p], rel[id(r)] = float(w[-1]), w
    for r in s.series():
        x = 1 - c * -np.expm1(-k * rel[id(r)] / max(walked[float(r.entry["pressure_kPa"])], 1e-12))
        if "force_N" in r.cols:
            r.cols["force_N"] = np.round(r.cols["force_N"] * x / 0.0980665) * 0.0980665  # the indicator's 0.01 kgf
        r.cols["disp_m"] = r.cols["disp_m"] * x**b


# ------------------------------------------------------------------------------------------------ dehydration


def dh_electroosmotic(s: Session) -> None:
    """Electro-osmotic drying: the hydrated cations drag water to the cathode's surface, where it leaves the
    polymer, so the strip loses water mostly while it is driven (with the charge passed, Q = int |i| dt) beside a
    slow baseline evaporation: loss = total ((1 - a) u + a Q(t)/Q_end), total 0.15-0.4, a 0.5-0.9."""
    total, a = s.rng.uniform(0.15, 0.4), s.rng.uniform(0.5, 0.9)
    recs = _chrono(s)
    tt = np.concatenate([r.cols["t_s"] for r in recs])
    q = np.cumsum(np.concatenate([np.abs(r.cols["i_A"]) * np.gradient(r.cols["t_s"]) for r in recs]))
    q /= max(q[-1], 1e-30)
    _dry(s, lambda u: total * ((1 - a) * u + a * np.interp(s.t0 + u * (s.t1 - s.t0), tt, q)))


def dh_falling_rate(s: Session) -> None:
    """The classic drying curve: a constant-rate period (free surface water leaves at a fixed rate) up to the
    critical moisture at u_c 0.25-0.5 of the session, then a falling-rate period where the rate is proportional to
    the water still removable, x -> X_e exponentially with a continuous rate. Loss at u_c 0.12-0.25, X_e 0.08-0.2
    above it."""
    uc, xc = s.rng.uniform(0.25, 0.5), s.rng.uniform(0.12, 0.25)
    xe = xc + s.rng.uniform(0.08, 0.2)
    rate = xc / uc
    _dry(s, lambda u: np.where(u < uc, rate * u, xe - (xe - xc) * np.exp(-rate * (u - uc) / (xe - xc))))


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_crack_hysteresis(s: Session) -> None:
    """Cracks in the tensioned electrode open with its strain but close only once the strain has come back by the
    cracks' friction (a play of radius 0.1-0.3 of the displacement scale, tension side only): the resistance
    follows a hysteretic crack opening, so the displacement and current gains fall more on the way down. The cracks'
    state carries through the session in time order."""
    rr, side = s.rng.uniform(0.1, 0.3), (1 if s.rng.random() < 0.5 else -1)
    recs, ref = _chrono(s), ref_disp(s)
    e = np.concatenate([side * r.cols["disp_m"] / ref for r in recs])
    opened = np.split(np.clip(play(e, rr), 0, None), np.cumsum([r.cols["disp_m"].size for r in recs])[:-1])
    by_rec = {id(r): x for r, x in zip(recs, opened)}
    it = iter([by_rec[id(r)] for r in s.series()])  # inject._strain asks for each record's shape in s.series() order
    _strain(s, lambda _e: next(it))


def sr_saturating(s: Session) -> None:
    """Crack density saturates (the crack spacing reaches the film's minimum, Punning et al.): dR/R of each
    electrode grows as tanh(e/e_s) of its tensile strain, e_s 0.5-1.5 of the displacement scale, the other
    electrode at 0-0.5 of the first's gauge."""
    es, other, g = s.rng.uniform(0.5, 1.5), s.rng.uniform(0.0, 0.5), s.rng.uniform(1.5, 3.0)
    _strain(s, lambda e: g * (np.tanh(np.clip(e, 0, None) / es) + other * np.tanh(np.clip(-e, 0, None) / es)))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_fixed_station(s: Session) -> None:
    """The laser's beam is fixed in the lab at a station x_s = 0.85-0.95 L (not on a material point): as the strip
    bends on an arc of curvature k = 2 d/L^2, its material points draw back and the beam meets the strip where
    sin(k s)/k = x_s, reading (1 - sqrt(1 - (k x_s)^2))/k; calibrated at small deflection (divided by x_s^2/L^2),
    so it reads MORE than the linear d as the deflection grows (d (1 + (k x_s)^2/4 + ...))."""
    lam = s.rng.uniform(0.85, 0.95)

    def f(r: Rec, d: np.ndarray) -> np.ndarray:
        L = float(s.specimen["length_m"])
        k = 2 * d / L**2
        kx = np.clip(k * lam * L, -0.99, 0.99)
        out = d.copy()
        big = np.abs(k) > 1e-9
        out[big] = (1 - np.sqrt(1 - kx[big] ** 2)) / k[big] / lam**2
        return out

    map_disp(s, f)


def ld_triangulation(s: Session) -> None:
    """A triangulation head without a linearisation table, calibrated near its reference distance Z0: the spot's
    image moves as d/(Z0 + d), so at range the reading is d Z0/(Z0 + d) (compressed on the far side, stretched on
    the near one). Z0 40-100 mm; the side towards the head drawn."""
    z0, side = s.rng.uniform(0.04, 0.1), (1 if s.rng.random() < 0.5 else -1)
    map_disp(s, lambda r, d: d / (1 + side * d / z0))


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_record_phase(s: Session) -> None:
    """Mains at 50 Hz with the odd harmonics of saturated transformers and rectifier loads (150 Hz 0.2-0.5, 250 Hz
    0.1-0.3 of it), on both lines; the DAQ's records are not triggered on the line, so each record starts at its own
    phase (drawn per record, harmonics phase-locked to the fundamental). Displacement 1-5 um, current 2-10 uA (log)."""
    ad, ai, h3, h5 = lu(s.rng, 1e-6, 5e-6), lu(s.rng, 2e-6, 1e-5), s.rng.uniform(0.2, 0.5), s.rng.uniform(0.1, 0.3)
    wave = lambda t, p: np.cos(2 * np.pi * 50 * t + p) + h3 * np.cos(6 * np.pi * 50 * t + 3 * p) + h5 * np.cos(10 * np.pi * 50 * t + 5 * p)  # noqa: E731
    for r in s.series():
        t = r.cols["t_s"] - r.cols["t_s"][0]
        p = s.rng.uniform(0, 2 * np.pi)
        r.cols["disp_m"] = r.cols["disp_m"] + ad * wave(t, p)
        r.cols["i_A"] = r.cols["i_A"] + ai * wave(t, p + s.rng.uniform(-0.5, 0.5))


def mp_lamp_flicker(s: Session) -> None:
    """Mains-driven room lighting flickers at twice the line frequency with the shape of a rectified sine; the
    laser's receiver sees it as a displacement ripple (|sin(2 pi 50 t)| less its mean: 100, 200, ... Hz), while the
    current line picks up the 50 Hz field itself. Grid off nominal by up to 0.05 Hz. Displacement 1-5 um, current
    2-10 uA (log)."""
    ad, ai, f = lu(s.rng, 1e-6, 5e-6), lu(s.rng, 2e-6, 1e-5), 50.0 + s.rng.uniform(-0.05, 0.05)
    pd, pi = s.rng.uniform(0, 2 * np.pi, 2)
    for r in s.series():
        t = r.cols["t_s"]
        r.cols["disp_m"] = r.cols["disp_m"] + ad * (np.abs(np.sin(2 * np.pi * f * t + pd)) - 2 / np.pi) * 2
        r.cols["i_A"] = r.cols["i_A"] + ai * np.cos(2 * np.pi * f * t + pi)


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_range_clip(s: Session) -> None:
    """The laser's measuring range ends on one side inside the strip's travel: beyond it the controller holds its
    range-end value (a hard clip at 0.55-0.8 of the session's largest excursion on that side, the other side free),
    and its analogue output is coarsely quantised (a 3-10 um step: a 12-bit output over a wide range)."""
    frac, q, side = s.rng.uniform(0.55, 0.8), lu(s.rng, 3e-6, 1e-5), (1 if s.rng.random() < 0.5 else -1)
    edge = frac * max(float(np.max(side * r.cols["disp_m"])) for r in s.series())
    map_disp(s, lambda r, d: side * np.minimum(np.round(side * d / q) * q, edge))


def out_autorange(s: Session) -> None:
    """An autoranging current amplifier whose upper range has a wrong shunt value: above a switching current
    (0.4-0.8 of the 1 V sine's peak current, so every large sine and step crosses it; back below 0.8 of it) the
    current reads 6-15 % high or low."""
    frac, g = s.rng.uniform(0.4, 0.8), s.rng.uniform(0.06, 0.15) * (1 if s.rng.random() < 0.5 else -1)
    sines = [r for r in s.series() if r.kind == "harmonic"] or [r for r in s.series() if r.kind == "stepped_sine"]
    i_sw = frac * max(float(np.max(np.abs(r.cols["i_A"]))) for r in sines)
    for r in s.series():
        i, hi = r.cols["i_A"], False
        gain = np.ones_like(i)
        for k, x in enumerate(np.abs(i)):
            hi = x > i_sw or (hi and x > 0.8 * i_sw)
            gain[k] = 1 + g if hi else 1.0
        r.cols["i_A"] = i * gain


def out_clock_mismatch(s: Session) -> None:
    """The displacement comes from the laser's own sample stream, restarted at each record's trigger and stamped
    at the nominal rate while the laser runs 0.3-1 % fast: the displacement's time base stretches within each record
    (a delay growing from zero at the trigger), not a fixed skew."""
    eps = lu(s.rng, 3e-3, 1e-2)

    def f(r: Rec, d: np.ndarray) -> np.ndarray:
        t = r.cols["t_s"]
        return np.interp(t[0] + (t - t[0]) / (1 + eps), t, d)

    map_disp(s, f)


FRESH2_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"havriliak_negami": br_havriliak_negami, "two_stage": br_two_stage},
    "faradaic_current": {"her_onset": far_her_onset, "adsorption": far_adsorption},
    "hysteresis": {"preisach_drive": hy_preisach_drive, "asym_pi_drive": hy_asym_pi_drive},
    "time_delay": {"rc_skew": td_rc_skew, "sample_hold": td_sample_hold},
    "sensor_offset": {"tilted_laser": so_tilted_laser, "line_spot": so_line_spot},
    "clamp_relaxation": {"seat_in": cr_seat_in, "fretting": cr_fretting},
    "dehydration": {"electroosmotic": dh_electroosmotic, "falling_rate": dh_falling_rate},
    "strain_resistance": {"crack_hysteresis": sr_crack_hysteresis, "saturating": sr_saturating},
    "large_deflection": {"fixed_station": ld_fixed_station, "triangulation": ld_triangulation},
    "mains_pickup": {"record_phase": mp_record_phase, "lamp_flicker": mp_lamp_flicker},
    "unexplained": {"range_clip": out_range_clip, "autorange": out_autorange, "clock_mismatch": out_clock_mismatch},
}
inject.REGISTRY.update({k: dict(v) for k, v in FRESH2_FORMS.items()})


# ------------------------------------------------------------------------------------------------ variants


def v_decimated3(s: Session) -> None:
    """Another DAQ: every series block-averaged by 3 (an averaging ADC at a third of the rate), each block stamped
    at its centre."""
    for r in s.series():
        n = r.cols["t_s"].size // 3 * 3
        r.cols = {k: x[:n].reshape(-1, 3).mean(axis=1) for k, x in r.cols.items()}


def v_own_clock(s: Session) -> None:
    """Every time series on its own clock from 0 (no shared session clock), the records in the order they ran."""
    for r in s.series():
        r.cols["t_s"] = r.cols["t_s"] - r.cols["t_s"][0]


inject.VARIANTS.update({"decimated3": v_decimated3, "own_clock": v_own_clock})

# ------------------------------------------------------------------------------------------------ the cases

P41, S42, L43 = "paper_41", "s001_42", "long_43"
PLAN = {  # effect: three (form, seed, base, variant); forms alternated over the seeds
    "back_relaxation": [("havriliak_negami", 41, P41, "asrun"), ("two_stage", 42, S42, "no_spectra"), ("havriliak_negami", 43, L43, "decimated3")],
    "faradaic_current": [("adsorption", 41, P41, "steps_sines"), ("her_onset", 42, S42, "asrun"), ("adsorption", 43, L43, "own_clock")],
    "hysteresis": [("preisach_drive", 41, P41, "two_pressures"), ("asym_pi_drive", 42, S42, "asrun"), ("preisach_drive", 43, L43, "shortened_shuffled")],
    "time_delay": [("sample_hold", 41, P41, "resampled"), ("rc_skew", 42, S42, "own_clock"), ("sample_hold", 43, L43, "asrun")],
    "sensor_offset": [("tilted_laser", 41, P41, "asrun"), ("line_spot", 42, S42, "steps_sines"), ("tilted_laser", 43, L43, "two_pressures")],
    "clamp_relaxation": [("fretting", 41, P41, "no_spectra"), ("seat_in", 42, S42, "asrun"), ("fretting", 43, L43, "resampled")],
    "dehydration": [("electroosmotic", 41, P41, "steps_sines"), ("falling_rate", 42, S42, "decimated3"), ("electroosmotic", 43, L43, "asrun")],
    "strain_resistance": [("saturating", 41, P41, "asrun"), ("crack_hysteresis", 42, S42, "shortened_shuffled"), ("saturating", 43, L43, "no_spectra")],
    "large_deflection": [("fixed_station", 41, P41, "decimated3"), ("triangulation", 42, S42, "two_pressures"), ("fixed_station", 43, L43, "steps_sines")],
    "mains_pickup": [("lamp_flicker", 41, P41, "shortened_shuffled"), ("record_phase", 42, S42, "no_spectra"), ("lamp_flicker", 43, L43, "own_clock")],
    "unexplained": [("range_clip", 41, P41, "asrun"), ("autorange", 42, S42, "asrun"), ("clock_mismatch", 43, L43, "asrun"),
                    ("range_clip", 43, L43, "no_spectra"), ("autorange", 41, P41, "steps_sines")],
}
CLEAN = [(41, P41, "asrun"), (41, P41, "own_clock"), (42, S42, "asrun"), (42, S42, "decimated3"), (43, L43, "asrun"),
         (43, L43, "shortened_shuffled")]


def fresh2_cases(only: str | None = None) -> list[Case]:
    """The third held-out set: 30 effect cases, 5 outside the catalogue, 6 clean (seeds 41-43)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh2_cases, "inject_fresh2", "fresh2")
