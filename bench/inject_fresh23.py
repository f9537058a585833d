"""A twenty-fourth held-out set for the diagnosis (issue 12), fresh23, written without sight of the diagnosis (its code,
its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh22.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (hydrogen bubbles growing on the cathode
and detaching in a sawtooth, an unpowered CMOS multiplexer back-powered through its ESD diodes, nickel electrodes in a
stir bar's field with Rayleigh's magnetic hysteresis, a superelastic nitinol core's flag-shaped loop, a copper-tape
current collector whose contact lifts off with the strain, cracks that open freely and close against the squeeze film of
their water, a glass bead's weight on the hanging strip's elastica, a tip magnet's torque in a stirrer's field), some on
the history, the clamp pressure or the session's events (the laser's ball head nudged at every button press,
natural-rubber pads creeping and then swelling, a video lamp warming the jaws during each record), some on time (the
clamp hung on a PTFE rod in a cooling bath, Schroeder's paradox relaxing a liquid-soaked strip in saturated air, a
humidity chamber's controller ringing onto its set point), two linear but neither a lag nor a spread of lags (the
back-flow entering a glassy layer as a Case II front, a ramp kernel; the Mandel-Cryer overshoot of a poroelastic slab
between stiff skins) and some from the lab's wiring or sensors (a logger correcting the laser's latency by more than it
has, a laser triggered by the DAQ's sample clock, an induction motor's slip sidebands, a stirrer-hotplate's transformer
shaking the clamp at twice the line through the strip's own transmissibility). Four structures outside the catalogue
(truth "unexplained": a magnetic flowmeter's coils excited at a fraction of the line, the laser's boom dithering the
spot along the bent strip, a logger filling its lost packets by straight lines, a centrifuge run up, held and run down);
clean sessions. All on three bases of new seeds (139-141: the paper strip, the seed-001 strip on its own sweep, the
paper strip 43 mm free) and on the earlier sets' protocol / data-shape variants plus one new here: the load cell's
serial link dropping out until the next re-clamping (``loadcell_dropout``).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh22 are reused (importing inject_fresh22 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import, none replaced. Strengths
are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it made on its case,
measured in memory against the clean base (relative RMS change over all series, form only, no variant; "noise": the
column's sample-to-sample noise at rest, inject_fresh15.rest_noise; the values for the three bases are in
docs/effects.md).

Run: python bench/inject_fresh23.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np

import inject
import inject_fresh22  # noqa: F401  (registers every earlier set's forms, bases, presets and variants)
from inject import Case, Rec, Session, lu, map_disp, ref_disp
from inject_fresh2 import _chrono, _through
from inject_fresh3 import _resist, _sign
from inject_fresh4 import _clamp_law
from inject_fresh9 import _dry_by, _session_grid
from inject_fresh10 import _lambda, _station
from inject_fresh12 import _line_f
from inject_fresh14 import _largest
from inject_fresh18 import _bv
from inject_fresh19 import _plays
from inject_fresh20 import _block_starts
from inject_fresh22 import BETAS, _f1, _grid_lag, _mode, _proxy, _table_map

# the paper's strip 43 mm free (earlier sets used 20, 22-29, 31-42 and 45 mm, and 30 mm is the paper preset itself;
# its 1 V step peaks near 17.5 mm, 16.8 mm at 42 mm x (43/42)^2, inside the laser's +-20 mm): preset "paper_43", base
# "p43_141", registered in every process importing this module
inject.register_free_length("paper_43", 0.043)

inject.BASES.update({
    "paper_139": ("paper-sweep", "paper", 139),
    "s001_140": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 140),
    "p43_141": ("paper-sweep", "paper_43", 141),
})

V_T = 0.025693  # kT/q at 25 C
BETAS6 = BETAS + (4.5 * math.pi, 5.5 * math.pi)  # the fifth and sixth clamped-free roots (cos b cosh b = -1)
# a clamped-free beam's modal participation at its tip, phi_n(1) int_0^1 phi_n dx (1.566, -0.868, 0.509, -0.364, ...)
_XS = np.linspace(0.0, 1.0, 2001)
TIP_SHARE = [_mode(b, 1.0)[0] * float(np.trapezoid([_mode(b, x)[0] for x in _XS], _XS)) for b in BETAS6]


# ------------------------------------------------------------------------------------------------ tools


def _by_block(s: Session) -> list[list[Rec]]:
    """The session's time series grouped by pressure block, blocks and records in time order."""
    out: dict[float, list[Rec]] = {}
    for r in _chrono(s):
        out.setdefault(float(r.entry["pressure_kPa"]), []).append(r)
    return list(out.values())


def _settings(s: Session) -> dict[float, float]:
    """Each pressure's setting time: 10-40 s before its block's first record (drawn per block)."""
    blocks = _block_starts(s)
    return {p: a - ld for (p, a), ld in zip(blocks, s.rng.uniform(10.0, 40.0, len(blocks)))}


def _transmissibility(w1: float, zeta: float, w: float) -> complex:
    """The tip's absolute motion over its clamp's (base excitation), six clamped-free modes from the first at w1."""
    out = 1.0 + 0.0j
    for b, g in zip(BETAS6, TIP_SHARE):
        wn = w1 * (b / BETAS[0]) ** 2
        out += g * w * w / (wn * wn - w * w + 2j * zeta * wn * w)
    return complex(out)


# ------------------------------------------------------------------------------------------------ back relaxation


def br_case_two_front(s: Session) -> None:
    """The water the back-flow returns enters the anode side, which the forward drag has just left drier than the rest
    of the membrane, and there it meets glassy polymer: below its glass transition a swollen polymer takes up water as a
    sharp front that advances at a constant speed set by the chains' relaxation, not by diffusion (Thomas and Windle's
    Case II sorption, Alfrey's classification). The opposing swelling then grows linearly in time and stops when the
    front has crossed the layer, T = l/v (4-20 s, log): a ramp kernel, 1 - K2 (1 - exp(-s T))/(s T) (K2 0.8-1.2), whose
    step response bends back in a straight line and stops with a kink, its frequency response with notches at k/T.
    Through inject_fresh2._through with 60 s of the session's history; displacement only. Measured (p43_141)
    displacement RMS -68 % (residual 110 %, 14000x its noise), the 1 V steps (17.5 mm clean) peaking at 4.7 mm after 4 s
    and falling back to -1.35 mm by the plateaus' end."""
    k2, T = s.rng.uniform(0.8, 1.2), lu(s.rng, 4.0, 20.0)

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        def h(z: np.ndarray) -> np.ndarray:
            zt = np.asarray(z, complex) * T
            with np.errstate(divide="ignore", invalid="ignore"):
                ramp = np.where(np.abs(zt) < 1e-8, 1 - zt / 2, -np.expm1(-zt) / zt)
            return 1 - k2 * ramp

        return h

    new = _through(s, H, 60.0)
    map_disp(s, lambda r, d: new[id(r)])


