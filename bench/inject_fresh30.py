"""A thirty-first held-out set for the diagnosis (issue 12), fresh30, written without sight of the diagnosis (its code,
its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh29.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (copper-tape contacts dissolving at the
anodic face beyond the metal's onset, an IPMC gripper finger whose lever's pin joint rubs with a friction in proportion
to its load, a plating blistered by the hydrogen its cathodic face makes at the large drives, colloid deposited on the
anodic face by electrophoresis and partly stripped when it turns cathodic, a laser head whose receiver's gain control
amplifies the hum inside it as the tilted strip returns less light, an LVDT's core and an analogue inductive sensor's
steel target), some on the history, the clamp pressure or the session's events (a drop of detergent added at a
re-clamping that lowers the back-flow's capillary threshold, a perfusion switched on in spells that thins the oxygen's
diffusion layer, a surgical hemostat whose serrations fall back into the dents of the earlier settings, knurled contacts
biting deeper at the higher settings) and some on time (peroxide left from a cleaning rinse decomposing on the platinum,
a leaking compressed-air fitting whose dry jet follows the compressor's cycle, a shape-memory wire clamp following the
enclosure's air temperature, a strip in air drying under a tape target that changes the spot's centroid, nylon guide
lines whose friction rises as the strip's surface dries, the grid's frequency wandering and swinging at the full hour);
lab wiring or sensors among them (the copper tape, the gripper's lever, the Hall sensor read through a copper thermostat
block, a bench multimeter integrating the current over a fraction of a line cycle, the unplated tip margin, the tape
target, the LVDT, the inductive sensor, the receiver's gain control, the bench's wiring). Four structures outside the
catalogue (truth "unexplained": vortices shed by the stirred bath's flow past the strip, the strip re-seated deeper in
the jaws at one re-clamping, a loose ground lug offsetting every single-ended input at once, an oxidised contact whose
resistance falls with the current through it); clean sessions. All on three bases of new seeds (160-162: the paper
strip, the seed-001 strip on its own sweep, the paper strip 15 mm free) and on the earlier sets' protocol / data-shape
variants plus one new here: a potentiostat that reports the cathodic current as positive (``cathodic_positive``).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh29 are reused (importing inject_fresh29 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import, none replaced. Strengths
are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it made on its case,
measured in memory against the clean base (relative RMS change over all series, form only, no variant; "noise": the
column's sample-to-sample noise at rest, inject_fresh15.rest_noise; the values for the three bases are in
docs/effects.md).

Run: python bench/inject_fresh30.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np
from scipy import signal
from scipy.integrate import cumulative_trapezoid

import inject
import inject_fresh29  # noqa: F401  (registers every earlier set's forms, bases, presets and variants)
from inject import Case, Rec, Session, lu, ref_disp
from inject_fresh2 import _chrono, _map_through, _spec, _through
from inject_fresh3 import _past, _resist, _sign, _through_x
from inject_fresh4 import _clamp_law
from inject_fresh6 import _bursts
from inject_fresh7 import _superpose
from inject_fresh9 import _dry_by, _gaps, _ou, _session_grid
from inject_fresh10 import _lag_varying, _station
from inject_fresh12 import _line_f
from inject_fresh14 import _largest
from inject_fresh16 import _grid_of
from inject_fresh22 import _f1, _table_map
from inject_fresh24 import _by_pressure_start
from inject_fresh25 import _setting_of
from inject_fresh26 import _later_setting, _split_noise
from inject_fresh28 import _stuck_zones
from inject_fresh29 import _logistic

# the paper's strip 15 mm free (earlier sets used 16-29, 31-45, 25 and 40 mm; 30 mm is the paper preset itself and the
# seed-001 strip is 20 mm; its 1 V step peaks near 2.3 mm, well inside the laser's +-20 mm and some 3900 times its
# noise): preset "paper_15", base "p15_162", registered in every process importing this module
inject.register_free_length("paper_15", 0.015)

inject.BASES.update({
    "paper_160": ("paper-sweep", "paper", 160),
    "s001_161": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 161),
    "p15_162": ("paper-sweep", "paper_15", 162),
})


# ------------------------------------------------------------------------------------------------ tools


def _cumulative(tg: np.ndarray, load: np.ndarray) -> np.ndarray:
    """The running sum of a 1 s grid's load (its cell means), normalised to 1 at the grid's end (0 if it is empty)."""
    q = np.cumsum(load)
    return q / q[-1] if q[-1] > 0 else q


def _spell_share(tg: np.ndarray, spells: list[tuple[float, float]], tau_on: float, tau_off: float) -> np.ndarray:
    """A share that rises towards 1 within tau_on while a spell is on and falls back within tau_off after it, on the
    grid tg (exact for the switch held over each cell)."""
    on = np.zeros(tg.size)
    for a, b in spells:
        on[(tg >= a) & (tg < b)] = 1.0
    out, x = np.empty(tg.size), 0.0
    dt = np.diff(tg, prepend=tg[0] - (tg[1] - tg[0] if tg.size > 1 else 1.0))
    for k, (u, h) in enumerate(zip(on.tolist(), dt.tolist())):
        x = u + (x - u) * math.exp(-h / (tau_on if u > x else tau_off))
        out[k] = x
    return out


# ------------------------------------------------------------------------------------------------ back relaxation


def br_copper_tape_contacts(s: Session) -> None:
    """The jaws' contacts made of copper foil tape (its conductive adhesive pressed on the plating at the root, a quick
    contact many labs use): on whichever face is the anode, beyond the copper's dissolution onset (v_cu 0.2-0.4 V of
    drive, width 0.02-0.05 V) the contact corrodes, Cu -> Cu2+, in proportion to the current it passes, and the ions
    migrate into the wet membrane. Divalent copper crosslinks the sulfonates ionically and binds water: the back-flow
    (K2_0 0.5-0.9, tau_0 2-8 s, log) loses share and slows as the copper is taken up, K2 = K2_0 (1 - a X), tau = tau_0
    (1 + b X) (a 0.3-0.6, b 0.5-1.5), the copper's share X growing with the dissolving charge (second by second,
    inject_fresh16._grid_of) towards x_end (0.4-0.9) by the session's end, the session's charge filling 1-3 e-folds.
    Through inject_fresh10._lag_varying (the reading d - K2 x, x the lag of d, sample by sample through the session,
    carried over the rests); displacement only. Measured (paper_160: K2_0 0.67, tau_0 4.3 s, the onset 0.22 V, x_end
    0.77) displacement RMS -46 % (residual 51 %, 3000x its noise): the 1 V steps at 3.43, 4.42, 5.02, 5.40 mm by their
    plateaus' end block by block (8.82-8.83 mm clean) and 0.95 to 2.04 mm 10 s after their fall (4.65 mm clean); the 1 V
    harmonics' gain 0.937 (+11.6 deg), 0.959 (+8.1 deg), 0.969 (+6.4 deg), 0.974 (+5.5 deg): the back-flow weakening as
    the copper is taken up."""
    k2_0, tau_0 = s.rng.uniform(0.5, 0.9), lu(s.rng, 2.0, 8.0)
    a_k, b_t = s.rng.uniform(0.3, 0.6), s.rng.uniform(0.5, 1.5)
    x_end, folds = s.rng.uniform(0.4, 0.9), s.rng.uniform(1.0, 3.0)
    v_cu, w = s.rng.uniform(0.2, 0.4), s.rng.uniform(0.02, 0.05)
    tg, load = _grid_of(s, "i_A", lambda i, v: np.abs(i) * _logistic((np.abs(v) - v_cu) / w))
    X = x_end * -np.expm1(-folds * _cumulative(tg, load)) / -math.expm1(-folds)

    def state(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        x = np.interp(np.asarray(t, float), tg, X)
        return k2_0 * (1.0 - a_k * x), tau_0 * (1.0 + b_t * x)

    _lag_varying(s, state)


def br_detergent_drop(s: Session) -> None:
    """The back-flow leaves the cathode's side through the plating's pores only above their capillary entry pressure (a
    Bingham-like flow: the opposing swelling x follows the bend d at ((|d - x| - theta)+)/tau, theta 0.1-0.3 of the
    session's displacement scale, tau 2-8 s, log, beside a slow leak through the membrane, tau_l 30-120 s, log; the
    reading d - K2 x, K2 0.5-0.9). At one re-clamping after the first (drawn; 0-30 s before that setting) the operator
    adds a drop of detergent to the bath to shed the bubbles clinging to the strip: the surfactant adsorbs in the pores
    (Langmuir, tau_a 30-200 s, log) and lowers the water's surface tension, so the entry threshold falls by c (0.5-0.9)
    of itself from then on: small bends that the back-flow ignored before are given back after. Sample by sample through
    the session in time order (the rests in steps of at most 0.25 s, the displacement linear across them); displacement
    only. Measured (p15_162: theta0 0.096 mm, K2 0.63, tau 3.1 s, c 0.81; the drop 12 s before the 4287 kPa setting)
    displacement RMS -56 % (residual 60 %, 900x its noise): the 1 V steps at 0.973 mm by their plateaus' end in the
    first three blocks and 0.944 mm after the drop (2.27 mm clean), 0.28 and 0.31 mm 10 s after their fall (1.16 mm
    clean); the 1 V harmonics' gain 0.913 (+12.0 deg) before it and 0.890 (+14.7 deg) after."""
    ref = ref_disp(s)
    theta0, tau, tau_l = s.rng.uniform(0.1, 0.3) * ref, lu(s.rng, 2.0, 8.0), lu(s.rng, 30.0, 120.0)
    k2, c, tau_a = s.rng.uniform(0.5, 0.9), s.rng.uniform(0.5, 0.9), lu(s.rng, 30.0, 200.0)
    _, t_set = _later_setting(s)
    t_det = t_set - s.rng.uniform(0.0, 30.0)

    def theta(t: float) -> float:
        return theta0 * (1.0 - c * -math.expm1(-max(t - t_det, 0.0) / tau_a))

    def step(x: float, d: float, dt: float, th: float) -> float:
        e = d - x
        return x + dt * (math.copysign(max(abs(e) - th, 0.0), e) / tau + e / tau_l)

    x, d_end = 0.0, 0.0
    for r, gap in _gaps(s, 0.25):
        t, d = r.cols["t_s"], r.cols["disp_m"]
        for k, (dt, u) in enumerate(gap):
            x = step(x, d_end + u * (float(d[0]) - d_end), dt, theta(float(t[0]) - (len(gap) - k - 0.5) * dt))
        dt = 1.0 / r.fs
        out = np.empty(d.size)
        for k, (dk, tk) in enumerate(zip(d.tolist(), t.tolist())):
            x = step(x, dk, dt, theta(tk))
            out[k] = x
        d_end = float(d[-1])
        r.cols["disp_m"] = d - k2 * out


