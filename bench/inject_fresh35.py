"""A thirty-sixth held-out set for the diagnosis (issue 12), fresh35, written without sight of the diagnosis (its code,
its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh34.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (formic acid left by a kettle descaler,
poisoning the platinum and stripped again in relaxation oscillations, a video tracker's hysteresis thresholding widened
by the motion blur, a home-made isolation stage of two optocouplers in push-pull, a position-sensitive triangulation
head diluting its spot with its own stray light as the tip tilts, the frames of an IP camera's stream arriving late by
their own size, the logging script's exponential smoothing set per sample) and some on the history, the clamp pressure
or the session's events (lifted plating flakes flipping open and shut as flap valves, silicone antifoam dropped into the
bath at a re-clamping, chromate from a chromic-acid glass clean blocking each cathode with its own film, a
maximum-reading telltale reset before each record, polycarbonate shims crazing under a stress-dependent incubation, wet
glass jaws whose capillary suction dries back after each re-wetting, a glass-slide lid laid over the cuvette, an edge
notch growing a crack by Paris' law, flaws nucleating cracks at random at the large tensions, a phenolic disinfectant
polymerising on the anodes, a kettle boiled in the lab's kitchen corner, a spot welder recharging its capacitors in the
workshop) and some on time (a webcam drifting out of focus as it warms, a CRT monitor's retrace running all session);
lab wiring or sensors among them (the camera and its stream, the logger's smoothing, the edge tracker, the telltale, the
lid, the optocouplers, the PSD head, the CRT, the welder). Four structures outside the catalogue (truth "unexplained":
the export script's linear detrend of each record's displacement; a laser Doppler vibrometer's displacement decoder
losing its fringes beyond its velocity limit; a fibre illuminator switched on to film, heating one face by the light its
tilt lets in; impedance spectra exported as modulus and phase into the real and imaginary columns); clean sessions. All
on three bases of new seeds (175-177: the paper strip, the seed-001 strip on its own sweep, the paper strip 10 mm free)
and on the earlier sets' data-shape variants plus one new here: every time series' columns in the DAQ task's channel
order with the time column last (``channel_order``).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh34 are reused (importing inject_fresh34 and inject_fresh33 registers every earlier set's
lookups), and the forms, bases, preset and variant of this set are registered into inject's lookups at import, none
replaced. Strengths are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it
made on its case, measured in memory against the clean base (relative RMS change over all series, form only, no variant;
"noise": the column's sample-to-sample noise at rest, inject_fresh15.rest_noise).

Run: python bench/inject_fresh35.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np
from scipy import signal
from scipy.stats import norm

import inject
import inject_fresh33  # noqa: F401  (registers fresh33's and, through fresh31, every other earlier set's)
import inject_fresh34  # noqa: F401  (registers fresh34's and, through fresh32, fresh30's lookups)
from inject import Case, Rec, Session, lu, ref_disp
from inject_fresh2 import _chrono
from inject_fresh3 import _resist, _sign
from inject_fresh4 import _clamp_law
from inject_fresh6 import _bursts
from inject_fresh9 import _dry_by, _session_grid
from inject_fresh10 import _lag_varying, _station
from inject_fresh12 import _line_f
from inject_fresh14 import _largest
from inject_fresh25 import _setting_of
from inject_fresh26 import _later_setting, _split_noise
from inject_fresh29 import _grid_lag
from inject_fresh33 import _static_map
from inject_fresh34 import _cumulative, _rising, _spell_envelope

# the paper's strip 10 mm free (earlier sets used 11-29 and 31-45 mm, 30 mm is the paper preset itself and the seed-001
# strip is 20 mm): its 1 V step peaks at 1.02 mm, well inside the laser's +-20 mm (2 mm/V on the DAQ's +-10 V) and 1800x
# the laser's 0.57 um noise at rest; its first mode at 29.7 Hz (zeta 0.10), above the sines' top (20 Hz). Preset
# "paper_10", base "p10_177", registered in every process importing this module
inject.register_free_length("paper_10", 0.010)

inject.BASES.update({
    "paper_175": ("paper-sweep", "paper", 175),
    "s001_176": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 176),
    "p10_177": ("paper-sweep", "paper_10", 177),
})


# ------------------------------------------------------------------------------------------------ tools


def _sides(s: Session) -> tuple[float, float]:
    """The session's largest bend on each side: (towards positive, towards negative), both positive."""
    hi = max(float(np.max(r.cols["disp_m"])) for r in s.series())
    lo = max(float(-np.min(r.cols["disp_m"])) for r in s.series())
    big = _largest(s) or ref_disp(s)
    return max(hi, 1e-3 * big), max(lo, 1e-3 * big)


