"""A thirty-eighth held-out set for the diagnosis (issue 12), fresh37, written without sight of the diagnosis (its code,
its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh36.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (nanoporous gold faces whose pores open
with the bend, persulfate left by a Nochromix clean reduced with a negative differential resistance, miniature
ball-bearing rollers with their pre-rolling friction, a host clock's coarse tick stamping a streamed laser, a
silver-nanowire mesh welded by the current's Joule heat, a woven micromesh collector on Hertzian crossings, a silicone
skin stiffening towards its locking stretch, a delta-sigma logger overloading softly) and some on the history, the clamp
pressure or the session's events (a cationic dye drawn into the cathodic faces, a sealed cuvette's oxygen drawn down by
the cathodes, a PTFE-reinforced membrane's fibres slipping in their ionomer, a gooseneck arm's coils slipping after it
was bent, an aluminium clamp's corrosion jacking its joint, a force loop ringing after every setting, a plating loosened
by an ultrasonic clean shedding at the large bends, liposomes fusing into a bilayer that the large drives electroporate,
a UPS going to its stepped inverter at the brown-outs) and some on time (a phone video's variable frame rate, hot-melt
glue creeping faster as the room warms, a heat-trace cable's inrush at each thermostat start); lab wiring or sensors
among them (the host tick, the phone video, the rollers, the hot-melt bracket, the gooseneck, the force loop, the
delta-sigma logger, the UPS, the heat trace, the nanowire mesh and the micromesh). Four structures outside the catalogue
(truth "unexplained": the laser output's scale rippling with a burst-mode regulator; every spectrum the analyser's last
sweep, its file overwritten; the current amplifier's antiparallel feedback diodes; every record's last buffer written
out with zeros); clean sessions. All on three bases of new seeds (181-183: the paper strip, the seed-001 strip on its
own sweep, the paper strip 8 mm free) and on the earlier sets' data-shape variants plus one new here: every time series
placed on the session clock by its file's modification time on a FAT memory card (2 s ticks, ``file_mtime_clock``).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh36 are reused (importing inject_fresh36 and inject_fresh35 registers every earlier set's
lookups), and the forms, bases, preset and variant of this set are registered into inject's lookups at import, none
replaced. Strengths are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it
made on its case, measured in memory against the clean base (relative RMS change over all series, form only, no variant;
"noise": the column's sample-to-sample noise at rest, inject_fresh15.rest_noise).

Run: python bench/inject_fresh37.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np

import inject
import inject_fresh35  # noqa: F401  (registers fresh35's and, through fresh33 and fresh31, every other earlier set's)
import inject_fresh36  # noqa: F401  (registers fresh36's and, through fresh34 and fresh32, fresh30's lookups)
from inject import Case, Rec, Session, lu, ref_disp
from inject_fresh2 import _chrono, _drive_side
from inject_fresh3 import _resist, _sign
from inject_fresh4 import _clamp_law
from inject_fresh6 import _bursts
from inject_fresh9 import _dry_by
from inject_fresh10 import _lag_varying, _station
from inject_fresh12 import _line_f
from inject_fresh14 import _largest
from inject_fresh25 import _setting_of
from inject_fresh26 import _split_noise
from inject_fresh33 import _static_map
from inject_fresh34 import _cumulative, _rising
from inject_fresh35 import _per_face, _session_curve

# the paper's strip 8 mm free (earlier sets used 9-45 mm, 30 mm is the paper preset itself and the seed-001 strip is
# 20 mm): its 1 V step peaks at 0.65 mm, well inside the laser's +-20 mm (2 mm/V on the DAQ's +-10 V) and some 1200x
# the laser's 0.55 um noise at rest; its first mode at 45-52 Hz (the four pressures), above the sines' top (20 Hz).
# Preset "paper_8", base "p8_183", registered in every process importing this module
inject.register_free_length("paper_8", 0.008)

inject.BASES.update({
    "paper_181": ("paper-sweep", "paper", 181),
    "s001_182": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 182),
    "p8_183": ("paper-sweep", "paper_8", 183),
})

FARADAY = 96485.33  # C/mol
O2_SAT = 0.26  # mol/m^3: dissolved oxygen in water under air at room temperature


# ------------------------------------------------------------------------------------------------ tools


def _signal_curve(s: Session, f: Callable[[np.ndarray], np.ndarray] = np.abs) -> Callable[[np.ndarray], np.ndarray]:
    """f of the displacement's signal (inject_fresh26._split_noise, no sensor noise) as a function of session time,
    linear across the rests (inject_fresh35._session_curve)."""
    return _session_curve(s, {id(r): f(_split_noise(r)[0]) for r in s.series()})


def _play_bank(u: np.ndarray, radii: np.ndarray, state: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Play operators of radii ``radii`` on ``u`` from ``state`` (one per radius), shape (len(u), len(radii)), and their
    last state. Rate-independent, so each monotone run of u is a clip of the run's starting state (a loop over the runs,
    vectorised within each; flat samples take the direction of the last move)."""
    y = np.empty((u.size, radii.size))
    if u.size == 0:
        return y, state
    d = np.sign(np.diff(u))
    nz = np.flatnonzero(d)
    if nz.size:
        d = d[nz[np.maximum(np.searchsorted(nz, np.arange(d.size), side="right") - 1, 0)]]
    ends = np.r_[np.flatnonzero(d[1:] != d[:-1]) + 1, u.size - 1] if d.size else np.array([u.size - 1])
    a = 0
    for b in ends.tolist():
        seg = u[a : b + 1, None]
        y[a : b + 1] = np.clip(state, seg - radii, seg + radii)
        state = y[b].copy()
        a = b + 1
    return y, state


def _deadband(u: np.ndarray, r: float) -> np.ndarray:
    """A play of radius r on u sample by sample (a dead band that holds the value until u has moved by r): the monitor's
    noise taken off a drive before a rate-independent operator counts its turning points."""
    y, prev = np.empty(u.size), float(u[0]) if u.size else 0.0
    for k, x in enumerate(u.tolist()):
        prev = min(max(prev, x - r), x + r)
        y[k] = prev
    return y


def _invert_odd(read: Callable[[np.ndarray], np.ndarray], top: float,
                n: int = 8001) -> Callable[[np.ndarray], np.ndarray]:
    """The inverse of a monotone odd map y -> read(y) over |y| <= top, tabulated and interpolated (held beyond)."""
    yg = np.linspace(-top, top, n)
    xg = read(yg)
    return lambda x: np.interp(x, xg, yg)


# ------------------------------------------------------------------------------------------------ back relaxation


