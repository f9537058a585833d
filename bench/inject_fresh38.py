"""A thirty-ninth held-out set for the diagnosis (issue 12), fresh38, written without sight of the diagnosis (its code,
its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh37.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (oxalic acid from a rust remover whose
oxidation the platinum's own oxide blocks, a felt pad whose leaning fibres rub the tip harder one way than the other, a
tacky silicone gel stop that snaps the tip in and lets it go only at its pull-off, a logging script's speed-adaptive
'one euro' filter, a silver-plated thread as a current collector whose filaments pack and then crack, a fibre pair read
through its Gaussian coupling, a sealed air chamber that the tip squeezes and draws out) and some on the history, the
clamp pressure or the session's events (sucrose drawn into the faces with the back-flow, a PNIPAM skin collapsing as a
heated holder overshoots after each re-clamping, sodium borohydride left in each face by the plating, a hydraulic
clamp's trapped air bubble dissolving faster the harder it is set, a ductile gold plating whose cracks close behind a
growing plastic wake, a vacuum chamber pumped down at one re-clamping, a Peltier holder stepping the bath's temperature
down block by block) and some on time (a fold mirror's RTV silicone curing as it creeps, a rail carriage's brake
slipping in regular jerks, alginate pads losing their calcium to a phosphate buffer, a laser streamed through a slip
buffer on its own clock, an oven's chattering contactor heard by a strip in air, a glassware washer running its
program); lab wiring or sensors among them (the felt guide, the gel stop, the one euro filter, the slip buffer, the
periscope mirror, the rail carriage, the hydraulic clamp, the thread collector, the fibre pair, the air chamber, the
contactor and the washer). Four structures outside the catalogue (truth "unexplained": a miniature filament lamp in
series with the drive as its indicator, the monitor before it; every spectrum's frequency column one sweep point ahead
of its impedance; the laser controller's output stage warming its own reference, a zero that follows the output's recent
dissipation; the plating wrapped round one cut edge, a leak between the faces that the bend cracks open); clean
sessions. All on three bases of new seeds (184-186: the paper strip, the seed-001 strip on its own sweep, the paper
strip 7 mm free) and on the earlier sets' data-shape variants plus one new here: every time series that a logger's
periodic file rotation cut written as consecutive records (``rotated_files``).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh37 are reused (importing inject_fresh37 and inject_fresh36 registers every earlier set's
lookups), and the forms, bases, preset and variant of this set are registered into inject's lookups at import, none
replaced. Strengths are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it
made on its case, measured in memory against the clean base (relative RMS change over all series, form only, no variant;
"noise": the column's sample-to-sample noise at rest, inject_fresh15.rest_noise).

Run: python bench/inject_fresh38.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np

import inject
import inject_fresh36  # noqa: F401  (registers fresh36's and, through fresh34 and fresh32, fresh30's lookups)
import inject_fresh37  # noqa: F401  (registers fresh37's and, through fresh35 and fresh33, every other earlier set's)
from inject import Case, Rec, Session, lu, ref_disp
from inject_fresh2 import _chrono
from inject_fresh3 import _resist, _sign
from inject_fresh4 import _clamp_law
from inject_fresh9 import _dry_by
from inject_fresh10 import _lag_varying, _station
from inject_fresh12 import _line_f
from inject_fresh14 import _largest
from inject_fresh22 import _f1
from inject_fresh25 import _setting_of
from inject_fresh26 import _split_noise
from inject_fresh33 import _static_map, _through_strip
from inject_fresh34 import _cumulative, _rising
from inject_fresh35 import _session_curve

# the paper's strip 7 mm free (earlier sets used 8-45 mm, 30 mm is the paper preset itself and the seed-001 strip is
# 20 mm; 46 mm and beyond would put the 1 V step near the laser's range): its 1 V step peaks at 0.50 mm, well inside the
# laser's +-20 mm (2 mm/V on the DAQ's +-10 V) and some 870x the laser's 0.57 um noise at rest; its first mode at 59 Hz
# (the four pressures), above the sines' top (20 Hz). Preset "paper_7", base "p7_186", registered in every process
# importing this module
inject.register_free_length("paper_7", 0.007)

inject.BASES.update({
    "paper_184": ("paper-sweep", "paper", 184),
    "s001_185": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 185),
    "p7_186": ("paper-sweep", "paper_7", 186),
})

KELVIN = 273.15


# ------------------------------------------------------------------------------------------------ tools


def _grid(s: Session, dt: float, lead: float = 0.0) -> np.ndarray:
    """An even grid of step dt over the session (from ``lead`` seconds before its first sample to its last)."""
    return np.arange(s.t0 - lead, s.t1 + dt, dt)


def _exact_lag(x: np.ndarray, tau: np.ndarray | float, dt: float, y0: float) -> np.ndarray:
    """y following x at 1/tau on an even grid (x and tau held over each step), from y0: exact per step."""
    a = np.exp(-dt / np.broadcast_to(np.asarray(tau, float), x.shape))
    y, out = float(y0), np.empty(x.size)
    for k, (xk, ak) in enumerate(zip(x.tolist(), a.tolist())):
        y = xk + (y - xk) * ak
        out[k] = y
    return out


def _signal_rate(r: Rec) -> np.ndarray:
    """The displacement's signal's rate of change (m/s; inject_fresh26._split_noise, no sensor noise)."""
    sig, _ = _split_noise(r)
    return np.gradient(sig, r.cols["t_s"]) if sig.size > 1 else np.zeros(sig.size)


def _face_of_anode(v: np.ndarray, sgn: float) -> np.ndarray:
    """The face's anodic drive (face A, sgn +1, the anode for v > 0)."""
    return sgn * v


def _walk_station(s: Session, walk: Callable[[np.ndarray], np.ndarray], m0: float) -> None:
    """The laser's station walking inboard from a margin m0 inside the tip's end by walk(t) (m, growing), read through
    the beam's own transfer functions (inject_fresh10._station)."""
    length = float(s.specimen["length_m"])
    first = 1.0 - m0 / length
    last = first - float(walk(np.array([s.t1]))[0]) / length
    _station(s, lambda r: first - walk(r.cols["t_s"]) / length, min(last, first) - 1e-9)


# ------------------------------------------------------------------------------------------------ back relaxation


