"""An eleventh held-out set for the diagnosis (issue 12), fresh10, written without sight of the diagnosis (its code,
its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh9.py and the simulated
bench (mock_devices/effects.py): some present in part of the session only (a lamp or a nitrogen purge switched on at
a re-clamping, a current range changed), some changing with the clamp pressure (a hardening root, Eyring flow of the
pads, a stepper's back-drive, water squeezed out of the clamped part) or with time (a boiled strip deswelling, a
creeping laser base, a sliding marker, a humidity cycle), some on one channel only, some carrying a memory (a local
pH shift, a training of the coupling's friction, a stick-slip lead, the laser's dynamic filter). Four structures
outside the catalogue (truth "unexplained": the laser read on a DAQ range set too wide, the DAQ driver re-delivering
a buffer, the strip's tip touching the cuvette's wall, the drive amplifier's rail sagging below the command); clean
sessions. All on three bases of new seeds (100-102: the paper strip, the seed-001 strip on its own sweep, the paper
strip 36 mm free) and on the earlier sets' protocol / data-shape variants plus one new here: a rig without a load
cell (no force_N column in any time series: the import contract lists force_N as optional).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh9 are reused (importing inject_fresh9 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import. Strengths are drawn from
the case's seed (uniform unless "log"); each form's docstring ends with the change it made on its case, measured in
memory against the clean base (relative RMS change over all series, form only, no variant; "noise": the column's
sample-to-sample noise at rest, std(diff)/sqrt(2) over the 200 samples before each step record's edge, the median over
the steps: 0.58 um and 42 uA on paper_100, 0.55 um and 10 uA on s001_101, 0.57 um and 42 uA on p36_102).

Run: python bench/inject_fresh10.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np
from scipy import signal, special

import inject
from inject import Case, Rec, Session, lu, map_disp, ref_disp
from inject_fresh2 import _chrono, _drive_side, _map_through, _spec, _through
from inject_fresh3 import _cat, _resist, _sign
from inject_fresh4 import _clamp_law
from inject_fresh6 import _blocks
from inject_fresh7 import _superpose
from inject_fresh8 import _hum, _late
from inject_fresh9 import _dry_by, _gaps, _ou, _session_grid

# the paper's strip 36 mm free (earlier sets used 20, 25, 28, 30, 32, 35, 38, 40, 42 and 45 mm; its 1 V step peaks
# near 12.5 mm, 8.8 mm x (36/30)^2, inside the laser's +-20 mm): registered in every process that imports this module
inject.register_free_length("paper_36", 0.036)

inject.BASES.update({
    "paper_100": ("paper-sweep", "paper", 100),
    "s001_101": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 101),
    "p36_102": ("paper-sweep", "paper_36", 102),
})


# ------------------------------------------------------------------------------------------------ tools


def _reclamps(s: Session) -> list[float]:
    """The blocks' first samples in time order."""
    return sorted(a for a, _ in _blocks(s).values())


def _later_block(s: Session) -> float:
    """The first sample of one block after the first, drawn (the first block's if there is only one)."""
    starts = _reclamps(s)
    return starts[int(s.rng.integers(1, len(starts)))] if len(starts) > 1 else starts[0]


def _lag_varying(s: Session, state: Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]]) -> None:
    """Back relaxation with a gain and a time constant that change with session time, state(t) -> (K2, tau): the
    reading d - K2 x, x a lag of d with time constant tau, sample by sample through the session in time order (the
    state carried over the rests, the displacement linear across them)."""
    x, d_end = 0.0, 0.0
    for r, gap in _gaps(s, 1.0):
        t, d = r.cols["t_s"], r.cols["disp_m"]
        for k, (dt, u) in enumerate(gap):
            tau = float(state(np.array([float(t[0]) - (len(gap) - k - 0.5) * dt]))[1][0])
            x += -math.expm1(-dt / tau) * (d_end + u * (float(d[0]) - d_end) - x)
        K2, tau = state(t)
        out = np.empty(d.size)
        for k, (dk, ak) in enumerate(zip(d.tolist(), np.exp(-1.0 / (r.fs * tau)).tolist())):
            x = dk + (x - dk) * ak
            out[k] = x
        d_end = float(d[-1])
        r.cols["disp_m"] = d - K2 * out


def _station(s: Session, frac: Callable[[Rec], np.ndarray], fa: float) -> None:
    """The reading at a station x_m = f L that moves sample by sample (frac(r): f per sample, fa <= f <= 1): the strip
    read at fa L through the beam's own transfer functions (displacement_tf with sensor_x over the tip's, with the
    session's history, inject_fresh2._through), and each sample interpolated between the tip's reading d and that one
    in (x/L)^2, d + (w_a - d) (1 - f^2)/(1 - fa^2) (exact for the quasi-static uniform curvature)."""
    from labrig.physics import transfer

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        sp = _spec(s, r)
        sa = sp.with_(sensor_x=fa * sp.geometry.length)

        def h(z: np.ndarray) -> np.ndarray:
            with np.errstate(divide="ignore", invalid="ignore"):
                return transfer.displacement_tf(z, sa) / transfer.displacement_tf(z, sp)

        return h

    wa = _through(s, H, 2.0)
    map_disp(s, lambda r, d: d + (wa[id(r)] - d) * (1 - frac(r) ** 2) / (1 - fa**2))


# ------------------------------------------------------------------------------------------------ back relaxation