def br_mandel_cryer(s: Session) -> None:
    """The membrane as a Biot poroelastic slab between two stiff plated skins: when the drive's swelling is imposed, the
    layers next to the drained faces let their water go first and, held by the skins, squeeze the core, whose pore
    pressure first rises above its initial value before it drains in turn (the Mandel-Cryer effect of consolidation).
    The opposing swelling so overshoots its final share and then gives part of it back: 1 - K2 ((1 + a)/(1 + s tau1) -
    a/(1 + s tau2)) (K2 0.7-1.1, a 0.2-0.5, tau1 1.5-6 s log, tau2 4-10 times tau1): a held bend falls below where it
    ends and recovers towards it, a give-back that is not monotonic. Through inject_fresh2._through with 240 s of the
    session's history; displacement only. Measured (s001_140) displacement RMS -72 % (residual 76 %, 2500x its noise),
    the 1 V steps (4.7 mm clean) rising to 0.87 mm, falling back to 0.72 mm and recovering to 1.1 mm by the plateaus'
    end."""
    k2, a = s.rng.uniform(0.7, 1.1), s.rng.uniform(0.2, 0.5)
    t1 = lu(s.rng, 1.5, 6.0)
    t2 = t1 * s.rng.uniform(4.0, 10.0)

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        return lambda z: 1 - k2 * ((1 + a) / (1 + t1 * np.asarray(z)) - a / (1 + t2 * np.asarray(z)))

    new = _through(s, H, 240.0)
    map_disp(s, lambda r, d: new[id(r)])


# ------------------------------------------------------------------------------------------------ faradaic current


def far_bubble_detachment(s: Session) -> None:
    """Electrolysis (a symmetric Butler-Volmer branch, 0.1-0.4 mA at 1 V, log, v_t 0.1-0.2 V) whose gas stays on the
    faces as a few large bubbles pinned at the cracks' mouths until buoyancy tears them off: the cathode's hydrogen
    bubble grows with the charge passed (the anode's oxygen at half its volume) and screens the area under it, its
    footprint as its volume to the 2/3, up to 0.2-0.5 of the active area when it detaches, which it does once the gas of
    0.5-3 s of the 1 V current has gone into it (log); at rest the bubbles dissolve (30-120 s, log). The current a held
    drive passes is a sawtooth, falling as the bubble grows and jumping back as it leaves, its period set by the current
    (the 0.5 V sines' bubbles grow four to twelve times slower); the DC does not decay. Sample by sample through the
    session in time order; the current only. Measured (paper_139) current RMS +0.33 % (residual 1.2 %, 0.93x its noise),
    a sawtooth between 0.079 and 0.103 mA on the 1 V steps' plateaus (a period of 0.77 s)."""
    i1, vt = lu(s.rng, 1e-4, 4e-4), s.rng.uniform(0.1, 0.2)
    qd, cover, tau_d = lu(s.rng, 0.5, 3.0) * i1, s.rng.uniform(0.2, 0.5), lu(s.rng, 30.0, 120.0)
    vol, t_end = [0.0, 0.0], None  # each face's bubble, in units of its volume at detachment
    for r in _chrono(s):
        t, v = r.cols["t_s"], r.cols["v_V"]
        if t_end is not None:
            vol = [x * math.exp(-max(float(t[0]) - t_end, 0.0) / tau_d) for x in vol]
        dt = 1.0 / r.fs
        out = np.empty(v.size)
        for k, (ik, vk) in enumerate(zip(_bv(v, i1, vt).tolist(), v.tolist())):
            cath = 0 if vk >= 0 else 1
            ik *= 1 - cover * vol[cath] ** (2 / 3)
            out[k] = ik
            g = abs(ik) * dt / qd
            vol[cath] += g
            vol[1 - cath] += 0.5 * g
            vol = [0.0 if x >= 1.0 else x for x in vol]
        r.cols["i_A"] = r.cols["i_A"] + out
        t_end = float(t[-1])


def _rail(v: np.ndarray, fs: float, V: float, R: float, C: float, Is: float, a: float) -> tuple[np.ndarray, float]:
    """An unpowered supply rail (C, the board's load R) charged from the line v through an ESD diode (Is, n V_T = a):
    implicit in each sample (Newton on C (V' - V)/dt + V'/R = Is (exp((v - V')/a) - 1)), exact decay while the diode is
    off. Returns the diode's current per sample and the last rail voltage."""
    dt = 1.0 / fs
    g0, decay = C / dt, math.exp(-dt / (R * C))
    out = np.zeros(v.size)
    for k, vk in enumerate(v.tolist()):
        Vd = V * decay
        if Is * math.exp(min((vk - Vd) / a, 600.0)) * dt / C < 1e-9:
            V = Vd
            continue
        x = Vd
        for _ in range(80):
            e = Is * math.exp(min((vk - x) / a, 600.0))
            step = (g0 * (x - V) + x / R - (e - Is)) / (g0 + 1.0 / R + e / a)
            x -= step
            if abs(step) < 1e-10:
                break
        out[k] = g0 * (x - V) + x / R
        V = x
    return out, V


def far_backpowered_mux(s: Session) -> None:
    """The lab's switch box routes the strip to the DAQ or to the impedance analyser through a CMOS analogue multiplexer
    powered from the analyser's front-panel supply, which is off while the analyser idles: the drive line stays on the
    off chip's pin, and through that pin's ESD diodes the drive back-powers the unpowered chip (a classic CMOS fault).
    Each diode (Is 1-100 pA, log, ideality 1.6-2.0) charges its rail's decoupling capacitor (1-10 uF, log) whenever the
    drive rises a diode drop above it, and the board's own load (1-5 kOhm, log) drains the rail: a held 1 V draws the
    load's current with the rail a diode drop below the drive (0.05-0.3 mA), each new peak of the drive a spike that
    recharges the rail, the 0.5 V sines almost nothing. A nonlinear conductance with memory on both polarities (one rail
    each). Sample by sample through the session in time order (the rails discharging over the rests); the current only.
    Measured (s001_140) current RMS +0.19 % (residual 0.82 %, 2.2x its noise): +0.052 mA on the 1 V steps' plateaus,
    0.16 mA at their edges."""
    R, C = lu(s.rng, 1e3, 5e3), lu(s.rng, 1e-6, 1e-5)
    Is, a = lu(s.rng, 1e-12, 1e-10), s.rng.uniform(1.6, 2.0) * V_T
    up, dn, t_end = 0.0, 0.0, None
    for r in _chrono(s):
        t, v = r.cols["t_s"], r.cols["v_V"]
        if t_end is not None:
            drop = math.exp(-max(float(t[0]) - t_end, 0.0) / (R * C))
            up, dn = up * drop, dn * drop
        iu, up = _rail(v, r.fs, up, R, C, Is, a)
        il, dn = _rail(-v, r.fs, dn, R, C, Is, a)
        r.cols["i_A"] = r.cols["i_A"] + iu - il
        t_end = float(t[-1])


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_rayleigh_nickel(s: Session) -> None:
    """Electrodes of electroless nickel (a cheaper IPMC plating) near the stirring bar left in the cuvette below the
    strip: the bar's field, graded along the bend, pulls on the films' magnetisation, and nickel at such weak fields
    follows Rayleigh's law: a susceptibility growing with the field's swing and a lens-shaped loop whose area goes as
    the swing cubed (the pinned domain walls' uniform Preisach density). The field at the films follows the tip's
    position, so the strip feels an extra force c (0.01-0.04 of the session's largest bend, its loop's height at the
    largest swing) times the Rayleigh operator of d over the largest bend (40 plays of uniform weight over its range,
    from the demagnetised state: b h^2 on the first rise), through the strip's first mode (a resonator at the preset's
    f1, damping 0.1-0.25): little on small bends, a loop on large ones as wide at 0.01 Hz as at 10 Hz. The plays through
    the session in time order; displacement only. Measured (p43_141) displacement RMS +4.9 % (residual 6.1 %, 740x its
    noise)."""
    big = _largest(s) or ref_disp(s)
    c, zeta = s.rng.uniform(0.01, 0.04), s.rng.uniform(0.1, 0.25)
    radii = (np.arange(40) + 0.5) / 40 * 1.05
    w = 2 * 1.05 / 40
    state, e = np.zeros(radii.size), {}
    for r in _chrono(s):
        y, state = _plays(r.cols["disp_m"] / big, radii, state)
        e[id(r)] = c * big * w * y.sum(axis=1)
    cache: dict[float, float] = {}

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        w1 = 2 * math.pi * _f1(s, float(r.entry["pressure_kPa"]), cache)
        return lambda q: w1**2 / (np.asarray(q) ** 2 + 2 * zeta * w1 * np.asarray(q) + w1**2)

    proxy, pairs = _proxy(s, e)
    out = _through(proxy, H, 2.0)
    for r, q in pairs:
        r.cols["disp_m"] = r.cols["disp_m"] + out[id(q)]


