"""A twenty-third held-out set for the diagnosis (issue 12), fresh22, written without sight of the diagnosis (its code,
its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh21.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (the ionic current's drag holding the
back-flow while it flows, hydrogen evolution through an adsorbed intermediate whose coverage relaxes faster the harder
it is driven, a titanium screw forming its anodic oxide like a valve metal, a controller's analogue output updated only
on a change larger than its dead band, platinum oxide's surface stress forming and stripping on each face at its own
potentials, overlapping electrode flakes whose contacts part in tension and press in compression, ionomer gel creeping
into the opened cracks, a coil-on-board inductive track whose copper target runs off its ends, a bi-cell detector whose
disc spot leaves its split), some on the history or on the clamp pressure (an AC solenoid clamp whose hum follows the
coil current set for each pressure, two-layer pads whose soft layer bottoms out above a pressure), some on time (a
nylon clamp screw taking up the bath's water, an automatic mister whose tank runs low, a bubbler humidifier cooling by
its own evaporation, a laser whose emission is gated to the records so that its mount warms only while it measures),
one linear but not a single lag (the back-flow's opposing swelling read where the water arrives at the far face: the
concentration at the far wall of a slab, 1/cosh(sqrt(s tau))), some from the lab's wiring or sensors (a conditioning
amplifier's group-delay equaliser, the current streamed from a potentiostat with its own latency per record, a modal
sensor film that reads the first mode only, a 60 Hz instrument on a frequency converter in a 50 Hz lab). Four
structures outside the catalogue (truth "unexplained": the drive amplifier breaking into a parasitic oscillation during
the charging spikes, a second strip driven in the same bath, the drive monitor reading across the strip's current
return, a pit in the plating that the beam crosses as the strip draws back); clean sessions. All on three bases of new
seeds (136-138: the paper strip, the seed-001 strip on its own sweep, the paper strip 41 mm free) and on the earlier
sets' protocol / data-shape variants plus one new here: the spectra exported by the impedance analyser's own software
and listed by the lab's merge script after all the DAQ's records (``spectra_last``).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh21 are reused (importing inject_fresh21 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import, none replaced. Strengths
are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it made on its case,
measured in memory against the clean base (relative RMS change over all series, form only, no variant; "noise": the
column's sample-to-sample noise at rest, inject_fresh15.rest_noise; the values for the three bases are in
docs/effects.md).

Run: python bench/inject_fresh22.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np

import inject
import inject_fresh21  # noqa: F401  (registers every earlier set's forms, bases, presets and variants)
from inject import Case, Rec, Session, lu, map_disp, ref_disp
from inject_fresh2 import _chrono, _through
from inject_fresh3 import _past, _resist, _sign
from inject_fresh4 import _clamp_law, _lag_state
from inject_fresh7 import _superpose
from inject_fresh9 import _dry_by, _gaps, _session_grid
from inject_fresh10 import _lambda, _station
from inject_fresh12 import _line_f
from inject_fresh14 import _largest
from inject_fresh18 import _bv
from inject_fresh20 import _block_starts, _relays
from inject_fresh21 import _main_side

# the paper's strip 41 mm free (earlier sets used 20, 22-29, 31-40, 42 and 45 mm, and 30 mm is the paper preset itself;
# its 1 V step peaks near 16 mm, 8.8 mm x (41/30)^2, inside the laser's +-20 mm): preset "paper_41", base "p41_138",
# registered in every process importing this module
inject.register_free_length("paper_41", 0.041)

inject.BASES.update({
    "paper_136": ("paper-sweep", "paper", 136),
    "s001_137": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 137),
    "p41_138": ("paper-sweep", "paper_41", 138),
})

BETAS = (1.8751040687, 4.6940911330, 7.8547574382, 10.9955407349)  # clamped-free roots, cos b cosh b = -1


# ------------------------------------------------------------------------------------------------ tools


def _mode(b: float, x: float) -> tuple[float, float]:
    """A clamped-free beam's mode of root b (unit norm over the unit length) and its slope at x (0..1)."""
    c = (math.cosh(b) + math.cos(b)) / (math.sinh(b) + math.sin(b))
    phi = math.cosh(b * x) - math.cos(b * x) - c * (math.sinh(b * x) - math.sin(b * x))
    dphi = b * (math.sinh(b * x) + math.sin(b * x) - c * (math.cosh(b * x) - math.cos(b * x)))
    return phi, dphi


def _f1(s: Session, p: float, cache: dict[float, float]) -> float:
    """The strip's first resonance (Hz) at pressure p: the first local peak of the preset's tip FRF (its gain is
    largest at the lowest frequencies, where the charge builds up, so the first bump above them, not the maximum)."""
    if p not in cache:
        from labrig.physics import presets, transfer

        f = np.logspace(-0.5, 3, 3000)
        a = np.abs(transfer.frf(f, presets.get(s.preset).specimen(p)))
        peaks = np.flatnonzero((a[1:-1] > a[:-2]) & (a[1:-1] >= a[2:])) + 1
        cache[p] = float(f[peaks[0]] if peaks.size else f[int(np.argmax(a))])
    return cache[p]


def _walk_lag(s: Session, target: Callable[[Rec], np.ndarray], rate: Callable[[Rec], np.ndarray], tau: float,
              rest_target: float = 0.0) -> dict[int, np.ndarray]:
    """A store y following target(r) at rate(r)/tau (exact for both held over each sample), sample by sample through
    the session in time order; over the rests it relaxes towards ``rest_target`` at 1/tau. Returns y per record."""
    out, y, t_end = {}, float(rest_target), None
    for r in _chrono(s):
        t = r.cols["t_s"]
        if t_end is not None:
            y = rest_target + (y - rest_target) * math.exp(-max(float(t[0]) - t_end, 0.0) / tau)
        a = np.exp(-np.asarray(rate(r), float) / (r.fs * tau))
        x = np.asarray(target(r), float)
        o = np.empty(x.size)
        for k, (xk, ak) in enumerate(zip(x.tolist(), a.tolist())):
            y = xk + (y - xk) * ak
            o[k] = y
        out[id(r)], t_end = o, float(t[-1])
    return out


def _proxy(s: Session, cols: dict[int, np.ndarray]) -> tuple[Session, list[tuple[Rec, Rec]]]:
    """A stand-in session whose "disp_m" is the per-record array ``cols`` (for inject_fresh2._through)."""
    pairs = [(r, Rec(r.entry, {"t_s": r.cols["t_s"], "disp_m": cols[id(r)]})) for r in s.series()]
    return Session(s.specimen, [q for _, q in pairs], s.preset, s.t0, s.t1), pairs


