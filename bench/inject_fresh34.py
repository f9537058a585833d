"""A thirty-fifth held-out set for the diagnosis (issue 12), fresh34, written without sight of the diagnosis (its code,
its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh33.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (ammonia from a glass cleaner oxidised on
the platinum and poisoning it with its own nitrogen, a plasticine seal at the jaws' edge yielding as an elastoplastic
fillet, the two reflections of a cover-slip target and the laser controller's peak selection, cations crowding against
the cathode, a 4-20 mA current loop short of compliance, the plating's cracks debonding by interfacial fatigue, the
edges of a laser-cut strip cracking in their heat-affected zone, platinum dissolved at each oxide-reduction cycle) and
some on the history, the clamp pressure or the session's events (antifreeze from the circulator's reservoir topped up at
a re-clamping, a colleague's second laser head on the shared controller, a scan list grown at a re-clamping, the tip's
plating darkened by the electrolysis under the laser's spot, a correction-fluid marker flaking with the large bends, a
wet threadlocker curing in the clamp's thread, Parafilm on the jaws squeezed out under the clamp, a PCR machine's
exhaust cycling on the next bench, a vacuum cleaner's universal motor, an EV charger's 12-pulse rectifier) and some on
time (the hydrophobic recovery of plasma-cleaned faces, an oxygen scavenger running out in an open cuvette); lab wiring
or sensors among them (the cover slip and the controller's peak selection, the shared controller, the DAQ's scan list,
the current loop, the paint marker, the vacuum cleaner, the charger). Four structures outside the catalogue (truth
"unexplained": a spare strip left in the cuvette beside the tested one, coupled to it through the water; impedance
sweeps started while the motorised clamp was still ramping; a high-side shunt read by a difference amplifier of finite
common-mode rejection; the drive amplifier's polarity LED glaring into the laser's receiver); clean sessions. All on
three bases of new seeds (172-174: the paper strip, the seed-001 strip on its own sweep, the paper strip 11 mm free) and
on the earlier sets' data-shape variants plus one new here: spectra measured at fewer points per decade
(``sparse_spectra``).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh33 are reused (importing inject_fresh33 and inject_fresh32 registers every earlier set's
lookups), and the forms, bases, preset and variant of this set are registered into inject's lookups at import, none
replaced. Strengths are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it
made on its case, measured in memory against the clean base (relative RMS change over all series, form only, no variant;
"noise": the column's sample-to-sample noise at rest, inject_fresh15.rest_noise).

Run: python bench/inject_fresh34.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np

import inject
import inject_fresh32  # noqa: F401  (registers fresh32's and, through it, fresh30's forms, bases, presets and variants)
import inject_fresh33  # noqa: F401  (registers fresh33's and, through fresh31, every other earlier set's)
from inject import Case, Rec, Session, lu, ref_disp
from inject_fresh2 import _chrono, _map_through, _spec
from inject_fresh3 import _resist, _sign, _through_x
from inject_fresh4 import _clamp_law
from inject_fresh6 import _bursts
from inject_fresh9 import _dry_by, _session_grid
from inject_fresh10 import _lag_varying, _station
from inject_fresh12 import _line_f
from inject_fresh14 import _largest
from inject_fresh24 import _by_pressure_start
from inject_fresh25 import _setting_of
from inject_fresh26 import _later_setting, _split_noise
from inject_fresh29 import _exchanged, _grid_lag, _logistic
from inject_fresh33 import _late_by, _static_map

# the paper's strip 11 mm free (earlier sets used 12-29 and 31-45 mm, 30 mm is the paper preset itself and the seed-001
# strip is 20 mm): its 1 V step peaks at 1.23 mm, well inside the laser's +-20 mm (2 mm/V on the DAQ's +-10 V) and 2200x
# the laser's 0.55 um noise at rest; its first mode at 24.5 Hz (zeta 0.11), above the sines' top (20 Hz). Preset
# "paper_11", base "p11_174", registered in every process importing this module
inject.register_free_length("paper_11", 0.011)

inject.BASES.update({
    "paper_172": ("paper-sweep", "paper", 172),
    "s001_173": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 173),
    "p11_174": ("paper-sweep", "paper_11", 174),
})


# ------------------------------------------------------------------------------------------------ tools


def _rising(x: np.ndarray, x0: float) -> np.ndarray:
    """A logistic wave of ``x`` (in units of its width) counted from its value at rest ``x0`` (0 there, 1 at saturation,
    never negative)."""
    l0 = float(_logistic(np.array([x0]))[0])
    return np.clip((_logistic(x) - l0) / (1.0 - l0), 0.0, None)


def _plays(u: np.ndarray, radii: np.ndarray, state: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Play (backlash) operators of ``radii`` on ``u`` from ``state`` (their sliders' positions), shape (len(u),
    len(radii)), and the last state. Rate-independent, so on each monotone run of u the recursion y_k = clip(y_(k-1),
    u_k - r, u_k + r) is a clip of the run's starting state: a loop over runs, vectorised within each (as
    mock_devices/effects.play, written here with a state carried in)."""
    y = np.empty((u.size, radii.size))
    if u.size == 0:
        return y, state
    d = np.sign(np.diff(u))
    nz = np.flatnonzero(d)
    if nz.size:  # flats take the direction of the last move, so a plateau never splits a run
        d = d[nz[np.maximum(np.searchsorted(nz, np.arange(d.size), side="right") - 1, 0)]]
    ends = np.concatenate([np.flatnonzero(d[1:] != d[:-1]) + 1, [u.size - 1]]) if d.size else np.array([0])
    a = 0
    st = np.asarray(state, float).copy()
    for b in ends:
        seg = u[a : b + 1, None]
        y[a : b + 1] = np.clip(st, seg - radii, seg + radii)
        st = y[b].copy()
        a = b + 1
    return y, st


def _cumulative(s: Session, rate: Callable[[Rec], np.ndarray]) -> tuple[dict[int, np.ndarray], np.ndarray, np.ndarray]:
    """A quantity accumulated through the session in time order, rate(r) per sample of each record (its units per
    second; nothing over the rests): its running total per record (id -> array), and (times, totals) over the whole
    session for interpolation."""
    per, ts, vs, total = {}, [], [], 0.0
    for r in _chrono(s):
        x = total + np.cumsum(rate(r)) / r.fs
        per[id(r)] = x
        total = float(x[-1]) if x.size else total
        ts.append(r.cols["t_s"])
        vs.append(x)
    return per, np.concatenate(ts), np.concatenate(vs)


def _mode1(s: Session, r: Rec) -> tuple[float, float]:
    """The strip's first mode at the record's clamp pressure (labrig.physics.transfer.modal_set): (omega, zeta)."""
    from labrig.physics import transfer

    ms = transfer.modal_set(_spec(s, r))
    return float(ms.omega[0]), float(ms.xi[0])


def _spell_envelope(t: np.ndarray, spells: list[tuple[float, float]], edge: float = 1.0) -> np.ndarray:
    """1 inside any (start, end) spell, linear edges of ``edge`` seconds, 0 elsewhere."""
    on = np.zeros(t.size)
    for a, b in spells:
        on = np.maximum(on, np.clip(np.minimum(t - a, b - t) / edge, 0.0, 1.0))
    return on


# ------------------------------------------------------------------------------------------------ back relaxation