def _flag(x: np.ndarray, xi: float, sg: float, c: float, ff: float, fr: float,
          e: float) -> tuple[np.ndarray, float, float]:
    """A superelastic core's restoring force on the strip's bend x (tip units; stiffness share c): austenite elastic,
    forward transformation at the force ff (martensite share xi, strain e per unit, sign sg), reverse at fr < ff.
    Returns the tip's reading (slope 1 at rest) and the state."""
    out = np.empty(x.size)
    for k, xk in enumerate(x.tolist()):
        if xi <= 0.0:
            xi, sg = 0.0, (1.0 if xk >= 0 else -1.0)
        g = c * (sg * xk - e * xi) / (1 + c)
        if g > ff:
            xi = min((sg * xk - ff * (1 + c) / c) / e, 1.0)
        elif g < fr and xi > 0.0:
            xi = max((sg * xk - fr * (1 + c) / c) / e, 0.0)
        out[k] = (1 + c) * (xk - c * (xk - e * xi * sg) / (1 + c))
    return out, xi, sg


def hy_nitinol_core(s: Session) -> None:
    """The strip tested as a catheter's steering actuator, bonded along a superelastic nitinol core wire (a guidewire's
    core of 0.1-0.2 mm): the wire bends with it and adds its own restoring moment, a share c (0.03-0.08) of the strip's
    stiffness while austenitic; past a transformation moment (reached at 0.3-0.55 of the session's largest bend) the
    wire turns to martensite at a constant moment, a soft plateau, and on unloading it stays elastic until a lower
    moment (0.3-0.6 of the forward one) where it turns back at constant moment until it is all austenite again (the full
    transformation 0.8-1.5 largest bends away). A flag-shaped loop on each side of rest, pinched at zero (no residual
    set: superelastic, not plastic), rate-independent, nothing below the transformation (the elastic share is taken as
    the fitted stiffness: slope 1 at rest). Sample by sample through the session in time order; displacement only.
    Measured (paper_139) displacement RMS +2.5 % (residual 2.7 %, 160x its noise)."""
    big = _largest(s) or ref_disp(s)
    c = s.rng.uniform(0.03, 0.08)
    xf = s.rng.uniform(0.3, 0.55) * big
    xr = xf * s.rng.uniform(0.3, 0.6)
    e = s.rng.uniform(0.8, 1.5) * big
    ff, fr = c * xf / (1 + c), c * xr / (1 + c)
    xi, sg = 0.0, 1.0
    for r in _chrono(s):
        r.cols["disp_m"], xi, sg = _flag(r.cols["disp_m"], xi, sg, c, ff, fr, e)


# ------------------------------------------------------------------------------------------------ time delay


def td_latency_overcorrection(s: Session) -> None:
    """The logging script corrects the laser's stream for its latency as the head's datasheet gives it (10, 15 or 20 ms,
    drawn: the value for its standard mode), by shifting each record's displacement earlier by that many whole samples
    of the record, while the head runs in its fast mode with a true latency of 3-8 ms (log): every record's displacement
    advanced by more than it was late, a pure lead of 2-17 ms (a little different from record to record with the
    rounding), the record's last samples held at its last reading. Gain unchanged, the phase advanced in proportion to
    the frequency, the steps' rise starting before the drive's edge. The head's latency through inject_fresh2._through
    (a pure delay, with 1 s of the session's history), the shift in whole samples; displacement only. Measured
    (paper_139) displacement RMS +0.0020 % (residual 0.18 %, 11x its noise)."""
    nominal, true = 5e-3 * int(s.rng.integers(2, 5)), lu(s.rng, 3e-3, 8e-3)
    late = _through(s, lambda r: (lambda z: np.exp(-np.asarray(z) * true)), 1.0)
    for r in s.series():
        d, n = late[id(r)], int(round(nominal * r.fs))
        r.cols["disp_m"] = np.r_[d[n:], np.full(min(n, d.size), d[-1])][: d.size]


def td_triggered_laser(s: Session) -> None:
    """The laser externally triggered by the DAQ's sample clock (one measurement per DAQ sample, so that the two never
    drift apart), each measurement the spot's position over an exposure of 0.2-1 ms (log) started by the trigger, its
    result reaching the analogue output after the head's processing time p (2-6 ms, log): each DAQ sample reads the
    measurement triggered ceil(p fs) samples before, a delay of whole samples of each record's own rate (1-2 at 200 Hz,
    2-6 at 1 kHz) less half the exposure; and since the laser measures only when triggered, the first samples of a
    record read what its output still holds from the previous record's last trigger. Displacement only. Measured
    (p43_141) displacement RMS -0.00048 % (residual 0.20 %, 24x its noise)."""
    p, half = lu(s.rng, 2e-3, 6e-3), lu(s.rng, 2e-4, 1e-3) / 2
    held = None
    for r in _chrono(s):
        t, d = r.cols["t_s"], r.cols["disp_m"]
        m = min(max(int(math.ceil(p * r.fs - 1e-9)), 1), d.size)
        first = float(d[0]) if held is None else held
        held = float(d[-1])
        r.cols["disp_m"] = np.r_[np.full(m, first), np.interp(t[:-m] + half, t, d)]


# ------------------------------------------------------------------------------------------------ sensor offset