# ------------------------------------------------------------------------------------------------ faradaic current


def far_peroxide_rinse(s: Session) -> None:
    """The strip cleaned in hydrogen peroxide (3 %, a lab's routine for platinum before a bio test) and rinsed too
    briefly 60-600 s before the first record: peroxide left in the membrane and the cuvette. Platinum oxidises it on the
    anodic face (H2O2 -> O2 + 2 H+ + 2 e-) and reduces it on the cathodic one (H2O2 + 2 H+ + 2 e- -> 2 H2O) at small
    overpotentials, both limited by its diffusion to the faces: a cell current i_lim tanh(v/2b) (b 0.04-0.08 V), i_lim
    0.2-0.8 mA (log) at the first record; the peroxide decomposes catalytically on the platinum (first order, tau_d
    900-3600 s, log), so the branch fades through the session: odd, memoryless within a record, dying with time. The
    current only. Measured (paper_160: i_lim 0.59 mA at the first record, b 0.054 V, tau_d 1150 s) current RMS +2.3 %
    (residual 6.0 %, 4.6x its noise): the 1 V steps' plateaus +0.57, +0.14, +0.04, +0.01 mA block by block; the 0.1 Hz
    sines' current gain 1.20 (-7.6 deg), 1.05, 1.01, 1.00."""
    i0, b = lu(s.rng, 2e-4, 8e-4), s.rng.uniform(0.04, 0.08)
    tau_d = lu(s.rng, 900.0, 3600.0)
    for r in s.series():
        lim = i0 * np.exp(-(r.cols["t_s"] - s.t0) / tau_d)
        r.cols["i_A"] = r.cols["i_A"] + lim * np.tanh(r.cols["v_V"] / (2.0 * b))


def far_perfusion_spells(s: Session) -> None:
    """Dissolved oxygen reduced on whichever face is the cathode (O2 + 4 H+ + 4 e- -> 2 H2O: a wave from E_o 0.2-0.4 V
    of drive, width 0.04-0.08 V; no oxygen evolution below 1.23 V), its limiting current set by the oxygen's diffusion
    through the unstirred layer at the face: j_q 80-200 uA/cm^2 (log) over one face's area in the still bath. The
    operator switches a gentle perfusion of the cuvette on now and then to keep its temperature (3-6 spells of 60-300 s,
    log, each starting inside a recorded series; its flow of a few mm/s moves the tip by well under a micrometre): the
    flow thins the diffusion layer and brings fresh oxygen, the limiting current rising m (2-4) times within 2-6 s of
    the switch-on and falling back within 15-60 s (log) of the switch-off as the layer regrows. i = sign(v) i_lim(t)
    wave(|v|); the current only. Measured (p15_162: E_o 0.36 V, 0.10 mA in the still bath, m 3.7; six spells of 67-138
    s) current RMS +1.9 % (residual 3.0 %, 2.0x its noise): +0.10 mA on every 1 V plateau, the 0.1 Hz sines' current
    gain 1.04 (-2.5 deg); 21 stepped sines (0.5-20 Hz) within or just after a spell, their crests' current up by as much
    as 0.35 mA."""
    e_o, w = s.rng.uniform(0.2, 0.4), s.rng.uniform(0.04, 0.08)
    area = float(s.specimen["length_m"]) * float(s.specimen["width_m"]) * 1e4  # cm^2, one face
    i_q, m = lu(s.rng, 80e-6, 200e-6) * area, s.rng.uniform(2.0, 4.0)
    spells = _bursts(s, int(s.rng.integers(3, 7)), (60.0, 300.0))
    tau_on, tau_off = s.rng.uniform(2.0, 6.0), lu(s.rng, 15.0, 60.0)
    tg = _session_grid(s, 0.5, 2.0)
    g = _spell_share(tg, spells, tau_on, tau_off)
    for r in s.series():
        t, v = r.cols["t_s"], r.cols["v_V"]
        lim = i_q * (1.0 + (m - 1.0) * np.interp(t, tg, g))
        r.cols["i_A"] = r.cols["i_A"] + np.sign(v) * lim * _logistic((np.abs(v) - e_o) / w)


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_gripper_pin_joint(s: Session) -> None:
    """The strip tested as a gripper's finger: its tip pushes a light pivoted jaw (a 3D-printed lever on a steel pin,
    held back by a hair spring, the laser reading the lever's end and calibrated to the tip at rest). The lever's spring
    takes kappa (0.03-0.1) of the tip's stiffness, so the tip moves u = d/(1 + kappa); the pin's dry friction is mu
    times the pin's load, which is the spring's preload plus its force, so the friction grows with the lever's
    deflection: the lever follows u through a play whose radius r = r0 + c |y| (r0 0.0003-0.0015 of the session's
    largest bend, c 0.01-0.04), loops whose width grows with the amplitude (a loss angle nearly independent of it) and
    that stay as the rate falls. Sample by sample through the session in time order, the laser's noise kept on the held
    reading (inject_fresh26._split_noise); displacement only. Measured (s001_161: kappa 0.082, c 0.037, r0 6.5 um)
    displacement RMS -8.5 % (residual 9.3 %, 290x its noise): the 1 V steps at 4.17-4.20 mm by their plateaus' end
    (4.69-4.72 mm clean); the 1 V harmonics' gain 0.905 (-3.2 deg), the 0.5 V 0.1 Hz sines' 0.908 (-2.2 deg); the 13.7
    Hz sines' 0.66-0.67 (-24 to -25 deg), the 20 Hz ones' 0.79 to 0.74 (-15 to -18 deg)."""
    big = _largest(s) or ref_disp(s)
    kappa, c, r0 = s.rng.uniform(0.03, 0.1), s.rng.uniform(0.01, 0.04), s.rng.uniform(0.0003, 0.0015) * big
    g, y = 1.0 / (1.0 + kappa), 0.0
    for r in _chrono(s):
        sig, noise = _split_noise(r)
        out = np.empty(sig.size)
        for k, u in enumerate((g * sig).tolist()):
            rad = r0 + c * abs(y)
            y = min(max(y, u - rad), u + rad)
            out[k] = y
        r.cols["disp_m"] = out + noise