def _grid_lag(tg: np.ndarray, target: np.ndarray, tau: float, x0: float) -> np.ndarray:
    """A first-order lag of ``target`` on the even grid ``tg`` from x0."""
    dt = float(tg[1] - tg[0]) if tg.size > 1 else 1.0
    a = math.exp(-dt / tau)
    out, x = np.empty(tg.size), float(x0)
    for k, y in enumerate(target.tolist()):
        x = y + (x - y) * a
        out[k] = x
    return out


# ------------------------------------------------------------------------------------------------ back relaxation


def _sech(z: np.ndarray) -> np.ndarray:
    q = np.sqrt(np.asarray(z, complex))  # principal root, Re >= 0
    e = np.exp(-q)
    return 2 * e / (1 + e * e)


def br_far_face_arrival(s: Session) -> None:
    """The opposing swelling that relaxes the bend is the water the back-flow delivers to the anode's side, and the bend
    feels it where its moment arm is largest, at the far face: the back-flow a diffusion across the membrane from the
    swollen cathode's side to a far wall it cannot cross, read at that wall. The concentration at the far wall of a slab
    whose other face is held, c(l, s)/c0 = 1/cosh(sqrt(s tau)) (tau = l^2/D 3-20 s, log): 1 - K2 sech(sqrt(s tau)) (K2
    0.8-1.2), a back-flow that arrives after a diffusive delay (flat at first: every derivative of its step response
    zero at the edge, then a sigmoid in log time), neither a lag, a spread of lags nor a dead time. Through
    inject_fresh2._through with 240 s of the session's history; displacement only. Measured (p41_138) displacement RMS
    -76 % (residual 91 %, 10000x its noise), the 1 V steps peaking at 3.8 mm (16 mm clean), 1.9 mm by the plateaus'
    end."""
    k2, tau = s.rng.uniform(0.8, 1.2), lu(s.rng, 3.0, 20.0)

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        return lambda q: 1 - k2 * _sech(tau * np.asarray(q))

    new = _through(s, H, 240.0)
    map_disp(s, lambda r, d: new[id(r)])


def br_drag_gated(s: Session) -> None:
    """The back-flow and the ionic current share the membrane's channels: while the cations move they drag water with
    them towards the cathode (the electro-osmotic drag, the Onsager cross term), against the water diffusing back, so
    the back-flow slows while the current flows and runs freely at rest. The store x of water flowing back follows the
    bend d at the rate 1/(tau0 (1 + abs(i)/i_d)) (tau0 3-10 s, log; i_d 0.05-0.2 of the session's 99.5th percentile of
    abs(i)), read d - K2 x (K2 0.8-1.2): the charging spikes hold the give-back for a moment, the 0.5 V sines' currents
    slow it by a factor of 1.2-3, the held 1 V plateaus (a leak of a few tenths of a mA) hardly at all, and after the
    fall it runs at tau0. Sample by sample through the session in time order (the store carried over the rests, the
    displacement linear across them); displacement only. Measured (s001_137) displacement RMS -60 % (residual 84 %,
    2800x its noise), the 1 V steps peaking at 1.85 mm (4.7 mm clean), 1.0 mm by the plateaus' end."""
    k2, tau0 = s.rng.uniform(0.8, 1.2), lu(s.rng, 3.0, 10.0)
    i_ref = float(np.percentile(np.abs(np.concatenate([r.cols["i_A"] for r in s.series()])), 99.5)) or 1e-3
    i_d = s.rng.uniform(0.05, 0.2) * i_ref
    x, d_end, new = 0.0, 0.0, {}
    for r, gap in _gaps(s, 1.0):
        d = r.cols["disp_m"]
        for dt, u in gap:
            x += -math.expm1(-dt / tau0) * (d_end + u * (float(d[0]) - d_end) - x)
        a = np.exp(-1.0 / (r.fs * tau0 * (1 + np.abs(r.cols["i_A"]) / i_d)))
        out = np.empty(d.size)
        for k, (dk, ak) in enumerate(zip(d.tolist(), a.tolist())):
            x = dk + (x - dk) * ak
            out[k] = x
        d_end = float(d[-1])
        new[id(r)] = d - k2 * out
    map_disp(s, lambda r, d: new[id(r)])


# ------------------------------------------------------------------------------------------------ faradaic current


def far_adsorbed_intermediate(s: Session) -> None:
    """Hydrogen (and oxygen) evolution runs through an adsorbed intermediate (the Volmer-Heyrovsky route on platinum):
    its steady current is a symmetric Butler-Volmer branch (0.08-0.3 mA at 1 V, log, v_t 0.1-0.2 V), but the current
    follows it only as fast as the intermediate's coverage relaxes, and that relaxation speeds up with the same
    exponential kinetics: a lag tau0/cosh(v/2 v_t) (tau0 0.1-0.6 s, log, near 0 V; ten times shorter at 1 V). A held 1 V
    reaches its leak at once, the fast 0.5 V sines carry only a lagging, flattened part of it, and no DC is lost. Sample
    by sample through the session in time order (the coverage relaxing over the rests); the current only. Measured
    (s001_137) current RMS +0.43 % (residual 1.4 %, 3.9x its noise)."""
    i1, vt, tau0 = lu(s.rng, 8e-5, 3e-4), s.rng.uniform(0.1, 0.2), lu(s.rng, 0.1, 0.6)
    y = _walk_lag(s, lambda r: _bv(r.cols["v_V"], i1, vt), lambda r: np.cosh(r.cols["v_V"] / (2 * vt)), tau0)
    for r in s.series():
        r.cols["i_A"] = r.cols["i_A"] + y[id(r)]


def _valve_cell(u: np.ndarray, fs: float, vf: float, i_h: float, b_c: float, q_f: float, b_f: float,
                c: float) -> tuple[np.ndarray, float]:
    """The current out of a valve-metal electrode at u (V against the strip's far face) from the formation voltage vf:
    cathodic, hydrogen evolution through its oxide, -i_h expm1(-u/b_c)/expm1(1/b_c); anodic, the high-field forming
    current i0 exp((u - V_f)/b_f) with dV_f/dt = i/q_f, exact for u held over each sample (exp((V_f - u)/b_f) grows by
    c dt, c = i0/(q_f b_f)). Returns the current and the last V_f."""
    out = np.where(u < 0, -i_h * np.expm1(np.clip(-u, 0, None) / b_c) / math.expm1(1 / b_c), 0.0)
    dt, lcd = 1.0 / fs, math.log(c / fs)
    for k, uk in enumerate(u.tolist()):
        if uk <= 0.0:
            continue
        lw = (vf - uk) / b_f
        new = uk + b_f * np.logaddexp(lw, lcd)
        out[k] += q_f * (new - vf) / dt
        vf = float(new)
    return out, vf


