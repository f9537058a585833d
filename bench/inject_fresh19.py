"""A twentieth held-out set for the diagnosis (issue 12), fresh19, written without sight of the diagnosis (its code,
its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh18.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (palladium electrodes taking up hydrogen on
whichever face is the cathode and giving it back as the anode, the pads' asperity contacts at the jaws in Mindlin's
partial slip, an ultrasonic ranger timing the first echo from the strip's nearest point, a long-range fibre-optic probe
on its front slope, a motion-capture marker riding on the tip's normal), some on the history (membrane channels that age
at rest and are rejuvenated by the bending, hydrophobic electrode pores wetted for good by electrowetting at the largest
drives, a tip in a bed of glass beads that carves a cavity and lets it refill, electrolysis gas filling the opened
cracks), some on time or on the clamp pressure (a pneumatic isolation table's levelling valve after each re-clamping,
cardboard pads swelling with the room's humidity, a spring clamp whose jaw sticks in its guide, an enclosure warmed by
the instruments at a fixed dew point, a warm-filled bath cooling and the membrane deswelling with it, crack contacts
tarnishing in air, the building's power-factor capacitors switching the network's resonance), one linear but not a sum
of lags (a strip whose electrodes are cracked through, a double-porosity medium) and some from the lab's wiring or
settings (a lock-in amplifier's output filter, a logger's real-time Savitzky-Golay smoothing, the triplen harmonics of a
shared neutral). Four structures outside the catalogue (truth "unexplained": a gas bubble growing under the laser's spot
and letting go, a neighbouring laser head's light beating with this head's sampling, the current amplifier's range
changed at a re-clamping without the logger's scale, 16.7 Hz pickup from a railway's traction current as trains pass);
clean sessions. All on three bases of new seeds (127-129: the paper strip, the seed-001 strip on its own sweep, the
paper strip 27 mm free) and on the earlier sets' protocol / data-shape variants plus one new here: a logger that writes
every channel on a master scan clock of its own at 1 kHz, each row holding the latest sample it has of each channel
(``scan_hold``).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh18 are reused (importing inject_fresh18 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import, none replaced. Strengths
are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it made on its case,
measured in memory against the clean base (relative RMS change over all series, form only, no variant; "noise": the
column's sample-to-sample noise at rest, inject_fresh15.rest_noise; the values for the three bases are in
docs/effects.md).

Run: python bench/inject_fresh19.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np
from scipy import signal

import inject
import inject_fresh18  # noqa: F401  (registers every earlier set's forms, bases, presets and variants)
from inject import Case, Rec, Session, lu, map_disp, ref_disp
from inject_fresh2 import _chrono, _through
from inject_fresh3 import _resist, _sign
from inject_fresh4 import _clamp_law, _lag_state
from inject_fresh5 import _arc
from inject_fresh6 import _blocks
from inject_fresh7 import _superpose
from inject_fresh9 import _dry_by, _gaps, _session_grid
from inject_fresh10 import _lambda, _station
from inject_fresh11 import _walk
from inject_fresh12 import _line_f
from inject_fresh14 import _lagged, _largest
from inject_fresh18 import _bv, _stations

# the paper's strip 27 mm free (earlier sets used 20, 23, 25, 26, 28, 29, 31-40, 42 and 45 mm; its 1 V step peaks near
# 7.1 mm, 8.8 mm x (27/30)^2, inside the laser's +-20 mm): preset "paper_27", base "p27_129", registered in every
# process importing this module
inject.register_free_length("paper_27", 0.027)

inject.BASES.update({
    "paper_127": ("paper-sweep", "paper", 127),
    "s001_128": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 128),
    "p27_129": ("paper-sweep", "paper_27", 129),
})

R_GAS = 8.314  # J/(mol K)


# ------------------------------------------------------------------------------------------------ tools


def _runs(x: np.ndarray) -> list[tuple[int, int]]:
    """The monotone runs of x (flats joined to the run before them): [(first, last)] sample indices, inclusive."""
    if x.size < 2:
        return [(0, x.size - 1)]
    d = np.sign(np.diff(x))
    nz = np.flatnonzero(d)
    if nz.size == 0:
        return [(0, x.size - 1)]
    d = d[nz[np.maximum(np.searchsorted(nz, np.arange(d.size), side="right") - 1, 0)]]
    turns = np.flatnonzero(d[1:] != d[:-1]) + 1
    ends = np.r_[turns, x.size - 1]
    starts = np.r_[0, turns + 1]
    return list(zip(starts.tolist(), ends.tolist()))


def _plays(x: np.ndarray, radii: np.ndarray, state: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Play operators of the given radii on x from ``state`` (one value per radius): on each monotone run of x the
    recursion y_k = clip(y_(k-1), x_k - r, x_k + r) is a clip of the run's starting state. Returns (n, len(radii)) and
    the last state."""
    y = np.empty((x.size, radii.size))
    st = np.asarray(state, float).copy()
    for a, b in _runs(x):
        seg = x[a : b + 1, None]
        y[a : b + 1] = np.clip(st, seg - radii, seg + radii)
        st = y[b].copy()
    return y, st


def _block_index(s: Session) -> Callable[[float], int]:
    """Session time -> the index of the pressure block it falls in (0 for the first block)."""
    starts = np.sort([a for a, _ in _blocks(s).values()])
    return lambda t: int(np.clip(np.searchsorted(starts, t, side="right") - 1, 0, None))


def _angle(d: np.ndarray, L: float) -> np.ndarray:
    """The tip's angle on the uniform-curvature arc of tip deflection d (kL, k = 2 d/L^2)."""
    return 2 * np.asarray(d, float) / L


def _magnus(t_c: np.ndarray | float) -> np.ndarray:
    """Water's saturation vapour pressure (hPa) at t_c deg C (Magnus, Sonntag's constants)."""
    t_c = np.asarray(t_c, float)
    return 6.112 * np.exp(17.62 * t_c / (243.12 + t_c))


# ------------------------------------------------------------------------------------------------ back relaxation


def br_dual_porosity(s: Session) -> None:
    """A strip whose plated electrodes are mud-cracked through: the water the bend pushed to one side flows back through
    the cracks (a network of fast paths that hold little of it, a share omega 0.05-0.3 of the storage) fed by the
    membrane's slabs between them, which give up their water by diffusion: a double-porosity medium (Warren & Root; the
    slabs' transient flow after de Swaan). The back-flow's storage is omega + (1 - omega) tanh(sqrt(tau_m s))/
    sqrt(tau_m s) (tau_m 5-60 s, log, the slabs' diffusion time), its lag tau_f s times that storage (tau_f 3-12 s,
    log): 1 - K2/(1 + tau_f s f(s)) (K2 0.8-1.2): a fast lag omega tau_f at first and the slabs' slow diffusive tail
    after it, not any sum of a few exponentials. Through inject_fresh2._through with 60 s of the session's history;
    displacement only. Measured (s001_128): K2 0.81, tau_f 4.9 s, omega 0.15 (the cracks' lag 0.75 s), tau_m 40 s:
    displacement RMS -73 % (residual 76 %, 2350x its noise); the 1 V steps at 0.44, 0.72, 0.86, 0.99 and 1.23 mm 0.5, 2,
    5, 10 and 29 s after their rise (0.54, 1.25, 2.02, 2.83, 4.62 mm clean), -3.0 mm 2 s after their falls; the 1 V
    harmonics' gain 0.60 with 26 deg of lead, the 4.4 Hz sines' 0.995 with 1.9 deg."""
    k2, tau_f = s.rng.uniform(0.8, 1.2), lu(s.rng, 3.0, 12.0)
    omega, tau_m = s.rng.uniform(0.05, 0.3), lu(s.rng, 5.0, 60.0)

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        def h(z: np.ndarray) -> np.ndarray:
            q = np.sqrt(tau_m * np.asarray(z) + 0j)
            small = np.abs(q) < 1e-6
            slab = np.where(small, 1.0 + 0j, np.tanh(q) / np.where(small, 1.0, q))
            return 1 - k2 / (1 + tau_f * np.asarray(z) * (omega + (1 - omega) * slab))

        return h

    new = _through(s, H, 60.0)
    map_disp(s, lambda r, d: new[id(r)])


