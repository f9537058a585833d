"""A thirtieth held-out set for the diagnosis (issue 12), fresh29, written without sight of the diagnosis (its code,
its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh28.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (fuel-cell-type electrodes bonded with PTFE
whose pores flood by electrowetting at the large drives, glucose oxidised on platinum that its own intermediates poison
during long anodic holds, a Prussian-blue layer switching by two-phase intercalation, a plating cracked through
stretched and sheared by the strip's twist, an electromagnetic tracking coil in a gradient field, a single-channel
Doppler radar module), some on the history, the clamp pressure or the session's events (the bath swapped for heavy
water at a re-clamping, a voice-coil clamp whose magnet warms with the coil's power, gas blinding the plating's pores at
the large drives, silt settling on a horizontal strip and stirred up at every re-clamping, a mercury lamp's magnetic
ballast switched on next door) and some on time (an ionic-liquid strip taking up the room's water, two stacked strips
gripping harder as the water film between them thins, a fluorescent marker photobleaching under its UV lamp, sponge pads
shrinking as they dry, a strip stored dry whose cracks close as it re-swells, a worn fluorescent tube's wandering
asymmetry); lab wiring or sensors among them (the second DAQ card, the shunt amplifier's input filter, the marker and
its camera, the Hall sensor reading a magnet inboard, the coil, the radar, the lamp's ballast, the tube). Four
structures outside the catalogue (truth "unexplained": the drive's even-order distortion that the monitor, wired to the
command, never sees; the current amplifier's offset warming up; the clamp's stand post ringing down after each
re-clamping; the impedance analyser's short compensation left from another fixture); clean sessions. All on three bases
of new seeds (157-159: the paper strip, the seed-001 strip on its own sweep, the paper strip 17 mm free) and on the
earlier sets' protocol / data-shape variants plus one new here: an analyser that measures each spectrum twice and writes
both passes into one file (``eis_two_passes``).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh28 are reused (importing inject_fresh28 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import, none replaced. Strengths
are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it made on its case,
measured in memory against the clean base (relative RMS change over all series, form only, no variant; "noise": the
column's sample-to-sample noise at rest, inject_fresh15.rest_noise; the values for the three bases are in
docs/effects.md).

Run: python bench/inject_fresh29.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np
from scipy import signal

import inject
import inject_fresh28  # noqa: F401  (registers every earlier set's forms, bases, presets and variants)
from inject_fresh28 import _stuck_zones
from inject import Case, Rec, Session, lu, map_disp, ref_disp
from inject_fresh2 import _chrono, _map_through, _spec
from inject_fresh3 import _resist, _sign, _through_x
from inject_fresh4 import _clamp_law
from inject_fresh6 import _bursts
from inject_fresh7 import _superpose
from inject_fresh8 import _late
from inject_fresh9 import _dry_by, _ou, _session_grid
from inject_fresh10 import _lag_varying, _station
from inject_fresh12 import _line_f
from inject_fresh14 import _largest
from inject_fresh15 import _store
from inject_fresh16 import _grid_of
from inject_fresh20 import _relays
from inject_fresh21 import _step_charge
from inject_fresh22 import _f1, _table_map, _walk_lag
from inject_fresh23 import _transmissibility
from inject_fresh24 import _by_pressure_start
from inject_fresh25 import _setting_of
from inject_fresh26 import _later_setting, _split_noise
from inject_fresh27 import _slab_left

# the paper's strip 17 mm free (earlier sets used 16-29 and 31-45 mm, 30 mm is the paper preset itself and the seed-001
# strip is 20 mm; its 1 V step peaks near 2.9 mm, well inside the laser's +-20 mm): preset "paper_17", base "p17_159",
# registered in every process importing this module
inject.register_free_length("paper_17", 0.017)

inject.BASES.update({
    "paper_157": ("paper-sweep", "paper", 157),
    "s001_158": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 158),
    "p17_159": ("paper-sweep", "paper_17", 159),
})


# ------------------------------------------------------------------------------------------------ tools


def _logistic(x: np.ndarray) -> np.ndarray:
    return 1.0 / (1.0 + np.exp(-np.clip(x, -60.0, 60.0)))


def _grid_lag(x: np.ndarray, dt: float, tau: float) -> np.ndarray:
    """A first-order lag (time constant tau) of x on an even grid of step dt, from 0, exact for x held over each
    step."""
    a = math.exp(-dt / tau)
    return signal.lfilter([1.0 - a], [1.0, -a], np.asarray(x, float))


def _exchanged(t: np.ndarray, t0: float, tau: float, t_end: float) -> np.ndarray:
    """The share a slab (both faces open, tau = l^2/D of its half-thickness) has exchanged with a bath entering at t0:
    1 - inject_fresh27._slab_left on a 1 s grid, interpolated (0 before t0)."""
    tg = np.arange(t0, max(t_end, t0 + 2.0) + 2.0, 1.0)
    share = 1.0 - _slab_left(tg - t0, tau)
    return np.interp(np.asarray(t, float), tg, share, left=0.0)


def _first_mode(s: Session) -> Callable[[Rec], Callable[[np.ndarray], np.ndarray]]:
    """Per record, the strip's first mode at its clamp pressure (labrig.physics.transfer.modal_set), normalised to 1
    at rest: H(r)(s) for inject_fresh3._through_x."""
    from labrig.physics import transfer

    modes: dict[float, tuple[float, float]] = {}

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        p = float(r.entry["pressure_kPa"])
        if p not in modes:
            ms = transfer.modal_set(_spec(s, r))
            modes[p] = (float(ms.omega[0]), float(ms.xi[0]))
        w1, z1 = modes[p]
        return lambda z: 1.0 / (1.0 + 2.0 * z1 * z / w1 + (z / w1) ** 2)

    return H



# ------------------------------------------------------------------------------------------------ back relaxation


def br_heavy_water_swap(s: Session) -> None:
    """The bath swapped for heavy water at one re-clamping after the first (drawn; 0-30 s before that setting: an
    isotope comparison within one session, or a strip being readied for a neutron or NMR measurement). The back-flow (K2
    0.5-0.9, tau_H 2-8 s, log) runs all session; after the swap the membrane's water exchanges with the D2O by diffusion
    across its thickness (the exchanged share 1 minus the slab's remaining content, inject_fresh27._slab_left, tau_x
    30-200 s, log), and D2O's viscosity (1.23-1.25 times water's at 20-25 C, with its slower self-diffusion; diluted by
    the wet cuvette and strip) slows the back-flow through the membrane's channels: tau = tau_H (1 + (r - 1) X), r
    1.15-1.25, K2 unchanged. Through inject_fresh10._lag_varying (the reading d - K2 x, x the lag of d, sample by sample
    through the session, carried over the rests); displacement only. Measured (paper_157, the swap before the 1837 kPa
    block) displacement RMS -63 % (residual 72 %, 4400x its noise): the 1 V steps at 2.70 mm by their plateaus' end in
    the first block and 2.83-2.84 mm after the swap (8.76-8.77 mm clean), 10 s after their fall 0.14 mm before it and
    0.05 mm after; the 0.1 Hz sines' gain 0.965 (+11.9 deg) before it, 0.973 (+10.3 deg) after."""
    k2, tau_h = s.rng.uniform(0.5, 0.9), lu(s.rng, 2.0, 8.0)
    ratio, tau_x = s.rng.uniform(1.15, 1.25), lu(s.rng, 30.0, 200.0)
    _, t_set = _later_setting(s)
    t_swap = t_set - s.rng.uniform(0.0, 30.0)
    tg = np.arange(t_swap, s.t1 + 2.0, 1.0)
    xg = _exchanged(tg, t_swap, tau_x, s.t1)

    def state(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        x = np.interp(np.asarray(t, float), tg, xg, left=0.0)
        return np.full(x.shape, k2), tau_h * (1.0 + (ratio - 1.0) * x)

    _lag_varying(s, state)


def br_ptfe_bonded_electrodes(s: Session) -> None:
    """Electrodes made the fuel-cell way (platinum black bonded with 10-30 % PTFE, hot-pressed onto the membrane: a
    lab's recipe for thick, low-resistance electrodes): the PTFE keeps the electrodes' pores dry, so the membrane
    exchanges no water with the bath through its faces and the back-flow runs through the membrane only (K_m 0.3-0.6, a
    lag of 2-8 s, log). Beyond v_ew (0.65-0.85 V of drive, width 0.01-0.03 V: the 1 V steps' plateaus and the 1 V
    harmonics' crests, not the 0.5 V sines) electrowetting floods the pores (the contact angle falling with the square
    of the double layer's voltage) and the anode side, which the drive has drained, draws bath water in through them: a
    second give-back (K_w 0.3-0.6) following the bend within tau_w (0.5-3 s, log) while the gate is open; when the drive
    falls the pores dewet and trap what came in, which leaves again only through the membrane (tau_out 20-80 s, log):
    the strip bends back past its rest after each 1 V record. The store sample by sample through the session in time
    order (inject_fresh22._walk_lag, relaxing over the rests), the membrane's lag with it (inject_fresh15._store);
    displacement only. Measured (p17_159) displacement RMS -75 % (residual 110 %, 2100x its noise): the 1 V steps at
    -0.04 mm by their plateaus' end (2.88-2.89 mm clean) and -0.60 mm 10 s after their fall (1.49 mm clean); the 1 V
    harmonics' gain 0.69 (+49 deg), the 0.5 V sines' 0.86 (+18 deg) at 0.1 Hz and 0.999 at 1.4 Hz."""
    km, tau_m = s.rng.uniform(0.3, 0.6), lu(s.rng, 2.0, 8.0)
    kw, tau_w, tau_out = s.rng.uniform(0.3, 0.6), lu(s.rng, 0.5, 3.0), lu(s.rng, 20.0, 80.0)
    v_ew, w = s.rng.uniform(0.65, 0.85), s.rng.uniform(0.01, 0.03)

    def gate(r: Rec) -> np.ndarray:
        return _logistic((np.abs(r.cols["v_V"]) - v_ew) / w)

    def rate(r: Rec) -> np.ndarray:  # the store's total rate, in units of 1/tau_out
        g = gate(r)
        return g * tau_out / tau_w + (1.0 - g)

    def target(r: Rec) -> np.ndarray:  # what it tends to: the bend while flooded, nothing while dry
        g = gate(r)
        return (g / tau_w) * r.cols["disp_m"] / (g / tau_w + (1.0 - g) / tau_out)

    y = _walk_lag(s, target, rate, tau_out)
    x = _store(s, tau_m)
    map_disp(s, lambda r, d: d - km * x[id(r)] - kw * y[id(r)])


# ------------------------------------------------------------------------------------------------ faradaic current


def far_hygroscopic_ionic_liquid(s: Session) -> None:
    """A strip run in air with an ionic liquid as its solvent (EMI-BF4 or EMI-Tf in place of the water, the usual way to
    keep an IPMC working in air), dried in a vacuum oven and mounted 120-900 s before the first record: the hygroscopic
    liquid takes up the room's water, Fickian through the strip's thickness (the share taken up 1 minus the slab's
    remaining content, inject_fresh27._slab_left, tau_w 2000-8000 s, log). The liquid's own window is wide, but the
    water it takes up is electrolysed on the platinum: a symmetric Butler-Volmer branch (v_t 0.08-0.15 V) whose exchange
    current follows the water's activity, i_eq (0.1-0.4 mA at 1 V, log, at full uptake) times the share taken up: odd
    and memoryless within a record, growing through the session. The current only. Measured (s001_158) current RMS +0.74
    % (residual 2.8 %, 7.5x its noise): 0.074, 0.157, 0.202, 0.231 mA added on the 1 V steps' plateaus block by block;
    the 1 V harmonics' current gain 1.010, 1.018, 1.024, 1.027."""
    i_eq, vt = lu(s.rng, 1e-4, 4e-4), s.rng.uniform(0.08, 0.15)
    t_m, tau_w = s.t0 - s.rng.uniform(120.0, 900.0), lu(s.rng, 2000.0, 8000.0)
    norm = math.sinh(0.5 / vt)
    for r in s.series():
        share = _exchanged(r.cols["t_s"], t_m, tau_w, s.t1)
        r.cols["i_A"] = r.cols["i_A"] + i_eq * share * np.sinh(np.clip(r.cols["v_V"] / (2.0 * vt), -60.0, 60.0)) / norm


def far_glucose_medium(s: Session) -> None:
    """A bio-IPMC test in a cell-culture medium (glucose 5-25 mM, DMEM-like): platinum oxidises the glucose at whichever
    face is the anode, a wave from E_g (0.15-0.35 V of drive, width 0.04-0.08 V) to a diffusion-limited current i_max
    (0.1-0.4 mA, log), but the dehydrogenation leaves adsorbed intermediates (CO-like) that poison the face: the
    poisoned share of the anodic face grows towards th_max (0.6-0.85) at the wave's rate 1/tau_p (tau_p 0.2-2 s, log, at
    the full wave), is stripped within tau_c (0.05-0.3 s, log) once the face is cathodic beyond E_c (0.15-0.35 V), and
    otherwise clears slowly (tau_h 30-120 s, log, over the rests too): i = sign(v) i_max wave (1 - theta of the anodic
    face). Rate-dependent: quick reversals keep both faces clean, long anodic holds (the steps' plateaus, the slow
    sines' half-cycles) poison them, so the current sags within each half-cycle; odd. Sample by sample through the
    session in time order; the current only. Measured (paper_157) current RMS +4.5 % (residual 5.5 %, 4.2x its noise):
    the 1 V steps' current +0.33 mA at its peak and +0.12 mA 5 s on and at the plateaus' end; the 0.5 V sines' current
    gain 1.087-1.093 at 0.1 Hz, 1.031-1.033 at 20 Hz, the 1 V harmonics' 1.046-1.049."""
    e_g, b, i_max = s.rng.uniform(0.15, 0.35), s.rng.uniform(0.04, 0.08), lu(s.rng, 1e-4, 4e-4)
    th_max, tau_p = s.rng.uniform(0.6, 0.85), lu(s.rng, 0.2, 2.0)
    e_c, tau_c, tau_h = s.rng.uniform(0.15, 0.35), lu(s.rng, 0.05, 0.3), lu(s.rng, 30.0, 120.0)
    th, t_end = [0.0, 0.0], None
    for r in _chrono(s):
        t, v = r.cols["t_s"], r.cols["v_V"]
        if t_end is not None:
            hold = math.exp(-max(float(t[0]) - t_end, 0.0) / tau_h)
            th = [x * hold for x in th]
        dt = 1.0 / r.fs
        wave = _logistic((np.abs(v) - e_g) / b)
        faces = []
        for u in (v, -v):  # face A is the anode on a positive drive, face B on a negative one
            anodic = u > 0
            rate = np.where(anodic, wave / tau_p + 1.0 / tau_h, np.where(-u > e_c, 1.0 / tau_c, 1.0 / tau_h))
            eq = np.where(anodic, th_max * (wave / tau_p) / (wave / tau_p + 1.0 / tau_h), 0.0)
            faces.append((eq.tolist(), np.exp(-rate * dt).tolist()))
        out = np.empty(v.size)
        (eq_a, dec_a), (eq_b, dec_b) = faces
        a_, b_ = th
        for k, vk in enumerate(v.tolist()):
            a_ = eq_a[k] + (a_ - eq_a[k]) * dec_a[k]
            b_ = eq_b[k] + (b_ - eq_b[k]) * dec_b[k]
            out[k] = 1.0 - (a_ if vk > 0 else b_)
        th, t_end = [a_, b_], float(t[-1])
        r.cols["i_A"] = r.cols["i_A"] + i_max * np.sign(v) * wave * out


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_prussian_blue_layer(s: Session) -> None:
    """Both faces' platinum overcoated with an electrodeposited Prussian-blue film (a redox layer labs add for a larger,
    slower stroke): the film turns to Prussian white by taking up cations when its face is driven cathodic and swells as
    it does, a two-phase intercalation that switches particle by particle with a gap between its reduction and its
    oxidation potentials (the miscibility gap's hysteresis, rate-independent): ten particle groups per face, each
    reduced once its face's cathodic drive reaches c_j + h_j and oxidised again below c_j - h_j (c_j 0.25-0.75 V of
    drive, h_j 0.05-0.15 V), each group's switching spread over tau_s (0.1-0.5 s, log: the phase front's travel); at 0 V
    every group is oxidised, so the film settles at each rest. The reduced shares' difference between the faces bends
    the strip the way the drive does, K (0.05-0.15 of the session's displacement scale) at full switching, through the
    strip's first mode (labrig.physics.transfer.modal_set, with the session's history: inject_fresh3._through_x); the
    charge it takes, Q (0.01-0.04 of the strip's double-layer charge at 1 V, from the first step:
    inject_fresh21._step_charge), passes through the current as the shares move. Loops in both that stay as the
    frequency falls; relays through the session in time order (inject_fresh20._relays). Measured (paper_157)
    displacement RMS +2.5 % (residual 3.4 %, 210x its noise), current RMS +5.3 % (residual 7.1 %, 5.3x its noise): the 1
    V steps +0.24 mm (9.00-9.01 mm for 8.76-8.77 at their plateaus' end), their current's peak +1.9 mA; the 1 V
    harmonics' gain 1.118 (+3.3 deg) in the displacement, 1.085-1.090 (+2.6 deg) in the current; the 0.5 V 0.1 Hz sines'
    1.060 and 1.043-1.046; the 20 Hz sines' 0.99."""
    n = 10
    k_pb, q_pb, tau_s = s.rng.uniform(0.05, 0.15), s.rng.uniform(0.01, 0.04), lu(s.rng, 0.1, 0.5)
    c, h = s.rng.uniform(0.25, 0.75, n), s.rng.uniform(0.05, 0.15, n)
    up, dn = c + h, c - h
    steps = [r for r in _chrono(s) if r.kind == "step"]
    charge = q_pb * (_step_charge(steps[0])[0] if steps else 0.01)
    scale = k_pb * ref_disp(s)
    state_a, state_b, prev, bend = np.zeros(n), np.zeros(n), (0.0, 0.0), {}
    for r in _chrono(s):
        v = r.cols["v_V"]
        _, state_a = _relays(np.zeros(1), up, dn, state_a)  # the rest before the record, at 0 V, long against tau_s
        _, state_b = _relays(np.zeros(1), up, dn, state_b)
        prev = (float(state_a.mean()), float(state_b.mean()))
        ra, state_a = _relays(-v, up, dn, state_a)  # face A is cathodic on a negative drive
        rb, state_b = _relays(v, up, dn, state_b)
        a = math.exp(-1.0 / (r.fs * tau_s))
        na = signal.lfilter([1.0 - a], [1.0, -a], ra.mean(axis=1), zi=[a * prev[0]])[0]
        nb = signal.lfilter([1.0 - a], [1.0, -a], rb.mean(axis=1), zi=[a * prev[1]])[0]
        diff = nb - na
        bend[id(r)] = scale * diff
        r.cols["i_A"] = r.cols["i_A"] + charge * np.diff(np.r_[prev[1] - prev[0], diff]) * r.fs
    moved = _through_x(s, bend, _first_mode(s), 2.0)  # the film's moment through the strip's first mode
    for r in s.series():
        r.cols["disp_m"] = r.cols["disp_m"] + moved[id(r)]


def hy_stacked_pair(s: Session) -> None:
    """Two strips stacked face to face and driven in parallel (a lab's way to double the blocked force), pressed
    together at the root by the clamp and held along their free length by the water film between them, in air: bent, the
    facing surfaces must slide past each other, and the film's capillary suction presses them together, so they stick
    until the shear passes the friction and then slide. While stuck the pair bends as one composite, much stiffer for
    the same actuation: three zones along the interface as stop operators (radii 0.02-0.1 of the session's largest bend,
    log-spread, times 0.7-1.3), the stuck zones taking K (0.25-0.5) of the motion, the reading u - K mean_j z_j, u the
    bend as it would be. The film thins as it evaporates from the edges (h = h_inf + (1 - h_inf) exp(-u/tau_e), h_inf
    0.3-0.6, tau_e 600-2400 s, log, from the mounting 300-1200 s before the first record) and the suction grows as 1/h:
    the radii grow through the session and ever more of the motion sticks. Sample by sample through the session in time
    order, the laser's noise kept on the held reading (inject_fresh26._split_noise); displacement only. Measured
    (s001_158) displacement RMS -1.1 % (residual 6.3 %, 190x its noise): the 20 Hz sines' gain 0.646 (stuck); the 1 V
    harmonics' 0.88, 0.86, 0.84, 0.84 block by block (-5 deg), the 0.5 V 0.1 Hz sines' 0.78 to 0.75; the 1 V steps at
    4.51-4.53 mm by their plateaus' end (4.65-4.68 mm clean) and 2.63-2.68 mm 10 s after their fall (2.50 mm clean)."""
    big = _largest(s) or ref_disp(s)
    k = s.rng.uniform(0.25, 0.5)
    radii = np.geomspace(0.02, 0.1, 3) * big * s.rng.uniform(0.7, 1.3)
    t_m, tau_e, h_inf = s.t0 - s.rng.uniform(300.0, 1200.0), lu(s.rng, 600.0, 2400.0), s.rng.uniform(0.3, 0.6)
    _stuck_zones(s, k, radii, lambda t: 1.0 / (h_inf + (1.0 - h_inf) * np.exp(-np.clip(t - t_m, 0.0, None) / tau_e)))


# ------------------------------------------------------------------------------------------------ time delay


def td_unsynced_second_card(s: Session) -> None:
    """The laser's analogue output read by a second USB DAQ card (the first card's inputs all taken), the two started by
    the logging script one after the other, the laser's card first, with no shared trigger or clock, and written side by
    side by sample index: each record's displacement is late by the start commands' USB round trip and the operating
    system's scheduling, delta_0 (3-8 ms, log) plus an exponential tail (mean 1-5 ms, log), drawn per record, and the
    second card's crystal runs 20-60 ppm (log, either sign) off the first's, so the lag drifts by that over each record
    (up to 3.7 ms over a 61 s step). Through inject_fresh8._late (the session's history before each record);
    displacement only. Measured (s001_158) displacement residual 0.37 % of its RMS (11x its noise): the 20 Hz sines'
    phase -56, -61, -68, -108 deg block by block (7.7 to 15 ms), their gain 0.998-1.000; the 0.1 Hz records' -0.3 to
    -0.5 deg."""
    d0, tail = lu(s.rng, 3e-3, 8e-3), lu(s.rng, 1e-3, 5e-3)
    ppm = _sign(s) * lu(s.rng, 20e-6, 60e-6)
    lag = {id(r): d0 + float(s.rng.exponential(tail)) for r in _chrono(s)}
    _late(s, lambda r, t: lag[id(r)] + ppm * (t - t[0]), 0.3)


def td_shunt_rfi_filter(s: Session) -> None:
    """The drive current read as the drop across a low-side shunt by an instrumentation amplifier whose inputs carry the
    usual RFI filter (a resistor in each leg and a differential capacitor, chosen for a noisy lab: 2 R_f C_d 0.4-2.5 ms,
    log): a first-order low-pass on the current channel, a delay of about its time constant at the drives' frequencies
    with the gain within a few per cent, and the steps' charging spikes rounded. A first-order lag exact for the current
    held over each sample, settled on each record's first sample (the rest before it); the current only. Measured
    (paper_157, tau 1.54 ms) current RMS -0.67 % (residual 7.9 %, 6.0x its noise): the 1 V steps' current peaks
    19.2-20.7 mA (26.3-28.2 mA clean); the 20 Hz sines' current phase -7.7 deg, gain 0.983; the 0.1 Hz records' within
    0.01 deg."""
    tau = lu(s.rng, 4e-4, 2.5e-3)
    for r in s.series():
        x = r.cols["i_A"]
        a = math.exp(-1.0 / (r.fs * tau))
        r.cols["i_A"] = signal.lfilter([1.0 - a], [1.0, -a], x, zi=[a * x[0]])[0]


# ------------------------------------------------------------------------------------------------ sensor offset


def so_bleaching_stripe(s: Session) -> None:
    """No laser: a camera tracking a stripe of fluorescent paint (a fluorescein or rhodamine marker, a lab's target for
    a dark strip) along the last 0.15-0.3 L of the strip up to its tip, lit by a UV LED aimed at the tip's end (its spot
    Gaussian, sigma 0.2-0.5 of the stripe's length) from 60-600 s before the first record, the camera triggered by the
    DAQ: the tracker reports the stripe's intensity-weighted centroid. The dye photobleaches in proportion to the light
    it takes (its brightness exp(-k I(x) u), the tip's end losing 50-90 % by the session's end), the tip's end fastest,
    so the centroid starts inboard of the tip (the stripe's middle) and walks further inboard through the session. The
    reading sum_j b_j w(x_j)/sum_j b_j over the stripe (twelve points), each record at the brightness of its middle, the
    points' w interpolated in (x/L)^2 between the tip's reading and the stripe's inboard end's (inject_fresh10._station,
    exact for the quasi-static uniform curvature, the inboard end through the beam's own transfer functions): a station
    sqrt(sum_j b_j xi_j^2/sum_j b_j) moving inboard record by record; displacement only. Measured (s001_158)
    displacement RMS -20 % (residual 20 %, 600x its noise): the 1 V steps at 3.80, 3.78, 3.75, 3.72 mm by their
    plateaus' end block by block (4.65-4.68 mm clean); the 1 V harmonics' gain 0.817, 0.810, 0.802, 0.795; the 20 Hz
    sines' 0.865 to 0.845."""
    ell = s.rng.uniform(0.15, 0.3)
    sig, loss_end, t_on = s.rng.uniform(0.2, 0.5) * ell, s.rng.uniform(0.5, 0.9), s.t0 - s.rng.uniform(60.0, 600.0)
    xi = 1.0 - ell * (np.arange(12) + 0.5) / 12.0
    light = np.exp(-0.5 * ((1.0 - xi) / sig) ** 2)  # the LED's intensity along the stripe, 1 at the tip's end
    k = -math.log(1.0 - loss_end) / max(s.t1 - t_on, 1.0)

    def station(t_mid: float) -> float:
        b = np.exp(-k * light * max(t_mid - t_on, 0.0))
        return float(np.sqrt(np.sum(b * xi**2) / np.sum(b)))

    _station(s, lambda r: np.full(r.cols["t_s"].size, station(float(np.mean(r.cols["t_s"])))), 1.0 - ell)


def so_inboard_hall_magnet(s: Session) -> None:
    """The strip's tip carries a tool (a micro-gripper or a probe: a medical actuator's test), so the lab reads its bend
    by a 0.5 mm NdFeB sphere glued inboard at x_m (0.55-0.85 L; under 2 % of the strip's mass, left out) and a Hall
    sensor facing it outside the cuvette (the field passes the water and the glass; the magnet's travel within the
    sensor's linear range), calibrated in place by a slow bend against the laser at the tip: the reading is w(x_m) times
    the static ratio w(L)/w(x_m) at 1 mHz. Right at rest and at the slow drives, but the modes read inboard differently:
    above the first resonance the reading's gain and phase depart (zeros move, poles stay). Through the beam's own
    transfer functions (labrig.physics.transfer, displacement_tf with sensor_x over the tip's) with the session's
    history (inject_fresh2._through); displacement only. Measured (p17_159) displacement RMS +0.10 % (residual 0.36 %,
    7.0x its noise): the slow records' gain 1.007 (+0.5 deg), the 1 V steps within 0.2 %; the 20 Hz sines' gain 2.04,
    1.77, 1.59, 2.04 block by block (-20 to -11 deg)."""
    from labrig.physics import transfer

    xi = s.rng.uniform(0.55, 0.85)
    z0 = np.array([2j * np.pi * 1e-3])

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        sp = _spec(s, r)
        sm = sp.with_(sensor_x=xi * sp.geometry.length)
        cal = abs(complex((transfer.displacement_tf(z0, sp) / transfer.displacement_tf(z0, sm))[0]))

        def h(z: np.ndarray) -> np.ndarray:
            with np.errstate(divide="ignore", invalid="ignore"):
                return cal * transfer.displacement_tf(z, sm) / transfer.displacement_tf(z, sp)

        return h

    _map_through(s, H, 2.0)


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_voice_coil_magnet(s: Session) -> None:
    """A voice-coil clamp (a moving-coil actuator pushing the jaw) on a current source that the operator sets at each
    setting while watching the load cell: the force goes as the current times the magnet's flux, and the NdFeB magnet's
    remanence falls by alpha (0.11-0.12 %/K) as it warms. The coil's dissipation (I^2 R, so in proportion to the square
    of the force set) heats the magnet through the actuator's body with a lag tau (100-400 s, log), the rise reaching
    dT_top (45-75 K: a high-temperature grade) at the top setting's power; energised from the first setting, heating on
    from where it was at each tightening. F/F_set = (1 - alpha dT(t))/(1 - alpha dT(t_set)): the light blocks barely
    move, the top block loses a few per cent. From each setting (inject_fresh25._setting_of) through the preset's clamp
    law (inject_fresh4._clamp_law), the load cell showing it. Measured (paper_157) the load cell at 1.000, 0.993, 0.984,
    0.974 of its setting by the blocks' ends; displacement residual 0.038 % of its RMS (2.3x its noise), current 0.15 %
    (0.11x); the top block's 20 Hz sines' gain 0.914 (-1.7 deg: its f1 moved)."""
    alpha, dt_top, tau = s.rng.uniform(0.0011, 0.0012), s.rng.uniform(45.0, 75.0), lu(s.rng, 100.0, 400.0)
    setting = _setting_of(s)
    starts = {p: setting(p, a) for p, a in _by_pressure_start(s).items()}
    top, first = max(starts), min(starts.values())
    tg = np.arange(first - 1.0, s.t1 + 2.0, 1.0)
    power = np.zeros(tg.size)
    for p, ts in sorted(starts.items(), key=lambda kv: kv[1]):
        power[tg >= ts] = (p / top) ** 2
    heat = dt_top * _grid_lag(power, 1.0, tau)

    def rel(t: np.ndarray, p: float, t_first: float) -> np.ndarray:
        ts = starts.get(p, t_first - 20.0)
        now = np.interp(np.asarray(t, float), tg, heat)
        return (1.0 - alpha * now) / (1.0 - alpha * float(np.interp(ts, tg, heat)))

    _clamp_law(s, rel)


def cr_sponge_pads_drying(s: Session) -> None:
    """A strip in air clamped between wet cellulose-sponge pads (cut 2-3 mm thick and soaked, to keep the root wet and
    spread the force), the force set at each re-clamping by the screw and then held by its fixed travel: the sponge
    dries through its open edges (its water falling as exp(-u/tau_d), tau_d 2000-8000 s, log, from the soaking 300-1200
    s before the first record) and shrinks in thickness with the water it loses (capillary contraction), so the squeeze
    each setting put into it falls by the shrinkage since that setting. The same shrinkage costs a larger share of a
    light setting's smaller squeeze: F/F_set = 1 - c_min (p_min/p) (D(t) - D(t_set))/(D(t_end) - D(t_first)), c_min
    (0.15-0.35) what the lightest setting would lose held from the first setting to the session's end, D the share
    dried. From each setting (inject_fresh25._setting_of) through the preset's clamp law (inject_fresh4._clamp_law), the
    load cell showing it. Measured (s001_158) the load cell at 0.902, 0.963, 0.982, 0.990 of its setting by the blocks'
    ends; displacement residual 0.006 % of its RMS (0.19x its noise: the seed-001 strip's clamp law moves its bend
    little at these forces), current 0.15 % (0.41x)."""
    c_min = s.rng.uniform(0.15, 0.35)
    t_w, tau_d = s.t0 - s.rng.uniform(300.0, 1200.0), lu(s.rng, 2000.0, 8000.0)
    setting = _setting_of(s)
    starts = {p: setting(p, a) for p, a in _by_pressure_start(s).items()}
    p_min, first = min(starts), min(starts.values())

    def dried(t) -> np.ndarray:
        return -np.expm1(-np.clip(np.asarray(t, float) - t_w, 0.0, None) / tau_d)

    span = max(float(dried(s.t1) - dried(first)), 1e-12)

    def rel(t: np.ndarray, p: float, t_first: float) -> np.ndarray:
        ts = starts.get(p, t_first - 20.0)
        return 1.0 - c_min * (p_min / p) * (dried(t) - dried(ts)) / span

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_gas_blinded_plating(s: Session) -> None:
    """The large drives' electrolysis (beyond v_g 0.6-0.85 V, width 0.03-0.06 V: the 1 V steps' plateaus, the 1 V
    harmonics' crests) makes its gas inside the plating's rough, partly hydrophobic platinum-black pores, where the
    bubbles stay pinned and blind the double layer behind them: the blinded share theta grows with the gas-making charge
    (the current through the gate, second by second: inject_fresh16._grid_of) towards th_max (0.1-0.3), the session's
    charge filling 1-3 e-folds, and shrinks as the gas dissolves into the bath (tau_dis 600-2400 s, log), over the rests
    too. The conductance falls with theta and the gain with it (0.6-1 of it), relative to the first record: a loss that
    grows at every large drive and partly recovers in between; the spectra at the next series' start
    (inject_fresh9._dry_by). Measured (paper_157) displacement RMS -4.0 % (residual 4.1 %, 250x its noise), current RMS
    -6.4 % (residual 6.6 %, 5.0x its noise): the 1 V steps at 8.56, 8.40, 8.35, 8.32 mm by their plateaus' end block by
    block (8.76-8.77 mm clean), the 1 V harmonics' gain 0.964 to 0.942 (current 0.946 to 0.912); the impedance 1.042,
    1.056, 1.062x in the later blocks' spectra."""
    v_g, w = s.rng.uniform(0.6, 0.85), s.rng.uniform(0.03, 0.06)
    th_max, folds = s.rng.uniform(0.1, 0.3), s.rng.uniform(1.0, 3.0)
    tau_dis, share = lu(s.rng, 600.0, 2400.0), s.rng.uniform(0.6, 1.0)
    tg, load = _grid_of(s, "i_A", lambda i, v: np.abs(i) * _logistic((np.abs(v) - v_g) / w), 5.0)
    k = folds / max(float(np.sum(load)), 1e-30)  # per coulomb, on the 1 s grid
    th, x = np.empty(tg.size), 0.0
    for j, q in enumerate(load.tolist()):
        a = k * q + 1.0 / tau_dis
        eq = k * q * th_max / a
        x = eq + (x - eq) * math.exp(-a)
        th[j] = x
    f0 = float(np.interp(s.t0, tg, th))

    def loss(t: np.ndarray) -> np.ndarray:
        return (np.interp(np.asarray(t, float), tg, th) - f0) / (1.0 - f0)

    _dry_by(s, lambda t: share * loss(t), loss)


def dh_silt_sedimentation(s: Session) -> None:
    """A strip held horizontal, face up, in a bath filled 0-600 s before the first record with tap water drawn just
    after a repair of the building's mains (turbid with fine rust and silt, 1-5 um): the particles settle (the
    suspension clearing as exp(-u/tau_s), tau_s 1500-6000 s, log: the water column over the settling speed) onto the
    cuvette's floor and onto the strip's upper face, and each re-clamping's handling stirs the bath and puts back into
    suspension a share r (0.2-0.5) of what lies on the floor (not what sticks to the plating), so the deposit on the
    strip grows faster again after every setting. The deposit blocks the upper face's pores (its accessible area 1 -
    theta, theta = th_max (1 - exp(-D/D_s)), th_max 0.3-0.6, 1-2.5 e-folds of D_s by the session's end); the strip's
    capacitance is its two faces' in series, so the conductance falls by 1 - 2 (1 - theta)/(2 - theta) and the gain with
    it (0.6-1 of it), relative to the first record; the spectra at the next series' start (inject_fresh9._dry_by).
    Measured (p17_159) displacement RMS -11 % (residual 13 %, 250x its noise), current RMS -18 % (residual 19 %, 13x its
    noise): the 1 V steps at 2.87, 2.57, 2.44, 2.37 mm by their plateaus' end block by block (2.88-2.89 mm clean); the
    impedance 1.16, 1.24, 1.30x in the later blocks' spectra."""
    t_f, tau_s = s.t0 - s.rng.uniform(0.0, 600.0), lu(s.rng, 1500.0, 6000.0)
    r_sus, th_max = s.rng.uniform(0.2, 0.5), s.rng.uniform(0.3, 0.6)
    folds, share = s.rng.uniform(1.0, 2.5), s.rng.uniform(0.6, 1.0)
    setting = _setting_of(s)
    stirs = sorted(setting(p, a) for p, a in _by_pressure_start(s).items())[1:]
    dt = 5.0
    tg = np.arange(t_f, s.t1 + dt, dt)
    sus, floor, dep = 1.0, 0.0, np.empty(tg.size)
    d, j_stir = 0.0, 0
    for j, t in enumerate(tg.tolist()):
        while j_stir < len(stirs) and stirs[j_stir] <= t:
            sus, floor, j_stir = sus + r_sus * floor, floor * (1.0 - r_sus), j_stir + 1
        fall = sus * -math.expm1(-dt / tau_s)
        sus, floor, d = sus - fall, floor + fall, d + fall
        dep[j] = d
    d_s = max(float(np.interp(s.t1, tg, dep)), 1e-12) / folds
    theta = th_max * -np.expm1(-dep / d_s)
    cond = 1.0 - 2.0 * (1.0 - theta) / (2.0 - theta)
    c0 = float(np.interp(s.t0, tg, cond))

    def loss(t: np.ndarray) -> np.ndarray:
        return (np.interp(np.asarray(t, float), tg, cond) - c0) / (1.0 - c0)

    _dry_by(s, lambda t: share * loss(t), loss)


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_resoaked_crack_closure(s: Session) -> None:
    """A strip stored dry between sessions (in a desiccator against fouling), its plating's mud cracks opened wide as
    the membrane shrank on drying, soaked in the bath 60-600 s before the first record: the membrane re-swells through
    the session (its slow second stage of water uptake, tau 1000-3000 s, log) and pushes the cracks' faces back
    together, so the bend's tension needed to open them again rises from e0 - d0 at the soaking towards e0 (e0 0.3-0.6
    of the session's displacement scale, d0 0.6-0.9 of e0). Each face's cracks open beyond that threshold, dR/R = k ((e
    - thr)+ + o (-e - thr)+) (k 0.1-0.3, the other face o 0.5-1 of it), each record at the threshold of its middle:
    strong early, weakening as the cracks close. Gains fall by 0.03-0.08 (displacement) and 0.06-0.15 (current) per unit
    of dR/R (inject_fresh3._resist). Measured (p17_159) displacement RMS -2.4 % (residual 2.5 %, 48x its noise), current
    RMS -0.41 % (residual 2.2 %, 1.5x its noise): the 1 V records only (23 of the 68 time series touched); the 1 V steps
    at 2.78-2.79 mm by their plateaus' end (2.88-2.89 mm clean); the 1 V harmonics' gain 0.985, 0.986, 0.986, 0.987
    block by block (current 0.971, 0.975, 0.976, 0.978), their second harmonic +0.55 % (current +1.9 %)."""
    k, o, e0 = s.rng.uniform(0.1, 0.3), s.rng.uniform(0.5, 1.0), s.rng.uniform(0.3, 0.6)
    d0 = s.rng.uniform(0.6, 0.9) * e0
    t_soak, tau = s.t0 - s.rng.uniform(60.0, 600.0), lu(s.rng, 1000.0, 3000.0)

    def law(r: Rec, e: np.ndarray) -> np.ndarray:
        thr = e0 - d0 * math.exp(-(float(np.mean(r.cols["t_s"])) - t_soak) / tau)
        e = np.asarray(e, float)
        return k * (np.clip(e - thr, 0.0, None) + o * np.clip(-e - thr, 0.0, None))

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


def sr_twist_shear_cracks(s: Session) -> None:
    """A plating thicker along one edge than the other (a strip cut from the edge of its plated sheet): the strip twists
    as it bends, its faces sheared by gamma = c e (c 0.15-0.5 per unit of the bend's strain e), and a face's mud cracks
    open under its largest principal tension, not the bend's alone (Mohr's circle): e/2 + |e| sqrt(1/4 + c^2) on the
    face the bend stretches, |e| (sqrt(1/4 + c^2) - 1/2) on the compressed one, which cracks too at the large bends. The
    thin-edged face (drawn) cracks beyond e0 (0.05-0.2 of the session's displacement scale), the other beyond m e0 (m
    1.5-3): dR/R = k ((p_A - e0)+ + (p_B - m e0)+) (k 0.1-0.3), two kinks on each side, asymmetric. Gains fall by
    0.03-0.08 (displacement) and 0.06-0.15 (current) per unit of dR/R (inject_fresh3._resist). Measured (p17_159)
    displacement RMS -2.0 % (residual 2.1 %, 40x its noise), current RMS -0.27 % (residual 1.3 %, 0.87x its noise); the
    1 V steps at 2.80-2.81 mm by their plateaus' end (2.88-2.89 mm clean); the 1 V harmonics' gain 0.988 (current
    0.983), their second harmonic +0.43 % (current +1.1 %); 58 of the 68 time series touched."""
    side, k, e0 = _sign(s), s.rng.uniform(0.1, 0.3), s.rng.uniform(0.05, 0.2)
    c, m = s.rng.uniform(0.15, 0.5), s.rng.uniform(1.5, 3.0)
    q = math.sqrt(0.25 + c * c)

    def law(r: Rec, e: np.ndarray) -> np.ndarray:
        x = side * np.asarray(e, float)  # positive: the thin-edged face stretched
        a = np.abs(x)
        p_a, p_b = 0.5 * x + q * a, -0.5 * x + q * a
        return k * (np.clip(p_a - e0, 0.0, None) + np.clip(p_b - m * e0, 0.0, None))

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_em_tracking_coil(s: Session) -> None:
    """No laser: an electromagnetic tracking coil (a 0.5 mm pickup coil, its axis across the strip, of the kind that
    tracks a catheter's tip) glued at the tip, in the field of a gradient pair of coils on either side of the cuvette
    (radius R 2.5-6 times the session's largest bend, spacing 2a, a/R 0.4-0.7, driven at some tens of kHz and read by a
    lock-in whose bandwidth is far above the drives): the axial field of two opposed loops, B(z) ~ f(z - a) - f(z + a),
    f(u) = R^2/(R^2 + u^2)^(3/2), is linear at the centre and falls behind it away from there, and the coil tilts with
    the tip (its slope 2 d/L on the uniform arc), picking up cos(2 d/L) of the field: both compress the large bends,
    odd. The lab's calibration is linear at rest. Tabulated and interpolated (slope 1 at rest,
    inject_fresh22._table_map); displacement only. Measured (p17_159) displacement RMS -4.0 % (residual 4.5 %, 87x its
    noise): the 1 V steps at 2.675-2.678 mm by their plateaus' end (2.883-2.887 mm clean), the 1 V harmonics' gain
    0.986, the 20 Hz sines' 1.000."""
    big = _largest(s) or ref_disp(s)
    rad = s.rng.uniform(2.5, 6.0) * big
    a = s.rng.uniform(0.4, 0.7) * rad
    length = float(s.specimen["length_m"])

    def reading(d: np.ndarray) -> np.ndarray:
        def loop(u: np.ndarray) -> np.ndarray:
            return rad**2 / (rad**2 + u * u) ** 1.5

        return (loop(d - a) - loop(d + a)) * np.cos(2.0 * d / length)

    _table_map(s, reading)


def ld_cw_doppler_radar(s: Session) -> None:
    """No laser: a strip in air read by a continuous-wave Doppler radar module (a 2.45 GHz or a 3.2 GHz motion-sensor
    module with its mixer's IF output brought out, drawn; a 3 mm foil corner reflector at the tip) whose single channel
    reads the sine of the echo's phase, (lambda/4 pi) sin(phi_0 + 4 pi d/lambda): the lab sets the stand-off so that the
    rest sits at the channel's zero crossing (phi_0 within 0.01-0.05 rad of it, either side) and calibrates it there,
    linearly. The phase grows by 4 pi/lambda per metre of the tip's travel, so the sine falls behind at the large bends,
    odd but for the small phi_0. Tabulated and interpolated (slope 1 at rest, inject_fresh22._table_map); displacement
    only. Measured (s001_158, 3.2 GHz, phi_0 0.042 rad) displacement RMS -4.5 % (residual 5.0 %, 150x its noise): the 1
    V steps at 4.30-4.32 mm by their plateaus' end (4.65-4.68 mm clean), the 1 V harmonics' gain 0.981, the 20 Hz sines'
    1.000."""
    freq = 2.45e9 if s.rng.random() < 0.5 else 3.2e9
    lam = 299792458.0 / freq
    phi0 = _sign(s) * s.rng.uniform(0.01, 0.05)
    _table_map(s, lambda d: np.sin(phi0 + 4.0 * np.pi * d / lam) - math.sin(phi0))


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_mercury_lamp_ballast(s: Session) -> None:
    """The fluorescence microscope on the next bench switched on at a moment 10-50 % into the session and left on (a
    mercury short-arc lamp must not be cycled): its 100 W lamp on a magnetic ballast (an inductor in the line) draws, as
    the arc warms over tau_w (60-200 s, log), a current falling from m0 (1.5-2.2) times its running value while the
    arc's voltage climbs and the current's waveform flattens (its 3rd harmonic growing to 0.15-0.3, its 5th to 0.05-0.15
    of the fundamental); the ballast's stray field, in proportion to that current, reaches the laser's cable and the
    current amplifier's input: 3-10 um (log) and 15-50 uA (log) at the running current, phase locked to the session
    clock (the line 50 or 60 Hz, inject_fresh12._line_f), sampled as the DAQ samples it (the harmonics alias at 200
    samples a second). Displacement and current, from the switch-on only. Measured (paper_157: 60 Hz, on 1019 s into the
    session, 3.2 um and 27 uA running, m0 2.2) displacement residual 0.060 % of its RMS (3.7x its noise), current
    residual 0.53 % (0.40x its noise); 51 of the 68 time series touched."""
    f0 = _line_f(s)
    t_on = s.t0 + s.rng.uniform(0.1, 0.5) * (s.t1 - s.t0)
    m0, tau_w = s.rng.uniform(1.5, 2.2), lu(s.rng, 60.0, 200.0)
    h3, h5 = s.rng.uniform(0.15, 0.3), s.rng.uniform(0.05, 0.15)
    amp = {"disp_m": lu(s.rng, 3e-6, 1e-5), "i_A": lu(s.rng, 1.5e-5, 5e-5)}
    phase = {col: s.rng.uniform(0.0, 2.0 * np.pi) for col in amp}
    for r in s.series():
        t = r.cols["t_s"]
        on = t >= t_on
        if not on.any():
            continue
        u = np.clip(t - t_on, 0.0, None)
        warm, size = -np.expm1(-u / tau_w), 1.0 + (m0 - 1.0) * np.exp(-u / tau_w)
        for col, a_ in amp.items():
            w = 2.0 * np.pi * f0 * t + phase[col]
            hum = np.cos(w) + warm * (h3 * np.cos(3.0 * w) + h5 * np.cos(5.0 * w))
            r.cols[col] = r.cols[col] + a_ * np.where(on, size * hum, 0.0)


def mp_worn_fluorescent_tube(s: Session) -> None:
    """The fluorescent tube over the bench on its magnetic ballast, near its end of life: one electrode's emitter worn,
    it conducts unequally on the two half-cycles, so its light carries the line frequency itself beside the usual
    flicker at twice it: light ~ abs(sin w) + a sin w - 2/pi, w the line's phase (50 or 60 Hz, inject_fresh12._line_f).
    The laser's receiver takes the room's light as a shift of its spot's image, 1-4 um (log) for the flicker's 2f
    component; the asymmetry a wanders as the worn electrode's hot spot moves (a log-normal walk about a_0 0.1-0.5, an
    Ornstein-Uhlenbeck process of 30-200 s, log) and jumps 2-4x in the tube's visible flickering spells (3-8 of 2-10 s,
    log). The displacement only (light). Measured (p17_159: 50 Hz, 2.8 um, a_0 0.28) displacement residual 0.23 % of its
    RMS (4.5x its noise), every time series touched."""
    f0 = _line_f(s)
    a2, a0, tau = lu(s.rng, 1e-6, 4e-6), s.rng.uniform(0.1, 0.5), lu(s.rng, 30.0, 200.0)
    tg = _session_grid(s, 1.0, 2.0)
    walk = a0 * np.exp(0.4 * _ou(s, tg, tau))
    spells = [(a, b, s.rng.uniform(2.0, 4.0)) for a, b in _bursts(s, int(s.rng.integers(3, 9)), (2.0, 10.0))]
    ph = s.rng.uniform(0.0, 2.0 * np.pi)
    for r in s.series():
        t = r.cols["t_s"]
        asym = np.interp(t, tg, walk)
        for a, b, jump in spells:
            asym = np.where((t >= a) & (t < b), asym * jump, asym)
        w = 2.0 * np.pi * f0 * t + ph
        light = np.abs(np.sin(w)) + asym * np.sin(w) - 2.0 / np.pi
        r.cols["disp_m"] = r.cols["disp_m"] + a2 * light / (4.0 / (3.0 * np.pi))


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_unmonitored_drive_distortion(s: Session) -> None:
    """The drive monitored at the DAQ's output (v_V the command), the strip driven through the lab's own single-ended
    class-A buffer (one transistor biased for a +-1 V swing): its transfer bends with the swing, adding a share a2 (1-3
    % at 1 V, either sign) of v^2 to the strip's drive, a DC shift and a second harmonic that the monitor never shows.
    The strip answers that unseen drive through its measured unit-step responses (inject_fresh7._superpose): a second
    harmonic and a shift in both the current and the displacement, in proportion to the strip's own response at 2f, four
    times larger on the 1 V records than on the 0.5 V ones. Measured (paper_157 and p17_159, a2 +0.016) displacement RMS
    +1.4 % (residual 1.5 %, 91x and 29x its noise), current residual 0.62 % and 0.56 % (0.47x and 0.39x): the 1 V steps
    +1.6 % (8.90 mm for 8.76; 2.93 for 2.88), the 1 V harmonics' second harmonic 0.55-0.57 % of their fundamental in the
    displacement and 1.0 % in the current, their fundamental within 0.05 %."""
    a2 = _sign(s) * s.rng.uniform(0.01, 0.03)
    _superpose(s, {id(r): a2 * r.cols["v_V"] ** 2 for r in s.series()})


def out_current_offset_drift(s: Session) -> None:
    """The current amplifier's offset warming up: a transimpedance stage on a FET-input op-amp switched on 0-600 s
    before the first record, its input offset and bias current drifting with its die's temperature towards o_inf (30-80
    uA of reading, log, either sign) with tau 600-2000 s (log), and wandering about that with the room (an
    Ornstein-Uhlenbeck process of 3-8 uA, log, 200-600 s): an offset on every current sample that depends on neither the
    drive nor the strip, drifting through the session. The current only. Measured (s001_158: +46 uA, tau 1060 s) current
    residual 1.2 % of its RMS (3.4x its noise), the 1 V steps' plateaus +0.010, +0.024, +0.038, +0.040 mA block by
    block; (p17_159: +40 uA, 890 s) 1.2 % (0.80x its noise: the 16 mm strip's current is noisier), +0.001, +0.029,
    +0.037, +0.040 mA."""
    o_inf = _sign(s) * lu(s.rng, 3e-5, 8e-5)
    t_on, tau = s.t0 - s.rng.uniform(0.0, 600.0), lu(s.rng, 600.0, 2000.0)
    tg = _session_grid(s, 1.0, 2.0)
    wander = lu(s.rng, 3e-6, 8e-6) * _ou(s, tg, lu(s.rng, 200.0, 600.0))
    for r in s.series():
        t = r.cols["t_s"]
        warm = o_inf * -np.expm1(-np.clip(t - t_on, 0.0, None) / tau)
        r.cols["i_A"] = r.cols["i_A"] + warm + np.interp(t, tg, wander)


def out_post_ringdown(s: Session) -> None:
    """The clamp held at the end of a long slender stand post (a 10-12 mm rod, 30-50 cm, its own first bending mode at
    f_p 1-4 Hz, lightly damped, zeta_p 0.002-0.006): each re-clamping's turning of the screw (at the setting,
    inject_fresh25._setting_of) sets the post ringing with 0.1-0.4 mm (log, a random phase) of sway along the bending
    direction, which dies away over tens of seconds into the block's first records; the laser, on its own stand, reads
    the tip's absolute motion, the post's through the strip's base-excitation transmissibility at f_p
    (inject_fresh23._transmissibility from the preset's first resonance at the setting's pressure, damping 0.05-0.15). A
    decaying tone at a frequency no drive has, after every setting only. Displacement only. Measured (paper_157: 3.61
    Hz, 9 s to 1/e) displacement residual 0.20 % of its RMS (12x its noise), 9 of the 68 time series touched; (s001_158:
    1.64 Hz, 17 s) 0.43 % (13x), 20 touched."""
    f_p, zeta_p, zeta = s.rng.uniform(1.0, 4.0), s.rng.uniform(0.002, 0.006), s.rng.uniform(0.05, 0.15)
    setting = _setting_of(s)
    kicks = sorted((setting(p, a), p) for p, a in _by_pressure_start(s).items())
    sizes = [(lu(s.rng, 1e-4, 4e-4), s.rng.uniform(0.0, 2.0 * np.pi)) for _ in kicks]
    wp, cache = 2.0 * math.pi * f_p, {}
    wd = wp * math.sqrt(1.0 - zeta_p**2)
    for r in s.series():
        t = r.cols["t_s"]
        add = np.zeros(t.size)
        for (ts, p), (a_, ph) in zip(kicks, sizes):
            u = t - ts
            if u[-1] <= 0.0 or zeta_p * wp * u[0] > 25.0:
                continue
            T = _transmissibility(2.0 * math.pi * _f1(s, p, cache), zeta, wp)
            env = np.exp(-zeta_p * wp * np.clip(u, 0.0, None)) * (u >= 0.0)
            add += a_ * abs(T) * env * np.cos(wd * u + ph + np.angle(T))
        r.cols["disp_m"] = r.cols["disp_m"] + add


def out_stale_short_correction(s: Session) -> None:
    """The impedance analyser's short compensation left enabled from another set-up (its fixture and long leads: R_c
    1.5-5 ohm, log, and L_c 0.2-1 uH, log, stored when the lab shorted them), subtracted from every point it measures on
    this rig's short leads: every spectrum reads Z - (R_c + j w L_c), its high-frequency resistance a few ohms below the
    strip's (the time series' step spikes say otherwise), its low-frequency part hardly touched. No time series touched.
    Measured (paper_157: 1.52 ohm, 0.98 uH) the spectra's resistance at 10 kHz 26.9-29.4 ohm (28.4-30.9 clean), |Z| at
    0.1 Hz -0.5 %; (s001_158: 3.73 ohm, 0.42 uH) 46.8-48.1 ohm (50.5-51.8), -1.3 %."""
    r_c, l_c = lu(s.rng, 1.5, 5.0), lu(s.rng, 2e-7, 1e-6)
    for r in s.recs:
        if not r.series:
            r.cols["z_re_ohm"] = r.cols["z_re_ohm"] - r_c
            r.cols["z_im_ohm"] = r.cols["z_im_ohm"] - 2.0 * np.pi * r.cols["f_Hz"] * l_c


FRESH29_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"heavy_water_swap": br_heavy_water_swap, "ptfe_bonded_electrodes": br_ptfe_bonded_electrodes},
    "faradaic_current": {"hygroscopic_ionic_liquid": far_hygroscopic_ionic_liquid,
                         "glucose_medium": far_glucose_medium},
    "hysteresis": {"prussian_blue_layer": hy_prussian_blue_layer, "stacked_pair": hy_stacked_pair},
    "time_delay": {"unsynced_second_card": td_unsynced_second_card, "shunt_rfi_filter": td_shunt_rfi_filter},
    "sensor_offset": {"bleaching_stripe": so_bleaching_stripe, "inboard_hall_magnet": so_inboard_hall_magnet},
    "clamp_relaxation": {"voice_coil_magnet": cr_voice_coil_magnet, "sponge_pads_drying": cr_sponge_pads_drying},
    "dehydration": {"gas_blinded_plating": dh_gas_blinded_plating, "silt_sedimentation": dh_silt_sedimentation},
    "strain_resistance": {"resoaked_crack_closure": sr_resoaked_crack_closure,
                          "twist_shear_cracks": sr_twist_shear_cracks},
    "large_deflection": {"em_tracking_coil": ld_em_tracking_coil, "cw_doppler_radar": ld_cw_doppler_radar},
    "mains_pickup": {"mercury_lamp_ballast": mp_mercury_lamp_ballast,
                     "worn_fluorescent_tube": mp_worn_fluorescent_tube},
    "unexplained": {"unmonitored_drive_distortion": out_unmonitored_drive_distortion,
                    "current_offset_drift": out_current_offset_drift, "post_ringdown": out_post_ringdown,
                    "stale_short_correction": out_stale_short_correction},
}
inject.register_forms(FRESH29_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def v_eis_two_passes(s: Session) -> None:
    """An impedance analyser set to measure each spectrum twice and to write both passes into one file (an impedance
    technique set to repeat, as potentiostat software offers, its repeats written into the same file: a stationarity
    check), each pass as the analyser sweeps it, from its highest frequency down: the first pass's rows (the session's
    values), then the second's, the same impedance measured again with the analyser's own repeatability (each point
    times 1 + n, n complex, its real and imaginary parts normal with sigma 0.1-0.3 %, drawn per spectrum). Every
    spectrum's f_Hz runs down twice, each frequency appearing twice; the time series and the manifest untouched. The
    import contract asks f_Hz positive, neither increasing nor distinct; ``labrig import`` stores the rows as written,
    and ``labrig export`` writes them back bit for bit (all four cases checked)."""
    for r in s.recs:
        if r.series:
            continue
        sig = s.rng.uniform(0.001, 0.003)
        order = np.argsort(-r.cols["f_Hz"], kind="stable")
        f, z = r.cols["f_Hz"][order], r.cols["z_re_ohm"][order] + 1j * r.cols["z_im_ohm"][order]
        again = z * (1.0 + sig * (s.rng.normal(size=f.size) + 1j * s.rng.normal(size=f.size)) / math.sqrt(2.0))
        r.cols = {"f_Hz": np.r_[f, f], "z_re_ohm": np.r_[z.real, again.real], "z_im_ohm": np.r_[z.imag, again.imag]}


inject.VARIANTS.update({"eis_two_passes": v_eis_two_passes})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_157", "s001_158", "p17_159"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 6 / 7 effect cases on seeds 157-159
    "back_relaxation": [("heavy_water_swap", 157, P, "settled_sines"), ("ptfe_bonded_electrodes", 159, T, "log_steps")],
    "faradaic_current": [("hygroscopic_ionic_liquid", 158, S, "fixed_decimals"),
                         ("glucose_medium", 157, P, "shortened_shuffled")],
    "hysteresis": [("prussian_blue_layer", 157, P, "asrun"), ("stacked_pair", 158, S, "swinging_door")],
    "time_delay": [("unsynced_second_card", 158, S, "trigger_clock"), ("shunt_rfi_filter", 157, P, "eis_two_passes")],
    "sensor_offset": [("bleaching_stripe", 158, S, "scan_hold"), ("inboard_hall_magnet", 159, T, "midnight_clock")],
    "clamp_relaxation": [("voice_coil_magnet", 157, P, "measured_pressures"),
                         ("sponge_pads_drying", 158, S, "merged_loadcell")],
    "dehydration": [("gas_blinded_plating", 157, P, "split_spectra"), ("silt_sedimentation", 159, T, "eis_descending")],
    "strain_resistance": [("resoaked_crack_closure", 159, T, "float32_time"),
                          ("twist_shear_cracks", 159, T, "block_clock")],
    "large_deflection": [("em_tracking_coil", 159, T, "eis_two_passes"),
                         ("cw_doppler_radar", 158, S, "coherent_sines")],
    "mains_pickup": [("mercury_lamp_ballast", 157, P, "dropped_packets"),
                     ("worn_fluorescent_tube", 159, T, "short_pretrigger")],
    "unexplained": [("unmonitored_drive_distortion", 157, P, "cycle_averaged"),
                    ("unmonitored_drive_distortion", 159, T, "stop_trigger"),
                    ("current_offset_drift", 158, S, "no_loadcell"), ("current_offset_drift", 159, T, "fir_decimated"),
                    ("post_ringdown", 157, P, "reversed_laser"), ("post_ringdown", 158, S, "host_timed"),
                    ("stale_short_correction", 157, P, "spectra_last"),
                    ("stale_short_correction", 158, S, "steps_sines")],
}
CLEAN = [(157, P, "eis_two_passes"), (157, P, "two_pressures"), (158, S, "tared_records"),
         (158, S, "loadcell_dropout"), (159, T, "eis_two_passes"), (159, T, "no_spectra")]


def fresh29_cases(only: str | None = None) -> list[Case]:
    """The thirtieth held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds
    157-159)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh29_cases, "inject_fresh29", "fresh29")