def so_button_nudge(s: Session) -> None:
    """The laser head on a ball head, aimed once a margin m (0.1-0.3 mm) inside the tip's end, and the lab's procedure
    starting each record with the head's own 'measure' button: the press loads the ball head, which slips a little under
    it now and then (stick-slip of its clamp: at 0.3-0.6 of the presses, each slip 8-25 um at the spot, log, times a
    log-normal spread), always the same way, so the spot walks inboard along the strip record by record: a staircase of
    stations, constant within each record and never walking back. The strip read at the moving station
    (inject_fresh10._station); displacement only. Measured (s001_140) displacement RMS -3.5 % (residual 3.8 %, 130x its
    noise), the spot 0.18 mm inboard of the end at the first record and 0.68 mm at the last."""
    L = float(s.specimen["length_m"])
    x, p_slip, size = s.rng.uniform(1e-4, 3e-4), s.rng.uniform(0.3, 0.6), lu(s.rng, 8e-6, 25e-6)
    at = {}
    for r in _chrono(s):
        if s.rng.random() < p_slip:
            x += size * float(np.exp(s.rng.normal(0.0, 0.5)))
        at[id(r)] = x
    _station(s, lambda r: np.full(r.cols["t_s"].size, 1 - at[id(r)] / L), 1 - x / L)


def so_ptfe_hanger(s: Session) -> None:
    """The clamp hung from the stand on a PTFE rod (an insulating hanger, so that the jaws' contacts float), the rod
    dipping into a bath filled warm (5-15 K above the room, 0-600 s before the first record) that cools back over
    1200-3600 s (log): PTFE expands ten times as much as aluminium (1.25e-4/K), and its 80-200 mm (log), lowered at the
    room's temperature, follow the bath through 60-300 s (log): the rod first warms (the hanging strip sinks) and then
    cools with the bath (the strip rises), and the level beam, aimed a margin 0.1-0.3 mm inside the tip's end (beyond
    the rod's whole travel) before the first record, meets the strip first further in and then further and further out:
    after the first minutes the station walks towards the tip, the gain creeping up. The strip read at the moving
    station (inject_fresh10._station); displacement only. Measured (paper_139) displacement RMS -2.1 % (residual 2.1 %,
    120x its noise), the spot 0.33 mm inboard at the first record, 0.37 mm as the rod warmed and 0.31 mm at the last."""
    L = float(s.specimen["length_m"])
    dT, tau_b, tau_r = s.rng.uniform(5.0, 15.0), lu(s.rng, 1200.0, 3600.0), lu(s.rng, 60.0, 300.0)
    lead, rod = s.rng.uniform(0.0, 600.0), lu(s.rng, 0.08, 0.2) * 1.25e-4
    tg = _session_grid(s, 1.0, lead)
    temp = _grid_lag(tg, dT * np.exp(-(tg - tg[0]) / tau_b), tau_r, 0.0)
    t_aim = s.t0 - s.rng.uniform(30.0, 120.0)
    shift = rod * (temp - float(np.interp(t_aim, tg, temp)))  # m: the strip lower (the station inboard) when > 0
    m0 = 5e-5 + max(0.0, -float(np.min(shift))) + s.rng.uniform(1e-4, 3e-4)
    margin = m0 + shift
    _station(s, lambda r: 1 - np.interp(r.cols["t_s"], tg, margin) / L, 1 - float(np.max(margin)) / L)


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_latex_pads(s: Session) -> None:
    """Pads cut from natural rubber (a latex glove's or a balloon's rubber, a makeshift of many labs) under a screw
    clamp's fixed gap, wet since the bath was filled (0-600 s before the first setting): the rubber creeps
    logarithmically from each setting (1.5-3 % of its force a decade, tau 2-20 s, log), and takes up water through its
    water-soluble impurities, osmotically and without saturating in an hour (as the square root of the time since the
    filling), so it swells against the fixed gap and adds the same newtons at any setting (0.3-1.2 N in the first hour
    after the filling). At the light settings the fall slows and turns into a rise once the swelling's newtons outpace
    the creep, at the tight ones the force only falls. Through the preset's clamp law (inject_fresh4._clamp_law), the
    load cell showing it. Measured (p43_141) displacement RMS -0.00036 % (residual 0.059 %, 7.2x its noise), current RMS
    -0.039 % (residual 0.25 %, 0.20x its noise), the load cell at 0.959-0.990 of its reading."""
    area = float(s.specimen["clamp_area_m2"])
    r_c, tau_c = s.rng.uniform(0.015, 0.03), lu(s.rng, 2.0, 20.0)
    dF, fill = s.rng.uniform(0.3, 1.2), s.rng.uniform(0.0, 600.0)
    t_set = _settings(s)
    t_imm = min(t_set.values(), default=s.t0) - fill

    def W(t: np.ndarray) -> np.ndarray:
        return np.sqrt(np.clip(np.asarray(t, float) - t_imm, 0, None) / 3600.0)

    def rel(t: np.ndarray, p: float, t_first: float) -> np.ndarray:
        ts = t_set.get(p, t_first - 20.0)
        u = np.clip(np.asarray(t, float) - ts, 0, None)
        return 1 - r_c * np.log10(1 + u / tau_c) + dF * (W(t) - W(np.array([ts]))[0]) / (p * 1e3 * area)

    _clamp_law(s, rel)


def cr_lamp_jaws(s: Session) -> None:
    """A screw clamp on silicone pads filmed under a halogen video lamp that the logger switches on for each record and
    off after it, the lamp aimed at the tip but lighting the clamp's black anodised jaws too: the jaws and pads warm
    while a record runs and cool over the rests (a lag of 20-60 s, log), and silicone's expansion under the fixed gap
    adds force with its temperature, the same newtons at any setting (0.2-0.8 N at the jaws' full warming), on top of
    the pads' logarithmic creep from each setting (1-2.5 % a decade, tau 2-20 s, log). The load cell rises within every
    record (most at the light settings) and falls back between them on a falling trend. Through the preset's clamp law
    (inject_fresh4._clamp_law), the load cell showing it. Measured (paper_139) displacement RMS +0.00055 % (residual
    0.055 %, 3.3x its noise), current RMS -0.056 % (residual 0.26 %, 0.19x its noise), the load cell at 0.959-1.030 of
    its reading."""
    area = float(s.specimen["clamp_area_m2"])
    dF, tau_h = s.rng.uniform(0.2, 0.8), lu(s.rng, 20.0, 60.0)
    r_c, tau_c = s.rng.uniform(0.01, 0.025), lu(s.rng, 2.0, 20.0)
    t_set = _settings(s)
    tg = _session_grid(s, 0.5, 120.0)
    on = np.zeros(tg.size)
    for r in s.series():
        on[(tg >= r.cols["t_s"][0]) & (tg <= r.cols["t_s"][-1])] = 1.0
    heat = _grid_lag(tg, on, tau_h, 0.0)

    def rel(t: np.ndarray, p: float, t_first: float) -> np.ndarray:
        ts = t_set.get(p, t_first - 20.0)
        u = np.clip(np.asarray(t, float) - ts, 0, None)
        warm = np.interp(t, tg, heat) - float(np.interp(ts, tg, heat))
        return 1 - r_c * np.log10(1 + u / tau_c) + dF * warm / (p * 1e3 * area)

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_schroeder_relaxation(s: Session) -> None:
    """A strip in air soaked in liquid water (lambda 20-23 water molecules per sulfonate) and mounted 60-600 s before
    the first record in a closed box kept near saturation (0.90-0.98 RH) to stop it drying: yet Nafion in saturated
    vapour holds only what its vapour isotherm gives (inject_fresh10._lambda, about 10-13 here: Schroeder's paradox),
    and the liquid-equilibrated state relaxes to it as the surface's hydrophobic skin reorganises, slowly and
    non-exponentially (Kohlrausch, exp(-(u/tau)^beta), tau 800-3000 s log, beta 0.5-0.8). A loss of a third of the water
    or more that is steep at first and keeps creeping, with no air flow, heat or drive to blame. The gain as the water,
    the conductance as its 1.5-2.5th power, relative to the first record, the spectra at the next series' start
    (inject_fresh9._dry_by). Measured (s001_140) displacement RMS -24 % (residual 29 %, 970x its noise), current RMS -42
    % (residual 46 %, 120x its noise), the spectra's |Z| at 0.1 Hz +0, +61, +101, +128 %."""
    lam_l, rh = s.rng.uniform(20.0, 23.0), s.rng.uniform(0.90, 0.98)
    lam_v = float(_lambda(np.array([rh]))[0])
    tau, beta = lu(s.rng, 800.0, 3000.0), s.rng.uniform(0.5, 0.8)
    t_out, gc = s.t0 - s.rng.uniform(60.0, 600.0), s.rng.uniform(1.5, 2.5)

    def lam(t: np.ndarray) -> np.ndarray:
        u = np.clip(np.asarray(t, float) - t_out, 0, None)
        return lam_v + (lam_l - lam_v) * np.exp(-((u / tau) ** beta))

    w0 = float(lam(np.array([s.t0]))[0])
    _dry_by(s, lambda t: 1 - lam(t) / w0, lambda t: 1 - (lam(t) / w0) ** gc)