def hy_drying_line_guide(s: Session) -> None:
    """A strip in air kept in the laser's plane by a guide of two taut nylon monofilaments strung either side of its
    tip's edges (a fishing-line guide, lighter than a fork), the lines touching the edges with a slight preload: the tip
    sticks to them until the bend's force beats their friction, two zones as stop operators (radii r_w 0.0005-0.002 of
    the session's largest bend and 1.2-1.8 times it) taking k (0.5-0.8) of the motion while stuck. The strip, mounted
    wet 60-600 s before the first record, dries at its surface (tau_d 600-2400 s, log): the water film that lubricated
    the contacts goes and the nylon's friction on the dry plating rises to rho (2-4) times the wet value, so the radii
    grow through the session (inject_fresh28._stuck_zones, the laser's noise kept on the held reading); displacement
    only. Measured (s001_161: k 0.53, r_w 6.6 um, rho 3.0, tau_d 740 s) displacement residual 0.58 % of its RMS (18x its
    noise): the 20 Hz sines' gain 0.69, 0.62, 0.56, 0.53 block by block (-13 to -8 deg), the 13.7 Hz ones' 0.49 to 0.47
    (stuck); the 1 V harmonics' phase -0.6 to -0.8 deg, the 0.1 Hz sines' -1.2 to -1.6 deg; the 1 V steps within 0.3 %.
    """
    big = _largest(s) or ref_disp(s)
    k, r_w = s.rng.uniform(0.5, 0.8), s.rng.uniform(0.0005, 0.002) * big
    radii = np.array([1.0, s.rng.uniform(1.2, 1.8)]) * r_w
    t_m, tau_d, rho = s.t0 - s.rng.uniform(60.0, 600.0), lu(s.rng, 600.0, 2400.0), s.rng.uniform(2.0, 4.0)
    _stuck_zones(s, k, radii, lambda t: 1.0 + (rho - 1.0) * -np.expm1(-np.clip(t - t_m, 0.0, None) / tau_d))


# ------------------------------------------------------------------------------------------------ time delay


def td_eddy_shielded_hall(s: Session) -> None:
    """No laser: a small magnet glued at the tip and a Hall sensor outside a thermostatted copper cuvette holder (a
    block 6-12 mm thick in the sensor's line of sight, to hold the bath's temperature), calibrated at rest against a
    laser: the magnet's field reaches the sensor through the copper, whose eddy currents hold back its changes. The
    field diffuses through the slab: 1/cosh(sqrt(s tau)), tau = mu0 sigma t^2 3-10 ms (log): a group delay of tau/2 at
    the drives' frequencies, the gain within a few per cent up to 20 Hz, the steps' edges rounded. Through
    inject_fresh2._through (0.5 s of the session's history); displacement only. Measured (p15_162, tau 5.8 ms)
    displacement residual 0.23 % of its RMS (3.4x its noise): the 20 Hz sines' phase -20.3 deg (2.8 ms), gain 0.958; the
    13.7 Hz sines' -14.1 deg, 0.980; the 0.1 Hz records' -0.1 deg."""
    tau = lu(s.rng, 3e-3, 10e-3)

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        return lambda z: 1.0 / np.cosh(np.sqrt(z * tau + 0j))

    _map_through(s, H, 0.5)


def td_dmm_nplc_current(s: Session) -> None:
    """The drive current read by a bench digital multimeter on its 100 mA range (the DAQ's inputs all taken), streaming
    its readings to the logger: each reading integrates the current over NPLC line cycles (0.06 or 0.2 of a 50 or 60 Hz
    cycle, drawn: 1.0-4 ms), the next starting after a short overhead (5-20 % of it), and its moving digital filter
    averages the last N readings (2 or 3); the logger puts the filtered readings, stamped by the meter at the end of
    each integration, on the DAQ's rows by linear interpolation. A lag of t_int/2 + (N - 1) t_r/2 (1-7 ms), the
    current's sines slightly low at 20 Hz and the steps' charging spikes rounded. With 0.3 s of the session's current
    before each record (inject_fresh3._past); the current only. Measured (s001_161: 0.06 NPLC at 50 Hz, 1.2 ms, N 3, a
    reading every 1.4 ms) current RMS -0.57 % (residual 14 %, 37x its noise): the 1 V steps' current peaks 16.0-16.8 mA
    (18.1-18.3 mA clean); the 20 Hz sines' current phase -14.5 deg (2.0 ms), gain 0.983; the 0.1 Hz records' -0.08 deg.
    """
    f_line = 50.0 if s.rng.random() < 0.5 else 60.0
    nplc = (0.06, 0.2)[int(s.rng.integers(0, 2))]
    n = int(s.rng.integers(2, 4))
    t_int = nplc / f_line
    t_r = t_int * (1.0 + s.rng.uniform(0.05, 0.2))
    for r in s.series():
        t = r.cols["t_s"]
        past = _past(s, r, "i_A", 0.3, r.fs)
        T = np.r_[t[0] - np.arange(past.size, 0, -1) / r.fs, t]
        X = np.r_[past, r.cols["i_A"]]
        C = cumulative_trapezoid(X, T, initial=0.0)
        tj = np.arange(T[0] + t_int + s.rng.uniform(0.0, t_r), T[-1] + 1e-12, t_r)
        mean = (np.interp(tj, T, C) - np.interp(tj - t_int, T, C)) / t_int
        filt = np.convolve(mean, np.ones(n) / n)[: mean.size]
        filt[: n - 1] = mean[: n - 1]
        r.cols["i_A"] = np.interp(t, tj, filt)


# ------------------------------------------------------------------------------------------------ sensor offset


def so_unplated_tip_margin(s: Session) -> None:
    """A strip plated with its tip end masked (the holder's clip in the plating bath): its last m (0.4-1.5 mm, log) is
    bare, translucent Nafion, which returns no spot the head can use, so the operator aims the laser at the end of the
    plating: the head reads w(L - m), the beam's own transfer function there (labrig.physics.transfer.displacement_tf
    with sensor_x) over the tip's, with the session's history (inject_fresh2._through): the gain a few per cent low, the
    modes read inboard (zeros move, poles stay). Displacement only. Measured (s001_161, m 0.56 mm) displacement RMS -5.3
    % (residual 5.3 %, 160x its noise): the slow records' gain 0.947 (+0.05 deg), the 13.7 Hz sines' 0.959, the 20 Hz
    ones' 0.963; the 1 V steps at 4.44-4.47 mm by their plateaus' end (4.69-4.72 mm clean)."""
    from labrig.physics import transfer

    m = lu(s.rng, 0.4e-3, 1.5e-3)

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        sp = _spec(s, r)
        sm = sp.with_(sensor_x=sp.geometry.length - m)

        def h(z: np.ndarray) -> np.ndarray:
            with np.errstate(divide="ignore", invalid="ignore"):
                return transfer.displacement_tf(z, sm) / transfer.displacement_tf(z, sp)

        return h

    _map_through(s, H, 2.0)