def far_valve_metal(s: Session) -> None:
    """A titanium screw (a clamp's, or a fixture's) touching one face's contact (drawn) and standing in the bath, facing
    the other face's platinum through the water: a valve metal, an electrolytic rectifier in parallel with the strip.
    With the screw the cathode, hydrogen evolves through its thin oxide, an exponential branch (0.1-0.4 mA at 1 V, log;
    b_c 0.1-0.2 V); with it the anode, its oxide grows by the high-field law, a forming current i0 exp((u - V_f)/b_f)
    (b_f 0.03-0.08 V) that raises the formation voltage V_f by i/q_f (q_f b_f 20-100 uC, log: the screw's wetted
    area), from its native film's 0.1-0.4 V: on the first anodic 1 V a current falling as q_f b_f/t, and afterwards
    almost nothing on that polarity until the drive goes beyond what the oxide was formed to. A one-sided exponential
    leak that never decays and an anodic transient that does not come back. Sample by sample through the session in
    time order (the oxide kept over the rests); the current only (the analyser's 10 mV sees nothing of either branch).
    Measured (paper_136) current RMS +0.37 % (residual 1.8 %, 1.4x its noise): +0.135 mA on the 1 V steps' plateaus (the
    screw the cathode there), 0.195 mA of forming current on the first 1 V harmonic's anodic half, 0.023 mA on the next
    block's."""
    side = _sign(s)
    i_h, b_c = lu(s.rng, 1e-4, 4e-4), s.rng.uniform(0.1, 0.2)
    b_f, qb, vf = s.rng.uniform(0.03, 0.08), lu(s.rng, 2e-5, 1e-4), s.rng.uniform(0.1, 0.4)
    q_f, i0 = qb / b_f, 1e-7
    c = i0 / (q_f * b_f)
    for r in _chrono(s):
        cur, vf = _valve_cell(side * r.cols["v_V"], r.fs, vf, i_h, b_c, q_f, b_f, c)
        r.cols["i_A"] = r.cols["i_A"] + side * cur


# ------------------------------------------------------------------------------------------------ hysteresis


def _send_on_delta(x: np.ndarray, h: float, y: float) -> tuple[np.ndarray, float]:
    out = np.empty(x.size)
    for k, xk in enumerate(x.tolist()):
        if abs(xk - y) > h:
            y = xk
        out[k] = y
    return out, y


def hy_send_on_delta(s: Session) -> None:
    """The laser controller's analogue output set to 'hysteresis' (the dead band of a change-of-value output, as
    indicators and controllers offer to stop a display or a PLC input from chattering): the output is updated to the
    reading only when the reading has moved more than h (0.02-0.08 of the displacement scale) from the value last put
    out, and holds in between. A staircase whose steps are at least h, lagging by up to h behind a rising reading and
    ahead of it on the way back: a loop as wide at 0.01 Hz as at 10 Hz, small motions inside the band frozen. Sample by
    sample through the session in time order (the output held over the rests); displacement only. Measured (p41_138)
    displacement RMS -0.13 % (residual 1.5 %, 160x its noise)."""
    h = s.rng.uniform(0.02, 0.08) * ref_disp(s)
    recs = _chrono(s)
    y = float(recs[0].cols["disp_m"][0]) if recs else 0.0
    for r in recs:
        r.cols["disp_m"], y = _send_on_delta(r.cols["disp_m"], h, y)


def hy_oxide_surface_stress(s: Session) -> None:
    """Platinum's surface stress changes when its oxide forms (adsorbed oxygen makes the surface pull: a cantilever's
    classic electrocapillary bending): each face's plating forms its oxide when it is the anode beyond its formation
    potential and strips it only when the drive has come back below a lower one (the oxide's irreversibility, 0.15-0.3 V
    lower). Forty relays a face, their formation levels spread over 0.2-0.4 V from 0.35-0.55 V of drive: the difference
    of the two faces' oxidised shares bends the strip by c (0.02-0.08 of the displacement scale) towards the side the
    positive drive bends it to, through the strip's first mode (a resonator at the preset's f1, damping 0.1-0.25). A
    double loop: one loop at each polarity, pinched at rest (both faces reduced below 0.05 V), rate-independent, nothing
    on small drives. The relays through the session in time order; displacement only. Measured (paper_136) displacement
    RMS +1.3 % (residual 1.8 %, 100x its noise)."""
    n = 40
    lo = s.rng.uniform(0.35, 0.55)
    up = [lo + s.rng.uniform(0.0, s.rng.uniform(0.2, 0.4), n) for _ in range(2)]
    dn = [u - s.rng.uniform(0.15, 0.3, n) for u in up]
    c, zeta = s.rng.uniform(0.02, 0.08) * ref_disp(s) * _main_side(s), s.rng.uniform(0.1, 0.25)
    state = [np.zeros(n), np.zeros(n)]
    e = {}
    for r in _chrono(s):
        v = r.cols["v_V"]
        th = []
        for f, u in enumerate((v, -v)):
            st, state[f] = _relays(u, up[f], dn[f], state[f])
            th.append(st.mean(axis=1))
        e[id(r)] = c * (th[0] - th[1])
    cache: dict[float, float] = {}

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        w1 = 2 * math.pi * _f1(s, float(r.entry["pressure_kPa"]), cache)
        return lambda q: w1**2 / (np.asarray(q) ** 2 + 2 * zeta * w1 * np.asarray(q) + w1**2)

    proxy, pairs = _proxy(s, e)
    out = _through(proxy, H, 2.0)
    for r, q in pairs:
        r.cols["disp_m"] = r.cols["disp_m"] + out[id(q)]


# ------------------------------------------------------------------------------------------------ time delay


def td_allpass_equaliser(s: Session) -> None:
    """The laser's analogue line through a conditioning amplifier whose group-delay equaliser (a second-order allpass
    stage, fitted to give every channel the delay of the module's 8-pole anti-alias filters) is switched in on the
    laser's channel alone: (s^2 - (w0/Q) s + w0^2)/(s^2 + (w0/Q) s + w0^2), a gain of exactly 1 at every frequency, a
    group delay of 2/(Q w0) at low frequency (5-20 ms, log; Q 0.55-0.75) falling off above w0, and the steps' edges with
    a dip before them and an overshoot after. Through inject_fresh2._through with 2 s of the session's history;
    displacement only. Measured (paper_136) displacement RMS -0.0042 % (residual 0.40 %, 22x its noise)."""
    tg, Q = lu(s.rng, 5e-3, 20e-3), s.rng.uniform(0.55, 0.75)
    w0 = 2 / (Q * tg)

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        def h(z: np.ndarray) -> np.ndarray:
            z = np.asarray(z)
            return (z * z - (w0 / Q) * z + w0**2) / (z * z + (w0 / Q) * z + w0**2)

        return h

    new = _through(s, H, 2.0)
    map_disp(s, lambda r, d: new[id(r)])