def dh_humidity_ringing(s: Session) -> None:
    """A strip in air in a humidity-controlled enclosure (a humidifier and a desiccant dryer on a PID loop) switched to
    a drier set point 0-120 s before the first record (0.10-0.25 below the room's 0.45-0.60 RH), its loop tuned too
    tight: the humidity rings onto its new set point as a second-order step (period 600-1500 s, damping 0.15-0.3),
    overshooting dry and coming back, and the strip's water follows Nafion's isotherm (inject_fresh10._lambda) through
    its sorption lag (60-300 s, log): a loss that overshoots, partly comes back and settles, the conductance leading.
    The gain as the water, the conductance as its 1.5-2.5th power, relative to the first record, the spectra at the next
    series' start (inject_fresh9._dry_by). Measured (s001_140) displacement RMS -10 % (residual 12 %, 390x its noise),
    current RMS -24 % (residual 25 %, 66x its noise), the spectra's |Z| at 0.1 Hz +0, +27, +31, +32 %."""
    rh0, drop = s.rng.uniform(0.45, 0.60), s.rng.uniform(0.10, 0.25)
    period, zeta = s.rng.uniform(600.0, 1500.0), s.rng.uniform(0.15, 0.3)
    lead, tau_s, gc = s.rng.uniform(0.0, 120.0), lu(s.rng, 60.0, 300.0), s.rng.uniform(1.5, 2.5)
    tg = _session_grid(s, 1.0, lead)
    u = tg - tg[0]
    wd = 2 * math.pi / period
    wn = wd / math.sqrt(1 - zeta**2)
    step = 1 - np.exp(-zeta * wn * u) * (np.cos(wd * u) + zeta / math.sqrt(1 - zeta**2) * np.sin(wd * u))
    w = _grid_lag(tg, _lambda(np.clip(rh0 - drop * step, 0.02, 0.95)), tau_s, float(_lambda(np.array([rh0]))[0]))
    w0 = float(np.interp(s.t0, tg, w))
    _dry_by(s, lambda t: 1 - np.interp(t, tg, w) / w0, lambda t: 1 - (np.interp(t, tg, w) / w0) ** gc)


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_taped_collector(s: Session) -> None:
    """A copper tape (its conductive acrylic adhesive) laid along one face (drawn) as a current collector, to carry the
    drive to the tip past the plating's resistance: the tape is inextensible and its adhesive thin, so as that face
    stretches or shortens the adhesive shears and the conductive particles bridging it to the plating part, the tape
    pulled taut in tension and buckling off in compression: the face loses its bypass as a Lorentzian complement of its
    strain, dR/R = k e^2/(e^2 + e0^2) (e the face's strain over the session's largest, e0 0.3-0.7, k 0.3-1.0 times
    0.4-0.8 in tension and 1.0-1.5 in compression): quadratic at small bends, saturating at large ones, unequal on the
    two sides, reversible. Gains fall by 0.03-0.08 (displacement) and 0.06-0.15 (current) per unit of dR/R
    (inject_fresh3._resist). Measured (p43_141) displacement RMS -4.8 % (residual 4.9 %, 590x its noise), current RMS
    -0.72 % (residual 2.1 %, 1.7x its noise)."""
    side, k = _sign(s), s.rng.uniform(0.3, 1.0)
    kc, kt, e0 = k * s.rng.uniform(1.0, 1.5), k * s.rng.uniform(0.4, 0.8), s.rng.uniform(0.3, 0.7)
    q = ref_disp(s) / (_largest(s) or ref_disp(s))

    def law(r: Rec, e: np.ndarray) -> np.ndarray:
        x = side * q * np.asarray(e)
        return np.where(x >= 0, kt, kc) * x * x / (x * x + e0 * e0)

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


def sr_squeeze_film_cracks(s: Session) -> None:
    """Cracks of the tensioned face (one face, drawn, the other at 0.2-0.5 of its gauge) opened beyond e0 (0.05-0.2 of
    the session's largest tension), their gaps full of water: opening, the water in a crack cavitates and air and vapour
    fill it, so a crack opens as fast as the face stretches; closing, its lips must squeeze the water out through a gap
    of width w, whose resistance goes as 1/w^3 (Reynolds' squeeze film), so a crack closes at a rate (w - w_t) w^3/tau
    (tau 0.2-2 s at the largest opening, log) that stalls as it narrows: the resistance follows a bend up at once and
    lags it on the way down, and after a large bend it falls back ever more slowly, its last part as a power law
    t^(-1/3). The openings through the session in time order (closing over the rests at that law). Gains fall by
    0.03-0.08 (displacement) and 0.06-0.15 (current) per unit of dR/R (inject_fresh3._resist). Measured (paper_139)
    displacement RMS -4.4 % (residual 4.6 %, 270x its noise), current RMS -1.5 % (residual 2.3 %, 1.7x its noise)."""
    side, o = _sign(s), s.rng.uniform(0.2, 0.5)
    e0, tau = s.rng.uniform(0.05, 0.2), lu(s.rng, 0.2, 2.0)
    ref = ref_disp(s)
    k = ref / (_largest(s) or ref)
    w, t_end, dr = [0.0, 0.0], None, {}
    for r in _chrono(s):
        x, t, dt = k * r.cols["disp_m"] / ref, r.cols["t_s"], 1.0 / r.fs
        out = np.zeros(x.size)
        for f, (g, sg) in enumerate(((1.0, side), (o, -side))):
            if t_end is not None:
                w[f] /= (1 + 3 * w[f] ** 3 * max(float(t[0]) - t_end, 0.0) / tau) ** (1 / 3)
            y, wf = np.empty(x.size), w[f]
            for j, tj in enumerate(np.clip(sg * x - e0, 0, None).tolist()):
                wf = tj if tj >= wf else tj + (wf - tj) / (1 + dt * wf**3 / tau)
                y[j] = wf
            w[f] = wf
            out += g * y
        dr[id(r)], t_end = out, float(t[-1])
    _resist(s, lambda r, e: dr[id(r)], (0.03, 0.08), (0.06, 0.15))


