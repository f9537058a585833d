"""A thirty-third held-out set for the diagnosis (issue 12), fresh32, written without sight of the diagnosis (its code,
its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh31.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (the plating's pores wetted by the drive's
own potential, sulfide stripped off the platinum by each large anodic excursion, formaldehyde from a fixative whose
oxidation the platinum's oxide shuts off, blistered plating snapping through, a CdS photoresistor's light-dependent
response time, cracks at the jaw's edge opened by the root's inertial shear, a slack pump membrane at the tip, a
magnetic centring spring) and some on the history, the clamp pressure or the session's events (the bath changed for cold
tap water at one re-clamping, a colleague's ultrasonic cleaner dithering the tip's friction, the laser's readings queued
behind a motorised clamp's bus traffic after each setting, the clamp's stand sinking into a foam mat, a battery-powered
electromagnet clamp, gelatin pads eroding in the bath, a colleague decanting liquid nitrogen, a gel-electrophoresis run
on the next bench, the logging PC's monitor waking at each re-clamping) and some on time (an ice bath on the bench
acting as a cold trap while it melts, a conformal lacquer curing over cracked plating); lab wiring or sensors among them
(the CAN bus, the photoresistor, the digital image correlation, the electromagnet's battery, the power supplies, the
monitor). Four structures outside the catalogue (truth "unexplained": the current cleaned by an acausal FFT brick-wall
filter in the export script; the impedance analyser's autorange leaving a calibration step in every spectrum; the laser
controller's output left in peak-hold mode; a worn range switch on the current amplifier); clean sessions. All on three
bases of new seeds (166-168: the paper strip, the seed-001 strip on its own sweep, the paper strip 13 mm free) and on
the earlier sets' data-shape variants plus one new here: a manifest with only the keys the import contract requires
(``minimal_manifest``).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh31 are reused (importing inject_fresh31 and inject_fresh30 registers every earlier set's
lookups), and the forms, bases, preset and variant of this set are registered into inject's lookups at import, none
replaced. Strengths are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it
made on its case, measured in memory against the clean base (relative RMS change over all series, form only, no variant;
"noise": the column's sample-to-sample noise at rest, inject_fresh15.rest_noise).

Run: python bench/inject_fresh32.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np

import inject
import inject_fresh30  # noqa: F401  (registers fresh30's forms, bases, preset and variant; fresh31 does not import it)
import inject_fresh31  # noqa: F401  (registers every other earlier set's forms, bases, presets and variants)
from inject import Case, Rec, Session, lu, map_disp, ref_disp
from inject_fresh2 import _chrono, _map_through, _spec
from inject_fresh3 import _resist, _sign, _through_x
from inject_fresh4 import _clamp_law
from inject_fresh6 import _bursts
from inject_fresh9 import _dry_by, _session_grid
from inject_fresh10 import _lag_varying, _station
from inject_fresh12 import _line_f
from inject_fresh14 import _largest
from inject_fresh22 import _table_map
from inject_fresh25 import _setting_of
from inject_fresh26 import _held_by, _later_setting, _split_noise
from inject_fresh29 import _grid_lag, _logistic
from inject_fresh29 import _first_mode
from inject_fresh31 import _on_grid, _relay_states, _settings

# the paper's strip 13 mm free (earlier sets used 14-29 and 31-45 mm, 30 mm is the paper preset itself and the seed-001
# strip is 20 mm): its 1 V step peaks at 1.71 mm, well inside the laser's +-20 mm (2 mm/V on the DAQ's +-10 V) and 3000x
# the laser's 0.58 um noise at rest. Preset "paper_13", base "p13_168", registered in every process importing this
# module
inject.register_free_length("paper_13", 0.013)

inject.BASES.update({
    "paper_166": ("paper-sweep", "paper", 166),
    "s001_167": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 167),
    "p13_168": ("paper-sweep", "paper_13", 168),
})


# ------------------------------------------------------------------------------------------------ tools


def _series_of(s: Session, col: str) -> tuple[np.ndarray, np.ndarray]:
    """A column over the whole session in time order (times, values), for interpolation (linear across the rests)."""
    recs = _chrono(s)
    return np.concatenate([r.cols["t_s"] for r in recs]), np.concatenate([r.cols[col] for r in recs])


def _first_order_varying(x: np.ndarray, fs: float, tau: np.ndarray) -> np.ndarray:
    """x through a first-order lag whose time constant changes sample by sample (tau per sample), settled on x's first
    sample."""
    a = np.exp(-1.0 / (fs * np.asarray(tau, float)))
    out = np.empty(x.size)
    y = float(x[0])
    for k, (xk, ak) in enumerate(zip(x.tolist(), a.tolist())):
        y = xk + (y - xk) * ak
        out[k] = y
    return out


# ------------------------------------------------------------------------------------------------ back relaxation


def br_cold_water_change(s: Session) -> None:
    """The back-flow through the membrane (K2 0.5-0.9, tau 2-8 s, log, at the room's 23 C) in a bath that the operator
    empties and refills with cold tap water at one re-clamping after the first (drawn; 0-60 s before that setting: the
    water looked cloudy), 6-12 K below the room's, warming back over tau_w 300-1200 s (log). Water's diffusivity in
    Nafion is thermally activated (E_a 20-35 kJ/mol), so the back-flow slows in the cold, tau exp(E_a/R (1/T - 1/T0)),
    and the membrane holds a little less free water (K2 times 1 - c dT, c 0.5-1.5 %/K), both recovering as the bath
    warms. Through inject_fresh10._lag_varying (the reading d - K2 x, x the lag of d, sample by sample through the
    session, carried over the rests); displacement only. Measured (p13_168: the water 9.9 K below the room's from 3 s
    before the 1837 kPa setting; tau 2.1 s at 23 C, 2.8 s in the cold, K2 0.50 and 0.44) displacement RMS -46 %
    (residual 47 %, 540x its noise): the 1 V steps at 0.88, 0.98, 0.90, 0.89 mm by their plateaus' end block by block
    (1.71 mm clean); the 0.1 Hz harmonics' gain 0.83, 0.89, 0.85, 0.84."""
    k_room, tau_room = s.rng.uniform(0.5, 0.9), lu(s.rng, 2.0, 8.0)
    d_t, tau_w = s.rng.uniform(6.0, 12.0), lu(s.rng, 300.0, 1200.0)
    e_a, c_k = s.rng.uniform(20e3, 35e3), s.rng.uniform(0.005, 0.015)
    _, t_set = _later_setting(s)
    t_c, t0 = t_set - s.rng.uniform(0.0, 60.0), 296.15

    def state(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        t = np.asarray(t, float)
        cold = np.where(t >= t_c, d_t * np.exp(-np.clip(t - t_c, 0.0, None) / tau_w), 0.0)
        return k_room * (1.0 - c_k * cold), tau_room * np.exp(e_a / 8.314 * (1.0 / (t0 - cold) - 1.0 / t0))

    _lag_varying(s, state)


def br_electrocapillary_pores(s: Session) -> None:
    """A strip whose back-flow is exchanged with the bath through its plating's pores (the cathode side giving its
    excess up, the anode side drawing water back), the pores left partly hydrophobic by the organics of the plating's
    reducer that the lab never burnt off. Each face's potential (half the drive) wets them (electrocapillarity:
    Lippmann's cos theta rises with the square of the interface's voltage over its double layer), so the exchange runs
    faster while the drive is high: tau = tau_0 / (1 + m v^2) (tau_0 4-15 s, log, at rest; m 2-6 at 1 V), K2 0.5-0.9. A
    1 V step gives back fast on its plateau and the give-back after its fall drains slowly; the 0.5 V sines see tau_0 /
    (1 + m/4) at their crests. Through inject_fresh10._lag_varying (the drive read on the session's series, 0 over the
    rests); displacement only. Measured (paper_166: tau_0 4.5 s, m 3.2, K2 0.74) displacement RMS -73 % (residual 77 %,
    4600x its noise): the 1 V steps at 2.36 mm by their plateaus' end (8.82-8.83 mm clean) and 0.53 mm 2 s after their
    fall (6.64 mm clean); the 1 V harmonics' gain 0.65 (+30 deg), the 0.5 V 0.1 Hz sines' 0.86 (+19 deg)."""
    k2, tau0, m = s.rng.uniform(0.5, 0.9), lu(s.rng, 4.0, 15.0), s.rng.uniform(2.0, 6.0)
    tv, vv = _series_of(s, "v_V")

    def state(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        v = np.interp(np.asarray(t, float), tv, vv)
        return np.full(v.shape, k2), tau0 / (1.0 + m * v**2)

    _lag_varying(s, state)


# ------------------------------------------------------------------------------------------------ faradaic current


def far_sulfide_stripping(s: Session) -> None:
    """A bath made up in a beaker closed with a rubber stopper (its vulcanisation accelerators release sulfide, a few
    uM): sulfide adsorbs on platinum at open circuit and is stripped oxidatively (S + 4 H2O -> SO4-- + 8 H+ + 6 e-) only
    from whichever face is the anode beyond E_s (0.6-0.85 V of drive), at the rate (exp((abs(v) - E_s)/b) -
    exp(-E_s/b))/tau_s (b 0.06-0.1 V, tau_s 1-5 s at E_s, log), each face's monolayer worth Q 0.1-0.4 mC (log); it
    re-adsorbs from the bath at (1 - theta)/tau_a (tau_a 30-200 s, log), over the rests too. An anodic stripping current
    in the drive's direction on the first large excursion after a rest, spent by the next one. Charge-conserving sample
    by sample through the session in time order (exact for the rate held over each sample); the current only. Measured
    (paper_166: Q 0.12 mC, E_s 0.71 V, tau_a 99 s) current RMS +0.15 % (residual 1.1 %, 0.84x its noise over the
    session, 77x at the peaks): a stripping peak of 3.2 mA at each 1 V step's edge (0.16 mC over the step, what
    re-adsorbs on its plateau stripped too), 0.23 mA on the 1 V harmonics' crests, under 3 uA on the 0.5 V sines."""
    q = lu(s.rng, 1e-4, 4e-4)
    e_s, b, tau_s = s.rng.uniform(0.6, 0.85), s.rng.uniform(0.06, 0.1), lu(s.rng, 1.0, 5.0)
    a = 1.0 / lu(s.rng, 30.0, 200.0)
    foot = math.exp(-e_s / b)
    th = [1.0, 1.0]  # face A (the anode for v > 0), face B
    t_end = None
    for r in _chrono(s):
        t, v = r.cols["t_s"], r.cols["v_V"]
        if t_end is not None:
            keep = math.exp(-a * max(float(t[0]) - t_end, 0.0))
            th = [1.0 - (1.0 - x) * keep for x in th]
        dt = 1.0 / r.fs
        back = math.exp(-a * dt)
        out = np.empty(v.size)
        for k, vk in enumerate(v.tolist()):
            f = 0 if vk > 0 else 1
            kk = (math.exp(min((abs(vk) - e_s) / b, 50.0)) - foot) / tau_s  # balanced at open circuit
            lam = kk + a
            eq = a / lam
            e = math.exp(-lam * dt)
            stripped = kk * (eq * dt + (th[f] - eq) * (1.0 - e) / lam)
            th[f] = eq + (th[f] - eq) * e
            th[1 - f] = 1.0 - (1.0 - th[1 - f]) * back
            out[k] = (1.0 if f == 0 else -1.0) * q * stripped / dt
        r.cols["i_A"] = r.cols["i_A"] + out
        t_end = float(t[-1])


def far_fixative_formaldehyde(s: Session) -> None:
    """A strip tested in a tissue phantom's fixative (formalin carried over from the phantom's preparation: 0.1-1 %
    formaldehyde): platinum oxidises formaldehyde at whichever face is the anode, a wave from E_f (0.15-0.35 V of drive,
    width 0.04-0.08 V) to a diffusion-limited i_max (0.15-0.5 mA, log; the wave's foot at 0 V taken off), but only on
    bare platinum: beyond E_ox (0.7-0.9 V of drive) the face's oxide forms (tau 0.02-0.2 s, log) and shuts the oxidation
    off, and the oxide is reduced only once the face falls below E_r (0.3-0.5 V: the oxide's irreversibility), so on the
    way back down the current reappears late, a reactivation peak. A rate-independent loop in the current, odd; each
    face's oxide carried through the session (reduced at rest). The current only. Measured (p13_168: i_max 0.17 mA, E_f
    0.30 V, E_ox 0.75 V, E_r 0.49 V) current RMS +1.8 % (residual 3.0 %, 1.9x its noise): +0.15 mA at each 1 V step's
    edge, nothing on its plateau (the oxide on); +0.15 mA at the 0.5 V sines' crests (their current's gain 1.08-1.09 at
    0.1 Hz, 1.013 at 20 Hz), up to 0.17 mA on the 1 V harmonics."""
    i_max = lu(s.rng, 1.5e-4, 5e-4)
    e_f, w = s.rng.uniform(0.15, 0.35), s.rng.uniform(0.04, 0.08)
    w0 = float(_logistic(np.array([-e_f / w]))[0])  # the wave's foot at 0 V, taken off: nothing at rest
    e_ox, e_r = s.rng.uniform(0.7, 0.9), s.rng.uniform(0.3, 0.5)
    tau_ox, tau_r = lu(s.rng, 0.02, 0.2), lu(s.rng, 0.02, 0.2)
    ox = [0.0, 0.0]
    t_end = None
    for r in _chrono(s):
        t, v = r.cols["t_s"], r.cols["v_V"]
        if t_end is not None:
            ox = [x * math.exp(-max(float(t[0]) - t_end, 0.0) / tau_r) for x in ox]
        dt = 1.0 / r.fs
        ga, gr = -math.expm1(-dt / tau_ox), -math.expm1(-dt / tau_r)
        wave = i_max * (_logistic((np.abs(v) - e_f) / w) - w0) / (1.0 - w0)
        out = np.empty(v.size)
        for k, (vk, wk) in enumerate(zip(v.tolist(), wave.tolist())):
            for f, u in ((0, vk), (1, -vk)):
                if u > e_ox:
                    ox[f] += ga * (1.0 - ox[f])
                elif u < e_r:
                    ox[f] -= gr * ox[f]
            f = 0 if vk > 0 else 1
            out[k] = (1.0 if vk > 0 else -1.0 if vk < 0 else 0.0) * wk * (1.0 - ox[f])
        r.cols["i_A"] = r.cols["i_A"] + out
        t_end = float(t[-1])


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_blister_snap_through(s: Session) -> None:
    """A plating with blisters (patches lifted off the membrane after drying and re-soaking, a known IPMC defect): a
    shallow dome of platinum snaps through when its face is compressed past its critical strain and snaps back only once
    the compression has fallen well below it (the dome's bistability). Eight blisters, each on one face (drawn),
    snapping in at a compression of 0.2-0.7 of the session's largest bend and back at 0.2-0.6 of that; a snapped blister
    relieves its face's compression and adds its share (0.02-0.05 of the largest bend over all eight) to the bend
    towards that face. Relays on the bend, not on the drive: a loop that stays as the drive slows, reset over the rests;
    through the strip's first mode (labrig.physics.transfer.modal_set, inject_fresh3._through_x); displacement only.
    Measured (s001_167: the eight blisters' share 0.025 of the largest bend) displacement RMS +3.2 % (residual 3.4 %,
    110x its noise): the 1 V steps +0.11 mm on their plateaus (4.80-4.83 mm for 4.69-4.72 clean) and still +0.11 mm 2 s
    after their fall; the 1 V harmonics' gain 1.03-1.04; 8 of the 68 series touched (the 0.5 V sines reach no
    blister)."""
    n = 8
    big = _largest(s) or ref_disp(s)
    faces = np.where(s.rng.random(n) < 0.5, 1.0, -1.0)  # +1: the face a positive bend compresses
    a_in = s.rng.uniform(0.2, 0.7, n) * big
    a_out = a_in * s.rng.uniform(0.2, 0.6, n)
    g = s.rng.uniform(0.02, 0.05) * s.rng.dirichlet(np.ones(n)) * big * faces
    state = np.zeros(n)
    bend = {}
    for r in _chrono(s):
        c = faces[None, :] * r.cols["disp_m"][:, None]  # each blister's face compression
        ev = np.where(c > a_in[None, :], 1.0, np.where(c < a_out[None, :], 0.0, np.nan))
        filled = _relay_states(state, ev)
        state = filled[-1].copy()
        bend[id(r)] = filled @ g
    moved = _through_x(s, bend, _first_mode(s), 2.0)
    for r in s.series():
        r.cols["disp_m"] = r.cols["disp_m"] + moved[id(r)]


def hy_ultrasonic_dither(s: Session) -> None:
    """The tip run between two PTFE guide pins (to keep a long strip in the laser's plane), set a hair too close: their
    dry friction holds the tip while the strip's pull stays within r0 (0.005-0.02 of the session's largest bend, log) of
    where it sticks. A colleague's ultrasonic cleaner on the same bench runs in 2-5 spells of 3-15 min (log, each
    starting inside a recorded series): its vibration dithers the contact and the friction all but vanishes (the radius
    0.1-0.4 of r0) while it runs. Rate-independent memory whose width the session's events set; dry friction sample by
    sample through the session in time order, the laser's noise kept on the held reading (inject_fresh26._held_by);
    displacement only. Measured (paper_166: r0 0.091 mm, 5 spells, 26 of the 68 series inside one) displacement RMS
    -0.28 % (residual 2.2 %, 130x its noise): the 1 V steps held 0.09 mm short of their peaks and 0.09 mm up 2 s after
    their fall; the 0.5 V 0.1 Hz sines' gain 0.96 (-6 deg) outside the spells, 0.998 (-0.8 deg) in one; the sines above
    9 Hz, their few um within the friction, held still outside the spells."""
    big = _largest(s) or ref_disp(s)
    r0, q = lu(s.rng, 0.005, 0.02) * big, s.rng.uniform(0.1, 0.4)
    spells = _bursts(s, int(s.rng.integers(2, 6)), (180.0, 900.0))

    def radius(r: Rec, sig: np.ndarray) -> np.ndarray:
        t = r.cols["t_s"]
        on = np.zeros(t.size, bool)
        for a, b in spells:
            on |= (t >= a) & (t < b)
        return np.where(on, q * r0, r0)

    _held_by(s, radius)


# ------------------------------------------------------------------------------------------------ time delay


def td_canbus_arbitration(s: Session) -> None:
    """The laser's readings sent over the rig's CAN bus (a CANopen process-data object, stamped by the logger on
    arrival) that it shares with the motorised clamp's servo drive: the laser's frames have the lower priority and wait
    for the bus. At rest the wait is its own frame time and a little, tau_0 1-3 ms (log); after each setting the servo
    regulates the force and floods the bus with its status frames, the laser's frames queuing behind them, an extra
    tau_b 3-10 ms (log) that fades as the servo settles, exp(-u/tau_s) (tau_s 120-600 s, log, from each setting,
    inject_fresh31._settings). A delay that changes with the time since the last setting; the displacement read late by
    it (interpolated, the record's first value held before it). Measured (s001_167: tau_0 2.8 ms, tau_b 5.7 ms, tau_s
    200 s) displacement residual 0.13 % of its RMS (4.3x its noise): the 1 V steps (each block's first record, 24-38 s
    after its setting) 7.0-7.3 ms late, the 20 Hz sines at the blocks' ends 2.9 ms (-20.6 deg), the 0.1 Hz records -0.15
    deg."""
    tau0, taub, taus = lu(s.rng, 1e-3, 3e-3), lu(s.rng, 3e-3, 1e-2), lu(s.rng, 120.0, 600.0)
    sets = np.array([ts for ts, _ in _settings(s)])

    def late(t: np.ndarray) -> np.ndarray:
        k = np.searchsorted(sets, t, side="right") - 1
        since = np.where(k >= 0, t - sets[np.clip(k, 0, None)], np.inf)
        return tau0 + taub * np.exp(-since / taus)

    map_disp(s, lambda r, d: np.interp(r.cols["t_s"] - late(r.cols["t_s"]), r.cols["t_s"], d, left=d[0]))


def td_ldr_shadow_sensor(s: Session) -> None:
    """No laser: a shadow sensor built from an LED and a CdS photoresistor, a vane at the tip cutting into the beam (a
    lab's cheap readout), linearised by a table made at rest. CdS answers slowly and the more slowly the less light it
    gets: its time constant tau = tau_b (E/E_b)^-gamma (tau_b 1.5-4 ms, log, in the full beam; gamma 0.5-0.8), and the
    vane shades the cell more as the tip moves to one side (drawn), the light E/E_b = 1 -+ c d/D (c 0.3-0.6 at the
    session's largest bend D). A lag that lengthens on one side of the bend; first order sample by sample within each
    record, settled on its first sample, the sensor's noise kept (inject_fresh26._split_noise); displacement only.
    Measured (p13_168: tau_b 3.8 ms, gamma 0.68, c 0.58, the positive bends in the brighter light) displacement residual
    0.29 % of its RMS (3.3x its noise): the 20 Hz sines -22 deg (gain 0.90), the 9.4 Hz ones -9.4 deg (0.975), the 0.1
    Hz records -0.06 deg; the 1 V steps' rise up to 8 um behind."""
    big = _largest(s) or ref_disp(s)
    side, c = _sign(s), s.rng.uniform(0.3, 0.6)
    tau_b, gam = lu(s.rng, 1.5e-3, 4e-3), s.rng.uniform(0.5, 0.8)
    for r in s.series():
        sig, noise = _split_noise(r)
        light = np.clip(1.0 - side * c * sig / big, 0.2, None)
        r.cols["disp_m"] = _first_order_varying(sig, r.fs, tau_b * light**-gam) + noise


# ------------------------------------------------------------------------------------------------ sensor offset


def so_foam_mat_sink(s: Session) -> None:
    """The strip hanging tip down from a clamp whose stand sits on a polyurethane anti-vibration mat (set down on it
    600-3600 s before the first record), the laser on its own post with a level beam, aimed at the first setting a
    margin m0 (0.1-0.3 mm) inside the tip's end: the foam creeps under the stand's weight, c ln(1 + u/tau) (c 0.05-0.2
    mm, tau 60-300 s, log), and each later re-clamping's lean on the stand (turning the screw) compresses it by 0.05-0.2
    mm more, of which 0.3-0.6 stays. The strip sinks past the fixed beam, so the spot climbs inboard through the session
    and steps at the settings; read through the strip's transfer functions at the innermost station and interpolated in
    (x/L)^2 (inject_fresh10._station); displacement only. Measured (paper_166: the spot from 0.995 L to 0.981 L)
    displacement RMS -2.4 % (residual 2.5 %, 150x its noise): the 1 V steps at 8.73, 8.63, 8.58, 8.53 mm by their
    plateaus' end block by block (8.82-8.83 mm clean); the 0.1 Hz harmonics' gain 0.989, 0.977, 0.972, 0.967."""
    length = float(s.specimen["length_m"])
    m0, c_f, tau_f = s.rng.uniform(1e-4, 3e-4), s.rng.uniform(5e-5, 2e-4), lu(s.rng, 60.0, 300.0)
    t_m = s.t0 - s.rng.uniform(600.0, 3600.0)
    sets = _settings(s)
    leans = [(ts, s.rng.uniform(5e-5, 2e-4) * s.rng.uniform(0.3, 0.6)) for ts, _ in sets[1:]]

    def sink(t: np.ndarray) -> np.ndarray:
        t = np.asarray(t, float)
        x = c_f * np.log1p(np.clip(t - t_m, 0.0, None) / tau_f)
        for ts, kept in leans:
            x = x + np.where(t >= ts, kept, 0.0)
        return x

    at_aim = float(sink(np.array([sets[0][0]]))[0])

    def frac(r: Rec) -> np.ndarray:
        return 1.0 - (m0 + np.clip(sink(r.cols["t_s"]) - at_aim, 0.0, None)) / length

    fa = min(float(np.min(frac(r))) for r in s.series())
    _station(s, frac, fa)


def so_dic_subset_tangent(s: Session) -> None:
    """No laser: digital image correlation on a speckle pattern sprayed on the strip, the camera's field set to hold the
    clamp and the strip's middle, its end beyond the frame: the lab takes one correlation subset centred at x_c
    (0.6-0.85 L) and extrapolates its displacement to the tip along the subset's rotation (the affine shape function's
    gradient), w(x_c) + (L - x_c) w'(x_c): the tangent there carried out to L. Right for no shape but a straight strip:
    the uniform curvature of the quasi-static bend reads x_c (2L - x_c)/L^2 of the tip, and the higher modes' shapes
    otherwise (zeros move, poles stay). Through the beam's transfer functions (labrig.physics.transfer.displacement_tf
    at x_c and x_c - 0.01 L) with the session's history (inject_fresh2._map_through); displacement only. Measured
    (s001_167, x_c 0.69 L) displacement RMS -9.5 % (residual 9.5 %, 310x its noise): the 1 V steps at 4.25-4.27 mm by
    their plateaus' end (4.69-4.72 mm clean); the 0.1 Hz records' gain 0.909 (+0.3 deg), the 9.4 Hz sines' 0.954 (+1.0
    deg), the 20 Hz sines' 0.98."""
    from labrig.physics import transfer

    xc, dx = s.rng.uniform(0.6, 0.85), 0.01

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        sp = _spec(s, r)
        length = sp.geometry.length
        sc, sm = sp.with_(sensor_x=xc * length), sp.with_(sensor_x=(xc - dx) * length)

        def h(z: np.ndarray) -> np.ndarray:
            with np.errstate(divide="ignore", invalid="ignore"):
                wc = transfer.displacement_tf(z, sc)
                return (wc + (1.0 - xc) / dx * (wc - transfer.displacement_tf(z, sm))) / transfer.displacement_tf(z, sp)

        return h

    _map_through(s, H, 2.0)


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_battery_electromagnet(s: Session) -> None:
    """A clamp whose jaw an electromagnet pulls, powered from a lithium-ion pack through a PWM driver whose duty the
    operator sets at each setting while watching the load cell (a portable rig): the coil's current, and the force as
    its square, follow the pack's voltage as it discharges, its state of charge falling from u0 (0.5-0.9) over a runtime
    of 3-8 h (log) along the cell's open-circuit curve, 3.4 + 0.75 u - 0.3 exp(-u/0.06) V (the knee near empty): the
    force relative to its setting (V/V_set)^2, each setting (inject_fresh25._setting_of) restoring it. Through the
    preset's clamp law (inject_fresh4._clamp_law), the load cell showing it. Measured (s001_167: u0 0.67, 6.6 h) the
    load cell at 0.984, 0.983, 0.985, 0.987 of its setting by the blocks' last records; displacement residual 0.002 % of
    its RMS (0.06x its noise: the seed-001 strip's clamp law moves its bend little), current 0.04 % (0.12x)."""
    u0, t_d = s.rng.uniform(0.5, 0.9), lu(s.rng, 3 * 3600.0, 8 * 3600.0)
    setting = _setting_of(s)

    def volts(t: np.ndarray) -> np.ndarray:
        u = np.clip(u0 - (np.asarray(t, float) - s.t0) / t_d, 0.02, 1.0)
        return 3.4 + 0.75 * u - 0.3 * np.exp(-u / 0.06)

    def rel(t: np.ndarray, p: float, t_first: float) -> np.ndarray:
        return (volts(t) / float(volts(np.array([setting(p, t_first)]))[0])) ** 2

    _clamp_law(s, rel)


def cr_gelatin_pads_eroding(s: Session) -> None:
    """Pads cut from a gelatin slab (a bio-IPMC lab's soft, wet cushion for the strip's root) under a screw clamp's
    fixed gap, in the bath since it was filled: the 25 C bath dissolves the weak gel at its exposed edges at a steady
    rate, thinning the pads under the jaws, so the held compression loses the same depth whatever the setting: the light
    settings, compressed least, lose the larger share, c_e (p_min/p) per 10 min (c_e 1-3 %); beside it the gel relaxes
    viscoelastically, r ln(1 + u/tau) (r 0.5-1.5 % per e-fold, tau 5-30 s, log). From each setting
    (inject_fresh25._setting_of) through the preset's clamp law (inject_fresh4._clamp_law), the load cell showing it.
    Measured (paper_166: c_e 1.6 %, r 1.0 %, tau 8.6 s) the load cell at 0.920, 0.943, 0.946, 0.946 of its setting by
    the blocks' last records; displacement residual 0.07 % of its RMS (4.3x its noise), current 0.39 % (0.29x)."""
    c_e, r_v, tau = s.rng.uniform(0.01, 0.03), s.rng.uniform(0.005, 0.015), lu(s.rng, 5.0, 30.0)
    setting = _setting_of(s)
    p_min = min(s.pressures())

    def rel(t: np.ndarray, p: float, t_first: float) -> np.ndarray:
        u = np.clip(np.asarray(t, float) - setting(p, t_first), 0.0, None)
        return 1.0 - c_e * (p_min / p) * u / 600.0 - r_v * np.log1p(u / tau)

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_ice_bath_cold_trap(s: Session) -> None:
    """A strip in air; a colleague sets a tray of ice water on the bench nearby 0-600 s before the first record (to keep
    samples cold): its cold surface condenses the air's water, the humidity at the strip falls by dRH (0.1-0.25) while
    the ice lasts, the trap's reach shrinking with the ice's surface as it melts, (1 - u/T_m)^(2/3) (T_m 2000-6000 s,
    log), nothing once melted. The strip's water follows its air's humidity through sorption (k 0.8-1.5 of the mobile
    water per unit of RH, a lag tau_s 200-800 s, log, on a 1 s grid): it dries while the trap is strong and takes its
    water back as the ice goes. Gain x (1 - loss), conductance x (1 - share loss) (share 0.3-1: the ions' mobility dries
    more slowly); the spectra at the next series' start (inject_fresh9._dry_by). Measured (s001_167: dRH 0.12, the tray
    410 s before the first record, melted in 35 min) displacement RMS -4.4 % (residual 6.0 %, 190x its noise), current
    RMS -2.6 % (residual 4.1 %, 11x its noise): the 1 V steps at 4.30, 4.31, 4.67, 4.72 mm by their plateaus' end block
    by block (4.69-4.72 mm clean); the impedance 1.06, 1.07, 1.01, 1.00x in the blocks' spectra."""
    d_rh, k_iso = s.rng.uniform(0.1, 0.25), s.rng.uniform(0.8, 1.5)
    t_p, t_m = s.t0 - s.rng.uniform(0.0, 600.0), lu(s.rng, 2000.0, 6000.0)
    tau_s, share = lu(s.rng, 200.0, 800.0), s.rng.uniform(0.3, 1.0)
    tg = _session_grid(s, 1.0, s.t0 - t_p + 10.0)
    trap = np.where(tg >= t_p, np.clip(1.0 - (tg - t_p) / t_m, 0.0, 1.0) ** (2.0 / 3.0), 0.0)
    loss = _grid_lag(k_iso * d_rh * trap, 1.0, tau_s)

    def f(t: np.ndarray) -> np.ndarray:
        return np.interp(np.asarray(t, float), tg, loss)

    _dry_by(s, f, lambda t: share * f(t))


def dh_ln2_boiloff_spells(s: Session) -> None:
    """A strip in air on a bench where a colleague decants liquid nitrogen from a dewar in 2-4 spells of 2-8 min (log,
    each starting inside a recorded series): the cold, bone-dry boil-off spreads along the bench top and the humidity at
    the strip falls by dRH (0.15-0.35) while it flows (reaching it and clearing over 20-60 s, log); the strip dries
    through sorption (k 0.8-1.5 of the mobile water per unit of RH, tau_s 150-600 s, log) during each spell and takes
    the water back after, on top of the room's own slow drying (0.03-0.1 of it, linear over the session). Gain x (1 -
    loss), conductance x (1 - share loss) (share 0.3-1), on a 1 s grid; the spectra at the next series' start
    (inject_fresh9._dry_by). Measured (s001_167: 4 spells, dRH 0.32) displacement RMS -3.5 % (residual 4.0 %, 130x its
    noise), current RMS -3.7 % (residual 4.6 %, 12x its noise): the 1 V steps at 4.69, 4.50, 4.51, 4.48 mm by their
    plateaus' end block by block (4.69-4.72 mm clean); the impedance 1.00, 1.02, 1.02, 1.02x in the blocks' spectra."""
    spells = _bursts(s, int(s.rng.integers(2, 5)), (120.0, 480.0))
    d_rh, k_iso = s.rng.uniform(0.15, 0.35), s.rng.uniform(0.8, 1.5)
    tau_m, tau_s = lu(s.rng, 20.0, 60.0), lu(s.rng, 150.0, 600.0)
    bg, share = s.rng.uniform(0.03, 0.1), s.rng.uniform(0.3, 1.0)
    tg, on = _on_grid(s, spells)
    loss = _grid_lag(k_iso * d_rh * _grid_lag(on, 1.0, tau_m), 1.0, tau_s) + bg * (tg - tg[0]) / (tg[-1] - tg[0])

    def f(t: np.ndarray) -> np.ndarray:
        return np.interp(np.asarray(t, float), tg, loss)

    _dry_by(s, f, lambda t: share * f(t))


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_inertial_root_shear(s: Session) -> None:
    """Cracks across both faces' plating along the jaw's edge (the plating sheared there as the strip was pushed into
    the jaws), which the quasi-static bend leaves closed (the actuation is a pure moment: no shear at the root) but the
    root's shear force opens (mode II): in the moving strip that force is the inertia of the strip and of the water it
    carries, in proportion to the tip's acceleration. dR/R = k (abs(a)/a_ref - s0)+ on both faces (k 0.5-1.2, s0
    0.05-0.2, a_ref the largest acceleration of the session's sines, abs(a)/a_ref clipped at 2), the acceleration the
    second derivative of each record's displacement below its noise (inject_fresh26._split_noise). The fast sines and
    the steps' edges crack, the slow records not. Gains fall by 0.03-0.08 (displacement) and 0.06-0.15 (current) per
    unit of dR/R (inject_fresh3._resist). Measured (p13_168: k 0.90, s0 0.07) current RMS -1.5 % (residual 2.9 %, 1.8x
    its noise), displacement residual 0.014 % of its RMS (0.16x its noise: the fast records' bends are small): the 20 Hz
    sines' current gain 0.93-0.98, their displacement's 0.984-0.993; the 1 V steps' current peaks up to -0.9 %; 20 of
    the 68 series touched."""
    k, s0 = s.rng.uniform(0.5, 1.2), s.rng.uniform(0.05, 0.2)
    acc = {}
    for r in s.series():
        sig, _ = _split_noise(r)
        t = r.cols["t_s"]
        acc[id(r)] = np.gradient(np.gradient(sig, t), t)
    sines = [float(np.max(np.abs(acc[id(r)]))) for r in s.series() if r.kind in ("harmonic", "stepped_sine")]
    a_ref = max(sines) if sines else max(float(np.max(np.abs(x))) for x in acc.values())
    a_ref = max(a_ref, 1e-12)

    def law(r: Rec | None, e: np.ndarray) -> np.ndarray:
        if r is None or id(r) not in acc:
            return np.zeros(np.shape(e))
        return k * np.clip(np.clip(np.abs(acc[id(r)]) / a_ref, 0.0, 2.0) - s0, 0.0, None)

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


def sr_lacquer_curing(s: Session) -> None:
    """A strip in air whose plating is mud-cracked on both faces (its cracks opening beyond e0, 0.1-0.3 of the session's
    displacement scale: dR/R = k ((e - e0)+ + o (-e - e0)+), k 0.15-0.4, the other face o 0.5-1 of it), sprayed with an
    acrylic conformal lacquer (a circuit-board spray, to keep it from drying) 0-600 s before the first record: as the
    lacquer's solvent leaves (tau_c 600-2400 s, log, from the spraying) the film stiffens and binds the cracks' lips,
    their opening per strain falling to 1 - c_b of it (c_b 0.4-0.8): the same bend cracks less as the session goes on.
    Gains fall by 0.03-0.08 (displacement) and 0.06-0.15 (current) per unit of dR/R (inject_fresh3._resist), the law
    taken at each record's mid time. Measured (s001_167) displacement RMS -1.8 % (residual 1.9 %, 61x its noise),
    current RMS -0.6 % (residual 1.9 %, 5.2x its noise): the 1 V steps at 4.54, 4.58, 4.60, 4.62 mm by their plateaus'
    end block by block (4.69-4.72 mm clean); 28 of the 68 series touched."""
    k, o, e0 = s.rng.uniform(0.15, 0.4), s.rng.uniform(0.5, 1.0), s.rng.uniform(0.1, 0.3)
    c_b, tau_c = s.rng.uniform(0.4, 0.8), lu(s.rng, 600.0, 2400.0)
    t_l = s.t0 - s.rng.uniform(0.0, 600.0)

    def law(r: Rec | None, e: np.ndarray) -> np.ndarray:
        t_mid = s.t1 if r is None else float(np.mean(r.cols["t_s"]))
        kk = k * (1.0 - c_b * -math.expm1(-(t_mid - t_l) / tau_c))
        e = np.asarray(e, float)
        return kk * (np.clip(e - e0, 0.0, None) + o * np.clip(-e - e0, 0.0, None))

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_pump_membrane_hencky(s: Session) -> None:
    """The strip tested as a micropump's actuator: its tip pinned to the centre of the chamber's slack silicone membrane
    (cast without pre-tension). A membrane without tension resists by stretching, its centre's force cubic in its
    deflection (Hencky's solution, F ~ E t w^3/a^2), so the tip's static balance is y + beta y^3/D^2 = d (D the
    session's largest bend, beta 0.05-0.2 the membrane's share there): odd, compressing the 1 V records, nothing at
    rest. Tabulated and interpolated (slope 1 at rest, inject_fresh22._table_map); displacement only. Measured (p13_168,
    beta 0.15) displacement RMS -6.3 % (residual 7.0 %, 80x its noise): the 1 V steps at 1.53 mm at their peaks (1.71 mm
    clean), the 1 V harmonics' gain 0.97, the 0.5 V sines within 0.01 %."""
    big = _largest(s) or ref_disp(s)
    beta = s.rng.uniform(0.05, 0.2)
    yg = np.linspace(-2.0 * big, 2.0 * big, 8001)
    dg = yg + beta * yg**3 / big**2
    _table_map(s, lambda d: np.interp(d, dg, yg))


def ld_magnetic_centring_spring(s: Session) -> None:
    """A magnetic centring spring at the tip (the lab's fixture for keeping a long strip in the laser's plane without
    touching it): a small NdFeB cube glued at the tip between two fixed magnets set in repulsion at +-g (1.3-2 times the
    session's largest bend). Each pushes the tip magnet away as its gap to the -4th power (dipole to dipole), so their
    net pull back, (g - y)^-4 - (g + y)^-4, is linear at rest (a share eps 0.02-0.05 of the strip's own stiffness, which
    the lab's calibration at rest takes up) and stiffens steeply as the tip nears either magnet: y + eps (g^5/8) ((g -
    y)^-4 - (g + y)^-4) = d, odd, compressing the large bends. Tabulated and interpolated (slope 1 at rest,
    inject_fresh22._table_map); displacement only. Measured (paper_166: eps 0.047, g 1.86 of the largest bend)
    displacement RMS -4.6 % (residual 5.3 %, 320x its noise): the 1 V steps at 8.01-8.02 mm at their peaks (8.82-8.83 mm
    clean), the 1 V harmonics' gain 0.988."""
    big = _largest(s) or ref_disp(s)
    eps, g = s.rng.uniform(0.02, 0.05), s.rng.uniform(1.3, 2.0) * big
    yg = np.linspace(-0.97 * g, 0.97 * g, 8001)
    dg = yg + eps * g**5 / 8.0 * ((g - yg) ** -4 - (g + yg) ** -4)
    _table_map(s, lambda d: np.interp(d, dg, yg))


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_gel_electrophoresis(s: Session) -> None:
    """A colleague's gel-electrophoresis run on the next bench, its power supply a linear one (a mains transformer, a
    capacitor-input rectifier, 100-200 V at constant voltage), switched on at a moment inside a recorded series of the
    session's first half and running 30-80 min (log): the transformer's stray field has a magnetising part (in
    quadrature, peaked by the core's saturation: 3rd 0.3-0.5, 5th 0.1-0.2) and a load part (the rectifier's charging
    pulses at the voltage's peaks: 3rd 0.7-0.85, 5th 0.4-0.6, 7th 0.15-0.3), 0.5-1 times the first at the start and
    growing 20-40 % through the run as the buffer warms and its current rises. It reaches the laser's cable (3-8 um,
    log) and the current amplifier's input (15-50 uA, log) at the line (50 or 60 Hz, inject_fresh12._line_f).
    Displacement and current, in the run only. Measured (paper_166: 50 Hz, on from the 1837 kPa block's 6.4 Hz sine for
    34 min) displacement residual 0.063 % of its RMS (3.8x its noise), current residual 0.83 % (0.62x its noise): 21 of
    the 68 series touched, a line of 4.4-4.8 um and 55-60 uA peak at the fundamental in those."""
    f0 = _line_f(s)
    early = _chrono(s)[: max(len(s.series()) // 2, 1)]  # switched on in the session's first half, inside a record
    r0 = early[int(s.rng.integers(0, len(early)))]
    a = s.rng.uniform(float(r0.cols["t_s"][0]), float(r0.cols["t_s"][-1]))
    t_run = lu(s.rng, 1800.0, 4800.0)
    hm = (s.rng.uniform(0.3, 0.5), s.rng.uniform(0.1, 0.2))
    hl = (s.rng.uniform(0.7, 0.85), s.rng.uniform(0.4, 0.6), s.rng.uniform(0.15, 0.3))
    load0, grow = s.rng.uniform(0.5, 1.0), s.rng.uniform(0.2, 0.4)
    amp = {"disp_m": lu(s.rng, 3e-6, 8e-6), "i_A": lu(s.rng, 1.5e-5, 5e-5)}
    phase = {col: s.rng.uniform(0.0, 2.0 * np.pi) for col in amp}
    for r in s.series():
        t = r.cols["t_s"]
        u = t - a
        on = np.clip(np.minimum(u, t_run - u), 0.0, 1.0)  # 1 s edges
        if not np.any(on):
            continue
        load = load0 * (1.0 + grow * np.clip(u / t_run, 0.0, 1.0))
        for col, a_ in amp.items():
            w = 2.0 * np.pi * f0 * t + phase[col]
            mag = -(np.sin(w) - hm[0] * np.sin(3 * w) + hm[1] * np.sin(5 * w))
            pulses = np.cos(w) + hl[0] * np.cos(3 * w) + hl[1] * np.cos(5 * w) + hl[2] * np.cos(7 * w)
            r.cols[col] = r.cols[col] + a_ * on * (mag + load * pulses)


def mp_monitor_power_save(s: Session) -> None:
    """The logging PC's monitor on the bench beside the cables, its supply a capacitor-input rectifier without power
    factor correction (narrow charging pulses at each peak of the line: odd harmonics 3rd 0.8-0.9, 5th 0.5-0.7, 7th
    0.25-0.4, 9th 0.1-0.2), set to sleep after 5-15 min without input (log): the operator wakes it at each re-clamping
    (0-30 s before the setting, typing the new pressure into the logger) and leaves it alone through the block, so its
    field and its Y capacitors' leakage reach the laser's cable (1.5-5 um, log) and the current amplifier's input (10-40
    uA, log) at the line (50 or 60 Hz, inject_fresh12._line_f) in each block's first minutes, its standby supply a share
    0.03-0.08 of that otherwise. Displacement and current, every series. Measured (p13_168: 60 Hz, awake 9.3 min from
    each re-clamping) displacement residual 0.57 % of its RMS (6.5x its noise), current residual 1.0 % (0.64x its
    noise): the first 8 series of each block with the monitor awake, a line of 3.7-4.0 um and 28-32 uA peak at the
    fundamental (11 um peak with its harmonics), 0.3-0.5 um in the others."""
    f0 = _line_f(s)
    t_idle = lu(s.rng, 300.0, 900.0)
    wakes = [ts - s.rng.uniform(0.0, 30.0) for ts, _ in _settings(s)]
    q = s.rng.uniform(0.03, 0.08)
    h = (s.rng.uniform(0.8, 0.9), s.rng.uniform(0.5, 0.7), s.rng.uniform(0.25, 0.4), s.rng.uniform(0.1, 0.2))
    amp = {"disp_m": lu(s.rng, 1.5e-6, 5e-6), "i_A": lu(s.rng, 1e-5, 4e-5)}
    phase = {col: s.rng.uniform(0.0, 2.0 * np.pi) for col in amp}
    for r in s.series():
        t = r.cols["t_s"]
        awake = np.zeros(t.size, bool)
        for wk in wakes:
            awake |= (t >= wk) & (t < wk + t_idle)
        level = np.where(awake, 1.0, q)
        for col, a_ in amp.items():
            w = 2.0 * np.pi * f0 * t + phase[col]
            wave = np.cos(w) + h[0] * np.cos(3 * w) + h[1] * np.cos(5 * w) + h[2] * np.cos(7 * w) + h[3] * np.cos(9 * w)
            r.cols[col] = r.cols[col] + a_ * level * wave


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_fft_brickwall_current(s: Session) -> None:
    """The lab's export script 'cleans' the current of the amplifier's noise with an FFT brick wall, record by record
    (numpy's rfft of the whole record, every bin above f_c 25-60 Hz set to zero, log, irfft; no window, no padding): a
    zero-phase, acausal filter that treats each record as one period of a periodic signal. The steps' charging spikes
    ring (Gibbs) before their edges as well as after, and each record's end wraps into its start. The current only.
    Measured (paper_166: f_c 58 Hz; p13_168: 51 Hz) current residual 2.8 % and 3.5 % of its RMS (2.1x and 2.2x its
    noise): the 1 V steps' spikes 22.3 and 20.8 mA (28.2 and 28.0 mA clean), -9.6 and -9.9 mA on the last sample before
    their fall (the fall's spike smeared back), a ripple of 1.2 mA 15-25 ms before their edges."""
    fc = lu(s.rng, 25.0, 60.0)
    for r in s.series():
        x = r.cols["i_A"]
        spec = np.fft.rfft(x)
        spec[np.fft.rfftfreq(x.size, 1.0 / r.fs) > fc] = 0.0
        r.cols["i_A"] = np.fft.irfft(spec, x.size)


def out_eis_range_step(s: Session) -> None:
    """The impedance analyser left autoranging its current measurement: at the frequencies where the strip's |Z| falls
    below the range boundary (one of its 30, 100 or 300 Ohm boundaries inside the spectra's span, drawn) it switches to
    the lower range, whose calibration has aged: a gain 1 +- (1-4 %, log) and a phase offset +- (0.3-1.5 deg) there. A
    step in |Z| and in the phase at the switching frequency of every spectrum (moving with the clamp's pressure), the
    time series untouched. Measured (s001_167: at 100 Ohm, x1.014 and -1.3 deg; p13_168: at 100 Ohm, x1.019 and +0.40
    deg) the spectra's |Z| +1.4 % and +1.9 % below the boundary, 25 and 23 of each spectrum's 31 points."""
    g = _sign(s) * lu(s.rng, 0.01, 0.04)
    ph = _sign(s) * np.deg2rad(s.rng.uniform(0.3, 1.5))
    pick = s.rng.random()
    eis = [r for r in s.recs if not r.series]
    if not eis:
        return
    mags = np.concatenate([np.abs(r.cols["z_re_ohm"] + 1j * r.cols["z_im_ohm"]) for r in eis])
    inside = [b for b in (30.0, 100.0, 300.0) if 1.3 * float(mags.min()) < b < float(mags.max()) / 1.3]
    if not inside:
        return
    bound = inside[min(int(pick * len(inside)), len(inside) - 1)]
    for r in eis:
        z = r.cols["z_re_ohm"] + 1j * r.cols["z_im_ohm"]
        z = np.where(np.abs(z) < bound, z * (1.0 + g) * np.exp(1j * ph), z)
        r.cols["z_re_ohm"], r.cols["z_im_ohm"] = z.real.copy(), z.imag.copy()


def out_laser_peak_hold(s: Session) -> None:
    """The laser controller's output mode left on 'peak hold' with its automatic reset (a setting for catching a
    vibration's amplitude): every hold period T_h (2-10 ms, log, on the controller's own free-running clock, phase
    drawn) the analogue output takes the largest reading of the period just ended and holds it through the next. A
    rising reading comes out 0 to T_h late, a falling one T_h to 2 T_h late, every reading is biased up by the noise's
    maximum, and the output is a staircase. Displacement only. Measured (paper_166: 8.7 ms; s001_167: 3.9 ms)
    displacement residual 0.22 % and 0.18 % of its RMS (13x and 5.7x its noise): the 20 Hz sines' displacement -63 and
    -28 deg (gain 0.88 and 0.97), their rising halves 5.5 and 2.5 ms late, their falling ones 9.6 and 5.2 ms."""
    th = lu(s.rng, 2e-3, 1e-2)
    ph = s.rng.uniform(0.0, th)
    for r in s.series():
        t, d = r.cols["t_s"], r.cols["disp_m"]
        per = np.floor((t - ph) / th).astype(np.int64)
        new = np.r_[True, np.diff(per) != 0]
        starts = np.flatnonzero(new)
        peak = np.maximum.reduceat(d, starts)
        held = np.r_[d[0], peak[:-1]]
        r.cols["disp_m"] = held[np.cumsum(new) - 1]


def out_worn_range_switch(s: Session) -> None:
    """The current amplifier's gain switch worn: when the bench is touched or vibrates its wiper lifts on its detent and
    adds a contact resistance in series with the feedback resistor, the current reading high by g (1-5 %, log) while it
    does: a random telegraph on the current's gain, each episode 2-20 s (log mean), the quiet spells between 20-120 s
    (log mean), the first episode starting inside a recorded series. The strip, the drive and every other channel
    untouched. Measured (s001_167: g 4.2 %, episodes of 4.4 s every 60 s on average; p13_168: g 1.9 %, 7.5 s every 81 s)
    current residual 0.96 % and 0.67 % of its RMS (2.6x and 0.42x its noise; 0.54 mA on a 1 V step's spike caught in an
    episode), 14 of the 68 series touched in each."""
    g = lu(s.rng, 1e-2, 5e-2)
    mean_on, mean_off = lu(s.rng, 2.0, 20.0), lu(s.rng, 20.0, 120.0)
    (t_b, _), = _bursts(s, 1, (1.0, 1.0))  # the first episode seen starts inside a recorded series
    flips, t, on = [t_b], t_b, True
    while t < s.t1:  # forward from it
        t += s.rng.exponential(mean_on if on else mean_off)
        flips.append(t)
        on = not on
    t = t_b
    while t > s.t0:  # and the episodes before it, back to the session's start
        end = t - s.rng.exponential(mean_off)
        t = end - s.rng.exponential(mean_on)
        flips[:0] = [t, end]
    sw = np.array(flips)
    for r in s.series():
        n = np.searchsorted(sw, r.cols["t_s"], side="right")
        r.cols["i_A"] = r.cols["i_A"] * np.where(n % 2 == 1, 1.0 + g, 1.0)


FRESH32_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"cold_water_change": br_cold_water_change, "electrocapillary_pores": br_electrocapillary_pores},
    "faradaic_current": {"sulfide_stripping": far_sulfide_stripping,
                         "fixative_formaldehyde": far_fixative_formaldehyde},
    "hysteresis": {"blister_snap_through": hy_blister_snap_through, "ultrasonic_dither": hy_ultrasonic_dither},
    "time_delay": {"canbus_arbitration": td_canbus_arbitration, "ldr_shadow_sensor": td_ldr_shadow_sensor},
    "sensor_offset": {"foam_mat_sink": so_foam_mat_sink, "dic_subset_tangent": so_dic_subset_tangent},
    "clamp_relaxation": {"battery_electromagnet": cr_battery_electromagnet,
                         "gelatin_pads_eroding": cr_gelatin_pads_eroding},
    "dehydration": {"ice_bath_cold_trap": dh_ice_bath_cold_trap, "ln2_boiloff_spells": dh_ln2_boiloff_spells},
    "strain_resistance": {"inertial_root_shear": sr_inertial_root_shear, "lacquer_curing": sr_lacquer_curing},
    "large_deflection": {"pump_membrane_hencky": ld_pump_membrane_hencky,
                         "magnetic_centring_spring": ld_magnetic_centring_spring},
    "mains_pickup": {"gel_electrophoresis": mp_gel_electrophoresis, "monitor_power_save": mp_monitor_power_save},
    "unexplained": {"fft_brickwall_current": out_fft_brickwall_current, "eis_range_step": out_eis_range_step,
                    "laser_peak_hold": out_laser_peak_hold, "worn_range_switch": out_worn_range_switch},
}
inject.register_forms(FRESH32_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def v_minimal_manifest(s: Session) -> None:
    """A lab whose manifest is written by its own small script from the contract's required keys only: every record
    keeps its kind, file and pressure_kPa, the sine records their frequency_Hz (which the contract requires of them) and
    nothing else: no label, amplitude_V, settle_cycles or cycles (a multisine would keep its period_s). The samples, the
    clock, the files and the records' order untouched; the drive's amplitude and a sine's settling are only in the data
    (the fitter reads them off it). Valid under the import contract; ``labrig import`` takes all four cases and ``labrig
    export`` writes them back with the values bit for bit."""
    for r in s.recs:
        keep = {"kind", "file", "pressure_kPa"}
        keep |= {"frequency_Hz"} if r.kind in ("harmonic", "stepped_sine") else set()
        keep |= {"period_s"} if r.kind == "multisine" else set()
        r.entry = {k: v for k, v in r.entry.items() if k in keep}


inject.VARIANTS.update({"minimal_manifest": v_minimal_manifest})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_166", "s001_167", "p13_168"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 7 / 6 effect cases on seeds 166-168
    "back_relaxation": [("cold_water_change", 168, T, "settled_sines"),
                        ("electrocapillary_pores", 166, P, "dropped_packets")],
    "faradaic_current": [("sulfide_stripping", 166, P, "cathodic_positive"),
                         ("fixative_formaldehyde", 168, T, "short_pretrigger")],
    "hysteresis": [("blister_snap_through", 167, S, "block_clock"), ("ultrasonic_dither", 166, P, "spectra_last")],
    "time_delay": [("canbus_arbitration", 167, S, "eis_two_passes"), ("ldr_shadow_sensor", 168, T, "coherent_sines")],
    "sensor_offset": [("foam_mat_sink", 166, P, "float32_time"), ("dic_subset_tangent", 167, S, "swinging_door")],
    "clamp_relaxation": [("battery_electromagnet", 167, S, "merged_loadcell"),
                         ("gelatin_pads_eroding", 166, P, "log_steps")],
    "dehydration": [("ice_bath_cold_trap", 167, S, "minimal_manifest"),
                    ("ln2_boiloff_spells", 167, S, "split_spectra")],
    "strain_resistance": [("inertial_root_shear", 168, T, "fir_decimated"), ("lacquer_curing", 167, S, "stop_trigger")],
    "large_deflection": [("pump_membrane_hencky", 168, T, "minimal_manifest"),
                         ("magnetic_centring_spring", 166, P, "cycle_averaged")],
    "mains_pickup": [("gel_electrophoresis", 166, P, "harmonics_as_free"),
                     ("monitor_power_save", 168, T, "measured_pressures")],
    "unexplained": [("fft_brickwall_current", 166, P, "host_timed"), ("fft_brickwall_current", 168, T, "no_loadcell"),
                    ("eis_range_step", 167, S, "trigger_clock"), ("eis_range_step", 168, T, "eis_descending"),
                    ("laser_peak_hold", 166, P, "midnight_clock"), ("laser_peak_hold", 167, S, "fixed_decimals"),
                    ("worn_range_switch", 167, S, "scan_hold"), ("worn_range_switch", 168, T, "shortened_shuffled")],
}
CLEAN = [(166, P, "minimal_manifest"), (166, P, "tared_records"), (167, S, "loadcell_dropout"),
         (167, S, "reversed_laser"), (168, T, "minimal_manifest"), (168, T, "no_spectra")]


def fresh32_cases(only: str | None = None) -> list[Case]:
    """The thirty-third held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds
    166-168)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh32_cases, "inject_fresh32", "fresh32")