def so_tape_target_drying(s: Session) -> None:
    """A strip in air whose dark plating returns little light: the lab sticks a small piece of retro-reflective tape on
    the face under the line-beam head (its line 2-4 mm long along the strip, ending a margin m0 0.1-0.3 mm inside the
    tip's end), the tape covering the inboard share f (0.3-0.6) of the line and returning R_t (5-20) times what the wet
    plating does: the receiver reports the intensity-weighted centroid of the line's heights, sqrt(sum R_j xi_j^2/sum
    R_j) the station for the quasi-static uniform curvature. The strip, mounted wet 60-600 s before the first record,
    dries at its surface (tau_d 600-2400 s, log) and the plating brightens rho (2-4) times as its water film goes, so
    the centroid walks outward towards the tip record by record. Each record at the station of its middle
    (inject_fresh10._station, the inboard end the line's); displacement only. Measured (s001_161: a 2.9 mm line, the
    tape on 0.47 of it returning 12.5 times the wet plating, rho 2.4, tau_d 1090 s) displacement RMS -19 % (residual 19
    %, 600x its noise): the 1 V harmonics' gain 0.804, 0.808, 0.810, 0.810 block by block, the 20 Hz sines' 0.864 to
    0.861; the 1 V steps at 3.76, 3.79, 3.81, 3.81 mm by their plateaus' end (4.69-4.72 mm clean)."""
    L = float(s.specimen["length_m"])
    ell, m0, f = s.rng.uniform(2e-3, 4e-3), s.rng.uniform(1e-4, 3e-4), s.rng.uniform(0.3, 0.6)
    r_t, rho = s.rng.uniform(5.0, 20.0), s.rng.uniform(2.0, 4.0)
    t_m, tau_d = s.t0 - s.rng.uniform(60.0, 600.0), lu(s.rng, 600.0, 2400.0)
    xi = (L - m0 - ell * (1.0 - (np.arange(16) + 0.5) / 16.0)) / L  # the line's points, inboard to outboard
    tape = np.arange(16) < int(round(16 * f))

    def station(t_mid: float) -> float:
        bright = 1.0 + (rho - 1.0) * -math.expm1(-max(t_mid - t_m, 0.0) / tau_d)
        wgt = np.where(tape, r_t, bright)
        return float(np.sqrt(np.sum(wgt * xi**2) / np.sum(wgt)))

    _station(s, lambda r: np.full(r.cols["t_s"].size, station(float(np.mean(r.cols["t_s"])))), float(xi[0]))


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_sma_wire_clamp(s: Session) -> None:
    """A clamp whose jaw is pulled by a shape-memory (NiTi) wire through a lever, the operator setting the wire's
    heating current at each setting while watching the load cell: in its austenite range the wire's stress follows its
    temperature (Clausius-Clapeyron, 6-7.5 MPa/K), and at a fixed current the wire's temperature follows the enclosure's
    air, which wanders (an Ornstein-Uhlenbeck process of 0.2-0.6 K over 200-900 s, log) and drifts by 0.5-2 K over the
    session (either way); the wire also relaxes its stress under the held heating (functional fatigue, r_f 0.5-2 % a
    decade of time, tau 5-50 s, log). The top setting's stress sigma_top 250-400 MPa, the others in proportion to their
    force, so the same kelvin moves a light setting's force more: F/F_set = (1 + (dsigma/dT) dT/sigma_set) (1 - r_f
    log10(1 + u/tau)), up and down, from each setting (inject_fresh25._setting_of) through the preset's clamp law
    (inject_fresh4._clamp_law), the load cell showing it. Measured (paper_160: sigma_top 343 MPa, 6.2 MPa/K, the air
    0.22 K about a fall of 1.1 K, r_f 1.4 % a decade) the load cell at 0.86-0.99 of its setting in the 612 kPa block's
    records, 0.96-1.00 at 1837, 0.99-1.00 at 3062 and 0.97-1.00 at 4287 kPa; displacement residual 0.038 % of its RMS
    (2.2x its noise), current 0.32 % (0.24x); the top block's 20 Hz sines' gain 0.921 (-1.6 deg: its f1 moved)."""
    sig_top, dsdt = s.rng.uniform(250.0, 400.0), s.rng.uniform(6.0, 7.5)
    sd, tau_w = s.rng.uniform(0.2, 0.6), lu(s.rng, 200.0, 900.0)
    trend = _sign(s) * s.rng.uniform(0.5, 2.0)
    r_f, tau_f = s.rng.uniform(0.005, 0.02), lu(s.rng, 5.0, 50.0)
    setting = _setting_of(s)
    starts = {p: setting(p, a) for p, a in _by_pressure_start(s).items()}
    p_top = max(starts)
    tg = _session_grid(s, 5.0, 1200.0)
    temp = sd * _ou(s, tg, tau_w) + trend * (tg - s.t0) / (s.t1 - s.t0)

    def rel(t: np.ndarray, p: float, t_first: float) -> np.ndarray:
        ts = starts.get(p, t_first - 20.0)
        dT = np.interp(np.asarray(t, float), tg, temp) - float(np.interp(ts, tg, temp))
        creep = 1.0 - r_f * np.log10(1.0 + np.clip(np.asarray(t, float) - ts, 0.0, None) / tau_f)
        return (1.0 + dsdt * dT / (sig_top * p / p_top)) * creep

    _clamp_law(s, rel)


def cr_hemostat_serration(s: Session) -> None:
    """A surgical hemostat as the clamp (a medical lab's), its ratchet's notch setting the force: its serrated jaws'
    teeth indent the wet Nafion at the root and, under the held gap, the indentation creeps, the force relaxing as (1 +
    u/tau)^(-n) (tau 2-20 s, log) from each setting. The operator re-seats the strip in the same place at every
    re-clamping, and the teeth fall back into the dents the earlier settings left, where the polymer is compacted and
    creeps less: each setting's exponent n_k = n_0 (1 - h (1 - exp(-D_k))), n_0 0.01-0.04, h 0.4-0.8, D_k the earlier
    settings' dents (sum of (p_j/p_top)^(2/3), the indentation depth) times 1-3: the later, harder settings relax less
    than the first. From each setting (inject_fresh25._setting_of) through the preset's clamp law
    (inject_fresh4._clamp_law), the load cell showing it. Measured (p15_162: n_0 0.037, tau 3.5 s, h 0.75) the load cell
    at 0.81-0.88 of its setting in the 612 kPa block's records, 0.88-0.93 at 1837, 0.93-0.96 at 3062, 0.95-0.97 at 4287
    kPa; displacement residual 0.17 % of its RMS (2.5x its noise), current 0.79 % (0.52x); the 13.7 and 20 Hz sines near
    the strip's first resonance moved most (the top block's 20 Hz gain 1.26)."""
    n0, tau, h = s.rng.uniform(0.01, 0.04), lu(s.rng, 2.0, 20.0), s.rng.uniform(0.4, 0.8)
    depth = s.rng.uniform(1.0, 3.0)
    setting = _setting_of(s)
    starts = sorted(((setting(p, a), p) for p, a in _by_pressure_start(s).items()))
    p_top = max(p for _, p in starts)
    expo, dents = {}, 0.0
    for ts, p in starts:
        expo[p] = (ts, n0 * (1.0 - h * -math.expm1(-depth * dents)))
        dents += (p / p_top) ** (2.0 / 3.0)

    def rel(t: np.ndarray, p: float, t_first: float) -> np.ndarray:
        ts, n = expo.get(p, (t_first - 20.0, n0))
        return (1.0 + np.clip(np.asarray(t, float) - ts, 0.0, None) / tau) ** (-n)

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_air_line_leak(s: Session) -> None:
    """A strip in air beside a leaking push-in fitting of the lab's compressed-air line (dried air, its dew point far
    below the room's): the leak's jet, its flow going as the square root of the line's pressure, dilutes the room's air
    at the strip by beta (0.3-0.6) at full pressure. The line's pressure saws with the compressor's cycle (a period of
    3-12 min, log: falling as the lab draws air from p_hi to p_lo, 0.6-0.8 of it, then recharging over 10-25 % of the
    cycle). The strip, mounted from a humid box 60-600 s before the first record, takes its water from the air it sees
    through Nafion's slow vapour sorption (tau_w 600-2000 s, log), so it dries towards the jet's humidity with the
    compressor's ripple on top. Gain and conductance fall with the water lost relative to the first record (the gain by
    G 0.5-0.9 of it, the conductance by 0.6-1 of the gain's), the spectra at the next series' start
    (inject_fresh9._dry_by). Measured (s001_161: beta 0.40, a cycle of 630 s, tau_w 810 s, G 0.74) displacement RMS -16
    % (residual 19 %, 580x its noise), current RMS -17 % (residual 18 %, 47x its noise): the 1 V steps at 4.65, 3.83,
    3.65, 3.62 mm by their plateaus' end block by block (4.69-4.72 mm clean); the 1 V harmonics' gain 0.958 to 0.769
    (current 0.963 to 0.800); the impedance 1.19, 1.24, 1.25x in the later blocks' spectra."""
    beta, period, lo = s.rng.uniform(0.3, 0.6), lu(s.rng, 180.0, 720.0), s.rng.uniform(0.6, 0.8)
    charge, phase = s.rng.uniform(0.1, 0.25), s.rng.uniform(0.0, 1.0)
    t_m, tau_w = s.t0 - s.rng.uniform(60.0, 600.0), lu(s.rng, 600.0, 2000.0)
    gain, share = s.rng.uniform(0.5, 0.9), s.rng.uniform(0.6, 1.0)
    tg = np.arange(t_m, s.t1 + 2.0, 1.0)
    u = ((tg - t_m) / period + phase) % 1.0
    p = np.where(u < 1.0 - charge, 1.0 - (1.0 - lo) * u / (1.0 - charge), lo + (1.0 - lo) * (u - 1.0 + charge) / charge)
    w_eq = 1.0 - beta * np.sqrt(p)
    a = math.exp(-1.0 / tau_w)
    w = signal.lfilter([1.0 - a], [1.0, -a], w_eq, zi=[a * 1.0])[0]  # from the humid box's 1 at the mounting
    w0 = float(np.interp(s.t0, tg, w))

    def lost(t: np.ndarray) -> np.ndarray:
        return (w0 - np.interp(np.asarray(t, float), tg, w)) / w0

    _dry_by(s, lambda t: gain * lost(t), lambda t: share * gain * lost(t))