def br_aged_channels(s: Session) -> None:
    """Physical ageing of the hydrated membrane at rest (Struik): left still, its polymer densifies about the water
    channels and the back-flow through them slows; bending rejuvenates it (mechanical rejuvenation erases physical
    ageing). The aged share a of the channels grows at rest towards 1 over T_a (100-600 s, log) and is worked off by the
    bend's path, da/dt = (1 - a)/T_a - a abs(dd/dt)/(c ref) (c 0.3-1.5 displacement scales of path by e); the
    back-flow's lag is tau_0 (1 + beta a) (tau_0 1.5-5 s, log, beta 1.5-4). The strip aged when the session starts (a =
    1). Sample by sample through the session in time order (the displacement linear across the rests, where the strip
    ages), read d - K2 x (K2 0.8-1.2); displacement only. Measured (p27_129): K2 1.00, tau_0 1.95 s, beta 2.9 (the aged
    lag 7.6 s), T_a 340 s, c 1.13 scales: displacement RMS -83 % (residual 97 %, 5180x its noise); the 1 V steps peak at
    1.54 mm in the first block, 1.42-1.43 mm in the later ones (7.19-7.20 mm clean), at 0.89, 1.51, 1.29, 0.68 and 0.25
    mm 0.5, 2, 5, 10 and 29 s after the first one's rise, -6.26 mm 2 s after their falls; the 1 V harmonics' gain 0.74
    with 41 deg of lead, the 4.4 Hz sines' 0.998 with 1.1 deg."""
    k2, tau0, beta = s.rng.uniform(0.8, 1.2), lu(s.rng, 1.5, 5.0), s.rng.uniform(1.5, 4.0)
    t_a, c = lu(s.rng, 100.0, 600.0), s.rng.uniform(0.3, 1.5) * ref_disp(s)
    a, x, d_end = 1.0, 0.0, 0.0
    for r, gap in _gaps(s, 1.0):
        d = r.cols["disp_m"]
        for dt, u in gap:
            a = 1 - (1 - a) * math.exp(-dt / t_a)
            x += -math.expm1(-dt / (tau0 * (1 + beta * a))) * (d_end + u * (float(d[0]) - d_end) - x)
        dt = 1.0 / r.fs
        out, prev = np.empty(d.size), float(d[0])
        for k, dk in enumerate(d.tolist()):
            rate = abs(dk - prev) / c  # the path this sample, in units of c
            a += (1 - a) * dt / t_a - a * (1 - math.exp(-rate))
            a = min(max(a, 0.0), 1.0)
            x += (dk - x) * -math.expm1(-dt / (tau0 * (1 + beta * a)))
            out[k], prev = x, dk
        d_end = float(d[-1])
        r.cols["disp_m"] = d - k2 * out


# ------------------------------------------------------------------------------------------------ faradaic current


def far_palladium_hydride(s: Session) -> None:
    """A strip plated with palladium instead of platinum (a cheaper IPMC electrode): palladium takes the hydrogen its
    cathodic face makes into its lattice (the alpha/beta hydride) before it evolves any: beyond the absorption's onset
    v_a (0.25-0.45 V of drive) the cathodic face absorbs at g_a (abs(v) - v_a) (1 - x_c) (0.2-0.8 mA at 1 V into an
    empty lattice, log), x_c its filling of a capacity Q (20-80 mC a face, log); once that face is the anode, its stored
    hydrogen is oxidised at i_r x_a (0.2-0.6 mA when full, log) above v_o (0.05-0.15 V); at rest the lattice loses its
    hydrogen over tau_l (300-1500 s, log). Each face its own store (face A the cathode for v < 0). A current that falls
    as the lattice fills through a hold, and a release burst after each reversal, larger the more the face took up.
    Sample by sample through the session in time order (inject_fresh9._gaps for the rests); the analyser's 10 mV sees
    nothing (below both onsets): the current only. Measured (paper_127): v_a 0.39 V, 0.31 mA at 1 V into an empty
    lattice, Q 29 mC, the release 0.29 mA when full (above 0.10 V), tau_l 530 s: current residual 3.9 % of its RMS (3.0x
    its noise); on each 1 V step +305 uA just after the rise, +275 uA at 10 s, +228 uA by the plateau's end (the
    plateaus' current +37 %); the 1 V harmonics' current gain 1.044 with 2.2 deg of lag, the 0.5 V sines' 1.023 at 0.1
    Hz, 1.004 at 20 Hz."""
    v_a, i_a1, q = s.rng.uniform(0.25, 0.45), lu(s.rng, 2e-4, 8e-4), lu(s.rng, 0.02, 0.08)
    i_r1, v_o, tau_l = lu(s.rng, 2e-4, 6e-4), s.rng.uniform(0.05, 0.15), lu(s.rng, 300.0, 1500.0)
    g_a = i_a1 / (1 - v_a)
    xa = xb = 0.0
    for r, gap in _gaps(s, 5.0):
        for dt, _ in gap:
            xa, xb = xa * math.exp(-dt / tau_l), xb * math.exp(-dt / tau_l)
        dt, v = 1.0 / r.fs, r.cols["v_V"]
        out = np.empty(v.size)
        for k, vk in enumerate(v.tolist()):
            m = abs(vk)
            cath, an = (xb, xa) if vk > 0 else (xa, xb)  # v > 0: face B the cathode
            ia = g_a * max(m - v_a, 0.0) * (1 - cath)
            ir = i_r1 * an if m > v_o else 0.0
            cath, an = min(cath + ia * dt / q, 1.0), max(an - ir * dt / q, 0.0)
            if vk > 0:
                xb, xa = cath, an
            else:
                xa, xb = cath, an
            xa, xb = xa * math.exp(-dt / tau_l), xb * math.exp(-dt / tau_l)
            out[k] = math.copysign(ia + ir, vk) if vk != 0 else 0.0
        r.cols["i_A"] = r.cols["i_A"] + out