def td_potentiostat_stream(s: Session) -> None:
    """The strip driven by a potentiostat (its external input from the DAQ's output, its voltage monitor on the DAQ),
    its current taken from its own digitised stream over USB and put on the DAQ's rows by the logging script, which
    starts both acquisitions with one software command per record: each record's current late by that command's round
    trip through the instrument's firmware, 5-30 ms (log), drawn afresh for every record. A pure delay of the current
    alone, of a different size in every record; the voltage and the displacement on time. The session's history before
    each record (inject_fresh3._past) supplies the samples before its start; the current only. Measured (p41_138)
    current RMS -0.18 % (residual 110 %, 83x its noise: the steps' charging spikes moved by about their own width)."""
    for r in _chrono(s):
        tau = lu(s.rng, 5e-3, 30e-3)
        t, i = r.cols["t_s"], r.cols["i_A"]
        past = _past(s, r, "i_A", 0.3, r.fs)
        T = np.r_[t[0] - np.arange(past.size, 0, -1) / r.fs, t]
        r.cols["i_A"] = np.interp(t - tau, T, np.r_[past, i])


# ------------------------------------------------------------------------------------------------ sensor offset


def so_modal_film(s: Session) -> None:
    """No laser: a modal sensor, a piezoresistive film laminated along the strip with its electrode shaped to the first
    mode's curvature (Lee and Moon's modal sensor, a lab's way to read a beam without optics), so that it reports the
    first mode's coordinate alone, calibrated at rest by pushing the tip with a micrometer (a point load, whose static
    deflection is 97 % first mode). The actuation's uniform moment puts 90 % of the static tip deflection in the first
    mode, so the reading is about 0.92 of the tip's at low frequency, and above f1 it follows the first mode's roll-off
    with none of the higher modes' share (their anti-resonance gone): zeros move, poles stay. Four modes of the
    clamped-free beam, the first at the preset's f1 (its FRF peak), modal damping 0.05-0.2; the ratio of the film's
    reading to the tip's applied to the displacement through inject_fresh2._through with 2 s of the session's history.
    Measured (p41_138) displacement RMS -8.2 % (residual 8.2 %, 910x its noise)."""
    zeta = s.rng.uniform(0.05, 0.2)
    mom = [_mode(b, 1.0) for b in BETAS]
    m = [dp * p / b**4 for (p, dp), b in zip(mom, BETAS)]  # static tip shares under a uniform moment (sum -> 1/2)
    p1 = (mom[0][0] ** 2 / BETAS[0] ** 4) / (1.0 / 3.0)  # the first mode's share of a tip point load's tip deflection
    rest = 0.5 - sum(m)  # the higher modes' static remainder
    cache: dict[float, float] = {}

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        w1 = 2 * math.pi * _f1(s, float(r.entry["pressure_kPa"]), cache)

        def h(z: np.ndarray) -> np.ndarray:
            z = np.asarray(z)
            terms = []
            for mi, b in zip(m, BETAS):
                wi = w1 * (b / BETAS[0]) ** 2
                terms.append(mi * wi**2 / (z * z + 2 * zeta * wi * z + wi**2))
            return terms[0] / p1 / (sum(terms) + rest)

        return h

    new = _through(s, H, 2.0)
    map_disp(s, lambda r, d: new[id(r)])


def so_emission_gating(s: Session) -> None:
    """The lab's script switches the laser's emission on only while a record runs (its 'laser off' input, to spare the
    diode and the eyes at the open bench), aimed once at a margin m (0.1-0.4 mm) inside the tip's end: the diode's heat
    warms its mount whenever it emits, tilting the beam so the spot walks inboard by up to Delta (0.2-0.8 mm) through a
    lag of 20-90 s (log), and the mount cools back over every rest. The station walks inboard within each record (the
    long steps furthest), back towards the tip between them: a sensor offset that grows within the records and resets at
    rest. The strip read at the moving station (inject_fresh10._station); displacement only. Measured (s001_137)
    displacement RMS -6.7 % (residual 6.8 %, 230x its noise)."""
    L = float(s.specimen["length_m"])
    m, dlt, tau = s.rng.uniform(1e-4, 4e-4), s.rng.uniform(2e-4, 8e-4), lu(s.rng, 20.0, 90.0)
    heat, h, t_end = {}, 0.0, None
    for r in _chrono(s):
        t = r.cols["t_s"]
        if t_end is not None:
            h *= math.exp(-max(float(t[0]) - t_end, 0.0) / tau)
        heat[id(r)] = 1 - (1 - h) * np.exp(-(t - t[0]) / tau)
        h, t_end = float(heat[id(r)][-1]), float(t[-1])
    _station(s, lambda r: 1 - (m + dlt * heat[id(r)]) / L, 1 - (m + dlt) / L)


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_nylon_screw(s: Session) -> None:
    """A clamp closed by a nylon screw (an insulating screw, chosen so that the jaws' contacts do not short through the
    frame), the clamp half in the bath since it was filled (0-600 s before the first record): polyamide takes up water
    (Fick, from the surface in: the uptake 1 - exp(-sqrt(u/tau_w)), tau_w 1500-6000 s, log) and swells lengthwise, and
    the screw's growing length takes the same newtons off the jaws at any setting, 0.8-3 N at saturation. Each re-
    clamping (10-40 s before a block's first record) sets the force anew, and the loss since it follows the uptake since
    then: fast after the filling, slower block by block, and a larger share of the lighter settings' force. Through the
    preset's clamp law (inject_fresh4._clamp_law), the load cell showing it. Measured (paper_136) displacement RMS
    -0.00018 % (residual 0.0013 %, 0.075x its noise), current RMS -0.026 % (residual 0.093 %, 0.071x its noise), the
    load cell at 0.950-1.001 of its reading (the indicator's 0.01 kgf)."""
    area = float(s.specimen["clamp_area_m2"])
    fill, tau_w, dF = s.rng.uniform(0.0, 600.0), lu(s.rng, 1500.0, 6000.0), s.rng.uniform(0.8, 3.0)
    blocks = _block_starts(s)
    leads = s.rng.uniform(10.0, 40.0, len(blocks))
    t_set = {p: a - ld for (p, a), ld in zip(blocks, leads)}
    t_imm = (blocks[0][1] if blocks else s.t0) - fill

    def M(t: np.ndarray) -> np.ndarray:
        return -np.expm1(-np.sqrt(np.clip(np.asarray(t, float) - t_imm, 0, None) / tau_w))

    def rel(t: np.ndarray, p: float, t_first: float) -> np.ndarray:
        ts = t_set.get(p, t_first)
        return 1 - dF * np.clip(M(t) - M(np.array([ts]))[0], 0, None) / (p * 1e3 * area)

    _clamp_law(s, rel)