def br_nanoporous_gold_faces(s: Session) -> None:
    """Electrodes of nanoporous gold (white-gold leaf dealloyed in nitric acid and floated onto the membrane, a lab's
    high-area electrode): the back-flow is exchanged with the bath through the faces' nanopores, and the leaf's
    ligaments part under the face's tension and close under its compression, so the exchange runs faster the further the
    strip is bent whichever way (one face is always stretched): tau = tau_0/(1 + g |d|/d_max) (tau_0 3-10 s, log; g 1-4;
    d the bend, d_max the session's largest), its share K2 (0.5-0.9) unchanged. A state of the bend itself, no memory:
    the large bends give back sooner than the small ones. Through inject_fresh10._lag_varying; displacement only.
    Measured (p8_183: K2 0.68, tau_0 3.1 s, g 3.6: tau 0.68 s at the largest bend) displacement RMS -65 % (residual 67
    %, 305x its noise): the 1 V steps at 0.211 mm by their plateaus' end in every block (0.648-0.649 mm clean) and 0.119
    mm 2 s after their fall (0.467 clean); the 1 V harmonics at 0.751-0.760 (+22.1 deg) and the 0.5 V sines at 0.1 Hz at
    0.852 (+22.1 deg); the 0.45 Hz sines 0.994 (+5.3 deg)."""
    k2, tau0, g = s.rng.uniform(0.5, 0.9), lu(s.rng, 3.0, 10.0), s.rng.uniform(1.0, 4.0)
    big = _largest(s) or ref_disp(s)
    bend = _signal_curve(s)

    def state(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        b = np.asarray(bend(t), float)
        return np.full(b.shape, k2), tau0 / (1.0 + g * b / big)

    _lag_varying(s, state)


def br_rhodamine_dye_uptake(s: Session) -> None:
    """Rhodamine 6G left in the cuvette from fluorescence imaging (a cationic dye, a few uM): the drive's field draws
    the dye cations into whichever face is the cathode along with the charge, and Nafion binds them to its sulfonates
    for good, the bulky cations narrowing the channels in that face's outer layer: each face loaded as 1 - exp(-Q/Q_d),
    Q its cathodic charge so far (the current's part that makes it the cathode, through the session in time order,
    inject_fresh35._per_face), Q_d set so that the more-loaded face reaches theta_end (0.4-0.8) by the session's end.
    The water a bend pushed to the cathode face leaves through that face's channels, so the back-flow's tau = tau_0 (1 +
    a theta), theta the load of the face that is the cathode for the bend's sign (a 1-3; tau_0 2-8 s, log; K2 0.5-0.9).
    Through inject_fresh10._lag_varying; displacement only. Measured (paper_181: K2 0.78, tau_0 6.0 s, a 1.65, theta_end
    0.75: tau up to 13 s for the positive bends by the end) displacement RMS -57 % (residual 70 %, 4000x its noise): the
    1 V steps at 2.70, 3.15, 3.46, 3.67 mm by their plateaus' end block by block (8.79-8.80 mm clean) and 0.62, 0.94,
    1.20, 1.39 mm 2 s after their fall (6.64 clean); the 1 V harmonics' gain 0.961 (+9.8 deg), 0.977, 0.981, 0.984 (+5.2
    deg)."""
    k2, tau0, a = s.rng.uniform(0.5, 0.9), lu(s.rng, 2.0, 8.0), s.rng.uniform(1.0, 3.0)
    th_end = s.rng.uniform(0.4, 0.8)
    big = _largest(s) or ref_disp(s)
    # each face's cathodic charge (face A, sgn +1, the anode for v > 0: cathodic while the current is negative)
    per, tot = _per_face(s, lambda r, sg: np.clip(-sg * r.cols["i_A"], 0.0, None))
    top = max(tot.values())
    k = -math.log1p(-th_end) / top if top > 0 else 0.0
    theta = {sg: _session_curve(s, {key: -np.expm1(-k * x) for key, x in per[sg].items()}) for sg in (1.0, -1.0)}
    bend = _signal_curve(s, lambda x: x)

    def state(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        t = np.asarray(t, float)
        w = 0.5 * (1.0 + np.tanh(bend(t) / (0.05 * big)))  # a positive bend: face B (sgn -1) the cathode, its water
        th = w * theta[-1.0](t) + (1.0 - w) * theta[1.0](t)
        return np.full(t.shape, k2), tau0 * (1.0 + a * th)

    _lag_varying(s, state)


# ------------------------------------------------------------------------------------------------ faradaic current


def far_persulfate_frumkin_ndr(s: Session) -> None:
    """Glassware cleaned with Nochromix (ammonium persulfate in sulfuric acid, the chromium-free replacement for chromic
    acid) and the cuvette rinsed too briefly: persulfate left in the bath is reduced on whichever face is the cathode
    from a low overpotential, a wave from E_s (0.05-0.2 V of drive, width 0.03-0.06 V) to its transport plateau i_L
    (0.1-0.4 mA, log), and beyond E_f (0.45-0.7 V, width 0.04-0.08 V) the cathode's growing negative charge repels the
    anion from its double layer (the Frumkin effect) and the current falls again by depth (0.5-0.85): i = i_L wave_s (1
    - depth wave_f), a negative differential resistance, each face as the cathode its own wave. The current only.
    Measured (paper_181: i_L 0.38 mA, E_s 0.07 V, E_f 0.68 V, depth 0.57) current RMS +6.2 % (residual 8.6 %, 6.5x its
    noise): the 1 V steps' plateau current 0.769, 0.737, 0.730, 0.736 mA (0.572-0.605 clean); the 0.5 V sines' current
    gain 1.17-1.18 (-6.6 to -7.0 deg) at 0.1 Hz, 1.10 at 0.45 Hz, 1.04 at 20 Hz, the 1 V harmonics' only 1.050-1.053
    (-2.2 to -2.4 deg): more current at half the drive."""
    i_l, e_s, w1 = lu(s.rng, 1e-4, 4e-4), s.rng.uniform(0.05, 0.2), s.rng.uniform(0.03, 0.06)
    e_f, w2, depth = s.rng.uniform(0.45, 0.7), s.rng.uniform(0.04, 0.08), s.rng.uniform(0.5, 0.85)
    for r in s.series():
        v = r.cols["v_V"]
        out = np.zeros(v.size)
        for sgn in (1.0, -1.0):
            c = -sgn * v  # the face's cathodic drive
            up = _rising((c - e_s) / w1, -e_s / w1)
            down = _rising((c - e_f) / w2, -e_f / w2)
            out += -sgn * i_l * up * (1.0 - depth * down)
        r.cols["i_A"] = r.cols["i_A"] + out


def far_sealed_cuvette_oxygen(s: Session) -> None:
    """A cuvette sealed with a stopper for a long session (against evaporation), its 0.5-1.5 ml of water holding the
    oxygen it had at air saturation and no more: whichever face is the cathode reduces it (a wave from E_r 0.1-0.3 V of
    drive, width 0.04-0.08 V, to i_r 0.1-0.3 mA at saturation, log, in proportion to the oxygen c left), whichever face
    is the anode beyond E_o (0.6-0.85 V, width 0.03-0.06 V) evolves it at i_o (0.15-0.4 mA, log), and the stopper lets
    it back in over tau_l (1-3 h, log): dc/dt = (i_o - i_r c)/(4 F n_sat) - (c - 1)/tau_l, sample by sample through the
    session in time order (relaxing over the rests). The small drives draw the sealed bath's oxygen down, the 1 V
    records make a little back; the current only. Measured (p8_183: i_r 0.19 mA, E_r 0.23 V, i_o 0.18 mA, E_o 0.61 V,
    0.68 ml, tau_l 66 min: c from 1.0 to 0.69 by the first block's end and 0.48 by the session's) current RMS +2.5 %
    (residual 7.2 %, 3.5x its noise): the 1 V steps' plateau current 0.588, 0.506, 0.477, 0.475 mA block by block
    (0.173-0.212 clean); the 1 V harmonics' current gain 1.163 (-8.4 deg) to 1.145 (-8.0 deg), the 0.45 Hz sines' 1.057
    to 1.043."""
    i_o, e_o, w_o = lu(s.rng, 1.5e-4, 4e-4), s.rng.uniform(0.6, 0.85), s.rng.uniform(0.03, 0.06)
    i_r, e_r, w_r = lu(s.rng, 1e-4, 3e-4), s.rng.uniform(0.1, 0.3), s.rng.uniform(0.04, 0.08)
    vol, tau_l = s.rng.uniform(0.5e-6, 1.5e-6), lu(s.rng, 3600.0, 10800.0)
    n_sat = O2_SAT * vol  # mol of oxygen in the sealed bath at air saturation
    c, t_end = 1.0, None
    for r in _chrono(s):
        v, t, dt = r.cols["v_V"], r.cols["t_s"], 1.0 / r.fs
        if t_end is not None:
            c = 1.0 + (c - 1.0) * math.exp(-max(float(t[0]) - t_end, 0.0) / tau_l)
        ox = np.zeros(v.size)
        red_unit = np.zeros(v.size)
        for sgn in (1.0, -1.0):
            u = sgn * v  # the face's anodic drive
            ox += sgn * i_o * _rising((u - e_o) / w_o, -e_o / w_o)
            red_unit += -sgn * i_r * _rising((-u - e_r) / w_r, -e_r / w_r)  # the face as cathode, at c = 1
        prod = np.abs(ox) / (4.0 * FARADAY * n_sat)  # the oxygen made, in units of c per second
        cons = np.abs(red_unit) / (4.0 * FARADAY * n_sat)
        cs = np.empty(v.size)
        for k, (p, q) in enumerate(zip(prod.tolist(), cons.tolist())):  # dc/dt = p - q c - (c - 1)/tau_l, exactly
            b = q + 1.0 / tau_l
            a = p + 1.0 / tau_l
            e = math.exp(-b * dt)
            c = c * e + a / b * (1.0 - e)
            cs[k] = c
        r.cols["i_A"] = r.cols["i_A"] + ox + red_unit * cs
        t_end = float(t[-1])


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_reinforced_membrane_fibres(s: Session) -> None:
    """A strip cut from a PTFE-reinforced membrane (a Nafion N324-type membrane, a woven PTFE fabric inside the ionomer,
    chosen by a lab for its strength): the fibres hold part of the swelling the drive makes until the ionomer slips on
    them, and the fibres' embedded lengths spread their slip thresholds: a drive-side Prandtl-Ishlinskii of twelve plays
    whose radii fall off exponentially in number (density exp(-r/u_0), u_0 0.1-0.3 of the peak drive, radii to 4 u_0),
    weight h (0.2-0.4): Gamma = (1 - h) V + h sum w_j play_j[V], Masing loops with an exponential backbone. Through the
    strip's measured step response (inject_fresh2._drive_side), the monitor's noise kept out of the plays by a 1 mV dead
    band; current untouched. Measured (s001_182: h 0.29, u_0 0.17 of the peak drive) displacement RMS +0.56 % (residual
    7.6 %, 250x its noise): the 1 V steps at 4.46, 4.62, 4.63, 4.63 mm by their plateaus' end (4.67-4.70 mm clean); the
    0.5 V sines' gain 0.91-0.92 (-3.8 to -4.9 deg) from 0.1 to 20 Hz, the 1 V harmonics' 0.974 (-1.3 deg)."""
    h, u0 = s.rng.uniform(0.2, 0.4), s.rng.uniform(0.1, 0.3)
    n = 12

    def gamma(v: np.ndarray) -> np.ndarray:
        vmax = float(np.max(np.abs(v))) or 1.0
        radii = (np.arange(n) + 0.5) / n * 4.0 * u0 * vmax
        w = np.exp(-radii / (u0 * vmax))
        w /= w.sum()
        quiet, _ = _play_bank(_deadband(v, 1e-3), radii, np.zeros(n))  # the monitor's noise is no move of the drive
        return (1.0 - h) * v + h * (quiet @ w)

    _drive_side(s, gamma)


def hy_miniature_bearing_rollers(s: Session) -> None:
    """The tip guided between two miniature ball bearings (2-3 mm outer rings on pins, a lab's low-friction guide
    against sideways swinging, the strip's edges running on them): their rolling resistance f_r (0.2-0.6 % of the
    session's largest bend in tip units, log) holds the tip back, reached over the bearings' pre-rolling travel (Dahl's
    law with exponent 2: df/dy = S (1 - f sgn(dy)/f_r)^2, the pre-rolling length 0.5-2 f_r), rate-independent, and held
    over the rests. Solved along the tip's own move sample by sample through the session in time order, the laser's
    noise kept; displacement only. Measured (paper_181: f_r 21 um, a pre-rolling length of 33 um) displacement residual
    0.53 % of its RMS (31x its noise): the 9.4 and 20 Hz sines at 0.61-0.62 of their gain (-1.4 to -3.0 deg), the 3 Hz
    ones at 0.95-0.96 (-3.8 to -4.4 deg), the 1 V harmonics at 0.996 (-0.7 deg); the steps 20 um short on their plateaus
    and 21 um long after their fall."""
    big = _largest(s) or ref_disp(s)
    f_r, ratio = lu(s.rng, 0.002, 0.006) * big, s.rng.uniform(0.5, 2.0)
    stiff = 1.0 / ratio  # the pre-rolling length f_r/stiff = ratio f_r: df/dy = stiff (1 - f sgn(dy)/f_r)^2
    f, last = 0.0, None
    for r in _chrono(s):
        sig, noise = _split_noise(r)
        dd = np.diff(sig, prepend=sig[0] if last is None else last).tolist()  # the move over the rest comes first
        out = np.empty(sig.size)
        for k, (x, dx) in enumerate(zip(sig.tolist(), dd)):
            if dx != 0.0:
                sg = 1.0 if dx > 0 else -1.0
                u0 = max(1.0 - f * sg / f_r, 0.0)
                df = stiff * u0 * u0 * dx / (1.0 + stiff * u0 * u0)  # a first guess, then Dahl's law solved exactly
                for _ in range(3):  # along the tip's own move dy = dd - df: u = u0/(1 + u0 S |dy|/f_r)
                    u = u0 / (1.0 + u0 * stiff * abs(dx - df) / f_r)
                    df = sg * f_r * (1.0 - u) - f
                f += df
            out[k] = x - f
        r.cols["disp_m"] = out + noise
        last = float(sig[-1])


# ------------------------------------------------------------------------------------------------ time delay


WIN_TICK = 0.015625  # s: Windows' default system-time tick (64 Hz)


def td_coarse_tick_stamps(s: Session) -> None:
    """The laser streamed to the logging PC (its own fast cycle) and stamped with the host's system time, which Windows
    advances in ticks of 15.625 ms: every reading arriving within a tick gets that tick's stamp, the logger keeps the
    newest reading per stamp and puts the stamped readings on the DAQ's rows by linear interpolation. The reading on a
    tick's stamp was taken one tick later less the stream's latency (2-8 ms, log), so the displacement is read early by
    15.6 ms less the latency and smoothed by the interpolation's triangle (its sinc^2 gain); the ticks' phase drawn. Per
    record; displacement only. Measured (paper_181: a latency of 6.9 ms, a lead of 8.7 ms) displacement residual 0.20 %
    of its RMS (11x its noise): the 3 Hz sines +9.6 deg at 0.995, the 9.4 Hz ones +29 deg at 0.92-0.94, the 20 Hz ones
    +62 to +63 deg at 0.70-0.72; the 1 V harmonics +0.3 deg."""
    lat, ph = lu(s.rng, 2e-3, 8e-3), s.rng.uniform(0.0, WIN_TICK)
    for r in s.series():
        t, d = r.cols["t_s"], r.cols["disp_m"]
        k0 = math.floor((float(t[0]) - ph) / WIN_TICK) - 1
        k1 = math.ceil((float(t[-1]) - ph) / WIN_TICK) + 1
        knots = ph + np.arange(k0, k1 + 1) * WIN_TICK  # the stamps the host's clock can give
        last = knots + WIN_TICK - lat  # the newest reading that arrived before the next tick
        vals = np.interp(last, t, d)
        r.cols["disp_m"] = np.interp(t, knots, vals)


def td_phone_vfr_video(s: Session) -> None:
    """No laser: the tip filmed by a phone in its slow-motion mode (120 or 240 frames/s) and tracked, the frames put on
    the DAQ's rows as if evenly spaced from each record's start (a flash at the trigger aligns them), but a phone
    records at a variable frame rate: its mean rate off the nominal by 0.02-0.1 % (either way), frames dropped now and
    then (2-8 per 10 000, log, each pushing every later frame one period on) and each frame's time jittered by 0.2-0.8
    ms: the reading runs late (or early) by a time error that grows through each record. Per record, the frames'
    positions at their true times interpolated at the assumed ones; displacement only. Measured (s001_182: 120 frames/s,
    the rate 0.093 % slow, 2.4 drops per 10 000, 0.29 ms of jitter) displacement residual 0.21 % of its RMS (6.8x its
    noise): the 20 Hz sines -13.3 to -13.5 deg at 0.90, the 9.4 Hz ones -6.3 deg, the 3 Hz ones -2.2 deg, the 0.1 Hz
    sines (60 s records) -0.6 to -0.9 deg."""
    fps = float(s.rng.choice([120.0, 240.0]))
    rate_off = s.rng.uniform(0.0002, 0.001) * _sign(s)
    drop = lu(s.rng, 2e-4, 8e-4)
    jitter = s.rng.uniform(0.2e-3, 0.8e-3)
    for r in s.series():
        t, d = r.cols["t_s"], r.cols["disp_m"]
        n = int(math.ceil((float(t[-1]) - float(t[0])) * fps)) + 2
        k = np.arange(n)
        assumed = float(t[0]) + k / fps
        drops = np.cumsum(s.rng.random(n) < drop)
        drops -= drops[0]
        true = float(t[0]) + (k + drops) / fps * (1.0 + rate_off) + s.rng.uniform(-jitter, jitter, n)
        true[0] = float(t[0])
        pos = np.interp(true, t, d)
        r.cols["disp_m"] = np.interp(t, assumed, pos)


# ------------------------------------------------------------------------------------------------ sensor offset


def so_hotmelt_glued_bracket(s: Session) -> None:
    """The laser head's bracket fixed to its post with hot-melt glue (a quick fix), aimed at the start a margin m0
    (0.1-0.3 mm) inside the tip's end: the glue creeps under the head's weight, its creep rate thermally activated, and
    the room warms through the session, so the head tilts ever faster and its spot walks inboard along the strip by a
    total of 1-4 % of L (log): the station f L with f = f_0 - walk (exp(a u) - 1)/(exp(a) - 1), u the session's
    fraction, a 1-3 (the creep rate 3-20 times faster by the end). Through inject_fresh10._station (the beam's own
    transfer functions at the station); displacement only. Measured (paper_181: m0 0.19 mm, a walk of 3.2 % of L, a 1.9:
    the station from 0.994 to 0.962 L) displacement RMS -3.0 % (residual 3.4 %, 200x its noise): the 1 V steps at 8.68,
    8.62, 8.50, 8.33 mm by their plateaus' end block by block (8.79-8.80 mm clean); the 0.1 Hz harmonics' gain 0.987,
    0.980, 0.965, 0.946; the 20 Hz sines' 0.96 to 0.83."""
    length = float(s.specimen["length_m"])
    m0, walk, acc = s.rng.uniform(1e-4, 3e-4), lu(s.rng, 0.01, 0.04), s.rng.uniform(1.0, 3.0)
    first = 1.0 - m0 / length
    span = s.t1 - s.t0

    def frac(r: Rec) -> np.ndarray:
        u = np.clip((r.cols["t_s"] - s.t0) / span, 0.0, 1.0)
        return first - walk * np.expm1(acc * u) / math.expm1(acc)

    _station(s, frac, first - walk)


def so_gooseneck_creep_jumps(s: Session) -> None:
    """The laser head held on a gooseneck arm (a flexible metal hose, the kind a microscope lamp rides on), bent into
    position 1-10 min before the first record (drawn) and aimed a margin m0 (0.1-0.3 mm) inside the tip's end: under the
    head's weight the hose's coils slip now and then, each slip turning the head so that its spot jumps inboard along
    the strip by an exponentially distributed step (mean 0.1-0.4 % of L, log), the slips coming at a rate that falls off
    as 1/(c + t) from the bending (Omori's law, c 30-120 s; 4-12 slips expected over the session): a staircase of
    stations, its steps crowded early. Through inject_fresh10._station; displacement only. Measured (s001_182: m0 0.23
    mm, six slips at 3.7, 4.5, 5.1, 7.7, 22.7 and 32.7 min into the session of 24, 47, 29, 139, 6 and 46 um: the station
    from 0.988 to 0.974 L) displacement RMS -4.2 % (residual 4.4 %, 140x its noise): the 1 V steps at 4.57, 4.48, 4.46,
    4.47 mm by their plateaus' end block by block (4.67-4.70 mm clean); the 0.1 Hz harmonics' gain 0.978, 0.955, 0.950,
    0.950."""
    length = float(s.specimen["length_m"])
    m0 = s.rng.uniform(1e-4, 3e-4)
    lead, c_o = s.rng.uniform(60.0, 600.0), s.rng.uniform(30.0, 120.0)
    n_exp, mean = s.rng.uniform(4.0, 12.0), lu(s.rng, 0.001, 0.004) * length
    a, b = c_o + lead, c_o + lead + (s.t1 - s.t0)  # Omori's law: rate n_exp/ln(b/a) / (c + time since mounting)
    n = int(s.rng.poisson(n_exp))
    times = s.t0 - lead - c_o + a * np.exp(s.rng.uniform(0.0, 1.0, n) * math.log(b / a))
    times.sort()
    sizes = s.rng.exponential(mean, n)
    first = 1.0 - m0 / length
    steps = np.r_[0.0, np.cumsum(sizes)] / length

    def frac(r: Rec) -> np.ndarray:
        return first - steps[np.searchsorted(times, r.cols["t_s"], side="right")]

    _station(s, frac, first - steps[-1] - 1e-9)


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_galvanic_oxide_jacking(s: Session) -> None:
    """A screw clamp with an aluminium frame and a stainless screw, half in the bath since it was filled (0-10 min
    before the first record): the two metals a galvanic couple in the water, the aluminium corrodes in the thread and at
    the jaw's seat, and its hydroxide, three times the metal's volume, grows parabolically and closes the joint under
    the held gap: the force rises as beta (sqrt(t - t_fill) - sqrt(t_set - t_fill))/sqrt(session) after each setting
    (beta 0.15-0.35: the rise the whole session would make), less in the later blocks, beside a small logarithmic
    relaxation of the pads (0.1-0.3 % a decade, tau_v 2-20 s, log). From each setting (inject_fresh25._setting_of)
    through the preset's clamp law (inject_fresh4._clamp_law), the load cell showing it. Measured (paper_181: filled 4.7
    min before, beta 0.21, the pads 0.13 % a decade) the load cell at 1.050, 1.030, 1.018, 1.017 of its setting by each
    block's last record (4.1 steps of 0.01 kgf RMS); displacement residual 0.024 % of its RMS (1.4x its noise: the 4287
    kPa block's 9.4 Hz sines 0.947, +4.2 deg), current 0.16 % (0.12x)."""
    t_fill = s.t0 - s.rng.uniform(0.0, 600.0)
    beta, r_c, tau_v = s.rng.uniform(0.15, 0.35), s.rng.uniform(0.001, 0.003), lu(s.rng, 2.0, 20.0)
    setting = _setting_of(s)
    scale = math.sqrt(max(s.t1 - t_fill, 1.0))

    def rel(t: np.ndarray, p: float, t_fp: float) -> np.ndarray:
        t_set = setting(p, t_fp)
        t = np.asarray(t, float)
        grown = np.sqrt(np.clip(t - t_fill, 0.0, None)) - math.sqrt(max(t_set - t_fill, 0.0))
        u = np.clip(t - t_set, 0.0, None)
        return (1.0 + beta * np.clip(grown, 0.0, None) / scale) * (1.0 - r_c * np.log10(1.0 + u / tau_v))

    _clamp_law(s, rel)


def cr_pi_clamp_ringing(s: Session) -> None:
    """A motorised clamp whose force loop (a PI controller on the load cell, its integral gain set too high for the
    pads' slow give) rings after every setting: the force swings about its setting as amp exp(-u/tau) cos(2 pi u/T +
    phi) (amp 3-8 %, T 1-4 min, tau 100-400 s, log; u the time since the setting, phi 0-90 deg), the same ringing in
    every block, the mean held by the loop. From each setting (inject_fresh25._setting_of) through the preset's clamp
    law (inject_fresh4._clamp_law), the load cell showing it. Measured (s001_182: amp 7.6 %, T 73 s, tau 194 s, phi 81
    deg) the load cell between 0.93 and 1.06 of its setting in the blocks' first records (14.5 steps of 0.01 kgf RMS),
    at 1.04-1.05 by the steps' plateaus' end; displacement residual 0.0067 % of its RMS (0.22x its noise), current 0.054
    % (0.14x)."""
    amp, period, tau = s.rng.uniform(0.03, 0.08), lu(s.rng, 60.0, 240.0), lu(s.rng, 100.0, 400.0)
    phase = s.rng.uniform(0.0, 0.5 * math.pi)
    setting = _setting_of(s)

    def rel(t: np.ndarray, p: float, t_fp: float) -> np.ndarray:
        u = np.clip(np.asarray(t, float) - setting(p, t_fp), 0.0, None)
        return 1.0 + amp * np.exp(-u / tau) * np.cos(2.0 * math.pi * u / period + phase)

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_ultrasonic_loosened_plating(s: Session) -> None:
    """A strip cleaned in an ultrasonic bath before mounting (the lab's routine against salt and dust), which loosened
    its plating's platelets: whenever the tip travels beyond e_t (0.3-0.6 of the session's largest bend) the bending
    sheds loose platelets, the active area lost as l_max (1 - exp(-P/P_c)) with P the tip's travel beyond e_t so far (in
    units of the largest bend, through the session in time order, inject_fresh34._cumulative; l_max 5-15 %, P_c set so
    that 0.4-0.8 of l_max is reached by the session's end): a loss that grows only at the large bends and never comes
    back. Gain x (1 - loss), conductance x (1 - share loss) (share 0.3-1); the spectra at the next series' start
    (inject_fresh9._dry_by). Measured (s001_182: e_t 0.52, l_max 7.0 %, 0.44 of it by the end, share 0.52) displacement
    RMS -1.7 % (residual 2.0 %, 64x its noise), current RMS -1.0 % (residual 1.1 %, 3.0x its noise): the 1 V steps at
    4.65, 4.62, 4.60, 4.57 mm by their plateaus' end block by block (4.67-4.70 mm clean); the 0.1 Hz harmonics' gain
    0.991, 0.982, 0.975, 0.969 (current 0.995 to 0.984)."""
    big = _largest(s) or ref_disp(s)
    e_t, l_max = s.rng.uniform(0.3, 0.6), s.rng.uniform(0.05, 0.15)
    th_end, share = s.rng.uniform(0.4, 0.8), s.rng.uniform(0.3, 1.0)

    def shed(r: Rec) -> np.ndarray:  # the path the tip travels beyond e_t of the largest bend, per second
        sig, _ = _split_noise(r)
        v = np.abs(np.gradient(sig, r.cols["t_s"])) if sig.size > 1 else np.zeros(sig.size)
        return v * (np.abs(sig) > e_t * big) / big

    per, _, tot = _cumulative(s, shed)
    k = -math.log1p(-th_end) / float(tot[-1]) if tot.size and tot[-1] > 0 else 0.0
    lost = _session_curve(s, {key: l_max * -np.expm1(-k * x) for key, x in per.items()})
    _dry_by(s, lost, lambda t: share * lost(t))


def dh_liposome_bilayer(s: Session) -> None:
    """A bio-IPMC test in a bath of liposomes (a vesicle suspension, 0.1-1 mg/ml of lipid, made up 0-5 min before the
    first record): the vesicles fuse onto the platinum faces into a supported bilayer, its cover growing as (1 - theta)/
    tau_f (tau_f 10-40 min, log), and a drive beyond V_ep (0.6-0.85 V, width 0.03-0.06 V) electroporates it and strips
    it at k_d (0.02-0.1 /s, log) times the wave; the bilayer blocks the ions' exchange over its cover, the loss l_max
    theta (l_max 8-20 %). Sample by sample through the session in time order (growing over the rests): a loss that grows
    at rest and through the small drives and falls through the large ones. Gain x (1 - loss), conductance x (1 - share
    loss) (share 0.3-1); the spectra at the next series' start (inject_fresh9._dry_by). Measured (p8_183: tau_f 12 min,
    V_ep 0.67 V, k_d 0.040 /s, l_max 11.4 %, share 0.55) displacement RMS -3.4 % (residual 3.8 %, 17x its noise),
    current RMS -4.0 % (residual 4.0 %, 2.0x its noise): the 1 V steps at 0.640, 0.630, 0.630, 0.630 mm by their
    plateaus' end (0.648-0.649 mm clean); the 0.5 V sines' gain 0.94-0.95 at 0.45 Hz and 0.92-0.93 at 9.4 Hz, the 1 V
    harmonics' 0.969-0.974 (their crests strip it)."""
    tau_f, lead = lu(s.rng, 600.0, 2400.0), s.rng.uniform(0.0, 300.0)
    v_ep, w, k_d = s.rng.uniform(0.6, 0.85), s.rng.uniform(0.03, 0.06), lu(s.rng, 0.02, 0.1)
    l_max, share = s.rng.uniform(0.08, 0.2), s.rng.uniform(0.3, 1.0)
    theta, t_end, cover = -math.expm1(-lead / tau_f), None, {}
    for r in _chrono(s):
        t, dt = r.cols["t_s"], 1.0 / r.fs
        if t_end is not None:
            theta = 1.0 - (1.0 - theta) * math.exp(-max(float(t[0]) - t_end, 0.0) / tau_f)
        sig, _ = _split_noise(r, "v_V")
        kill = k_d * _rising((np.abs(sig) - v_ep) / w, -v_ep / w)
        out = np.empty(t.size)
        for j, b in enumerate(kill.tolist()):  # d theta/dt = (1 - theta)/tau_f - b theta, exact per sample
            a = 1.0 / tau_f
            e = math.exp(-(a + b) * dt)
            inf = a / (a + b)
            theta = inf + (theta - inf) * e
            out[j] = theta
        cover[id(r)] = out
        t_end = float(t[-1])
    lost = _session_curve(s, {key: l_max * x for key, x in cover.items()})
    _dry_by(s, lost, lambda t: share * lost(t))


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_agnw_joule_welding(s: Session) -> None:
    """A silver-nanowire mesh sprayed over each face's platinum (a lab's recipe for a low surface resistance): a face's
    tension opens the wire junctions, dR/R = k w e+/e_max (k 0.8-2 on one face, drawn, 0.3-0.8 of it on the other; e+
    the face's tension over the session's largest), and the current's Joule heat welds the junctions as it passes, the
    unwelded share w = exp(-J/J_c) of the current's integral of i^2 so far (through the session in time order, w 0.3-0.6
    by its end): a gauge that fades through the session. The two faces' mean; gains fall by 0.03-0.08 (displacement) and
    0.06-0.15 (current) per unit of dR/R (inject_fresh3._resist). Measured (paper_181: k 1.59 and 1.20, w 0.35 by the
    end; gains 0.069 and 0.074) displacement RMS -2.7 % (residual 2.9 %, 170x its noise), current RMS -0.23 % (residual
    0.78 %, 0.59x its noise): the 1 V steps at 8.32, 8.44, 8.52, 8.58 mm by their plateaus' end block by block
    (8.79-8.80 mm clean), their current 0.015-0.035 mA lower; the 1 V harmonics' gain 0.975, 0.981, 0.985, 0.989."""
    ref = ref_disp(s)
    big = (_largest(s) or ref) / ref
    k_a = s.rng.uniform(0.8, 2.0)
    side, k_b = _sign(s), k_a * s.rng.uniform(0.3, 0.8)
    w_end = s.rng.uniform(0.3, 0.6)
    per, _, tot = _cumulative(s, lambda r: r.cols["i_A"] ** 2)
    k = -math.log(w_end) / float(tot[-1]) if tot.size and tot[-1] > 0 else 0.0
    weld = {key: np.exp(-k * x) for key, x in per.items()}

    def law(r: Rec, e: np.ndarray) -> np.ndarray:
        w = weld[id(r)]
        return 0.5 * w * sum(kk * np.clip(sg * e, 0.0, None) / big for sg, kk in ((side, k_a), (-side, k_b)))

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


def sr_woven_mesh_collectors(s: Session) -> None:
    """A woven stainless micromesh pressed onto each face as a current collector (a lab's way to feed a strip along its
    length): the current crosses into the plating at the mesh's crossings, Hertzian contacts whose resistance goes as
    the contact force to the -1/3, and bending loads them: the compressed face's mesh lifts off its crossings, the
    stretched face's presses on, each face's dR/R = (1 - x)^(-1/3) - 1 with x the face's compression over its lift-off
    strain (1.1-1.8 of the session's largest bend on one face, drawn, 1-2 times that on the other; x within +-0.95): up
    steeply on the compressed face, down gently on the stretched one. The two faces' mean; gains fall by 0.03-0.08
    (displacement) and 0.06-0.15 (current) per unit of dR/R (inject_fresh3._resist). Measured (s001_182: lift-off at
    1.28 and 1.74 of the largest bend; gains 0.033 and 0.090) displacement RMS -0.40 % (residual 0.47 %, 15x its noise),
    current RMS -0.086 % (residual 0.35 %, 0.92x its noise): the 1 V steps at 4.63-4.66 mm by their plateaus' end
    (4.67-4.70 mm clean), their current 0.013-0.015 mA lower; the 1 V harmonics' gain 0.9986; the 0.5 V sines
    untouched."""
    ref = ref_disp(s)
    big = (_largest(s) or ref) / ref
    e_a = s.rng.uniform(1.1, 1.8) * big
    side, e_b = _sign(s), e_a * s.rng.uniform(1.0, 2.0)

    def law(r: Rec, e: np.ndarray) -> np.ndarray:
        out = np.zeros(e.size)
        for sg, e0 in ((side, e_a), (-side, e_b)):
            x = np.clip(-sg * e / e0, -0.95, 0.95)  # the face's compression over its lift-off strain
            out += (1.0 - x) ** (-1.0 / 3.0) - 1.0  # Hertzian crossings: R ~ F^(-1/3), F ~ 1 - x
        return 0.5 * out

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_gent_silicone_skin(s: Session) -> None:
    """A strip cast into a thin silicone skin (an Ecoflex-type skin either side, a soft-robotic finger's): the skin adds
    its own bending stiffness, and a rubber's chains stiffen as they near their locking stretch (Gent's law, the stress
    going as 1/(1 - (stretch measure)/J_m)): the tip rests where d = y (1 + kappa q/(1 - q)), q = (y/y_m)^2 (y_m 1.3-2.2
    of the session's largest bend: the skin's lock; kappa set so that the largest bend is held back by h, 0.04-0.12),
    odd, slope 1 at rest (the skin's small-strain stiffness is in the strip's gain already). Tabulated and interpolated
    (inject_fresh33._static_map); displacement only. Measured (p8_183: y_m 1.96 of the largest bend, h 0.115)
    displacement RMS -6.5 % (residual 7.3 %, 33x its noise): the 1 V steps at 0.574-0.575 mm by their plateaus' end
    (0.648-0.649 mm clean) and 0.437 mm 2 s after their fall (0.467 clean); the 1 V harmonics' gain 0.972-0.975; the 0.5
    V sines' 0.9996-1.0000."""
    big = _largest(s) or ref_disp(s)
    y_m, h = s.rng.uniform(1.3, 2.2) * big, s.rng.uniform(0.04, 0.12)
    y_b = big * (1.0 - h)
    q_b = (y_b / y_m) ** 2
    kappa = (big / y_b - 1.0) * (1.0 - q_b) / q_b  # the largest bend held back by h
    yg = np.linspace(-0.999 * y_m, 0.999 * y_m, 8001)
    q = (yg / y_m) ** 2
    dg = yg * (1.0 + kappa * q / (1.0 - q))
    _static_map(s, yg, dg)


def ld_sigma_delta_overrange(s: Session) -> None:
    """The laser's analogue output logged by a 24-bit delta-sigma data logger (its inputs all the DAQ had spare), its
    range set so that the 1 V steps reach 0.8-0.92 of full scale: a second-order modulator stays linear up to a knee
    (0.55-0.75 of full scale) and beyond it overloads softly, its decimated output compressed towards full scale: y = x
    below the knee, knee + (FS - knee) tanh((|x| - knee)/(FS - knee)) beyond, odd. Displacement only; the records that
    stay below the knee untouched. Measured (p8_183: the steps at 0.817 of full scale, the knee at 0.569) displacement
    RMS -0.58 % (residual 1.0 %, 4.7x its noise; the four steps' records 7.9x): the 1 V steps at 0.630 mm by their
    plateaus' end (0.648-0.649 mm clean), as clean 2 s after their fall; every other record (the 1 V harmonics at 0.26
    of the steps) untouched."""
    big = _largest(s) or ref_disp(s)
    fs_m = big / s.rng.uniform(0.8, 0.92)  # the input's full scale in metres of bend
    knee = s.rng.uniform(0.55, 0.75) * fs_m
    soft = fs_m - knee

    def read(r: Rec, x: np.ndarray) -> np.ndarray:
        a = np.abs(x)
        return np.where(a <= knee, x, np.sign(x) * (knee + soft * np.tanh((a - knee) / soft)))

    inject.map_disp(s, read)


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_ups_modified_sine(s: Session) -> None:
    """The laser's controller on a line-interactive UPS that goes to its battery whenever the building's supply sags
    (2-4 brown-outs of 1-6 min, log, each starting inside a recorded series): on the grid the controller's supply-borne
    hum follows the line (1-3 um, log, its third 0.1-0.3), on the battery the UPS's inverter makes a stepped
    ('modified') sine at its own crystal frequency (the nominal +-0.002 Hz), on a share 0.5-0.7 of each half-cycle, its
    odd harmonics sin(n pi duty/2)/(n sin(pi duty/2)) up to the 15th (3-8 um, log), its phase starting afresh at each
    transfer. Displacement only. Measured (p8_183: the grid at 59.984 Hz, 2.3 um with a third of 0.14; the inverter at
    60.0015 Hz, 5.6 um, duty 0.67; brown-outs 25.0, 32.5 and 72.8 min into the session, of 4.9, 1.2 and 2.6 min)
    displacement residual 0.82 % of its RMS (3.7x its noise); every series touched."""
    f_grid = _line_f(s)
    f_inv = round(f_grid) + s.rng.uniform(-0.002, 0.002)
    a_g, h3 = lu(s.rng, 1e-6, 3e-6), s.rng.uniform(0.1, 0.3)
    a_u, duty = lu(s.rng, 3e-6, 8e-6), s.rng.uniform(0.5, 0.7)
    ph_g = s.rng.uniform(0.0, 2.0 * math.pi)
    spells = sorted(_bursts(s, int(s.rng.integers(2, 5)), (60.0, 360.0)))
    phases = s.rng.uniform(0.0, 1.0, len(spells))  # the inverter starts at a phase of its own at each transfer
    amp = {1: 1.0}
    for n in range(3, 16, 2):
        amp[n] = math.sin(n * math.pi * duty / 2.0) / (n * math.sin(math.pi * duty / 2.0))
    for r in s.series():
        t = r.cols["t_s"]
        out = a_g * (np.cos(2 * math.pi * f_grid * t + ph_g) + h3 * np.cos(6 * math.pi * f_grid * t + 3 * ph_g))
        for (a, b), p in zip(spells, phases):
            on = (t >= a) & (t <= b)
            if not np.any(on):
                continue
            x = f_inv * (t[on] - a) + p
            stepped = sum(c * np.sin(2 * math.pi * n * x) for n, c in amp.items())
            out[on] = a_u * stepped
        r.cols["disp_m"] = r.cols["disp_m"] + out


def mp_self_regulating_heat_trace(s: Session) -> None:
    """A self-regulating heat-trace cable (a frost-protection heater along the lab's water pipe behind the bench, its
    PTC polymer core limiting its own current as it warms) switched by its thermostat, on for a share 0.3-0.6 of a cycle
    of 15-60 min (log): at each switch-on the cold cable draws an inrush m (3-5) times its warm current, falling as its
    core warms over tau_h (1-4 min, log), and its field reaches the laser's cable and the current amplifier's input: the
    line (50 or 60 Hz, inject_fresh12._line_f; its third 0.03-0.1, a resistive load) at 1.5-4 um and 8-25 uA (log, each
    its sign) times 1 + (m - 1) exp(-u/tau_h), nothing while off. Displacement and current. Measured (s001_182: 49.984
    Hz, on 11 min of every 24, an inrush of 3.4 decaying over 3.1 min, 4.0 um and 12 uA) displacement residual 0.14 % of
    its RMS (4.6x its noise), current 0.28 % (0.74x): 29 of the 68 series touched, in them 5.1 um and 15 uA RMS (9.2x
    and 1.5x their noise)."""
    f0 = _line_f(s)
    period, duty = lu(s.rng, 900.0, 3600.0), s.rng.uniform(0.3, 0.6)
    m, tau_h = s.rng.uniform(3.0, 5.0), lu(s.rng, 60.0, 240.0)
    h3 = s.rng.uniform(0.03, 0.1)
    ph0 = s.rng.uniform(0.0, 1.0)
    amp = {"disp_m": lu(s.rng, 1.5e-6, 4e-6) * _sign(s), "i_A": lu(s.rng, 8e-6, 2.5e-5) * _sign(s)}
    phase = {col: s.rng.uniform(0.0, 2.0 * math.pi) for col in amp}
    for r in s.series():
        t = r.cols["t_s"]
        u = np.mod(t / period + ph0, 1.0) * period  # seconds since the thermostat's last switch-on
        env = np.where(u < duty * period, 1.0 + (m - 1.0) * np.exp(-u / tau_h), 0.0)
        for col, a in amp.items():
            wt = 2 * math.pi * f0 * t + phase[col]
            r.cols[col] = r.cols[col] + a * env * (np.cos(wt) + h3 * np.cos(3 * wt))


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_burst_mode_reference(s: Session) -> None:
    """The laser controller's analogue output stage referenced to a rail made by a small switching regulator that runs
    in burst mode at its light load (pulse skipping): the rail ripples at the burst rate, f_c (12-35 Hz) wandering by
    +-10-20 % with the load (three slow swings of 2-10 min), and the output's scale ripples with it: y = d (1 + m sin
    phi(t)) (m 0.6-2 %, log), zero staying zero, on the session's clock. A multiplicative modulation at a wandering
    frequency: sidebands about every line of the drive, the steps' plateaus rippling; displacement only. Measured
    (paper_181: f_c 16.3 Hz +-16 %, m 1.5 %; s001_182: 24.4 Hz +-20 %, m 1.3 %) displacement residual 1.05 % and 0.91 %
    of its RMS (60x and 30x its noise); the steps' plateaus +-130 um and +-61 um; the sines' lines within 0.1 % of their
    gain."""
    f_c, dev, m = s.rng.uniform(12.0, 35.0), s.rng.uniform(0.1, 0.2), lu(s.rng, 0.006, 0.02)
    periods, weights = s.rng.uniform(120.0, 600.0, 3), s.rng.uniform(0.5, 1.0, 3)
    phases = s.rng.uniform(0.0, 2 * math.pi, 3)
    weights /= weights.sum()
    ph0 = s.rng.uniform(0.0, 2 * math.pi)

    def phase(t: np.ndarray) -> np.ndarray:  # 2 pi times the integral of f_c (1 + dev sum w_j sin(2 pi t/P_j + phi_j))
        wander = sum(w * -p / (2 * math.pi) * np.cos(2 * math.pi * t / p + q)
                     for w, p, q in zip(weights, periods, phases))
        return 2 * math.pi * f_c * (t + dev * wander) + ph0

    for r in s.series():
        r.cols["disp_m"] = r.cols["disp_m"] * (1.0 + m * np.sin(phase(r.cols["t_s"] - s.t0)))


def out_overwritten_spectrum_file(s: Session) -> None:
    """The impedance analyser's software saving every sweep under the same file name, and the lab's script copying that
    file into the session's folder once, at the end: every spectrum of the manifest is the session's last sweep (the
    highest pressure's), each at its own block's place and pressure. The time series untouched: their contact resistance
    and capacitance follow the clamp's settings, the spectra do not. Measured (s001_182: the 500, 900 and 1300 kPa
    spectra replaced by the 1700 kPa one, |Z| 2-9 % off at 0.1 Hz and 1-3 % at 10 kHz; p8_183: the 612-3062 kPa ones by
    the 4287 kPa one, -2 to +17 % at 0.1 Hz, Re Z at 10 kHz 31.0 ohm for 28.7-31.4)."""
    eis = [r for r in s.recs if not r.series]
    if len(eis) < 2:
        return
    last = eis[-1]
    for r in eis[:-1]:
        r.cols = {c: x.copy() for c, x in last.cols.items()}


def out_feedback_diodes_current(s: Session) -> None:
    """The current read by a home-made transimpedance amplifier whose feedback resistor carries the usual pair of
    antiparallel silicon diodes against overload: they conduct exponentially as the output nears their knee, so the
    output compresses, i = i_read + 2 I_s sinh(i_read/i_T) (the diodes' current a tenth of the total at the knee,
    0.5-0.9 of the largest stepped sine's peak; i_T, n V_T over R_f, an 8th to a 14th of the knee), odd, nothing at the
    small currents. The current only: the fast sines' crests and every step's charging spike read short, the slow
    records untouched. Measured (paper_181: the knee at 10.3 mA, i_T 1.2 mA; s001_182: 7.8 mA, 0.64 mA) current RMS -2.5
    % and -2.2 % (residual 4.8 % and 5.2 %, 3.6x and 14x its noise): the 20 Hz sines' current at 0.95-0.96 of its gain,
    the 9.4 Hz ones' 0.97-0.98; the steps' plateaus within 0.3 uA."""
    i_max = _largest(s, "i_A")
    sines = [r for r in s.series() if r.kind == "stepped_sine"] or s.series()
    i_sine = max(float(np.max(np.abs(r.cols["i_A"]))) for r in sines)
    knee = s.rng.uniform(0.5, 0.9) * i_sine  # where the diodes carry a tenth of the current
    i_t = knee / s.rng.uniform(8.0, 14.0)  # n V_T / R_f in current units: the diodes' exponential scale
    i_s = 0.1 * knee / (2.0 * math.sinh(knee / i_t))

    def true_of(read: np.ndarray) -> np.ndarray:
        return read + 2.0 * i_s * np.sinh(read / i_t)

    top = 1.05 * i_max
    inverse = _invert_odd(true_of, top, 20001)
    for r in s.series():
        r.cols["i_A"] = inverse(r.cols["i_A"])


def out_zero_filled_last_buffer(s: Session) -> None:
    """A logger that writes every record in whole buffers of N samples (256, 512 or 1024, drawn for the session) and
    writes the record's last, partial buffer out in full, its unfilled slots as the buffer was allocated, zero: every
    time series carries up to N - 1 rows more, its clock going on at its rate, the drive, the current and the
    displacement zero there (the strip still bent), the load cell (merged from its own indicator's stream) at its last
    reading. Measured (paper_181: buffers of 256, 9300 rows added over the 68 series, each step's last 220 rows zero
    where the strip was still at 3.14 mm; p8_183: 512, 14420 rows, the steps' 0.22 mm)."""
    n_buf = int(s.rng.choice([256, 512, 1024]))
    for r in s.series():
        n = r.cols["t_s"].size
        extra = (-n) % n_buf
        if extra == 0:
            continue
        dt = float(np.median(np.diff(r.cols["t_s"])))
        t = np.r_[r.cols["t_s"], r.cols["t_s"][-1] + dt * np.arange(1, extra + 1)]
        cols = {}
        for c, x in r.cols.items():
            if c == "t_s":
                cols[c] = t
            elif c == "force_N":
                cols[c] = np.r_[x, np.full(extra, x[-1])]  # the indicator's stream, merged on after
            else:
                cols[c] = np.r_[x, np.zeros(extra)]
        r.cols = cols


FRESH37_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"nanoporous_gold_faces": br_nanoporous_gold_faces,
                        "rhodamine_dye_uptake": br_rhodamine_dye_uptake},
    "faradaic_current": {"persulfate_frumkin_ndr": far_persulfate_frumkin_ndr,
                         "sealed_cuvette_oxygen": far_sealed_cuvette_oxygen},
    "hysteresis": {"reinforced_membrane_fibres": hy_reinforced_membrane_fibres,
                   "miniature_bearing_rollers": hy_miniature_bearing_rollers},
    "time_delay": {"coarse_tick_stamps": td_coarse_tick_stamps, "phone_vfr_video": td_phone_vfr_video},
    "sensor_offset": {"hotmelt_glued_bracket": so_hotmelt_glued_bracket,
                      "gooseneck_creep_jumps": so_gooseneck_creep_jumps},
    "clamp_relaxation": {"galvanic_oxide_jacking": cr_galvanic_oxide_jacking, "pi_clamp_ringing": cr_pi_clamp_ringing},
    "dehydration": {"ultrasonic_loosened_plating": dh_ultrasonic_loosened_plating,
                    "liposome_bilayer": dh_liposome_bilayer},
    "strain_resistance": {"agnw_joule_welding": sr_agnw_joule_welding,
                          "woven_mesh_collectors": sr_woven_mesh_collectors},
    "large_deflection": {"gent_silicone_skin": ld_gent_silicone_skin,
                         "sigma_delta_overrange": ld_sigma_delta_overrange},
    "mains_pickup": {"ups_modified_sine": mp_ups_modified_sine,
                     "self_regulating_heat_trace": mp_self_regulating_heat_trace},
    "unexplained": {"burst_mode_reference": out_burst_mode_reference,
                    "overwritten_spectrum_file": out_overwritten_spectrum_file,
                    "feedback_diodes_current": out_feedback_diodes_current,
                    "zero_filled_last_buffer": out_zero_filled_last_buffer},
}
inject.register_forms(FRESH37_FORMS)