def far_electrowetting_pores(s: Session) -> None:
    """Platinum electrodes whose pores hold air (the strip dried, or handled with greasy gloves, before it was mounted:
    the rough plating's pores in the Cassie state), so that the water is electrolysed only on the outer share a_0
    (0.2-0.5) of the electrode's area: the electrolysis a symmetric Butler-Volmer branch (0.1-0.4 mA at 1 V on the whole
    wetted area, log, v_t 0.1-0.2 V). Electrowetting (Young-Lippmann: cos theta grows as the interface's voltage
    squared) drives the water into the pores once abs(v) passes v_ew (0.4-0.75 V), the wetted share of the pores growing
    towards ((v/v_ew)^2 - 1)/((1/v_ew)^2 - 1) of them over tau_in (1-5 s, log); wetted pores stay wetted (the Wenzel
    state is stable): the largest drive so far sets the leak for the rest of the session. Through the session in time
    order (the target the running maximum of abs(v), the share its lag); the analyser's 10 mV sees the branch's slope at
    0 V (under 0.1 mS): the current only. Measured (p27_129): a_0 0.46, 0.38 mA at 1 V on the whole wetted area, v_t
    0.18 V, v_ew 0.72 V, tau_in 1.9 s: current residual 5.6 % of its RMS (4.2x its noise); the session's first 1 V step
    +181 uA at its rise, +310 uA at 2 s, +383 uA from 10 s on, every later record with the pores wetted (+383 uA on
    every later plateau, +68 to +73 %); the 1 V harmonics' current 1.051 with 2.7 deg of lag, the 0.5 V sines' 1.031 at
    0.1 Hz, 1.007 at 20 Hz."""
    a0, i1, vt = s.rng.uniform(0.2, 0.5), lu(s.rng, 1e-4, 4e-4), s.rng.uniform(0.1, 0.2)
    v_ew, tau_in = s.rng.uniform(0.4, 0.75), lu(s.rng, 1.0, 5.0)
    top, w, t_end = 0.0, 0.0, None
    for r in _chrono(s):
        t, v = r.cols["t_s"], r.cols["v_V"]
        target = np.maximum.accumulate(np.maximum(np.abs(v), top))
        top = float(target[-1])
        goal = np.clip(((target / v_ew) ** 2 - 1) / ((1 / v_ew) ** 2 - 1), 0.0, 1.0)
        if t_end is not None:  # over the rest the share goes on towards the largest drive's
            w = float(goal[0]) + (w - float(goal[0])) * math.exp(-max(float(t[0]) - t_end, 0.0) / tau_in)
        share = _lag_state(goal, r.fs, tau_in, w)
        w, t_end = float(share[-1]), float(t[-1])
        r.cols["i_A"] = r.cols["i_A"] + (a0 + (1 - a0) * share) * _bv(v, i1, vt)


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_pad_microslip(s: Session) -> None:
    """The clamped part of the strip is driven too (the drive enters through the jaws' contacts), and its actuation
    moment presses on the pads, whose rough contact with the strip yields by partial slip at its asperities
    (Mindlin-Deresiewicz): under a moment T the root turns by delta* (1 - (1 - T/T_s)^(2/3)), T_s = mu N the contact's
    full-slip limit, and back by Masing's rule (twice the curve from each reversal), which an Iwan bank of plays with
    the curve's own density reproduces. The limit goes as the clamp's force (T_s ~ p) and delta* as p^(2/3) (Hertzian
    contacts), so the loops (growing as the cube of the moment while T << T_s) are wide at the light settings and vanish
    at the tight ones: the session's largest drive reaches q_0 (0.6-0.9) of T_s at the lightest setting, where the
    root's turn at 1 V adds k_s (0.04-0.12) of the strip's own bend; the pads reseated at each re-clamping (the plays
    from rest at each block's first record). The moment taken as the drive (the clamped part's charge follows it
    closely); the root's turn, in volts of drive, reaches the displacement through the strip's measured step response
    (inject_fresh7._superpose, current untouched). Measured (p27_129): q_0 0.75, k_s 0.095: displacement RMS +5.3 %
    (residual 5.9 %, 311x its noise); the 1 V steps' peaks +9.5, +5.7, +4.7, +4.2 % block by block (612 to 4287 kPa);
    the 1 V harmonics' gain 1.095 with 0.5 deg of lag at 612 kPa (residual 9.9 %), 1.057, 1.047, 1.042 in the tighter
    blocks (residuals 5.8 to 4.2 %)."""
    q0, ks = s.rng.uniform(0.6, 0.9), s.rng.uniform(0.04, 0.12)
    p_min = min(s.pressures())
    big = _largest(s, "v_V") or 1.0
    u = (np.arange(32) + 0.5) / 32 * 0.97  # the plays' radii over T_s

    def bank(p: float) -> tuple[float, float, np.ndarray, np.ndarray]:
        ts = big / q0 * p / p_min
        ds = ks * big / (1 - (1 - q0) ** (2 / 3)) * (p / p_min) ** (2 / 3)  # delta*: k_s at 1 V at the lightest
        dprime = lambda x: (2 / 3) * ds / ts * (1 - x) ** (-1 / 3)  # noqa: E731  the curve's slope at T = x T_s
        edges = np.r_[0.0, (u[1:] + u[:-1]) / 2, 0.985]
        w = np.diff(dprime(edges))
        return ts, dprime(0.0), u * ts, w

    block, e, state, at = _block_index(s), {}, None, None
    for r in _chrono(s):
        b = block(float(r.cols["t_s"][0]))
        ts, c0, radii, w = bank(float(r.entry["pressure_kPa"]))
        if b != at:
            state, at = np.zeros(radii.size), b
        v = r.cols["v_V"]
        y, state = _plays(v, radii, state)
        e[id(r)] = c0 * v + y @ w
    _superpose(s, e, {"i_A": 0.0})


def hy_granular_bed(s: Session) -> None:
    """A strip tested in a bed of glass beads under water (a soil phantom for burrowing robots): its tip, a few
    millimetres into the bed, pushes the beads aside only when the strip's pull exceeds the bed's yield, r in the tip's
    units (0.03-0.08 of the displacement scale), and leaves a cavity behind: inside the cavity it moves freely, at its
    walls it must push beads again. The beads avalanche back into the empty cavity at rest and in motion, its walls
    closing on the tip over tau_f (5-60 s, log). So the tip follows the strip freely within the ground it has carved,
    lags by r when it carves further, and the small motions after a long still spell are held by the refilled bed.
    Rate-independent but for the refill. Sample by sample through the session in time order (the rests in steps of 0.5
    s, the free bend linear across them); displacement only. Measured (paper_127): the yield 74 um (0.035 of the 2.09 mm
    scale), tau_f 16 s: displacement RMS -0.4 % (residual 1.6 %, 93x its noise); the 1 V steps 74 um short while they
    rise (the tip carving), their peaks -0.8 %; the 1 V harmonics' gain 0.977 with 0.7 deg of lag, the 0.5 V sines'
    0.948 at 0.1 Hz and 0.920 at 4.4 Hz; the 20 Hz sines' few um held by the refilled bed (gain 0.006)."""
    ref = ref_disp(s)
    ry, tau_f = s.rng.uniform(0.03, 0.08) * ref, lu(s.rng, 5.0, 60.0)
    y, hi, lo, d_end = None, 0.0, 0.0, 0.0

    def step(x: float, dt: float) -> None:
        nonlocal y, hi, lo
        f = math.exp(-dt / tau_f)
        hi, lo = y + (hi - y) * f, y - (y - lo) * f  # the walls close on the tip
        if x > hi:
            y = max(hi, x - ry)
            hi = y
        elif x < lo:
            y = min(lo, x + ry)
            lo = y
        else:
            y = x

    for r, gap in _gaps(s, 0.5):
        d = r.cols["disp_m"]
        if y is None:
            y = hi = lo = float(d[0])
        for dt, u in gap:
            step(d_end + u * (float(d[0]) - d_end), dt)
        dt, out = 1.0 / r.fs, np.empty(d.size)
        for k, dk in enumerate(d.tolist()):
            step(dk, dt)
            out[k] = y
        d_end = float(d[-1])
        r.cols["disp_m"] = out


# ------------------------------------------------------------------------------------------------ time delay


def td_lockin_demodulator(s: Session) -> None:
    """No laser: a capacitive probe facing the strip's face near its tip (a guarded electrode read as an impedance,
    linear in the gap), excited at 20-50 kHz and demodulated by a lock-in amplifier: the lock-in's output filter is a
    cascade of n identical RC stages, 1/(1 + s tau)^n, at the slope and time constant the lab left it on (12, 18 or 24
    dB/oct: n 2-4; tau 1 or 3 ms from its 1-3-10 sequence). Far below 1/tau it is a delay of n tau with a gain that
    falls only slowly: a lag more gradual in its phase than a Butterworth's or a Bessel's of the same order, the 20 Hz
    records late and a little low. Through inject_fresh2._through (0.5 s of the session's history); displacement only.
    Measured (s001_128): two stages of 3 ms (12 dB/oct, 6 ms of delay): displacement residual 0.22 % of its RMS (6.7x
    its noise); the 1 V harmonics 0.21 deg late at 0.1 Hz, the 4.4 Hz sines' gain 0.993 at -9.4 deg, the 20 Hz ones'
    0.875 at -41 deg; the steps within 2 um."""
    n, tau = int(s.rng.choice([2, 3, 4])), float(s.rng.choice([1e-3, 3e-3]))
    new = _through(s, lambda r: (lambda z: 1.0 / (1.0 + tau * np.asarray(z)) ** n), 0.5)
    map_disp(s, lambda r, d: new[id(r)])


def td_savgol_logger(s: Session) -> None:
    """The lab's logging script smooths the laser's channel in real time with a Savitzky-Golay filter (a quadratic
    fitted over the last 2m + 1 samples, the window T_w 8-25 ms, log, in whole samples at each record's rate) and writes
    the fit's value at the window's centre with the newest sample's time stamp: a linear-phase FIR, a delay of m samples
    (half the window: 4-12 ms) with the filter's flat gain, dropping only near its corner. Through
    inject_fresh2._through (0.5 s of the session's history); displacement only. Measured (paper_127): a window of 18.7
    ms (19 samples at 1 kHz, 5 at 200 Hz: delays of 9 and 10 ms): displacement residual 0.23 % of its RMS (13x its
    noise); the 1 V harmonics 0.35 deg late at 0.1 Hz, the 4.4 Hz sines -14.4 deg (9.1 ms) with a gain of 1.001, the 20
    Hz ones -65 deg (9.0 ms) with 0.993; the steps within 2 um."""
    t_w = lu(s.rng, 8e-3, 25e-3)

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        m = max(int(round(t_w * r.fs / 2)), 1)
        c = signal.savgol_coeffs(2 * m + 1, 2)  # symmetric: the centre's weights
        lags = np.arange(2 * m + 1) / r.fs
        return lambda z: np.exp(-np.asarray(z)[:, None] * lags[None, :]) @ c

    new = _through(s, H, 0.5)
    map_disp(s, lambda r, d: new[id(r)])