def cr_bottoming_pads(s: Session) -> None:
    """Two-layer pads under the jaws: a soft open-cell polyurethane foam layer (to spread the force over the strip) on a
    firm rubber backing. The foam creeps logarithmically under a held gap (r_s 1.5-4 % of its force per decade of time,
    tau 2-20 s, log, from each setting 10-40 s before its block), the rubber hardly (0.5-1.5 % a decade); and the foam
    carries the force alone only until it is crushed flat: above a bottoming pressure p_b (between the session's second
    and third settings) the backing takes the rest, so the share that relaxes falls as 1/(1 + (p/p_b)^k) (k 3-6). The
    light settings' force falls by several percent through their blocks, the tight ones' by a percent or so. Through the
    preset's clamp law (inject_fresh4._clamp_law), the load cell showing it. Measured (p41_138) displacement RMS
    -0.0016 % (residual 0.048 %, 5.3x its noise), current RMS +0.023 % (residual 0.42 %, 0.34x its noise), the load cell
    at 0.890-0.989 of its reading."""
    ps = s.pressures() or [1.0]
    lo_p, hi_p = ps[min(1, len(ps) - 1)], ps[min(2, len(ps) - 1)]
    p_b = math.exp(s.rng.uniform(math.log(lo_p), math.log(max(hi_p, lo_p * 1.0001))))
    k, r_s, r_h, tau = s.rng.uniform(3.0, 6.0), s.rng.uniform(0.015, 0.04), s.rng.uniform(0.005, 0.015), \
        lu(s.rng, 2.0, 20.0)
    blocks = _block_starts(s)
    leads = dict(zip((p for p, _ in blocks), s.rng.uniform(10.0, 40.0, len(blocks))))

    def rel(t: np.ndarray, p: float, t_first: float) -> np.ndarray:
        u = np.clip(np.asarray(t, float) - (t_first - leads.get(p, 20.0)), 0, None)
        return 1 - (r_s / (1 + (p / p_b) ** k) + r_h) * np.log10(1 + u / tau)

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_timer_mister(s: Session) -> None:
    """A strip in air kept moist by an automatic mister on a cycle timer (an ultrasonic fogger of the kind terraria and
    plant-tissue benches use), its nozzle aimed at the strip: every T (150-500 s, its phase unrelated to the records) it
    fogs for a few seconds and restores a share rho of the water lost since (0.8-0.95 at first), and its small tank runs
    low, so each burst restores 0.01-0.04 less than the one before; between bursts the strip dries towards a loss of
    0.15-0.35 through 100-400 s (log), from its mounting (wet) 0-300 s before the first record. A sawtooth out of step
    with the blocks on a drying trend that steepens as the mister fails. The gain as the water, the conductance as its
    1.5-2.5th power, the spectra at the next series' start (inject_fresh9._dry_by), on a 1 s grid. Measured (s001_137)
    displacement RMS -16 % (residual 18 %, 590x its noise), current RMS -37 % (residual 40 %, 110x its noise), the
    spectra's |Z| at 0.1 Hz +5.5, +69, +18, +77 %."""
    T, lead = s.rng.uniform(150.0, 500.0), s.rng.uniform(0.0, 300.0)
    ph = s.rng.uniform(0.0, 1.0) * T
    rho0, drho = s.rng.uniform(0.8, 0.95), s.rng.uniform(0.01, 0.04)
    x_inf, tau, gc = s.rng.uniform(0.15, 0.35), lu(s.rng, 100.0, 400.0), s.rng.uniform(1.5, 2.5)
    tg = _session_grid(s, 1.0, lead)
    a = math.exp(-1.0 / tau)
    x, burst, loss = 0.0, 0, np.empty(tg.size)
    next_t = tg[0] + ph
    for k, t in enumerate(tg.tolist()):
        x = x_inf + (x - x_inf) * a
        if t >= next_t:
            x *= 1 - max(rho0 - drho * burst, 0.0)
            burst, next_t = burst + 1, next_t + T
        loss[k] = x
    _dry_by(s, lambda t: np.interp(t, tg, loss), lambda t: 1 - (1 - np.interp(t, tg, loss)) ** gc)


def dh_bubbler_cooling(s: Session) -> None:
    """A strip in air in an enclosure fed by a bubbler humidifier (dry compressed air bubbled through a bottle of water,
    set to 0.75-0.9 RH at the strip when it was switched on 0-600 s before the first record): the bottle's water cools
    by its own evaporation towards the wet-bulb temperature, so the air's dew point falls and the humidity at the strip
    sinks by 0.08-0.2 over 600-2000 s (log) and levels off. The strip's water follows Nafion's isotherm
    (inject_fresh10._lambda) through its sorption lag (100-400 s, log): a loss that starts slowly (a lag of a lag),
    steepens and levels off. The gain as the water, the conductance as its 1.5-2.5th power, relative to the first
    record, the spectra at the next series' start (inject_fresh9._dry_by). Measured (s001_137) displacement RMS -15 %
    (residual 18 %, 600x its noise), current RMS -35 % (residual 38 %, 100x its noise), the spectra's |Z| at 0.1 Hz +0,
    +47, +73, +84 %."""
    rh0, drh, tau_c = s.rng.uniform(0.75, 0.9), s.rng.uniform(0.08, 0.2), lu(s.rng, 600.0, 2000.0)
    lead, tau_s, gc = s.rng.uniform(0.0, 600.0), lu(s.rng, 100.0, 400.0), s.rng.uniform(1.5, 2.5)
    tg = _session_grid(s, 1.0, lead)
    rh = rh0 - drh * -np.expm1(-(tg - tg[0]) / tau_c)
    w = _grid_lag(tg, _lambda(np.clip(rh, 0.0, 0.95)), tau_s, float(_lambda(np.array([rh0]))[0]))
    w0 = float(np.interp(s.t0, tg, w))
    _dry_by(s, lambda t: 1 - np.interp(t, tg, w) / w0, lambda t: 1 - (np.interp(t, tg, w) / w0) ** gc)


# ------------------------------------------------------------------------------------------------ strain resistance


def _hyper(e: np.ndarray, k: float) -> np.ndarray:
    """The flakes' overlap law: dR/R = k e/(1 - k e), k e held below 0.9 (the flakes do not part completely)."""
    ke = np.clip(k * e, -50.0, 0.9)
    return ke / (1 - ke)


def sr_shingled_flakes(s: Session) -> None:
    """Electrodes of overlapping metal flakes (a flake-silver or platinum-black ink painted on and sintered, the flakes
    lying like roof tiles): the current crosses from flake to flake through their overlaps, whose length the face's
    strain shortens in tension and lengthens in compression, so each face's resistance goes as the inverse of its
    overlap, dR/R = k e/(1 - k e) (e the face's strain over the session's largest, k 0.3-0.6 on one face, drawn, 0.3-0.7
    of that on the other): steeply up in tension, gently down in compression. The two faces' sum is even in the bend
    where they match and keeps an odd part where they do not. Gains fall by 0.03-0.08 (displacement) and 0.06-0.15
    (current) per unit of dR/R (inject_fresh3._resist). Measured (paper_136) displacement RMS -0.40 % (residual 0.50 %,
    28x its noise), current RMS -0.082 % (residual 0.58 %, 0.44x its noise)."""
    side = _sign(s)
    ka = s.rng.uniform(0.3, 0.6)
    kb = ka * s.rng.uniform(0.3, 0.7)
    k = ref_disp(s) / (_largest(s) or ref_disp(s))
    _resist(s, lambda r, e: _hyper(side * k * e, ka) + _hyper(-side * k * e, kb), (0.03, 0.08), (0.06, 0.15))