def dh_electrophoretic_colloid(s: Session) -> None:
    """A bath made up with water from a line carrying colloidal silica (or the residue of the lab's alumina polishing
    slurry), negatively charged particles of 20-200 nm: the drive's field in the water drives them onto whichever face
    is the anode (electrophoretic deposition, in proportion to the time-integral of the drive, Hamaker's law), where
    they pack into the plating's pores and block the double layer behind them; when that face turns cathodic a share of
    the loose deposit is pushed off again (at kr 0.1-0.5 of the deposition's rate). Each face's blocked share theta
    grows towards th_max (0.3-0.6) at k |v|, k such that the session's largest face dose fills 0.5-2 e-folds; the
    strip's capacitance is its two faces' in series, so the conductance falls by 1 - 2/(1/(1 - theta_A) + 1/(1 -
    theta_B)) and the gain with it (0.6-1 of it), relative to the first record: the positive steps' long plateaus load
    one face, the sines both and strip them; the spectra at the next series' start (inject_fresh9._dry_by). Measured
    (paper_160: th_max 0.35, 1.5 e-folds, kr 0.38, the gain 0.63 of it) displacement RMS -7.0 % (residual 8.1 %, 480x
    its noise), current RMS -14 % (residual 15 %, 11x its noise): the 1 V steps at 8.69, 8.27, 7.99, 7.81 mm by their
    plateaus' end block by block (8.82-8.83 mm clean), their current's peak 28.2, 25.2, 22.6, 22.1 mA (26.3-28.2); the
    impedance 1.09, 1.16, 1.22x in the later blocks' spectra."""
    th_max, folds, kr = s.rng.uniform(0.3, 0.6), s.rng.uniform(0.5, 2.0), s.rng.uniform(0.1, 0.5)
    share = s.rng.uniform(0.6, 1.0)
    tg, vp = _grid_of(s, "v_V", lambda v, _: np.clip(v, 0.0, None))
    _, vn = _grid_of(s, "v_V", lambda v, _: np.clip(-v, 0.0, None))
    k = folds / max(float(np.sum(vp)), float(np.sum(vn)), 1e-30)
    th_a, th_b, a_, b_ = np.empty(tg.size), np.empty(tg.size), 0.0, 0.0
    for j, (up, dn) in enumerate(zip(vp.tolist(), vn.tolist())):
        a_ += k * up * (th_max - a_) - kr * k * dn * a_  # face A the anode on a positive drive
        b_ += k * dn * (th_max - b_) - kr * k * up * b_
        th_a[j], th_b[j] = a_, b_
    cond = 2.0 / (1.0 / (1.0 - th_a) + 1.0 / (1.0 - th_b))
    c0 = float(np.interp(s.t0, tg, cond))

    def loss(t: np.ndarray) -> np.ndarray:
        return 1.0 - np.interp(np.asarray(t, float), tg, cond) / c0

    _dry_by(s, lambda t: share * loss(t), loss)


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_cathodic_blistering(s: Session) -> None:
    """Hydrogen made on the cathodic face at the large drives (beyond v_h 0.6-0.85 V, width 0.03-0.06 V: the 1 V steps'
    plateaus and the 1 V harmonics' crests) partly enters the interface under the plating through its cracks and gathers
    in micro-blisters that lift the film off the membrane; an unsupported film's cracks open wider and sooner under the
    bend's tension. The face a positive drive makes the cathode is the one it stretches (the strip bends away from the
    swelling cathode side): its blistered share b grows with the hydrogen it makes (the current through the gate, second
    by second, the session's dose filling 1-3 e-folds) and shrinks as the gas dissolves (tau_b 300-1500 s, log). Each
    face's cracks open beyond e0 (1 - b/2) (e0 0.1-0.3 of the session's displacement scale), dR/R = k0 (1 + g b) (e - e0
    (1 - b/2))+ (k0 0.05-0.15, g 2-6), the other face with its own b on the other sign. Gains fall by 0.03-0.08
    (displacement) and 0.06-0.15 (current) per unit of dR/R (inject_fresh3._resist). Measured (p15_162: v_h 0.73 V, k0
    0.082, e0 0.16, g 5.9, tau_b 350 s) displacement RMS -3.9 % (residual 4.1 %, 62x its noise), current RMS -0.30 %
    (residual 1.6 %, 1.1x its noise): the 1 V records only (40 of the 68 time series touched); the 1 V steps at
    2.13-2.14 mm by their plateaus' end (2.27 mm clean), their plateau's current 0.35-0.39 mA (0.40-0.45); the 1 V
    harmonics' gain 0.973-0.975 (current 0.974-0.977)."""
    v_h, w = s.rng.uniform(0.6, 0.85), s.rng.uniform(0.03, 0.06)
    k0, e0, g = s.rng.uniform(0.05, 0.15), s.rng.uniform(0.1, 0.3), s.rng.uniform(2.0, 6.0)
    folds, tau_b = s.rng.uniform(1.0, 3.0), lu(s.rng, 300.0, 1500.0)
    tg, hb = _grid_of(s, "i_A", lambda i, v: np.abs(i) * _logistic((v - v_h) / w))  # face B the cathode at v > 0
    _, ha = _grid_of(s, "i_A", lambda i, v: np.abs(i) * _logistic((-v - v_h) / w))
    k = folds / max(float(np.sum(ha) + np.sum(hb)), 1e-30)
    decay = math.exp(-1.0 / tau_b)
    bl_a, bl_b, a_, b_ = np.empty(tg.size), np.empty(tg.size), 0.0, 0.0
    for j, (qa, qb) in enumerate(zip(ha.tolist(), hb.tolist())):
        a_ = (a_ + k * qa * (1.0 - a_)) * decay
        b_ = (b_ + k * qb * (1.0 - b_)) * decay
        bl_a[j], bl_b[j] = a_, b_

    def law(r: Rec, e: np.ndarray) -> np.ndarray:
        t = r.cols["t_s"]
        ba, bb = np.interp(t, tg, bl_a), np.interp(t, tg, bl_b)
        e = np.asarray(e, float)
        return (k0 * (1.0 + g * bb) * np.clip(e - e0 * (1.0 - 0.5 * bb), 0.0, None)
                + k0 * (1.0 + g * ba) * np.clip(-e - e0 * (1.0 - 0.5 * ba), 0.0, None))

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