# ------------------------------------------------------------------------------------------------ sensor offset


def so_first_echo_sonar(s: Session) -> None:
    """No laser: an ultrasonic ranger (an immersion transducer and pulser-receiver in the bath, or an air-coupled one
    for a strip in air) facing one face of the strip near its tip, its beam covering the strip from x_a (0.75-0.92 L) to
    the tip: the receiver times the first echo over its threshold, the strip's point nearest the transducer. When the
    strip bends towards it that is the tip; when it bends away it is the footprint's inboard edge x_a, which moves less.
    The lab reads the range as the tip's displacement (calibrated by its slope at rest). The side the transducer faces
    drawn; x_a read through the beam's transfer functions with the session's history (inject_fresh18._stations); the
    reading the nearer of the two; displacement only. Measured (paper_127): the transducer on the side the negative
    drive bends towards, x_a 0.90 L: displacement RMS -18 % (residual 18 %, 1070x its noise); the 1 V steps (bending
    away) -18.2 %, the 1 V harmonics' gain 0.82 (their crests short, their troughs as they were), the 0.5 V sines' 0.90
    at 0.1 Hz, 0.94 at 4.4 Hz, 0.74 at 20 Hz (the footprint's edge in the sines' dynamic shape)."""
    side, xa = _sign(s), s.rng.uniform(0.75, 0.92)
    at = _stations(s, np.array([xa]))
    map_disp(s, lambda r, d: side * np.maximum(side * d, side * at[id(r)][0]))


def so_levelling_table(s: Session) -> None:
    """The clamp on a pneumatic isolation table, the laser's stand on the floor beside it, the strip hanging tip down
    and the beam level, aimed a margin m (0.35-0.6 mm) above the tip's end: the table's levelling valves hold its height
    only within their dead band (+-0.05-0.3 mm, each settling its own height within it), and at each re-clamping (10-40
    s before the block's first record) the operator's hand sinks the table by s (0.3-1.2 mm), which the valve makes up
    over tau_v (3-20 s, log). A table low by h moves the spot up the strip, inboard, by h: the station 1 - (m - h)/L,
    inboard at each block's start, settling to a level of its own in each block. The strip read at the moving station
    (inject_fresh10._station); displacement only. Measured (p27_129): m 0.56 mm, the dead band +-0.28 mm, the hand's
    sink 0.81 mm made up over 4.8 s from 18 s before each block: the blocks settled at stations 0.979, 0.989, 0.975 and
    0.979 L (the table -0.02, +0.26, -0.12, -0.01 mm); displacement RMS -3.8 % (residual 4.0 %, 210x its noise); the 1 V
    steps' peaks -4.1, -2.2, -4.9, -4.1 % block by block, the 1 V harmonics' gain 0.959, the 20 Hz sines' 0.89."""
    L = float(s.specimen["length_m"])
    m, band = s.rng.uniform(3.5e-4, 6e-4), s.rng.uniform(5e-5, 3e-4)
    sink, tau_v, lead = s.rng.uniform(3e-4, 1.2e-3), lu(s.rng, 3.0, 20.0), s.rng.uniform(10.0, 40.0)
    blocks = sorted(_blocks(s).items(), key=lambda kv: kv[1][0])
    level = {p: s.rng.uniform(-band, band) for p, _ in blocks}
    touch = {p: a - lead for p, (a, _) in blocks}

    def frac(r: Rec) -> np.ndarray:
        p = float(r.entry["pressure_kPa"])
        h = level[p] - sink * np.exp(-np.clip(r.cols["t_s"] - touch[p], 0, None) / tau_v)
        return np.minimum(1 - (m - h) / L, 1.0)

    _station(s, frac, 1 - (m + band + sink) / L)


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_hygroscopic_pads(s: Session) -> None:
    """A strip in air clamped between cardboard (or blotting-paper) pads laid under the jaws to spread the force, the
    force set at each re-clamping by the screw and then held by the screw's fixed travel. Paper takes up water from the
    air within minutes (a lag of 60-300 s, log) and swells in its thickness with it; the room's humidity cycles with the
    air conditioning by +-3-8 % RH (a period of 900-2400 s) about a drift of -6 to +6 % over the session. The swelling
    pad pushes against the fixed travel: the force changes by c (0.2-0.5 % per % RH at the top setting) times
    sqrt(p_top/p) (the same swelling costs less force on the softer, lightly pressed pad, but a larger share of it),
    relative to the humidity at the setting (10-40 s before the block). The force relative to its setting through the
    preset's clamp law (inject_fresh4._clamp_law), the load cell showing it. Measured (s001_128): +-4.6 % RH over 1960 s
    about a drift of -3.6 %, the pads' lag 112 s, c 0.41 % per % RH (0.75 % at 500 kPa): the load cell at 1.004-1.047 of
    its setting through the 500 kPa block, 0.96-0.998 at 900 kPa, 1.002-1.026 at 1300, 0.972-0.999 at 1700; displacement
    residual 0.006 % of its RMS (0.20x its noise), current 0.12 % (0.33x); the 20 Hz sines' gain within 1.1 %."""
    amp, per, ph = s.rng.uniform(3.0, 8.0), s.rng.uniform(900.0, 2400.0), s.rng.uniform(0.0, 2 * np.pi)
    drift, tau_j, c_top = s.rng.uniform(-6.0, 6.0), lu(s.rng, 60.0, 300.0), s.rng.uniform(2e-3, 5e-3)
    lead = s.rng.uniform(10.0, 40.0)
    tg = _session_grid(s, 1.0, 1500.0)
    rh = amp * np.sin(2 * np.pi * tg / per + ph) + drift * np.clip((tg - s.t0) / (s.t1 - s.t0), 0, None)
    pad = _lagged(tg, rh, tau_j)
    p_top = max(s.pressures())

    def rel(t: np.ndarray, p: float, t_set: float) -> np.ndarray:
        j0 = float(np.interp(t_set - lead, tg, pad))
        return 1 + c_top * math.sqrt(p_top / p) * (np.interp(t, tg, pad) - j0)

    _clamp_law(s, rel)