def sr_gel_bridges(s: Session) -> None:
    """Cracks of the tensioned face (one face, drawn, the other at 0.2-0.5 of its gauge) that open beyond e0 (0.05-0.2
    of the session's largest tension) and fill with the soft ionomer gel of the membrane's surface, which creeps into an
    opened crack through a viscous lag (0.3-3 s, log) and bridges it ionically: a crack's resistance is its opening less
    a share beta (0.5-0.85) of the gel that has crept into it. A slow bend lets the gel follow and costs little, a fast
    one opens the cracks faster than the gel can fill them; the gel, squeezed out as a crack closes, never bridges more
    than the crack's opening. The gel's fill through the session in time order (emptying over the rests). Gains fall by
    0.05-0.12 (displacement) and 0.1-0.25 (current) per unit of dR/R (inject_fresh3._resist). Measured (p41_138)
    displacement RMS -1.4 % (residual 1.5 %, 160x its noise), current RMS -0.30 % (residual 0.92 %, 0.73x its noise)."""
    side, o = _sign(s), s.rng.uniform(0.2, 0.5)
    e0, tau, beta = s.rng.uniform(0.05, 0.2), lu(s.rng, 0.3, 3.0), s.rng.uniform(0.5, 0.85)
    ref = ref_disp(s)
    k = ref / (_largest(s) or ref)
    fill, t_end, dr = [0.0, 0.0], None, {}
    for r in _chrono(s):
        x = k * r.cols["disp_m"] / ref
        t = r.cols["t_s"]
        out = np.zeros(x.size)
        for f, (w, sg) in enumerate(((1.0, side), (o, -side))):
            if t_end is not None:
                fill[f] *= math.exp(-max(float(t[0]) - t_end, 0.0) / tau)
            op = np.clip(sg * x - e0, 0, None)
            g = _lag_state(op, r.fs, tau, fill[f])
            fill[f] = float(g[-1])
            out += w * (op - beta * np.minimum(g, op))
        dr[id(r)], t_end = out, float(t[-1])
    _resist(s, lambda r, e: dr[id(r)], (0.05, 0.12), (0.1, 0.25))


# ------------------------------------------------------------------------------------------------ large deflection


def _table_map(s: Session, reading: Callable[[np.ndarray], np.ndarray]) -> None:
    """A static reading map of the displacement, tabulated over 1.6 times the session's largest bend (slope 1 at rest)
    and interpolated sample by sample."""
    big = 1.6 * (_largest(s) or ref_disp(s))
    dg = np.linspace(-big, big, 4001)
    yg = reading(dg)
    slope = (yg[2001] - yg[1999]) / (dg[2001] - dg[1999])
    yg = (yg - yg[2000]) / slope
    map_disp(s, lambda r, d: np.interp(d, dg, yg))


def ld_inductive_track(s: Session) -> None:
    """No laser: a coil-on-board inductive position sensor (a PCB with a transmitting loop and two receiving coils in
    sine and cosine patterns along a straight track, read by its interface chip), its track along the bending direction
    beside the tip and a copper foil target (w 0.4-0.8 of the session's largest bend wide) glued on the tip's face: the
    reading is linear while the whole target is over the track and rolls off as the target runs past the track's end
    (half-length a, the roll-off starting at 0.6-0.9 of the largest bend): the track's position weighted by the target's
    coverage, the clip of the track convolved with the target's width, a quadratic knee. The large bends read short on
    both sides, the small ones true. Tabulated and interpolated (slope 1 at rest); displacement only. Measured
    (paper_136) displacement RMS -0.19 % (residual 0.43 %, 24x its noise)."""
    big = _largest(s) or ref_disp(s)
    w = s.rng.uniform(0.4, 0.8) * big
    a = s.rng.uniform(0.6, 0.9) * big + w / 2

    def reading(x: np.ndarray) -> np.ndarray:
        u = np.linspace(-0.5, 0.5, 201) * w
        return np.mean(np.clip(x[:, None] + u[None, :], -a, a), axis=1)

    _table_map(s, reading)


def ld_bicell_disc(s: Session) -> None:
    """No laser: a bi-cell photodiode (two halves side by side across the bending direction) reads the image of a small
    back-lit aperture carried at the tip (a pinhole in a foil flag lit from behind through the bath): the image is a
    uniform disc (radius R, 1.1-1.6 of the session's largest bend in tip units), and the cell's difference over sum is
    the disc's area on one half less the other, (2/pi)(asin(u) + u sqrt(1 - u^2)), u = x/R, calibrated by its slope at
    the centre: the circular segment's law, true at rest and short at the large bends on both sides (the steps' tops by
    several percent). Tabulated and interpolated (slope 1 at rest); displacement only. Measured (p41_138) displacement
    RMS -7.6 % (residual 8.7 %, 960x its noise)."""
    R = s.rng.uniform(1.1, 1.6) * (_largest(s) or ref_disp(s))

    def reading(x: np.ndarray) -> np.ndarray:
        u = np.clip(x / R, -1, 1)
        return R * (np.arcsin(u) + u * np.sqrt(1 - u * u)) / 2

    _table_map(s, reading)


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_frequency_converter(s: Session) -> None:
    """An instrument built for the other grid (a 60 Hz chiller or vacuum pump in a 50 Hz lab, or the reverse) run from
    a static frequency converter on the bench's circuit: its motor's field at the converter's output frequency, from its
    crystal (+-0.005 Hz), with the iron's third harmonic (0.1-0.3), 1-4 um and 2-8 uA (log); and its input rectifier
    drawing the building's line in pulses, whose field carries that line's odd harmonics (third 0.5-0.8, fifth 0.3-0.5
    of its fundamental), 0.5-2 um and 1-5 uA (log). Two lines and their harmonics, 10 Hz apart at the fundamental, each
    with its own coupling phase on each channel, phase locked to the session clock. Measured (s001_137) displacement
    RMS +1.2e-05 % (residual 0.049 %, 1.6x its noise), current RMS +6e-05 % (residual 0.11 %, 0.30x its noise)."""
    f_in = _line_f(s)
    f_out = (60.0 if f_in < 55.0 else 50.0) + s.rng.uniform(-0.005, 0.005)
    h3o = s.rng.uniform(0.1, 0.3)
    h3i, h5i = s.rng.uniform(0.5, 0.8), s.rng.uniform(0.3, 0.5)
    amp = {"disp_m": (lu(s.rng, 1e-6, 4e-6), lu(s.rng, 5e-7, 2e-6)),
           "i_A": (lu(s.rng, 2e-6, 8e-6), lu(s.rng, 1e-6, 5e-6))}
    ph = {col: s.rng.uniform(0, 2 * np.pi, 5) for col in amp}
    for r in s.series():
        t = r.cols["t_s"]
        for col, (ao, ai) in amp.items():
            p = ph[col]
            hum = ao * (np.cos(2 * np.pi * f_out * t + p[0]) + h3o * np.cos(6 * np.pi * f_out * t + p[1]))
            hum += ai * (np.cos(2 * np.pi * f_in * t + p[2]) + h3i * np.cos(6 * np.pi * f_in * t + p[3])
                         + h5i * np.cos(10 * np.pi * f_in * t + p[4]))
            r.cols[col] = r.cols[col] + hum