def sr_knurled_contact_bite(s: Session) -> None:
    """The jaws' contacts are knurled brass inserts (to bite through the plating's surface film), their teeth pressed
    into the plating at the jaw's edge where the bend's strain is largest: each tooth's dent is a notch from which the
    film cracks under tension, and the dents go deeper as the clamp is set harder (indentation depth as force^(2/3)), so
    the gauge grows with the setting: dR/R = k_top (p/p_top)^(2/3) ((x - e0)+ + o (-x - e0)+), x the bend over the
    session's displacement scale on the face with the sharper insert (drawn), k_top 0.15-0.4, e0 0.05-0.2, the other
    face's worn insert o 0.3-0.8 of it. Gains fall by 0.03-0.08 (displacement) and 0.06-0.15 (current) per unit of dR/R
    (inject_fresh3._resist). Measured (paper_160: k_top 0.24, e0 0.078, the other insert 0.79 of it) displacement RMS
    -1.7 % (residual 1.9 %, 110x its noise), current RMS -0.26 % (residual 0.99 %, 0.75x its noise): the 1 V steps at
    8.73, 8.65, 8.57, 8.51 mm by their plateaus' end block by block (8.82-8.83 mm clean); the 1 V harmonics' gain 0.996,
    0.991, 0.988, 0.984 (current alike); the small sines untouched (51 of the 68 time series touched)."""
    side, k_top, e0, o = _sign(s), s.rng.uniform(0.15, 0.4), s.rng.uniform(0.05, 0.2), s.rng.uniform(0.3, 0.8)
    p_top = max(s.pressures())

    def law(r: Rec, e: np.ndarray) -> np.ndarray:
        kp = k_top * (float(r.entry["pressure_kPa"]) / p_top) ** (2.0 / 3.0)
        x = side * np.asarray(e, float)
        return kp * (np.clip(x - e0, 0.0, None) + o * np.clip(-x - e0, 0.0, None))

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_lvdt_core(s: Session) -> None:
    """No laser: a free-core LVDT (a 4-6 mm bore, its coil's axis along the bending direction) whose ferrite core (a 0.5
    mm pin, about 2 mg: a few per cent of the strip's moving mass, left out) stands off the strip's face at its tip. The
    secondaries' coupling to the core falls off as it leaves them, the differential output exp(-((d - s_c)/w)^2) -
    exp(-((d + s_c)/w)^2) (s_c 1.5-2.5 of the session's largest bend, w 1.0-1.5 s_c), linear at the centre and bending
    over away from it; the core also tilts with the tip (cos(2 d/L)^q, q 0.2-0.5) and is carried off the bore's axis by
    the tip's draw-back ((2/3) d^2/L), losing coupling as (1 - c (offset/r_bore)^2) (r_bore 2-3 mm, c 0.01-0.04): all
    compress the large bends, odd. The lab's calibration is linear at rest. Tabulated and interpolated (slope 1 at rest,
    inject_fresh22._table_map); displacement only. Measured (paper_160: s_c 2.0 of the largest bend, w 1.43 s_c, q 0.28,
    r_bore 2.2 mm, c 0.020) displacement RMS -7.3 % (residual 8.3 %, 490x its noise): the 1 V steps at 7.63-7.64 mm by
    their plateaus' end (8.82-8.83 mm clean), the 1 V harmonics' gain 0.975-0.978, the 0.5 V 0.1 Hz sines' 0.999, the 20
    Hz sines' 1.000."""
    big = _largest(s) or ref_disp(s)
    L = float(s.specimen["length_m"])
    s_c = s.rng.uniform(1.5, 2.5) * big
    w = s.rng.uniform(1.0, 1.5) * s_c
    q, r_b, c = s.rng.uniform(0.2, 0.5), s.rng.uniform(2e-3, 3e-3), s.rng.uniform(0.01, 0.04)

    def reading(d: np.ndarray) -> np.ndarray:
        v = np.exp(-(((d - s_c) / w) ** 2)) - np.exp(-(((d + s_c) / w) ** 2))
        off = (2.0 / 3.0) * d * d / L
        return v * (1.0 - c * (off / r_b) ** 2) * np.cos(2.0 * d / L) ** q

    _table_map(s, reading)


def ld_inductive_analog(s: Session) -> None:
    """No laser: an industrial analogue inductive proximity sensor (an M18 body with a 0-10 V output, outside the
    cuvette's glass) facing a steel shim tab (25 um, 2 x 2 mm, under 1 mg) glued on the strip's face at its tip: a small
    target's signal falls with the gap as 1/(1 + (g/g_0)^n) (n 2-4), and the lab sets the rest gap at that curve's
    inflection, where it is steepest and straightest, and calibrates it linearly there; the largest bend spans 0.3-0.55
    of the rest gap. The curve bends over on both sides of the inflection, compressing the large bends (nearly odd, a
    small even part from its asymmetry). Tabulated and interpolated (slope 1 at rest, inject_fresh22._table_map);
    displacement only. Measured (p15_162: n 3.6, the largest bend 0.34 of the rest gap) displacement RMS -5.1 %
    (residual 5.7 %, 85x its noise): the 1 V steps at 2.07 mm by their plateaus' end (2.27 mm clean), the 1 V harmonics'
    gain 0.978-0.979, the 0.5 V 0.1 Hz sines' 0.999, the 20 Hz sines' 1.000."""
    big = _largest(s) or ref_disp(s)
    n = s.rng.uniform(2.0, 4.0)
    g_rest = big / s.rng.uniform(0.3, 0.55)
    g0 = g_rest / ((n - 1.0) / (n + 1.0)) ** (1.0 / n)
    side = _sign(s)

    def reading(d: np.ndarray) -> np.ndarray:
        gap = np.clip(g_rest - side * d, 1e-6 * g_rest, None)
        return side / (1.0 + (gap / g0) ** n)

    _table_map(s, reading)


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_agc_hum(s: Session) -> None:
    """Hum inside the laser head: its receiver board sits beside the head's own mains transformer, which puts a little
    of the line (50 or 60 Hz, inject_fresh12._line_f, with its third harmonic at 0.1-0.3) on the receiver's signal after
    the line sensor; the head's automatic gain control keeps the spot's peak constant, so as the bent strip tilts its
    plated face away (its return falling as cos^k of the tip's angle 2 d/L, k 3-8) the gain rises and the hum's position
    error with it: a_h (1.5-5 um at rest, log) times 1/cos^k(2 d/L). A line whose amplitude the strip's own bend
    modulates (sidebands at the line plus and minus twice the drive's frequency), phase locked to the session clock.
    Displacement only. Measured (paper_160: 50.018 Hz, 2.1 um at rest, k 7.4: 8 um on the 1 V steps' plateaus)
    displacement residual 0.066 % of its RMS (3.9x its noise), every time series touched."""
    f0, h3 = _line_f(s), s.rng.uniform(0.1, 0.3)
    a_h, k = lu(s.rng, 1.5e-6, 5e-6), s.rng.uniform(3.0, 8.0)
    ph = s.rng.uniform(0.0, 2.0 * np.pi)
    L = float(s.specimen["length_m"])
    for r in s.series():
        t, d = r.cols["t_s"], r.cols["disp_m"]
        w = 2.0 * np.pi * f0 * t + ph
        gain = np.cos(np.clip(2.0 * d / L, -1.2, 1.2)) ** (-k)
        r.cols["disp_m"] = d + a_h * gain * (np.cos(w) + h3 * np.cos(3.0 * w))