def _relay_bank(x: np.ndarray, up: np.ndarray, down: np.ndarray, state: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Relays on ``x``, one per (up_j, down_j): on once x > up_j, off once x < down_j (down_j < up_j), held between,
    from ``state``: their states per sample, shape (len(x), len(up)), and the last state. Vectorised per relay (the last
    switching event forward-filled)."""
    n = x.size
    out = np.empty((n, up.size))
    idx = np.arange(n)
    for j in range(up.size):
        ev = np.where(x > up[j], 1.0, np.where(x < down[j], 0.0, -1.0))
        last = np.maximum.accumulate(np.where(ev >= 0.0, idx, -1))
        out[:, j] = np.where(last >= 0, ev[np.maximum(last, 0)], state[j])
    return out, (out[-1].copy() if n else state)


def _session_curve(s: Session, per: dict[int, np.ndarray]) -> Callable[[np.ndarray], np.ndarray]:
    """A quantity known at every sample of the series (id(record) -> array) as a function of session time: linear
    between samples, across the rests from one record's last value to the next record's first."""
    recs = _chrono(s)
    T = np.concatenate([r.cols["t_s"] for r in recs])
    X = np.concatenate([per[id(r)] for r in recs])
    return lambda t: np.interp(np.asarray(t, float), T, X)


def _speed(r: Rec) -> np.ndarray:
    """The tip's speed (m/s) from the displacement's signal (its sensor noise left out, inject_fresh26._split_noise)."""
    sig, _ = _split_noise(r)
    return np.abs(np.gradient(sig, r.cols["t_s"])) if sig.size > 1 else np.zeros(sig.size)


def _per_face(s: Session, rate: Callable[[Rec, float], np.ndarray]) -> tuple[dict, dict]:
    """A quantity accumulated per face through the session (face A the anode for v > 0: sgn +1, face B sgn -1), rate(r,
    sgn) per sample of each record (per second): {sgn: {id(record): running total}} and {sgn: the session's total}."""
    per, tot = {}, {}
    for sgn in (1.0, -1.0):
        p, _, x = _cumulative(s, lambda r, sg=sgn: rate(r, sg))
        per[sgn], tot[sgn] = p, (float(x[-1]) if x.size else 0.0)
    return per, tot


# ------------------------------------------------------------------------------------------------ back relaxation


def br_flake_flap_valves(s: Session) -> None:
    """A thickly plated strip whose mud-cracked plating has platelets with lifted edges (bent hard while it was
    handled): a lifted platelet is a flap over its crack's mouth, and the back-flow (K2, tau) that the faces exchange
    with the bath runs through the cracks whose flaps are open. A flap tilts open when its face is stretched past its
    own threshold (a_j 0.2-0.9 of the session's largest bend to that side) and flips shut only when the face is
    compressed past another (b_j 0.02-0.3 of the largest bend the other way): 24 such relays a face, their open share o
    (both faces' mean) carried through the session in time order on the laser's signal (inject_fresh26._split_noise).
    The exchange quickens and grows with it: tau = tau_c/(1 + m o), K2 = K_c (1 + k o) (K_c 0.35-0.6, tau_c 4-12 s, log,
    m 1.5-4, k 0.3-0.7). Through inject_fresh10._lag_varying; displacement only. Measured (paper_175: K_c 0.60, tau_c
    6.6 s, m 3.8, k 0.53: K2 0.60-0.76 and tau 6.6-2.3 s as the flaps open and shut, never both faces' all open at once)
    displacement RMS -66 % (residual 72 %, 4300x its noise): the 1 V steps at 2.38 mm by their plateaus' end (8.79-8.80
    mm clean) and 0.75-0.76 mm 2 s after their fall (6.64 mm clean); the 0.1 Hz harmonics' gain 0.809-0.816 (+22.5 to
    +23.0 deg), the 0.45 Hz sines' 0.989 (+5.4 deg)."""
    k_c, tau_c = s.rng.uniform(0.35, 0.6), lu(s.rng, 4.0, 12.0)
    m, kk = s.rng.uniform(1.5, 4.0), s.rng.uniform(0.3, 0.7)
    n = 24
    up = s.rng.uniform(0.2, 0.9, (2, n))
    down = s.rng.uniform(0.02, 0.3, (2, n))
    hi, lo = _sides(s)
    states = [np.zeros(n), np.zeros(n)]
    share = {}
    for r in _chrono(s):
        sig, _ = _split_noise(r)
        a, states[0] = _relay_bank(sig, up[0] * hi, -down[0] * lo, states[0])  # face A stretched by positive bends
        b, states[1] = _relay_bank(-sig, up[1] * lo, -down[1] * hi, states[1])  # face B by negative ones
        share[id(r)] = 0.5 * (a.mean(axis=1) + b.mean(axis=1))
    open_share = _session_curve(s, share)

    def state(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        o = open_share(t)
        return k_c * (1.0 + kk * o), tau_c / (1.0 + m * o)

    _lag_varying(s, state)


def br_antifoam_drop(s: Session) -> None:
    """A drop of silicone antifoam (a PDMS emulsion, the kind labs keep against froth) added to the bath at one
    re-clamping after the first (drawn; 0-60 s before the setting) to stop the electrolysis's foam clinging to the
    laser's window: its droplets settle on the strip's faces as long as they stay dispersed, and they cream to the
    surface over tau_cr (300-1200 s, log), so the deposit grows as 1 - exp(-(u/tau_cr)) and stops: the pores' blocked
    share theta = theta_max (1 - exp(-g (1 - exp(-u/tau_cr)))) (theta_max 0.4-0.7, g 1-4: what the emulsion can lay down
    before it has creamed). The back-flow (K2 0.5-0.9) that the faces exchange with the bath through the pores slows in
    proportion to the open area, tau = tau_0/(1 - theta) (tau_0 2-6 s, log), its share unchanged (the same water comes
    back, later). Through inject_fresh10._lag_varying; displacement only. Measured (p10_177: K2 0.73, tau_0 2.3 s,
    theta_max 0.43, g 1.74, tau_cr 7.4 min, the drop 45 s before the 3062 kPa setting: tau up to 3.6 s) displacement RMS
    -67 % (residual 71 %, 490x its noise): the 1 V steps at 0.295, 0.295, 0.300, 0.311 mm by their plateaus' end block
    by block (1.01 mm clean) and 0.087, 0.087, 0.081, 0.074 mm 2 s after their fall (0.73 mm clean); the 0.1 Hz
    harmonics' gain 0.813-0.814 (+22.1 to +22.2 deg) in the first two blocks, 0.866 (+18.6 deg) and 0.900 (+16.0 deg) in
    the last two."""
    k2, tau0 = s.rng.uniform(0.5, 0.9), lu(s.rng, 2.0, 6.0)
    th_max, g, tau_cr = s.rng.uniform(0.4, 0.7), s.rng.uniform(1.0, 4.0), lu(s.rng, 300.0, 1200.0)
    _, t_set = _later_setting(s)
    t_e = t_set - s.rng.uniform(0.0, 60.0)

    def state(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        u = np.clip(np.asarray(t, float) - t_e, 0.0, None)
        theta = th_max * -np.expm1(-g * -np.expm1(-u / tau_cr))
        return np.full(u.shape, k2), tau0 / (1.0 - theta)

    _lag_varying(s, state)


# ------------------------------------------------------------------------------------------------ faradaic current


def far_formic_descaler(s: Session) -> None:
    """The cuvette descaled with a formic-acid kettle descaler and rinsed too briefly (a few mM left): platinum oxidises
    formic acid on whichever face is the anode, a wave from E_f (0.15-0.3 V of drive, width 0.03-0.06 V) to i_f
    (0.15-0.4 mA, log) on the free surface, but through the dual path: the same wave dehydrates it to adsorbed CO, which
    poisons the face (its CO coverage theta growing at w(u) (1 - theta)/tau_p, tau_p 0.3-1.5 s, log), and the CO is
    stripped only when the face's potential passes E_s (0.55-0.8 V) and the coverage has reached theta_c (0.6-0.85),
    then fast (tau_s 0.02-0.08 s, log) down to theta_lo (0.03-0.1), its monolayer's charge q_m (10-40 uC, log) passing
    as a spike: the potentiostatic oscillations of formic acid on platinum, a sawtooth current on every held anodic
    excursion past E_s, and a face poisoned for good by the excursions below it. Each face's coverage and stripping
    state sample by sample through the session in time order (kept over the rests); the current only. Measured
    (paper_175: i_f 0.21 mA, E_f 0.23 V, tau_p 1.17 s, E_s 0.71 V, theta_c 0.70, theta_lo 0.08, tau_s 72 ms, q_m 21 uC)
    current RMS +0.45 % (residual 2.1 %, 1.6x its noise): on the 1 V steps' plateaus a sawtooth of 1.45 s (0.68 Hz)
    between 0.06 and 0.25 mA, +0.14-0.15 mA on average (0.72-0.75 mA at the plateaus' end against 0.57-0.61 clean); the
    1 V harmonics' current gain 1.025-1.026 (-1.2 to -1.3 deg); the 0.5 V sines (below E_s, their faces poisoned for
    good by the first of them after each 1 V record) within 0.01 %."""
    i_f, e_f, b = lu(s.rng, 1.5e-4, 4e-4), s.rng.uniform(0.15, 0.3), s.rng.uniform(0.03, 0.06)
    tau_p, e_s = lu(s.rng, 0.3, 1.5), s.rng.uniform(0.55, 0.8)
    th_c, th_lo, tau_s = s.rng.uniform(0.6, 0.85), s.rng.uniform(0.03, 0.1), lu(s.rng, 0.02, 0.08)
    q_m = lu(s.rng, 1e-5, 4e-5)
    face = {1.0: [0.0, False], -1.0: [0.0, False]}  # (CO coverage, stripping)
    for r in _chrono(s):
        v, dt = r.cols["v_V"], 1.0 / r.fs
        out = np.zeros(v.size)
        for sgn in (1.0, -1.0):
            u = sgn * v
            if float(np.max(u)) <= e_f - 4.0 * b:  # no oxidation on this face in this record: nothing changes
                continue
            w = _rising((u - e_f) / b, -e_f / b)
            th, strip = face[sgn]
            a_s = -math.expm1(-dt / tau_s)
            col = np.empty(v.size)
            for k, (uk, wk) in enumerate(zip(u.tolist(), w.tolist())):
                spike = 0.0
                if strip and uk > e_s:
                    d_th = th * a_s
                    th -= d_th
                    spike = q_m * d_th / dt
                    strip = th > th_lo
                else:
                    strip = uk > e_s and th >= th_c
                    th += (1.0 - th) * -math.expm1(-wk * dt / tau_p)
                col[k] = i_f * wk * (1.0 - th) + spike
            face[sgn] = [th, strip]
            out += sgn * col
        r.cols["i_A"] = r.cols["i_A"] + out


def far_chromic_acid_residue(s: Session) -> None:
    """Glassware cleaned in chromic acid (dichromate in sulfuric acid, an old lab's bath) and the cuvette rinsed too
    briefly: micromoles of chromate left in the bath. Whichever face is the cathode reduces it at a small overpotential
    (a wave from E_c 0.05-0.2 V of drive, width 0.02-0.05 V) at its transport limit i_c (0.15-0.4 mA, log), and the
    chromium(III) hydroxide it leaves films that face where it formed (the 'chromate film' of chlorate cells), blocking
    the free share exp(-Q/q_b) of it for good, Q the charge the wave would have passed on that face so far (q_b 20-80
    mC, log); the bath's chromate hardly used up. Each face its own film, through the session in time order
    (inject_fresh34._cumulative): a cathodic wave on both faces in turn that fades with each face's own history, the
    steps' positive plateaus wearing face B, the sines' negative halves face A. The current only. Measured (p10_177: i_c
    0.28 mA, E_c 0.053 V, q_b 23 mC) current RMS +0.61 % (residual 2.8 %, 1.6x its noise): the 1 V steps' plateau
    current 0.443, 0.252, 0.215, 0.217 mA block by block (0.248, 0.217, 0.209, 0.216 clean); the 1 V harmonics' current
    gain 1.093 (-5.0 deg), 1.022, 1.005, 1.001; the 0.45 Hz sines' 1.031 to 1.0004, the 20 Hz ones' 1.007 to 1.0001
    (first and last block)."""
    i_c, e_c, b = lu(s.rng, 1.5e-4, 4e-4), s.rng.uniform(0.05, 0.2), s.rng.uniform(0.02, 0.05)
    q_b = lu(s.rng, 2e-2, 8e-2)

    def wave(r: Rec, sgn: float) -> np.ndarray:
        c = -sgn * r.cols["v_V"]  # the face's cathodic drive
        return i_c * _rising((c - e_c) / b, -e_c / b)

    per, _ = _per_face(s, wave)
    for r in s.series():
        out = np.zeros(r.cols["v_V"].size)
        for sgn in (1.0, -1.0):
            out += -sgn * wave(r, sgn) * np.exp(-per[sgn][id(r)] / q_b)
        r.cols["i_A"] = r.cols["i_A"] + out


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_max_pointer_telltale(s: Session) -> None:
    """A maximum-reading telltale on the rig (a teaching lab's visual check of each record's largest bend): a light
    pointer on a stiff pivot, on the side of the session's larger bends, that the operator sets before each record a
    clearance c0 (0.02-0.08 of the session's largest bend) from the tip at rest. The tip pushes it ahead whenever it
    goes beyond it and leaves it at its furthest reach; the pivot's friction holds the tip back by delta (0.01-0.03 of
    the largest bend: its torque over the strip's tip stiffness) while it pushes, and the tip rests against the pointer,
    held, while its pull is within delta of it. Quasi-statically the reading on that side is min(x, P), P = max(c0, the
    running maximum of x - delta) within the record (x the free strip's bend on that side): the first crest beyond c0
    read delta short, the later ones flattened at the pointer, the small bends and the other side untouched;
    rate-independent memory reset at every record. The laser's own noise kept (inject_fresh26._split_noise);
    displacement only. Measured (s001_176: on the positive side, c0 0.28 mm, delta 0.11 mm) displacement RMS -1.9 %
    (residual 2.6 %, 82x its noise): the 1 V steps at 4.56-4.59 mm by their plateaus' end (4.67-4.70 mm clean), the same
    2 s after their fall; the 1 V harmonics' gain 0.990 (-1.03 to -1.06 deg); 44 of the 68 series touched (the small
    sines never reach the pointer)."""
    big = _largest(s) or ref_disp(s)
    hi, lo = _sides(s)
    side = 1.0 if hi >= lo else -1.0
    c0, delta = s.rng.uniform(0.02, 0.08) * big, s.rng.uniform(0.01, 0.03) * big
    for r in s.series():
        sig, noise = _split_noise(r)
        x = side * sig
        p = np.maximum(c0, np.maximum.accumulate(x - delta))
        r.cols["disp_m"] = side * np.minimum(x, p) + noise


def hy_canny_edge_tracker(s: Session) -> None:
    """No laser: the tip tracked on video against a back light, the lab's OpenCV pipeline finding its edge with Canny's
    detector and taking the kept edge pixels' sub-pixel mean: Canny's hysteresis thresholding keeps a pixel over the low
    threshold only while it joins one over the high threshold, so when the tip reverses the kept edge stays where it was
    until the profile has moved by the band between the thresholds over the edge's gradient: a play of radius r0 (1-4
    um, log: 0.05-0.15 of a 20-30 um pixel). The motion blurs the edge over the exposure (t_e 1-4 ms) against its own
    width (w_e 40-120 um), flattening the gradient, so the radius grows with the speed, r = r0 (1 + U t_e/w_e) (U the
    tip's speed, inject_fresh26._split_noise's signal). Sample by sample through the session in time order (the kept
    edge carried over the rests); the sensor's noise kept; displacement only. Measured (paper_175: r0 2.0 um, t_e 2.5
    ms, w_e 60 um) displacement residual 0.058 % of its RMS (3.4x its noise): the 9.4 Hz sines (a bend of 6 um) at
    0.70-0.85 of their gain (-16 to -28 deg), the 20 Hz ones (7 um) at 0.52-0.76 (-24 to -39 deg), the 3 Hz ones at
    0.999 (-0.5 to -0.6 deg) , the 0.45 Hz ones at 0.9995 (-0.34 deg); the steps 2 um short on their plateaus and 2 um
    long after their fall."""
    r0, t_e, w_e = lu(s.rng, 1e-6, 4e-6), s.rng.uniform(1e-3, 4e-3), s.rng.uniform(4e-5, 1.2e-4)
    y = None
    for r in _chrono(s):
        sig, noise = _split_noise(r)
        rad = r0 * (1.0 + _speed(r) * t_e / w_e)
        lo, hi = (sig - rad).tolist(), (sig + rad).tolist()
        out = np.empty(sig.size)
        if y is None:
            y = float(sig[0])
        for k in range(sig.size):
            y = min(max(y, lo[k]), hi[k])
            out[k] = y
        r.cols["disp_m"] = out + noise


# ------------------------------------------------------------------------------------------------ time delay


def td_ip_camera_stream(s: Session) -> None:
    """No laser: the tip filmed by an IP camera (a network camera streaming H.264 to the logging PC, free running at F
    90-200 frames/s, its phase drawn) and tracked frame by frame, each frame stamped on arrival and the positions put on
    the DAQ's rows by those stamps (interpolated): a frame reaches the PC after the encoder's latency d0 (4-12 ms, log)
    and its own transmission, which the link serialises (a frame waits for the one before it): a P-frame's size grows
    with the motion it codes, t_P0 + t_M min(U/U_ref, 1) (t_P0 0.5-2 ms, log; t_M 2-8 ms, log, at the speed U_ref, 0.5
    of the session's largest), an I-frame every N (15-60) frames costs t_I (4-12 ms, log). A delay that grows with the
    tip's speed and jumps at each I-frame, on top of the frames' own sampling. Displacement only. Measured (s001_176:
    103 frames/s, an I-frame every 58, d0 8.6 ms, t_P0 0.65 ms, t_M 2.2 ms, t_I 8.4 ms) displacement residual 0.39 % of
    its RMS (12x its noise): the 0.45 Hz sines -1.6 deg (9.8 ms), the 3 Hz ones -10.9 deg (10.0 ms), the 9.4 Hz ones
    -34.6 to -34.9 deg (10.3 ms) at 0.97 of their gain, the 20 Hz ones -81 deg (11.2 ms) at 0.88."""
    fps, n_gop = s.rng.uniform(90.0, 200.0), int(s.rng.integers(15, 61))
    d0, t_p0, t_m, t_i = lu(s.rng, 4e-3, 1.2e-2), lu(s.rng, 5e-4, 2e-3), lu(s.rng, 2e-3, 8e-3), lu(s.rng, 4e-3, 1.2e-2)
    phase, i_phase = s.rng.uniform(0.0, 1.0 / fps), int(s.rng.integers(0, n_gop))
    u_ref = 0.5 * max(float(np.max(_speed(r))) for r in s.series())
    for r in s.series():
        t, d = r.cols["t_s"], r.cols["disp_m"]
        sig, _ = _split_noise(r)
        spd = _speed(r)
        k0 = int(math.floor((t[0] - 4.0 / fps - phase) * fps))
        k1 = int(math.ceil((t[-1] - phase) * fps))
        ks = np.arange(k0, k1 + 1)
        cap = phase + ks / fps
        val = np.interp(cap, t, d, left=d[0])
        size = t_p0 + t_m * np.minimum(np.interp(cap, t, spd, left=0.0) / u_ref, 1.0)
        size = np.where((ks - i_phase) % n_gop == 0, t_i, size)
        arr = np.empty(ks.size)
        last = -np.inf
        for j, (c, z) in enumerate(zip(cap.tolist(), size.tolist())):
            last = max(last, c + d0) + z
            arr[j] = last
        r.cols["disp_m"] = np.interp(t, arr, val, left=val[0])


def td_logger_ema(s: Session) -> None:
    """The lab's logging script smooths the laser's channel with an exponential moving average, its 'smoothing' slider
    set as a weight per sample, y += alpha (x - y) (alpha 0.15-0.5), started on each record's first sample: the same
    weight on every record, so its time constant (1 - alpha)/(alpha fs) is a fixed number of samples and a different
    time at each record's own rate (the sines' rates from 200 Hz to 1 kHz, the steps' 500 Hz): a first-order lag of 1-6
    samples, late by that much at low frequencies and falling at high ones. Displacement only. Measured (p10_177: alpha
    0.35, a lag of 1.9 samples) displacement residual 0.29 % of its RMS (2.0x its noise): the 0.1 Hz harmonics -0.32 deg
    and the 0.45 Hz sines -1.5 deg (9.4 ms at 200 Hz), the 3 Hz sines -10.0 deg (9.2 ms) at 0.976 of their gain, the 9.4
    Hz (469 Hz) and 20 Hz (1 kHz) ones both -13.1 deg (3.9 and 1.8 ms) at 0.960."""
    alpha = s.rng.uniform(0.15, 0.5)
    for r in s.series():
        x = r.cols["disp_m"]
        y, _ = signal.lfilter([alpha], [1.0, -(1.0 - alpha)], x, zi=[(1.0 - alpha) * x[0]])
        r.cols["disp_m"] = y


# ------------------------------------------------------------------------------------------------ sensor offset


def so_webcam_focus_drift(s: Session) -> None:
    """No laser: a webcam (a fixed-focus plastic lens, focused by hand on the strip) tracking the tip's end: the lab's
    script takes the strip's end where the intensity along its axis crosses its binarisation level, thr 0.6-0.8 of the
    strip's contrast, above the edge's midpoint, so it lands sigma Phi^-1(thr) inboard of the true end, sigma the edge's
    blur. The camera was switched on 0-20 min before the first record and its plastic lens and sensor mount warm over
    tau_w (600-2400 s, log), defocusing it: the blur grows from sigma_0 (20-50 um) to sigma_max (0.15-0.5 mm), and the
    tracked point walks inboard with it. The strip read at that station through the beam's own transfer functions
    (inject_fresh10._station); displacement only. Measured (s001_176: thr 0.75, 0.66 sigma inboard; the blur from 46 to
    453 um over tau_w 12 min, the camera switched on 7.8 min before the first record: the tracked point 0.16 mm inboard
    at the first record, 0.30 mm by the end) displacement RMS -2.5 % (residual 2.5 %, 79x its noise): the 1 V steps at
    4.60, 4.57, 4.56, 4.57 mm by their plateaus' end block by block (4.67-4.70 mm clean); the 0.1 Hz harmonics' gain
    0.983, 0.974, 0.972, 0.972; the 20 Hz sines' 0.983 to 0.980."""
    length = float(s.specimen["length_m"])
    thr = s.rng.uniform(0.6, 0.8)
    sg0, sg1, tau_w = s.rng.uniform(2e-5, 5e-5), s.rng.uniform(1.5e-4, 5e-4), lu(s.rng, 600.0, 2400.0)
    t_on = s.t0 - s.rng.uniform(0.0, 1200.0)
    z = float(norm.ppf(thr))

    def frac(r: Rec) -> np.ndarray:
        u = np.clip(r.cols["t_s"] - t_on, 0.0, None)
        sigma = sg0 + (sg1 - sg0) * -np.expm1(-u / tau_w)
        return 1.0 - sigma * z / length

    _station(s, frac, 1.0 - sg1 * z / length)


def so_lid_plate_shift(s: Session) -> None:
    """The strip held horizontal in its bath under a laser head looking down at its tip (aimed a margin m0, 0.1-0.3 mm,
    inside the tip's end), and at one re-clamping after the first (drawn; 0-60 s before the setting) the operator lays a
    glass slide over the cuvette as a lid against evaporation, resting tilted on the drive's wires: the head's beam now
    crosses a tilted plate (t 0.95-1.2 mm, n 1.52, the beam's incidence on it 8-25 deg), which displaces it sideways by
    t sin(theta) (1 - cos(theta)/sqrt(n^2 - sin^2(theta))), towards the clamp: the spot sits that much further inboard
    from then on (the operator re-zeroes the controller, its path's offset gone). The strip read at the station through
    the beam's own transfer functions (inject_fresh10._station); displacement only. Measured (paper_175: m0 0.25 mm, a
    slide 1.08 mm thick met at 13.0 deg, laid 34 s before the 1837 kPa setting: the spot 0.086 mm further inboard)
    displacement RMS -2.0 % (residual 2.0 %, 120x its noise): the 1 V steps at 8.65 mm by their plateau's end in the
    first block and 8.61 in the others (8.79-8.80 mm clean); the 0.1 Hz harmonics' gain 0.985, then 0.979; the 20 Hz
    sines' 0.962, then 0.948-0.949."""
    length = float(s.specimen["length_m"])
    m0, t_g = s.rng.uniform(1e-4, 3e-4), s.rng.uniform(9.5e-4, 1.2e-3)
    th = math.radians(s.rng.uniform(8.0, 25.0))
    shift = t_g * math.sin(th) * (1.0 - math.cos(th) / math.sqrt(1.52**2 - math.sin(th) ** 2))
    _, t_set = _later_setting(s)
    t_e = t_set - s.rng.uniform(0.0, 60.0)
    before, after = 1.0 - m0 / length, 1.0 - (m0 + shift) / length
    _station(s, lambda r: np.where(r.cols["t_s"] < t_e, before, after), after)


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_glass_jaws_capillary(s: Session) -> None:
    """A strip in air clamped between glass-slide jaws (flat, smooth, insulating: a lab's quick clamp) whose faces the
    operator wets at each re-clamping so that the root does not dry, setting the force on the load cell with the film
    fresh: the water film between glass and strip pulls them together by its Laplace suction, 2 gamma over the film's
    thickness (p_cap 50-200 kPa, log: films of 0.7-3 um), on top of the screw's force. The film dries back from the
    jaws' open edges, its wetted area (1 - sqrt(u/tau_d))^2 of the jaws (a receding front, tau_d 300-1500 s, log, from
    each setting, inject_fresh25._setting_of), and the suction it loses is shared between the strip and the screw by
    their stiffnesses: the strip's pressure falls by chi (0.3-0.8) of it, the screw's force, which the load cell in its
    line reads, rises by the rest. The strip through the preset's clamp law (inject_fresh4._clamp_law), the load cell at
    the indicator's 0.01 kgf: a pressure on the strip that relaxes through each block while the load cell creeps up.
    Displacement, current and the load cell. Measured (s001_176: p_cap 60 kPa, tau_d 15 min, chi 0.64) the load cell at
    1.012, 1.007, 1.006, 1.002 of its setting at each block's first record and 1.043, 1.024, 1.017, 1.013 by the blocks'
    last (creeping up); displacement residual 0.034 % of its RMS (1.05x its noise), current 0.21 % (0.58x): the 1 V
    steps' plateau current 0.638 mA in the first block (0.649 clean), the 1 V harmonics' current gain 0.996-0.998."""
    p_cap, tau_d, chi = lu(s.rng, 50.0, 200.0), lu(s.rng, 300.0, 1500.0), s.rng.uniform(0.3, 0.8)
    setting = _setting_of(s)

    def dried(t: np.ndarray, p: float, t_fp: float) -> np.ndarray:
        u = np.clip((np.asarray(t, float) - setting(p, t_fp)) / tau_d, 0.0, 1.0)
        return (p_cap / p) * (1.0 - (1.0 - np.sqrt(u)) ** 2)  # the suction lost, over the setting's pressure

    force = {id(r): r.cols["force_N"].copy() for r in s.series() if "force_N" in r.cols}
    _clamp_law(s, lambda t, p, t_fp: 1.0 + p_cap / p - chi * dried(t, p, t_fp))
    first: dict[float, float] = {}
    for r in s.series():
        p = float(r.entry["pressure_kPa"])
        first[p] = min(first.get(p, np.inf), float(r.cols["t_s"][0]))
    for r in s.series():
        if id(r) in force:
            p = float(r.entry["pressure_kPa"])
            rel = 1.0 + (1.0 - chi) * dried(r.cols["t_s"], p, first[p])
            r.cols["force_N"] = np.round(force[id(r)] * rel / 0.0980665) * 0.0980665


def cr_crazing_pc_shims(s: Session) -> None:
    """Shims of polycarbonate (cut from a sheet to keep the clamp's gap stiff) under a screw clamp's fixed gap, wiped
    with isopropanol when the clamp was cleaned: a glassy polymer under stress in contact with an alcohol crazes
    (environmental stress crazing), after an incubation that shortens steeply with the stress, t_i = t_i0 (p_max/p)^m_i
    (t_i0 60-400 s, log, at the session's heaviest setting; m_i 2-4), and then the crazes open and the shims creep,
    taking r_c (4-10 %) off the force along 1 - exp(-((u - t_i)/tau_c)^beta) (tau_c 60-600 s, log, beta 1-2); beside it
    the glass's own small relaxation, r_v (0.3-1 %) log10(1 + u/tau_v) (tau_v 2-20 s, log). From each setting
    (inject_fresh25._setting_of) through the preset's clamp law (inject_fresh4._clamp_law), the load cell showing it:
    the heavy settings sag after a wait, the light ones hardly. Measured (paper_175: r_v 0.63 %, tau_v 3.6 s, r_c 5.4 %,
    tau_c 3.0 min, beta 1.1, t_i0 138 s, m_i 2.6: incubations of 2.3 min at 4287 kPa, 5.5 min at 3062, 20 min at 1837
    and 5.8 h at 612) the load cell at 0.990, 0.997, 0.996, 0.995 of its setting at each block's first record and 0.980,
    0.987, 0.932, 0.931 by the blocks' last; displacement residual 0.087 % of its RMS (5.2x its noise: the 4287 kPa
    block's sines, the clamp law moving f1, the 3 Hz ones 0.92 (+13.5 deg) and the 9.4 Hz ones 1.26 (-12.6 deg)),
    current 0.39 % (0.29x)."""
    r_v, tau_v = s.rng.uniform(0.003, 0.01), lu(s.rng, 2.0, 20.0)
    r_c, tau_c, beta = s.rng.uniform(0.04, 0.10), lu(s.rng, 60.0, 600.0), s.rng.uniform(1.0, 2.0)
    t_i0, m_i = lu(s.rng, 60.0, 400.0), s.rng.uniform(2.0, 4.0)
    setting = _setting_of(s)
    p_max = max(s.pressures())

    def rel(t: np.ndarray, p: float, t_fp: float) -> np.ndarray:
        u = np.clip(np.asarray(t, float) - setting(p, t_fp), 0.0, None)
        t_i = t_i0 * (p_max / p) ** m_i
        craze = -np.expm1(-((np.clip(u - t_i, 0.0, None) / tau_c) ** beta))
        return 1.0 - r_v * np.log10(1.0 + u / tau_v) - r_c * craze

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_kettle_steam(s: Session) -> None:
    """A strip in air drying slowly in a dry room (towards k_d 0.05-0.15 of its mobile water, tau_d 3000-10000 s, log,
    from its mounting 0-600 s before the first record), in a lab whose kitchen corner has a kettle: a colleague boils it
    2-6 times in the session (drawn), each boil putting out steam for 2-4 min, the plume raising the humidity at the
    strip by a_b (0.05-0.15) as it builds and mixing away over tau_m (3-10 min, log) after the kettle clicks off. The
    strip's water follows the humidity through sorption (k 0.5-1 of the mobile water per unit of RH, a lag of tau_s
    60-300 s, log, on a 1 s grid): a slow loss with a wet bump at every boil. Gain x (1 - loss), conductance x (1 -
    share loss) (share 0.3-1); the spectra at the next series' start (inject_fresh9._dry_by). Measured (s001_176: drying
    towards 6.8 % with tau_d 89 min; five boils, 3, 20, 22, 56 and 59 min into the session, raising the humidity by
    0.057-0.126 and mixing away over 3.1-6.4 min; k 0.74, the sorption's lag 75 s, share 0.88) displacement RMS +0.98 %
    (residual 3.9 %, 120x its noise), current RMS -0.47 % (residual 2.6 %, 7.0x its noise): the 1 V steps at 4.65, 4.66,
    4.57, 5.05 mm by their plateaus' end block by block (4.67-4.70 mm clean: the fourth after the boils at 56 and 59
    min); the 0.1 Hz harmonics' gain 0.994, 1.020, 0.972, 1.047; the impedance 1.004, 1.008, 1.024, 0.937x at 0.1 Hz in
    the blocks' spectra."""
    k_d, tau_d, t_m = s.rng.uniform(0.05, 0.15), lu(s.rng, 3000.0, 10000.0), s.t0 - s.rng.uniform(0.0, 600.0)
    n_b = int(s.rng.integers(2, 7))
    boils = [(s.rng.uniform(s.t0, s.t1), s.rng.uniform(120.0, 240.0), s.rng.uniform(0.05, 0.15),
              lu(s.rng, 180.0, 600.0)) for _ in range(n_b)]
    k_iso, tau_s, share = s.rng.uniform(0.5, 1.0), lu(s.rng, 60.0, 300.0), s.rng.uniform(0.3, 1.0)
    tg = _session_grid(s, 1.0, 2.0)
    rh = np.zeros(tg.size)
    for a, dur, amp, tau_m in boils:
        u = tg - a
        build = np.clip(u / dur, 0.0, 1.0)
        rh += amp * np.where(u < dur, build, np.exp(-np.clip(u - dur, 0.0, None) / tau_m)) * (u >= 0)
    wet = k_iso * _grid_lag(rh, 1.0, tau_s)
    loss = k_d * -np.expm1(-np.clip(tg - t_m, 0.0, None) / tau_d) - wet

    def f(t: np.ndarray) -> np.ndarray:
        return np.interp(np.asarray(t, float), tg, loss)

    _dry_by(s, f, lambda t: share * f(t))


def dh_phenolic_film(s: Session) -> None:
    """The bench and the cuvette wiped with a phenolic disinfectant (an o-phenylphenol one) and the cuvette rinsed too
    briefly: whichever face is the anode beyond E_p (0.3-0.5 V of drive, width 0.03-0.06 V) oxidises the phenol, and the
    phenoxy radicals polymerise into an insulating poly(phenylene oxide) film on that face (the classic self-limiting
    fouling of electrodes by phenols): each face's covered share grows as 1 - exp(-k W), W the time it has spent
    oxidising (the wave's weight integrated, inject_fresh34._cumulative), k set so that the face that oxidised most is
    covered to theta_end (0.5-0.9) by the session's end; the film takes its share of the electrode's active area, a_max
    (6-15 %) of it at full cover, the loss the two faces' mean. Gain x (1 - loss), conductance x (1 - share loss) (share
    0.3-1); the spectra at the next series' start (inject_fresh9._dry_by). Measured (p10_177: E_p 0.44 V, the
    more-worked face covered to 0.77 by the session's end, a_max 7.2 %, share 0.78) displacement RMS -2.5 % (residual
    2.9 %, 20x its noise), current RMS -2.5 % (residual 2.7 %, 1.5x its noise): the 1 V steps at 1.006, 0.990, 0.978,
    0.969 mm by their plateaus' end block by block (1.011-1.012 mm clean); the sines' gain 0.982-0.989 in the first
    block and 0.952-0.955 in the last (their current 0.986-0.992 and 0.963-0.965) ; the impedance 1.000, 1.014, 1.025,
    1.033x in the blocks' spectra."""
    e_p, w = s.rng.uniform(0.3, 0.5), s.rng.uniform(0.03, 0.06)
    th_end, a_max, share = s.rng.uniform(0.5, 0.9), s.rng.uniform(0.06, 0.15), s.rng.uniform(0.3, 1.0)

    def wave(r: Rec, sgn: float) -> np.ndarray:
        u = sgn * r.cols["v_V"]
        return _rising((u - e_p) / w, -e_p / w)

    per, tot = _per_face(s, wave)
    top = max(tot.values())
    k = -math.log1p(-th_end) / top if top > 0 else 0.0
    loss_per = {id(r): a_max * 0.5 * sum(-np.expm1(-k * per[sg][id(r)]) for sg in (1.0, -1.0)) for r in s.series()}
    loss_t = _session_curve(s, loss_per)

    def f(t: np.ndarray) -> np.ndarray:
        return loss_t(t)

    _dry_by(s, f, lambda t: share * f(t))


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_notch_edge_crack(s: Session) -> None:
    """A strip trimmed with blunt scissors that left a notch in one cut edge near its root: the notch cuts both faces'
    plating, and from it a crack grows across each face's plating with every large tension that face sees, by Paris' law
    on the notch's own stress concentration, da/dN = C (e sqrt(pi a))^m (m 2.5-4: self-accelerating, the longer crack
    the faster), from the notch's depth a_0 (0.05-0.15 of the width) to a_end (0.3-0.6) on the face that worked most by
    the session's end (the growth counted on the loading half of each cycle, weighted by (e/e_max)^(m-1),
    inject_fresh34._cumulative, and integrated exactly). The crack opens with its face's tension beyond e_c (0.05-0.2 of
    the largest) and, open, narrows that face's current path at the notch: dR/R = kappa (1/(1 - a o) - 1) (kappa
    0.3-0.7, the share of the face's resistance at the notch's station), the two faces' mean. Gains fall by 0.03-0.08
    (displacement) and 0.06-0.15 (current) per unit of dR/R (inject_fresh3._resist). Measured (paper_175: m 2.56, the
    crack from 0.096 to 0.57 of the width, e_c 0.12 of the largest bend, kappa 0.36; gains 0.047 and 0.097 per unit of
    dR/R) displacement RMS -0.19 % (residual 0.25 %, 15x its noise), current RMS -0.025 % (residual 0.13 %, 0.10x its
    noise): the 1 V steps at 8.780, 8.782, 8.772, 8.733 mm by their plateaus' end block by block (8.79-8.80 mm clean:
    the crack growing, fastest at the end), their current 0.002-0.009 mA lower; the 1 V harmonics' gain 0.9996, 0.9993,
    0.9989, 0.9979; 12 of the 68 series touched."""
    ref = ref_disp(s)
    big = (_largest(s) or ref) / ref
    m = s.rng.uniform(2.5, 4.0)
    a0, a_end = s.rng.uniform(0.05, 0.15), s.rng.uniform(0.3, 0.6)
    e_c, kappa = s.rng.uniform(0.05, 0.2) * big, s.rng.uniform(0.3, 0.7)

    def rate(r: Rec, sgn: float) -> np.ndarray:
        sig, _ = _split_noise(r)
        e = sgn * sig / ref
        de = np.gradient(e, r.cols["t_s"]) if e.size > 1 else np.zeros(e.size)
        return np.clip(de, 0.0, None) * (np.clip(e, 0.0, None) / big) ** (m - 1.0)

    per, tot = _per_face(s, rate)
    q = 1.0 - m / 2.0  # Paris integrated: a^q/q grows in proportion to the damage
    top = max(tot.values())
    c = (a_end**q - a0**q) / q / top if top > 0 else 0.0

    def crack(x: np.ndarray) -> np.ndarray:
        return np.clip(q * (a0**q / q + c * x), 1e-12, None) ** (1.0 / q)

    def law(r: Rec, e: np.ndarray) -> np.ndarray:
        out = np.zeros(e.size)
        for sgn in (1.0, -1.0):
            o = np.clip((sgn * e - e_c) / (big - e_c), 0.0, 1.0)
            a = np.minimum(crack(per[sgn][id(r)]), 0.95)
            out += kappa * (1.0 / (1.0 - a * o) - 1.0)
        return 0.5 * out

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


def sr_flaw_crack_births(s: Session) -> None:
    """A plating with sparse flaws (thin spots where bubbles sat during the plating): at every crest of a face's tension
    above 0.2 of the session's largest bend, a new crack may nucleate across that face, with the flaws' Weibull
    probability 1 - exp(-(e_p/e_0)^k) (e_p the crest, e_0 0.7-1.2 of the largest, k 4-8), drawn from the case's seed:
    once born it opens with that face's tension beyond its own e_j (0.3-0.7 of the crest that made it), saturating at
    the largest bend, and adds its own g_j (exponential, mean 0.03-0.08) to the face's dR/R: dR/R = sum_j g_j clip((e -
    e_j)/(e_max - e_j), 0, 1) per face, the two faces' mean. A gauge that grows in random steps at the large tensions
    (the 1 V records), the face the steps stretch more than the other. Gains fall by 0.03-0.08 (displacement) and
    0.06-0.15 (current) per unit of dR/R (inject_fresh3._resist). Measured (s001_176: e_0 0.93 of the largest bend, k
    4.6, g_j's mean 0.076: cracks born on the 500, 1300 and 1700 kPa steps, face A's dR/R at full tension 0.021, 0.126,
    0.167 after them, face B's none) displacement RMS -0.20 % (residual 0.32 %, 10x its noise), current RMS -0.04 %
    (residual 0.24 %, 0.65x its noise): the 1 V steps at 4.671, 4.682, 4.690, 4.661 mm by their plateaus' end block by
    block (4.67-4.70 mm clean), their current 0.000, 0.002, 0.002, 0.010 mA lower; the 1 V harmonics' gain 0.9997,
    0.9997, 0.9987, 0.9980; 8 of the 68 series touched."""
    ref = ref_disp(s)
    big = (_largest(s) or ref) / ref
    e0, kw, g_m = s.rng.uniform(0.7, 1.2) * big, s.rng.uniform(4.0, 8.0), s.rng.uniform(0.03, 0.08)
    cracks = {1.0: [], -1.0: []}  # (birth time, e_j, g_j)
    for r in _chrono(s):
        sig, _ = _split_noise(r)
        for sgn in (1.0, -1.0):
            e = sgn * sig / ref
            peaks, _ = signal.find_peaks(e, height=0.2 * big, prominence=0.1 * big)
            for k in peaks.tolist():
                ep = float(e[k])
                u, frac, g = s.rng.random(), s.rng.uniform(0.3, 0.7), s.rng.exponential(g_m)
                if u < -math.expm1(-((ep / e0) ** kw)):
                    cracks[sgn].append((float(r.cols["t_s"][k]), frac * ep, g))

    def law(r: Rec, e: np.ndarray) -> np.ndarray:
        t = r.cols["t_s"]
        out = np.zeros(e.size)
        for sgn in (1.0, -1.0):
            for tb, ej, g in cracks[sgn]:
                out += g * np.clip((sgn * e - ej) / (big - ej), 0.0, 1.0) * (t >= tb)
        return 0.5 * out

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_psd_background_dilution(s: Session) -> None:
    """A triangulation head of the older kind whose receiver is a lateral-effect position-sensitive detector, not a line
    sensor: the PSD reports the centroid of all the light on it, and the head's own stray light (its window's internal
    reflection, a fixed patch at the detector's centre) adds B (0.05-0.3 of the spot's return at rest) to it, so the
    reading is the spot's position times S/(S + B), calibrated at rest. The spot's return S falls as the tip tilts, as
    cos^k of its angle (k 1-3: the plating's diffuse lobe), the angle 2 d/L on the uniform arc: a reading d g, g =
    cos^k/(cos^k + B)(1 + B), compressed at the large bends on either side. Tabulated and interpolated
    (inject_fresh33._static_map); displacement only. Measured (paper_175: k 1.57, B 0.28) displacement RMS -3.6 %
    (residual 4.1 %, 240x its noise): the 1 V steps at 8.20-8.21 mm by their plateaus' end (8.79-8.80 mm clean) and 6.40
    mm 2 s after their fall (6.64 mm clean); the 1 V harmonics' gain 0.987-0.988; the 0.5 V sines' 0.999 or above."""
    length = float(s.specimen["length_m"])
    big = _largest(s) or ref_disp(s)
    kk, b = s.rng.uniform(1.0, 3.0), s.rng.uniform(0.05, 0.3)
    dg = np.linspace(-1.25 * big, 1.25 * big, 5001)  # the session's bends and a margin (no reading goes beyond)
    c = np.cos(2.0 * dg / length) ** kk
    _static_map(s, dg * c / (c + b) * (1.0 + b), dg)


def ld_opto_push_pull(s: Session) -> None:
    """The laser's analogue output carried to the DAQ through the lab's home-made isolation stage against a ground loop:
    two optocouplers in push-pull, one for each polarity, each LED driven in proportion to its half of the signal over a
    small bias b (0.02-0.1 of the stage's full-scale current) and read by its phototransistor, the two outputs
    subtracted, calibrated by its slope at rest. An optocoupler's current transfer ratio falls at high LED current
    (CTR0/(1 + I/I_s), I_s 6-20 times the full scale: the LED's droop and the transistor's gain falling), so each half
    compresses its large readings: h(I) = I/(1 + I/I_s), the reading [h(x+ + b) - h(x- + b)]/h'(b), the stage's full
    scale R 1.2-2 times the session's largest bend. An odd compression of the large bends, both sides alike. Tabulated
    and interpolated (inject_fresh33._static_map); displacement only. Measured (p10_177: the stage's full scale 1.8
    times the largest bend, b 0.091, I_s 6.3) displacement RMS -5.7 % (residual 6.0 %, 41x its noise): the 1 V steps at
    0.931-0.932 mm by their plateaus' end (1.011-1.012 mm clean) and 0.687 mm 2 s after their fall (0.730 clean); the 1
    V harmonics' gain 0.961-0.963; the 0.1 Hz sines' 0.991, the 0.45 Hz ones' 0.995, the 3 Hz ones' 0.998."""
    big = _largest(s) or ref_disp(s)
    span, b, i_s = s.rng.uniform(1.2, 2.0) * big, s.rng.uniform(0.02, 0.1), lu(s.rng, 6.0, 20.0)
    dg = np.linspace(-2.0 * big, 2.0 * big, 8001)
    x = dg / span

    def h(i: np.ndarray) -> np.ndarray:
        return i / (1.0 + i / i_s)

    y = (h(np.clip(x, 0.0, None) + b) - h(np.clip(-x, 0.0, None) + b)) / (1.0 / (1.0 + b / i_s) ** 2)
    _static_map(s, y * span, dg)


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_crt_monitor_retrace(s: Session) -> None:
    """The neighbouring rig's old CRT monitor (its instrument PC's, on all session), its vertical deflection yoke driven
    by a sawtooth at its field rate f_v (50 Hz for a PAL monitor, 59.94 Hz for a VGA one, drawn; off by up to 2e-4, its
    own crystal): the yoke's stray field ramps over the field and snaps back over the retrace (r 0.03-0.08 of it), and
    the laser's cable and the current amplifier's input, loops in that field, pick up its rate of change: a flat
    baseline over the ramp and a half-sine pulse of the opposite sign over each retrace (zero mean), every harmonic of
    f_v up to 1/(r T), at 1-4 um and 8-30 uA RMS (log), each channel's sign drawn, as the DAQ samples them (aliased
    where the rate is low). Displacement and current. Measured (p10_177: a PAL monitor at 50.003 Hz, its retrace 0.055
    of the field, 3.0 um and 12 uA RMS) displacement residual 0.71 % of its RMS (4.9x its noise), current 0.44 %
    (0.25x): every series touched, its lines at 50.003 Hz and every harmonic, aliased in the slow records."""
    f_v = (50.0 if s.rng.random() < 0.5 else 59.94) * (1.0 + s.rng.uniform(-2e-4, 2e-4))
    ret, ph = s.rng.uniform(0.03, 0.08), s.rng.uniform(0.0, 1.0)
    amp = {"disp_m": lu(s.rng, 1e-6, 4e-6) * _sign(s), "i_A": lu(s.rng, 8e-6, 3e-5) * _sign(s)}
    rms = math.sqrt((1.0 - ret) + ((1.0 - ret) / ret) ** 2 * ret * (math.pi**2 / 8.0))  # of the unscaled wave
    for r in s.series():
        x = np.mod(f_v * r.cols["t_s"] + ph, 1.0)
        pulse = (math.pi / 2.0) * np.sin(np.pi * np.clip((x - (1.0 - ret)) / ret, 0.0, 1.0))
        wave = np.where(x < 1.0 - ret, 1.0, -(1.0 - ret) / ret * pulse) / rms
        for col, a in amp.items():
            r.cols[col] = r.cols[col] + a * wave


def mp_spot_welder_recharge(s: Session) -> None:
    """The workshop next door building battery packs with a capacitor-discharge spot welder on the building's supply, in
    2-3 spells of 10-30 min (log, each starting inside a recorded series: a pack's tabs welded one after another): after
    every weld (Poisson, one every 2-6 s on average, log) the welder recharges its capacitor bank through a
    capacitor-input rectifier, drawing the line's current in narrow pulses at each peak, rich in odd harmonics (the 3rd
    0.7-0.9 of the fundamental, the 5th 0.45-0.6, the 7th 0.25-0.4, the 9th 0.1-0.2), in a burst that decays as the bank
    fills (tau_r 0.5-2 s, log). Picked up magnetically by the laser's cable and the current amplifier's input (4-12 um
    and 20-60 uA at a burst's start, log), at the line (50 or 60 Hz, inject_fresh12._line_f), as the DAQ samples them.
    Displacement and current. Measured (s001_176: 49.999 Hz; a spell of 23 min from 53 min into the session and two
    brushing its end; a weld every 4.6 s, tau_r 0.58 s, 5.2 um and 36 uA at a burst's start) displacement residual 0.044
    % of its RMS (1.4x its noise), current 0.17 % (0.46x): 21 of the 68 series touched, in them 1.5 um and 9.0 uA RMS
    (2.6x and 0.87x their noise)."""
    f0 = _line_f(s)
    spells = _bursts(s, int(s.rng.integers(2, 4)), (600.0, 1800.0))
    gap, tau_r = lu(s.rng, 2.0, 6.0), lu(s.rng, 0.5, 2.0)
    harm = {1: 1.0, 3: s.rng.uniform(0.7, 0.9), 5: s.rng.uniform(0.45, 0.6), 7: s.rng.uniform(0.25, 0.4),
            9: s.rng.uniform(0.1, 0.2)}
    amp = {"disp_m": lu(s.rng, 4e-6, 1.2e-5), "i_A": lu(s.rng, 2e-5, 6e-5)}
    phase = {col: {h: s.rng.uniform(0.0, 2.0 * np.pi) for h in harm} for col in amp}
    welds = []
    for a, b in spells:
        t = a + s.rng.exponential(gap)
        while t < b:
            welds.append(t)
            t += s.rng.exponential(gap)
    welds = np.array(sorted(welds))
    for r in s.series():
        t = r.cols["t_s"]
        env = np.zeros(t.size)
        for w_t in welds[(welds <= t[-1]) & (welds > t[0] - 8.0 * tau_r)].tolist():
            env += np.where(t >= w_t, np.exp(-np.clip(t - w_t, 0.0, None) / tau_r), 0.0)
        if not np.any(env):
            continue
        wt = 2.0 * np.pi * f0 * t
        for col, a_ in amp.items():
            wave = sum(c * np.cos(h * wt + phase[col][h]) for h, c in harm.items())
            r.cols[col] = r.cols[col] + a_ * env * wave


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_detrended_records(s: Session) -> None:
    """The lab's export script 'cleans' the laser's drift by detrending every record's displacement: the least-squares
    straight line through the record's samples taken off (scipy.signal.detrend, linear, the whole record). A sine of
    whole cycles loses little; a step, up for its first half and back for its second, loses a tilt and an offset, the
    records' rests and tails a slope of their own. The displacement only. Measured (paper_175 and p10_177) displacement
    RMS -63 % and -62 % (residual 93 %, 5500x and 640x its noise): the 1 V steps at 3.63-3.64 and 0.42 mm by their
    plateaus' end (8.79-8.80 and 1.01 mm clean) and 1.51-1.52 and 0.15 mm 2 s after their fall (6.64 and 0.73 mm clean);
    the 0.1 Hz harmonics' gain 0.937-0.938 (-3.9 deg) and 0.930-0.931 (-3.4 to -3.5 deg); the sines within 2.4 % (the
    paper strip's 9.4 Hz ones, by its resonance, 1.011-1.024)."""
    for r in s.series():
        r.cols["disp_m"] = signal.detrend(r.cols["disp_m"], type="linear")


def out_ldv_fringe_loss(s: Session) -> None:
    """No triangulation: a laser Doppler vibrometer aimed at the tip, read through its displacement decoder (a fringe
    counter with an interpolator) on its finest range, whose data sheet's maximum velocity there is low: beyond v_max
    (0.3-0.6 of the session's largest tip speed) the decoder misses fringes, counting at most v_max per unit time, and
    the motion it misses is lost for good. The reading counts the signal's increments, each clipped to v_max dt, through
    the session in time order (the slow motion over the rests counted in full), its own noise the laser's: the fast
    edges of the steps and the fastest sines read short, and each record after them offset by what was lost.
    Displacement only. Measured (paper_175: v_max 0.41 of the session's largest tip speed; s001_176: 0.56) displacement
    residual 12.9 % and 0.26 % of its RMS (770x and 8.2x its noise): on the paper strip the 3 Hz sines (its resonance)
    at 0.51-0.63 of their gain and the steps' plateaus at 8.53, 8.78, 9.01, 9.23 mm block by block (8.79-8.80 mm clean)
    as the lost motion adds up; on the seed-001 strip the 20 Hz sines (by its resonance) at 0.77, 0.83, 0.89, 0.92, the
    steps within 0.01 mm."""
    v_max = s.rng.uniform(0.3, 0.6) * max(float(np.max(_speed(r))) for r in s.series())
    y_end, d_end = 0.0, None
    for r in _chrono(s):
        sig, noise = _split_noise(r)
        dt = np.diff(r.cols["t_s"])
        y0 = float(sig[0]) if d_end is None else y_end + float(sig[0]) - d_end
        inc = np.clip(np.diff(sig), -v_max * dt, v_max * dt)
        y = y0 + np.r_[0.0, np.cumsum(inc)]
        y_end, d_end = float(y[-1]), float(sig[-1])
        r.cols["disp_m"] = y + noise


def out_illuminator_heating(s: Session) -> None:
    """A fibre-optic illuminator (a halogen cold light, its gooseneck guide aimed at the tip from one side at theta_0
    0-25 deg off the face's normal) that the operator switches on to film the strip in 2-4 spells of 3-12 min (log, each
    starting inside a recorded series): the light absorbed on the lit face's dark plating warms it against the other,
    and the membrane's expansion across its thickness bends the strip away from the light (a thermal bimorph), by D0 at
    full light (10-40 um in air, 5-15 um in water, log) through the face's thermal lag (tau_th 1-4 s in air, 0.3-1 s in
    water, log). The power let in follows the face's tilt to the guide, cos(theta_0 + phi)/cos(theta_0), phi the tip's
    angle on the uniform arc (2 d/L): a term of the bend's own that comes and goes with the light, additive in the
    displacement, its state carried over the rests. Displacement only. Measured (s001_176: D0 36 um, tau_th 1.7 s,
    theta_0 22 deg, spells of 12 and 8 min from 41 and 75 min into the session, the second cut by its end; p10_177: 5.1
    um, 0.79 s, -20.5 deg, two spells of 5 min from 30 and 52 min) displacement residual 0.91 % and 0.35 % of its RMS
    (28x and 2.4x its noise): 32 and 20 of the 68 series touched, in them 23 and 2.3 um RMS (40x and 4.0x their noise);
    the seed-001 strip's 1300 kPa step 0.026 mm short on its plateau."""
    length = float(s.specimen["length_m"])
    air = s.specimen.get("medium") == "air"
    d0 = (lu(s.rng, 1e-5, 4e-5) if air else lu(s.rng, 5e-6, 1.5e-5)) * _sign(s)
    tau = lu(s.rng, 1.0, 4.0) if air else lu(s.rng, 0.3, 1.0)
    th0 = math.radians(s.rng.uniform(0.0, 25.0)) * _sign(s)
    spells = _bursts(s, int(s.rng.integers(2, 5)), (180.0, 720.0))
    x, t_end, d_end = 0.0, None, 0.0
    for r in _chrono(s):
        t = r.cols["t_s"]
        sig, _ = _split_noise(r)
        if t_end is not None and t[0] > t_end:  # over the rest: towards the light's share at the strip's rest bend
            mid = 0.5 * (t_end + float(t[0]))
            on = float(_spell_envelope(np.array([mid]), spells, 0.2)[0])
            target = on * math.cos(th0 + 2.0 * d_end / length) / math.cos(th0)
            x = target + (x - target) * math.exp(-(float(t[0]) - t_end) / tau)
        power = _spell_envelope(t, spells, 0.2) * np.cos(th0 + 2.0 * sig / length) / math.cos(th0)
        a = math.exp(-1.0 / (r.fs * tau))
        y, _ = signal.lfilter([1.0 - a], [1.0, -a], power, zi=[a * x])
        x, t_end, d_end = float(y[-1]), float(t[-1]), float(sig[-1])
        r.cols["disp_m"] = r.cols["disp_m"] + d0 * y


def out_polar_export_spectra(s: Session) -> None:
    """The impedance analyser's software exporting its sweeps in Bode form, modulus and phase (|Z| in ohm, the phase in
    degrees), and the lab's conversion script copying its second and third columns into the manifest's z_re_ohm and
    z_im_ohm as if they were Nyquist's Z' and Z'': each spectrum's real column |Z|, its imaginary column the phase in
    degrees (negative, tens at the low frequencies, a degree or less at 10 kHz). The spectra only, the time series
    untouched. Measured (s001_176 and p10_177) every spectrum's real column |Z| and its imaginary one the phase in
    degrees: at 0.1 Hz 215.8 and -38.3 for 169.3 - 133.8j ohm in the seed-001 strip's first spectrum, 460.3 and -48.0
    for 307.8 - 342.2j in the 10 mm strip's; at 10 kHz 50.33 and -0.55 for 50.33 - 0.48j, 28.48 and -1.18 for 28.47 -
    0.58j; no time series touched."""
    for r in s.recs:
        if r.series:
            continue
        z = r.cols["z_re_ohm"] + 1j * r.cols["z_im_ohm"]
        r.cols["z_re_ohm"], r.cols["z_im_ohm"] = np.abs(z), np.degrees(np.angle(z))


FRESH35_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"flake_flap_valves": br_flake_flap_valves, "antifoam_drop": br_antifoam_drop},
    "faradaic_current": {"formic_descaler": far_formic_descaler, "chromic_acid_residue": far_chromic_acid_residue},
    "hysteresis": {"max_pointer_telltale": hy_max_pointer_telltale, "canny_edge_tracker": hy_canny_edge_tracker},
    "time_delay": {"ip_camera_stream": td_ip_camera_stream, "logger_ema": td_logger_ema},
    "sensor_offset": {"webcam_focus_drift": so_webcam_focus_drift, "lid_plate_shift": so_lid_plate_shift},
    "clamp_relaxation": {"glass_jaws_capillary": cr_glass_jaws_capillary, "crazing_pc_shims": cr_crazing_pc_shims},
    "dehydration": {"kettle_steam": dh_kettle_steam, "phenolic_film": dh_phenolic_film},
    "strain_resistance": {"notch_edge_crack": sr_notch_edge_crack, "flaw_crack_births": sr_flaw_crack_births},
    "large_deflection": {"psd_background_dilution": ld_psd_background_dilution, "opto_push_pull": ld_opto_push_pull},
    "mains_pickup": {"crt_monitor_retrace": mp_crt_monitor_retrace, "spot_welder_recharge": mp_spot_welder_recharge},
    "unexplained": {"detrended_records": out_detrended_records, "ldv_fringe_loss": out_ldv_fringe_loss,
                    "illuminator_heating": out_illuminator_heating, "polar_export_spectra": out_polar_export_spectra},
}
inject.register_forms(FRESH35_FORMS)


# ------------------------------------------------------------------------------------------------ variants

CHANNEL_ORDER = ("disp_m", "i_A", "v_V", "force_N", "t_s")


def v_channel_order(s: Session) -> None:
    """A logger that writes each record's table in its DAQ task's channel order (the channels in the order the lab added
    them to the task: the laser, the current amplifier, the drive monitor, the load cell merged after them) with the
    time stamp appended as the last column, as a script building its table from the task's channel list does: every time
    series' columns disp_m, i_A, v_V, force_N (where it has one), t_s, in that order; the values, the rows, the spectra
    and the manifest untouched. The import contract names the columns in a header row and asks for no order; ``labrig
    import`` takes it and ``labrig export`` writes the records back, their values as written."""
    for r in s.series():
        r.cols = {c: r.cols[c] for c in CHANNEL_ORDER if c in r.cols} | {c: x for c, x in r.cols.items()
                                                                          if c not in CHANNEL_ORDER}


inject.VARIANTS.update({"channel_order": v_channel_order})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_175", "s001_176", "p10_177"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 7 / 6 effect cases on seeds 175-177
    "back_relaxation": [("flake_flap_valves", 175, P, "loadcell_dropout"), ("antifoam_drop", 177, T, "float32_time")],
    "faradaic_current": [("formic_descaler", 175, P, "eis_two_passes"),
                         ("chromic_acid_residue", 177, T, "cathodic_positive")],
    "hysteresis": [("max_pointer_telltale", 176, S, "own_clock"), ("canny_edge_tracker", 175, P, "rate07")],
    "time_delay": [("ip_camera_stream", 176, S, "no_loadcell"), ("logger_ema", 177, T, "trigger_clock")],
    "sensor_offset": [("webcam_focus_drift", 176, S, "fir_decimated"), ("lid_plate_shift", 175, P, "coherent_sines")],
    "clamp_relaxation": [("glass_jaws_capillary", 176, S, "settled_sines"),
                         ("crazing_pc_shims", 175, P, "merged_loadcell")],
    "dehydration": [("kettle_steam", 176, S, "measured_pressures"), ("phenolic_film", 177, T, "eis_descending")],
    "strain_resistance": [("notch_edge_crack", 175, P, "reversed_laser"),
                          ("flaw_crack_births", 176, S, "swinging_door")],
    "large_deflection": [("psd_background_dilution", 175, P, "channel_order"),
                         ("opto_push_pull", 177, T, "tared_records")],
    "mains_pickup": [("crt_monitor_retrace", 177, T, "block_clock"),
                     ("spot_welder_recharge", 176, S, "dropped_packets")],
    "unexplained": [("detrended_records", 175, P, "midnight_clock"), ("detrended_records", 177, T, "harmonics_as_free"),
                    ("ldv_fringe_loss", 175, P, "short_pretrigger"), ("ldv_fringe_loss", 176, S, "stop_trigger"),
                    ("illuminator_heating", 176, S, "steps_sines"), ("illuminator_heating", 177, T, "two_pressures"),
                    ("polar_export_spectra", 176, S, "spectra_last"),
                    ("polar_export_spectra", 177, T, "channel_order")],
}
CLEAN = [(175, P, "channel_order"), (175, P, "decimated3"), (176, S, "channel_order"),
         (176, S, "log_steps"), (177, T, "no_spectra"), (177, T, "minimal_manifest")]


def fresh35_cases(only: str | None = None) -> list[Case]:
    """The thirty-sixth held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds
    175-177)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh35_cases, "inject_fresh35", "fresh35")