def br_pnipam_lcst_skin(s: Session) -> None:
    """Both faces coated with a thin PNIPAM hydrogel skin (a soft-robotics lab's thermoresponsive coat), through which
    the back-flow is exchanged with the bath: above its lower critical solution temperature (T_c 31-33 C) the gel
    collapses and passes water 2-6 times worse (a 1-5) than swollen below it, its state following the temperature
    through the gel's own volume transition (a lag tau_g 20-90 s, log; a logistic width 0.3-0.8 K). The bath is held a
    little above T_c (0.3-1.2 K) by a heated cuvette holder, but at each re-clamping the lid is off and the operator's
    hand and tools cool it by dT (2.5-5 K) at the setting (inject_fresh25._setting_of), after which the holder's loop
    brings it back with an overshoot, T_set - dT exp(-u/tau_h) cos(2 pi u/P) (tau_h 60-180 s, P 2.5-4 tau_h): the skin
    swells open for the block's first minutes, then collapses again. The back-flow's share K2 (0.5-0.9), its time
    constant tau_0 (1 + a (1 - o)) (tau_0 1.5-5 s, log; o the skin's openness, 0 collapsed, 1 swollen). Through
    inject_fresh10._lag_varying (sample by sample through the session, carried over the rests); displacement only.
    Measured (p7_186: K2 0.69, tau_0 5.0 s, a 1.54, T_c 31.05 C held 0.58 K above, the dip 4.35 K, tau_h 84 s: tau 10.2
    s with the skin collapsed, 6.4 s at the blocks' first minutes) displacement RMS -57 % (residual 66 %, 219x its
    noise): the 1 V steps at 0.193-0.196 mm by their plateaus' end (0.498-0.499 mm clean) and 0.058-0.060 mm 2 s after
    their fall (0.357 clean); the 1 V harmonics' gain 0.993 (+5.8 deg), the 0.1 Hz sines' 0.988 (+6.4 deg), the 0.45 Hz
    ones' 0.999 (+1.4 deg)."""
    k2, tau0, a = s.rng.uniform(0.5, 0.9), lu(s.rng, 1.5, 5.0), s.rng.uniform(1.0, 5.0)
    t_c, width, tau_g = s.rng.uniform(31.0, 33.0), s.rng.uniform(0.3, 0.8), lu(s.rng, 20.0, 90.0)
    above, dip, tau_h = s.rng.uniform(0.3, 1.2), s.rng.uniform(2.5, 5.0), s.rng.uniform(60.0, 180.0)
    period = tau_h * s.rng.uniform(2.5, 4.0)
    setting = _setting_of(s)
    firsts: dict[float, float] = {}
    for r in s.series():
        p = float(r.entry["pressure_kPa"])
        firsts[p] = min(firsts.get(p, np.inf), float(r.cols["t_s"][0]))
    sets = np.sort([setting(p, t) for p, t in firsts.items()])
    dt = 0.5
    g = _grid(s, dt, lead=max(0.0, s.t0 - float(sets[0])) + 600.0)
    k = np.searchsorted(sets, g, side="right") - 1
    u = np.where(k >= 0, g - sets[np.clip(k, 0, None)], np.inf)
    temp = t_c + above - np.where(np.isfinite(u), dip * np.exp(-np.minimum(u, 1e9) / tau_h)
                                  * np.cos(2 * math.pi * np.minimum(u, 1e9) / period), 0.0)
    o_eq = 1.0 / (1.0 + np.exp(np.clip((temp - t_c) / width, -60.0, 60.0)))
    o = _exact_lag(o_eq, tau_g, dt, float(o_eq[0]))

    def state(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        t = np.asarray(t, float)
        return np.full(t.shape, k2), tau0 * (1.0 + a * (1.0 - np.interp(t, g, o)))

    _lag_varying(s, state)


def br_sucrose_density_medium(s: Session) -> None:
    """A strip tested in a sucrose solution (15-30 % by mass: a swimming-robot lab's density matching, so that the strip
    neither sinks nor floats) whose back-flow is exchanged with the bath through its faces: the side a bend leaves short
    of water (the concave anode side) draws it back from the bath, and with it sucrose into its face's outer pores,
    where it raises the water's viscosity (exp(b c), b so that a fully loaded layer is 2-4 times as viscous, log) and
    slows the exchange through that face; the sugar diffuses back out over tau_out (5-20 min, log). Each face's load c
    (0-1, of the bath's) grows with the water it draws in, k q (1 - c), q that face's inflow (the rate at which the bend
    moves towards making it concave, in largest bends a second, read off the displacement's signal), k set so that the
    busier face reaches 0.4-0.8 at its most; through the session in time order on a 0.2 s grid, washing out over the
    rests. The back-flow (K2 0.5-0.9) returns through the face that is drawing water for the bend's sign, tau = tau_0
    exp(b c_face) (tau_0 1.5-6 s, log). Through inject_fresh10._lag_varying; displacement only. Measured (paper_184: K2
    0.86, tau_0 4.5 s, a full layer 2.1 times as viscous, tau_out 6.7 min, the busier face to 0.51: tau 4.5 s at the
    start, up to 6.0 s after each block's sines) displacement RMS -70 % (residual 82 %, 4900x its noise): the 1 V steps
    at 1.82, 1.89, 1.90, 1.90 mm by their plateaus' end block by block (8.82-8.83 mm clean) and -0.14 to -0.11 mm 2 s
    after their fall (6.64 clean); the 1 V harmonics' gain 0.962 (+15.6 deg) in the first block, 0.967 (+14.6 deg) in
    the last; the 0.45 Hz sines' 0.998 (+2.9 deg)."""
    k2, tau0 = s.rng.uniform(0.5, 0.9), lu(s.rng, 1.5, 6.0)
    b, tau_out, top = math.log(lu(s.rng, 2.0, 4.0)), lu(s.rng, 300.0, 1200.0), s.rng.uniform(0.4, 0.8)
    big = _largest(s) or ref_disp(s)
    dt = 0.2
    g = _grid(s, dt)
    inflow = {}
    for sg in (1.0, -1.0):  # face A (sgn +1) concave for a positive bend: it draws water while the bend grows positive
        _, ts, tot = _cumulative(s, lambda r, sg=sg: np.clip(sg * _signal_rate(r), 0.0, None) / big)
        cum = np.interp(g, ts, tot, left=0.0)
        inflow[sg] = np.diff(cum, prepend=cum[0]) / dt

    def load(kin: float) -> dict[float, np.ndarray]:
        out = {}
        for sg, q in inflow.items():  # dc/dt = kin q (1 - c) - c/tau_out: exact per step with q held
            rate = kin * q + 1.0 / tau_out
            eq = np.where(rate > 0, kin * q / rate, 0.0)
            out[sg] = _exact_lag(eq, 1.0 / rate, dt, 0.0)
        return out

    lo, hi = 1e-3, 1e3  # the uptake constant that brings the busier face to ``top`` at its most (bisection in log)
    for _ in range(40):
        mid = math.sqrt(lo * hi)
        peak = max(float(np.max(c)) for c in load(mid).values())
        lo, hi = (mid, hi) if peak < top else (lo, mid)
    c = load(math.sqrt(lo * hi))
    bend = _session_curve(s, {id(r): _split_noise(r)[0] for r in s.series()})

    def state(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        t = np.asarray(t, float)
        w = 0.5 * (1.0 + np.tanh(bend(t) / (0.05 * big)))  # a positive bend: face A draws the water back
        cf = w * np.interp(t, g, c[1.0]) + (1.0 - w) * np.interp(t, g, c[-1.0])
        return np.full(t.shape, k2), tau0 * np.exp(b * cf)

    _lag_varying(s, state)


# ------------------------------------------------------------------------------------------------ faradaic current


def far_borohydride_plating_residue(s: Session) -> None:
    """A strip plated by impregnation-reduction whose reducing bath (sodium borohydride) was not washed out: each face's
    outer layer keeps a reservoir of borohydride, which platinum oxidises almost at once whenever that face is the anode
    (a wave from E_b 0.03-0.12 V of drive, width 0.03-0.06 V, to i_b 0.2-0.6 mA, log, times the face's remaining share
    r). Each face's share falls with the charge its own wave passes (8 electrons a molecule: the face's content 3-6
    times the charge its wave would pass over the session at full strength) and by the borohydride's hydrolysis, which
    platinum catalyses, over tau_h (40-120 min, log, through the rests too; the strip mounted 0-600 s before the first
    record): r = exp(-A - (t - t_m)/tau_h), A the face's charge so far over its content. An odd, nearly square wave of
    current on every record with a drive beyond a tenth of a volt, each face its own and both fading; the current only.
    Measured (paper_184: i_b 0.42 mA, E_b 0.05 V, the faces' contents 4.2 and 4.8 times their full-strength charge,
    tau_h 53 min, mounted 3 min before) current RMS +3.8 % (residual 6.3 %, 4.7x its noise): the 1 V steps' plateau
    current 1.00, 0.84, 0.75, 0.70 mA block by block (0.57-0.61 mA clean); the 1 V harmonics' current gain 1.084 (-3.6
    deg) to 1.027 (-1.3 deg), the 0.1 Hz sines' 1.073 (-3.2 deg) to 1.008."""
    i_b, e_b, w = lu(s.rng, 2e-4, 6e-4), s.rng.uniform(0.03, 0.12), s.rng.uniform(0.03, 0.06)
    tau_h, lead = lu(s.rng, 2400.0, 7200.0), s.rng.uniform(0.0, 600.0)
    mult = {1.0: s.rng.uniform(3.0, 6.0), -1.0: s.rng.uniform(3.0, 6.0)}
    t_m = s.t0 - lead
    wave = {}
    for r in s.series():
        v = r.cols["v_V"]
        wave[id(r)] = {sg: _rising((_face_of_anode(v, sg) - e_b) / w, -e_b / w) for sg in (1.0, -1.0)}
    out = {id(r): np.zeros(r.cols["t_s"].size) for r in s.series()}
    for sg in (1.0, -1.0):
        per, _, tot = _cumulative(s, lambda r, sg=sg: i_b * wave[id(r)][sg])
        content = mult[sg] * (float(tot[-1]) if tot.size and tot[-1] > 0 else 1.0)
        for r in s.series():  # dr/dt = -(i_b wave r)/Q0 - r/tau_h, so ln r = -X/Q0 - (t - t_m)/tau_h exactly, X the
            t = r.cols["t_s"]  # face's full-strength charge so far (through the session in time order)
            lnr = -per[id(r)] / content - (t - t_m) / tau_h
            out[id(r)] = out[id(r)] + sg * i_b * wave[id(r)][sg] * np.exp(lnr)
    for r in s.series():
        r.cols["i_A"] = r.cols["i_A"] + out[id(r)]


def far_oxalic_cleaner_oxide_gated(s: Session) -> None:
    """The stainless clamp cleaned with an oxalic-acid rust remover (a bar-keeper's powder) and rinsed too briefly: a
    few mM of oxalate in the bath, which platinum oxidises to CO2 on whichever face is the anode, a wave from E_x
    (0.3-0.5 V of drive, width 0.04-0.08 V) to i_x (0.3-0.8 mA, log), but only on bare platinum: beyond E_pt (0.6-0.8 V)
    the face's own oxide grows (towards a logistic coverage of width 0.03-0.06 V, over tau_ox 0.05-0.5 s, log) and
    blocks it, and the oxide is reduced again only once the face's drive has fallen below E_pt - 0.2-0.4 V (over tau_red
    0.1-1 s, log): i = i_x wave (1 - theta). Each face's coverage sample by sample through the session in time order
    (kept over the rests, where it is reduced). The 1 V steps' current rising and then shut off by the oxide, the 1 V
    harmonics' crests blocked until the drive has come well down (a loop), the 0.5 V sines' wave unhindered; the current
    only. Measured (paper_184: i_x 0.40 mA, E_x 0.40 V, the oxide from 0.71 V, reduced below 0.49 V, tau_ox 63 ms)
    current RMS +3.3 % (residual 4.8 %, 3.7x its noise): the 1 V steps' current up by the wave at their edges and back
    to within 0.2 uA of clean by their plateaus' end (the oxide), the 1 V harmonics' current gain 1.021-1.023 (+0.2 deg:
    their crests blocked), the 0.5 V sines' 1.039-1.041 (-1.9 deg) at 0.1 Hz and 1.010 at 20 Hz (unblocked)."""
    i_x, e_x, w_x = lu(s.rng, 3e-4, 8e-4), s.rng.uniform(0.3, 0.5), s.rng.uniform(0.04, 0.08)
    e_pt, w_o = s.rng.uniform(0.6, 0.8), s.rng.uniform(0.03, 0.06)
    e_red = e_pt - s.rng.uniform(0.2, 0.4)
    tau_ox, tau_red = lu(s.rng, 0.05, 0.5), lu(s.rng, 0.1, 1.0)
    theta = {1.0: 0.0, -1.0: 0.0}
    t_end = None
    for r in _chrono(s):
        v, _ = _split_noise(r, "v_V")
        t, dt = r.cols["t_s"], 1.0 / r.fs
        extra = np.zeros(v.size)
        for sg in (1.0, -1.0):
            u = _face_of_anode(v, sg)
            th = theta[sg]
            if t_end is not None:  # reduced over the rest (the drive at zero, below E_red)
                th *= math.exp(-max(float(t[0]) - t_end, 0.0) / tau_red)
            grow = _rising((u - e_pt) / w_o, -e_pt / w_o)
            a_ox, a_red = math.exp(-dt / tau_ox), math.exp(-dt / tau_red)
            cov = np.empty(v.size)
            for k, (uk, gk) in enumerate(zip(u.tolist(), grow.tolist())):
                if gk > th:
                    th = gk + (th - gk) * a_ox
                elif uk < e_red:
                    th *= a_red
                cov[k] = th
            theta[sg] = th
            extra += sg * i_x * _rising((u - e_x) / w_x, -e_x / w_x) * (1.0 - cov)
        r.cols["i_A"] = r.cols["i_A"] + extra
        t_end = float(t[-1])


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_felt_nap_guide(s: Session) -> None:
    """A strip of felt (or a velvet ribbon) set against the tip's face as a soft guide against sideways swinging, its
    fibres leaning one way (the nap, drawn): the tip sliding against the nap meets f_a (0.6-1.5 % of the session's
    largest bend in tip units, log), with the nap only f_a/rho (rho 2-4), and before sliding the fibres bend over a pre-
    sliding travel of 0.3-1.5 f_a: Dahl's law, df/dy = (s F(s) - f)/delta_p along the tip's own move y (s its direction,
    F(s) the limit that way), rate-independent, held over the rests. The tip lags behind the free bend by f: loops
    shifted towards the nap's side, their width f_a (1 + 1/rho). Solved exactly along the tip's own move, sample by
    sample through the session in time order, the laser's noise kept; displacement only. Measured (p7_186: f_a 5.1 um,
    rho 2.4, the nap against a positive bend, a pre-sliding travel of 0.97 f_a) displacement RMS -0.58 % (residual 1.5
    %, 5.0x its noise): the 0.5 V sines at 0.985 (-3.7 deg) at 0.1 Hz, 0.93 (-6.8 deg) at 0.45 Hz, 0.74 (-10 deg) at 3
    Hz and 0.60-0.63 (-5 to -7 deg) at 9.4 and 20 Hz (their few um rubbed away); the 1 V harmonics 0.991 (-2.0 deg); the
    steps 2.3 um short on their plateaus and 0.9 um long after their fall."""
    big = _largest(s) or ref_disp(s)
    f_a, rho = lu(s.rng, 0.006, 0.015) * big, s.rng.uniform(2.0, 4.0)
    nap = _sign(s)
    delta = s.rng.uniform(0.3, 1.5) * f_a
    lim = {nap: f_a, -nap: f_a / rho}  # against the nap (the tip moving opposite to the fibres' lean), with it
    f, last = 0.0, None
    for r in _chrono(s):
        sig, noise = _split_noise(r)
        dd = np.diff(sig, prepend=sig[0] if last is None else last).tolist()
        out = np.empty(sig.size)
        for k, (x, dx) in enumerate(zip(sig.tolist(), dd)):
            if dx != 0.0:  # f_new = target + (f - target) exp(-u/delta) along the tip's own move u = |dx - df|:
                sgn = 1.0 if dx > 0 else -1.0  # u + A (1 - exp(-u/delta)) = |dx|, A = sgn (target - f) >= 0,
                a, big_a = abs(dx), max(lim[sgn] - sgn * f, 0.0)  # solved by Newton from the left (concave, rising)
                u = 0.0
                for _ in range(6):
                    ex = math.exp(-u / delta)
                    u -= (u + big_a * (1.0 - ex) - a) / (1.0 + big_a / delta * ex)
                f += sgn * (a - min(max(u, 0.0), a))
            out[k] = x - f
        r.cols["disp_m"] = out + noise
        last = float(sig[-1])


def hy_tacky_gel_stop(s: Session) -> None:
    """A pad of tacky silicone gel (a Gel-Pak-type pad, or a bumper of PDMS cast that day and still tacky) glued in the
    cuvette on one side of the tip's path (drawn) as a soft stop, at a gap of 0.7-0.95 of the session's largest bend on
    that side: reaching it, the tip is pulled in by the gel's adhesion (A, 1-3 % of the largest bend in tip units) and
    pressed into it against a Hertzian force (K delta^1.5, K set so that the largest bend is held back by 0.03-0.08 of
    its excess over the gap); drawing back, the adhesive neck holds the tip at A beyond the free bend until it has
    stretched by delta_c (0.5-2 A) past the pad's surface, where it lets go (the pull-off). A contact state sample by
    sample through the session in time order; a loop at the stop's side only, the same at any rate. The displacement's
    signal through it (inject_fresh26._split_noise), the noise kept; displacement only. Measured (s001_185: the stop on
    the positive side at 0.75 of the 4.72 mm largest bend, A 61 um, h 0.043, delta_c 1.17 A) displacement residual 0.62
    % of its RMS (20x its noise; 32 of the 68 series touched, 27x there): the 1 V steps at 4.641-4.667 mm by their
    plateaus' end (4.688-4.718 mm clean) and held at 3.635-3.641 mm 2 s after their fall (3.576-3.583 clean: the neck);
    the 1 V harmonics' crests pressed in and let go late; the 0.5 V sines untouched."""
    side = _sign(s)
    big = max(float(np.max(side * _split_noise(r)[0])) for r in s.series()) or ref_disp(s)
    gap = s.rng.uniform(0.7, 0.95) * big
    adh, h = lu(s.rng, 0.01, 0.03) * big, s.rng.uniform(0.03, 0.08)
    neck = s.rng.uniform(0.5, 2.0) * adh
    y_b = big - h * (big - gap)
    kk = (big - y_b + adh) / (y_b - gap) ** 1.5
    dg = np.linspace(0.0, 3.0 * (big - gap + adh) + adh, 4001)  # indentations: x - gap + A = delta + K delta^1.5
    lhs = dg + kk * dg**1.5

    def in_contact(xs: np.ndarray) -> np.ndarray:  # the tip's rest y (side-relative) for the free bend xs, in contact
        z = xs - gap + adh
        return np.where(z >= 0.0, gap + np.interp(z, lhs, dg), xs + adh)

    stuck = False
    for r in _chrono(s):
        sig, noise = _split_noise(r)
        x = side * sig
        y = x.copy()
        touch = x >= gap
        lose = x < gap - neck - adh
        k = 0
        n = x.size
        while k < n:
            if not stuck:
                nxt = int(np.argmax(touch[k:])) + k if np.any(touch[k:]) else n
                k = nxt
                if k < n:
                    stuck = True
            else:
                nxt = int(np.argmax(lose[k:])) + k if np.any(lose[k:]) else n
                y[k:nxt] = in_contact(x[k:nxt])
                k = nxt
                if k < n:
                    stuck = False
        r.cols["disp_m"] = side * y + noise


# ------------------------------------------------------------------------------------------------ time delay


def td_one_euro_logger(s: Session) -> None:
    """The lab's logging script smooths the laser's channel with the 'one euro' filter (Casiez et al., a speed-adaptive
    low-pass popular in tracking software): an exponential smoothing whose cut-off rises with the reading's speed, f_c =
    f_min + beta abs(dx/dt) (f_min 15-40 Hz, log, set to pass the 20 Hz sines; beta so that the fastest sines open it m
    3-10 times, log), the speed taken from the new reading less the last smoothed one through a 1 Hz low-pass; restarted
    on each record's first sample. A delay of 1/(2 pi f_c) that is long on the slow records and at rest and short on the
    fast moves, its amount set by speed, not frequency; the noise at rest much reduced. Sample by sample per record;
    displacement only. Measured (paper_184: f_min 35 Hz, m 5.9) displacement residual 0.060 % of its RMS (3.6x its
    noise): the 20 Hz sines at 0.85-0.86 (-28 deg), the 9.4 Hz ones at 0.955 (-14 deg), the 3 Hz ones (the fastest) at
    1.003 (-2.7 deg), the 0.45 Hz ones -0.4 deg; the steps' edges lagging 1-2 samples."""
    f_min, m = lu(s.rng, 15.0, 40.0), lu(s.rng, 3.0, 10.0)
    f_d = 1.0
    sines = [r for r in s.series() if r.kind == "stepped_sine"] or s.series()
    v_ref = max(float(np.max(np.abs(_signal_rate(r)))) for r in sines) or 1.0
    beta = (m - 1.0) * f_min / v_ref
    for r in s.series():
        x = r.cols["disp_m"]
        dt = 1.0 / r.fs
        a_d = 1.0 / (1.0 + 1.0 / (2 * math.pi * f_d * dt))
        y, dy = float(x[0]), 0.0
        out = np.empty(x.size)
        for k, xk in enumerate(x.tolist()):
            dy += a_d * ((xk - y) / dt - dy)  # the speed, low-passed at f_d
            fc = f_min + beta * abs(dy)
            y += (xk - y) / (1.0 + 1.0 / (2 * math.pi * fc * dt))
            out[k] = y
        r.cols["disp_m"] = out


def td_slip_buffer_resync(s: Session) -> None:
    """The laser streams on its own crystal (f_L 200-1000 Hz, log), 50-300 ppm (log, either way) off the DAQ's, into a
    logger that keeps the two in step with a slip buffer: it stamps the laser's readings at the nominal rate and, each
    time the accumulated drift reaches one laser period, drops or repeats one reading (a sample-rate bridge's slip, as
    audio interfaces' adaptive modes do), then puts them on the DAQ's rows by linear interpolation, after the buffer's
    fixed latency (1-4 ms, log). The reading's delay saws between the latency and the latency plus one laser period with
    a period of 1/(f_L ppm) (a few seconds to a minute) on the session's clock, the linear interpolation's sinc^2 gain
    on top. Per record on the session clock; displacement only. Measured (s001_185: f_L 485 Hz, 77 ppm: a slip every 27
    s; a latency of 3.1 ms) displacement residual 0.17 % of its RMS (5.5x its noise): the 20 Hz sines -25 to -35 deg at
    0.993, the 9.4 Hz ones -11 to -17 deg, the 3 Hz ones -3.8 deg, the 0.1 Hz harmonics -0.1 deg: a delay of 3.1-5.2 ms
    that differs from record to record with where the saw stands."""
    f_l, ppm = lu(s.rng, 200.0, 1000.0), lu(s.rng, 5e-5, 3e-4) * _sign(s)
    lat, phase = lu(s.rng, 1e-3, 4e-3), s.rng.uniform(0.0, 1.0)
    t_l = 1.0 / f_l
    for r in s.series():
        t, d = r.cols["t_s"], r.cols["disp_m"]
        j = np.arange(math.floor((float(t[0]) - s.t0) / t_l) - 2, math.ceil((float(t[-1]) - s.t0) / t_l) + 3)
        stamp = s.t0 + j * t_l  # where the logger puts reading j
        slip = np.mod(ppm * (stamp - s.t0) / t_l + phase, 1.0)  # the drift since the last slip, in laser periods
        taken = stamp - lat - t_l * (slip if ppm > 0 else 1.0 - slip)  # when reading j was taken on the DAQ's clock
        vals = np.interp(taken, t, d)
        r.cols["disp_m"] = np.interp(t, stamp, vals)


# ------------------------------------------------------------------------------------------------ sensor offset


def so_rtv_periscope_mirror(s: Session) -> None:
    """The laser head could not be placed in front of the strip, so its beam is folded onto the tip by a small 45 deg
    mirror glued to a post with a blob of acetoxy RTV silicone 10-60 min (log) before the first record and aimed then, a
    margin m0 (0.1-0.3 mm) inside the tip's end: the mirror's weight on its soft, still curing glue makes it tilt, and a
    mirror's tilt turns the beam by twice as much, walking the spot inboard along the strip; the glue's viscosity rises
    as it cures (eta_0 exp(b alpha), b 2-5, alpha = 1 - exp(-(t - t_g)/tau_c), tau_c 20-90 min, log), so the creep slows
    and freezes: walk = W G(t)/G(t1), G the integral of exp(-b alpha) from the gluing, W 0.5-2.5 % of L (log) over the
    whole creep to the session's end. The strip read at the moving station (inject_fresh10._station); displacement only.
    Measured (p7_186: m0 0.26 mm, glued 10 min before the first record, b 4.3, tau_c 22 min, a walk of 2.1 % of L by the
    end: the station from 0.962 to 0.941 L, half of it in the first block) displacement RMS -9.7 % (residual 9.8 %, 33x
    its noise): the 1 V steps at 0.461, 0.450, 0.447, 0.444 mm by their plateaus' end block by block (0.498-0.499 mm
    clean); the 1 V harmonics' gain 0.921, 0.901, 0.894, 0.890."""
    length = float(s.specimen["length_m"])
    m0, lead = s.rng.uniform(1e-4, 3e-4), lu(s.rng, 600.0, 3600.0)
    b, tau_c, total = s.rng.uniform(2.0, 5.0), lu(s.rng, 1200.0, 5400.0), lu(s.rng, 0.005, 0.025) * length
    t_g = s.t0 - lead
    tg = np.linspace(t_g, s.t1, 20001)
    alpha = -np.expm1(-(tg - t_g) / tau_c)
    integ = np.r_[0.0, np.cumsum(0.5 * (np.exp(-b * alpha[1:]) + np.exp(-b * alpha[:-1])) * np.diff(tg))]
    g0 = float(np.interp(s.t0, tg, integ))
    scale = total / (float(integ[-1]) - g0)

    def walk(t: np.ndarray) -> np.ndarray:
        return scale * (np.interp(np.asarray(t, float), tg, integ) - g0)

    _walk_station(s, walk, m0)


def so_rail_carriage_stickslip(s: Session) -> None:
    """The strip mounted upright (the clamp below, the tip up) and the laser head on a carriage on a vertical rail
    beside it, its beam level and aimed at the first record a margin m0 (0.1-0.3 mm) below the tip's end; the carriage
    is held by a spring-loaded brake pad whose grip the head's weight slowly overcomes: the pad creeps until its static
    friction gives, the carriage slips by s_j (0.2-0.6 % of L, log, each +-20 %) and the pad grips again. Regular jerks,
    the first 0-1 interval after the aim, every T_j (3-10 min, log), the intervals lengthening by a factor 1-1.15 each
    (the pad's friction ageing): a staircase walking the spot down the strip, inboard. The strip read at the moving
    station (inject_fresh10._station); displacement only. Measured (paper_184: m0 0.26 mm, T_j 3.0 min lengthening 1.14
    times each, jerks of 0.54 % of L: 10 by the session's end, the station from 0.991 to 0.939 L) displacement RMS -6.8
    % (residual 7.6 %, 450x its noise): the 1 V steps at 8.67, 8.24, 8.08, 7.91 mm by their plateaus' end block by block
    (8.82-8.83 mm clean); the 1 V harmonics' gain 0.974, 0.935, 0.917, 0.898; the 20 Hz sines' 0.89 to 0.72."""
    length = float(s.specimen["length_m"])
    m0, t_j, grow = s.rng.uniform(1e-4, 3e-4), lu(s.rng, 180.0, 600.0), s.rng.uniform(1.0, 1.15)
    step, first = lu(s.rng, 0.002, 0.006) * length, s.rng.uniform(0.0, 1.0)
    times, t, gap = [], s.t0 + first * t_j, t_j
    while t < s.t1:
        times.append(t)
        gap *= grow
        t += gap
    sizes = step * s.rng.uniform(0.8, 1.2, len(times))
    times_a, steps = np.array(times), np.r_[0.0, np.cumsum(sizes)]

    def walk(tt: np.ndarray) -> np.ndarray:
        return steps[np.searchsorted(times_a, np.asarray(tt, float), side="right")]

    _walk_station(s, walk, m0)


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_alginate_pads_phosphate(s: Session) -> None:
    """Jaw pads cut from a calcium-alginate hydrogel slab (a bio lab's soft, wet cushion for the strip's root) under a
    screw clamp's fixed gap, in a phosphate-buffered bath filled 0-300 s before the first setting: the phosphate and the
    bath's sodium draw the calcium crosslinks out of the pads from their exposed edges, a de-crosslinked band that grows
    inwards by diffusion, its share s = sqrt((t - t_f)/T_f) (T_f 1-4 sessions, log: the whole pad by then), the band's
    sol carrying a share phi (0.3-0.7) less of the load than the gel: the held force follows the modulus, the same share
    at every setting and fastest early, F/F_set = (1 - phi s(t))/(1 - phi s(t_set)), beside the gel's own viscoelastic
    relaxation, r ln(1 + u/tau) (r 0.5-1.5 % per e-fold, tau 5-30 s, log). From each setting
    (inject_fresh25._setting_of) through the preset's clamp law (inject_fresh4._clamp_law), the load cell showing it.
    Measured (paper_184: filled 4.5 min before, T_f 1.6 sessions, phi 0.42, r 1.4 % per e-fold, tau 30 s) the load cell
    at 0.976-0.985 of its setting at each block's first record and 0.870, 0.900, 0.910, 0.916 by the blocks' last (23x
    the 0.01 kgf step in RMS); displacement residual 0.093 % of its RMS (5.5x its noise: the 4287 kPa block's 3 Hz sines
    0.91 (+14 deg), its 9.4 Hz ones 1.29 (-14 deg), the clamp law moving f1), current 0.61 % (0.46x)."""
    t_f = s.t0 - s.rng.uniform(0.0, 300.0)
    span = lu(s.rng, 1.0, 4.0) * (s.t1 - t_f)
    phi, r_v, tau_v = s.rng.uniform(0.3, 0.7), s.rng.uniform(0.005, 0.015), lu(s.rng, 5.0, 30.0)
    setting = _setting_of(s)

    def share(t: np.ndarray) -> np.ndarray:
        return np.sqrt(np.clip((np.asarray(t, float) - t_f) / span, 0.0, 1.0))

    def rel(t: np.ndarray, p: float, t_fp: float) -> np.ndarray:
        t_set = setting(p, t_fp)
        u = np.clip(np.asarray(t, float) - t_set, 0.0, None)
        return (1.0 - phi * share(t)) / (1.0 - phi * share(np.array([t_set]))[0]) * (1.0 - r_v * np.log1p(u / tau_v))

    _clamp_law(s, rel)


def cr_hydraulic_air_bubble(s: Session) -> None:
    """A small hydraulic clamp (the jaw on a syringe-type cylinder, set by a screw-driven master syringe and closed by
    its valve at each setting) whose line was filled without bleeding it: a trapped air bubble. At the held piston the
    line's pressure is the bubble's, and the bubble's air dissolves into the liquid under it (Henry's law: the faster
    the higher the pressure), so the force falls as 1 - phi_k (1 - exp(-u/tau_k)), tau_k = tau_d p_top/p_k (tau_d 60-300
    s, log, at the top setting), phi_k the share the bubble's remaining air can give (phi_0 4-12 % at the first
    setting); the air that has dissolved does not come back, so each later setting finds a smaller bubble, phi in
    proportion to the air left. From each setting (inject_fresh25._setting_of) through the preset's clamp law
    (inject_fresh4._clamp_law), the load cell showing it: the heavy settings sag quicker, the later ones less deep.
    Measured (s001_185: tau_d 3.6 min at the top setting, phi_0 9.8 %) the load cell at 0.987-0.993 of its setting at
    each block's first record and 0.937, 0.924, 0.923, 0.926 by the blocks' last (29x the 0.01 kgf step in RMS);
    displacement residual 0.015 % of its RMS (0.49x its noise: the seed-001 strip's clamp law moves its bend little at
    these forces), current 0.28 % (0.74x)."""
    tau_d, phi0 = lu(s.rng, 60.0, 300.0), s.rng.uniform(0.04, 0.12)
    setting = _setting_of(s)
    firsts: dict[float, float] = {}
    for r in s.series():
        p = float(r.entry["pressure_kPa"])
        firsts[p] = min(firsts.get(p, np.inf), float(r.cols["t_s"][0]))
    order = sorted(firsts, key=lambda p: setting(p, firsts[p]))
    p_top = max(order)
    air, params = 1.0, {}
    for k, p in enumerate(order):
        t_set = setting(p, firsts[p])
        nxt = setting(order[k + 1], firsts[order[k + 1]]) if k + 1 < len(order) else s.t1
        phi, tau = phi0 * air, tau_d * p_top / p
        params[p] = (t_set, phi, tau)
        air *= 1.0 - phi * -math.expm1(-max(nxt - t_set, 0.0) / tau)

    def rel(t: np.ndarray, p: float, t_fp: float) -> np.ndarray:
        t_set, phi, tau = params.get(p, (setting(p, t_fp), phi0, tau_d))
        u = np.clip(np.asarray(t, float) - t_set, 0.0, None)
        return 1.0 - phi * -np.expm1(-u / tau)

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


ATM = 1013.25  # hPa


def dh_vacuum_chamber_step(s: Session) -> None:
    """A strip in air inside a bell jar on the lab's rotary pump (a test of actuators for thin air), mounted 0-600 s
    before the first record from a humid box and drying slowly towards the room's air (a loss of k_0 3-8 % of its mobile
    water at equilibrium, tau 1500-5000 s, log); at one re-clamping after the first (drawn; 30-90 s after the setting,
    through the clamp's feedthrough) the jar is pumped down to P (150-400 hPa) over tau_p (20-60 s) and held there: the
    water vapour is pumped with the air, so the relative humidity at the strip falls as P/P_atm (from rh0 0.4-0.6), and
    the vapour's diffusion through the thinner gas is P_atm/P times faster, so the strip dries towards a much drier
    equilibrium (the loss there k_0 + g (rh0 - rh), g 0.3-0.6 per unit of humidity) at that quicker rate. The water's
    loss through the session on a 1 s grid; gain x (1 - G loss) (G 0.6-1), conductance x (1 - share loss) (share 0.5-1.2
    of G); the spectra at the next series' start (inject_fresh9._dry_by). Measured (s001_185: k_0 4.5 %, tau 59 min, rh0
    0.55, g 0.58, G 0.71, the conductance's share 0.52 of G; pumped to 270 hPa at the 1300 kPa block) displacement RMS
    -7.7 % (residual 11 %, 360x its noise), current RMS -5.2 % (residual 6.5 %, 17x its noise): the 1 V steps at 4.687,
    4.667, 4.089, 3.887 mm by their plateaus' end block by block (4.688-4.718 mm clean); the 1 V harmonics' gain 0.999,
    0.980, 0.861, 0.822 (current 0.999 to 0.907); the impedance 1.004, 1.073, 1.101x in the later blocks' spectra."""
    lead, k0, tau = s.rng.uniform(0.0, 600.0), s.rng.uniform(0.03, 0.08), lu(s.rng, 1500.0, 5000.0)
    p_low, tau_p = s.rng.uniform(150.0, 400.0), s.rng.uniform(20.0, 60.0)
    rh0, gain_rh = s.rng.uniform(0.4, 0.6), s.rng.uniform(0.3, 0.6)
    g_d = s.rng.uniform(0.6, 1.0)
    share = s.rng.uniform(0.5, 1.2) * g_d
    setting = _setting_of(s)
    firsts: dict[float, float] = {}
    for r in s.series():
        p = float(r.entry["pressure_kPa"])
        firsts[p] = min(firsts.get(p, np.inf), float(r.cols["t_s"][0]))
    later = sorted(firsts)[1:]
    p_at = later[int(s.rng.integers(0, len(later)))] if later else sorted(firsts)[0]
    t_pump = setting(p_at, firsts[p_at]) + s.rng.uniform(30.0, 90.0)
    dt = 1.0
    g = _grid(s, dt, lead=lead)
    press = np.where(g < t_pump, ATM, p_low + (ATM - p_low) * np.exp(-np.clip(g - t_pump, 0.0, None) / tau_p))
    rh = rh0 * press / ATM
    eq = k0 + gain_rh * (rh0 - rh)
    loss = _exact_lag(eq, tau * press / ATM, dt, 0.0)
    base = float(np.interp(s.t0, g, loss))
    lost = lambda t: np.clip(np.interp(np.asarray(t, float), g, loss) - base, 0.0, None)  # noqa: E731
    _dry_by(s, lambda t: g_d * lost(t), lambda t: share * lost(t))


def dh_peltier_temperature_steps(s: Session) -> None:
    """A bath on a Peltier cuvette holder whose set point the lab's protocol steps down at each re-clamping (a sweep of
    temperature paired with the pressures: T_0 34-40 C for the first block, dT 3-6 K lower at each setting after it,
    inject_fresh25._setting_of; the holder reaching each over tau_h 60-180 s, log). Nafion in liquid water takes up less
    of it the colder it is (0.5-1.5 % of its mobile water per K, log), and the membrane deswells towards the new uptake
    only slowly (tau_w 300-900 s, log), so each block starts wetter than it ends; the membrane's ionic conduction falls
    with the cold too (Arrhenius, E_a 10-16 kJ/mol). Gain x (1 - loss), conductance x (1 - share loss) (share 0.6-1.2)
    times the Arrhenius factor; the spectra at the next series' start (inject_fresh9._dry_by). On a 1 s grid through the
    session. Measured (p7_186: T_0 37.3 C, steps of 4.7 K, tau_h 90 s, 0.89 % a K, tau_w 7.6 min, share 0.62, E_a 12.6
    kJ/mol) displacement RMS -3.0 % (residual 4.5 %, 15x its noise), current RMS -12 % (residual 16 %, 7.0x its noise;
    51 of the 68 series touched, the first block not): the 1 V steps at 0.498, 0.499, 0.480, 0.459 mm by their plateaus'
    end block by block (0.498-0.499 mm clean), their current 0.201, 0.163, 0.141, 0.132 mA (0.161-0.201 clean); the 1 V
    harmonics' gain 1.000, 0.994, 0.954, 0.913 (current 1.000 to 0.761); the impedance 1.011, 1.127, 1.247x in the later
    blocks' spectra."""
    t0c, step = s.rng.uniform(34.0, 40.0), s.rng.uniform(3.0, 6.0)
    tau_h, per_k, tau_w = lu(s.rng, 60.0, 180.0), lu(s.rng, 0.005, 0.015), lu(s.rng, 300.0, 900.0)
    share, e_a = s.rng.uniform(0.6, 1.2), s.rng.uniform(10e3, 16e3)
    setting = _setting_of(s)
    firsts: dict[float, float] = {}
    for r in s.series():
        p = float(r.entry["pressure_kPa"])
        firsts[p] = min(firsts.get(p, np.inf), float(r.cols["t_s"][0]))
    sets = sorted(setting(p, t) for p, t in firsts.items())
    dt = 1.0
    g = _grid(s, dt, lead=max(0.0, s.t0 - sets[0]) + 60.0)
    n_after = np.searchsorted(np.array(sets[1:]), g, side="right")  # settings passed after the first
    target = t0c - step * n_after
    temp = _exact_lag(target, tau_h, dt, t0c)
    water = _exact_lag(per_k * (t0c - temp), tau_w, dt, 0.0)  # the water lost since the first block
    arr = np.exp(-e_a / 8.314 * (1.0 / (temp + KELVIN) - 1.0 / (t0c + KELVIN)))
    loss = lambda t: np.interp(np.asarray(t, float), g, water)  # noqa: E731
    cond = lambda t: 1.0 - (1.0 - share * loss(t)) * np.interp(np.asarray(t, float), g, arr)  # noqa: E731
    _dry_by(s, loss, cond)


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_silver_thread_collector(s: Session) -> None:
    """A silver-plated nylon thread (the e-textile kind) glued along one face (drawn) as a current collector carrying
    part of that face's conduction: stretched, its plated filaments first pack together and touch more (the face's
    resistance down by a 0.1-0.3, saturating over e_p 0.1-0.3 of the largest bend), then their silver cracks (up as k
    ((e - e_c)+)^2, k 3-8, e_c 0.35-0.6); shortened, the thread buckles off the plating in loops between its glue spots,
    losing its contacts (up as b e^2, b 0.5-1.5). On that face dR/R = -a (1 - exp(-e/e_p)) + k ((e - e_c)+)^2 in
    tension, b e^2 in compression (e the face's tension over the session's largest bend): a U-shaped gauge, the other
    face untouched. Gains fall by 0.03-0.08 (displacement) and 0.06-0.15 (current) per unit of dR/R
    (inject_fresh3._resist). Measured (p7_186: the thread on the face a negative bend stretches, a 0.14, e_p 0.13, k
    7.7, e_c 0.40, b 0.71) displacement RMS -1.7 % (residual 1.9 %, 6.3x its noise), current RMS -0.05 % (residual 0.56
    %, 0.25x its noise): the 1 V steps at 0.483-0.484 mm by their plateaus' end (0.498-0.499 mm clean), their current
    0.009-0.011 mA lower; the 1 V harmonics' gain 0.993; the 0.5 V sines 1.001 (the thread's packing)."""
    ref = ref_disp(s)
    big = (_largest(s) or ref) / ref
    side = _sign(s)
    a, e_p = s.rng.uniform(0.1, 0.3), s.rng.uniform(0.1, 0.3)
    k, e_c, bb = s.rng.uniform(3.0, 8.0), s.rng.uniform(0.35, 0.6), s.rng.uniform(0.5, 1.5)

    def law(r: Rec, e: np.ndarray) -> np.ndarray:
        x = side * e / big  # the coated face's tension over the largest
        ten = np.clip(x, 0.0, None)
        return np.where(x >= 0.0, -a * -np.expm1(-ten / e_p) + k * np.clip(x - e_c, 0.0, None) ** 2, bb * x**2)

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


def sr_gold_wake_closure(s: Session) -> None:
    """A ductile gold plating (an electroless gold strip) whose cracks' flanks are stretched plastically at every
    tension beyond the film's yield (e_y 0.3-0.5 of the largest bend): the plastic wake left on the flanks wedges each
    crack shut, so it opens only once the face's tension passes an opening level that grows with the plastic stretching
    the face has had (Elber's closure), e_op = e_0 + (e_inf - e_0)(1 - exp(-Y/Y_c)) (e_0 0.05-0.15, e_inf 0.4-0.7; Y the
    face's tension travelled beyond e_y so far, in largest bends, through the session in time order; Y_c so that 0.5-0.9
    of the rise is reached by the session's end), and beyond it dR/R = k (e - e_op)+ (k 0.8-2; the other face at 0.3-1
    of it): a gauge that gives way to a widening dead zone as the session goes. Gains fall by 0.03-0.08 (displacement)
    and 0.06-0.15 (current) per unit of dR/R (inject_fresh3._resist). Measured (paper_184: e_y 0.30, e_0 0.10 to e_inf
    0.68, 0.62 of the rise by the end, k 1.14, the other face 0.48 of it) displacement RMS -1.8 % (residual 2.0 %, 120x
    its noise; only the 1 V records touched, 160x there), current RMS -0.13 % (residual 0.66 %, 0.50x its noise): the 1
    V steps at 8.50, 8.55, 8.59, 8.61 mm by their plateaus' end block by block (8.82-8.83 mm clean), their current
    0.019-0.030 mA lower; the 1 V harmonics' gain 0.988, 0.993, 0.997, 0.999 (the dead zone widening); the 0.5 V sines
    untouched."""
    ref = ref_disp(s)
    big = (_largest(s) or ref) / ref
    e_y, e_0, e_inf = s.rng.uniform(0.3, 0.5), s.rng.uniform(0.05, 0.15), s.rng.uniform(0.4, 0.7)
    frac, k_a = s.rng.uniform(0.5, 0.9), s.rng.uniform(0.8, 2.0)
    side, other = _sign(s), s.rng.uniform(0.3, 1.0)
    bigm = _largest(s) or ref_disp(s)
    open_at = {}
    for sg in (side, -side):
        def plastic(r: Rec, sg: float = sg) -> np.ndarray:  # tension rate while beyond yield, largest bends a second
            sig, _ = _split_noise(r)
            rate = np.gradient(sig, r.cols["t_s"]) if sig.size > 1 else np.zeros(sig.size)
            return np.clip(sg * rate, 0.0, None) * (sg * sig > e_y * bigm) / bigm

        per, _, tot = _cumulative(s, plastic)
        top = float(tot[-1]) if tot.size and tot[-1] > 0 else 1.0
        y_c = top / -math.log1p(-frac)
        open_at[sg] = {key: e_0 + (e_inf - e_0) * -np.expm1(-x / y_c) for key, x in per.items()}

    def law(r: Rec, e: np.ndarray) -> np.ndarray:
        x = e / big
        return 0.5 * sum(kk * np.clip(sg * x - open_at[sg][id(r)], 0.0, None)
                         for sg, kk in ((side, k_a), (-side, other * k_a)))

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_fibre_pair_gaussian_coupling(s: Session) -> None:
    """No laser: a fibre-optic pair (a lab's cheap displacement sensor): a receiving fibre glued at the tip facing an
    emitting fibre fixed beside it across a small gap, offset along the bending direction so that the tip's bend moves
    the receiver across the emitter's beam. The power coupled follows the Gaussian overlap of the two modes, P ~ exp(-2
    (d - d_0)^2/w^2), w the beam's radius at the gap (3-6 times the session's largest bend, log) and d_0 the offset at
    rest (0.4-0.6 w, near the curve's inflection where it is most linear); the lab converts power to displacement with
    the slope at rest, (P(d) - P(0))/P'(0): compressed on both sides, more on the side towards the peak, an odd and an
    even part. A static reading map (inject_fresh33._static_map); displacement only. Measured (p7_186: w 3.9 times the
    largest bend, the offset 0.47 w on the negative side) displacement RMS -2.3 % (residual 2.8 %, 9.4x its noise): the
    1 V steps at 0.474-0.475 mm by their plateaus' end (0.498-0.499 mm clean) and 0.349-0.350 mm 2 s after their fall
    (0.357 clean); the 1 V harmonics' gain 0.995-0.996; the 0.5 V sines 0.9994-1.0000."""
    big = _largest(s) or ref_disp(s)
    w = lu(s.rng, 3.0, 6.0) * big
    d0 = s.rng.uniform(0.4, 0.6) * w * _sign(s)
    dg = np.linspace(-1.5 * big, 1.5 * big, 8001)  # within the curve's rising side: abs(d0) >= 1.2 big
    p = np.exp(-2.0 * ((dg - d0) ** 2 - d0**2) / w**2)  # P(d)/P(0)
    slope = 4.0 * d0 / w**2
    yg = (p - 1.0) / slope
    _static_map(s, yg, dg)


def ld_air_spring_sealed_chamber(s: Session) -> None:
    """The seed-001 strip tested as the flap of a micropump jig: its tip's face closes a small sealed air chamber
    through a slack latex film glued round the chamber's rim and onto the tip, so that the bend sweeps the trapped air's
    volume one way or the other, isothermally: the air pushes back with p_0 A (V_0/(V_0 - A y) - 1), in the strip's own
    units x - y = kappa (1/(1 - y/y_0) - 1) (x the free bend, y the tip; y_0 = V_0/A 2-4 times the session's largest
    bend, log, its sign drawn; kappa so that the air's small-bend stiffness is 2-6 % of the strip's, which the fit's
    gain takes up): stiffer as the air is squeezed, softer as it is drawn out, an odd and an even part growing with the
    bend. Tabulated and interpolated (inject_fresh33._static_map); displacement only. Measured (s001_185: y_0 2.45 times
    the largest bend on the positive side, kappa 0.037 y_0) displacement RMS -4.8 % (residual 4.9 %, 160x its noise):
    the 1 V steps at 4.43-4.45 mm by their plateaus' end (4.69-4.72 mm clean: 0.944) and 3.40-3.41 mm 2 s after their
    fall (3.58 clean); the 1 V harmonics' gain 0.957, the 0.5 V sines' 0.965 (the air's linear stiffness, which the
    fit's gain takes up)."""
    big = _largest(s) or ref_disp(s)
    y0 = lu(s.rng, 2.0, 4.0) * big * _sign(s)
    kappa = s.rng.uniform(0.02, 0.06) * abs(y0)
    yg = np.linspace(-0.95 * min(abs(y0), 2.0 * big), 0.95 * min(abs(y0), 2.0 * big), 8001)
    dg = yg + kappa * (1.0 / (1.0 - yg / y0) - 1.0)
    _static_map(s, yg, dg)


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_contactor_chatter_acoustic(s: Session) -> None:
    """The drying oven behind the bench on its thermostat (on for a share 0.3-0.6 of a 5-15 min cycle, log, phase
    drawn), its heater switched by an AC contactor whose shading ring has cracked: while closed, the armature chatters
    against its pole face twice a line period, a loud buzz at twice the line frequency (50 or 60 Hz,
    inject_fresh12._line_f) with its harmonics (the impacts' spectrum, the k-th at k^-q, q 0.5-1.2, to the 8th). A strip
    in air hears it: the sound's pressure bends the light strip through its first mode (its resonance at the block's
    pressure from the preset's FRF, inject_fresh22._f1; damping 0.02-0.08 in air), each line of the buzz filtered by it,
    the tip's motion at the buzz's fundamental 3-8 um (log), far above resonance: a real motion of the strip, not a
    sensor's hum, at even multiples of the line only, phase locked to it while the contactor is closed, nothing while
    open. Displacement only. Measured (s001_185: 59.997 Hz, the buzz at 120 Hz, on 44 % of a 7.7 min cycle, q 0.81,
    damping 0.048, 3.7 um at 120 Hz) displacement residual 0.096 % of its RMS (3.1x its noise): 33 of the 68 series
    touched, 4.5x there; aliased on the 200 Hz records (120 Hz read at 80 Hz); no line at 60 Hz itself."""
    f0 = _line_f(s)
    period, duty, ph0 = lu(s.rng, 300.0, 900.0), s.rng.uniform(0.3, 0.6), s.rng.uniform(0.0, 1.0)
    q, zeta, amp = s.rng.uniform(0.5, 1.2), s.rng.uniform(0.02, 0.08), lu(s.rng, 3e-6, 8e-6)  # at 2 f0, filtered
    phases = s.rng.uniform(0.0, 2 * math.pi, 8)
    cache: dict[float, float] = {}
    for r in s.series():
        t = r.cols["t_s"]
        on = np.mod((t - s.t0) / period + ph0, 1.0) < duty
        if not np.any(on):
            continue
        f1 = _f1(s, float(r.entry["pressure_kPa"]), cache)
        h = [1.0 / complex(1.0 - (2.0 * k * f0 / f1) ** 2, 2.0 * zeta * 2.0 * k * f0 / f1) for k in range(1, 9)]
        out = np.zeros(t.size)
        for k, hk in enumerate(h, start=1):
            a_k = amp * k**-q * abs(hk) / abs(h[0])
            out += a_k * np.cos(2 * math.pi * 2.0 * k * f0 * t + phases[k - 1] + math.atan2(hk.imag, hk.real))
        r.cols["disp_m"] = r.cols["disp_m"] + out * on


def mp_glassware_washer_program(s: Session) -> None:
    """A laboratory glassware washer on the bench's circuit runs one program through the session (from 10-40 % into it):
    a prewash (fill 1 min, wash 3-6 min, drain 1 min), a main wash (fill, heating 8-15 min with the circulation pump
    running, drain), two rinses (fill, wash 2-4 min, drain) and a drying stage (10-20 min, heater and fan), each load
    with its own current and harmonics on the line (50 or 60 Hz, inject_fresh12._line_f): the filling valve's solenoid
    (0.05 of the heater's current, its third 0.4-0.6), the circulation pump's induction motor (0.15-0.25, third 0.1-0.2,
    fifth 0.05), the drain pump's small synchronous motor (0.05-0.1, third 0.3-0.5, fifth 0.2-0.3), the heater (1, a
    pure line) and the drier's fan (0.05). The cable behind the bench carries their sum, which reaches the laser's cable
    and the current amplifier's input: 4-10 um and 30-100 uA (log, each its sign) at the heater's current. Displacement
    and current. Measured (s001_185: 50.013 Hz, the program from 37 % into the session) displacement residual 0.089 % of
    its RMS (2.9x its noise), current 1.1 % (2.9x): 47 of the 68 series touched, 3.8x in both there; the heater's stages
    the pure line, the pumps' their third and fifth."""
    f0 = _line_f(s)
    start = s.t0 + s.rng.uniform(0.1, 0.4) * (s.t1 - s.t0)
    loads = {"valve": (0.05, {3: s.rng.uniform(0.4, 0.6)}),
             "pump": (s.rng.uniform(0.15, 0.25), {3: s.rng.uniform(0.1, 0.2), 5: 0.05}),
             "drain": (s.rng.uniform(0.05, 0.1), {3: s.rng.uniform(0.3, 0.5), 5: s.rng.uniform(0.2, 0.3)}),
             "heater": (1.0, {}), "fan": (0.05, {})}
    program = [("valve",), ("pump",), ("drain",)]
    lengths = [60.0, s.rng.uniform(180.0, 360.0), 60.0]
    program += [("valve",), ("heater", "pump"), ("drain",)]
    lengths += [60.0, s.rng.uniform(480.0, 900.0), 60.0]
    for _ in range(2):
        program += [("valve",), ("pump",), ("drain",)]
        lengths += [60.0, s.rng.uniform(120.0, 240.0), 60.0]
    program += [("heater", "fan")]
    lengths += [s.rng.uniform(600.0, 1200.0)]
    edges = start + np.r_[0.0, np.cumsum(lengths)]
    amp = {"disp_m": lu(s.rng, 4e-6, 1e-5) * _sign(s), "i_A": lu(s.rng, 3e-5, 1e-4) * _sign(s)}
    phase = {name: s.rng.uniform(0.0, 2 * math.pi, 6) for name in loads}
    for r in s.series():
        t = r.cols["t_s"]
        stage = np.searchsorted(edges, t, side="right") - 1
        if not np.any((stage >= 0) & (stage < len(program))):
            continue
        wave = np.zeros(t.size)
        for j, names in enumerate(program):
            on = stage == j
            if not np.any(on):
                continue
            tt = t[on]
            for name in names:
                level, harm = loads[name]
                ph = phase[name]
                part = np.cos(2 * math.pi * f0 * tt + ph[0])
                for n, hn in harm.items():
                    part += hn * np.cos(2 * math.pi * n * f0 * tt + ph[n // 2])
                wave[on] += level * part
        for col, a in amp.items():
            r.cols[col] = r.cols[col] + a * wave


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_series_pilot_lamp(s: Session) -> None:
    """A miniature filament lamp (a 'grain of wheat' micro bulb, its rated current 1.1-1.7 times the stepped sines'
    largest current, so that it warms on the fast sines and the steps' edges without glowing) in series with the drive
    as its 'drive on' indicator, the monitor v_V at the amplifier's output before it: a tungsten filament, its
    resistance going as its absolute temperature to the 1.2 (R_c 5-15 Ohm cold, log, which the fit's series resistance
    takes up; 2400 K at its rated current), its temperature following the power the strip's current puts into it through
    its thermal time constant (tau 20-80 ms, log). The steps' charging spikes and the fast sines' currents warm it, and
    the strip gets e = -(R(T) - R_c) i less drive, within a cycle and record by record: the current's crests and the
    bend's fast response cut, an odd distortion with a thermal memory. e (the current's signal,
    inject_fresh26._split_noise; the filament's temperature sample by sample through the session in time order, each
    step exact for the power linearised about it, cooling over the rests) through the preset's admittance and
    displacement transfer functions at each record's pressure (inject_fresh33._through_strip); current and displacement.
    Measured (paper_184: R_c 12.6 Ohm, tau 21 ms, rated at 1.56 times the sines' largest current; s001_185: 9.5 Ohm, 21
    ms, 1.13 times) current residual 3.0 % and 7.8 % of its RMS (2.3x and 21x its noise), displacement 0.085 % and 0.49
    % (5.0x and 16x): the 20 Hz sines' current and bend at 0.956 and 0.945 of their gain, the 3 Hz ones' 0.984 and
    0.966, the 0.1 Hz ones' 0.9996 and 0.999; the 1 V harmonics 0.999 and 0.996."""
    r_c, tau = lu(s.rng, 5.0, 15.0), lu(s.rng, 0.02, 0.08)
    sines = [r for r in s.series() if r.kind == "stepped_sine"] or s.series()
    i_rate = s.rng.uniform(1.1, 1.7) * max(float(np.max(np.abs(r.cols["i_A"]))) for r in sines)
    t_amb, t_hot = 300.0, 2400.0
    r_hot = r_c * (t_hot / t_amb) ** 1.2
    cond = i_rate**2 * r_hot / (t_hot - t_amb)  # W/K to the bulb: the rated power at its rated temperature
    heat_cap = cond * tau
    temp, t_end, e = t_amb, None, {}
    for r in _chrono(s):
        i, _ = _split_noise(r, "i_A")
        t, dt = r.cols["t_s"], 1.0 / r.fs
        if t_end is not None:
            temp = t_amb + (temp - t_amb) * math.exp(-max(float(t[0]) - t_end, 0.0) / tau)
        out = np.empty(i.size)
        for k, ik in enumerate(i.tolist()):
            res = r_c * (temp / t_amb) ** 1.2
            q = ik * ik * res - cond * (temp - t_amb)  # the net heating, and its slope in temperature
            lam = cond - 1.2 * ik * ik * res / temp
            if lam > 1e-12 * cond:
                temp += q / lam * -math.expm1(-lam * dt / heat_cap)
            else:
                temp += q * dt / heat_cap
            temp = min(max(temp, t_amb), t_hot)
            out[k] = r_c * (temp / t_amb) ** 1.2 - r_c
        e[id(r)] = -out * i
        t_end = float(t[-1])
    di, dd = _through_strip(s, e)
    for r in s.series():
        r.cols["i_A"] = r.cols["i_A"] + di[id(r)]
        r.cols["disp_m"] = r.cols["disp_m"] + dd[id(r)]


def out_eis_frequency_row_ahead(s: Session) -> None:
    """The impedance analyser's export writing each sweep point's frequency from the sweep table one point ahead of its
    measured impedance (the frequency it set next, a classic off-by-one of an export loop): every spectrum's f_Hz column
    runs one point ahead of its z_re_ohm and z_im_ohm, the last row's frequency the next the log grid would have taken
    (a factor of the grid's step, 1.47 for six points a decade), every measured value kept. The spectra's low-frequency
    branch shifted a grid step up in frequency, their impedance at each labelled frequency the one of the point below;
    the time series untouched. Measured (paper_184 and p7_186: the grid's step 1.468) the spectra's abs(Z) 1.19 and
    1.23-1.24 times the clean spectrum's at the lowest labelled frequency (now 0.147 Hz), 1.000 at the highest (now 14.7
    kHz: the resistive plateau); no time series touched."""
    for r in s.recs:
        if r.series:
            continue
        f = r.cols["f_Hz"]
        if f.size < 2:
            continue
        order = np.argsort(f)
        ratio = float(np.exp(np.median(np.diff(np.log(f[order])))))
        ahead = np.empty(f.size)
        ahead[order[:-1]] = f[order[1:]]
        ahead[order[-1]] = f[order[-1]] * ratio
        r.cols["f_Hz"] = ahead


def out_output_stage_thermal_tail(s: Session) -> None:
    """The laser controller's analogue output (0-10 V over its range, into the DAQ and a 1-2 kOhm panel meter beside it)
    comes from an output stage on the same small board as its voltage reference: the stage dissipates (V_s - abs(v_o))
    abs(v_o)/R_L (V_s 12-15 V) and warms the reference (20-50 ppm/K of the 10 V span through a thermal lag of 0.5-3 s,
    log; 0.5-1.5 K per 10 mW), so the zero follows the output's own recent dissipation: an offset even in the reading,
    growing with its magnitude and lagging it (a 'thermal tail' after every large excursion, the same after a positive
    and a negative one), 3-8 um at the session's largest output (log, its sign drawn). The reading converted to volts at
    the controller's 2 mm/V; a first-order lag through the session in time order (cooling over the rests); displacement
    only. Measured (paper_184: V_s 14.1 V, R_L 1.5 kOhm, tau 0.74 s, 7.5 um at the largest output, negative; s001_185:
    13.1 V, 1.3 kOhm, 2.3 s, 7.4 um, negative) displacement residual 0.096 % and 0.16 % of its RMS (5.6x and 5.3x its
    noise): the steps 7 um low on their plateaus and 6-7 um low 2 s after their fall, the 1 V harmonics' fundamental
    0.999 with an offset and a second harmonic riding on it; the 0.5 V sines hardly touched."""
    v_s, r_l = s.rng.uniform(12.0, 15.0), lu(s.rng, 1000.0, 2000.0)
    tau, size, sign = lu(s.rng, 0.5, 3.0), lu(s.rng, 3e-6, 8e-6), _sign(s)
    volts = 1.0 / 2e-3  # V per metre of reading
    big = _largest(s) or ref_disp(s)
    p_big = (v_s - min(big * volts, v_s)) * min(big * volts, v_s) / r_l
    scale = size / p_big if p_big > 0 else 0.0
    x, t_end = 0.0, None
    for r in _chrono(s):
        sig, _ = _split_noise(r)
        t, dt = r.cols["t_s"], 1.0 / r.fs
        vo = np.clip(np.abs(sig) * volts, 0.0, v_s)
        power = (v_s - vo) * vo / r_l
        if t_end is not None:
            x *= math.exp(-max(float(t[0]) - t_end, 0.0) / tau)
        lagged = _exact_lag(power, tau, dt, x)
        x = float(lagged[-1])
        r.cols["disp_m"] = r.cols["disp_m"] + sign * scale * lagged
        t_end = float(t[-1])


def out_edge_wrap_leak(s: Session) -> None:
    """The plating wrapped round one cut edge (a strip cut from its plated sheet with scissors that smeared the platinum
    over the edge): a thin bridge of metal joining the two faces along part of that edge, a leak G_0 (0.5-2 mS, log:
    0.5-2 mA at 1 V) beside the strip, which a fit's leak could take up at rest; but the bend stretches the bridge on
    whichever face is convex and its thin film cracks open, g = 1/(1 + (abs(d)/d_c)^n) (d_c 0.3-0.6 of the session's
    largest bend, n 2-4), closing again as the strip comes back. An extra current v G_0 g that follows the drive times a
    function of the bend, the strip's drive and bend untouched; the current only. Measured (s001_185: G_0 1.33 mS, d_c
    0.47 of the largest bend, n 2.9; p7_186: 0.71 mS, 0.33, 3.0) current RMS +13 % and +5.5 % (residual 17 % and 9.8 %,
    44x and 4.4x its noise): the 1 V steps' plateau current 0.14 and 0.026 mA up (the bridge cracked open at the steps'
    bend, its leak left there), the 1 V harmonics' current gain 1.20-1.21 (-7 deg) and 1.21-1.26 (-10 to -11 deg), the
    0.5 V sines' current up by the bridge's whole leak."""
    big = _largest(s) or ref_disp(s)
    g0, d_c, n = lu(s.rng, 5e-4, 2e-3), s.rng.uniform(0.3, 0.6) * big, s.rng.uniform(2.0, 4.0)
    for r in s.series():
        v, _ = _split_noise(r, "v_V")
        d, _ = _split_noise(r)
        g = 1.0 / (1.0 + (np.abs(d) / d_c) ** n)
        r.cols["i_A"] = r.cols["i_A"] + v * g0 * g


FRESH38_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"pnipam_lcst_skin": br_pnipam_lcst_skin, "sucrose_density_medium": br_sucrose_density_medium},
    "faradaic_current": {"borohydride_plating_residue": far_borohydride_plating_residue,
                         "oxalic_cleaner_oxide_gated": far_oxalic_cleaner_oxide_gated},
    "hysteresis": {"felt_nap_guide": hy_felt_nap_guide, "tacky_gel_stop": hy_tacky_gel_stop},
    "time_delay": {"one_euro_logger": td_one_euro_logger, "slip_buffer_resync": td_slip_buffer_resync},
    "sensor_offset": {"rtv_periscope_mirror": so_rtv_periscope_mirror,
                      "rail_carriage_stickslip": so_rail_carriage_stickslip},
    "clamp_relaxation": {"alginate_pads_phosphate": cr_alginate_pads_phosphate,
                         "hydraulic_air_bubble": cr_hydraulic_air_bubble},
    "dehydration": {"vacuum_chamber_step": dh_vacuum_chamber_step,
                    "peltier_temperature_steps": dh_peltier_temperature_steps},
    "strain_resistance": {"silver_thread_collector": sr_silver_thread_collector,
                          "gold_wake_closure": sr_gold_wake_closure},
    "large_deflection": {"fibre_pair_gaussian_coupling": ld_fibre_pair_gaussian_coupling,
                         "air_spring_sealed_chamber": ld_air_spring_sealed_chamber},
    "mains_pickup": {"contactor_chatter_acoustic": mp_contactor_chatter_acoustic,
                     "glassware_washer_program": mp_glassware_washer_program},
    "unexplained": {"series_pilot_lamp": out_series_pilot_lamp,
                    "eis_frequency_row_ahead": out_eis_frequency_row_ahead,
                    "output_stage_thermal_tail": out_output_stage_thermal_tail,
                    "edge_wrap_leak": out_edge_wrap_leak},
}
inject.register_forms(FRESH38_FORMS)


# ------------------------------------------------------------------------------------------------ variants

ROTATIONS_S = (300.0, 600.0)  # a logging program's file rotation periods


def v_rotated_files(s: Session) -> None:
    """A logging program that rotates its output file every T_rot (5 or 10 min of the session clock, drawn, the first
    rotation's phase drawn: the rotation a long acquisition uses so that a crash loses at most one file): a time series
    running across a rotation is written as consecutive records, its rows before the rotation in the old file and those
    from it on in the new one (a rotation within two rows of a record's ends not taken: the logger writes whole rows in
    pairs), each a record of the record's kind, pressure, frequency and amplitude (files suffixed '_part1', '_part2',
    ..., labels 'part 1', 'part 2', ...) without the record's layout keys (settle_cycles, cycles: the manifest script
    knows the protocol's records, not the pieces' layout); every record that no rotation falls in, the spectra and every
    value untouched. The import contract asks of a time series only a table whose t_s strictly increases (nothing of its
    edges or cycles); ``labrig import`` takes the pieces (a step that starts on its plateau, a sine that starts or stops
    mid-cycle) and ``labrig export`` writes every record back, its values as written."""
    period = float(s.rng.choice(ROTATIONS_S))
    phase = s.rng.uniform(0.0, period)
    out = []
    for r in s.recs:
        if not r.series:
            out.append(r)
            continue
        t = r.cols["t_s"]
        k0 = math.ceil((float(t[0]) - s.t0 - phase) / period)
        k1 = math.floor((float(t[-1]) - s.t0 - phase) / period)
        cuts = [int(np.searchsorted(t, s.t0 + phase + k * period)) for k in range(k0, k1 + 1)]
        cuts = sorted({c for c in cuts if 2 <= c <= t.size - 2})
        if not cuts:
            out.append(r)
            continue
        bounds = [0, *cuts, t.size]
        for j, (a, b) in enumerate(zip(bounds[:-1], bounds[1:]), start=1):
            entry = {k: v for k, v in r.entry.items() if k not in ("settle_cycles", "cycles")}
            stem, dot, ext = entry["file"].rpartition(".")
            entry["file"] = f"{stem}_part{j}.{ext}" if dot else f"{entry['file']}_part{j}"
            if "label" in entry:
                entry["label"] = f"{entry['label']} part {j}"
            out.append(Rec(entry, {c: x[a:b].copy() for c, x in r.cols.items()}))
    s.recs = out


inject.VARIANTS.update({"rotated_files": v_rotated_files})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_184", "s001_185", "p7_186"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 7 / 6 effect cases on seeds 184-186
    "back_relaxation": [("sucrose_density_medium", 184, P, "rotated_files"),
                        ("pnipam_lcst_skin", 186, T, "eis_two_passes")],
    "faradaic_current": [("oxalic_cleaner_oxide_gated", 184, P, "fir_decimated"),
                         ("borohydride_plating_residue", 184, P, "two_rate_sines")],
    "hysteresis": [("tacky_gel_stop", 185, S, "fixed_decimals"), ("felt_nap_guide", 186, T, "log_steps")],
    "time_delay": [("one_euro_logger", 184, P, "cycle_averaged"), ("slip_buffer_resync", 185, S, "split_spectra")],
    "sensor_offset": [("rail_carriage_stickslip", 184, P, "resampled"),
                      ("rtv_periscope_mirror", 186, T, "short_pretrigger")],
    "clamp_relaxation": [("alginate_pads_phosphate", 184, P, "sparse_spectra"),
                         ("hydraulic_air_bubble", 185, S, "eis_descending")],
    "dehydration": [("vacuum_chamber_step", 185, S, "host_timed"),
                    ("peltier_temperature_steps", 186, T, "minimal_manifest")],
    "strain_resistance": [("gold_wake_closure", 184, P, "shortened_shuffled"),
                          ("silver_thread_collector", 186, T, "own_clock")],
    "large_deflection": [("air_spring_sealed_chamber", 185, S, "trigger_clock"),
                         ("fibre_pair_gaussian_coupling", 186, T, "reversed_laser")],
    "mains_pickup": [("contactor_chatter_acoustic", 185, S, "spectra_last"),
                     ("glassware_washer_program", 185, S, "edge_files")],
    "unexplained": [("series_pilot_lamp", 184, P, "decimated3"),
                    ("series_pilot_lamp", 185, S, "dropped_packets"),
                    ("eis_frequency_row_ahead", 184, P, "asrun"),
                    ("eis_frequency_row_ahead", 186, T, "settled_sines"),
                    ("output_stage_thermal_tail", 184, P, "scan_hold"),
                    ("output_stage_thermal_tail", 185, S, "stop_trigger"),
                    ("edge_wrap_leak", 185, S, "rotated_files"),
                    ("edge_wrap_leak", 186, T, "float32_time")],
}
CLEAN = [(184, P, "rotated_files"), (184, P, "merged_loadcell"), (185, S, "rotated_files"), (185, S, "no_loadcell"),
         (186, T, "no_spectra"), (186, T, "swinging_door")]


def fresh38_cases(only: str | None = None) -> list[Case]:
    """The thirty-ninth held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds
    184-186)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh38_cases, "inject_fresh38", "fresh38")