def mp_ac_solenoid_clamp(s: Session) -> None:
    """A clamp whose jaw is pulled by an AC solenoid (a shaded-pole electromagnet on the line, as door locks and old
    fixtures use), its coil current set for each pressure (the force going as the current squared): the coil's leakage
    field at the line frequency, in proportion to the current, with a third harmonic that grows as the iron saturates
    (0.05 + 0.25 (I/I_top)^2), reaches the laser's cable and the current amplifier's input (at the top setting 1-4 um,
    3-12 uA, log); and the pull's ripple at twice the line frequency, which the shading ring leaves at 10-30 % of the
    force, shakes the clamp and the strip with it (0.5-2 um at the top setting, log, as the current squared): the hum's
    level steps with the pressure block, its 100 or 120 Hz only on the displacement. Phase locked to the session clock.
    Measured (paper_136) displacement RMS +1.4e-05 % (residual 0.051 %, 2.9x its noise), current RMS +3e-05 %
    (residual 0.11 %, 0.081x its noise)."""
    f0 = _line_f(s)
    ad, ai, ab = lu(s.rng, 1e-6, 4e-6), lu(s.rng, 3e-6, 1.2e-5), lu(s.rng, 5e-7, 2e-6)
    pd, pi, p3d, p3i, pb = s.rng.uniform(0, 2 * np.pi, 5)
    top = max(s.pressures() or [1.0])
    for r in s.series():
        t = r.cols["t_s"]
        lev = math.sqrt(float(r.entry["pressure_kPa"]) / top)
        h3 = 0.05 + 0.25 * lev**2
        w = 2 * np.pi * f0 * t
        r.cols["disp_m"] = r.cols["disp_m"] + ad * lev * (np.cos(w + pd) + h3 * np.cos(3 * w + p3d)) \
            + ab * lev**2 * np.cos(2 * w + pb)
        r.cols["i_A"] = r.cols["i_A"] + ai * lev * (np.cos(w + pi) + h3 * np.cos(3 * w + p3i))


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_amp_oscillation(s: Session) -> None:
    """The drive amplifier (a power op-amp booster driving the strip's large capacitance) is marginally stable with its
    load, and while its output current is large (above 0.3-0.6 of the session's largest, with 20 % to spare below) its
    output stage breaks into a parasitic oscillation at 20-80 kHz, a little higher the harder it is driven (+10 % at the
    peak): bursts on the drive monitor (10-50 mV, log) and on the current (50-200 uA, log) during the steps' charging
    spikes and the fast large sines' crests, which the DAQ, without an anti-alias filter, samples as aliases at any
    frequency below its Nyquist. The strip cannot follow 20 kHz: its displacement knows nothing of them. Drive monitor
    and current. Measured (paper_136) drive residual 0.43 % of its RMS (2.3 mV, 9.1x its
    noise; on 5 % of the samples, peaks of 18 mV), current residual 0.25 % (0.19x its noise); (s001_137) drive 0.31 %
    (6.2x; 7 %, 11 mV), current 0.65 % (1.8x)."""
    i_max = _largest(s, "i_A") or 1e-3
    i_th = s.rng.uniform(0.3, 0.6) * i_max
    f_osc, av, ai = s.rng.uniform(20e3, 80e3), lu(s.rng, 1e-2, 5e-2), lu(s.rng, 5e-5, 2e-4)
    pv, pi = s.rng.uniform(0, 2 * np.pi, 2)
    for r in s.series():
        t, i = r.cols["t_s"], np.abs(r.cols["i_A"])
        gate = np.clip((i / i_th - 0.8) / 0.2, 0.0, 1.0)
        if not np.any(gate):
            continue
        cyc = f_osc * (t - t[0]) + 0.1 * f_osc * np.cumsum(i / i_max) / r.fs
        cyc = np.mod(cyc + f_osc * (t[0] - s.t0), 1.0)
        r.cols["v_V"] = r.cols["v_V"] + av * gate * np.cos(2 * np.pi * cyc + pv)
        r.cols["i_A"] = r.cols["i_A"] + ai * gate * np.cos(2 * np.pi * cyc + pi)


def out_twin_strip(s: Session) -> None:
    """A colleague tests a second strip in the same cuvette, driven by its own generator: 3-6 spells of 120-600 s, each
    a square wave or a sine (drawn) of 0.5-1 V at 0.05-1 Hz (log). Its ionic current spreads through the bath, and our
    strip, standing in that field with its faces at different distances from the other strip, feels a share k (0.3-2 %)
    of the other's drive across its faces, which the recorded v_V knows nothing of: our strip bends and draws current in
    answer to a voltage that was never recorded (through its own measured step responses, inject_fresh7._superpose).
    Displacement and current. Measured (paper_136) displacement residual 0.59 % of its RMS (33x its noise), current 0.49
    % (0.37x); (p41_138) displacement 0.92 % (100x), current 1.2 % (0.95x)."""
    n = int(s.rng.integers(3, 7))
    starts = np.sort(s.rng.uniform(s.t0, s.t1, n))
    spells = []
    for k, a in enumerate(starts.tolist()):  # one generator: a spell ends before the next begins
        b = min(a + s.rng.uniform(120.0, 600.0), float(starts[k + 1]) if k + 1 < n else np.inf)
        spells.append((a, b, s.rng.uniform(0.5, 1.0), lu(s.rng, 0.05, 1.0), s.rng.random() < 0.5, s.rng.uniform(0, 1)))
    k = s.rng.uniform(0.003, 0.02)
    e = {}
    for r in s.series():
        t = r.cols["t_s"]
        u = np.zeros(t.size)
        for a, b, amp, f, square, ph in spells:
            on = (t >= a) & (t < b)
            wave = np.sin(2 * np.pi * (f * (t - a) + ph))
            u += np.where(on, amp * (np.sign(wave) if square else wave), 0.0)
        e[id(r)] = k * u
    _superpose(s, e)