# ------------------------------------------------------------------------------------------------ large deflection


def _hanging_arc(u: np.ndarray, beta: float, n: int = 200) -> np.ndarray:
    """The tip's lateral position (over L) of a hanging strip bent by a uniform moment (u = its angle without a load)
    with a weight beta (W L^2/EI) at its tip: theta' = u - beta (Y - y), y' = sin theta, RK4 over n steps, Y by
    fixed-point iteration from the unloaded arc."""
    u = np.asarray(u, float)
    small = np.abs(u) < 1e-12
    Y = np.where(small, u / 2, (1 - np.cos(u)) / np.where(small, 1.0, u))
    h = 1.0 / n
    for _ in range(80):
        th, y = np.zeros_like(u), np.zeros_like(u)
        for _ in range(n):
            k1 = (u - beta * (Y - y), np.sin(th))
            k2 = (u - beta * (Y - y - h / 2 * k1[1]), np.sin(th + h / 2 * k1[0]))
            k3 = (u - beta * (Y - y - h / 2 * k2[1]), np.sin(th + h / 2 * k2[0]))
            k4 = (u - beta * (Y - y - h * k3[1]), np.sin(th + h * k3[0]))
            th = th + h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
            y = y + h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
        done = float(np.max(np.abs(y - Y))) < 1e-14
        Y = y
        if done:
            break
    return Y


def ld_hanging_tip_bead(s: Session) -> None:
    """A glass bead (a retro-reflective target of 1-2 mm for the laser's spot) glued at the tip of the hanging strip:
    its weight less the water's buoyancy pulls along the strip at rest, and on the bent strip it acts at the tip's
    lateral offset, a pendulum's restoring force on the elastica: with the drive's uniform moment, theta' = u - beta (Y
    - y(s)), y' = sin theta (beta = W L^2/EI 0.05-0.2, u the tip's angle the drive alone would give, 2 d/L), solved for
    the tip's lateral position Y and read relative to the same arc without the bead (the arc's own projection is another
    effect), slope 1 at rest (the bead's linear pendulum stiffness taken as the fitted one; its inertia too). Since the
    bent strip's lateral positions fall behind the linear ones, the restoring lever does too and the large bends read
    long on both sides: a softening odd law, no sensor to blame. Tabulated and interpolated; displacement only. Measured
    (s001_140) displacement RMS +0.14 % (residual 0.15 %, 5.1x its noise)."""
    L, beta = float(s.specimen["length_m"]), s.rng.uniform(0.05, 0.2)

    def reading(x: np.ndarray) -> np.ndarray:
        u = np.abs(2 * np.asarray(x, float) / L)
        ug = np.linspace(0.0, max(float(np.max(u)), 1e-6), 161)[1:]  # the ratio is even and smooth: on a grid
        ratio = _hanging_arc(ug, beta) / ((1 - np.cos(ug)) / ug)
        return np.asarray(x, float) * np.interp(u, np.r_[0.0, ug], np.r_[ratio[0], ratio])

    _table_map(s, reading)


def ld_compass_torque(s: Session) -> None:
    """A small magnet glued at the tip (left from a magnetic readout the lab uses on other days), magnetised along the
    strip, in the field of the stirrer-hotplate's drive magnet under the cuvette, which runs along the hanging strip:
    the field twists the tip magnet towards its own direction with a torque m B sin(theta), theta the tip's angle, a
    compass needle's; a tip torque bends the strip uniformly, as the drive does, so the tip's angle u = kappa L obeys u
    + c sin u = u0 (c 0.05-0.15, the torque's stiffness over the strip's; the magnet aligned with the field, restoring,
    or against it, destabilising, drawn), u0 the angle the drive alone would give (2 d/L). Linear in the small bends
    (taken as the fitted stiffness: slope 1 at rest) and, as sin u falls below u, softening at the large ones when it
    restores and stiffening when it destabilises: an odd geometric law of the tip's rotation. Tabulated and
    interpolated; displacement only. Measured (p43_141) displacement RMS +0.60 % (residual 0.68 %, 82x its noise)."""
    L = float(s.specimen["length_m"])
    c, sg = s.rng.uniform(0.05, 0.15), _sign(s)

    def reading(x: np.ndarray) -> np.ndarray:
        u0 = 2 * np.asarray(x, float) / L
        u = u0 / (1 + sg * c)
        for _ in range(40):
            u = u - (u + sg * c * np.sin(u) - u0) / (1 + sg * c * np.cos(u))
        return u * L / 2

    _table_map(s, reading)


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_slip_sidebands(s: Session) -> None:
    """An induction motor on the bench's circuit (a fume hood's fan, a circulator's pump) with a broken rotor bar: its
    leakage field at the line frequency (with a third harmonic, 0.05-0.2) is amplitude-modulated at twice the slip
    frequency (slip 2-5 %) by the rotor's asymmetry, the motor-current-signature sidebands at f (1 +- 2 s), depth
    0.1-0.4 (a share of the modulation on each), 1-4 um on the laser's cable and 2-8 uA on the current amplifier's input
    (log), each channel with its own coupling phase, the modulation's phase the rotor's. Phase locked to the session
    clock. Measured (paper_139) displacement RMS +3.9e-06 % (residual 0.028 %, 1.7x its noise), current RMS +1.6e-05 %
    (residual 0.057 %, 0.043x its noise)."""
    f0 = _line_f(s)
    slip, m, h3 = s.rng.uniform(0.02, 0.05), s.rng.uniform(0.1, 0.4), s.rng.uniform(0.05, 0.2)
    amp = {"disp_m": lu(s.rng, 1e-6, 4e-6), "i_A": lu(s.rng, 2e-6, 8e-6)}
    ph = {col: s.rng.uniform(0, 2 * np.pi, 2) for col in amp}
    pm = s.rng.uniform(0, 2 * np.pi)
    for r in s.series():
        t = r.cols["t_s"]
        env = 1 + m * np.cos(2 * np.pi * 2 * slip * f0 * t + pm)
        for col, a in amp.items():
            p = ph[col]
            hum = env * np.cos(2 * np.pi * f0 * t + p[0]) + h3 * np.cos(6 * np.pi * f0 * t + p[1])
            r.cols[col] = r.cols[col] + a * hum