def cr_sticking_guide(s: Session) -> None:
    """A spring clamp: the moving jaw pushed by a compression spring that the screw sets, the jaw sliding in a dovetail
    guide with friction. The pads creep under the jaw (their force falling as r F log(1 + u/tau) with the jaw held, r
    1-3 %, tau 5-30 s, log, from each setting 5-30 s before the block), and the jaw stays stuck in its guide until the
    spring beats the pads by the guide's static friction f_s (0.5-1.5 % of the top setting's force: a fixed force, a
    larger share of the light settings), then slips forward until only the kinetic friction f_k (0.5-0.8 f_s) is left:
    the force falls, jumps back by f_s - f_k, falls again, the slips ever rarer as the creep slows (a saw between F -
    f_k and F - f_s). Through the preset's clamp law (inject_fresh4._clamp_law), the load cell showing the saw. Measured
    (p27_129): r 2.3 %, tau 7.0 s, set 11 s before each block, f_s 1.38 % of the top setting's force (9.7 % of the 612
    kPa setting's), f_k 0.63 f_s: the load cell down to 0.90 of its setting and sawing up to 0.94 through the 612 kPa
    block (2 slips), between 0.98 and 0.97 at 1837 kPa (8 slips), 0.99-0.98 at 3062 and 4287 kPa (13 and 19);
    displacement residual 0.023 % of its RMS (1.2x its noise), current 0.20 % (0.15x); the 4287 kPa block's 20 Hz sines
    -3.5 %."""
    r_c, tau, lead = s.rng.uniform(0.01, 0.03), lu(s.rng, 5.0, 30.0), s.rng.uniform(5.0, 30.0)
    fs_top, kin = s.rng.uniform(0.005, 0.015), s.rng.uniform(0.5, 0.8)
    p_top = max(s.pressures())

    def rel(t: np.ndarray, p: float, t_set: float) -> np.ndarray:
        f_s = fs_top * p_top / p  # relative to this setting's force
        f_k = kin * f_s
        creep = r_c * np.log1p(np.clip(t - (t_set - lead), 0, None) / tau)
        slipped = creep >= f_s
        since = np.where(slipped, np.mod(creep - f_s, f_s - f_k), 0.0)
        return np.where(slipped, 1 - f_k - since, 1 - creep)

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_heated_enclosure(s: Session) -> None:
    """A strip in air in a closed enclosure (a clear box against draughts) that also holds the laser's controller and
    the drive amplifier: closed 0-600 s before the first record, its air warms by dT 2-6 K over tau_e (600-2000 s, log)
    while its water stays (the box tight: a fixed dew point), so its relative humidity falls from the room's RH_0 (35-55
    %) as p_sat(T_0)/p_sat(T_0 + dT) (Magnus). The strip's water follows Nafion's isotherm (inject_fresh10._lambda)
    through its sorption lag (100-400 s, log; inject_fresh14._lagged): a loss growing through the session. The gain as
    the water, the conductance as its 1.5-2.5th power, the spectra at the next series' start (inject_fresh9._dry_by).
    Measured (s001_128): RH_0 37.5 % at 21.4 C, dT 5.9 K over 1900 s, the box closed 500 s before the first record, the
    sorption lag 395 s, the conductance's power 2.32: the box at 22.8 C and 34.5 % RH at the first record, 26.6 C and
    27.4 % by the last; displacement RMS -6.5 % (residual 7.4 %, 229x its noise), current -16 % (47x); the 1 V steps'
    peaks -1.5, -5.8, -8.6, -10.3 % block by block, their plateaus' current -3.5, -13, -19, -22 %; the spectra's |Z|
    +3.3, +14, +23, +29 %."""
    rh0, t0c, dT = s.rng.uniform(0.35, 0.55), s.rng.uniform(20.0, 25.0), s.rng.uniform(2.0, 6.0)
    tau_e, lead = lu(s.rng, 600.0, 2000.0), s.rng.uniform(0.0, 600.0)
    tau_s, gc = lu(s.rng, 100.0, 400.0), s.rng.uniform(1.5, 2.5)
    tg = _session_grid(s, 1.0, lead)
    temp = t0c + dT * -np.expm1(-(tg - tg[0]) / tau_e)
    rh = rh0 * _magnus(t0c) / _magnus(temp)
    water = _lagged(tg, _lambda(rh), tau_s) / float(_lambda(np.array([rh0]))[0])
    _dry_by(s, lambda t: 1 - np.interp(t, tg, water), lambda t: 1 - np.interp(t, tg, water) ** gc)


def dh_cooling_bath(s: Session) -> None:
    """A bath filled from a warm source (a heated reservoir, a warm tap: 32-42 C) 0-300 s before the first record, the
    strip soaked in the same water beforehand, the bath cooling towards the room (21-24 C) over tau_c (900-2500 s, log).
    Nafion's uptake in liquid water rises with the temperature (by a_T 0.3-0.8 % per K), so as the bath cools the
    membrane gives water up, through its sorption lag (60-300 s, log): a loss of water that grows through the session
    and levels off; the conductance falls with the water (its 1.5-2.5th power) and with the temperature too (the
    protons' activation energy, 8-14 kJ/mol). Both relative to the session's first record. The gain as the water, the
    conductance as above, the spectra at the next series' start (inject_fresh9._dry_by). Measured (p27_129): filled at
    36.5 C 77 s before the first record, the room at 23.7 C, tau_c 1170 s, a_T 0.69 % per K, the sorption lag 81 s, the
    conductance's power 1.67, E_a 12.1 kJ/mol: the bath at 35.7 C at the first record, 24.2 C by the last; displacement
    RMS -4.6 % (residual 5.4 %, 286x its noise), current -20 % (16x); the 1 V steps' peaks -0.1, -4.5, -6.5, -7.3 %
    block by block, their plateaus' current -0.7, -17, -23, -26 %; the spectra's |Z| as they were, +20, +30, +35 %."""
    t_f, t_r, tau_c = s.rng.uniform(32.0, 42.0), s.rng.uniform(21.0, 24.0), lu(s.rng, 900.0, 2500.0)
    lead, a_t, tau_s = s.rng.uniform(0.0, 300.0), s.rng.uniform(0.003, 0.008), lu(s.rng, 60.0, 300.0)
    gc, ea = s.rng.uniform(1.5, 2.5), s.rng.uniform(8e3, 14e3)
    tg = _session_grid(s, 1.0, lead)
    temp = t_r + (t_f - t_r) * np.exp(-(tg - tg[0]) / tau_c)
    water = _lagged(tg, 1 + a_t * (temp - t_r), tau_s)
    arr = np.exp(-ea / R_GAS * (1 / (temp + 273.15) - 1 / (t_r + 273.15)))
    w0 = float(np.interp(s.t0, tg, water))
    c0 = w0**gc * float(np.interp(s.t0, tg, arr))
    _dry_by(s, lambda t: 1 - np.interp(t, tg, water) / w0,
            lambda t: 1 - np.interp(t, tg, water) ** gc * np.interp(t, tg, arr) / c0)


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_gassed_cracks(s: Session) -> None:
    """Cracked electrodes in water, the cracks bridged by the water that fills them (ionically, through the membrane at
    their floor): a face's cracks add resistance as its tension e^1.5 (e the bend over the session's largest, so 1 at
    the largest bend), one face (drawn) more cracked than the other (the other at 0.2-0.5 of its gauge). The crack walls
    are bare platinum, and above the electrolysis' onset v_g (0.55-0.8 V: the 1 V steps' plateaus, the 1 V harmonics'
    crests) they make gas, which fills the opened cracks (over 0.5-3 s at 1 V, log) and cuts the water's path: the
    cracks' resistance then b (2-5) times higher, until the gas dissolves (10-60 s, log). So the same bend costs more
    during and just after the large drives. The gas fill sample by sample through the session (inject_fresh11._walk);
    gains fall by 0.02-0.06 (displacement) and 0.05-0.15 (current) per unit of dR/R (inject_fresh3._resist). Measured
    (paper_127): the more cracked face the one the negative drive stretches, the other at 0.46, v_g 0.73 V, the cracks
    gassed in 2.0 s at 1 V and cleared over 21 s, b 3.7, 0.056 and 0.106 per unit: displacement RMS -6.5 % (residual 7.4
    %, 436x its noise), current residual 3.3 % (2.5x); the 1 V steps' peaks -11.2 %, their plateaus' current -20 %,
    -0.45 mm left 2 s after their falls; the 1 V harmonics' gain 0.973 (current 0.980); the 0.5 V sines within
    0.12 %."""
    side, o, v_g, t_fill = _sign(s), s.rng.uniform(0.2, 0.5), s.rng.uniform(0.55, 0.8), lu(s.rng, 0.5, 3.0)
    tau_d, b = lu(s.rng, 10.0, 60.0), s.rng.uniform(2.0, 5.0)

    def step(g: float, v: float, dt: float) -> float:
        rate = max(abs(v) - v_g, 0.0) / (1 - v_g) / t_fill
        k = rate + 1 / tau_d
        g_inf = rate / k
        return g_inf + (g - g_inf) * math.exp(-k * dt)

    gas = _walk(s, step, "v_V", 0.0, lambda g, sec: g * math.exp(-sec / tau_d))
    k = ref_disp(s) / (_largest(s) or ref_disp(s))  # e over the displacement scale -> over the largest bend

    def shape(r: Rec, e: np.ndarray) -> np.ndarray:
        x = k * e
        return (np.clip(side * x, 0, None) ** 1.5 + o * np.clip(-side * x, 0, None) ** 1.5) * (1 + b * gas[id(r)])

    _resist(s, shape, (0.02, 0.06), (0.05, 0.15))