def out_monitor_return(s: Session) -> None:
    """The drive monitor's ground shares the strip's current return (the monitor's BNC shield and the drive's return
    joined at the clamp and run together to the amplifier): the DAQ reads the strip's voltage plus the strip's own
    current's drop across that return, R 1-5 Ohm (log). The recorded drive carries a spike at every step's edge and a
    current-shaped error on the fast sines that the strip never felt; the strip, the current and the displacement as
    they were. Drive monitor only. Measured (s001_137) drive residual 1.2 % of its RMS (6.5 mV, 25x its noise),
    the 1 V steps' edges +42 mV; (p41_138) 1.5 % (7.9 mV, 33x), +67 mV."""
    R = lu(s.rng, 1.0, 5.0)
    for r in s.series():
        r.cols["v_V"] = r.cols["v_V"] + R * r.cols["i_A"]


def out_spot_scratch(s: Session) -> None:
    """A pit in the plating (a scratch, a bare spot where a flake came off) 30-100 um wide and 3-8 of its widths beyond
    the point the laser's beam meets at rest: the beam is fixed in the lab and the strip draws back along it as it bends
    (the material point under the beam moves outboard by about 2 d^2/3L), so the beam crosses the pit whenever the
    bend's magnitude passes sqrt(1.5 L s_p) and the triangulation, its spot half in the dark pit, misreads by 5-30 um
    (log, either sign) for as long as it is there: a bump at one bend's magnitude, the same on both sides of rest,
    wherever and whenever the strip passes it. Displacement only. Measured (s001_137) displacement residual 0.41 % of
    its RMS (14x its noise); (p41_138) 0.038 % (4.2x)."""
    L = float(s.specimen["length_m"])
    wp = s.rng.uniform(3e-5, 1e-4)
    sp, A = wp * s.rng.uniform(3.0, 8.0), _sign(s) * lu(s.rng, 5e-6, 3e-5)

    def bump(d: np.ndarray) -> np.ndarray:
        return np.exp(-0.5 * ((2 * d * d / (3 * L) - sp) / wp) ** 2)

    at_rest = float(bump(np.zeros(1))[0])  # the pit's shoulder under the beam at rest: in the lab's zero
    map_disp(s, lambda r, d: d + A * (bump(d) - at_rest))


FRESH22_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"far_face_arrival": br_far_face_arrival, "drag_gated": br_drag_gated},
    "faradaic_current": {"adsorbed_intermediate": far_adsorbed_intermediate, "valve_metal": far_valve_metal},
    "hysteresis": {"send_on_delta": hy_send_on_delta, "oxide_surface_stress": hy_oxide_surface_stress},
    "time_delay": {"allpass_equaliser": td_allpass_equaliser, "potentiostat_stream": td_potentiostat_stream},
    "sensor_offset": {"modal_film": so_modal_film, "emission_gating": so_emission_gating},
    "clamp_relaxation": {"nylon_screw": cr_nylon_screw, "bottoming_pads": cr_bottoming_pads},
    "dehydration": {"timer_mister": dh_timer_mister, "bubbler_cooling": dh_bubbler_cooling},
    "strain_resistance": {"shingled_flakes": sr_shingled_flakes, "gel_bridges": sr_gel_bridges},
    "large_deflection": {"inductive_track": ld_inductive_track, "bicell_disc": ld_bicell_disc},
    "mains_pickup": {"frequency_converter": mp_frequency_converter, "ac_solenoid_clamp": mp_ac_solenoid_clamp},
    "unexplained": {"amp_oscillation": out_amp_oscillation, "twin_strip": out_twin_strip,
                    "monitor_return": out_monitor_return, "spot_scratch": out_spot_scratch},
}
inject.register_forms(FRESH22_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def v_spectra_last(s: Session) -> None:
    """Two instruments, two exports: the DAQ's time series from the logging software, the impedance spectra from the
    analyser's own software (a potentiostat's or an impedance analyser's data files), and the lab's merge script
    writing the manifest from the two folders one after the other: every time series in the order it ran, then every
    spectrum in the order the analyser measured them. Nothing in the files changes; the manifest's order does, so a
    spectrum no longer sits between the records it was measured between (``labrig import`` places a spectrum, which has
    no clock, where the time series before it in the manifest ended: all of them at the session's end)."""
    s.recs = [r for r in s.recs if r.series] + [r for r in s.recs if not r.series]


inject.VARIANTS.update({"spectra_last": v_spectra_last})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_136", "s001_137", "p41_138"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 6 / 7 effect cases on seeds 136-138
    "back_relaxation": [("far_face_arrival", 138, T, "spectra_last"), ("drag_gated", 137, S, "log_steps")],
    "faradaic_current": [("adsorbed_intermediate", 137, S, "coherent_sines"),
                         ("valve_metal", 136, P, "short_pretrigger")],
    "hysteresis": [("send_on_delta", 138, T, "fixed_decimals"), ("oxide_surface_stress", 136, P, "cycle_averaged")],
    "time_delay": [("allpass_equaliser", 136, P, "fir_decimated"), ("potentiostat_stream", 138, T, "dropped_packets")],
    "sensor_offset": [("modal_film", 138, T, "rate07"), ("emission_gating", 137, S, "stop_trigger")],
    "clamp_relaxation": [("nylon_screw", 136, P, "spectra_last"), ("bottoming_pads", 138, T, "merged_loadcell")],
    "dehydration": [("timer_mister", 137, S, "eis_descending"), ("bubbler_cooling", 137, S, "spectra_last")],
    "strain_resistance": [("shingled_flakes", 136, P, "resampled"), ("gel_bridges", 138, T, "swinging_door")],
    "large_deflection": [("inductive_track", 136, P, "settled_sines"), ("bicell_disc", 138, T, "tared_records")],
    "mains_pickup": [("frequency_converter", 137, S, "own_clock"), ("ac_solenoid_clamp", 136, P, "trigger_clock")],
    "unexplained": [("amp_oscillation", 136, P, "host_timed"), ("amp_oscillation", 137, S, "spectra_last"),
                    ("twin_strip", 136, P, "no_loadcell"), ("twin_strip", 138, T, "spectra_last"),
                    ("monitor_return", 137, S, "float32_time"), ("monitor_return", 138, T, "scan_hold"),
                    ("spot_scratch", 137, S, "decimated3"), ("spot_scratch", 138, T, "shortened_shuffled")],
}
CLEAN = [(136, P, "two_pressures"), (136, P, "spectra_last"), (137, S, "asrun"), (137, S, "no_spectra"),
         (138, T, "steps_sines"), (138, T, "spectra_last")]


def fresh22_cases(only: str | None = None) -> list[Case]:
    """The twenty-third held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds
    136-138)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh22_cases, "inject_fresh22", "fresh22")