def mp_stirrer_base(s: Session) -> None:
    """The cuvette and the clamp's stand on a stirrer-hotplate, switched on at its mains switch (its transformer
    energised) with the stirring and heating off: the transformer's laminations hum magnetostrictively at twice the line
    (1-4 um at the plate, log) and at four times it (0.2-0.5 of that), shaking the clamp; the laser, on its own stand,
    reads the tip's absolute motion, which is the clamp's through the strip's own base-excitation transmissibility 1 +
    sum g_n w^2/(w_n^2 - w^2 + 2 j zeta w_n w) (six clamped-free modes from the preset's f1 at the record's pressure,
    tip participations 1.566, -0.868, 0.509, -0.364, 0.283, -0.231, damping 0.05-0.15): lines at the line's even
    harmonics whose size and phase step with the clamp pressure. Phase locked to the session clock; displacement only.
    Measured (p43_141) displacement RMS +1.2e-05 % (residual 0.026 %, 3.1x its noise)."""
    f0, a = _line_f(s), lu(s.rng, 1e-6, 4e-6)
    h4, zeta = s.rng.uniform(0.2, 0.5), s.rng.uniform(0.05, 0.15)
    p2, p4 = s.rng.uniform(0, 2 * np.pi, 2)
    cache: dict[float, float] = {}
    for r in s.series():
        w1 = 2 * math.pi * _f1(s, float(r.entry["pressure_kPa"]), cache)
        t, out = r.cols["t_s"], 0.0
        for n, an, pn in ((2, a, p2), (4, a * h4, p4)):
            T = _transmissibility(w1, zeta, 2 * math.pi * n * f0)
            out = out + an * abs(T) * np.cos(2 * np.pi * n * f0 * t + pn + np.angle(T))
        r.cols["disp_m"] = r.cols["disp_m"] + out


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_flowmeter_coils(s: Session) -> None:
    """The bath's circulation loop runs through a magnetic-inductive flowmeter, whose coils are excited with a pulsed DC
    square wave locked to the mains at a fraction of it (f/4 or f/8, drawn: 6.25-15 Hz), each reversal settling with the
    coils' L/R (3-10 ms, log): its field reaches the laser's cable (2-8 um) and the current amplifier's input (5-20 uA,
    log), a square wave on both, so lines at the odd multiples of f/k, none of them a multiple of the line frequency,
    right in the stepped sines' band. Phase locked to the session clock. Displacement and current. Measured (paper_139)
    displacement residual 0.091 % of its RMS (5.4x its noise), current residual 0.33 % (0.25x); (p43_141) displacement
    0.029 % (3.5x), current 0.37 % (0.29x)."""
    fl = _line_f(s)
    fc = fl / (4 if s.rng.random() < 0.5 else 8)
    tau, ph = lu(s.rng, 3e-3, 1e-2), s.rng.uniform(0.0, 1.0)
    amp = {"disp_m": _sign(s) * lu(s.rng, 2e-6, 8e-6), "i_A": _sign(s) * lu(s.rng, 5e-6, 2e-5)}
    T = 1.0 / fc
    th = math.tanh(T / (4 * tau))
    for r in s.series():
        c = ((r.cols["t_s"] - s.t0) / T + ph) % 1.0
        second = c >= 0.5
        y = 1 - (1 + th) * np.exp(-np.where(second, c - 0.5, c) * T / tau)
        y = np.where(second, -y, y)
        for col, a in amp.items():
            r.cols[col] = r.cols[col] + a * y


def out_boom_dither(s: Session) -> None:
    """The laser head at the end of a long boom, its controller's cooling fan (2300-2750 rpm, 38-46 Hz, its speed
    wandering +-0.2-0.6 % over 60-300 s) shaking the boom in its soft direction, along the strip: the spot dithers along
    the strip by +-10-30 um (log), and on a bent strip a spot moved along it by x reads lower by the strip's slope there
    times x (2 d/L at the tip on the uniform arc), while a small share (2-8 %) of the motion is along the beam and reads
    at once. A line at the fan's speed whose size follows the bend: none at rest, largest on the steps' plateaus and the
    large sines' crests, sidebands around it on the moving records. Displacement only. Measured (paper_139) displacement
    residual 0.086 % of its RMS (5.1x its noise, peaks of 11 um); (s001_140) 0.15 % (4.8x, 10 um)."""
    L = float(s.specimen["length_m"])
    delta, fr = lu(s.rng, 1e-5, 3e-5), s.rng.uniform(38.0, 46.0)
    wander, Tw, pw = s.rng.uniform(0.002, 0.006), s.rng.uniform(60.0, 300.0), s.rng.uniform(0, 2 * np.pi)
    cb, ph = s.rng.uniform(0.02, 0.08), s.rng.uniform(0, 2 * np.pi)
    for r in s.series():
        u = r.cols["t_s"] - s.t0
        phase = 2 * np.pi * fr * (u + wander * Tw / (2 * np.pi) * (np.sin(2 * np.pi * u / Tw + pw) - math.sin(pw)))
        dx = delta * np.sin(phase + ph)
        d = r.cols["disp_m"]
        r.cols["disp_m"] = d - 2 * d / L * dx + cb * dx