def sr_tarnishing_bridges(s: Session) -> None:
    """A strip in air whose electrodes are cracked through (one face, drawn, more than the other: 0.2-0.5 of its gauge),
    the cracks' edges touching at their asperities under the film's residual compression: each touch is a contact whose
    constriction resistance goes as its force to the -1/2 (Holm, plastic asperities), and the face's tension lifts them
    apart, the force falling as 1 - e/e_0 (e_0 1.3-2 times the session's largest tension): the cracks' share of the
    resistance (1 - e/e_0)^(-1/2) - 1, steepening towards e_0. In air the clean platinum contacts tarnish (adsorbed
    water and hydrocarbons, the relay-contact film): their resistance grows by a (0.5-2) of itself as 1 - exp(-u/tau)
    (tau 0.3-1 session) from the mounting 0-600 s before the first record. Normalised to unit slope at rest; gains fall
    by 0.01-0.03 (displacement) and 0.03-0.08 (current) per unit of dR/R (inject_fresh3._resist). Measured (s001_128):
    the more cracked face the one the negative drive stretches, the other at 0.44, e_0 2.0 times the largest tension, a
    1.12 over 0.98 session from 200 s before the first record, 0.021 and 0.038 per unit: displacement RMS -5.7 %
    (residual 6.3 %, 195x its noise), current residual 3.1 % (8.3x); the 1 V steps' peaks -7.2, -8.9, -10.3, -11.3 %
    block by block, their plateaus' current -12, -15, -18, -19 %; the 1 V harmonics' gain 0.977 to 0.965."""
    side, o, k0 = _sign(s), s.rng.uniform(0.2, 0.5), s.rng.uniform(1.3, 2.0)
    a, tau, lead = s.rng.uniform(0.5, 2.0), s.rng.uniform(0.3, 1.0) * (s.t1 - s.t0), s.rng.uniform(0.0, 600.0)
    e0 = k0 * max(_largest(s) / ref_disp(s), 1e-6)

    def shape(r: Rec, e: np.ndarray) -> np.ndarray:
        g = 1 + a * -np.expm1(-(r.cols["t_s"] - s.t0 + lead) / tau)
        a_, b_ = np.clip(side * e / e0, 0.0, 0.97), np.clip(-side * e / e0, 0.0, 0.97)
        return 2 * e0 * g * ((1 - a_) ** -0.5 - 1 + o * ((1 - b_) ** -0.5 - 1))

    _resist(s, shape, (0.01, 0.03), (0.03, 0.08))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_fibre_bundle(s: Session) -> None:
    """No laser: a long-range reflectance fibre-optic probe (a bifurcated bundle of emitting and receiving fibres behind
    a collimating lens, its response stretched over tens of millimetres) facing one face of the strip at its tip (the
    side drawn), at a gap g_0 (2-4 times the session's largest bend, log) on the front slope of its response: the light
    the receiving fibres catch goes as x^2 exp(1 - x^2) in the gap over the peak's gap (g_0 at 0.4-0.7 of the peak),
    rising steeply near contact and rolling over towards the peak, and the tip's tilt steers the reflected cone off the
    receiving fibres, exp(-(theta/theta_a)^2) (theta_a 4-8 times the tip's largest angle). The tip's height on the exact
    arc (inject_fresh5._arc) and its angle kL = 2 d/L, read through the lab's calibration by the slope at rest:
    compressed one way, stretched the other, and pulled down by the tilt at the large bends both ways. Displacement
    only. Measured (paper_127): the probe on the side the positive drive bends towards, g_0 3.2 times the largest bend
    (28 mm) at 0.63 of the peak's gap, theta_a 5.8 times the tip's largest angle: displacement RMS +10.5 % (residual
    10.6 %, 629x its noise); the 1 V steps' peaks +11.7 %, +0.75 mm 2 s after their falls; the 1 V harmonics' gain
    1.083; the 0.5 V sines within 0.25 %."""
    L, big = float(s.specimen["length_m"]), _largest(s)
    side, g0 = _sign(s), lu(s.rng, 2.0, 4.0) * big
    gp = g0 / s.rng.uniform(0.4, 0.7)
    th_big = abs(_angle(np.array([big]), L)[0]) or 1e-6
    th_a = s.rng.uniform(4.0, 8.0) * th_big

    def power(y: np.ndarray, th: np.ndarray) -> np.ndarray:
        x = (g0 - side * y) / gp
        return x**2 * np.exp(1 - x**2) * np.exp(-((th / th_a) ** 2))

    h = 1e-4 * g0
    slope = float((power(np.array([h]), np.zeros(1)) - power(np.array([-h]), np.zeros(1)))[0]) / (2 * h)
    p0 = float(power(np.zeros(1), np.zeros(1))[0])

    def read(r: Rec, d: np.ndarray) -> np.ndarray:
        Y, _ = _arc(d, L)
        return (power(Y, _angle(d, L)) - p0) / slope

    map_disp(s, read)


def ld_mocap_marker(s: Session) -> None:
    """Motion capture (an optical tracking system of the kind robotics labs keep, through the cuvette's flat wall, its
    refraction calibrated out at rest): a small retro-reflective ball on a short post glued on one face at the tip (the
    ball's centre h 3-8 mm off the face: post, glue and radius; the face drawn), and the lab reports the ball's lateral
    coordinate as the tip's deflection. The ball rides on the tip's normal: as the tip turns by kL (k = 2 d/L^2 on the
    exact arc, inject_fresh5._arc) its centre swings by h (1 - cos kL) back towards the face's side, whichever way the
    strip bends, on top of the arc's own compression: the large bends read short on one side and long on the other, the
    rest zeroed. Displacement only. Measured (p27_129): the ball's centre 3.6 mm off the face, swinging towards the
    positive side: displacement RMS +3.6 % (residual 3.7 %, 197x its noise); the 1 V steps' peaks +4.6 % (+0.33 mm),
    +0.21 mm 2 s after their falls; the 1 V harmonics' gain 1.026 (residual 4.5 %); the 0.5 V sines within 0.02 %."""
    L, side, h = float(s.specimen["length_m"]), _sign(s), s.rng.uniform(3e-3, 8e-3)

    def read(r: Rec, d: np.ndarray) -> np.ndarray:
        Y, _ = _arc(d, L)
        return Y - side * h * (1 - np.cos(_angle(d, L)))

    map_disp(s, read)


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_pfc_resonance(s: Session) -> None:
    """The building's automatic power-factor correction: a capacitor bank of K (3-6) steps that its controller switches
    in and out as the reactive load changes (4-12 switchings in the session, one step at a time). With k steps in, the
    bank and the network's inductance resonate at the harmonic order h_1/sqrt(k) (h_1 9-15 for one step), damped by the
    resistive load (Q 2-5), and the voltage's harmonics near it (the loads' 3rd, 5th, 7th, 11th, 13th: 1-4 % of the line
    without capacitors) are magnified, the others shifted in phase: the hum's waveform jumps at each switching. Picked
    up capacitively (the voltage's waveform, each harmonic weighted by its order), 50 or 60 Hz, phase locked to the
    session clock; 1-4 um and 2-8 uA at the line (log). Displacement and current. Measured (paper_127): 50.00 Hz, five
    steps, h_1 12.8, Q 4.5, ten switchings (4, 5, 4, 5, 4, 3, 2, 1, 2, 3, 4 steps in): the pickup's 7th from 0.39 of the
    line (five steps) to 0.93 (three, the resonance at 7.4), its 5th from 0.56 to 0.20, its 11th and 13th up to 0.61 and
    0.63 (one step); 1.7 um and 4.9 uA at the line: displacement residual 0.044 % of its RMS (2.6x its noise), current
    0.14 % (0.11x)."""
    f0 = _line_f(s)
    kk = int(s.rng.integers(3, 7))
    h1, qd = s.rng.uniform(9.0, 15.0), s.rng.uniform(2.0, 5.0)
    orders = np.array([3, 5, 7, 11, 13])
    base = np.array([s.rng.uniform(0.01, 0.04) for _ in orders])
    phn = s.rng.uniform(0, 2 * np.pi, orders.size)
    n_ev = int(s.rng.integers(4, 13))
    times = np.sort(s.rng.uniform(s.t0, s.t1, n_ev))
    k = int(s.rng.integers(0, kk + 1))
    states = [k]  # the steps in before the first switching, then after each
    for _ in range(n_ev):
        k = 1 if k == 0 else kk - 1 if k == kk else k + (1 if s.rng.random() < 0.5 else -1)
        states.append(k)
    ad, ai = lu(s.rng, 1e-6, 4e-6), lu(s.rng, 2e-6, 8e-6)
    ph = s.rng.uniform(0, 2 * np.pi, 2)

    def z(n: np.ndarray, kn: int) -> np.ndarray:
        if kn == 0:
            y = 1 / (1j * n) + 1 / (qd * h1)
        else:
            hr = h1 / math.sqrt(kn)
            y = 1 / (1j * n) + 1j * n / hr**2 + 1 / (qd * hr)
        return 1 / y

    mag = {kn: z(orders.astype(float), kn) / z(orders.astype(float), 0) for kn in range(kk + 1)}
    for r in s.series():
        t = r.cols["t_s"]
        idx = np.searchsorted(times, t, side="right")
        for col, amp, p in (("disp_m", ad, ph[0]), ("i_A", ai, ph[1])):
            w = 2 * np.pi * f0 * t + p
            wave = np.cos(w)
            for j, n in enumerate(orders):
                g = np.array([mag[int(kn)][j] for kn in states])[idx]
                wave = wave + n * base[j] * np.abs(g) * np.cos(n * w + phn[j] + np.angle(g))
            r.cols[col] = r.cols[col] + amp * wave


