"""An eighth held-out set for the diagnosis (issue 12), written without sight of the diagnosis (its code, its doc,
its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh6.py and the simulated
bench (mock_devices/effects.py); four structures outside the catalogue (truth "unexplained": a loose banana plug in
the drive line, the current amplifier's overload and its recovery, convection plumes steering the laser's beam, the
load cell's serial frames leaking into the analogue inputs); clean sessions. All on three bases of new seeds (91-93:
the paper strip, the seed-001 strip on its own sweep, the paper strip 38 mm free) and on the earlier sets' protocol
/ data-shape variants plus one new here: every impedance spectrum listed from its highest frequency down (the order a
potentiostat sweeps and exports it; the import contract asks f_Hz positive, not increasing).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh6 are reused (importing inject_fresh6 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import. Strengths are drawn from
the case's seed (uniform unless "log"); each form's docstring ends with the change it made on its case, measured in
memory against the clean base (relative RMS change over all series, form only, no variant; "noise": the column's
sample-to-sample noise at rest, from the step records' last 2 s).

Run: python bench/inject_fresh7.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Callable

import numpy as np
from scipy import signal

import inject
from inject import Case, Rec, Session, _dry, lti, lu, map_disp
from inject_fresh2 import _chrono, _map_through
from inject_fresh3 import _past, _resist, _sign, _step_responses, _through_x
from inject_fresh4 import _preset, _ratio_both
from inject_fresh5 import _u
from inject_fresh6 import _blocks, _bursts, _reading

# the paper's strip 38 mm free (earlier sets used 20, 25, 28, 30, 35, 40 and 45 mm; its 1 V step peaks at 13.9 mm,
# inside the laser's +-20 mm): registered in every process that imports this module
inject.register_free_length("paper_38", 0.038)

inject.BASES.update({
    "paper_91": ("paper-sweep", "paper", 91),
    "s001_92": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 92),
    "p38_93": ("paper-sweep", "paper_38", 93),
})

Q_V = 10.0 / 32768  # the voltage channel's step (+-10 V, 16 bits)
KGF = 0.0980665  # the load-cell indicator's 0.01 kgf


# ------------------------------------------------------------------------------------------------ tools


def _superpose(s: Session, e: dict[int, np.ndarray], scale: dict[str, float] | None = None) -> None:
    """A voltage e (id(record) -> array) added to the drive the strip felt, the recorded v_V untouched: its change
    within each record reaches the current and the displacement through the strip's measured unit-step responses at
    that pressure (inject_fresh3._step_responses of the pressure's first step record, on the record's own clock, held
    at their last values beyond; superposition of e's steps). The part of e already there at a record's start is
    taken as settled into the rest it starts from. ``scale``: a factor per column ("i_A", "disp_m"), 1 if not given."""
    steps = {}
    for r in reversed(_chrono(s)):
        if r.kind == "step":
            si, sd, _, _ = _step_responses(r)
            steps[float(r.entry["pressure_kPa"])] = (np.arange(si.size) / r.fs, si, sd)
    for r in s.series():
        x, p = e[id(r)], float(r.entry["pressure_kPa"])
        if p not in steps or not np.any(x != x[0]):
            continue
        n = x.size
        m = 1 << int(math.ceil(math.log2(2 * n)))
        de = np.fft.rfft(np.diff(x - x[0], prepend=0.0), m)
        ts = steps[p][0]
        for col, S in (("i_A", steps[p][1]), ("disp_m", steps[p][2])):
            kern = np.interp(np.arange(n) / r.fs, ts, S)
            r.cols[col] = r.cols[col] + (scale or {}).get(col, 1.0) * np.fft.irfft(de * np.fft.rfft(kern, m), m)[:n]


def _lag(v: np.ndarray, fs: float, tau: float) -> np.ndarray:
    """The interface's own potential: the terminal voltage through the double layer's charging lag."""
    return lti(v, fs, lambda z: 1 / (1 + tau * z))


def _episodes(s: Session, spells: list[tuple[float, float]], per_s: float,
              dur: tuple[float, float]) -> list[tuple[float, float]]:
    """Short episodes inside each spell: the first at its start, then Poisson at per_s, each lasting dur (log)."""
    out = []
    for a, b in spells:
        t = a
        while t < b:
            out.append((t, t + lu(s.rng, *dur)))
            t += s.rng.exponential(1 / per_s)
    return out


def _ramp_env(t: np.ndarray, spans: list[tuple[float, float]], edge: float) -> np.ndarray:
    """1 inside any span, raised-cosine edges of ``edge`` seconds, 0 elsewhere."""
    env = np.zeros(t.size)
    for a, b in spans:
        x = np.clip(np.minimum(t - a, b - t) / edge, 0, 1)
        env = np.maximum(env, 0.5 - 0.5 * np.cos(np.pi * x))
    return env


def _block_of(s: Session) -> Callable[[np.ndarray], np.ndarray]:
    """Session time -> the start of the pressure block it falls in (the last block started before it)."""
    starts = np.sort([a for a, _ in _blocks(s).values()])
    return lambda t: starts[np.clip(np.searchsorted(starts, t, side="right") - 1, 0, None)]


# ------------------------------------------------------------------------------------------------ back relaxation


def br_cation_exchange(s: Session) -> None:
    """The strip arrives in its acid (H+) form and the bath holds sodium (a saline storage bath, a buffer, or tap
    water's Na+): the counter-ions exchange through the session, 1 - exp(-u/tau_x) (tau_x 0.2-0.6 of the session).
    H+ carries little water and hardly relaxes back (K2 0.2-0.5, tau 1.5-4 s, log); Na+ drags more water that flows
    back more slowly (K2 0.9-1.3, tau 5-15 s, log). One lag per record at its mid time, 1 - K2/(tau s + 1), K2 linear
    and tau log-linear in the exchanged share, with the session's history: the give-back grows through the session.
    Measured (paper_91): displacement RMS -57 % (residual 77 % of its RMS), the 1 V steps' peaks -29, -69, -75 and -76 %
    (early to late)."""
    k2h, k2n, th, tn = s.rng.uniform(0.2, 0.5), s.rng.uniform(0.9, 1.3), lu(s.rng, 1.5, 4.0), lu(s.rng, 5.0, 15.0)
    tx = s.rng.uniform(0.2, 0.6)

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        x = -math.expm1(-float(_u(s, np.mean(r.cols["t_s"]))) / tx)
        k2, tau = k2h + (k2n - k2h) * x, th * (tn / th) ** x
        return lambda z: 1 - k2 / (tau * z + 1)

    _map_through(s, H, 120.0)


def br_skin_barrier(s: Session) -> None:
    """Water diffusing back across the membrane (half-thickness l, diffusivity D) must then cross the dense plated
    layer at the electrode (a surface permeability h): finite diffusion with a surface resistance (Robin boundary),
    kernel (tanh q/q)/(1 + q tanh q/Bi), q = sqrt(tau s), tau = l^2/D, Bi = h l/D 0.2-3 (log). Bi large is plain
    diffusion, Bi small a single lag; between, a lag-like start with a diffusive tail. K2 0.8-1.2, the effective
    time tau (1/3 + 1/Bi) 3-15 s (log). With the session's history. Measured (p38_93): displacement RMS -76 % (residual
    110 %), the 1 V steps' peaks -82 %, 20 Hz record residual 56-65 %."""
    k2, teff, bi = s.rng.uniform(0.8, 1.2), lu(s.rng, 3.0, 15.0), lu(s.rng, 0.2, 3.0)
    tau = teff / (1 / 3 + 1 / bi)

    def kernel(z: np.ndarray) -> np.ndarray:
        q = np.sqrt(tau * z + 0j)
        small = np.abs(q) < 1e-3
        qs = np.where(small, 1.0, q)
        th = np.tanh(qs)
        return np.where(small, 1.0 - q**2 * (1 / 3 + 1 / bi), th / qs / (1 + qs * th / bi))

    _map_through(s, lambda r: lambda z: 1 - k2 * kernel(z), 120.0)


# ------------------------------------------------------------------------------------------------ faradaic current


def far_poole_frenkel(s: Session) -> None:
    """Platinum grown into the membrane during plating (dendrites, a known IPMC fault) leaves thin polymer gaps
    between the electrodes; electrons cross them by Poole-Frenkel emission from traps, i ~ V exp(beta sqrt|V|)
    (the field lowers the traps' barrier as its square root), beta 2-5 V^-1/2: an electronic leak beside the ionic
    one, instantaneous (no double-layer lag, no transport), growing far faster than V. 0.1-0.5 mA at 1 V (log).
    Current only. Measured (s001_92): current RMS +0.9 %, residual 2.2 % of its RMS (36x its noise), peaks 0.14 mA."""
    i1, beta = lu(s.rng, 1e-4, 5e-4), s.rng.uniform(2.0, 5.0)
    for r in s.series():
        v = r.cols["v_V"]
        r.cols["i_A"] = r.cols["i_A"] + i1 * v * np.exp(beta * (np.sqrt(np.abs(v)) - 1.0))


def far_bicarbonate_ce(s: Session) -> None:
    """A bicarbonate-buffered bath (a physiological buffer, or a carbonated one): protons for the cathode's hydrogen
    evolution come from carbonic acid, and the slow step is the hydration of CO2 that makes it (k ~ 0.02-0.1 s^-1):
    a CE mechanism. Each electrode, the cathode on its own polarity, runs a Tafel wave k/(1 + k), k = exp((v -
    E_h)/b) (E_h 0.2-0.5 V, b 40-80 mV), at the interface's potential (double-layer lag 20-100 ms, log), through the
    reaction layer's Gerischer admittance W = sqrt(1 + tau_c s) (tau_c 10-60 s, log) in series with the finite
    kinetic rate (W (1 + 1/kap)/(1 + W/kap), kap 2-5): each edge brings a diffusion spike (1 + kap) times the plateau
    that decays to the chemistry's plateau over tau_c. Plateau 0.05-0.3 mA (log). Current only. Measured (paper_91):
    current RMS +4.3 %, residual 7.8 % (150x its noise), peaks 0.54 mA."""
    il, eh, b = lu(s.rng, 5e-5, 3e-4), s.rng.uniform(0.2, 0.5), s.rng.uniform(0.04, 0.08)
    tauc, taui, kap = lu(s.rng, 10.0, 60.0), lu(s.rng, 0.02, 0.1), s.rng.uniform(2.0, 5.0)
    wave = lambda v: 1 / (1 + np.exp(-np.clip((v - eh) / b, -60, 60)))  # noqa: E731  k/(1 + k)
    theta = {}
    for r in s.series():
        vi = _lag(r.cols["v_V"], r.fs, taui)
        theta[id(r)] = wave(vi) - wave(-vi)

    def K(z: np.ndarray) -> np.ndarray:
        W = np.sqrt(1 + tauc * z + 0j)
        return W * (1 + 1 / kap) / (1 + W / kap)

    new = _through_x(s, theta, lambda r: K, 120.0)
    for r in s.series():
        r.cols["i_A"] = r.cols["i_A"] + il * new[id(r)]


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_jaw_peel(s: Session) -> None:
    """Adhesion hysteresis at the clamp's jaws: the wet strip sticks to the pads, and a large bend peels it off the
    jaw on its convex side, the contact line moving into the jaw by a and the free length growing by a (tip gain
    1 + 2a/L, quasi-static). Peeling runs while the energy release rate (the root moment squared) exceeds the
    contact's toughness, which rises inward as the pad's pressure builds, so the front stops at a_p(m) = a_max
    clip((m^2 - m_p^2)/(1 - m_p^2), 0, 1), m the bend over the session's largest on that side; it re-adheres only
    below rho of the toughness (rho 0.3-0.7: adhesion hysteresis), at a_p(m/sqrt(rho)). The front is a rate-independent
    clip between the two: small bends see nothing, large ones a gain that rises and a loop that stays as f -> 0.
    Each side its own pad (m_p 0.3-0.6, a_max 1.5-4 % of L). Displacement only. Measured (p38_93): displacement RMS +1.6
    % (residual 2.0 %, 270x its noise), 33 % of the samples touched, the 1 V steps' peaks +3.5 %."""
    L, rho = float(s.specimen["length_m"]), s.rng.uniform(0.3, 0.7)
    sides = [(s.rng.uniform(0.3, 0.6), L * s.rng.uniform(0.015, 0.04)) for _ in range(2)]
    recs = _chrono(s)
    d = np.concatenate([r.cols["disp_m"] for r in recs])
    gain = np.ones(d.size)
    for sg, (mp, amax) in zip((1.0, -1.0), sides):
        m = np.clip(sg * d, 0, None) / max(float(np.max(sg * d)), 1e-12)
        lo = amax * np.clip((m**2 - mp**2) / (1 - mp**2), 0, 1)
        hi = amax * np.clip((m**2 / rho - mp**2) / (1 - mp**2), 0, 1)
        a, front = 0.0, np.empty(d.size)
        for k, (x, y) in enumerate(zip(lo.tolist(), hi.tolist())):
            a = min(max(a, x), y)
            front[k] = a
        gain = np.where(sg * d > 0, 1 + 2 * front / L, gain)
    parts = np.split(d * gain, np.cumsum([r.cols["disp_m"].size for r in recs])[:-1])
    for r, x in zip(recs, parts):
        r.cols["disp_m"] = x


def hy_interface_adsorption(s: Session) -> None:
    """Specific adsorption of anions on each electrode's platinum with lateral attraction (a Frumkin isotherm beyond
    its critical interaction): each surface domain is bistable, adsorbing when its electrode's potential rises past
    E_j + w_j and desorbing only below E_j - w_j, so the interface's charge is a rate-independent function of the
    drive's history. 60 domains per electrode, E_j ~ N(E_0, s_E) (E_0 0.3-0.6 V, s_E 0.1-0.25 V), w_j log-normal
    around 0.08-0.25 V (domains with E_j < w_j stay adsorbed at rest: a remanence); one electrode on +V, the other on
    -V. The adsorbed charge (h 0.04-0.1 V of drive at full coverage, through the adsorption's own kinetics, a 5-30 ms
    lag) adds to what the strip charges and bends by: current and displacement through the strip's measured step
    responses (_superpose), the recorded v_V untouched; state through the session. Measured (paper_91): displacement RMS
    +7.3 % (residual 7.4 %), the 1 V steps' peaks +7.7 %, current residual 4.9 % (93x its noise), 20 Hz record
    displacement residual 62-76 % (the remanent charge's quasi-static bend)."""
    h, e0, se, wm = s.rng.uniform(0.04, 0.1), s.rng.uniform(0.3, 0.6), s.rng.uniform(0.1, 0.25), s.rng.uniform(0.08, 0.25)
    taua = lu(s.rng, 0.005, 0.03)
    E, w = e0 + se * s.rng.normal(size=(2, 60)), wm * np.exp(0.4 * s.rng.normal(size=(2, 60)))
    up, dn = E + w, E - w
    state = dn < 0  # the domains that stay adsorbed at 0 V start adsorbed (the strip has been at rest)
    recs = _chrono(s)
    v = np.concatenate([r.cols["v_V"] for r in recs]).tolist()
    cover = np.empty(len(v))
    for k, x in enumerate(v):
        for j, pot in enumerate((x, -x)):
            state[j] |= pot >= up[j]
            state[j] &= pot > dn[j]
        cover[k] = state[0].mean() - state[1].mean()
    parts = np.split(cover, np.cumsum([r.cols["v_V"].size for r in recs])[:-1])
    _superpose(s, {id(r): h * _lag(c, r.fs, taua) for r, c in zip(recs, parts)})


# ------------------------------------------------------------------------------------------------ time delay


def td_mcu_logger(s: Session) -> None:
    """The laser's analogue output logged by a microcontroller board (an Arduino-type logger beside the DAQ) in a
    timer interrupt at its own rate f_b 250-1000 Hz: each conversion starts after the interrupt's latency (USB and
    serial interrupts queue ahead of it: exponential, mean 0.1-1 ms, log), the board sends its values in blocks and
    the host stamps each value by its nominal tick plus the n_b (2-5) board periods its double buffer holds it, then
    interpolates the stream onto the DAQ's clock. The reading is late by n_b/f_b (2-20 ms) less the latency, which
    jitters sample to sample; the board's ticks free-running on the session clock. Measured (s001_92): displacement RMS
    -0.0 % over all (residual 0.24 %, 11x its noise), 20 Hz record residual 74 %."""
    fb, nb, lat, ph = s.rng.uniform(250.0, 1000.0), int(s.rng.integers(2, 6)), lu(s.rng, 1e-4, 1e-3), s.rng.uniform(0, 1)
    new = {}
    for r in s.series():
        t, d = r.cols["t_s"], r.cols["disp_m"]
        past = _past(s, r, "disp_m", 0.1, r.fs)
        T, D = np.r_[t[0] - np.arange(past.size, 0, -1) / r.fs, t], np.r_[past, d]
        tj = (np.arange(math.floor((t[0] - 0.05) * fb), math.ceil(t[-1] * fb) + 1) + ph) / fb
        val = np.interp(tj + s.rng.exponential(lat, tj.size), T, D)
        new[id(r)] = np.interp(t, tj + nb / fb, val)
    map_disp(s, lambda r, d: new[id(r)])


def td_isolated_monitor(s: Session) -> None:
    """The drive's voltage monitor goes through an isolation amplifier of the digitising kind (a delta-sigma
    modulator across the barrier, a sinc^3 decimator at a word rate f_w 200-500 Hz, a DAC re-making the analogue
    output, held between words): the recorded v_V is the drive through sinc^3 (group delay 1.5/f_w) and a zero-order
    hold (another 0.5/f_w), late by 4-10 ms, re-read at the DAQ's 0.31 mV step; the strip, its current and its
    displacement saw the drive itself. Words free-running on the session clock. Measured (p38_93): v_V residual 17 % of
    its RMS (up to a full volt at the steps' edges), 83 % of the samples moved."""
    fw, ph = s.rng.uniform(200.0, 500.0), s.rng.uniform(0, 1)
    T = 1 / fw

    def sinc3(z: np.ndarray) -> np.ndarray:
        small = np.abs(z * T) < 1e-9
        return np.where(small, 1.0 + 0j, (-np.expm1(-z * T) / np.where(small, 1.0, z * T)) ** 3)

    filt = _through_x(s, {id(r): r.cols["v_V"] for r in s.series()}, lambda r: sinc3, 0.1)
    for r in s.series():
        t = r.cols["t_s"]
        word = (np.floor(t * fw - ph) + ph) / fw  # the last word the isolator's DAC put out
        r.cols["v_V"] = np.round(np.interp(word, t, filt[id(r)], left=0.0) / Q_V) * Q_V


# ------------------------------------------------------------------------------------------------ sensor offset


def so_ghost_spot(s: Session) -> None:
    """A ghost of the laser's spot: the cuvette's uncoated window reflects part of the beam back, and the second
    reflection strikes the strip inboard of the main spot (delta 0.15-0.45 L, set by the window's distance and the
    beam's incidence); the triangulation receiver's peak detector sees both images and reports their intensity
    weighted centroid, (1 - g) w(x_m) + g w(x_m - delta L), g 0.1-0.3, the main spot at x_m 0.93-1 L. Through the
    strip's quasi-static deflections and modal parts (inject_fresh6._reading): gain down, zeros move, poles stay.
    Measured (paper_91): displacement RMS -13 % (residual 13 %), 20 Hz record residual 24-27 %."""
    xm, g, dx = s.rng.uniform(0.93, 1.0), s.rng.uniform(0.1, 0.3), s.rng.uniform(0.15, 0.45)
    new = _reading(s, lambda sp: [(1 - g, xm * sp.geometry.length, 0), (g, (xm - dx) * sp.geometry.length, 0)])
    map_disp(s, lambda r, d: new[id(r)])


def so_fibre_bend(s: Session) -> None:
    """No laser: a fibre-optic bend sensor (a plastic optical fibre with a sensitised zone, or a fibre Bragg grating)
    glued along the middle of the strip reads the mean curvature over its zone [a, b] L (a 0.1-0.35, b 0.6-0.95),
    (w'(b L) - w'(a L))/((b - a) L), converted to tip deflection as a uniform arc would give it (kappa L^2/2, its
    static calibration); the fibre thin enough not to stiffen the strip. Exact for the quasi-static eigen-moment
    bend's uniform part; the voltage's fall along the electrodes and the modes above f1 bend the zone otherwise than
    the tip (zeros move, poles stay). Through inject_fresh6._reading. Measured (s001_92): displacement RMS -0.4 %
    (residual 0.66 %, 30x its noise), 20 Hz record residual 46-52 %."""
    a, b = s.rng.uniform(0.1, 0.35), s.rng.uniform(0.6, 0.95)

    def pts(sp) -> list[tuple[float, float, int]]:
        L = sp.geometry.length
        return [(L / (2 * (b - a)), b * L, 1), (-L / (2 * (b - a)), a * L, 1)]

    new = _reading(s, pts)
    map_disp(s, lambda r, d: new[id(r)])


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_spring_clamp(s: Session) -> None:
    """A constant-force clamp (a spring-loaded or dead-weight lever jaw): the load cell reads its set force through
    every block, but the Nafion under the pads creeps all the same (Burgers: a primary part 1 - exp(-t/tau_k), tau_k
    30-300 s, log, plus steady flow t/tau_v, tau_v 2000-8000 s, log, from each block's start). The squeezed layer
    goes on losing water and conforming, the way Table 1's rows change with pressure: its CPE Q0c x (1 - q c), its
    R_c and leak R_pc x (1 + q c) (q 0.1-0.3), the real contact grows (r_cont x (1 - a c), a 0.15-0.35) and the
    thinned layer grips less (K_t bar x (1 - k c), k 0.05-0.15), c the creep. Per record at its mean creep, through the
    strip's transfer functions (inject_fresh4._ratio_both): current, gain and f1 drift within each block, the load
    cell flat. Measured (p38_93): current RMS -4.1 % (residual 4.5 %, 86x its noise), displacement residual 0.10 %
    (13x), 20 Hz record residuals 8-9 % (displacement) and 5-6 % (current); the load cell unchanged."""
    a, q, k = s.rng.uniform(0.15, 0.35), s.rng.uniform(0.1, 0.3), s.rng.uniform(0.05, 0.15)
    tk, tv = lu(s.rng, 30.0, 300.0), lu(s.rng, 2000.0, 8000.0)
    block, pre = _block_of(s), _preset(s)
    c = {}
    for r in s.series():
        t = np.clip(r.cols["t_s"] - block(r.cols["t_s"]), 0, None)
        c[id(r)] = float(np.mean(-np.expm1(-t / tk) + t / tv))

    def new(r: Rec):
        sp, x = pre.specimen(float(r.entry["pressure_kPa"])), c[id(r)]
        cl = sp.clamp
        cl = replace(cl, r_cont=cl.r_cont * max(1 - a * x, 0.3), Q0c=cl.Q0c * max(1 - q * x, 0.3), R_c=cl.R_c * (1 + q * x),
                     R_pc=cl.R_pc * (1 + q * x))
        return sp.with_(clamp=cl, Kt_bar=sp.Kt_bar * max(1 - k * x, 0.5))

    _ratio_both(s, new)


def cr_charge_squeeze(s: Session) -> None:
    """Electro-osmotic drag in the clamped part: every coulomb through the jaws pumps water to the cathode face, where
    the pad's pressure squeezes it out of the clamped zone; the zone dries and thins and the force of the held gap
    falls with the charge passed, dx = (1 - x) |i| dt/q_c - x dt/tau_w (re-wetting from the free strip, tau_w 200-1000
    s, log, also over the rests), F = F_set (1 - r x)/(1 - r x_set), r 5-15 %, q_c 0.1-0.4 of the session's charge
    per block: the load cell falls in the driven records and creeps back in the pauses. Per record at its mean, the strip
    clamped at that force (the preset's clamp law) with its clamped layer as dry as x says (Q0c x (1 - q x), R_c and
    R_pc x (1 + q x), q 0.2-0.5), through the strip's transfer functions (inject_fresh4._ratio_both); the load cell at
    its 0.01 kgf. Measured (paper_91): load cell at 0.95-0.97 of its setting by the blocks' ends, current RMS -3.8 %
    (residual 4.1 %), displacement residual 0.06 % (5x its noise)."""
    r0, tw, q = s.rng.uniform(0.05, 0.15), lu(s.rng, 200.0, 1000.0), s.rng.uniform(0.2, 0.5)
    recs = _chrono(s)
    qtot = sum(float(np.sum(np.abs(r.cols["i_A"]) * np.gradient(r.cols["t_s"]))) for r in recs)
    qc = s.rng.uniform(0.1, 0.4) * qtot / max(len(_blocks(s)), 1)
    block, pre = _block_of(s), _preset(s)
    x, t_end, cur, xset, mean = 0.0, None, None, 0.0, {}
    for r in recs:
        t, i = r.cols["t_s"], np.abs(r.cols["i_A"])
        if t_end is not None:
            x *= math.exp(-(t[0] - t_end) / tw)
        if block(t[:1])[0] != cur:  # a new setting: the operator sets the force on the strip as it is now
            cur, xset = block(t[:1])[0], x
        dts = np.diff(t, prepend=t[0]).tolist()
        out = np.empty(t.size)
        for n, (ik, dt) in enumerate(zip(i.tolist(), dts)):
            kk = ik / qc + 1 / tw
            eq = ik / qc / kk
            x = eq + (x - eq) * math.exp(-kk * dt)
            out[n] = x
        rel = (1 - r0 * out) / (1 - r0 * xset)
        if "force_N" in r.cols:
            r.cols["force_N"] = np.round(r.cols["force_N"] * rel / KGF) * KGF
        mean[id(r)] = (float(r.entry["pressure_kPa"]) * float(np.mean(rel)), float(np.mean(out)))
        t_end = float(t[-1])

    def new(r: Rec):
        p, xm = mean[id(r)]
        sp = pre.specimen(p)
        cl = sp.clamp
        return sp.with_(clamp=replace(cl, Q0c=cl.Q0c * (1 - q * xm), R_c=cl.R_c * (1 + q * xm), R_pc=cl.R_pc * (1 + q * xm)))

    _ratio_both(s, new)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_osmotic_bath(s: Session) -> None:
    """An open cuvette of salt solution (the strip's storage or ion-exchange bath) warmed by the lamp or the
    amplifiers loses 10-35 % of its water by evaporation over the session: its salinity rises as 1/(1 - eps u), the
    water activity falls, and osmosis draws water out of the membrane, which loses coupling and conductance with it.
    The loss follows the salinity's rise, total (c(u) - 1)/(c(1) - 1), total 0.1-0.25: slow at first, accelerating
    (the opposite curvature of a strip drying in air). Through inject._dry (conductance 0.3-1 of the gain's share,
    spectra at the start of the series after them). Measured (p38_93): displacement RMS -7.8 % (the 1 V steps' peaks
    -0.1, -4.8, -10 and -17 %), current -7.5 %, |Z| at 0.1 Hz up to 1.14x."""
    total, eps = s.rng.uniform(0.1, 0.25), s.rng.uniform(0.1, 0.35)
    c = lambda u: 1 / (1 - eps * np.clip(u, 0, 1)) - 1  # noqa: E731
    _dry(s, lambda u: total * c(u) / c(1.0))


def dh_rewetted_blocks(s: Session) -> None:
    """A strip in air that the operator re-wets (a drop from a pipette, a dip) each time the clamp is re-set: within
    each pressure block it dries, x = x_0 + total (1 - exp(-(t - t_b)/tau)) (tau 100-600 s, log; total 0.15-0.35 by
    a block's length), and each re-wetting restores a share rho 0.7-1 of what was lost, so a little carries over:
    a sawtooth of drying through the blocks, the load cell untouched. Through inject._dry (conductance and spectra
    follow). Measured (s001_92): displacement RMS -4.8 % (residual 5.9 %), current -18 % (residual 19 %), |Z| at 0.1 Hz
    within 0.3 % (each spectrum follows a re-wetting)."""
    tau, rho = lu(s.rng, 100.0, 600.0), s.rng.uniform(0.7, 1.0)
    spans = sorted(_blocks(s).values())
    total = s.rng.uniform(0.15, 0.35) / -math.expm1(-max(b - a for a, b in spans) / tau)
    starts, carry, x0 = np.array([a for a, _ in spans]), [], 0.0
    for a, b in spans:  # what each block starts from: the part of the last block's loss the re-wetting left
        carry.append(x0)
        x0 = (1 - rho) * (x0 + total * -math.expm1(-(b - a) / tau))

    def loss(u: np.ndarray) -> np.ndarray:
        t = s.t0 + np.asarray(u) * (s.t1 - s.t0)
        k = np.clip(np.searchsorted(starts, t, side="right") - 1, 0, None)
        return np.asarray(carry)[k] + total * -np.expm1(-np.clip(t - starts[k], 0, None) / tau)

    _dry(s, loss)


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_tunnelling(s: Session) -> None:
    """An electrode of platinum nanoparticles (impregnation-reduction leaves a particulate layer) conducts by
    tunnelling across the gaps between particles: stretching widens every gap in proportion, so the resistance grows
    exponentially with the strain, dR/R = exp(gamma e) - 1, and compression narrows them (down towards touching:
    exp(-gamma e) - 1 > -1). The tensioned face (side drawn) with gamma_a 0.2-0.6 per unit of the displacement scale,
    the other face 0.5-1.5 times as steep at 0.2-0.6 of its weight; normalised to the first face's slope at rest.
    Gains fall by 0.015-0.04 (displacement), 0.04-0.1 (current) per unit (inject_fresh3._resist). Measured (paper_91):
    displacement RMS -9.9 % (the 1 V steps' peaks -16 %), current -1.6 % (residual 6.8 %)."""
    side, ga, c = _sign(s), s.rng.uniform(0.2, 0.6), s.rng.uniform(0.2, 0.6)
    gb = ga * s.rng.uniform(0.5, 1.5)
    _resist(s, lambda r, e: (np.expm1(ga * side * e) + c * np.expm1(-gb * side * e)) / ga, (0.015, 0.04), (0.04, 0.1))


def sr_reclamp_damage(s: Session) -> None:
    """The electrode near the root is scored each time the clamp is re-set (the strip handled, the jaw's edge pressed
    into the plating): the tensioned face's crack density, and with it its gauge, steps up at every block, by
    0.3-1 of the first block's (log) each time; the face cracks on tension only (side drawn), the other face at
    0.1-0.4 of its gauge. Gains fall by 0.015-0.04 (displacement), 0.04-0.1 (current) per unit (inject_fresh3._resist).
    Measured (s001_92): displacement RMS -1.0 % (residual 1.1 %, 50x its noise), the 1 V steps' peaks -0.8, -1.2, -1.7
    and -2.0 % block by block, current residual 1.0 %."""
    side, gb = _sign(s), s.rng.uniform(0.1, 0.4)
    starts = np.sort([a for a, _ in _blocks(s).values()])
    gauge = np.cumsum(np.r_[1.0, [lu(s.rng, 0.3, 1.0) for _ in starts[1:]]])
    block = _block_of(s)

    def shape(r: Rec, e: np.ndarray) -> np.ndarray:
        g = gauge[int(np.searchsorted(starts, block(r.cols["t_s"][:1])[0]))]
        return g * (np.clip(side * e, 0, None) + gb * np.clip(-side * e, 0, None))

    _resist(s, shape, (0.015, 0.04), (0.04, 0.1))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_angle_rod(s: Session) -> None:
    """Video tracking of the tip's orientation (a line marker over the tip's last phi L, phi 0-0.3: its angle the
    mean tangent there), the angle converted to deflection with a rigid-rod rule, y = L_c sin(theta), its gain
    calibrated at small angles. On the exact arc the marker's angle is theta = 2 d (1 - phi/2)/L, so the reading is
    L_c sin(d/L_c) with L_c = L/(2 - phi): an odd compression about twice the arc's, with no even part. Measured
    (s001_92): displacement RMS -1.8 % (residual 2.0 %), the 1 V steps' peaks -3.3 %."""
    lc = float(s.specimen["length_m"]) / (2 - s.rng.uniform(0.0, 0.3))
    map_disp(s, lambda r, d: lc * np.sin(d / lc))


def ld_tip_heavy_taper(s: Session) -> None:
    """A hand-cut or hand-polished strip thinner towards its tip, h(s) = h_0 (1 - tau s/L), tau 0.1-0.3: the
    actuation moment per length goes as alpha h times the charge and the bending stiffness as h^3, so the curvature
    rises towards the tip as 1/h^2. The laser reads the exact height int sin(theta) ds of the tip's material point,
    theta(s) = int kappa, for the strip whose linear reading int theta ds is d (inject_fresh4's tapered curvature is
    the opposite profile, falling from the root): more rotation per deflection, so more compression than the
    uniform arc. Measured (p38_93): displacement RMS -2.8 % (residual 3.1 %), the 1 V steps' peaks -5.0 %."""
    tau = s.rng.uniform(0.1, 0.3)
    L = float(s.specimen["length_m"])
    sg = np.linspace(0.0, L, 257)
    th1 = np.r_[0.0, np.cumsum(np.diff(sg) * 0.5 * (1 / (1 - tau * sg[1:] / L) ** 2 + 1 / (1 - tau * sg[:-1] / L) ** 2))]
    dlin1 = np.trapezoid(th1, sg)
    top = max(float(np.max(np.abs(r.cols["disp_m"]))) for r in s.series()) * 1.05 + 1e-12
    grid = np.linspace(-top, top, 801)
    table = np.trapezoid(np.sin(np.outer(grid / dlin1, th1)), sg, axis=1)
    map_disp(s, lambda r, d: np.interp(d, grid, table))


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_body_capacitance(s: Session) -> None:
    """Hum coupled through the operator's body: a person standing at the bench is a plate at mains potential a few
    centimetres from the laser's cable and the current amplifier's input lead, and the pickup grows several-fold while
    they are there (4-8 visits of 20-120 s that start inside recorded series, 3 s approach and departure); with
    nobody there the room's wiring leaves 0.2-0.4 of it. 50 or 60 Hz (+-0.05) with a 3rd harmonic (0.1-0.3), phase
    locked to the session clock, on both lines: 1.5-5 um and 3-10 uA (log) at full. Measured (paper_91): residual 0.84
    um RMS on the displacement (2.2x its noise) and 1.1 uA on the current (0.6x), peaks 3.6 um and 4.5 uA, 20 Hz record
    residual 11-39 %."""
    ad, ai, h3, base = lu(s.rng, 1.5e-6, 5e-6), lu(s.rng, 3e-6, 1e-5), s.rng.uniform(0.1, 0.3), s.rng.uniform(0.2, 0.4)
    f = (50.0 if s.rng.random() < 0.5 else 60.0) + s.rng.uniform(-0.05, 0.05)
    pd, pi = s.rng.uniform(0, 2 * np.pi, 2)
    visits = _bursts(s, int(s.rng.integers(4, 9)), (20.0, 120.0))
    for r in s.series():
        t = r.cols["t_s"]
        env = base + (1 - base) * _ramp_env(t, visits, 3.0)
        w = 2 * np.pi * f * t
        r.cols["disp_m"] = r.cols["disp_m"] + ad * env * (np.cos(w + pd) + h3 * np.cos(3 * (w + pd)))
        r.cols["i_A"] = r.cols["i_A"] + ai * env * (np.cos(w + pi) + h3 * np.cos(3 * (w + pi)))


def mp_transformer_hum(s: Session) -> None:
    """Magnetostrictive hum: the laser controller's mains transformer (or a ballast on the same shelf) vibrates at
    twice the line frequency, 100 or 120 Hz (+-0.1), with its harmonics (4f 0.2-0.5, 6f 0.05-0.2 of it), and the
    shelf carries it to the laser head: the head moves against the strip, so the displacement reads a line at 2f and
    its harmonics, 0.5-3 um peak (log); the current line is untouched (no electrical coupling). Phase locked to the
    session clock; sampled as the DAQ samples it (at 200 Hz the 100 Hz line sits at Nyquist and beats slowly). Measured
    (p38_93): residual 2.0 um RMS on the displacement (5x its noise), peaks 4.0 um, 20 Hz record residual 41 %."""
    a, h4, h6 = lu(s.rng, 5e-7, 3e-6), s.rng.uniform(0.2, 0.5), s.rng.uniform(0.05, 0.2)
    f2 = 2 * ((50.0 if s.rng.random() < 0.5 else 60.0) + s.rng.uniform(-0.05, 0.05))
    p = s.rng.uniform(0, 2 * np.pi, 3)
    for r in s.series():
        w = 2 * np.pi * f2 * r.cols["t_s"]
        r.cols["disp_m"] = r.cols["disp_m"] + a * (np.sin(w + p[0]) + h4 * np.sin(2 * w + p[1]) + h6 * np.sin(3 * w + p[2]))


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_loose_connector(s: Session) -> None:
    """A loose banana plug in the drive line, between the amplifier's output (where v_V is monitored) and the strip:
    when the bench is touched or vibrates, its contact resistance R_c jumps to 3-30 ohm (log, per episode) for
    20-500 ms (log), several times a second through spells of 2-20 s (5-10 spells starting inside recorded series).
    The strip loses the voltage across the contact, -R_c i/(1 + R_c/R_hf) (R_hf the strip's series resistance, which
    shares the drop at the edges), and its current and bend follow that deficit through their measured step responses
    (_superpose); v_V never shows it. Measured (paper_91): current residual 1.9 % of its RMS, 7 % of its samples touched
    (0.24 mA RMS there, peaks 3.0 mA); displacement peaks 57 um (11 % touched)."""
    from labrig.physics import transfer

    ps = s.pressures()
    rhf = 1 / abs(transfer.admittance_tf(np.array([2j * np.pi * 1e3]), _preset(s).specimen(ps[len(ps) // 2]))[0])
    eps = _episodes(s, _bursts(s, int(s.rng.integers(5, 11)), (2.0, 20.0)), s.rng.uniform(2.0, 6.0), (0.02, 0.5))
    rc = [lu(s.rng, 3.0, 30.0) for _ in eps]
    e = {}
    for r in s.series():
        t = r.cols["t_s"]
        R = np.zeros(t.size)
        for (a, b), x in zip(eps, rc):
            if b < t[0] or a > t[-1]:
                continue
            R = np.where((t >= a) & (t < b), np.maximum(R, x), R)
        e[id(r)] = -R * r.cols["i_A"] / (1 + R / rhf)
    _superpose(s, e)


def out_current_overload(s: Session) -> None:
    """The current amplifier on a range too sensitive for the strip's charging currents: its output saturates at
    I_sat (0.55-0.85 of the largest sine's peak current, so the fast sines' peaks and every step's edge overload),
    and after the input comes back inside the range the stage stays pinned at its rail for its overload recovery
    time, t_r (1 + ln(peak/I_sat)), t_r 1-10 ms (log): flat, lengthened tops. Current only. Measured (s001_92): current
    RMS -6.6 % (residual 20 %), 8.8 % of the samples touched, peaks 12.5 mA, 20 Hz record residual 33 %."""
    frac, tr = s.rng.uniform(0.55, 0.85), lu(s.rng, 1e-3, 1e-2)
    sines = [r for r in s.series() if r.kind in ("harmonic", "stepped_sine")] or s.series()
    isat = frac * max(float(np.max(np.abs(r.cols["i_A"]))) for r in sines)
    for r in s.series():
        t, i = r.cols["t_s"], r.cols["i_A"].copy()
        over = np.flatnonzero(np.abs(i) > isat)
        runs = np.split(over, np.flatnonzero(np.diff(over) > 1) + 1) if over.size else []
        for run in runs:
            sg, peak = np.sign(i[run[0]]), float(np.max(np.abs(i[run])))
            held = (t >= t[run[0]]) & (t <= t[run[-1]] + tr * (1 + math.log(peak / isat)))
            i[held] = sg * isat
        r.cols["i_A"] = i


def out_heat_haze(s: Session) -> None:
    """Convection plumes steer the laser's beam: a heater (the bath's thermostat, a lamp) sets up rising plumes of
    warmer water (or air) in the beam's path, whose refractive-index gradients (water: -1e-4 per K) bend the beam and
    move the triangulated spot: a random wander of 2-6 um RMS (log) band-limited to 0.03-0.1 to 0.5-3 Hz, strong
    while the heater runs (its on-off cycle: period 300-900 s, on 30-60 %, 20 s build-up) and 0.1-0.3 of it while it
    rests. One wander on the session clock (generated at 50 Hz, interpolated onto the samples). Displacement only.
    Measured (p38_93): displacement residual 1.5 um RMS (3.6x its noise), peaks 7.8 um, 20 Hz record residuals 9-50 %
    (heater off or on)."""
    a, flo, fhi, base = lu(s.rng, 2e-6, 6e-6), s.rng.uniform(0.03, 0.1), s.rng.uniform(0.5, 3.0), s.rng.uniform(0.1, 0.3)
    period, duty, ph = s.rng.uniform(300.0, 900.0), s.rng.uniform(0.3, 0.6), s.rng.uniform(0, 1)
    tg = np.arange(s.t0 - 60.0, s.t1 + 1.0, 0.02)
    x = signal.sosfilt(signal.butter(2, [flo, fhi], "bandpass", fs=50.0, output="sos"), s.rng.normal(size=tg.size))
    x /= np.std(x[3000:])
    k = np.arange(math.floor((s.t0 - 60) / period) - 1, math.ceil(s.t1 / period) + 1)
    on = [((j + ph) * period, (j + ph + duty) * period) for j in k]
    for r in s.series():
        t = r.cols["t_s"]
        env = base + (1 - base) * _ramp_env(t, on, 20.0)
        r.cols["disp_m"] = r.cols["disp_m"] + a * env * np.interp(t, tg, x)


def _frame_bits(kg: float) -> np.ndarray:
    """An indicator's frame "ST,GS,+0012.34kg\\r\\n" as RS-232 line levels, 8N1: a start bit (space), eight data bits
    LSB first, a stop bit (mark); 1 = space (+V), 0 = mark (the idle level)."""
    bits = []
    for ch in f"ST,GS,{kg:+08.2f}kg\r\n".encode():
        bits += [1] + [1 - ((ch >> b) & 1) for b in range(8)] + [0]
    return np.array(bits, float)


def out_serial_crosstalk(s: Session) -> None:
    """The load cell's indicator streams its frames ("ST,GS,+0012.34kg") over RS-232 (+-6-10 V swings) 5-20 times a
    second on its own clock, and its cable shares a ground return with the laser's and the current amplifier's
    analogue inputs: during each frame the line's bit pattern appears on both channels (2-6 um and 5-15 uA per space
    level, log, the signs by wiring), sampled wherever the DAQ's samples fall, nothing between frames. 9600 or 19200
    baud; the frame's digits those of the record's force. Measured (paper_91): 9.5 % of the samples touched (in the
    frames), 3.8 um on the displacement (10x its noise) and 6.9 uA on the current (4x) there."""
    baud, rate = float(s.rng.choice([9600, 19200])), s.rng.uniform(5.0, 20.0)
    kd, ki, ph = lu(s.rng, 2e-6, 6e-6) * _sign(s), lu(s.rng, 5e-6, 1.5e-5) * _sign(s), s.rng.uniform(0, 1)
    for r in s.series():
        t = r.cols["t_s"]
        bits = _frame_bits(float(np.mean(r.cols["force_N"])) / 9.80665 if "force_N" in r.cols else 0.0)
        into = (t * rate - ph) % 1.0 / rate  # time since the last frame started
        k = np.floor(into * baud).astype(int)
        level = np.where(k < bits.size, bits[np.clip(k, 0, bits.size - 1)], 0.0)
        r.cols["disp_m"] = r.cols["disp_m"] + kd * level
        r.cols["i_A"] = r.cols["i_A"] + ki * level


FRESH7_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"cation_exchange": br_cation_exchange, "skin_barrier": br_skin_barrier},
    "faradaic_current": {"poole_frenkel": far_poole_frenkel, "bicarbonate_ce": far_bicarbonate_ce},
    "hysteresis": {"jaw_peel": hy_jaw_peel, "interface_adsorption": hy_interface_adsorption},
    "time_delay": {"mcu_logger": td_mcu_logger, "isolated_monitor": td_isolated_monitor},
    "sensor_offset": {"ghost_spot": so_ghost_spot, "fibre_bend": so_fibre_bend},
    "clamp_relaxation": {"spring_clamp": cr_spring_clamp, "charge_squeeze": cr_charge_squeeze},
    "dehydration": {"osmotic_bath": dh_osmotic_bath, "rewetted_blocks": dh_rewetted_blocks},
    "strain_resistance": {"tunnelling": sr_tunnelling, "reclamp_damage": sr_reclamp_damage},
    "large_deflection": {"angle_rod": ld_angle_rod, "tip_heavy_taper": ld_tip_heavy_taper},
    "mains_pickup": {"body_capacitance": mp_body_capacitance, "transformer_hum": mp_transformer_hum},
    "unexplained": {"loose_connector": out_loose_connector, "current_overload": out_current_overload,
                    "heat_haze": out_heat_haze, "serial_crosstalk": out_serial_crosstalk},
}
inject.register_forms(FRESH7_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def v_eis_descending(s: Session) -> None:
    """A potentiostat's export: every impedance spectrum listed in the order it was swept, from its highest
    frequency down (VersaSTAT-type sweeps run 10 kHz -> 0.1 Hz). The import contract asks f_Hz positive, not
    increasing, and stores the rows as written; the time series untouched."""
    for r in s.recs:
        if not r.series:
            r.cols = {k: x[::-1].copy() for k, x in r.cols.items()}


inject.VARIANTS.update({"eis_descending": v_eis_descending})

# ------------------------------------------------------------------------------------------------ the cases

P91, S92, T93 = "paper_91", "s001_92", "p38_93"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 6 / 7 effect cases on seeds 91 / 92 / 93
    "back_relaxation": [("cation_exchange", 91, P91, "asrun"), ("skin_barrier", 93, T93, "eis_descending")],
    "faradaic_current": [("poole_frenkel", 92, S92, "asrun"), ("bicarbonate_ce", 91, P91, "two_pressures")],
    "hysteresis": [("jaw_peel", 93, T93, "asrun"), ("interface_adsorption", 91, P91, "rate07")],
    "time_delay": [("mcu_logger", 92, S92, "trigger_clock"), ("isolated_monitor", 93, T93, "decimated3")],
    "sensor_offset": [("ghost_spot", 91, P91, "eis_descending"), ("fibre_bend", 92, S92, "no_spectra")],
    "clamp_relaxation": [("spring_clamp", 93, T93, "asrun"), ("charge_squeeze", 91, P91, "float32_time")],
    "dehydration": [("rewetted_blocks", 92, S92, "asrun"), ("osmotic_bath", 93, T93, "eis_descending")],
    "strain_resistance": [("tunnelling", 91, P91, "asrun"), ("reclamp_damage", 92, S92, "shortened_shuffled")],
    "large_deflection": [("angle_rod", 92, S92, "own_clock"), ("tip_heavy_taper", 93, T93, "resampled")],
    "mains_pickup": [("body_capacitance", 91, P91, "dropped_packets"), ("transformer_hum", 93, T93, "steps_sines")],
    "unexplained": [("loose_connector", 91, P91, "asrun"), ("loose_connector", 93, T93, "eis_descending"),
                    ("current_overload", 92, S92, "asrun"), ("current_overload", 91, P91, "decimated3"),
                    ("heat_haze", 93, T93, "asrun"), ("heat_haze", 92, S92, "rate07"),
                    ("serial_crosstalk", 91, P91, "no_spectra"), ("serial_crosstalk", 93, T93, "own_clock")],
}
CLEAN = [(91, P91, "asrun"), (91, P91, "eis_descending"), (92, S92, "asrun"), (92, S92, "eis_descending"),
         (93, T93, "asrun"), (93, T93, "two_pressures")]


def fresh7_cases(only: str | None = None) -> list[Case]:
    """The eighth held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds 91-93)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh7_cases, "inject_fresh7", "fresh7")