# ------------------------------------------------------------------------------------------------ variants

FAT_TICK = 2.0  # s: a FAT32 file system's modification-time resolution


def v_file_mtime_clock(s: Session) -> None:
    """A standalone data logger writing each record to its own file on a FAT32 memory card, and the lab's merge script
    placing each record on the session clock by its file's modification time (the record's end: the file closed 0.05-0.5
    s after the last sample, drawn for the session), which FAT keeps to 2 s, floored (the ticks' phase drawn), the rows
    within the file from the logger's sample clock: every time series moved whole by -2 to +0.5 s, its spacing, its
    values and the records' order untouched; the spectra untouched. The import contract asks of a time series only a
    strictly increasing t_s; ``labrig import`` takes it (the records still on one clock, the rests a little off) and
    ``labrig export`` writes the records back, their values as written."""
    lat, ph = s.rng.uniform(0.05, 0.5), s.rng.uniform(0.0, FAT_TICK)
    for r in s.series():
        t = r.cols["t_s"]
        end = float(t[-1])
        mtime = FAT_TICK * math.floor((end + lat - ph) / FAT_TICK) + ph
        r.cols["t_s"] = t + (mtime - end)


inject.VARIANTS.update({"file_mtime_clock": v_file_mtime_clock})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_181", "s001_182", "p8_183"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 7 / 6 effect cases on seeds 181-183
    "back_relaxation": [("rhodamine_dye_uptake", 181, P, "eis_descending"),
                        ("nanoporous_gold_faces", 183, T, "rate07")],
    "faradaic_current": [("persulfate_frumkin_ndr", 181, P, "trigger_clock"),
                         ("sealed_cuvette_oxygen", 183, T, "dropped_packets")],
    "hysteresis": [("miniature_bearing_rollers", 181, P, "settled_sines"),
                   ("reinforced_membrane_fibres", 182, S, "log_steps")],
    "time_delay": [("coarse_tick_stamps", 181, P, "own_clock"), ("phone_vfr_video", 182, S, "block_clock")],
    "sensor_offset": [("hotmelt_glued_bracket", 181, P, "float32_time"),
                      ("gooseneck_creep_jumps", 182, S, "spectra_last")],
    "clamp_relaxation": [("galvanic_oxide_jacking", 181, P, "channel_order"),
                         ("pi_clamp_ringing", 182, S, "short_pretrigger")],
    "dehydration": [("ultrasonic_loosened_plating", 182, S, "eis_two_passes"),
                    ("liposome_bilayer", 183, T, "merged_loadcell")],
    "strain_resistance": [("agnw_joule_welding", 181, P, "swinging_door"),
                          ("woven_mesh_collectors", 182, S, "midnight_clock")],
    "large_deflection": [("gent_silicone_skin", 183, T, "reversed_laser"),
                         ("sigma_delta_overrange", 183, T, "file_mtime_clock")],
    "mains_pickup": [("self_regulating_heat_trace", 182, S, "minimal_manifest"),
                     ("ups_modified_sine", 183, T, "harmonics_as_free")],
    "unexplained": [("burst_mode_reference", 181, P, "stop_trigger"),
                    ("burst_mode_reference", 182, S, "coherent_sines"),
                    ("overwritten_spectrum_file", 182, S, "steps_sines"),
                    ("overwritten_spectrum_file", 183, T, "two_pressures"),
                    ("feedback_diodes_current", 181, P, "loadcell_dropout"),
                    ("feedback_diodes_current", 182, S, "file_mtime_clock"),
                    ("zero_filled_last_buffer", 181, P, "measured_pressures"),
                    ("zero_filled_last_buffer", 183, T, "edge_files")],
}
CLEAN = [(181, P, "file_mtime_clock"), (181, P, "no_loadcell"), (182, S, "file_mtime_clock"),
         (182, S, "tared_records"), (183, T, "no_spectra"), (183, T, "cathodic_positive")]


def fresh37_cases(only: str | None = None) -> list[Case]:
    """The thirty-eighth held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds
    181-183)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh37_cases, "inject_fresh37", "fresh37")