def mp_grid_frequency(s: Session) -> None:
    """Hum from the bench's wiring on the laser's cable and the current amplifier's input (1-5 um and 2-10 uA, log, its
    third harmonic 0.1-0.3), its frequency the grid's, which is never quite nominal: it wanders (an Ornstein-Uhlenbeck
    process of 10-30 mHz over 60-300 s, log) and swings at each full hour as the generation schedules change in steps (a
    dip or a rise of 40-120 mHz, either way per hour, reached within 1-3 min and recovering over 5-15 min, log; the
    first full hour 0-60 min into the session). The hum's phase is the grid's integrated phase (on a 0.5 s grid,
    interpolated), so its line wanders by a tenth of a hertz. Displacement and current, every time series. Measured
    (p15_162: 60 Hz, 4.0 um and 9.4 uA, the wander 14 mHz over 100 s, a swing of -111 mHz at the full hour 2760 s into
    the session) displacement residual 0.33 % of its RMS (4.9x its noise), current 0.24 % (0.16x), every time series
    touched."""
    f0 = (50.0 if s.rng.random() < 0.5 else 60.0)
    amp = {"disp_m": lu(s.rng, 1e-6, 5e-6), "i_A": lu(s.rng, 2e-6, 1e-5)}
    h3 = s.rng.uniform(0.1, 0.3)
    sd, tau = lu(s.rng, 0.01, 0.03), lu(s.rng, 60.0, 300.0)
    first = s.t0 + s.rng.uniform(0.0, 3600.0)
    rise, fall = lu(s.rng, 60.0, 180.0), lu(s.rng, 300.0, 900.0)
    tg = _session_grid(s, 0.5, 2.0)
    df = sd * _ou(s, tg, tau)
    u_pk = math.log(fall / rise) * rise * fall / (fall - rise)  # the swing's peak, where it is normalised to its size
    peak = math.exp(-u_pk / fall) - math.exp(-u_pk / rise)
    for t_h in np.arange(first, s.t1, 3600.0):
        size = _sign(s) * s.rng.uniform(0.04, 0.12)
        u = np.clip(tg - t_h, 0.0, None)
        df = df + size * (np.exp(-u / fall) - np.exp(-u / rise)) / peak * (tg >= t_h)
    phase = 2.0 * np.pi * np.r_[0.0, np.cumsum(0.5 * (df[1:] + df[:-1]) * np.diff(tg))]
    ph = {col: s.rng.uniform(0.0, 2.0 * np.pi) for col in amp}
    for r in s.series():
        t = r.cols["t_s"]
        base = 2.0 * np.pi * f0 * t + np.interp(t, tg, phase)
        for col, a_ in amp.items():
            w = base + ph[col]
            r.cols[col] = r.cols[col] + a_ * (np.cos(w) + h3 * np.cos(3.0 * w))


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_vortex_shedding(s: Session) -> None:
    """The bath stirred all session by a magnetic stirrer (to hold it mixed at the thermostat's temperature), its flow
    passing the hanging strip broadside at a few cm/s: the strip sheds vortices from its edges at the Strouhal frequency
    (St 0.15 on its width: f_v 0.6-1.8 Hz, log), the flow's speed, and with it f_v, wandering by 3-8 % over 20-60 s
    (log); the alternating lift drives the strip at f_v through its first mode (the preset's first resonance at the
    record's pressure, inject_fresh22._f1; damping 0.1-0.3), a tip motion of 3-20 um (log) in the quasi-static limit,
    its amplitude wandering by 20-40 % with the vortex street's coherence. A narrow, wandering line at no drive's
    frequency, in every record whatever the drive; displacement only. Measured (paper_160: f_v 1.31 Hz, 19 um; p15_162:
    1.02 Hz, 8.4 um) displacement residual 0.51 % of its RMS (30x its noise) and 0.71 % (11x), every time series
    touched; the 1 V steps' plateau ends moved by up to 33 um and 8 um."""
    f_v, sd_f, tau_f = lu(s.rng, 0.6, 1.8), s.rng.uniform(0.03, 0.08), lu(s.rng, 20.0, 60.0)
    a_v, sd_a, zeta = lu(s.rng, 3e-6, 2e-5), s.rng.uniform(0.2, 0.4), s.rng.uniform(0.1, 0.3)
    tg = _session_grid(s, 0.1, 2.0)
    f = f_v * (1.0 + sd_f * _ou(s, tg, tau_f))
    phase = 2.0 * np.pi * np.r_[0.0, np.cumsum(0.5 * (f[1:] + f[:-1]) * np.diff(tg))] + s.rng.uniform(0.0, 2 * np.pi)
    amp = np.exp(sd_a * _ou(s, tg, tau_f) - 0.5 * sd_a**2)
    cache: dict[float, float] = {}
    for r in s.series():
        t = r.cols["t_s"]
        f1 = _f1(s, float(r.entry["pressure_kPa"]), cache)
        x = f_v / f1
        gain = 1.0 / complex(1.0 - x * x, 2.0 * zeta * x)
        ph = np.interp(t, tg, phase) + math.atan2(gain.imag, gain.real)
        r.cols["disp_m"] = r.cols["disp_m"] + a_v * abs(gain) * np.interp(t, tg, amp) * np.cos(ph)