def br_boiled_history(s: Session) -> None:
    """A strip pretreated the usual way (boiled in water or acid, the expanded form of Nafion, lambda near 20) and
    mounted soon after: at room temperature its clusters deswell towards their room-temperature uptake over hours
    (the membrane's hydrothermal history relaxes), so the free water that flows back falls and the back-flow slows
    through the session: K2 from 1.0-1.4 at the mounting down to 0.35-0.6 of it, tau from 3-8 s (log) to 1.5-2.5x it,
    along exp(-(t + t_m)/t_h) (t_h 600-2000 s, log; the strip mounted t_m 0-300 s before the first record). A lag
    with a time-varying K2 and time constant, sample by sample through the session (inject_fresh10._lag_varying),
    reading d - K2 x. Displacement only. Measured (paper_100): displacement RMS -65 % (residual 95 % of its RMS); the
    1 V steps' peaks -57 to -73 %, the first block's step reversing to -2.3 mm by its plateau's end, the last block's
    still at +2.6 mm there; 20 Hz records' residuals 14-26 %."""
    k2a = s.rng.uniform(1.0, 1.4)
    k2b, ta = k2a * s.rng.uniform(0.35, 0.6), lu(s.rng, 3.0, 8.0)
    tb, th, tm = ta * s.rng.uniform(1.5, 2.5), lu(s.rng, 600.0, 2000.0), s.rng.uniform(0.0, 300.0)

    def state(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        x = np.exp(-np.clip(t - s.t0 + tm, 0, None) / th)
        return k2b + (k2a - k2b) * x, tb * (ta / tb) ** x

    _lag_varying(s, state)


def br_cylinder_channels(s: Session) -> None:
    """Water exchanged with Nafion's parallel cylindrical water channels (the Schmidt-Rohr & Chen picture of the
    membrane's nanostructure) by radial diffusion: the opposing flux follows the bend through the cylinder's uptake
    kernel 2 I1(q)/(q I0(q)), q = sqrt(tau s), tau = a^2/D 15-60 s (log; its mean time tau/8), beside the slab's tanh
    and the sphere's kernels of the earlier sets; K2 0.9-1.3. d - K2 F(s) d through inject_fresh2._through with the
    session's history (120 s). Displacement only. Measured (p36_102): displacement RMS -71 % (residual 111 %), the 1
    V steps' peaks -73 %, reversing to -0.7 mm by the plateau's end (12.5 mm clean), 20 Hz records' residuals 29-41
    %."""
    k2, tau = s.rng.uniform(0.9, 1.3), lu(s.rng, 15.0, 60.0)

    def H(z: np.ndarray) -> np.ndarray:
        q = np.sqrt(tau * np.asarray(z, complex))
        with np.errstate(divide="ignore", invalid="ignore"):
            f = 2 * special.ive(1, q) / (q * special.ive(0, q))
        return 1 - k2 * np.where(np.abs(q) < 1e-6, 1.0, f)

    _map_through(s, lambda r: H, 120.0)


# ------------------------------------------------------------------------------------------------ faradaic current


def far_lamp_arrhenius(s: Session) -> None:
    """Electrolysis (symmetric Butler-Volmer, 2 i0 sinh(v/2v_t), v_t 0.12-0.2 V, 0.08-0.3 mA at 1 V at the room's
    temperature, log) whose exchange current follows the interface's temperature (Arrhenius, E_a 40-60 kJ/mol, the
    hydrogen and oxygen evolutions' on platinum): the operator switches on a microscope illuminator (a halogen lamp)
    to film the strip at a re-clamping after the first (10-60 s before that block's first record), and the bath under
    it warms by 8-20 K along 1 - exp(-t/tau_th) (tau_th 100-300 s, log: a small cuvette close under the lamp), the
    room's temperature before: the same wave at its room-temperature size until the lamp goes on, growing after it.
    The strip's own linear response is taken as unchanged by the warming (the form adds the faradaic branch only).
    Current only. Measured (p36_102, the lamp on before the 4287 kPa block): current residual 1.8 % of its RMS (1.4x
    its noise of 42 uA); the 1 V steps' plateaus +0.120 mA in the first three blocks, +0.149 mA in the last."""
    i1, vt, ea = lu(s.rng, 8e-5, 3e-4), s.rng.uniform(0.12, 0.2), s.rng.uniform(4e4, 6e4)
    dT, tth = s.rng.uniform(8.0, 20.0), lu(s.rng, 100.0, 300.0)
    t_on = _later_block(s) - s.rng.uniform(10.0, 60.0)
    for r in s.series():
        t, v = r.cols["t_s"], r.cols["v_V"]
        T = 298.15 + dT * -np.expm1(-np.clip(t - t_on, 0, None) / tth)
        arr = np.exp(ea / 8.314 * (1 / 298.15 - 1 / T))
        r.cols["i_A"] = r.cols["i_A"] + i1 * arr * np.sinh(v / (2 * vt)) / math.sinh(1 / (2 * vt))


def far_ph_polarisation(s: Session) -> None:
    """Electrolysis whose own products polarise it: water split at the electrodes leaves H+ at the anode and OH- at
    the cathode in their unstirred layers (the thin water film of a strip in air, the boundary layer in a bath), and
    the pH difference builds a Nernst back-voltage E (59 mV per pH unit per face) against the drive; it grows with
    the faradaic charge and relaxes by diffusion over tau_d 5-30 s (log), dE/dt = k i_f - E/tau_d, clipped at +-0.3
    V, the current i_f = 2 i0 sinh((v - E)/2v_t) (v_t 0.1-0.18 V; 0.1-0.4 mA at 1 V from rest, log), k set so that a
    held 1 V would bring E to 0.08-0.2 V. A held step's faradaic current decays as the pH shift builds and recovers
    over the rests; a sine's barely moves it. Sample by sample through the session in time order (E carried over the
    rests, decaying). Current only. Measured (s001_101): current residual 2.3 % of its RMS (6.1x its noise); on every
    1 V step the added current falls from 0.20 mA at the edge to 0.12 mA by the plateau's end."""
    i1, vt, td = lu(s.rng, 1e-4, 4e-4), s.rng.uniform(0.1, 0.18), lu(s.rng, 5.0, 30.0)
    e_hold = s.rng.uniform(0.08, 0.2)
    i0 = i1 / (2 * math.sinh(1 / (2 * vt)))
    k = e_hold / (2 * i0 * math.sinh((1 - e_hold) / (2 * vt)) * td)
    E, t_end = 0.0, None
    for r in _chrono(s):
        t, v = r.cols["t_s"], r.cols["v_V"]
        if t_end is not None:
            E *= math.exp(-max(float(t[0]) - t_end, 0.0) / td)
        dt, out = 1.0 / r.fs, np.empty(v.size)
        for j, x in enumerate(v.tolist()):
            i = 2 * i0 * math.sinh((x - E) / (2 * vt))
            E = min(max(E + dt * (k * i - E / td), -0.3), 0.3)
            out[j] = i
        t_end = float(t[-1])
        r.cols["i_A"] = r.cols["i_A"] + out


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_shakedown(s: Session) -> None:
    """A coupling whose friction is trained by use (shakedown: the pinned cluster domains and the platelets of a
    fresh electrode settle into easier paths with the first cycles after mounting, as a Mullins-like conditioning):
    six plays on the drive, radii evenly to r_max 0.2-0.4 V, a share h 0.2-0.35 of the drive, Gamma = (1 - h) v + h
    mean(plays), each radius shrinking with the drive's accumulated path P (sum abs dv through the session) as r (c +
    (1 - c) exp(-P/P0)), c 0.2-0.4, P0 0.05-0.2 of the session's path: wide loops early, narrow late. Sample by
    sample through the session in time order; through the strip's measured step response (inject_fresh2._drive_side);
    current untouched. Measured (paper_100): displacement residual 4.5 % of its RMS (260x its noise); the first 1 V
    step's peak -4.9 %, the later ones unchanged; the 1 V harmonic's residual 114 um RMS in the first block, 24 um in
    the last; the 20 Hz records' residuals 400-800 % (their 5 um of signal, the play's drift)."""
    h, rmax, c = s.rng.uniform(0.2, 0.35), s.rng.uniform(0.2, 0.4), s.rng.uniform(0.2, 0.4)
    radii = rmax * np.arange(1, 7) / 6
    recs = _chrono(s)
    total = sum(float(np.sum(np.abs(np.diff(r.cols["v_V"])))) + abs(float(r.cols["v_V"][0])) for r in recs)
    p0 = s.rng.uniform(0.05, 0.2) * max(total, 1e-9)
    z, P, v_prev, parts = np.zeros(6), 0.0, 0.0, []
    for r in recs:
        v = r.cols["v_V"]
        out = np.empty(v.size)
        for k, x in enumerate(v.tolist()):
            P += abs(x - v_prev)
            v_prev = x
            rr = radii * (c + (1 - c) * math.exp(-P / p0))
            z = np.minimum(np.maximum(z, x - rr), x + rr)
            out[k] = float(np.mean(z))
        parts.append((1 - h) * v + h * out)
    gam = np.concatenate(parts)
    _drive_side(s, lambda v: gam)


def hy_stick_slip_lead(s: Session) -> None:
    """A fine lead tacked to the electrode near the tip (a thermocouple's, or a sense lead for a four-wire resistance
    measurement) drapes over the cuvette's rim and drags on it with static and kinetic friction (F_s, F_k 0.3-0.7
    F_s): the lead acts on the tip as a spring (a share r 0.03-0.1 of the tip's stiffness) to a point on the rim that
    sticks until the spring's pull exceeds F_s (in tip units 0.2-0.5 of the displacement scale), then slips until it
    pulls F_k: the tip reads y = (1 - r) d + r x, x the lead's point on the rim, a play-like loop with jumps (a
    stick-slip sawtooth on slow ramps). Sample by sample through the session in time order (x held over the rests).
    Displacement only (the lead carries no drive current). Measured (s001_101): displacement residual 0.7 % of its
    RMS (24x its noise), the 1 V steps' peaks -0.2 to -0.4 %, slips up to 27 um, the 20 Hz records' residuals 21-44
    %."""
    r_, fs_ = s.rng.uniform(0.03, 0.1), s.rng.uniform(0.2, 0.5) * ref_disp(s)
    fk = s.rng.uniform(0.3, 0.7) * fs_
    x = 0.0
    for r in _chrono(s):
        d = r.cols["disp_m"]
        out = np.empty(d.size)
        for k, dk in enumerate(d.tolist()):
            y = (1 - r_) * dk + r_ * x
            if abs(y - x) > fs_:
                x = dk - math.copysign(fk, y - x) / (1 - r_)
                y = (1 - r_) * dk + r_ * x
            out[k] = y
        r.cols["disp_m"] = out


# ------------------------------------------------------------------------------------------------ time delay


def td_auto_exposure(s: Session) -> None:
    """The triangulation laser's automatic exposure: the return from the plated surface falls as the tip tilts (cos^k
    of the tip's angle 2d/L on the arc, k 3-8) and the controller lengthens its exposure to keep the spot's peak, t_e
    = t_e0/cos^k (t_e0 2-8 ms at rest, log; capped at 15-40 ms), and each reading is the centroid of its exposure: a
    delay t_e/2 that grows with the bend (a few ms at rest, several times that at the steps' peaks). Through
    inject_fresh8._late; displacement only. Measured (p36_102): delay 2.6 ms at rest, 11.8 ms at the 1 V steps'
    peaks; displacement residual 0.07 % of its RMS (5.7x its noise), the 20 Hz records' residuals 17-18 %."""
    te0, k, cap = lu(s.rng, 2e-3, 8e-3), s.rng.uniform(3.0, 8.0), s.rng.uniform(15e-3, 40e-3)
    L = float(s.specimen["length_m"])
    _late(s, lambda r, t: 0.5 * np.minimum(te0 / np.cos(np.clip(2 * r.cols["disp_m"] / L, -1.2, 1.2)) ** k, cap))


def td_dynamic_filter(s: Session) -> None:
    """The laser controller's "dynamic" averaging (an adaptive recursive filter, as indicators and laser controllers
    offer to quieten the reading at rest without slowing big moves): y += (x - y)(1 - exp(-dt/tau)), tau = tau_slow
    (20-80 ms, log) while abs(x - y) stays inside a band (5-30 um, log), tau_fast (1-4 ms, log) beyond it: a long
    delay on slow, small motions and at rest (less noise), a short one on large fast moves, and a lag that switches
    within a cycle on the mid-sized sines. Sample by sample through the session in time order (the state carried over
    the rests). Displacement only. Measured (paper_100): displacement residual 0.24 % of its RMS (14x its noise), the
    sample-to-sample noise at rest down to 0.03 of itself, the 20 Hz records' (5 um) residuals 56-68 %."""
    ts, tf, band = lu(s.rng, 0.02, 0.08), lu(s.rng, 1e-3, 4e-3), lu(s.rng, 5e-6, 3e-5)
    y, t_end, x_end = None, 0.0, 0.0
    for r in _chrono(s):
        d, t = r.cols["disp_m"], r.cols["t_s"]
        if y is None:
            y = float(d[0])
        else:
            y = float(d[0]) + (y - x_end) * math.exp(-max(float(t[0]) - t_end, 0.0) / ts)
        a_s, a_f = -math.expm1(-1.0 / (r.fs * ts)), -math.expm1(-1.0 / (r.fs * tf))
        out = np.empty(d.size)
        for k, x in enumerate(d.tolist()):
            e = x - y
            y += e * (a_s if abs(e) < band else a_f)
            out[k] = y
        t_end, x_end = float(t[-1]), float(d[-1])
        r.cols["disp_m"] = out


# ------------------------------------------------------------------------------------------------ sensor offset


def so_creeping_base(s: Session) -> None:
    """The laser on a magnetic base (or a tripod's head) re-aimed at the tip at every re-clamping (5-20 s before each
    block's first record), then settling: its spot walks inboard along the strip by 5-15 % of L (the head's lever on
    a base that creeps by a fraction of a degree) along 1 - exp(-u/tau) (tau 60-400 s, log) from each re-aim: a
    sawtooth of the station, at the tip at each block's start, inboard by its end. Read through the strip's own
    transfer functions at the station (inject_fresh10._station); displacement only. Measured (s001_101): displacement
    RMS -8.5 % (residual 9.2 %), the 1 V steps' peaks -9.1, -8.9, -8.9, -7.4 % block by block, the 20 Hz records'
    residuals 18 %."""
    dlt, tau = s.rng.uniform(0.05, 0.15), lu(s.rng, 60.0, 400.0)
    aims = {p: a - s.rng.uniform(5.0, 20.0) for p, (a, _) in _blocks(s).items()}
    def frac(r: Rec) -> np.ndarray:
        u = np.clip(r.cols["t_s"] - aims[float(r.entry["pressure_kPa"])], 0, None)
        return 1 - dlt * -np.expm1(-u / tau)

    _station(s, frac, 1 - dlt)


def so_sliding_marker(s: Session) -> None:
    """Video tracking of a foil marker stuck at the tip of a wet strip: the adhesive softens in water and the marker
    slides inboard along the strip whenever the strip moves fast enough for the water's drag on it to pass the
    softened adhesive's yield (the tip's speed, smoothed over 20 ms, above 0.3-0.6 of the session's fastest), at a
    rate growing with the excess: the station falls in jerks at the steps' edges and the fast sines, 5-15 % of L by
    the session's end, and stays. Read through the strip's own transfer functions at the station
    (inject_fresh10._station); displacement only. Measured (paper_100): displacement RMS -8.5 % (residual 11 %), the
    1 V steps' peaks -0.2, -6.3, -11, -17 % block by block, the 20 Hz records' residuals 11-39 %."""
    total, q = s.rng.uniform(0.05, 0.15), s.rng.uniform(0.3, 0.6)
    recs = _chrono(s)
    speed = []
    for r in recs:
        a = math.exp(-1.0 / (r.fs * 0.02))
        y = signal.lfilter([1 - a], [1.0, -a], r.cols["disp_m"] - r.cols["disp_m"][0])
        speed.append(np.abs(np.gradient(y, r.cols["t_s"])))
    vmax = max(float(np.max(v)) for v in speed) or 1.0
    dt = [np.full(r.cols["t_s"].size, 1.0 / r.fs) for r in recs]
    rate = np.concatenate([np.clip(v / vmax - q, 0, None) * w for v, w in zip(speed, dt)])
    cum = np.cumsum(rate)
    cum = cum / max(float(cum[-1]), 1e-30)
    f = dict(zip([id(r) for r in recs], np.split(1 - total * cum, np.cumsum([r.cols["t_s"].size for r in recs])[:-1])))
    _station(s, lambda r: f[id(r)], 1 - total)


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_eyring_flow(s: Session) -> None:
    """The pads relax by stress-activated (Eyring) flow under the held gap: d sigma/dt = -(sigma0/tau) sinh(sigma/
    sigma0), closed form tanh(sigma/2 sigma0) = tanh(sigma_i/2 sigma0) exp(-t/tau), from each block's setting sigma_i
    (its pressure). The activation stress sigma0 is 0.15-0.3 of the session's highest pressure, and tau is set so the
    highest block loses 8-15 % over the session's median block length: the rate grows as sinh with the pressure, so
    the low blocks relax by a percent or two and the high ones fast at first, then slowly (log-like). Through the
    preset's clamp law (inject_fresh4._clamp_law). Measured (p36_102): load cell down to 0.96, 0.95, 0.92, 0.88 of
    its setting by the blocks' ends; current residual 0.6 % (0.5x its noise), displacement 0.11 % (9x), the 4287 kPa
    block's 20 Hz record residual 17 %."""
    ps = s.pressures()
    s0 = s.rng.uniform(0.15, 0.3) * ps[-1]
    r_hi = s.rng.uniform(0.08, 0.15)
    T = float(np.median([b - a for a, b in _blocks(s).values()])) or 1.0
    u0 = ps[-1] / s0
    tau = -T / math.log(math.tanh(u0 * (1 - r_hi) / 2) / math.tanh(u0 / 2))

    def rel(t: np.ndarray, p: float, t_set: float) -> np.ndarray:
        u = np.clip(t - t_set, 0, None) / tau
        return 2 * s0 * np.arctanh(math.tanh(p / (2 * s0)) * np.exp(-u)) / p

    _clamp_law(s, rel)


def cr_microstep_backdrive(s: Session) -> None:
    """A motorised clamp whose stepper drops to a reduced holding current after the servo hold: the pads' force
    back-drives the lead screw whenever its torque beats the motor's detent plus the thread's friction, one microstep
    at a time (each the same gap, so the same force drop, 1-2 % of the session's highest setting), at a rate growing
    with the excess, lambda0 (F - F_d)/F_d (lambda0 0.005-0.02 per second, log), until the force is down to F_d
    (0.4-0.7 of the way from the lowest setting to the highest), the first step 1-5 s after the hold (the rotor
    falling back into the detent under load as its current drops): a staircase of equal steps, steep at the high
    pressures, none below F_d. Event times drawn per block from its setting; through the preset's clamp law
    (inject_fresh4._clamp_law). Measured (paper_100): the 612 and 1837 kPa blocks untouched (below F_d), the load
    cell down to 0.88 and 0.76 of its setting by the ends of the 3062 and 4287 kPa blocks; displacement residual 0.16
    % (10x its noise), the 4287 kPa block's 20 Hz record residual 37 %, current 0.9 % (0.7x)."""
    ps = s.pressures()
    dp = s.rng.uniform(0.01, 0.02) * ps[-1]
    fd = ps[0] + (ps[-1] - ps[0]) * s.rng.uniform(0.4, 0.7)
    lam0 = lu(s.rng, 0.005, 0.02)
    events: dict[float, np.ndarray] = {}
    for p, (a, b) in sorted(_blocks(s).items()):
        t, F, ev = s.rng.uniform(1.0, 5.0), p, []
        while F - dp > fd:
            if ev:
                t += s.rng.exponential(1.0 / (lam0 * (F - fd) / fd))
            if t > b - a + 60.0:
                break
            ev.append(t)
            F -= dp
        events[p] = np.array(ev)

    def rel(t: np.ndarray, p: float, t_set: float) -> np.ndarray:
        n = np.searchsorted(events[p], t - t_set, side="right")
        return 1 - n * dp / p

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def _lambda(a: np.ndarray) -> np.ndarray:
    """Nafion's water uptake (water per sulfonate) against the relative humidity a (Zawodzinski et al. 1993, 30 C)."""
    return 0.043 + 17.81 * a - 39.85 * a**2 + 36.0 * a**3


def dh_nitrogen_purge(s: Session) -> None:
    """A strip in air in an enclosure the operator starts purging with dry nitrogen (to stop the room's humidity
    wandering) at a re-clamping after the first: the relative humidity falls from 0.4-0.6 to 0.05-0.2 along the
    enclosure's flush, exp(-u/tau_p) (tau_p 200-800 s, log), and the strip's water follows Nafion's sorption isotherm
    (Zawodzinski's cubic lambda(a): flat in the middle, steep at low humidity) with the membrane's lag tau_d 60-300 s
    (log): a slow start, then a steep loss. Gain x (1 - k_d (1 - lambda/lambda_0)), k_d 0.2-0.4, conductance x (1 -
    k_c (...)), k_c 0.1-0.3, the spectra following (inject_fresh9._dry_by); nothing before the purge. Measured
    (s001_101, purged before the 900 kPa block): displacement RMS -8.0 % (residual 12 %), the 1 V steps' peaks 0.0,
    -0.3, -15, -18 % block by block; current -4.4 % (15x its noise); impedance at 0.1 Hz 1.07-1.08x in the last two
    blocks."""
    a0, a1 = s.rng.uniform(0.4, 0.6), s.rng.uniform(0.05, 0.2)
    tp, td = lu(s.rng, 200.0, 800.0), lu(s.rng, 60.0, 300.0)
    kd, kc = s.rng.uniform(0.2, 0.4), s.rng.uniform(0.1, 0.3)
    t_on = _later_block(s) - s.rng.uniform(10.0, 60.0)
    tg = _session_grid(s, 1.0, 10.0)
    a = a1 + (a0 - a1) * np.exp(-np.clip(tg - t_on, 0, None) / tp)
    lam0 = float(_lambda(np.array([a0]))[0])
    w = np.exp(-1.0 / td)
    lam = np.empty(tg.size)
    lam[0] = lam0
    eq = _lambda(a)
    for k in range(1, tg.size):
        lam[k] = eq[k] + (lam[k - 1] - eq[k]) * w
    loss = 1 - lam / lam0
    _dry_by(s, lambda t: kd * np.interp(t, tg, loss), lambda t: kc * np.interp(t, tg, loss))


def dh_squeeze_rewet(s: Session) -> None:
    """A strip in air drying steadily (10-25 % of its mobile water by the session's end, 1 - exp(-t/tau), tau
    1500-4000 s, log), while each re-clamping at a higher pressure squeezes water out of the clamped part, part of it
    into the free strip at its root, where it counts most: each block after the first starts re-wetted by w (ln p_k -
    ln p_(k-1))/ln(p_max/p_min) (w 0.04-0.1 of the mobile water) that evaporates again over tau_e 100-400 s (log): a
    drying trend with a rise at each re-clamping, largest at the largest pressure step. Gain x (1 - loss),
    conductance x (1 - c loss), c 0.4-0.9, the spectra following (inject_fresh9._dry_by). Measured (s001_101):
    displacement RMS -7.6 % (residual 9.3 %), the 1 V steps' peaks -0.2, -5.9, -11, -14 % block by block (each step
    well after its block's re-wetting has evaporated again); current -6.9 % (20x its noise); impedance at 0.1 Hz
    1.03-1.09x."""
    tot, tau = s.rng.uniform(0.1, 0.25), lu(s.rng, 1500.0, 4000.0)
    w, te, c = s.rng.uniform(0.04, 0.1), lu(s.rng, 100.0, 400.0), s.rng.uniform(0.4, 0.9)
    blocks = sorted(_blocks(s).items(), key=lambda kv: kv[1][0])
    ps = s.pressures()
    span = math.log(ps[-1] / ps[0]) if ps[-1] > ps[0] else 1.0
    kicks = [(a - 5.0, w * max(math.log(p / q), 0.0) / span) for (q, _), (p, (a, _)) in zip(blocks, blocks[1:])]
    end = -math.expm1(-(s.t1 - s.t0) / tau)

    def loss(t: np.ndarray) -> np.ndarray:
        x = tot * -np.expm1(-np.clip(t - s.t0, 0, None) / tau) / end
        for tk, wk in kicks:
            x = x - wk * np.where(t > tk, np.exp(-np.clip(t - tk, 0, None) / te), 0.0)
        return x

    _dry_by(s, loss, lambda t: c * loss(t))


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_compression_buckling(s: Session) -> None:
    """The compressed face's electrode: a stiff platinum film on a soft swollen polymer wrinkles and its platelets
    lift off (buckle-delamination) once the compressive strain passes a critical one (the bend beyond 0.35-0.65 of
    the session's largest on that side), the lifted platelets losing contact: dR/R ~ (excess)^1.5, and part of the
    delamination stays (a share m 0.3-0.6 follows the running largest excess, through the session in time order). The
    earlier sets' cracking acts on the tensioned face; here the concave one (side drawn), the other face untouched.
    Gains fall by 0.02-0.06 (displacement), 0.05-0.15 (current) per unit of dR/R (inject_fresh3._resist). Measured
    (paper_100): displacement RMS -0.9 % (residual 1.0 %, 57x its noise), the 1 V steps' peaks 0.0 % in the first
    block and -1.1 % in the later ones (the delamination kept), current residual 2.0 % (1.5x its noise)."""
    side, ec, m = _sign(s), s.rng.uniform(0.35, 0.65), s.rng.uniform(0.3, 0.6)
    recs, e, cuts = _cat(s, "disp_m")
    comp = np.clip(-side * e, 0, None) / max(float(np.max(-side * e)), 1e-12)
    ex = np.clip(comp - ec, 0, None) / (1 - ec)
    g = (1 - m) * ex**1.5 + m * np.maximum.accumulate(ex) ** 1.5
    fac = dict(zip([id(r) for r in recs], np.split(g, cuts)))
    _resist(s, lambda r, x: fac[id(r)], (0.02, 0.06), (0.05, 0.15))


def sr_humidity_gauge(s: Session) -> None:
    """A strip in air whose tensioned electrode's cracks are bridged by the hydrated polymer's surface layer, an
    ionic path in parallel with the cracks: the room's air conditioning cycles the relative humidity (a triangle of
    +-5-15 % RH, period 600-1800 s), and the bridges' conductance follows it within seconds (the bulk's water hardly
    moves in that time), so the electrode's strain sensitivity breathes with the room: dR/R = (1 + g u(t)) (e+ + o
    e-), u the cycle (-1 to 1, dry positive), g 0.4-0.8, o 0.1-0.3 (the other face), one side (drawn) in tension.
    Gains fall by 0.02-0.06 (displacement), 0.05-0.15 (current) per unit (inject_fresh3._resist). Measured
    (s001_101): displacement RMS -2.4 % (residual 2.6 %), the 1 V steps' peaks -4.0, -3.0, -2.1, -4.6 % as the cycle
    goes, current residual 1.9 % (5.1x its noise)."""
    side, g, o = _sign(s), s.rng.uniform(0.4, 0.8), s.rng.uniform(0.1, 0.3)
    period, ph = s.rng.uniform(600.0, 1800.0), s.rng.uniform(0, 1)

    def shape(r: Rec, x: np.ndarray) -> np.ndarray:
        u = 4 * np.abs(((r.cols["t_s"] - s.t0) / period + ph) % 1.0 - 0.5) - 1
        return (1 + g * u) * (np.clip(side * x, 0, None) + o * np.clip(-side * x, 0, None))

    _resist(s, shape, (0.02, 0.06), (0.05, 0.15))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_root_hardening(s: Session) -> None:
    """The strip's root rotates in the compliant pads, and the pads' edge stiffens as it is pressed (the contact
    spreads under the jaw's edge: a hardening rotational spring, M = k phi (1 + (phi/phi_h)^2)): the root's share of
    the tip's motion, linear at small bends (the clamp law's own compliance), saturates at large ones. In tip units,
    the linear share u = c d, and the hardened one x solving x + x^3/u_h^2 = u (Cardano); the reading d - u + x. The
    share c falls with the clamp pressure, c_min (p_min/p)^m (c_min 0.1-0.25, m 0.5-1: a firm clamp lets the root
    turn less), u_h 0.5-1.5 of the displacement scale: a compressed top of the large steps, strongest in the lowest
    block. Displacement only. Measured (p36_102): the 1 V steps' peaks -4.1, -1.1, -0.5, -0.3 % block by block,
    displacement RMS -1.0 % (residual 1.5 %, 126x its noise)."""
    cmin, m, uh = s.rng.uniform(0.1, 0.25), s.rng.uniform(0.5, 1.0), s.rng.uniform(0.5, 1.5) * ref_disp(s)
    pmin = min(s.pressures())

    def read(r: Rec, d: np.ndarray) -> np.ndarray:
        u = cmin * (pmin / float(r.entry["pressure_kPa"])) ** m * d
        q = -(uh**2) * u
        root = np.sqrt(q**2 / 4 + uh**6 / 27)
        x = np.cbrt(-q / 2 + root) + np.cbrt(-q / 2 - root)
        return d - u + x

    map_disp(s, read)


def ld_capacitive_tilt(s: Session) -> None:
    """No laser: a capacitive displacement probe (for a strip in air) facing the strip near its tip, at a gap g0
    1.4-2x the session's largest bend on the side it faces (drawn), calibrated on a parallel target. The bent strip's
    tip is tilted under the probe by theta = 2d/L, and a tilted target's capacitance over the probe's radius R
    (1.5-3.5 mm) is that of a wedge, C ~ (A/g) (1/(2t)) ln((1 + t)/(1 - t)), t = R tan(theta)/g: the probe reads a
    gap smaller than the true one by g (1 - 2t/ln((1+t)/(1-t))) ~ g t^2/3: even in the tilt, largest where the strip
    comes close to the probe, so the two directions of bend read differently at large bends. Displacement only.
    Measured (s001_101, the probe on the side the steps bend away from): the 1 V steps' peaks -1.5 to -1.6 %,
    displacement RMS -1.3 % (residual 1.3 %, 43x its noise)."""
    side, R = _sign(s), s.rng.uniform(1.5e-3, 3.5e-3)
    L = float(s.specimen["length_m"])
    top = max(float(np.max(side * r.cols["disp_m"])) for r in s.series())
    g0 = max(top, 1e-4) * s.rng.uniform(1.4, 2.0)

    def read(r: Rec, d: np.ndarray) -> np.ndarray:
        g = g0 - side * d
        t = np.clip(R * np.abs(np.tan(np.clip(2 * d / L, -1.2, 1.2))) / g, 1e-9, 0.95)
        geff = g * 2 * t / np.log((1 + t) / (1 - t))
        return d + side * (g - geff)

    map_disp(s, read)


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_range_hum(s: Session) -> None:
    """Hum picked up on the cable from the current amplifier's output to the DAQ (50 or 60 Hz +- 0.05, 3rd harmonic
    0.1-0.3, phase locked to the session clock; a fraction of a millivolt on the line), which the recording scales by
    the amplifier's range: at a re-clamping after the first the operator switches to a less sensitive range (x2, x5
    or x10 the amperes per volt, the 1-2-5 steps) to keep the higher pressures' charging spikes on scale, so the hum
    in amperes jumps by that factor from that block on (2-6 uA before it, log). Current only. Measured (paper_100,
    switched x2 before the 1837 kPa block): 2.4 uA RMS in the first block, 4.7 uA after it (0.06-0.1x the current's
    noise: a narrow line)."""
    a1 = lu(s.rng, 2e-6, 6e-6)
    fac = float(s.rng.choice([2.0, 5.0, 10.0]))
    f = (50.0 if s.rng.random() < 0.5 else 60.0) + s.rng.uniform(-0.05, 0.05)
    h3, ph = s.rng.uniform(0.1, 0.3), s.rng.uniform(0, 2 * np.pi)
    t_sw = _later_block(s) - 1.0
    for r in s.series():
        t = r.cols["t_s"]
        r.cols["i_A"] = r.cols["i_A"] + a1 * np.where(t > t_sw, fac, 1.0) * _hum(t, f, {3: h3}, ph)


def mp_ups_beat(s: Session) -> None:
    """The laser controller runs from an online (double-conversion) UPS whose inverter makes its own 50 or 60 Hz from
    a crystal (+-0.01 Hz), while the grid beside the bench runs 0.02-0.1 Hz off nominal (either way; a slow wander of
    +-5 mHz): the displacement carries both, the controller's supply-borne line (1-4 um, log) and the grid's field
    (1-4 um, log), beating at their difference (a 10-50 s envelope), and the current amplifier, on the grid, only the
    grid's line (2-8 uA, log, 3rd harmonic 0.1-0.3). Phase locked to the session clock. Measured (p36_102):
    displacement 1.6 um RMS (2.8x its noise), its envelope between 0.3 and 3.2 um on the 1 V harmonic; current 2.4 uA
    RMS (0.06x)."""
    nom = 50.0 if s.rng.random() < 0.5 else 60.0
    fu = nom + s.rng.uniform(-0.01, 0.01)
    fg = nom + _sign(s) * s.rng.uniform(0.02, 0.1)
    au, ag, ai = lu(s.rng, 1e-6, 4e-6), lu(s.rng, 1e-6, 4e-6), lu(s.rng, 2e-6, 8e-6)
    h3, pu, pg = s.rng.uniform(0.1, 0.3), s.rng.uniform(0, 2 * np.pi), s.rng.uniform(0, 2 * np.pi)
    tg = _session_grid(s, 1.0, 10.0)
    wander = 0.005 * _ou(s, tg, 120.0) / 2
    phase = 2 * np.pi * np.r_[0.0, np.cumsum(0.5 * (wander[1:] + wander[:-1]) * np.diff(tg))]
    for r in s.series():
        t = r.cols["t_s"]
        pgt = pg + np.interp(t, tg, phase)
        grid = np.cos(2 * np.pi * fg * t + pgt)
        r.cols["disp_m"] = r.cols["disp_m"] + au * np.cos(2 * np.pi * fu * t + pu) + ag * grid
        r.cols["i_A"] = r.cols["i_A"] + ai * (grid + h3 * np.cos(3 * (2 * np.pi * fg * t + pgt)))


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_coarse_range(s: Session) -> None:
    """The laser's analogue output read on a DAQ input range set far too wide (the +-10 V range of a 12-bit card, or
    a 16-bit card's range with a gain left at 1 for a millivolt-level output): each reading is rounded to the
    converter's step, 5-20 um of displacement (log), about an offset within one step (drawn): a staircase with no
    dither (the signal's noise is far below the step). Displacement only. Measured (paper_100): a 14 um step,
    residual 2.0 um RMS (3.4x its noise), the 20 Hz records' residuals 31-35 %; (s001_101): a 6.2 um step, 4.1 um
    (7.5x), 20 Hz residuals 17-22 %."""
    lsb, off = lu(s.rng, 5e-6, 2e-5), s.rng.uniform(0, 1)
    map_disp(s, lambda r, d: (np.round(d / lsb - off) + off) * lsb)


def out_repeated_buffers(s: Session) -> None:
    """The DAQ driver re-delivers a buffer now and then (a buffer overwritten before the host read it, the previous
    one handed out again under the new samples' time stamps): 2-6 times in the session, in a record long enough, a
    block of 64-512 samples (a power of two, the driver's buffer) of every DAQ channel (the voltage, the current and
    the laser; the load cell is its own stream) replaced by a copy of the block before it. Measured (s001_101):
    blocks of 512 samples in five stepped-sine records (0.1-0.3 Hz), 1 % of the samples: displacement residual 2.3 %
    of its RMS, current 11 %; (p36_102): blocks of 64 in six records, displacement 0.09 %, current 8 % (a step's
    charging spike re-delivered)."""
    n = int(2 ** s.rng.integers(6, 10))
    ser = [r for r in s.series() if r.cols["t_s"].size >= 4 * n]
    if not ser:
        return
    for _ in range(int(s.rng.integers(2, 7))):
        r = ser[int(s.rng.integers(0, len(ser)))]
        k = n * int(s.rng.integers(1, r.cols["t_s"].size // n))
        k = min(k, r.cols["t_s"].size - n)
        for col in ("v_V", "i_A", "disp_m"):
            x = r.cols[col].copy()
            x[k:k + n] = x[k - n:k]
            r.cols[col] = x


def out_wall_contact(s: Session) -> None:
    """The strip in a narrow cuvette with its tip closer to a wall on one side (drawn) than its largest bends reach
    (at 0.45-0.8 of the session's largest bend on that side, where the strip was put in the cuvette): at large bends
    the tip touches the glass and stays there while the rest of the strip bows further (the reading moves on at k_c
    0.05-0.2 of the free motion), and the water film between tip and wall (a squeeze film, or a meniscus in air)
    holds it until the free motion has pulled back by 0.1-0.3 of the wall's distance, when it lets go at once: a soft
    one-sided stop with an adhesive release. Sample by sample through the session in time order. Displacement only
    (the glass carries no current). Measured (p36_102): the 1 V steps' plateaus held at 10.0 mm (-20 %), displacement
    RMS -5.4 %, 12 % of the samples touched; (paper_100, the wall on the side the steps bend away from): six records
    touched (3 % of the samples), 0.35 mm RMS there."""
    side = _sign(s)
    dw = s.rng.uniform(0.45, 0.8) * max(max(float(np.max(side * r.cols["disp_m"])) for r in s.series()), 1e-9)
    kc, rel = s.rng.uniform(0.05, 0.2), s.rng.uniform(0.1, 0.3) * dw
    stuck = False
    for r in _chrono(s):
        d = side * r.cols["disp_m"]
        out = np.empty(d.size)
        for k, x in enumerate(d.tolist()):
            if not stuck and x >= dw:
                stuck = True
            elif stuck and x < dw - rel:
                stuck = False
            out[k] = dw + (x - dw) * kc if stuck else x
        r.cols["disp_m"] = side * out


def out_rail_sag(s: Session) -> None:
    """The drive amplifier runs from a battery pack (a portable rig) or a bench supply creeping into its current
    limit: its output's swing sags through the session, from 1.3-1.6 V at the start to 0.8-0.95 V at the end (linear
    in time), and beyond it the output clips (a soft knee of 20-50 mV), while the DAQ records the command (v_V knows
    nothing of it). The strip answers the clipped drive: its difference from the command reaches the current and the
    displacement through the strip's measured step responses (inject_fresh7._superpose). The 1 V records pass
    untouched early and lose their tops late. Measured (paper_100): the 1 V steps' peaks -1.2 % in the 3062 kPa block
    and -8.9 % in the 4287 kPa one, their edges' current spikes cut by 0.2 and 1.6 mA; displacement residual 4.1 %,
    current 1.4 % of their RMS; (s001_101): the last block's step -4.9 %."""
    v0, v1, knee = s.rng.uniform(1.3, 1.6), s.rng.uniform(0.8, 0.95), s.rng.uniform(0.02, 0.05)
    e = {}
    for r in s.series():
        v = r.cols["v_V"]
        rail = v0 + (v1 - v0) * (r.cols["t_s"] - s.t0) / max(s.t1 - s.t0, 1e-9)
        over = np.abs(v) - rail
        cut = np.where(over > -4 * knee, knee * np.logaddexp(0.0, over / knee), 0.0)  # the excess beyond the knee
        e[id(r)] = -np.sign(v) * cut
    _superpose(s, e)


FRESH10_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"boiled_history": br_boiled_history, "cylinder_channels": br_cylinder_channels},
    "faradaic_current": {"lamp_arrhenius": far_lamp_arrhenius, "ph_polarisation": far_ph_polarisation},
    "hysteresis": {"shakedown": hy_shakedown, "stick_slip_lead": hy_stick_slip_lead},
    "time_delay": {"auto_exposure": td_auto_exposure, "dynamic_filter": td_dynamic_filter},
    "sensor_offset": {"creeping_base": so_creeping_base, "sliding_marker": so_sliding_marker},
    "clamp_relaxation": {"eyring_flow": cr_eyring_flow, "microstep_backdrive": cr_microstep_backdrive},
    "dehydration": {"nitrogen_purge": dh_nitrogen_purge, "squeeze_rewet": dh_squeeze_rewet},
    "strain_resistance": {"compression_buckling": sr_compression_buckling, "humidity_gauge": sr_humidity_gauge},
    "large_deflection": {"root_hardening": ld_root_hardening, "capacitive_tilt": ld_capacitive_tilt},
    "mains_pickup": {"range_hum": mp_range_hum, "ups_beat": mp_ups_beat},
    "unexplained": {"coarse_range": out_coarse_range, "repeated_buffers": out_repeated_buffers,
                    "wall_contact": out_wall_contact, "rail_sag": out_rail_sag},
}
inject.register_forms(FRESH10_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def v_no_loadcell(s: Session) -> None:
    """A rig without a load cell (the clamp set by a torque screwdriver or a calibrated spring, its pressure written
    in the manifest): no force_N column in any time series. The import contract lists force_N as optional; the other
    columns, the rows and the spectra untouched."""
    for r in s.series():
        r.cols.pop("force_N", None)


inject.VARIANTS.update({"no_loadcell": v_no_loadcell})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_100", "s001_101", "p36_102"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 7 / 6 effect cases on seeds 100-102
    "back_relaxation": [("boiled_history", 100, P, "asrun"), ("cylinder_channels", 102, T, "no_loadcell")],
    "faradaic_current": [("lamp_arrhenius", 102, T, "asrun"), ("ph_polarisation", 101, S, "eis_descending")],
    "hysteresis": [("shakedown", 100, P, "rate07"), ("stick_slip_lead", 101, S, "asrun")],
    "time_delay": [("auto_exposure", 102, T, "host_timed"), ("dynamic_filter", 100, P, "asrun")],
    "sensor_offset": [("creeping_base", 101, S, "two_pressures"), ("sliding_marker", 100, P, "asrun")],
    "clamp_relaxation": [("eyring_flow", 102, T, "asrun"), ("microstep_backdrive", 100, P, "merged_loadcell")],
    "dehydration": [("nitrogen_purge", 101, S, "asrun"), ("squeeze_rewet", 101, S, "decimated3")],
    "strain_resistance": [("compression_buckling", 100, P, "dropped_packets"),
                          ("humidity_gauge", 101, S, "no_loadcell")],
    "large_deflection": [("root_hardening", 102, T, "float32_time"), ("capacitive_tilt", 101, S, "asrun")],
    "mains_pickup": [("range_hum", 100, P, "no_spectra"), ("ups_beat", 102, T, "resampled")],
    "unexplained": [("coarse_range", 100, P, "asrun"), ("coarse_range", 101, S, "own_clock"),
                    ("repeated_buffers", 101, S, "asrun"), ("repeated_buffers", 102, T, "shortened_shuffled"),
                    ("wall_contact", 102, T, "asrun"), ("wall_contact", 100, P, "steps_sines"),
                    ("rail_sag", 100, P, "no_loadcell"), ("rail_sag", 101, S, "trigger_clock")],
}
CLEAN = [(100, P, "asrun"), (100, P, "no_loadcell"), (101, S, "asrun"), (101, S, "merged_loadcell"),
         (102, T, "asrun"), (102, T, "no_loadcell")]


def fresh10_cases(only: str | None = None) -> list[Case]:
    """The eleventh held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds
    100-102)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh10_cases, "inject_fresh10", "fresh10")