def mp_neutral_triplen(s: Session) -> None:
    """A three-phase board behind the bench feeding the building's computers and monitors (single-phase loads spread
    over the phases), its neutral run apart from its phases (a conduit of its own, or the bench beside the neutral bar):
    in the shared neutral the fundamentals of the phases cancel but for the loads' imbalance (5-20 %), as do their 5th,
    7th, 11th and 13th harmonics, while the triplen harmonics of the computers' capacitor-input rectifiers (3rd 0.75-0.9
    of the fundamental, 9th 0.15-0.3, 15th 0.03-0.08) add three times over: the field at the bench mostly 150 (or 180)
    Hz. Picked up magnetically (each harmonic weighted by its order), phase locked to the session clock; 1-4 um and 2-8
    uA at the 3rd harmonic (log). Displacement and current. Measured (s001_128): 60.00 Hz, the imbalance 6.3 %, the
    rectifiers' 3rd 0.82, 9th 0.24, 15th 0.034: in the pickup the 9th 0.90 and the 15th 0.21 of the 3rd, the line 0.009,
    the 5th and 7th 0.02; 2.5 um and 3.9 uA at 180 Hz: displacement residual 0.13 % of its RMS (4.1x its noise), current
    0.13 % (0.36x)."""
    f0, ph = _line_f(s), s.rng.uniform(0, 2 * np.pi, 2)
    imb = s.rng.uniform(0.05, 0.2)
    c = {3: s.rng.uniform(0.75, 0.9), 5: s.rng.uniform(0.5, 0.7), 7: s.rng.uniform(0.3, 0.45),
         9: s.rng.uniform(0.15, 0.3), 11: s.rng.uniform(0.08, 0.15), 13: s.rng.uniform(0.05, 0.1),
         15: s.rng.uniform(0.03, 0.08)}
    neutral = {1: imb, **{n: (3 * a if n % 3 == 0 else imb * a) for n, a in c.items()}}
    pick = {n: n * a for n, a in neutral.items()}
    top = pick[3]
    pn = {n: s.rng.uniform(0, 2 * np.pi) for n in neutral}
    ad, ai = lu(s.rng, 1e-6, 4e-6), lu(s.rng, 2e-6, 8e-6)
    for r in s.series():
        t = r.cols["t_s"]
        for col, amp, p in (("disp_m", ad, ph[0]), ("i_A", ai, ph[1])):
            w = 2 * np.pi * f0 * t + p
            wave = sum(a / top * np.cos(n * w + pn[n]) for n, a in pick.items())
            r.cols[col] = r.cols[col] + amp * wave


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_spot_bubble(s: Session) -> None:
    """A nucleation site (a scratch, a crack's mouth) on the strip's face right under the laser's spot: while that face
    makes gas (abs(v) above v_g 0.6-0.85 V; hydrogen on the cathode, half as much oxygen on the anode) a bubble grows
    there on the gas the site collects (to its departure radius R_d 0.15-0.5 mm in 2-10 s at 1 V, log), and the laser
    reads its cap, R nearer the head, until it lets go and the next one starts; out of the gas it dissolves (20-120 s,
    log). A saw of growing offsets during the large drives, each dropping back at a departure. The face the laser sees,
    and which drive makes it the cathode, drawn. Sample by sample through the session (the rests in steps of 1 s);
    displacement only. Measured: (paper_127) the offset away from the laser's positive side, v_g 0.65 V, R_d 0.34 mm in
    3.3 s at 1 V (6.7 s on the anode's oxygen), dissolving over 70 s: saws of up to 0.34 mm on the 1 V steps' plateaus,
    -0.22 mm at their ends; displacement residual 5.2 % of its RMS (307x its noise); (p27_129) the other way, v_g 0.75
    V, R_d 0.25 mm in 4.2 s: +0.23 mm at the plateaus' ends; 5.2 % (277x)."""
    side, v_g = _sign(s), s.rng.uniform(0.6, 0.85)
    r_d, t_grow, tau_dis = s.rng.uniform(1.5e-4, 5e-4), lu(s.rng, 2.0, 10.0), lu(s.rng, 20.0, 120.0)
    cath_pos = s.rng.random() < 0.5  # the face is the cathode for v > 0
    v_d = 2 / 3 * math.pi * r_d**3
    g1 = v_d / t_grow
    vol = 0.0
    for r, gap in _gaps(s, 1.0):
        for dt, _ in gap:
            vol *= math.exp(-dt / tau_dis)
        dt, out = 1.0 / r.fs, np.empty(r.cols["v_V"].size)
        for k, vk in enumerate(r.cols["v_V"].tolist()):
            over = max(abs(vk) - v_g, 0.0) / (1 - v_g)
            share = 1.0 if ((vk > 0) == cath_pos) else 0.5
            vol = vol * math.exp(-dt / tau_dis) + g1 * over * share * dt
            if vol >= v_d:
                vol = 0.0
            out[k] = (3 * vol / (2 * math.pi)) ** (1 / 3)
        r.cols["disp_m"] = r.cols["disp_m"] + side * out


def out_second_head_beat(s: Session) -> None:
    """A second laser head of the same make on the next rig, aimed near this one, both with their mutual-interference
    setting off: for a share delta (0.05-0.2) of every beat between the two heads' sampling clocks (f_b 0.05-1 Hz, log,
    drifting by up to +-5 % over the session with their temperatures) the other head's pulses fall in this head's
    exposure, and its scattered spot pulls the reading by a_s (20-200 um, log, either sign) over a raised-cosine bump.
    Periodic bumps in the displacement, phase locked to the session clock, unrelated to the drive; displacement only.
    Measured: (paper_127) 0.54 Hz, delta 0.13, +175 um: displacement residual 1.2 % of its RMS (68x its noise), the 20
    Hz sines' residuals 750 %; (s001_128) 0.63 Hz, 0.17, -22 um: 0.30 % (9.4x)."""
    fb, delta = lu(s.rng, 0.05, 1.0), s.rng.uniform(0.05, 0.2)
    a_s, eps, ph = _sign(s) * lu(s.rng, 2e-5, 2e-4), s.rng.uniform(-0.05, 0.05), s.rng.uniform(0.0, 1.0)
    span = s.t1 - s.t0

    def bump(t: np.ndarray) -> np.ndarray:
        u = t - s.t0
        x = np.mod(fb * u + eps * fb * u**2 / (2 * span) + ph, 1.0)
        return np.where(x < delta, 0.5 * (1 - np.cos(2 * np.pi * x / delta)), 0.0)

    map_disp(s, lambda r, d: d + a_s * bump(r.cols["t_s"]))


def out_stale_current_range(s: Session) -> None:
    """The current amplifier's range changed at a re-clamping (to keep the 1 V steps' charging spikes off its limit: one
    step less sensitive in its 1-2-5 sequence, a gain of 0.5 or 0.4 of the old), the logger's scale left as it was: from
    that block (drawn, not the first) the logged current is the true one times that factor, and with a chance of 0.3 the
    operator switches back at a later block. The displacement, the drive and the analyser's spectra untouched: the
    current alone steps by a factor at a block's start; the current only. Measured: (s001_128) 0.5 from the 1700 kPa
    block (the last) on: current residual 25 % of its RMS (65x its noise), the last block's plateaus 0.28 mA (0.56 mA
    true); (p27_129) 0.5 from the 4287 kPa block on: 25 % (18x)."""
    blocks = sorted(_blocks(s).items(), key=lambda kv: kv[1][0])
    n = len(blocks)
    k_on = int(s.rng.integers(1, n)) if n > 1 else 0
    factor = float(s.rng.choice([0.5, 0.4]))
    back = s.rng.random() < 0.3 and k_on + 1 < n
    k_off = int(s.rng.integers(k_on + 1, n)) if back else n
    scaled = {p for j, (p, _) in enumerate(blocks) if k_on <= j < k_off}
    for r in s.series():
        if float(r.entry["pressure_kPa"]) in scaled:
            r.cols["i_A"] = r.cols["i_A"] * factor