def out_reseated_root(s: Session) -> None:
    """At one re-clamping after the first (drawn) the operator, loosening the jaws, lets the strip slide and re-seats it
    delta (0.5-2 mm, log) deeper between them, re-aims the laser at the new tip and goes on; the manifest keeps the
    strip's length. From that block on the free length is L - delta: the tip's gain falls (nearly as L^2), the first
    resonance rises (as 1/L^2) and the free part's electrical line is shorter (the current lower); the clamp, its area
    and the load cell as before. Every record and spectrum of the later blocks through the ratios of the shorter strip's
    transfer functions (displacement and admittance, labrig.physics.transfer) over the strip's (as
    inject_fresh4._ratio_both, with the session's history), the spectra divided by the same admittance ratio. A step in
    gain, resonance and conductance at one re-clamping, the load cell unmoved. Measured (s001_161: 0.75 mm deeper at the
    1300 kPa setting) displacement RMS -3.6 % (residual 5.1 %, 160x its noise), current residual 0.88 % (2.3x): the
    later blocks' 1 V steps at 4.37-4.38 mm (4.71-4.72 mm clean), their 0.1 Hz gain 0.934 (current 0.980), the 20 Hz
    sines' 0.73-0.75 (+6 to +7 deg), their spectra up to 2.2 % higher; (p15_162: 0.78 mm at 3062 kPa) -4.9 % (residual
    7.1 %, 110x), current 1.3 % (0.89x): the steps at 2.04 mm (2.27), the 0.1 Hz gain 0.902 (current 0.959), the 13.7
    and 20 Hz sines near the moved resonance 0.68-1.56, the spectra up to 4.3 % higher; 34 of the 68 time series
    touched."""
    from dataclasses import replace

    from labrig.physics import transfer

    delta = lu(s.rng, 0.5e-3, 2e-3)
    p_k, t_set = _later_setting(s)
    order = sorted(_by_pressure_start(s).items(), key=lambda kv: kv[1])
    later = {p for p, a in order if a >= t_set}

    def shorter(r: Rec):
        sp = _spec(s, r)
        if float(r.entry["pressure_kPa"]) not in later:
            return sp
        return sp.with_(geometry=replace(sp.geometry, length=sp.geometry.length - delta))

    def ratio(tf: Callable) -> Callable[[Rec], Callable[[np.ndarray], np.ndarray]]:
        def per(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
            a, b = _spec(s, r), shorter(r)

            def h(z: np.ndarray) -> np.ndarray:
                with np.errstate(divide="ignore", invalid="ignore"):  # s = 0 (lti replaces that bin)
                    return tf(z, b) / tf(z, a)

            return h

        return per

    cur = _through_x(s, {id(r): r.cols["i_A"] for r in s.series()}, ratio(transfer.admittance_tf), 2.0)
    dis = _through(s, ratio(transfer.displacement_tf), 2.0)
    for r in s.series():
        if float(r.entry["pressure_kPa"]) in later:
            r.cols["i_A"], r.cols["disp_m"] = cur[id(r)], dis[id(r)]
    for r in s.recs:
        if r.series or float(r.entry["pressure_kPa"]) not in later:
            continue
        sp = _spec(s, r)
        short = shorter(r)
        z = 2j * np.pi * r.cols["f_Hz"]
        ratio = transfer.admittance_tf(z, sp) / transfer.admittance_tf(z, short)
        zz = (r.cols["z_re_ohm"] + 1j * r.cols["z_im_ohm"]) * ratio
        r.cols["z_re_ohm"], r.cols["z_im_ohm"] = zz.real, zz.imag


def out_loose_ground_lug(s: Session) -> None:
    """The DAQ's analogue ground reaches its terminal block through a ring lug whose screw has worked loose: when the
    bench is touched or vibrates the lug's contact makes and breaks (a random telegraph, its bad state lasting 2-15 s,
    log, its good state 10-60 s, log), and in the bad state the return current of the instruments sharing it puts dv
    (2-8 mV, log, either sign) on the ground every single-ended input is read against: each channel reads dv through its
    own scale, the drive monitor dv itself, the current dv over the amplifier's transimpedance (1-10 V/mA, log), the
    laser dv times its analogue scale (0.5-2 mm/V, log). Offset steps at the same instants on all three channels with
    fixed ratios; the strip feels none of them (the monitor's steps are not the drive's). Measured (paper_160: -2.8 mV,
    bad 11 s, good 17 s, 6.6 V/mA, 1.7 mm/V) drive monitor residual 0.31 % of its RMS (6.6x its noise), displacement
    0.082 % (4.8x), current 0.008 % (0.006x), 51 of the 68 time series touched; (s001_161: -7.2 mV, bad 2.2 s, good 46
    s, 5.6 V/mA, 0.54 mm/V) monitor 0.25 % (5.6x), displacement 0.040 % (1.2x), 16 touched."""
    dv = _sign(s) * lu(s.rng, 2e-3, 8e-3)
    bad, good = lu(s.rng, 2.0, 15.0), lu(s.rng, 10.0, 60.0)
    scale = {"v_V": 1.0, "i_A": 1e-3 / lu(s.rng, 1.0, 10.0), "disp_m": 1e-3 * lu(s.rng, 0.5, 2.0)}
    edges, t, state = [], s.t0 - s.rng.uniform(0.0, good), 0
    while t < s.t1:
        t += float(s.rng.exponential(bad if state else good))
        state = 1 - state
        edges.append(t)
    edges = np.array(edges)
    for r in s.series():
        tt = r.cols["t_s"]
        on = (np.searchsorted(edges, tt, side="right") % 2).astype(float)  # 1 after an odd number of switches
        for col, k in scale.items():
            r.cols[col] = r.cols[col] + dv * k * on


def out_oxide_film_contact(s: Session) -> None:
    """The jaws' contact pads tin-plated copper, tarnished: a thin oxide film between them and the plating that conducts
    by tunnelling, its conductance growing with the voltage across it (Simmons: G = G_0 (1 + (u/u_0)^2)), so the
    contact's resistance falls at large currents: R_c(i) ~ R_c0/(1 + (i R_c0/u_0)^2) (R_c0 2-6 ohm, log; u_0 0.02-0.06
    V), in series with the strip. At rest and at the small currents it is R_c0, already in the strip's contact
    resistance; at the steps' charging spikes and the fast sines' currents it falls, and the strip receives i (R_c0 -
    R_c(i)) more of the drive than the monitor's reading implies, an unseen voltage answered through the strip's
    measured step responses (inject_fresh7._superpose): the spikes taller and quicker, a little of it in the bend,
    nothing at the slow drives. Current and displacement. Measured (s001_161: R_c0 2.7 ohm, u_0 0.023 V) current RMS
    +0.97 % (residual 1.3 %, 3.4x its noise), displacement residual 0.048 % (1.5x): the 1 V steps' current peaks +0.7 mA
    (18.8-19.0 mA for 18.1-18.3), the 13.7 and 20 Hz sines' current gain 1.016-1.018, the 0.1 Hz records' 1.001-1.002;
    (p15_162: 5.7 ohm, 0.024 V) +6.6 % (residual 7.8 %, 5.2x), displacement 0.14 % (2.1x): the peaks +3.7 to +4.3 mA,
    the 13.7 and 20 Hz sines' current gain 1.08-1.10."""
    r0, u0 = lu(s.rng, 2.0, 6.0), s.rng.uniform(0.02, 0.06)
    e = {}
    for r in s.series():
        i = r.cols["i_A"]
        x = (i * r0 / u0) ** 2
        e[id(r)] = i * r0 * x / (1.0 + x)
    _superpose(s, e)


FRESH30_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"copper_tape_contacts": br_copper_tape_contacts, "detergent_drop": br_detergent_drop},
    "faradaic_current": {"peroxide_rinse": far_peroxide_rinse, "perfusion_spells": far_perfusion_spells},
    "hysteresis": {"gripper_pin_joint": hy_gripper_pin_joint, "drying_line_guide": hy_drying_line_guide},
    "time_delay": {"eddy_shielded_hall": td_eddy_shielded_hall, "dmm_nplc_current": td_dmm_nplc_current},
    "sensor_offset": {"unplated_tip_margin": so_unplated_tip_margin, "tape_target_drying": so_tape_target_drying},
    "clamp_relaxation": {"sma_wire_clamp": cr_sma_wire_clamp, "hemostat_serration": cr_hemostat_serration},
    "dehydration": {"air_line_leak": dh_air_line_leak, "electrophoretic_colloid": dh_electrophoretic_colloid},
    "strain_resistance": {"cathodic_blistering": sr_cathodic_blistering,
                          "knurled_contact_bite": sr_knurled_contact_bite},
    "large_deflection": {"lvdt_core": ld_lvdt_core, "inductive_analog": ld_inductive_analog},
    "mains_pickup": {"agc_hum": mp_agc_hum, "grid_frequency": mp_grid_frequency},
    "unexplained": {"vortex_shedding": out_vortex_shedding, "reseated_root": out_reseated_root,
                    "loose_ground_lug": out_loose_ground_lug, "oxide_film_contact": out_oxide_film_contact},
}
inject.register_forms(FRESH30_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def v_cathodic_positive(s: Session) -> None:
    """A potentiostat that reports its current in the polarographic ("American") convention, cathodic current positive
    (the default of some makers' software, CH Instruments' among them), driving the strip through its working-electrode
    lead and logged from its own current output: every time series' i_A written with the opposite sign (a positive drive
    charges the strip with a current the file calls negative). The drive, the displacement, the load cell, the spectra
    (the analyser's own impedance, not a current), the rows and the manifest as they were. The import contract says
    nothing of the current's sign; ``labrig import`` takes it."""
    for r in s.series():
        r.cols["i_A"] = -r.cols["i_A"]


inject.VARIANTS.update({"cathodic_positive": v_cathodic_positive})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_160", "s001_161", "p15_162"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 6 / 7 effect cases on seeds 160-162
    "back_relaxation": [("copper_tape_contacts", 160, P, "settled_sines"), ("detergent_drop", 162, T, "log_steps")],
    "faradaic_current": [("peroxide_rinse", 160, P, "fixed_decimals"), ("perfusion_spells", 162, T, "no_loadcell")],
    "hysteresis": [("gripper_pin_joint", 161, S, "asrun"), ("drying_line_guide", 161, S, "swinging_door")],
    "time_delay": [("eddy_shielded_hall", 162, T, "midnight_clock"), ("dmm_nplc_current", 161, S, "cycle_averaged")],
    "sensor_offset": [("unplated_tip_margin", 161, S, "trigger_clock"), ("tape_target_drying", 161, S, "scan_hold")],
    "clamp_relaxation": [("sma_wire_clamp", 160, P, "measured_pressures"),
                         ("hemostat_serration", 162, T, "merged_loadcell")],
    "dehydration": [("air_line_leak", 161, S, "fir_decimated"), ("electrophoretic_colloid", 160, P, "host_timed")],
    "strain_resistance": [("cathodic_blistering", 162, T, "stop_trigger"),
                          ("knurled_contact_bite", 160, P, "block_clock")],
    "large_deflection": [("lvdt_core", 160, P, "coherent_sines"), ("inductive_analog", 162, T, "cathodic_positive")],
    "mains_pickup": [("agc_hum", 160, P, "dropped_packets"), ("grid_frequency", 162, T, "short_pretrigger")],
    "unexplained": [("vortex_shedding", 160, P, "cathodic_positive"), ("vortex_shedding", 162, T, "shortened_shuffled"),
                    ("reseated_root", 161, S, "reversed_laser"), ("reseated_root", 162, T, "split_spectra"),
                    ("loose_ground_lug", 160, P, "spectra_last"), ("loose_ground_lug", 161, S, "steps_sines"),
                    ("oxide_film_contact", 161, S, "float32_time"),
                    ("oxide_film_contact", 162, T, "eis_two_passes")],
}
CLEAN = [(160, P, "cathodic_positive"), (160, P, "two_pressures"), (161, S, "tared_records"),
         (161, S, "loadcell_dropout"), (162, T, "cathodic_positive"), (162, T, "no_spectra")]


def fresh30_cases(only: str | None = None) -> list[Case]:
    """The thirty-first held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds
    160-162)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh30_cases, "inject_fresh30", "fresh30")