def br_glycol_topup(s: Session) -> None:
    """A flow-through thermostat's bath: the cuvette kept at temperature by a circulator, and at one re-clamping after
    the first (drawn; 0-60 s before the setting) the operator tops up the evaporated bath from the circulator's
    reservoir, whose water carries its propylene-glycol antifreeze: the bath's glycol fraction jumps to c_b (0.05-0.15
    by mass) and the membrane takes the glycol up through its faces (a slab's exchange, inject_fresh29._exchanged, tau_x
    300-1500 s, log: glycol diffuses in Nafion far slower than water). The back-flow (K2 0.5-0.9, tau_0 2-8 s, log) runs
    through a pore liquid whose viscosity rises as exp(b c) (b 2.5-3.2, water-propylene glycol) and whose osmotic
    contrast falls: tau = tau_0 exp(b c), K2 x (1 - a c) (a 1-3). Through inject_fresh10._lag_varying (sample by sample
    through the session, carried over the rests); displacement only. Measured (paper_172: K2 0.55, tau_0 6.6 s, topped
    up 19 s before the 3062 kPa setting to c_b 0.114, tau_x 877 s: tau up to 1.37x and K2 down to 0.71x as the glycol
    goes in) displacement RMS -42 % (residual 46 %, 2700x its noise): the 1 V steps at 4.54, 4.55, 5.07, 5.98 mm by
    their plateaus' end block by block (8.82-8.83 mm clean) and 2.42, 2.42, 2.91, 3.78 mm 2 s after their fall (6.64 mm
    clean); the 0.1 Hz harmonics' gain 0.968 (+6.6 deg) in the first two blocks, 0.976 (+4.6 deg) and 0.984 (+3.4 deg)
    in the last two."""
    k2, tau0 = s.rng.uniform(0.5, 0.9), lu(s.rng, 2.0, 8.0)
    c_b, b, a = s.rng.uniform(0.05, 0.15), s.rng.uniform(2.5, 3.2), s.rng.uniform(1.0, 3.0)
    tau_x = lu(s.rng, 300.0, 1500.0)
    _, t_set = _later_setting(s)
    t_top = t_set - s.rng.uniform(0.0, 60.0)
    tg = _session_grid(s, 1.0, 2.0)
    cg = c_b * _exchanged(tg, t_top, tau_x, s.t1 + 2.0)  # the glycol fraction of the membrane's pore liquid

    def state(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        c = np.interp(np.asarray(t, float), tg, cg)
        return k2 * (1.0 - a * c), tau0 * np.exp(b * c)

    _lag_varying(s, state)


def br_plasma_cleaned_faces(s: Session) -> None:
    """A strip whose platinum faces were cleaned in an oxygen plasma (a lab's routine before a coating or a
    contact-angle test) 5-60 min before the first record (log; mounted in the bath meanwhile), so its plating's pores
    were wholly wettable; their walls then take up hydrocarbons again from the air and the bath's traces (the
    hydrophobic recovery of a plasma-cleaned metal, the contact angle climbing as the logarithm of the time since), and
    the back-flow (K2 0.5-0.9) that the faces exchange with the bath through those pores slows: tau = tau_w (1 + g ln(1
    + u/tau_c)) (tau_w 1.5-5 s, log, on the fresh surface; g 0.15-0.4; tau_c 60-600 s, log; u the time since the
    cleaning). Through inject_fresh10._lag_varying; displacement only. Measured (p11_174: K2 0.58, tau_w 2.3 s, g 0.24,
    tau_c 594 s, cleaned 35 min before the first record: tau 3.1 s at the first record, 3.6 s at the last) displacement
    RMS -53 % (residual 56 %, 480x its noise): the 1 V steps at 0.547-0.553 mm by their plateaus' end (1.225-1.226 mm
    clean) and 0.26 mm 2 s after their fall (0.88 mm clean); the 0.1 Hz harmonics' gain 0.900 (+14.2 deg) in the first
    block and 0.919 (+12.7 deg) in the last (the slower exchange losing less at 0.1 Hz)."""
    k2, tau_w = s.rng.uniform(0.5, 0.9), lu(s.rng, 1.5, 5.0)
    g, tau_c = s.rng.uniform(0.15, 0.4), lu(s.rng, 60.0, 600.0)
    t_p = s.t0 - lu(s.rng, 300.0, 3600.0)

    def state(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        u = np.clip(np.asarray(t, float) - t_p, 0.0, None)
        return np.full(u.shape, k2), tau_w * (1.0 + g * np.log1p(u / tau_c))

    _lag_varying(s, state)


# ------------------------------------------------------------------------------------------------ faradaic current


def far_sulfite_scavenger(s: Session) -> None:
    """Sodium sulfite (cobalt-catalysed, an oxygen scavenger) added to the bath 0-300 s before the first record to take
    its oxygen out: the dissolved oxygen falls within minutes (tau_o 60-240 s, log) while the sulfite, in excess, is
    oxidised on whichever face is the anode (a wave from E_s 0.25-0.45 V of drive, width 0.04-0.08 V, to its transport
    limit i_s 0.2-0.6 mA, log, at full sulfite); in the open cuvette the air dissolving at the surface keeps oxidising
    the sulfite at a steady rate, so it runs out at 30-80 % of the session (drawn; its current falling linearly to
    nothing), and the bath then re-aerates (tau_r 600-1800 s, log), the oxygen's reduction coming back on whichever face
    is the cathode (a wave from E_o 0.2-0.4 V, width 0.04-0.08 V, to i_o 0.15-0.4 mA, log, at air saturation). Both
    waves in the drive's direction, each against the strip's own reactions on the other face; the current only. Measured
    (paper_172: i_s 0.23 mA, E_s 0.39 V; i_o 0.25 mA, E_o 0.30 V; added 189 s before the first record; the sulfite out
    at 66 % of the session, tau_r 27 min) current RMS +1.5 % (residual 3.0 %, 2.3x its noise): the 1 V steps' current at
    their plateaus' end 0.90, 0.70, 0.61, 0.67 mA block by block (0.61, 0.58, 0.57, 0.58 mA clean: the sulfite's wave
    running down, then the oxygen's back); the 0.1 Hz harmonics' current gain 1.047, 1.024, 1.008, 1.023 (-2.2 to -0.4
    deg); the 20 Hz sines' 1.009 and 1.015 in the first and the last block."""
    i_s, e_s, b_s = lu(s.rng, 2e-4, 6e-4), s.rng.uniform(0.25, 0.45), s.rng.uniform(0.04, 0.08)
    i_o, e_o, w_o = lu(s.rng, 1.5e-4, 4e-4), s.rng.uniform(0.2, 0.4), s.rng.uniform(0.04, 0.08)
    t_add = s.t0 - s.rng.uniform(0.0, 300.0)
    t_x = s.t0 + s.rng.uniform(0.3, 0.8) * (s.t1 - s.t0)
    tau_o, tau_r = lu(s.rng, 60.0, 240.0), lu(s.rng, 600.0, 1800.0)
    o_x = math.exp(-(t_x - t_add) / tau_o)

    def sulfite(t: np.ndarray) -> np.ndarray:
        return np.clip((t_x - t) / (t_x - t_add), 0.0, 1.0)

    def oxygen(t: np.ndarray) -> np.ndarray:
        early = np.exp(-np.clip(t - t_add, 0.0, None) / tau_o)
        late = 1.0 - (1.0 - o_x) * np.exp(-np.clip(t - t_x, 0.0, None) / tau_r)
        return np.where(t < t_x, early, late)

    for r in s.series():
        t, v = r.cols["t_s"], r.cols["v_V"]
        u = np.abs(v)
        ws, wo = _rising((u - e_s) / b_s, -e_s / b_s), _rising((u - e_o) / w_o, -e_o / w_o)
        r.cols["i_A"] = r.cols["i_A"] + np.sign(v) * (i_s * sulfite(t) * ws + i_o * oxygen(t) * wo)


def far_ammonia_glass_cleaner(s: Session) -> None:
    """The cuvette cleaned with an ammonia glass cleaner and rinsed too briefly (0.5-5 mM of ammonia left): platinum
    oxidises ammonia on whichever face is the anode beyond E_a (0.3-0.45 V of drive, width 0.03-0.06 V) at its
    transport-limited rate (i_a 0.2-0.6 mA, log, on a clean surface), and poisons itself with the adsorbed nitrogen it
    leaves (N_ads, the Gerischer-Mauerer route): each face's free share falls by the charge passed, a monolayer per q_p
    (40-200 uC, log), and the nitrogen is hydrogenated off again only while that face is the cathode beyond E_c (0.1-0.3
    V, first order, tau_c 0.05-0.5 s, log). A burst of current at the start of every anodic excursion that dies within
    it: the fast sines, whose cathodic halves clean the faces, carry it on every cycle, a held step only at its edge.
    Each face's coverage sample by sample through the session in time order (kept over the rests), the current from the
    charge of the nitrogen laid down; the current only. Measured (p11_174: i_a 0.33 mA, E_a 0.42 V, q_p 85 uC, E_c 0.17
    V, tau_c 0.41 s) current RMS +1.4 % (residual 2.0 %, 1.1x its noise): the 0.45 Hz sines' current gain 1.032-1.035
    (-1.2 to -1.3 deg), the 0.1 Hz ones' 1.027-1.031, the 3 Hz ones' 1.016-1.017, the 20 Hz ones' 1.010-1.011, the 1 V
    harmonics' 1.014-1.016 (+0.13 deg); the 1 V steps' plateaus untouched (0.23-0.27 mA)."""
    i_a, e_a, b = lu(s.rng, 2e-4, 6e-4), s.rng.uniform(0.3, 0.45), s.rng.uniform(0.03, 0.06)
    q_p = lu(s.rng, 4e-5, 2e-4)
    e_c, w_c, tau_c = s.rng.uniform(0.1, 0.3), s.rng.uniform(0.03, 0.06), lu(s.rng, 0.05, 0.5)
    th = [0.0, 0.0]  # each face's nitrogen coverage (face A: the anode for v > 0)
    for r in _chrono(s):
        v, dt = r.cols["v_V"], 1.0 / r.fs
        out = np.zeros(v.size)
        for f, sgn in ((0, 1.0), (1, -1.0)):
            u = sgn * v
            poison = np.exp(-i_a * _rising((u - e_a) / b, -e_a / b) * dt / q_p)  # the free share's decay a sample
            clean = np.exp(-_rising((-u - e_c) / w_c, -e_c / w_c) * dt / tau_c)
            x = th[f]
            col = np.empty(v.size)
            for k, (pk, ck) in enumerate(zip(poison.tolist(), clean.tolist())):
                new = 1.0 - (1.0 - x) * pk
                col[k] = sgn * q_p * (new - x) / dt  # each coulomb of ammonia oxidised leaves its nitrogen
                x = new * ck
            th[f] = x
            out += col
        r.cols["i_A"] = r.cols["i_A"] + out


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_plasticine_root_seal(s: Session) -> None:
    """A bead of plasticine (oil-based modelling clay, which water does not dissolve) pressed along the jaws' front edge
    over the root to keep the bath out of the contacts: its fillet resists the root's rotation, elastically at first and
    then yielding, as an elastoplastic material of Ramberg-Osgood's law (the bend x = f + alpha f^n in yield units, n
    3-6, alpha 0.5-1; yield at 0.02-0.08 of the session's largest bend) unloading by Masing's rule, realised as an Iwan
    bank of 48 spring-slider elements whose stiffnesses follow the backbone's slope; while elastic it holds back a share
    c (0.05-0.15) of the tip's bend. The reading d - c d_y F(d/d_y), the fillet's state carried through the session in
    time order (the laser's noise kept, inject_fresh26._split_noise); rate-independent, amplitude-dependent;
    displacement only. Measured (paper_172: c 0.12, n 4.3, alpha 0.58, yield at 0.040 of the largest bend, 0.36 mm)
    displacement RMS -0.8 % (residual 1.6 %, 94x its noise): the 9.4 and 20 Hz sines at 0.879 of their gain (the fillet
    elastic), the 3 Hz ones 0.896 (-0.8 deg), the 0.45 Hz ones 0.908 (-1.1 deg), the 0.1 Hz ones 0.945 (-1.4 deg), the 1
    V harmonics 0.968 (-1.15 deg); the 1 V steps at 8.71-8.72 mm by their plateaus' end (8.82-8.83 mm clean) and 10 um
    up 2 s after their fall."""
    c, n_ro, alpha = s.rng.uniform(0.05, 0.15), s.rng.uniform(3.0, 6.0), s.rng.uniform(0.5, 1.0)
    big = _largest(s) or ref_disp(s)
    d_y = s.rng.uniform(0.02, 0.08) * big
    x_max = 2.5 * big / d_y
    f_top = 1.0
    while f_top + alpha * f_top**n_ro < x_max:
        f_top *= 1.5
    fg = np.linspace(0.0, f_top, 20001)
    xg = fg + alpha * fg**n_ro  # Ramberg-Osgood: the bend (in yield bends) at a fillet force (in yield forces)
    radii = np.geomspace(0.01, x_max, 48)

    def slope(x: np.ndarray) -> np.ndarray:
        f = np.interp(x, xg, fg)
        return 1.0 / (1.0 + alpha * n_ro * f ** (n_ro - 1.0))

    sl = slope(radii)
    k = -np.diff(np.r_[1.0, sl])  # each Jenkins element's stiffness: the backbone's slope lost at its radius
    k_inf = float(sl[-1])
    state = np.zeros(radii.size)
    for r in _chrono(s):
        sig, noise = _split_noise(r)
        x = sig / d_y
        p, state = _plays(x, radii, state)
        force = (x[:, None] - p) @ k + k_inf * x  # Iwan: Masing's rule from every reversal
        r.cols["disp_m"] = sig - c * d_y * force + noise


def hy_coverslip_double_peak(s: Session) -> None:
    """A cover-slip chip (0.13-0.17 mm of glass, n 1.52) glued on the tip's face as the laser's target (a dark plating's
    usual fix): the triangulation head sees two peaks, the glass's front face and its back face on the plating, the
    front one t/n nearer the head, and its controller measures on the larger (its 'peak selection' keeping the peak it
    is on until the other is larger by a margin). The plating's diffuse back-face peak is the larger but for a window of
    tip tilts where the front face's specular lobe sweeps over the receiver: the front peak takes over when the bend
    comes within h_on of d_c (d_c 0.35-0.6 of the session's largest bend on one side, drawn; h_on 0.08-0.15 of it) and
    gives it back only beyond h_off (1.3-2 times h_on): a relay in the reading, jumping by t/n (sign drawn), with its
    own hysteresis, its state carried through the session in time order on the laser's signal
    (inject_fresh26._split_noise). Rate-independent memory; displacement only. Measured (s001_173: t 0.157 mm, the jump
    +0.103 mm, the window on the positive side over 1.39-2.29 mm, left below 1.17 and above 2.51 mm) displacement RMS
    +1.0 % (residual 2.3 %, 70x its noise): the 1 V harmonics' gain 1.060-1.061 (-0.35 deg), the steps' edges; 8 of the
    68 series touched (the 0.5 V sines never reach the window)."""
    big = _largest(s) or ref_disp(s)
    t_g = s.rng.uniform(1.3e-4, 1.7e-4)
    jump = _sign(s) * t_g / 1.52  # the front face's peak lies t/n nearer the head than the back face's
    side = _sign(s)  # the bend that tilts the front face into the receiver's specular lobe
    d_c, h_on = s.rng.uniform(0.35, 0.6) * big, s.rng.uniform(0.08, 0.15) * big
    h_off = h_on * s.rng.uniform(1.3, 2.0)
    on = False
    for r in _chrono(s):
        sig, _ = _split_noise(r)
        dev = np.abs(side * sig - d_c).tolist()
        st = np.empty(len(dev))
        for k, dk in enumerate(dev):
            on = dk < h_off if on else dk < h_on
            st[k] = 1.0 if on else 0.0
        r.cols["disp_m"] = r.cols["disp_m"] + jump * st


# ------------------------------------------------------------------------------------------------ time delay


def td_shared_controller_head(s: Session) -> None:
    """The laser controller's second head port taken by a colleague's head for their own rig at one re-clamping after
    the first (drawn; 0-120 s before the setting): the controller then samples its two heads in turn (its mutual
    interference prevention), so this head's analogue output, updated after each of its measurements (every T, 1-4 ms,
    log, on the controller's free-running clock; the value shown lat T later, lat 1.5-2.5), is updated every 2 T from
    then on: a sample-and-hold whose period doubles at the event and whose delay (lat T + half the period on average)
    grows with it. Each record's displacement read late by it, sample by sample (inject_fresh33._late_by). Measured
    (p11_174: T 3.35 ms, lat 1.86, the second head from the 1837 kPa setting) displacement residual 0.73 % of its RMS
    (6.2x its noise): the 20 Hz sines -56.9 deg (7.9 ms) and gain 0.991 in the first block, -68.9 deg (9.6 ms) and 0.970
    in the last; the 9.4 Hz ones -26.7 and -32.4 deg, the 3 Hz ones -8.6 and -10.4 deg."""
    T, lat = lu(s.rng, 1e-3, 4e-3), s.rng.uniform(1.5, 2.5)
    _, t_set = _later_setting(s)
    t_ev = t_set - s.rng.uniform(0.0, 120.0)
    ph = s.rng.uniform(0.0, 1.0) * T
    for r in s.series():
        t = r.cols["t_s"]
        m = t - lat * T  # the measurement the output shows: the last one processed by then
        before = ph + T * np.floor((m - ph) / T)
        after = t_ev + 2.0 * T * np.floor((m - t_ev) / (2.0 * T))
        r.cols["disp_m"] = _late_by(r, t - np.where(m < t_ev, before, after))


def td_scan_list_grown(s: Session) -> None:
    """The laser read on a multiplexed DAQ module that spreads its conversions evenly over each sample period (the
    round-robin scan of a USB multifunction DAQ), the drive monitor and the current on a simultaneous module: the laser
    k0-th of n0 channels in the scan (k0 1-2 after the first, n0 k0 + 1-2: a thermocouple and the bath's level probe
    beside it), read k0/(n0 fs) after the monitor. At one re-clamping after the first (drawn; 0-60 s before the setting)
    the lab's script inserts 1-3 more channels ahead of it (a humidity probe, a second thermocouple): k/n grows, so the
    skew grows, a fraction of the record's own sample period (a rate-dependent delay: 5 ms at 200 Hz at most, 1 ms at
    1000 Hz), plus the converter's 5-20 us. The displacement read late by it (inject_fresh33._late_by). Measured
    (s001_173: the laser 2nd of 3, then 5th of 6 from the 1700 kPa setting) displacement residual 0.044 % of its RMS
    (1.3x its noise): the 200 Hz records late by 1.7 ms, then 3.4 ms (the 3 Hz sines -1.8 then -3.6 deg), the 1000 Hz
    ones by 0.35 and 0.68 ms (the 20 Hz sines -2.5 then -4.9 deg)."""
    k0 = int(s.rng.integers(1, 3))
    n0 = k0 + int(s.rng.integers(1, 3))
    add = int(s.rng.integers(1, 4))
    t_conv = s.rng.uniform(5e-6, 2e-5)
    _, t_set = _later_setting(s)
    t_ev = t_set - s.rng.uniform(0.0, 60.0)
    for r in s.series():
        k, n = (k0, n0) if float(r.cols["t_s"][0]) < t_ev else (k0 + add, n0 + add)
        r.cols["disp_m"] = _late_by(r, np.full(r.cols["t_s"].size, k / (n * r.fs) + t_conv))


# ------------------------------------------------------------------------------------------------ sensor offset


def so_tip_darkening(s: Session) -> None:
    """The laser's spot (a Gaussian footprint along the strip, its 1/e^2 radius w 0.4-0.8 mm) centred m (0.2-0.5 mm)
    inside the tip's end, part of it beyond the end and lost: the head reads the intensity-weighted centroid of the part
    on the strip. The large drives' electrolysis blackens the plating where the current crowds, at the cut end (platinum
    dissolved and redeposited as black, graded as exp(-(L - x)/lam), lam 0.2-0.6 mm), its reflectance falling by up to
    0.6-0.9 as the charge passed beyond v_g (0.6-0.85 V of drive, width 0.03-0.06 V) accumulates (0.5-0.9 of it by the
    session's end), so the centroid walks inboard with that charge. The strip read at the centroid through the beam's
    own transfer functions (inject_fresh10._station, the charge in time order); displacement only. Measured (paper_172:
    m 0.32 mm, w 0.78 mm, lam 0.33 mm, the blackening 0.81 at saturation and 0.67 of it by the end, v_g 0.74 V: the
    centroid 0.46 mm inboard at first, 0.50 mm at the end) displacement RMS -3.1 % (residual 3.1 %, 180x its noise): the
    1 V steps at 8.555, 8.556, 8.552, 8.545 mm by their plateaus' end block by block (8.82-8.83 mm clean); the 0.1 Hz
    harmonics' gain 0.971, 0.970, 0.969, 0.969; the 9.4 Hz sines' 0.977 (-3.4 deg) to 0.976 (-3.6 deg), the 20 Hz ones'
    0.928 to 0.924."""
    length = float(s.specimen["length_m"])
    m, w = s.rng.uniform(2e-4, 5e-4), s.rng.uniform(4e-4, 8e-4)
    lam, dark, d_end = s.rng.uniform(2e-4, 6e-4), s.rng.uniform(0.6, 0.9), s.rng.uniform(0.5, 0.9)
    v_g, w_g = s.rng.uniform(0.6, 0.85), s.rng.uniform(0.03, 0.06)
    xs = length - np.linspace(4e-3, 0.0, 1601)  # the strip's last 4 mm (the spot's Gaussian dies well inside them)
    g = np.exp(-2.0 * (xs - (length - m)) ** 2 / w**2)
    graded = np.exp(-(length - xs) / lam)  # the blackening, strongest at the cut end where the current crowds

    def centroid(dk: float) -> float:
        wt = g * (1.0 - dark * dk * graded)
        return float(np.sum(xs * wt) / np.sum(wt))

    dg = np.linspace(0.0, 1.0, 101)
    xc = np.array([centroid(x) for x in dg]) / length
    def electrolysis(r: Rec) -> np.ndarray:
        return np.abs(r.cols["i_A"]) * _rising((np.abs(r.cols["v_V"]) - v_g) / w_g, -v_g / w_g)

    per, _, q = _cumulative(s, electrolysis)
    q_tot = float(q[-1]) if q.size else 0.0
    q_d = q_tot / -math.log1p(-d_end) if q_tot > 0 else 1.0
    _station(s, lambda r: np.interp(-np.expm1(-per[id(r)] / q_d), dg, xc), float(xc[-1]))


def so_flaking_paint_marker(s: Session) -> None:
    """No laser: video tracking of a dot of correction fluid painted on the tip (a white marker on the dark plating, the
    lab's quick target for a strip in air) over its last a (0.8-2 mm), the tracker following the dot's centroid. The
    dried paint is brittle and flakes off from the tip's end inward under the bending's fatigue: its damage grows with
    the path the tip travels beyond d_th (0.3-0.6 of the session's largest bend), weighted by the excess to the power m
    (2-4), and the flaked length grows to 0.25-0.5 a by the session's end (at most 0.6 a), the centroid moving inboard
    by half of it. The strip read at the centroid through the beam's own transfer functions (inject_fresh10._station,
    the damage in time order); displacement only. Measured (s001_173: a 1.35 mm, the threshold 0.32 of the largest bend,
    m 2.9, 0.65 mm flaked by the end: the centroid 0.68 mm inboard, then 1.0 mm) displacement RMS -8.4 % (residual 8.5
    %, 260x its noise): the 1 V steps at 4.35, 4.32, 4.29, 4.27 mm by their plateaus' end block by block (4.69-4.72 mm
    clean); the 0.1 Hz harmonics' gain 0.923, 0.915, 0.909, 0.905; the 20 Hz sines' 0.947 in the first block and 0.933
    in the last."""
    length = float(s.specimen["length_m"])
    big = _largest(s) or ref_disp(s)
    a = s.rng.uniform(8e-4, 2e-3)
    l_max, l_end = 0.6 * a, s.rng.uniform(0.25, 0.5) * a
    d_th, mb = s.rng.uniform(0.3, 0.6) * big, s.rng.uniform(2.0, 4.0)

    def rate(r: Rec) -> np.ndarray:
        sig, _ = _split_noise(r)
        speed = np.abs(np.gradient(sig, r.cols["t_s"])) if sig.size > 1 else np.zeros(sig.size)
        return speed / big * np.clip(np.abs(sig) / d_th - 1.0, 0.0, None) ** mb

    per, _, dmg = _cumulative(s, rate)
    d_tot = float(dmg[-1]) if dmg.size else 0.0
    d0 = d_tot / -math.log1p(-l_end / l_max) if d_tot > 0 else 1.0

    def frac(r: Rec) -> np.ndarray:
        flaked = l_max * -np.expm1(-per[id(r)] / d0)
        return (length - (a + flaked) / 2.0) / length

    _station(s, frac, (length - (a + l_max) / 2.0) / length)


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_wet_threadlocker(s: Session) -> None:
    """A drop of medium-strength threadlocker (an anaerobic methacrylate) put on the clamp's screw by the operator 0-600
    s before the first setting, against its loosening: until it cures in the thread it lubricates the loaded flanks, and
    the joint settles as every tightened joint does (the flanks and the screw's seat embedding, the force falling as c_e
    ln(1 + u/tau_e), c_e 0.4-1 %, tau_e 5-30 s, log) at a rate the cure arrests (an autocatalytic cure, X = 1 -
    exp(-(t/tau_c)^m) from the drop, tau_c 10-40 min, log, m 1.5-3): the first setting's loss the integral of c_e (1 -
    X)/(tau_e + u). At each later setting the turned screw breaks the cured film, and the crushed adhesive's grains
    embed in the re-loaded flanks without any cure to stop them: g c_e ln(1 + u/tau_e) (g 1.2-2). From each setting
    (inject_fresh25._setting_of) through the preset's clamp law (inject_fresh4._clamp_law), the load cell showing it.
    Measured (paper_172: c_e 0.83 %, tau_e 7.1 s, g 1.72, tau_c 36 min, the drop 344 s before the first setting) the
    load cell at 0.990, 0.983, 0.981, 0.977 of its setting at each block's first record and 0.960, 0.930, 0.928, 0.927
    by the blocks' last; displacement residual 0.090 % of its RMS (5.4x its noise: the 4287 kPa block's sines, the clamp
    law moving f1, the 3 Hz ones 0.92 (+13.8 deg) and the 9.4 Hz ones 1.27 (-12.8 deg)), current 0.47 % (0.36x)."""
    c_e, tau_e, g = s.rng.uniform(0.004, 0.01), lu(s.rng, 5.0, 30.0), s.rng.uniform(1.2, 2.0)
    tau_c, mc = lu(s.rng, 600.0, 2400.0), s.rng.uniform(1.5, 3.0)
    setting = _setting_of(s)
    p_first, a_first = min(_by_pressure_start(s).items(), key=lambda kv: kv[1])
    t_first = setting(p_first, a_first)
    t_a = t_first - s.rng.uniform(0.0, 600.0)
    ug = np.arange(0.0, s.t1 - t_first + 10.0, 0.5)
    cure = -np.expm1(-((np.clip(t_first + ug - t_a, 0.0, None) / tau_c) ** mc))
    rate = (1.0 - cure) / (tau_e + ug)
    arrested = c_e * np.r_[0.0, np.cumsum(0.5 * (rate[1:] + rate[:-1]) * np.diff(ug))]

    def rel(t: np.ndarray, p: float, t_fp: float) -> np.ndarray:
        t_set = setting(p, t_fp)
        u = np.clip(np.asarray(t, float) - t_set, 0.0, None)
        if abs(t_set - t_first) < 1e-9:
            return 1.0 - np.interp(u, ug, arrested)
        return 1.0 - g * c_e * np.log1p(u / tau_e)

    _clamp_law(s, rel)


def cr_parafilm_wrapped_jaws(s: Session) -> None:
    """The jaws wrapped in Parafilm (two turns of the paraffin-polyolefin film, to insulate the metal jaws from the
    faces and seal them): under the held jaw gap the film is squeezed out from under the jaws as a shear-thinning liquid
    (power-law index n 0.4-0.6), its thinning rate growing with the pressure as (p rho)^(1/n) and with the film's
    thickness as eta^((2n+1)/n) (the squeeze flow of a power-law fluid), the frame unloading as it thins, until the
    jaw's roughness meets the strip (the squeezable share 0.5-0.8 of the film; a smooth floor 0.03-0.08 wide): the force
    lost at the floor r_min (4-10 %) at the lightest setting and r_min p_min/p at the others, reached at the lightest in
    about t_half (300-1500 s, log) and within seconds at the heaviest. Solved per setting (sub-stepped), from each
    setting (inject_fresh25._setting_of) through the preset's clamp law (inject_fresh4._clamp_law), the load cell
    showing it. Measured (p11_174: n 0.41, r_min 8.0 %, t_half 9.1 min, the squeezable share 0.62) the load cell at
    1.000, 0.997, 0.991, 0.992 of its setting at each block's first record and 0.970, 0.973, 0.984, 0.989 by the blocks'
    last (the light settings losing most, slowly; the heavy ones at their floor before their first record); displacement
    residual 0.012 % of its RMS and current 0.17 % (0.10x their noise: the 11 mm strip's clamp law moves its bend
    little)."""
    n, r_min, t_half = s.rng.uniform(0.4, 0.6), s.rng.uniform(0.04, 0.1), lu(s.rng, 300.0, 1500.0)
    thin, soft = s.rng.uniform(0.5, 0.8), s.rng.uniform(0.03, 0.08)  # the film's squeezable share, its floor's width
    setting = _setting_of(s)
    p_min = min(s.pressures())
    rate0 = thin / (2.0 * t_half)  # the film's thinning rate at the lightest setting, at full thickness
    cache: dict[float, tuple[np.ndarray, np.ndarray]] = {}

    def course(p: float) -> tuple[np.ndarray, np.ndarray]:
        """The force's share kept against the time since the setting at p (a 1 s grid, explicit steps)."""
        if p not in cache:
            kappa = r_min * p_min / p / thin  # the frame's unloading per share of film thickness, over the force
            ug = np.arange(0.0, s.t1 - s.t0 + 4000.0, 1.0)
            eta, out = 1.0, np.empty(ug.size)
            for k in range(ug.size):
                out[k] = 1.0 - kappa * (1.0 - eta)
                left = 1.0
                while left > 0.0:  # sub-steps of at most a quarter of the floor's width in eta
                    rho = 1.0 - kappa * (1.0 - eta)
                    floor = -math.expm1(-max(eta - (1.0 - thin), 0.0) / soft)
                    speed = rate0 * (p * rho / p_min) ** (1.0 / n) * eta ** ((2.0 * n + 1.0) / n) * floor
                    h = min(left, 0.25 * soft / speed) if speed > 0 else left
                    eta -= speed * h
                    left -= h
            cache[p] = (ug, out)
        return cache[p]

    def rel(t: np.ndarray, p: float, t_fp: float) -> np.ndarray:
        ug, out = course(p)
        return np.interp(np.asarray(t, float) - setting(p, t_fp), ug, out, left=1.0)

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_pcr_thermal_cycler(s: Session) -> None:
    """A strip in air beside a colleague's PCR thermal cycler on the next bench, its Peltier block's heat sink fan
    blowing its exhaust across the bench: the run starts 10-50 % into the session (drawn) and lasts 30-40 cycles of
    1.5-3 min (log), and at each cycle's denaturation (its first 0.2-0.35: the block at 95 C, the sink at its hottest)
    the exhaust warms the strip's air by dT (1-3 K; a third of it all through the run), through the air's mixing lag
    (20-60 s, log). The same water in warmer air: the relative humidity down 6.4 % per K from the room's rh0 (0.4-0.6),
    a dip at every cycle; the strip's water follows through sorption (k 0.8-1.5 of the mobile water per unit of RH, a
    lag of 120-600 s, log, on a 1 s grid). Gain x (1 - loss), conductance x (1 - share loss) (share 0.3-1); the spectra
    at the next series' start (inject_fresh9._dry_by). Measured (s001_173: 34 cycles of 2.6 min from 14 % into the
    session, denaturation 0.22 of each, dT 1.8 K, rh0 0.56, k 1.07, the sorption's lag 8.5 min, share 0.48) displacement
    RMS -2.2 % (residual 2.5 %, 78x its noise), current RMS -1.1 % (residual 1.3 %, 3.5x its noise): the 1 V steps at
    4.69, 4.60, 4.56, 4.56 mm by their plateaus' end block by block (4.69-4.72 mm clean); the impedance 1.010, 1.016,
    1.016x in the last three blocks' spectra; 56 of the 68 series touched."""
    n_cyc, t_c = int(s.rng.integers(30, 41)), lu(s.rng, 90.0, 180.0)
    t_run = s.t0 + s.rng.uniform(0.1, 0.5) * (s.t1 - s.t0)
    den, d_t, tau_a = s.rng.uniform(0.2, 0.35), s.rng.uniform(1.0, 3.0), lu(s.rng, 20.0, 60.0)
    rh0, k_iso = s.rng.uniform(0.4, 0.6), s.rng.uniform(0.8, 1.5)
    tau_s, share = lu(s.rng, 120.0, 600.0), s.rng.uniform(0.3, 1.0)
    tg = _session_grid(s, 1.0, 2.0)
    running = (tg >= t_run) & (tg < t_run + n_cyc * t_c)
    hot = ((tg - t_run) % t_c) / t_c < den
    temp = d_t * _grid_lag(np.where(running, 0.35 + 0.65 * hot, 0.0), 1.0, tau_a)  # the exhaust's warming at the strip
    dry = rh0 * -np.expm1(-0.064 * temp)  # the same water in warmer air: its relative humidity down 6.4 % per K
    loss = k_iso * _grid_lag(dry, 1.0, tau_s)

    def f(t: np.ndarray) -> np.ndarray:
        return np.interp(np.asarray(t, float), tg, loss)

    _dry_by(s, f, lambda t: share * f(t))


def dh_pt_cycling_dissolution(s: Session) -> None:
    """Platinum dissolved by the strip's own oxide-reduction cycles: whichever face the drive takes beyond E_ox
    (0.6-0.85 V, width 0.03-0.06 V) grows its oxide (a lag of 0.05-0.5 s, log), and when the face comes back below E_r
    (0.1-0.4 V) the oxide is reduced (0.02-0.2 s, log) and a little platinum dissolves with it (the transient
    dissolution of platinum on oxide reduction), to be redeposited in the membrane: the electrode's active area, its
    double layer and its coupling lost in proportion to the oxide reduced so far, to L 4-12 % of the gain by the
    session's last cycle (the conductance 0.3-1 of that). Each face's oxide sample by sample through the session in time
    order; nothing but the 1 V records reach E_ox. Gain x (1 - loss), conductance x (1 - share loss); the spectra at the
    next series' start (inject_fresh9._dry_by). Measured (p11_174: E_ox 0.62 V, E_r 0.24 V, tau_ox 0.38 s, tau_red 0.050
    s, L 4.6 %, share 0.84) displacement RMS -1.8 % (residual 2.2 %, 19x its noise), current RMS -2.2 % (residual 2.5 %,
    1.5x its noise): the 1 V steps at 1.225, 1.212, 1.198, 1.184 mm by their plateaus' end block by block (1.225-1.226
    mm clean); the sines' gain 0.989 in the first block and 0.954-0.955 in the last (their current 0.991 and 0.962); the
    impedance 1.000, 1.010, 1.020, 1.030x in the blocks' spectra."""
    e_ox, w = s.rng.uniform(0.6, 0.85), s.rng.uniform(0.03, 0.06)
    e_r, tau_ox, tau_red = s.rng.uniform(0.1, 0.4), lu(s.rng, 0.05, 0.5), lu(s.rng, 0.02, 0.2)
    l_end, share = s.rng.uniform(0.04, 0.12), s.rng.uniform(0.3, 1.0)
    ox = [0.0, 0.0]
    done, ts, vs = 0.0, [], []
    for r in _chrono(s):
        v, dt = r.cols["v_V"], 1.0 / r.fs
        lost = np.zeros(v.size)
        for f, sgn in ((0, 1.0), (1, -1.0)):
            grow = _logistic((sgn * v - e_ox) / w).tolist()
            red = (-np.expm1(-_logistic((e_r - sgn * v) / w) * dt / tau_red)).tolist()
            a_ox, x = -math.expm1(-dt / tau_ox), ox[f]
            col = np.empty(v.size)
            for k, (gk, rk) in enumerate(zip(grow, red)):
                if gk > x:
                    x += (gk - x) * a_ox
                col[k] = x * rk  # the oxide reduced in this sample: a little platinum dissolves with it
                x -= x * rk
            ox[f] = x
            lost += col
        cum = done + np.cumsum(lost)
        done = float(cum[-1]) if cum.size else done
        ts.append(r.cols["t_s"])
        vs.append(cum)
    t_all, d_all = np.concatenate(ts), np.concatenate(vs)
    scale = l_end / done if done > 0 else 0.0

    def f(t: np.ndarray) -> np.ndarray:
        return scale * np.interp(np.asarray(t, float), t_all, d_all)

    _dry_by(s, f, lambda t: share * f(t))


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_laser_cut_edges(s: Session) -> None:
    """A strip cut from its plated sheet with a CO2 laser (a lab's way to cut many at once): along both cut edges the
    plating lies in the heat-affected zone, brittle and partly lifted, deeper on the face the beam entered (a 0.1-0.2 of
    the width, drawn for face A, the exit face B 0.3-0.7 of that). The first large bends crack it into channels from
    each edge inward, the cracked share following the largest tension the face has had so far by a Weibull law (1 -
    exp(-((e_max - e_on)/e_w)^m), e_on 0.3-0.6 and e_w 0.15-0.3 of the session's largest bend, m 4-8), and the cracked
    bands open with the face's tension beyond e_c (0.02-0.08 of it), taking their width out of the face's conductance:
    dR/R = 1/(1 - 2 a W o) - 1 per face, their mean. Gains fall by 0.03-0.08 (displacement) and 0.06-0.15 (current) per
    unit of dR/R (inject_fresh3._resist). Measured (paper_172: a 0.108 on face A and 0.034 on B, e_on 0.49 and e_w 0.26
    of the largest bend, m 6.0, e_c 0.067) displacement RMS -0.36 % (residual 0.39 %, 23x its noise), current RMS -0.07
    % (residual 0.27 %, 0.20x its noise): the 1 V steps at 8.765, 8.774, 8.777, 8.775 mm by their plateaus' end
    (8.82-8.83 mm clean), their current 0.010 mA lower; the 1 V harmonics' gain 0.998 in both; 27 of the 68 series
    touched (the 0.5 V sines at the low frequencies open the bands a little)."""
    ref = ref_disp(s)
    big = (_largest(s) or ref) / ref
    a_a = s.rng.uniform(0.1, 0.2)
    a_b = s.rng.uniform(0.3, 0.7) * a_a
    e_on, e_w, m = s.rng.uniform(0.3, 0.6) * big, s.rng.uniform(0.15, 0.3) * big, s.rng.uniform(4.0, 8.0)
    e_c = s.rng.uniform(0.02, 0.08) * big
    top = [0.0, 0.0]
    depth = {}
    for r in _chrono(s):
        sig, _ = _split_noise(r)
        e = sig / ref
        da, db = np.maximum.accumulate(np.r_[top[0], e])[1:], np.maximum.accumulate(np.r_[top[1], -e])[1:]
        top = [float(da[-1]), float(db[-1])]
        weib = lambda x: -np.expm1(-((np.clip(x - e_on, 0.0, None) / e_w) ** m))  # noqa: E731
        depth[id(r)] = (a_a * weib(da), a_b * weib(db))

    def law(r: Rec, e: np.ndarray) -> np.ndarray:
        qa, qb = depth[id(r)]
        oa = np.clip((e - e_c) / (big - e_c), 0.0, 1.0)
        ob = np.clip((-e - e_c) / (big - e_c), 0.0, 1.0)
        return 0.5 * (1.0 / (1.0 - 2.0 * qa * oa) + 1.0 / (1.0 - 2.0 * qb * ob)) - 1.0

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


def sr_paris_debonding(s: Session) -> None:
    """A strip whose plating is mud-cracked on both faces (cracks opening beyond e0, 0.1-0.3 of the session's largest
    bend: dR/R = k ((e - e0)+ + o (-e - e0)+), k 0.2-0.5, o 0.5-1) and whose plating debonds from the membrane at the
    cracks' edges under cycling (interfacial fatigue, Paris' law: the debond grows per cycle as the energy release rate
    to the power m, m 1.5-3, the rate as the strain to 2m): a debonded plating spans its crack without straining it, so
    the cracks' opening, and the gauge with it, falls as the debond grows, k/(1 + a), a growing with the path the tip
    travels weighted by (abs(e)/e_max)^(2m-1) to 0.5-2 by the session's end. The large bends open the cracks and wear
    the bond; the small ones do neither. Gains fall by 0.03-0.08 (displacement) and 0.06-0.15 (current) per unit of dR/R
    (inject_fresh3._resist). Measured (s001_173: k 0.33, o 0.82, e0 0.20 of the largest bend, m 2.2, the debond to 0.87)
    displacement RMS -4.1 % (residual 4.5 %, 140x its noise), current RMS -0.35 % (residual 1.4 %, 3.8x its noise): the
    1 V steps at 4.32, 4.39, 4.44, 4.48 mm by their plateaus' end block by block (4.69-4.72 mm clean: the gauge
    weakening), their current 0.587, 0.539, 0.523, 0.515 mA (0.649, 0.585, 0.561, 0.548 clean); the 1 V harmonics' gain
    0.979, 0.982, 0.986, 0.986; 8 of the 68 series touched (the 1 V records)."""
    ref = ref_disp(s)
    big = (_largest(s) or ref) / ref
    k0, o, e0 = s.rng.uniform(0.2, 0.5), s.rng.uniform(0.5, 1.0), s.rng.uniform(0.1, 0.3) * big
    q, a_end = 2.0 * s.rng.uniform(1.5, 3.0) - 1.0, s.rng.uniform(0.5, 2.0)

    def rate(r: Rec) -> np.ndarray:
        sig, _ = _split_noise(r)
        e = sig / ref
        speed = np.abs(np.gradient(e, r.cols["t_s"])) if e.size > 1 else np.zeros(e.size)
        return speed * (np.abs(e) / big) ** q

    per, _, dmg = _cumulative(s, rate)
    d_tot = float(dmg[-1]) if dmg.size else 0.0

    def law(r: Rec, e: np.ndarray) -> np.ndarray:
        debond = a_end * per[id(r)] / d_tot if d_tot > 0 else 0.0
        return k0 / (1.0 + debond) * (np.clip(e - e0, 0.0, None) + o * np.clip(-e - e0, 0.0, None))

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_cathode_crowding(s: Session) -> None:
    """Cations crowding against the cathode: the counter-ions driven to the cathode side pile up in the clusters next to
    the platinum up to their packing limit (the steric limit of a concentrated double layer, Bikerman's), so the
    swelling, the actuation moment, per unit of charge falls at large charge: the moment a saturating function of the
    quasi-static bend, cap tanh(q/cap) (cap 1.5-3 times the session's largest bend), before the strip's dynamics (a
    Hammerstein stage, not a reading's map): q the drive through the preset's displacement transfer function with its
    first mode taken out (the quasi-static bend), and the difference cap tanh(q/cap) - q put back through that mode
    (labrig.physics.transfer.modal_set; inject_fresh3._through_x, the zero-frequency bin at the grid's first line). Gain
    falls at large amplitude, odd harmonics in the bend; displacement only. Measured (paper_172: cap 2.26 times the
    largest bend, 19.9 mm) displacement RMS -1.9 % (residual 2.3 %, 130x its noise): the 1 V steps at 8.47-8.48 mm by
    their plateaus' end (8.82-8.83 mm clean) and 6.51 mm 2 s after their fall (6.64 mm clean); the 1 V harmonics' gain
    0.997; the 0.5 V sines within 0.01 %."""
    from labrig.physics import transfer

    big = _largest(s) or ref_disp(s)
    cap = s.rng.uniform(1.5, 3.0) * big

    def quasi_static(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        sp, (w1, z1) = _spec(s, r), _mode1(s, r)
        return lambda z: transfer.displacement_tf(z, sp) * (1.0 + 2.0 * z1 * z / w1 + (z / w1) ** 2)

    def mode(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        w1, z1 = _mode1(s, r)
        return lambda z: 1.0 / (1.0 + 2.0 * z1 * z / w1 + (z / w1) ** 2)

    qs = _through_x(s, {id(r): r.cols["v_V"] for r in s.series()}, quasi_static, 2.0, dc_at_first_line=True)
    extra = _through_x(s, {id(r): cap * np.tanh(qs[id(r)] / cap) - qs[id(r)] for r in s.series()}, mode, 2.0)
    for r in s.series():
        r.cols["disp_m"] = r.cols["disp_m"] + extra[id(r)]


def ld_current_loop_compliance(s: Session) -> None:
    """The laser's analogue output taken from its 4-20 mA current loop (its head's range +-R, 1.2-2 times the session's
    largest bend, over 4-20 mA, the rest at 12 mA, the large bends' side towards 20 mA), read across a 250 Ohm resistor
    at the DAQ, the loop run from a 24 V supply through a long cable and a loop-powered panel display whose drops leave
    the transmitter short of compliance near the top: its output current leaves regulation softly at i_max (0.85-0.97 of
    the largest reading's current above 12 mA; a knee of w 0.1-0.3 mA), I - w ln(1 + exp((I - i_max)/w)), nothing at
    rest. One-sided, compressing the largest bends only; tabulated and interpolated (slope 1 at rest), displacement
    only. Measured (s001_173: the range +-7.6 mm, the knee at 0.93 of the top reading's current, w 0.28 mA) displacement
    RMS -1.6 % (residual 2.9 %, 89x its noise): the 1 V steps at 4.31-4.32 mm by their plateaus' end (4.69-4.72 mm
    clean) and 10-14 um short 2 s after their fall; the harmonics and the sines within 0.01 %."""
    big = _largest(s) or ref_disp(s)
    span = s.rng.uniform(1.2, 2.0) * big
    side = 1.0 if max(float(np.max(r.cols["disp_m"])) for r in s.series()) >= big else -1.0  # the large bends' side
    i_top = 8e-3 * big / span  # the largest reading's current above the loop's 12 mA zero
    i_max, w = s.rng.uniform(0.85, 0.97) * i_top, s.rng.uniform(1e-4, 3e-4)
    dg = np.linspace(-2.0 * big, 2.0 * big, 8001)
    cur = side * 8e-3 * dg / span
    out = cur - w * np.logaddexp(0.0, (cur - i_max) / w) + w * math.log1p(math.exp(-i_max / w))
    _static_map(s, side * out * span / 8e-3, dg)  # increasing in dg on either side


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_vacuum_cleaner_brushes(s: Session) -> None:
    """The cleaner's vacuum cleaner run in the lab and the corridor behind the bench in 2-3 spells of 10-25 min (log,
    each starting inside a recorded series): its universal motor's current, at the line (50 or 60 Hz,
    inject_fresh12._line_f) with its iron's and its commutation's 3rd (0.1-0.3) and 5th (0.05-0.15), couples into the
    laser's cable (2.5-7 um, log) and the current amplifier's input (10-40 uA, log), and the brushes' sparks at every
    commutation add broadband bursts whose strength follows the line current's magnitude (abs(sin)^p, p 2-4, their rms
    0.3-1 of the fundamental's amplitude): noise modulated at twice the line, drawn from the case's seed. Displacement
    and current while it runs (1 s edges). Measured (s001_173: 50.01 Hz, spells of 13 and 19 min, 2.8 um and 25 uA at
    the fundamental) displacement residual 0.053 % of its RMS (1.6x its noise), current residual 0.30 % (0.80x its
    noise): 15 of the 68 series touched, in them 2.8 um and 25 uA RMS (4.8x and 2.4x their noise)."""
    f0 = _line_f(s)
    spells = _bursts(s, int(s.rng.integers(2, 4)), (600.0, 1500.0))
    h3, h5 = s.rng.uniform(0.1, 0.3), s.rng.uniform(0.05, 0.15)
    amp = {"disp_m": lu(s.rng, 2.5e-6, 7e-6), "i_A": lu(s.rng, 1e-5, 4e-5)}
    spark, p_env = s.rng.uniform(0.3, 1.0), s.rng.uniform(2.0, 4.0)
    phase = {col: s.rng.uniform(0.0, 2.0 * np.pi, 3) for col in amp}
    ph_i = s.rng.uniform(0.0, 2.0 * np.pi)
    norm = math.sqrt(math.gamma(p_env + 0.5) / (math.sqrt(math.pi) * math.gamma(p_env + 1.0)))  # rms of |sin|^p
    for r in s.series():
        t = r.cols["t_s"]
        on = _spell_envelope(t, spells)
        if not np.any(on):
            continue
        wt = 2.0 * np.pi * f0 * t
        env = np.abs(np.sin(wt + ph_i)) ** p_env / norm
        for col, a_ in amp.items():
            ph = phase[col]
            line = np.cos(wt + ph[0]) + h3 * np.cos(3.0 * wt + ph[1]) + h5 * np.cos(5.0 * wt + ph[2])
            r.cols[col] = r.cols[col] + a_ * on * (line + spark * env * s.rng.standard_normal(t.size))


def mp_ev_charger_12pulse(s: Session) -> None:
    """An electric-vehicle fast charger in the car park beyond the lab's wall, on the building's supply: its 12-pulse
    rectifier's commutation notches the building's voltage at its characteristic harmonics, the 11th and 13th (x_s 1-3 %
    of the line, the 13th 0.8-1 of it), the 23rd and 25th (0.4-0.7 and 0.3-0.6), with a little 5th and 7th from its
    transformer's imbalance (0.1-0.3), during 1-3 charging sessions of 20-60 min (log, each starting inside a recorded
    series) whose power holds and then tapers (its constant-voltage phase over the last 15-40 %). Picked up capacitively
    by the laser's cable and the current amplifier's input, each harmonic weighted by its order (the 11th at 1-4 um and
    10-40 uA, log), at the line (50 or 60 Hz, inject_fresh12._line_f), as the DAQ samples them (aliased where the rate
    is low); no fundamental of its own. Displacement and current. Measured (p11_174: 50.02 Hz, one session of 57 min,
    x_s 1.5 %, 2.5 um and 12 uA at the 11th) displacement residual 0.48 % of its RMS (4.1x its noise), current 0.40 %
    (0.23x): 35 of the 68 series touched, in them 3.3 um and 15 uA RMS (6.1x and 0.34x their noise)."""
    f0 = _line_f(s)
    sessions = _bursts(s, int(s.rng.integers(1, 4)), (1200.0, 3600.0))
    cc = [s.rng.uniform(0.6, 0.85) for _ in sessions]
    x_s = s.rng.uniform(0.01, 0.03)
    harm = {11: x_s, 13: x_s * s.rng.uniform(0.8, 1.0), 5: x_s * s.rng.uniform(0.1, 0.3),
            7: x_s * s.rng.uniform(0.1, 0.3), 23: x_s * s.rng.uniform(0.4, 0.7), 25: x_s * s.rng.uniform(0.3, 0.6)}
    amp = {"disp_m": lu(s.rng, 1e-6, 4e-6), "i_A": lu(s.rng, 1e-5, 4e-5)}  # the 11th's pickup
    phase = {col: {h: s.rng.uniform(0.0, 2.0 * np.pi) for h in harm} for col in amp}
    for r in s.series():
        t = r.cols["t_s"]
        power = np.zeros(t.size)
        for (a, b), c in zip(sessions, cc):
            u = (t - a) / (b - a)
            taper = np.where(u < c, 1.0, np.exp(-np.clip(u - c, 0.0, None) / (0.3 * (1.0 - c))))
            power = np.maximum(power, np.where((u >= 0.0) & (u < 1.0), taper, 0.0) * _spell_envelope(t, [(a, b)]))
        if not np.any(power):
            continue
        wt = 2.0 * np.pi * f0 * t
        for col, a_ in amp.items():
            wave = sum(h * c_h * np.cos(h * wt + phase[col][h]) for h, c_h in harm.items()) / (11.0 * x_s)
            r.cols[col] = r.cols[col] + a_ * power * wave


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_spare_strip_coupling(s: Session) -> None:
    """A spare strip (a longer offcut, 1-1.3 times this one's free length, hung from its own holder) left in the cuvette
    face to face with the tested strip, a gap of a few millimetres between them: the water in the gap couples the two (a
    mutual added mass, mu 0.2-0.45 of each one's modal mass with its own water), so the tested strip's first mode drives
    the spare's (its own at f1/lambda^2, the same damping) and feels it back: the displacement through D1/(D1 - mu^2
    s^4/D2), D_i the two modes' s^2 + 2 zeta w s + w^2 (labrig.physics.transfer.modal_set at each record's pressure; the
    spare's from the lightest), with the session's history (inject_fresh2._map_through). An absorber's notch and a
    second peak beside the strip's resonance, nothing at rest; displacement only. Measured (paper_172: lambda 1.15, mu
    0.24; p11_174: 1.10, 0.25) displacement residual 0.15 % and 0.18 % of its RMS (8.8x and 1.6x its noise): on the
    paper strip the 3 Hz sines at 0.77 of their gain (+5.1 deg) and the 9.4 and 20 Hz ones at 1.07 and 1.06; on the 11
    mm strip the 20 Hz sines at 0.79 (-21 deg)."""
    lam, mu = s.rng.uniform(1.0, 1.3), s.rng.uniform(0.2, 0.45)
    first = min(s.series(), key=lambda r: float(r.entry["pressure_kPa"]))
    w_ref, z2 = _mode1(s, first)
    w2 = w_ref / lam**2

    def ratio(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        w1, z1 = _mode1(s, r)

        def h(z: np.ndarray) -> np.ndarray:
            d1 = w1**2 + 2.0 * z1 * w1 * z + z**2
            d2 = w2**2 + 2.0 * z2 * w2 * z + z**2
            return d1 / (d1 - mu**2 * z**4 / d2)

        return h

    _map_through(s, ratio, 2.0)


def out_eis_during_clamp_ramp(s: Session) -> None:
    """The logger starts each impedance sweep at the clamp's command instead of at its settled flag, so every spectrum
    (swept in its rows' order, as the analyser ran it: from 0.1 Hz up, each point n_c 3-6 cycles plus 0.3-1 s) begins
    while the motorised clamp is still closing: the force ramps from rho0 (0.05-0.3, drawn per spectrum) of its setting
    to the setting over t_ramp (30-120 s, log, per spectrum), and the points measured meanwhile (the slowest, lowest
    frequencies) see the contact at the lower force: each such point times the preset's impedance at the force reached
    over its impedance at the setting (labrig.physics.transfer.admittance_tf). The spectra only, the time series
    untouched. Measured (s001_173 and p11_174) the lowest point of every spectrum off: abs(Z) 0.957, 0.967, 0.953, 0.965
    at 0.1 Hz (+0.3 to +2.7 deg) and 0.992 at 0.15 Hz in the first on the seed-001 strip; 0.973, 0.943, 0.958, 0.962 at
    0.1 Hz and up to 1.5 % at the next two points on the 11 mm strip (the spectra's noise 0.4-0.5 %)."""
    from labrig.physics import presets, transfer

    pre = presets.get(s.preset)
    n_c, t_o = s.rng.uniform(3.0, 6.0), s.rng.uniform(0.3, 1.0)
    for r in s.recs:
        if r.series:
            continue
        p, f = float(r.entry["pressure_kPa"]), r.cols["f_Hz"]
        rho0, t_ramp = s.rng.uniform(0.05, 0.3), lu(s.rng, 30.0, 120.0)
        dur = n_c / f + t_o
        t_k = np.cumsum(dur) - 0.5 * dur  # each point's middle, the sweep in the rows' order (as the analyser ran it)
        pk = p * (rho0 + (1.0 - rho0) * np.clip(t_k / t_ramp, 0.0, 1.0))
        z = 2j * np.pi * f
        ratio = np.ones(f.size, complex)
        y_set = transfer.admittance_tf(z, pre.specimen(p))
        for k in np.flatnonzero(pk < p):
            ratio[k] = y_set[k] / transfer.admittance_tf(z[k : k + 1], pre.specimen(float(pk[k])))[0]
        zm = (r.cols["z_re_ohm"] + 1j * r.cols["z_im_ohm"]) * ratio
        r.cols["z_re_ohm"], r.cols["z_im_ohm"] = zm.real.copy(), zm.imag.copy()


def out_shunt_cmrr_leak(s: Session) -> None:
    """The current read as the drop across a high-side shunt (R_sh 2-5 Ohm, log) by a difference amplifier built from 1
    % resistors (its common-mode rejection 54-66 dB at low frequency, falling above f_c 0.5-3 kHz, log): the shunt's
    common-mode voltage, the drive itself, leaks into the reading, i + (v + v'/(2 pi f_c))/(R_sh CMRR). A conductance
    and a little capacitance in the current alone; the spectra (the analyser reads the strip) and the displacement
    untouched. Measured (paper_172: 3.2 Ohm, 61.3 dB, 0.27 mS; s001_173: 3.6 Ohm, 58.6 dB, 0.33 mS) current RMS +2.4 %
    and +3.7 % (residual 4.4 % and 6.2 %, 3.4x and 17x its noise): the 1 V steps' plateau current +0.27 and +0.33 mA
    (0.84-0.88 mA against 0.58-0.61, 0.88-0.98 against 0.55-0.65 clean); the 0.1 Hz harmonics' current gain 1.046-1.049
    (-2.1 to -2.2 deg) and 1.056-1.060 (-2.4 to -2.7 deg); the 20 Hz sines' 1.012 and 1.020."""
    r_sh, cmrr_db, f_c = lu(s.rng, 2.0, 5.0), s.rng.uniform(54.0, 66.0), lu(s.rng, 500.0, 3000.0)
    g = 1.0 / (r_sh * 10.0 ** (cmrr_db / 20.0))
    for r in s.series():
        v, t = r.cols["v_V"], r.cols["t_s"]
        vs, _ = _split_noise(r, "v_V")
        dv = np.gradient(vs, t) if t.size > 1 else np.zeros(t.size)
        r.cols["i_A"] = r.cols["i_A"] + g * (v + dv / (2.0 * np.pi * f_c))


def out_polarity_led_glare(s: Session) -> None:
    """The drive amplifier's front-panel polarity LED (a bicolour one, green for a positive output and red for a
    negative, lit by a comparator beyond v_th 0.05-0.2 V with a soft edge of 2-5 mV) a few centimetres from the laser
    head's receiver window: its light adds a background to the receiver's line sensor that pulls the spot's peak by a
    few micrometres, each colour by its own amount (2-8 um, log; the receiver's filter passes them unequally), both the
    same way (drawn). A copy of the drive's sign in the displacement, without the strip's dynamics: a square wave at
    each sine's frequency, a step on each plateau. Displacement only. Measured (s001_173: v_th 0.19 V, -5.2 um green and
    -2.7 um red; p11_174: 0.14 V, +2.2 and +3.7 um) displacement residual 0.20 % and 0.51 % of its RMS (6.2x and 4.3x
    its noise): on the seed-001 strip the 9.4 Hz sines at 0.995 (-3.9 deg) and the 20 Hz ones at 1.014-1.017 (-2.3 to
    -3.1 deg), the steps 5 um short on their plateaus; on the 11 mm strip the 3 Hz sines 0.981 (-1.6 deg), the 9.4 Hz
    ones 0.980 (-3.4 deg), the 20 Hz ones 1.005 (-2.9 deg), the steps 2-3 um up."""
    v_th, w_v = s.rng.uniform(0.05, 0.2), s.rng.uniform(2e-3, 5e-3)
    sgn, a_p, a_n = _sign(s), lu(s.rng, 2e-6, 8e-6), lu(s.rng, 2e-6, 8e-6)
    for r in s.series():
        v = r.cols["v_V"]
        glare = a_p * _logistic((v - v_th) / w_v) + a_n * _logistic((-v - v_th) / w_v)
        r.cols["disp_m"] = r.cols["disp_m"] + sgn * glare


FRESH34_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"glycol_topup": br_glycol_topup, "plasma_cleaned_faces": br_plasma_cleaned_faces},
    "faradaic_current": {"sulfite_scavenger": far_sulfite_scavenger,
                         "ammonia_glass_cleaner": far_ammonia_glass_cleaner},
    "hysteresis": {"plasticine_root_seal": hy_plasticine_root_seal, "coverslip_double_peak": hy_coverslip_double_peak},
    "time_delay": {"shared_controller_head": td_shared_controller_head, "scan_list_grown": td_scan_list_grown},
    "sensor_offset": {"tip_darkening": so_tip_darkening, "flaking_paint_marker": so_flaking_paint_marker},
    "clamp_relaxation": {"wet_threadlocker": cr_wet_threadlocker, "parafilm_wrapped_jaws": cr_parafilm_wrapped_jaws},
    "dehydration": {"pcr_thermal_cycler": dh_pcr_thermal_cycler, "pt_cycling_dissolution": dh_pt_cycling_dissolution},
    "strain_resistance": {"laser_cut_edges": sr_laser_cut_edges, "paris_debonding": sr_paris_debonding},
    "large_deflection": {"cathode_crowding": ld_cathode_crowding,
                         "current_loop_compliance": ld_current_loop_compliance},
    "mains_pickup": {"vacuum_cleaner_brushes": mp_vacuum_cleaner_brushes, "ev_charger_12pulse": mp_ev_charger_12pulse},
    "unexplained": {"spare_strip_coupling": out_spare_strip_coupling,
                    "eis_during_clamp_ramp": out_eis_during_clamp_ramp,
                    "shunt_cmrr_leak": out_shunt_cmrr_leak, "polarity_led_glare": out_polarity_led_glare},
}
inject.register_forms(FRESH34_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def v_sparse_spectra(s: Session) -> None:
    """An impedance method set to fewer points per decade: the lab's quick sweep at each re-clamping, its analyser at k
    times sparser than the base's (k 2 or 3 for the session: three or two points a decade of its six), the points kept
    counted from the highest frequency down and the lowest one kept (the method's start and stop frequencies), each
    point's value as measured, the rows in their order. The time series, the other columns and the manifest untouched.
    The import contract asks f_Hz positive, nothing of the spectra's density; ``labrig import`` takes it and
    ``labrig export`` writes the spectra back as written."""
    k = int(s.rng.choice([2, 3]))
    for r in s.recs:
        if r.series:
            continue
        f = r.cols["f_Hz"]
        order = np.argsort(-f, kind="stable")
        keep = np.unique(np.r_[order[::k], int(np.argmin(f))])
        r.cols = {c: x[keep] for c, x in r.cols.items()}


inject.VARIANTS.update({"sparse_spectra": v_sparse_spectra})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_172", "s001_173", "p11_174"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 7 / 6 effect cases on seeds 172-174
    "back_relaxation": [("glycol_topup", 172, P, "steps_sines"), ("plasma_cleaned_faces", 174, T, "dropped_packets")],
    "faradaic_current": [("sulfite_scavenger", 172, P, "eis_two_passes"),
                         ("ammonia_glass_cleaner", 174, T, "sparse_spectra")],
    "hysteresis": [("plasticine_root_seal", 172, P, "decimated3"), ("coverslip_double_peak", 173, S, "settled_sines")],
    "time_delay": [("shared_controller_head", 174, T, "two_rate_sines"), ("scan_list_grown", 173, S, "stop_trigger")],
    "sensor_offset": [("tip_darkening", 172, P, "float32_time"), ("flaking_paint_marker", 173, S, "rate07")],
    "clamp_relaxation": [("wet_threadlocker", 172, P, "short_pretrigger"),
                         ("parafilm_wrapped_jaws", 174, T, "two_pressures")],
    "dehydration": [("pcr_thermal_cycler", 173, S, "split_spectra"),
                    ("pt_cycling_dissolution", 174, T, "eis_descending")],
    "strain_resistance": [("laser_cut_edges", 172, P, "resampled"), ("paris_debonding", 173, S, "swinging_door")],
    "large_deflection": [("cathode_crowding", 172, P, "own_clock"),
                         ("current_loop_compliance", 173, S, "trigger_clock")],
    "mains_pickup": [("vacuum_cleaner_brushes", 173, S, "minimal_manifest"),
                     ("ev_charger_12pulse", 174, T, "sparse_spectra")],
    "unexplained": [("spare_strip_coupling", 172, P, "asrun"), ("spare_strip_coupling", 174, T, "block_clock"),
                    ("eis_during_clamp_ramp", 173, S, "harmonics_as_free"),
                    ("eis_during_clamp_ramp", 174, T, "spectra_last"),
                    ("shunt_cmrr_leak", 172, P, "midnight_clock"), ("shunt_cmrr_leak", 173, S, "scan_hold"),
                    ("polarity_led_glare", 173, S, "cycle_averaged"), ("polarity_led_glare", 174, T, "log_steps")],
}
CLEAN = [(172, P, "sparse_spectra"), (172, P, "fixed_decimals"), (173, S, "sparse_spectra"),
         (173, S, "host_timed"), (174, T, "no_spectra"), (174, T, "shortened_shuffled")]


def fresh34_cases(only: str | None = None) -> list[Case]:
    """The thirty-fifth held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds
    172-174)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh34_cases, "inject_fresh34", "fresh34")