def out_gap_filled(s: Session) -> None:
    """A USB DAQ that loses whole packets now and then (32, 64 or 128 samples, drawn for the session; each lost with a
    probability of 0.3-1.5 %, log, never the first two or the last of a record, at least one in the session) and a
    logger that keeps its grid uniform by filling every lost packet with the straight line between the samples on either
    side, on every column: the drive, the current and the displacement in a gap are straight lines, which the strip
    never did, and the strip's true response carries on after the gap from where the true drive left it. Every column of
    the series (a flat force stays flat). Measured (s001_140) drive residual 3.5 % of its RMS (77x its noise, about 120
    gaps), current 9.0 % (24x), displacement 0.095 % (3.1x); (p43_141) drive 1.2 % (27x, about 100 gaps), current 3.8 %
    (3.1x), displacement 0.012 % (1.4x)."""
    n, p = int(s.rng.choice([32, 64, 128])), lu(s.rng, 3e-3, 1.5e-2)
    cands = [(r, j) for r in s.series() for j in range(2, r.cols["t_s"].size // n - 1)]
    hits = [c for c in cands if s.rng.random() < p]
    if not hits and cands:
        hits = [cands[int(s.rng.integers(len(cands)))]]
    for r, j in hits:
        a, b = j * n - 1, (j + 1) * n
        frac = (np.arange(a + 1, b) - a) / (b - a)
        for col, x in r.cols.items():
            if col != "t_s":
                x = x.copy()
                x[a + 1 : b] = x[a] + (x[b] - x[a]) * frac
                r.cols[col] = x


def out_centrifuge_runup(s: Session) -> None:
    """A benchtop centrifuge on the next bench run 1-3 times in the session (each reaching full speed inside a recorded
    series): its rotor's imbalance shakes the bench, and the laser's stand against the clamp's, at the rotor's speed,
    which rises linearly over 20-60 s to 33-46 or 64-80 Hz (drawn: 2000-4800 rpm), holds for 120-600 s and coasts down
    over 40-120 s: a line whose frequency sweeps up, holds and sweeps down, its size as the speed squared (2-8 um at
    full speed, log), never at the line frequency while it holds. Displacement only. Measured (s001_140) displacement
    residual 0.077 % of its RMS (2.5x its noise over the session, on the 11 % of the samples in its 3 runs, peaks of 6.5
    um); (p43_141) 0.017 % (2.1x, 2 runs over 13 %, 7.8 um)."""
    recs = s.series()
    A, runs, end = lu(s.rng, 2e-6, 8e-6), [], -np.inf
    for _ in range(int(s.rng.integers(1, 4))):
        r0 = recs[int(s.rng.integers(len(recs)))]
        fm = s.rng.uniform(33.0, 46.0) if s.rng.random() < 0.5 else s.rng.uniform(64.0, 80.0)
        up, hold, down = s.rng.uniform(20.0, 60.0), s.rng.uniform(120.0, 600.0), s.rng.uniform(40.0, 120.0)
        t0 = max(float(s.rng.uniform(r0.cols["t_s"][0], r0.cols["t_s"][-1])) - up, end + 60.0)
        runs.append((t0, fm, up, hold, down, s.rng.uniform(0, 2 * np.pi)))
        end = t0 + up + hold + down
    for r in recs:
        t, out = r.cols["t_s"], np.zeros(r.cols["t_s"].size)
        for t0, fm, up, hold, down, ph in runs:
            u = t - t0
            w = np.clip(u - up - hold, 0.0, down)
            f = np.where(u < up, fm * u / up, np.where(u < up + hold, fm, fm * (1 - w / down)))
            cyc = np.where(u < up, fm * u * u / (2 * up),
                           fm * up / 2 + fm * np.clip(u - up, 0.0, hold) + fm * (w - w * w / (2 * down)))
            on = (u >= 0) & (u <= up + hold + down)
            out += np.where(on, A * (f / fm) ** 2 * np.sin(2 * np.pi * cyc + ph), 0.0)
        r.cols["disp_m"] = r.cols["disp_m"] + out


FRESH23_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"case_two_front": br_case_two_front, "mandel_cryer": br_mandel_cryer},
    "faradaic_current": {"bubble_detachment": far_bubble_detachment, "backpowered_mux": far_backpowered_mux},
    "hysteresis": {"rayleigh_nickel": hy_rayleigh_nickel, "nitinol_core": hy_nitinol_core},
    "time_delay": {"latency_overcorrection": td_latency_overcorrection, "triggered_laser": td_triggered_laser},
    "sensor_offset": {"button_nudge": so_button_nudge, "ptfe_hanger": so_ptfe_hanger},
    "clamp_relaxation": {"latex_pads": cr_latex_pads, "lamp_jaws": cr_lamp_jaws},
    "dehydration": {"schroeder_relaxation": dh_schroeder_relaxation, "humidity_ringing": dh_humidity_ringing},
    "strain_resistance": {"taped_collector": sr_taped_collector, "squeeze_film_cracks": sr_squeeze_film_cracks},
    "large_deflection": {"hanging_tip_bead": ld_hanging_tip_bead, "compass_torque": ld_compass_torque},
    "mains_pickup": {"slip_sidebands": mp_slip_sidebands, "stirrer_base": mp_stirrer_base},
    "unexplained": {"flowmeter_coils": out_flowmeter_coils, "boom_dither": out_boom_dither,
                    "gap_filled": out_gap_filled, "centrifuge_runup": out_centrifuge_runup},
}
inject.register_forms(FRESH23_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def v_loadcell_dropout(s: Session) -> None:
    """The load cell's indicator read by the logging script over a USB-serial adapter that drops out now and then (the
    adapter's port lost after a jolt or to the PC's USB power saving) and stays out until the operator, at the next
    re-clamping, notices and re-plugs it: the script writes a record's force_N only when the indicator answered, so from
    a record drawn at random in one or two pressure blocks (drawn) to the end of that block the time series have no
    force_N column (the session's first record always keeps it). The import contract lists force_N as optional, file by
    file; the other columns, the rows, the spectra and the manifest untouched."""
    blocks = [b for b in _by_block(s) if any("force_N" in r.cols for r in b)]
    if not blocks:
        return
    n = min(1 + int(s.rng.random() < 0.5), len(blocks))
    for b in sorted(s.rng.choice(len(blocks), size=n, replace=False).tolist()):
        recs = blocks[b]
        k = int(s.rng.integers(len(recs)))
        if b == 0:
            k = max(k, 1)
        for r in recs[k:]:
            r.cols.pop("force_N", None)


inject.VARIANTS.update({"loadcell_dropout": v_loadcell_dropout})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_139", "s001_140", "p43_141"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 6 / 7 effect cases on seeds 139-141
    "back_relaxation": [("case_two_front", 141, T, "log_steps"), ("mandel_cryer", 140, S, "stop_trigger")],
    "faradaic_current": [("bubble_detachment", 139, P, "short_pretrigger"),
                         ("backpowered_mux", 140, S, "coherent_sines")],
    "hysteresis": [("rayleigh_nickel", 141, T, "cycle_averaged"), ("nitinol_core", 139, P, "fixed_decimals")],
    "time_delay": [("latency_overcorrection", 139, P, "fir_decimated"),
                   ("triggered_laser", 141, T, "loadcell_dropout")],
    "sensor_offset": [("button_nudge", 140, S, "tared_records"), ("ptfe_hanger", 139, P, "rate07")],
    "clamp_relaxation": [("latex_pads", 141, T, "loadcell_dropout"), ("lamp_jaws", 139, P, "merged_loadcell")],
    "dehydration": [("schroeder_relaxation", 140, S, "eis_descending"),
                    ("humidity_ringing", 140, S, "loadcell_dropout")],
    "strain_resistance": [("taped_collector", 141, T, "resampled"), ("squeeze_film_cracks", 139, P, "swinging_door")],
    "large_deflection": [("hanging_tip_bead", 140, S, "scan_hold"), ("compass_torque", 141, T, "settled_sines")],
    "mains_pickup": [("slip_sidebands", 139, P, "own_clock"), ("stirrer_base", 141, T, "trigger_clock")],
    "unexplained": [("flowmeter_coils", 139, P, "loadcell_dropout"), ("flowmeter_coils", 141, T, "spectra_last"),
                    ("boom_dither", 139, P, "no_loadcell"), ("boom_dither", 140, S, "decimated3"),
                    ("gap_filled", 140, S, "float32_time"), ("gap_filled", 141, T, "shortened_shuffled"),
                    ("centrifuge_runup", 140, S, "host_timed"), ("centrifuge_runup", 141, T, "dropped_packets")],
}
CLEAN = [(139, P, "steps_sines"), (139, P, "loadcell_dropout"), (140, S, "no_spectra"), (140, S, "loadcell_dropout"),
         (141, T, "two_pressures"), (141, T, "asrun")]


def fresh23_cases(only: str | None = None) -> list[Case]:
    """The twenty-fourth held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds
    139-141)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh23_cases, "inject_fresh23", "fresh23")