def out_railway_traction(s: Session) -> None:
    """An electrified railway (a 16.7 Hz traction grid) a few hundred metres from the lab: while a train draws power on
    the nearby section its current's return through the rails and the ground sets up a field at 16.7 Hz (16.6-16.8, the
    traction grid's loose regulation wandering +-0.05-0.15 Hz over 200-600 s), picked up on the laser's and the current
    amplifier's cables: spells as trains pass (8-20 an hour, at least six in the session; each 90-300 s with a
    raised-cosine swell and fade, its strength 0.5-2 times the typical, log), 2-8 um and 4-16 uA typical (log). A narrow
    line off the mains family and off every drive frequency; displacement and current. Measured: (paper_127) 16.75 Hz
    wandering +-0.14 Hz over 430 s, 12 trains (strengths 0.7-1.9), 7.4 um and 16 uA typical: displacement residual 0.12
    % of its RMS (7.2x its noise), current 0.28 % (0.21x); (s001_128) 16.71 Hz, 11 trains, 6.6 um and 8.7 uA: 0.15 %
    (4.7x), 0.13 % (0.35x)."""
    f_r, wander, t_w = s.rng.uniform(16.6, 16.8), s.rng.uniform(0.05, 0.15), s.rng.uniform(200.0, 600.0)
    rate = s.rng.uniform(8.0, 20.0) / 3600.0
    n = max(int(s.rng.poisson(rate * (s.t1 - s.t0))), 6)
    centre = s.rng.uniform(s.t0, s.t1, n)
    half = s.rng.uniform(45.0, 150.0, n)
    strength = np.exp(s.rng.uniform(math.log(0.5), math.log(2.0), n))
    ad, ai = lu(s.rng, 2e-6, 8e-6), lu(s.rng, 4e-6, 1.6e-5)
    ph, pw = s.rng.uniform(0, 2 * np.pi, 2), s.rng.uniform(0, 2 * np.pi)

    def env(t: np.ndarray) -> np.ndarray:
        u = (t[None, :] - centre[:, None]) / half[:, None]
        return np.sum(strength[:, None] * np.where(np.abs(u) < 1, 0.5 * (1 + np.cos(np.pi * u)), 0.0), axis=0)

    for r in s.series():
        t = r.cols["t_s"]
        phase = 2 * np.pi * f_r * t - wander * t_w * np.cos(2 * np.pi * t / t_w + pw)  # the frequency's wander
        e = env(t)
        r.cols["disp_m"] = r.cols["disp_m"] + ad * e * np.cos(phase + ph[0])
        r.cols["i_A"] = r.cols["i_A"] + ai * e * np.cos(phase + ph[1])


FRESH19_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"dual_porosity": br_dual_porosity, "aged_channels": br_aged_channels},
    "faradaic_current": {"palladium_hydride": far_palladium_hydride, "electrowetting_pores": far_electrowetting_pores},
    "hysteresis": {"pad_microslip": hy_pad_microslip, "granular_bed": hy_granular_bed},
    "time_delay": {"lockin_demodulator": td_lockin_demodulator, "savgol_logger": td_savgol_logger},
    "sensor_offset": {"first_echo_sonar": so_first_echo_sonar, "levelling_table": so_levelling_table},
    "clamp_relaxation": {"hygroscopic_pads": cr_hygroscopic_pads, "sticking_guide": cr_sticking_guide},
    "dehydration": {"heated_enclosure": dh_heated_enclosure, "cooling_bath": dh_cooling_bath},
    "strain_resistance": {"gassed_cracks": sr_gassed_cracks, "tarnishing_bridges": sr_tarnishing_bridges},
    "large_deflection": {"fibre_bundle": ld_fibre_bundle, "mocap_marker": ld_mocap_marker},
    "mains_pickup": {"pfc_resonance": mp_pfc_resonance, "neutral_triplen": mp_neutral_triplen},
    "unexplained": {"spot_bubble": out_spot_bubble, "second_head_beat": out_second_head_beat,
                    "stale_current_range": out_stale_current_range, "railway_traction": out_railway_traction},
}
inject.register_forms(FRESH19_FORMS)


# ------------------------------------------------------------------------------------------------ variants


SCAN_HZ = 1000.0  # the logger's master scan


def v_scan_hold(s: Session) -> None:
    """A logger that writes its table on a master scan clock of its own (1 kHz, its phase unrelated to the DAQ's
    sample clock, running through the whole session), each row holding the latest sample it has received of every
    channel (the 'last value' resampling of a scan-table logger or a historian exporting at a fixed rate): every time
    series re-stamped at the scan's ticks within its own span, each value repeated until the next sample arrives (a
    200 Hz record's values five times over, a 685 Hz one's once or twice), late by up to one sample period on every
    channel alike. The spectra and the manifest as they were. ``labrig import`` takes it (t_s strictly increasing, the
    session clock kept)."""
    origin = s.t0 - s.rng.uniform(0.0, 1.0 / SCAN_HZ)
    for r in s.series():
        t = r.cols["t_s"]
        k0 = math.ceil((float(t[0]) - origin) * SCAN_HZ - 1e-6)
        k1 = math.floor((float(t[-1]) - origin) * SCAN_HZ + 1e-6)
        ticks = origin + np.arange(k0, k1 + 1) / SCAN_HZ
        idx = np.clip(np.searchsorted(t, ticks + 1e-9, side="right") - 1, 0, t.size - 1)
        r.cols = {k: (ticks if k == "t_s" else x[idx]) for k, x in r.cols.items()}


inject.VARIANTS.update({"scan_hold": v_scan_hold})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_127", "s001_128", "p27_129"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 6 / 7 effect cases on seeds 127-129
    "back_relaxation": [("dual_porosity", 128, S, "scan_hold"), ("aged_channels", 129, T, "log_steps")],
    "faradaic_current": [("palladium_hydride", 127, P, "rate07"), ("electrowetting_pores", 129, T, "float32_time")],
    "hysteresis": [("granular_bed", 127, P, "settled_sines"), ("pad_microslip", 129, T, "tared_records")],
    "time_delay": [("savgol_logger", 127, P, "dropped_packets"), ("lockin_demodulator", 128, S, "trigger_clock")],
    "sensor_offset": [("first_echo_sonar", 127, P, "shortened_shuffled"),
                      ("levelling_table", 129, T, "short_pretrigger")],
    "clamp_relaxation": [("hygroscopic_pads", 128, S, "merged_loadcell"), ("sticking_guide", 129, T, "host_timed")],
    "dehydration": [("heated_enclosure", 128, S, "scan_hold"), ("cooling_bath", 129, T, "steps_sines")],
    "strain_resistance": [("gassed_cracks", 127, P, "two_pressures"), ("tarnishing_bridges", 128, S, "coherent_sines")],
    "large_deflection": [("fibre_bundle", 127, P, "resampled"), ("mocap_marker", 129, T, "decimated3")],
    "mains_pickup": [("pfc_resonance", 127, P, "eis_descending"), ("neutral_triplen", 128, S, "own_clock")],
    "unexplained": [("spot_bubble", 127, P, "swinging_door"), ("spot_bubble", 129, T, "asrun"),
                    ("second_head_beat", 127, P, "fir_decimated"), ("second_head_beat", 128, S, "scan_hold"),
                    ("stale_current_range", 128, S, "no_loadcell"), ("stale_current_range", 129, T, "cycle_averaged"),
                    ("railway_traction", 127, P, "asrun"), ("railway_traction", 128, S, "scan_hold")],
}
CLEAN = [(127, P, "asrun"), (127, P, "scan_hold"), (128, S, "asrun"), (128, S, "no_spectra"),
         (129, T, "asrun"), (129, T, "scan_hold")]


def fresh19_cases(only: str | None = None) -> list[Case]:
    """The twentieth held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds
    127-129)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh19_cases, "inject_fresh19", "fresh19")
