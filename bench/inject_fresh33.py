"""A thirty-fourth held-out set for the diagnosis (issue 12), fresh33, written without sight of the diagnosis (its code,
its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh32.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (the strip's own motion stirring the
unstirred layer its back-flow crosses, a silver contact pad chloriding by nucleation and growth, a tip magnet cogging
along a threaded steel rod, a carbon-ink flex sensor's particle contacts, a vibrometer's decoder auto-ranging with the
tip's speed, a low-voltage Zener clamp on the DAQ's input, a loose silicone sleeve over the root that the large bends
take up) and some on the history, the clamp pressure or the session's events (a gravity-fed perfusion bottle refilled at
each re-clamping, nickel hydroxide deposited by the cathodic excursions and cycled by the anodic ones, tap-water scale
wedging the cathodic face's open cracks, a vacuum pump fretting the cracks' bridges in spells, a dead-weight lever clamp
whose water ballast seeps, a screw clamp ratcheted loose by the air conditioning's temperature cycles, the room's air
conditioner re-evaporating its coil's water after each compressor stop, LED lamps dimmed at one re-clamping, an AC
static eliminator switched on at re-clampings) and some on time (the laser controller's processor throttling as it
warms, hydroxyl radicals from peroxide and a clamp's iron attacking the ionomer); sensors among them (the flex sensor,
the vibrometer, the capillary meniscus read as a micropump's flap sweeps it, the fibre Bragg gratings) and the lab's
wiring and appliances (the controller's processor, the Zener clamp, the dimmer, the ioniser, the air conditioner, the
vacuum pump). Four structures outside the catalogue (truth "unexplained": spectra exported with the analyser's -Z''
column as z_im_ohm; the drive re-quantised by a DSP amplifier's input converter after the monitor; eddy-current damping
of a tip magnet near the stand's aluminium block; a CMOS switch in the drive line whose on-resistance follows the
signal); clean sessions. All on three bases of new seeds (169-171: the paper strip, the seed-001 strip on its own sweep,
the paper strip 12 mm free) and on the earlier sets' data-shape variants plus one new here: a logger that switches its
rate at each stepped sine's trigger, the settling cycles at a fraction of the rate (``two_rate_sines``).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh32 are reused (importing inject_fresh32 and inject_fresh31 registers every earlier set's
lookups), and the forms, bases, preset and variant of this set are registered into inject's lookups at import, none
replaced. Strengths are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it
made on its case, measured in memory against the clean base (relative RMS change over all series, form only, no variant;
"noise": the column's sample-to-sample noise at rest, inject_fresh15.rest_noise).

Run: python bench/inject_fresh33.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np

import inject
import inject_fresh31  # noqa: F401  (registers every earlier set's forms, bases, presets and variants but fresh30's)
import inject_fresh32  # noqa: F401  (registers fresh32's and, through it, fresh30's)
from inject import Case, Rec, Session, lu, map_disp, ref_disp
from inject_fresh2 import _chrono, _map_through, _spec
from inject_fresh3 import _resist, _sign, _through_x
from inject_fresh4 import _clamp_law
from inject_fresh6 import _bursts
from inject_fresh9 import _dry_by, _session_grid
from inject_fresh10 import _lag_varying
from inject_fresh12 import _line_f
from inject_fresh14 import _largest
from inject_fresh25 import _setting_of
from inject_fresh26 import _later_setting, _split_noise
from inject_fresh29 import _grid_lag, _logistic
from inject_fresh31 import _on_grid, _settings

# the paper's strip 12 mm free (earlier sets used 13-29 and 31-45 mm, 30 mm is the paper preset itself and the seed-001
# strip is 20 mm): its 1 V step peaks at 1.46 mm, well inside the laser's +-20 mm (2 mm/V on the DAQ's +-10 V) and 2400x
# the laser's 0.60 um noise at rest; its first mode at 20.6 Hz (zeta 0.11), at the top of the sines. Preset "paper_12",
# base "p12_171", registered in every process importing this module
inject.register_free_length("paper_12", 0.012)

inject.BASES.update({
    "paper_169": ("paper-sweep", "paper", 169),
    "s001_170": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 170),
    "p12_171": ("paper-sweep", "paper_12", 171),
})

LASER_M_PER_V = 2e-3  # the simulated laser's analogue scale (2 mm/V: +-20 mm on the DAQ's +-10 V)


# ------------------------------------------------------------------------------------------------ tools


def _smooth_speed(s: Session, t_r: float) -> tuple[np.ndarray, np.ndarray]:
    """The tip's speed (the displacement's signal, inject_fresh26._split_noise, differentiated) averaged over the last
    t_r seconds (a first-order lag through the session in time order, decaying over the rests): (times, values) for
    interpolation."""
    ts, us, u, t_end = [], [], 0.0, None
    for r in _chrono(s):
        t = r.cols["t_s"]
        sig, _ = _split_noise(r)
        v = np.abs(np.gradient(sig, t)) if t.size > 1 else np.zeros(t.size)
        if t_end is not None:
            u *= math.exp(-max(float(t[0]) - t_end, 0.0) / t_r)
        a = math.exp(-1.0 / (r.fs * t_r))
        out = np.empty(t.size)
        for k, vk in enumerate(v.tolist()):
            u = vk + (u - vk) * a
            out[k] = u
        ts.append(t)
        us.append(out)
        t_end = float(t[-1])
    return np.concatenate(ts), np.concatenate(us)


def _modal_reading(s: Session, weights: Callable[[object], np.ndarray]) -> None:
    """The displacement as read by a sensor that weighs the strip's modes by ``weights(sp)`` (a vector over the modes:
    the reading of mode i per unit of its amplitude), calibrated against the tip at rest: each record through the ratio
    (sum_i q_i(s) c_i / the same at rest) / (w(L, s) / w(L, 0)) (labrig.physics.transfer.modal_responses), with the
    session's history (inject_fresh2._map_through)."""
    from labrig.physics import transfer

    cache: dict[float, Callable[[np.ndarray], np.ndarray]] = {}

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        p = float(r.entry["pressure_kPa"])
        if p not in cache:
            sp = _spec(s, r)
            ms = transfer.modal_set(sp)
            c, tip = weights(sp), ms.phi_sensor
            z0 = np.array([2j * np.pi * 1e-4])
            q0 = transfer.modal_responses(z0, sp, ms)[0]
            norm = (q0 @ tip) / (q0 @ c)

            def h(z: np.ndarray, sp=sp, ms=ms, c=c, tip=tip, norm=norm) -> np.ndarray:
                q = transfer.modal_responses(z, sp, ms)
                with np.errstate(divide="ignore", invalid="ignore"):
                    out = norm * (q @ c) / (q @ tip)
                return np.where(np.isfinite(out), out, 1.0)

            cache[p] = h
        return cache[p]

    _map_through(s, H, 2.0)


def _through_strip(s: Session, e: dict[int, np.ndarray]) -> tuple[dict[int, np.ndarray], dict[int, np.ndarray]]:
    """The strip's current and displacement answers to an extra drive e (volts per sample, id(record) -> array) the
    monitor does not see: through the preset's admittance and displacement transfer functions at each record's
    pressure, each record preceded by 2 s of the session's e before it and followed by its last value held
    (inject_fresh3._through_x), the zero-frequency bin at the grid's first line (inject.lti)."""
    from labrig.physics import transfer

    def tf(of: Callable) -> Callable[[Rec], Callable[[np.ndarray], np.ndarray]]:
        return lambda r: (lambda z, sp=_spec(s, r): of(z, sp))

    return (_through_x(s, e, tf(transfer.admittance_tf), 2.0, dc_at_first_line=True),
            _through_x(s, e, tf(transfer.displacement_tf), 2.0, dc_at_first_line=True))


def _late_by(r: Rec, late: np.ndarray) -> np.ndarray:
    """The record's displacement read ``late`` seconds late, sample by sample (interpolated, the first value held
    before the record's start)."""
    t, d = r.cols["t_s"], r.cols["disp_m"]
    return np.interp(t - late, t, d, left=d[0])


def _static_map(s: Session, yg: np.ndarray, dg: np.ndarray) -> None:
    """A static reading map tabulated as (reading yg, linear bend dg), both increasing: every displacement sample read
    through it (interpolated; slope 1 at rest by construction of the caller)."""
    map_disp(s, lambda r, d: np.interp(d, dg, yg))


# ------------------------------------------------------------------------------------------------ back relaxation


def br_self_stirred_layer(s: Session) -> None:
    """A strip whose back-flow is exchanged with the bath through its faces (the cathode side giving its excess up,
    the anode side drawing water back) across the still cuvette's unstirred layer, which the strip's own motion
    thins: the layer's thickness falls as the flow past the faces grows (a laminar boundary layer, delta ~ U^-1/2),
    so the exchange's time constant tau = tau_0 / sqrt(1 + U/U_c) (tau_0 4-15 s, log, in the still bath; K2 0.5-0.9),
    U the tip's speed averaged over the layer's renewal time t_r (1-4 s, log; the speed read off the displacement's
    signal), U_c 0.05-0.2 of the session's largest averaged speed. The steps' edges and the fast
    sines stir it, the slow records and the rests let it settle. Through inject_fresh10._lag_varying (sample by
    sample through the session, carried over the rests); displacement only. Measured (paper_169: tau_0 14.6 s, t_r
    2.6 s, U_c 0.19 of the largest averaged speed, K2 0.89: tau 5.8-14.6 s) displacement RMS -58 % (residual 77 %,
    4700x its noise): the 1 V steps at 2.94 mm by their plateaus' end (8.82-8.83 mm clean) and 0.63 mm 2 s after
    their fall (6.64 mm clean); the 0.1 Hz harmonics' gain 0.96 (+7.2 deg), the 0.45 Hz sines' 1.004 (+2.3 deg), the
    3 Hz ones' +0.5 deg."""
    k2, tau0, t_r = s.rng.uniform(0.5, 0.9), lu(s.rng, 4.0, 15.0), lu(s.rng, 1.0, 4.0)
    c_u = s.rng.uniform(0.05, 0.2)
    tu, uu = _smooth_speed(s, t_r)
    u_c = max(c_u * float(np.max(uu)), 1e-12)

    def state(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        u = np.interp(np.asarray(t, float), tu, uu)
        return np.full(u.shape, k2), tau0 / np.sqrt(1.0 + u / u_c)

    _lag_varying(s, state)


def br_gravity_perfusion(s: Session) -> None:
    """A flow cell perfused from a gravity-fed bottle on a shelf above it (the lab's way to keep the bath fresh
    without a pump), refilled by the operator 0-300 s before the first record and again at each re-clamping (0-60 s
    before the setting): the flow through the cell's fixed resistance follows the head, which falls as the bottle
    drains, exp(-u/tau_d) (tau_d 15-60 min, log: laminar outflow), so the flow past the strip and with it the
    exchange of its back-flow across the faces' boundary layer (delta ~ U^-1/2) slow through each block: tau = tau_s
    / sqrt(1 + q0 h(t)) (tau_s 5-15 s, log, in still water; q0 3-15, log, the full head's flow over the layer's
    scale; K2 0.5-0.9). Through inject_fresh10._lag_varying (sample by sample through the session, carried over the
    rests); displacement only. Measured (p12_171: tau_s 6.3 s, q0 13.7, tau_d 20 min, K2 0.65: tau 1.6 s at a full
    bottle, 2.4 s by a block's end) displacement RMS -61 % (residual 64 %, 590x its noise): the 1 V steps at 0.54 mm
    by their plateaus' end (1.46 mm clean) and 0.26 mm 2 s after their fall (1.05 mm clean); the 0.1 Hz harmonics'
    gain 0.77-0.79 (+23 deg), the 0.45 Hz sines' 0.98 (+6 deg)."""
    k2, tau_s, q0 = s.rng.uniform(0.5, 0.9), lu(s.rng, 5.0, 15.0), lu(s.rng, 3.0, 15.0)
    tau_d = lu(s.rng, 900.0, 3600.0)
    fills = [s.t0 - s.rng.uniform(0.0, 300.0)] + [ts - s.rng.uniform(0.0, 60.0) for ts, _ in _settings(s)[1:]]
    fills = np.sort(np.array(fills))

    def state(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        t = np.asarray(t, float)
        k = np.clip(np.searchsorted(fills, t, side="right") - 1, 0, None)
        h = np.exp(-np.clip(t - fills[k], 0.0, None) / tau_d)
        return np.full(t.shape, k2), tau_s / np.sqrt(1.0 + q0 * h)

    _lag_varying(s, state)


# ------------------------------------------------------------------------------------------------ faradaic current


def far_silver_contact_chloriding(s: Session) -> None:
    """One jaw's contact pad silver-plated (the other gold), wetted by a tap-water bath (its chloride): while that
    face is the anode beyond E_ox (0.2-0.4 V of drive, width b 0.02-0.05 V) the wetted silver turns to silver
    chloride by nucleation and growth (Avrami, n 2-3: the converted share X = 1 - exp(-z^n), z growing at k0 =
    1/tau_n, tau_n 0.5-3 s, log), Q 0.05-0.2 mC (log) of it, and while the face is the cathode beyond E_r (0.1-0.3 V)
    the chloride is reduced back (first order, tau_r 0.05-0.5 s, log; a thousandth left as the next growth's nuclei).
    A faradaic current in the drive's direction: the first growth after a reduction delayed (the nuclei must grow),
    nothing on a held plateau once converted, and a grown film partly reduced and re-oxidised on every swing.
    Charge-conserving sample by sample through the session in time order (the film kept over the rests); the current
    only. Measured (paper_169: the silver on the face a negative drive makes the anode, Q 0.19 mC, tau_n 0.55 s, n
    2.65, E_ox 0.30 V, E_r 0.22 V) current RMS +3.5 % (residual 4.4 %, 3.4x its noise): each 1 V step but the first
    reduces the chloride the negative swings before it made, 93 uC on its plateau (+0.31 mA at its edge); once the
    film has grown, its partial reduction and re-oxidation on every swing: the current's gain 1.03-1.08 at 0.1 Hz,
    1.06 at 0.45 Hz, 1.03 at 20 Hz (+-0.3-0.4 mA)."""
    side, n = _sign(s), s.rng.uniform(2.0, 3.0)
    e_ox, e_r, b = s.rng.uniform(0.2, 0.4), s.rng.uniform(0.1, 0.3), s.rng.uniform(0.02, 0.05)
    k0, kr = 1.0 / lu(s.rng, 0.5, 3.0), 1.0 / lu(s.rng, 0.05, 0.5)
    q = lu(s.rng, 5e-5, 2e-4)
    x_min = 1e-3
    f_ox, f_r = float(_logistic(np.array([-e_ox / b]))[0]), float(_logistic(np.array([-e_r / b]))[0])
    x = x_min
    for r in _chrono(s):
        u = side * r.cols["v_V"]
        dt = 1.0 / r.fs
        ko = k0 * np.clip(_logistic((u - e_ox) / b) - f_ox, 0.0, None) * dt
        dr = np.exp(-kr * np.clip(_logistic((-u - e_r) / b) - f_r, 0.0, None) * dt)
        out = np.empty(u.size)
        for k, (gk, rk) in enumerate(zip(ko.tolist(), dr.tolist())):
            x_old = x
            if gk > 0.0:
                z = (-math.log1p(-min(x, 1.0 - 1e-15))) ** (1.0 / n) + gk
                x = -math.expm1(-(z**n))
            x = max(x_min, x * rk) if rk < 1.0 else x
            out[k] = side * q * (x - x_old) / dt
        r.cols["i_A"] = r.cols["i_A"] + out


def far_nickel_hydroxide_film(s: Session) -> None:
    """A bath of tap water carrying nickel (0.05-0.3 mg/l leached from a nickel-chrome tap): wherever a face is the
    cathode beyond E_c (0.5-0.8 V of drive, width 0.03-0.06 V) the hydroxide its electrolysis makes precipitates the
    nickel there as Ni(OH)2, so each face's film grows with its own cathodic time (to Q_end 5-30 uC, log, on the face
    that gets most by the session's end), and the film cycles as a battery-type couple (Ni(OH)2 <-> NiOOH) while its
    face is the anode: oxidised above E_ni + h/2 and reduced below E_ni - h/2 (E_ni 0.35-0.6 V, h 0.05-0.15 V, width
    0.02-0.04 V, a kinetic lag of 5-50 ms, log). A pair of redox peaks on the anodic swings that grows through the
    session, one face (the one the steps make the cathode) more than the other. Sample by sample through the session
    in time order (the films kept over the rests); the current only. Measured (p12_171: E_c 0.74 V, Q_end 23 uC, E_ni
    0.41 V, h 0.054 V, lag 17 ms) current RMS +2.2 % (residual 3.7 %, 2.2x its noise): the 1 V harmonics' redox peaks
    31, 66, 94, 125 uA block by block, the 20 Hz sines' current gain 1.011, 1.022, 1.034, 1.044 (peaks up to 1.1 mA
    by the last block)."""
    e_c, w_c, q_end = s.rng.uniform(0.5, 0.8), s.rng.uniform(0.03, 0.06), lu(s.rng, 5e-6, 3e-5)
    e_ni, h, w = s.rng.uniform(0.35, 0.6), s.rng.uniform(0.05, 0.15), s.rng.uniform(0.02, 0.04)
    tau_k = lu(s.rng, 5e-3, 5e-2)
    recs = _chrono(s)
    expo = np.zeros(2)  # each face's cathodic exposure over the session (face A: the anode for v > 0)
    for r in recs:
        v = r.cols["v_V"]
        expo += [float(np.sum(_logistic((-v - e_c) / w_c))) / r.fs, float(np.sum(_logistic((v - e_c) / w_c))) / r.fs]
    rate = q_end / max(float(expo.max()), 1e-9)
    qf, th = np.zeros(2), np.zeros(2)
    for r in recs:
        v, dt = r.cols["v_V"], 1.0 / r.fs
        a = -math.expm1(-dt / tau_k)
        grow = [rate * dt * _logistic((-v - e_c) / w_c), rate * dt * _logistic((v - e_c) / w_c)]
        up = [_logistic((v - e_ni - h / 2) / w), _logistic((-v - e_ni - h / 2) / w)]
        down = [_logistic((v - e_ni + h / 2) / w), _logistic((-v - e_ni + h / 2) / w)]
        out = np.zeros(v.size)
        for f, sgn in ((0, 1.0), (1, -1.0)):
            g, ox, rd = grow[f].tolist(), up[f].tolist(), down[f].tolist()
            qq, tt = float(qf[f]), float(th[f])
            col = np.empty(v.size)
            for k in range(v.size):
                t_old = tt
                if tt < ox[k]:
                    tt += (ox[k] - tt) * a
                elif tt > rd[k]:
                    tt -= (tt - rd[k]) * a
                col[k] = sgn * qq * (tt - t_old) / dt
                qq += g[k]  # new film precipitates reduced (the face is the cathode while it grows)
                tt = tt * (qq - g[k]) / qq if qq > 0 else tt
            qf[f], th[f] = qq, tt
            out += col
        r.cols["i_A"] = r.cols["i_A"] + out


# ------------------------------------------------------------------------------------------------ hysteresis


def _cogged(x: np.ndarray, y: float, a: float, p: float, ph: float) -> tuple[np.ndarray, float]:
    """The tip's position y on the branch it sits on, sample by sample, where the strip's pull k (x - y) balances a
    cogging force periodic in y, y - x + a sin(2 pi y/p + ph) = 0: from the last position the tip slides (overdamped,
    quasi-static) to the first stable root in the direction it is pulled (a fold sends it to the next well). Returns
    the positions and the last one."""
    tw = 2.0 * math.pi / p
    step = p / 64.0
    out = np.empty(x.size)

    def g(yy: float, xx: float) -> float:
        return yy - xx + a * math.sin(tw * yy + ph)

    for k, xk in enumerate(x.tolist()):
        gy = g(y, xk)
        if gy != 0.0:
            d = step if gy < 0.0 else -step
            lo = y
            hi = y + d
            while (g(hi, xk) < 0.0) == (gy < 0.0):
                lo, hi = hi, hi + d
            for _ in range(30):
                mid = 0.5 * (lo + hi)
                if (g(mid, xk) < 0.0) == (gy < 0.0):
                    lo = mid
                else:
                    hi = mid
            y = 0.5 * (lo + hi)
        out[k] = y
    return out, y


def hy_threaded_rod_cogging(s: Session) -> None:
    """A small magnet glued at the tip (left from the magnetic readout the lab uses on other days) runs along the
    stand's threaded steel rod (an M3-M6 thread, pitch p 0.5-1.0 mm) that stands beside the tip's path: the thread's
    teeth cog the magnet, a force periodic in the tip's position, and the strip's own stiffness k pulls the tip
    towards its free bend x: y - x + a sin(2 pi y/p + ph) = 0, a = eta p/(2 pi), eta 1.05-1.6 (over 1: the
    Prandtl-Tomlinson stick-slip, the tip sticking in a tooth's well and slipping to the next as the pull passes its
    crest; ph drawn), the lab's zero at the session's first rest. Rate-independent memory (the branch the tip is on),
    sample by sample through the session in time order, the laser's noise kept on the reading
    (inject_fresh26._split_noise); displacement only. Measured (paper_169: pitch 0.57 mm, eta 1.28: the cogging's
    swing +-0.12 mm) displacement RMS -0.9 % (residual 2.7 %, 160x its noise): the 1 V steps at 8.69 mm by their
    plateaus' end (8.82-8.83 mm clean) and 6.47 mm 2 s after their fall (6.64 mm clean); the 0.45 Hz sines' gain
    1.10-1.12 (-0.8 deg), the 3 Hz ones' 0.93 (-1 to -2 deg), the 9.4 and 20 Hz ones' 0.47 (held in a tooth's well)."""
    p, eta, ph = s.rng.uniform(5e-4, 1e-3), s.rng.uniform(1.05, 1.6), s.rng.uniform(0.0, 2.0 * np.pi)
    a = eta * p / (2.0 * math.pi)
    _, y0 = _cogged(np.zeros(1), 0.0, a, p, ph)
    y = y0
    for r in _chrono(s):
        sig, noise = _split_noise(r)
        out, y = _cogged(sig, y, a, p, ph)
        r.cols["disp_m"] = out - y0 + noise


def hy_carbon_flex_sensor(s: Session) -> None:
    """No laser: a resistive flex sensor (the carbon-ink-on-polyimide strip of maker kits) laminated along the
    strip's face and read through a divider, calibrated against a laser in a slow static sweep (one linear slope each
    way, so its different sensitivity to the two directions is taken out). Its ink's carbon particles lose and remake
    contacts as the film is stretched, a rate-independent memory: a share w 0.2-0.4 of the reading through three
    plays of radii (0.004, 0.015, 0.05) times 0.5-1 of the session's largest bend on the side that stretches the ink
    (drawn) and 0.3-0.6 of that on the side that compresses it (a generalised play, its radius set by the side of the
    bend). The state carried through the session in time order, the sensor's noise the laser's
    (inject_fresh26._split_noise); displacement only. Measured (s001_170: the ink stretched by a negative bend, w
    0.28, radii 11, 41 and 138 um, 0.31 of them on the other side) displacement residual 0.46 % of its RMS (14x its
    noise): the 0.1 Hz sines' gain 0.986 (-1.3 deg), the 0.45 Hz ones' 0.952 (-2.1 deg), the 3 Hz ones' 0.85 (-2.2
    deg), the 9.4 Hz ones' 0.78, the 20 Hz ones' 0.81; the 1 V steps 6 um short at their plateaus' end and 6 um up 2
    s after their fall."""
    big = _largest(s) or ref_disp(s)
    side, w = _sign(s), s.rng.uniform(0.2, 0.4)
    radii = np.array([0.004, 0.015, 0.05]) * s.rng.uniform(0.5, 1.0) * big
    q_c = s.rng.uniform(0.3, 0.6)
    ys = np.zeros(3)
    for r in _chrono(s):
        sig, noise = _split_noise(r)
        scale = np.where(side * sig >= 0.0, 1.0, q_c)
        out = np.empty(sig.size)
        for k, (xk, ck) in enumerate(zip(sig.tolist(), scale.tolist())):
            rr = radii * ck
            ys = np.minimum(np.maximum(ys, xk - rr), xk + rr)
            out[k] = (1.0 - w) * xk + w * float(ys.mean())
        r.cols["disp_m"] = out + noise


# ------------------------------------------------------------------------------------------------ time delay


def td_ldv_autorange(s: Session) -> None:
    """No triangulation: a laser Doppler vibrometer aimed at the tip with its displacement output, its velocity
    decoder on auto-range: the decoder switches to its high velocity range when the tip's speed passes v_hi (0.3-0.6
    of the session's largest, the speed over the decoder's last 5 ms) and back to the low range once the speed has
    stayed below half of that for a hold time (0.2-1 s, log); each range has its own tracking filter, the low range's
    narrower, so the reading is late by tau_lo (2-6 ms, log) on the low range and by tau_hi (0.2-0.8 ms, log) on the
    high one: a delay that shortens while the tip moves fast (the steps' edges, the large fast sines) and lengthens
    when it is slow or still, with the range's hysteresis. Record by record (the decoder on the low range at each
    record's start), the displacement read late by it (interpolated). Measured (paper_169: v_hi 0.32 of the largest
    speed, tau_lo 5.4 ms, tau_hi 0.55 ms, hold 0.22 s) displacement residual 0.084 % of its RMS (5.1x its noise): the
    20 Hz sines -39 deg (5.4 ms), the 9.4 Hz ones -18 deg, the 0.45 Hz ones -0.9 deg, but the 3 Hz ones, at the
    strip's resonance and the fastest of the sines, on the high range, -0.6 deg (0.55 ms); the steps' edges 0.55 ms
    late."""
    frac, hold = s.rng.uniform(0.3, 0.6), lu(s.rng, 0.2, 1.0)
    tau_lo, tau_hi = lu(s.rng, 2e-3, 6e-3), lu(s.rng, 2e-4, 8e-4)
    speed = {}
    for r in s.series():
        sig, _ = _split_noise(r)
        t = r.cols["t_s"]
        n = max(int(round(0.005 * r.fs)), 1)
        v = np.abs(np.gradient(sig, t)) if t.size > 1 else np.zeros(t.size)
        speed[id(r)] = np.convolve(v, np.ones(n) / n)[: v.size]  # the decoder's last 5 ms
    v_hi = frac * max((float(np.max(x)) for x in speed.values() if x.size), default=1.0)
    for r in s.series():
        late = np.empty(r.cols["t_s"].size)
        high, quiet = False, 0.0
        for k, vk in enumerate(speed[id(r)].tolist()):
            if vk > v_hi:
                high, quiet = True, 0.0
            elif high:
                quiet = quiet + 1.0 / r.fs if vk < 0.5 * v_hi else 0.0
                high = quiet < hold
            late[k] = tau_hi if high else tau_lo
        r.cols["disp_m"] = _late_by(r, late)


def td_controller_throttling(s: Session) -> None:
    """The laser controller's processor (its measurement pipeline in firmware) throttles its clock to half when its
    enclosure passes a threshold temperature, and back above it once 1-2 K cooler: the controller, switched on 0-600
    s before the first record on a shelf above the drive amplifier, warms by 8-15 K over tau_w 600-1800 s (log), the
    threshold reached 20-60 % into the session (drawn), the room's air conditioning swinging it by +-0.5-1.5 K
    (period 15-40 min, log) so that the clock may toggle about the threshold. Each reading late by tau_io 0.5-1.5 ms
    plus its processing tau_cpu 2-5 ms (log) over the clock's share: a delay that steps between two values at the
    toggles (a 1 s grid, the relay held through the rests); the displacement read late by it (interpolated). Measured
    (s001_170: tau_io 0.87 ms, tau_cpu 3.2 ms, the threshold crossed 47 % into the session) displacement residual
    0.22 % of its RMS (7.0x its noise): the 20 Hz sines -29.4 deg (4.1 ms) in the first two blocks and -52.6 deg (7.3
    ms) in the last two, the 9.4 Hz ones -13.8 and -24.7 deg."""
    t_on = s.t0 - s.rng.uniform(0.0, 600.0)
    d_t, tau_w = s.rng.uniform(8.0, 15.0), lu(s.rng, 600.0, 1800.0)
    x_thr, hyst = s.rng.uniform(0.2, 0.6), s.rng.uniform(1.0, 2.0)
    amp, per, ph = s.rng.uniform(0.5, 1.5), lu(s.rng, 900.0, 2400.0), s.rng.uniform(0.0, 2.0 * np.pi)
    tau_io, tau_cpu = s.rng.uniform(5e-4, 1.5e-3), lu(s.rng, 2e-3, 5e-3)
    tg = _session_grid(s, 1.0, 2.0)
    warm = d_t * -np.expm1(-(tg - t_on) / tau_w)
    temp = warm + amp * np.sin(2.0 * np.pi * (tg - s.t0) / per + ph)
    t_x = s.t0 + x_thr * (s.t1 - s.t0)
    thr = d_t * -math.expm1(-(t_x - t_on) / tau_w)
    slow = np.zeros(tg.size)
    on = False
    for k, tk in enumerate(temp.tolist()):
        on = tk >= thr if not on else tk > thr - hyst
        slow[k] = 1.0 if on else 0.0
    late_g = tau_io + tau_cpu * (1.0 + slow)
    map_disp(s, lambda r, d: _late_by(r, np.interp(r.cols["t_s"], tg, late_g)))


# ------------------------------------------------------------------------------------------------ sensor offset


def so_capillary_volume_readout(s: Session) -> None:
    """No laser: the strip tested as a micropump's flap, its root sealed in the chamber's wall and its edges running
    in the side walls' slots, the chamber closed but for a glass capillary whose meniscus the lab's camera follows;
    the meniscus reads the volume the flap's face sweeps, w(x) integrated over its length beyond the wall's seal
    (0-0.1 L) (the capillary's bore wide enough for the flow's resistance and inertia to be negligible below 20 Hz),
    calibrated to the tip against a laser once, at rest. Right for the quasi-static bend, whose shape the calibration
    fixed, and otherwise each mode weighed by its shape's integral, not its tip: the zeros move, the poles stay.
    Through the beam's modes (labrig.physics.transfer.modal_responses, shape integrals by Gauss-Legendre on 16 nodes
    of shapes_at) with the session's history (inject_fresh2._map_through); displacement only. Measured (paper_169)
    displacement RMS +0.35 % (residual 0.74 %, 45x its noise): the 1 V steps at 8.86-8.87 mm by their plateaus' end
    (8.82-8.83 mm clean); the 0.1 Hz records' gain 1.020 (+1.0 deg), the 3 Hz sines' 1.20-1.26, the 9.4 Hz ones'
    1.8-2.6 (-29 to -55 deg: the tip's antiresonance between the first two modes is not the volume's), the 20 Hz
    ones' 0.81-0.93 (-128 to -153 deg)."""
    from labrig.physics import transfer

    xg, wg = np.polynomial.legendre.leggauss(16)
    seal = s.rng.uniform(0.0, 0.1)  # the flap's root in the wall's seal sweeps nothing

    def weights(sp) -> np.ndarray:
        length = sp.geometry.length
        span = (1.0 - seal) * length
        x = seal * length + 0.5 * span * (xg + 1.0)
        return (0.5 * span * wg) @ transfer.shapes_at(x, sp)

    _modal_reading(s, weights)


def so_fbg_shape_sensing(s: Session) -> None:
    """No laser: three fibre Bragg gratings in a fibre bonded along the strip's face (a soft-robotics lab's shape
    sensor) at x_1 0.1-0.25 L, x_2 0.4-0.55 L and x_3 0.7-0.85 L, each reading its face's strain, the curvature
    there; the lab's script fits a straight line kappa(x) = a + b x through the three curvatures by least squares and
    integrates it twice to the tip, w(L) = a L^2/2 + b L^3/6, calibrated to a laser once at rest (the quasi-static
    bend's own curvature profile, which the line does not quite follow, taken out). Each mode weighed by its fitted
    curvature's integral, not its tip: the zeros move, the poles stay. Through the beam's modes
    (labrig.physics.transfer.modal_responses, the shapes' curvature by a central difference of shapes_at over 0.01 L)
    with the session's history (inject_fresh2._map_through); displacement only. Measured (s001_170: the gratings at
    0.20, 0.40 and 0.72 L) displacement RMS -0.09 % (residual 0.24 %, 7.6x its noise): the 0.1 Hz records' gain 0.995
    (-0.3 deg), the 3 Hz sines' 0.957 (-1.8 deg), the 9.4 Hz ones' 0.88-0.89, the 20 Hz ones' 0.66-0.73 (+0.5 to +2.2
    deg)."""
    from labrig.physics import transfer

    xs = np.array([s.rng.uniform(0.1, 0.25), s.rng.uniform(0.4, 0.55), s.rng.uniform(0.7, 0.85)])

    def weights(sp) -> np.ndarray:
        length = sp.geometry.length
        x, hx = xs * length, 0.01 * length
        shape = transfer.shapes_at
        kap = (shape(x + hx, sp) - 2.0 * shape(x, sp) + shape(x - hx, sp)) / hx**2
        fit = np.linalg.pinv(np.column_stack([np.ones(3), x]))  # (2, 3): kappa values -> (a, b)
        tip = np.array([length**2 / 2.0, length**3 / 6.0]) @ fit
        return tip @ kap

    _modal_reading(s, weights)


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_water_ballast_lever(s: Session) -> None:
    """A dead-weight lever clamp (the jaw on a lever whose far arm carries a plastic bottle as its adjustable
    weight): at each setting the operator fills the bottle until the load cell shows the force (a dead weight keeps
    it whatever the pads do), but the bottle's cap seeps, so the water drains by Torricelli's law through the leak,
    sqrt(h) falling linearly: the force relative to its setting (1 - u/T_e)^2, T_e the time to empty, which grows as
    the square root of the setting's height, T_e = T_min sqrt(p/p_min) (T_min 4-16 h, log, at the lightest setting):
    the light settings lose the larger share. From each setting (inject_fresh25._setting_of) through the preset's
    clamp law (inject_fresh4._clamp_law), the load cell showing it. Measured (s001_170: T_min 12.1 h) the load cell
    at 0.965, 0.974, 0.980, 0.983 of its setting by the blocks' last records; displacement residual 0.003 % of its
    RMS (0.10x its noise: the seed-001 strip's clamp law moves its bend little), current 0.07 % (0.20x)."""
    t_min = lu(s.rng, 4 * 3600.0, 16 * 3600.0)
    setting = _setting_of(s)
    p_min = min(s.pressures())

    def rel(t: np.ndarray, p: float, t_first: float) -> np.ndarray:
        u = np.clip(np.asarray(t, float) - setting(p, t_first), 0.0, None)
        return np.clip(1.0 - u / (t_min * math.sqrt(p / p_min)), 0.0, None) ** 2

    _clamp_law(s, rel)


def cr_thermal_ratchet_thread(s: Session) -> None:
    """A screw clamp whose steel screw runs in an aluminium frame, the room's air conditioning cycling its
    temperature by +-0.5-1.5 K (period 15-40 min, log, phase drawn): the two metals' differential expansion moves the
    preload reversibly, -c_r dT (c_r 1-3 %/K), and each warming stroke lets the loaded thread slip back a little
    (thermal ratcheting, the self-loosening of bolted joints under temperature cycles), a loss c_l (1-3 %, of the
    setting per full cycle's warming) that the cooling does not return: the force relative to its setting 1 - c_r (T
    - T_set) - c_l R/(2 A), R the warming since the setting (the integral of the temperature's rises). From each
    setting (inject_fresh25._setting_of) through the preset's clamp law (inject_fresh4._clamp_law), the load cell
    showing it. Measured (p12_171: +-1.25 K over 15 min, c_r 2.6 %/K, c_l 1.6 %) the load cell at 1.010, 1.013,
    0.992, 0.956 of its setting by the blocks' last records (the reversible part up and down, the ratchet's loss
    adding up); displacement residual 0.14 % of its RMS (1.3x its noise: the 20 Hz sines, at the 12 mm strip's
    resonance, +18 deg in the last block), current 0.34 % (0.21x)."""
    amp, per, ph = s.rng.uniform(0.5, 1.5), lu(s.rng, 900.0, 2400.0), s.rng.uniform(0.0, 2.0 * np.pi)
    c_r, c_l = s.rng.uniform(0.01, 0.03), s.rng.uniform(0.01, 0.03)
    setting = _setting_of(s)
    w = 2.0 * math.pi / per

    def temp(t: np.ndarray) -> np.ndarray:
        return amp * np.sin(w * (np.asarray(t, float) - s.t0) + ph)

    def warmed(t: np.ndarray) -> np.ndarray:
        """The integral of max(dT/dt, 0) from the session's start (a 1 s grid, interpolated)."""
        tg = _session_grid(s, 1.0, 1200.0)
        rise = np.r_[0.0, np.cumsum(np.clip(np.diff(temp(tg)), 0.0, None))]
        return np.interp(np.asarray(t, float), tg, rise)

    def rel(t: np.ndarray, p: float, t_first: float) -> np.ndarray:
        ts = np.array([setting(p, t_first)])
        return 1.0 - c_r * (temp(t) - temp(ts)) - c_l * np.clip(warmed(t) - warmed(ts), 0.0, None) / (2.0 * amp)

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_ac_reevaporation(s: Session) -> None:
    """A strip in air in a room cooled by a split air conditioner with its fan left running: the compressor cycles
    (on 5-15 min, off 5-15 min, log, phase drawn), and while it runs the cold coil condenses the room's water (the
    room's humidity relaxing towards a drier level, 0.08-0.2 below where it was, over the room's air change, 5-15
    min, log), some of it held on the coil (a share 0.3-0.7), which the fan blows back into the room after each stop
    (re-evaporating over 2-6 min, log): the humidity falls through the session in a sawtooth, a dip with each run and
    a burst after each stop. The conditioner switched on 0-20 min before the first record, the strip mounted then;
    its water follows its air's humidity through sorption (k 0.8-1.5 of the mobile water per unit of RH, a lag tau_s
    200-800 s, log, on a 1 s grid). Gain x (1 - loss), conductance x (1 - share loss) (share 0.3-1); the spectra at
    the next series' start (inject_fresh9._dry_by). Measured (s001_170: on 6.4 min and off 12.1 min, d_rh 0.12, held
    0.42, the room's air change 9.2 min, the coil's water back over 4.6 min, tau_s 4.7 min, the conditioner on 5 min
    before the first record) displacement RMS -4.3 % (residual 4.4 %, 140x its noise), current RMS -2.0 % (residual
    2.1 %, 5.8x its noise): the 1 V steps at 4.56, 4.47, 4.47, 4.51 mm by their plateaus' end block by block
    (4.69-4.72 mm clean); the impedance 1.017, 1.032, 1.031, 1.026x in the blocks' spectra."""
    t_on, t_off, ph = lu(s.rng, 300.0, 900.0), lu(s.rng, 300.0, 900.0), s.rng.uniform(0.0, 1.0)
    d_rh, tau_x, held = s.rng.uniform(0.08, 0.2), lu(s.rng, 300.0, 900.0), s.rng.uniform(0.3, 0.7)
    tau_e, k_iso, tau_s = lu(s.rng, 120.0, 360.0), s.rng.uniform(0.8, 1.5), lu(s.rng, 200.0, 800.0)
    share, lead = s.rng.uniform(0.3, 1.0), s.rng.uniform(0.0, 1200.0)
    tg = _session_grid(s, 1.0, lead)  # the conditioner switched on 0-20 min before the first record, the strip mounted
    cyc = t_on + t_off
    running = ((tg - tg[0]) / cyc + ph) % 1.0 < t_on / cyc
    deficit, coil = 0.0, 0.0  # the room's humidity below its level at the start, and the coil's water (RH units)
    dry = np.empty(tg.size)
    for k, on in enumerate(running.tolist()):
        if on:  # the coil condenses, the room relaxing towards d_rh below the start; a share of the water stays on it
            cond = (d_rh - deficit) / tau_x
            deficit += cond
            coil += held * max(cond, 0.0)
        else:  # the room's own sources bring its humidity back, and the fan blows the coil's water off
            back = coil / tau_e
            coil -= back
            deficit += -deficit / tau_x - back
        dry[k] = deficit
    loss = _grid_lag(k_iso * dry, 1.0, tau_s)

    def f(t: np.ndarray) -> np.ndarray:
        return np.interp(np.asarray(t, float), tg, loss)

    _dry_by(s, f, lambda t: share * f(t))


def dh_fenton_ionomer_attack(s: Session) -> None:
    """A strip cleaned in 3 % hydrogen peroxide (a lab's routine for platinum before a bio test) and rinsed too
    briefly, mounted 60-600 s before the first record in a bath its steel clamp screw slowly gives iron to (its
    ferrous ions growing linearly from the mounting): the iron catalyses the peroxide left in the membrane into
    hydroxyl radicals (Fenton), which cut the ionomer's side chains and take its sulfonate sites, and with them its
    water and its mobile ions, for good; the peroxide is itself used up and decomposed on the platinum, exp(-u/tau_p)
    (tau_p 600-2400 s, log). The sites lost follow the attack's integral, Fe x H2O2, 1 - (1 + x) exp(-x), x = u/tau_p
    (slow at first, then saturating), to L 5-15 % of the gain by its end (the conductance 0.3-1 of that: the
    remaining sites' ions move as before). Gain x (1 - loss), conductance x (1 - share loss); the spectra at the next
    series' start (inject_fresh9._dry_by). Measured (p12_171: mounted 80 s before the first record, tau_p 30 min, L
    11 %, share 0.57) displacement RMS -2.9 % (residual 3.8 %, 35x its noise), current RMS -2.2 % (residual 2.6 %,
    1.6x its noise): the 1 V steps at 1.457, 1.437, 1.401, 1.369 mm by their plateaus' end block by block
    (1.458-1.459 mm clean); the impedance 1.000, 1.008, 1.023, 1.036x in the blocks' spectra."""
    t_m, tau_p = s.t0 - s.rng.uniform(60.0, 600.0), lu(s.rng, 600.0, 2400.0)
    big, share = s.rng.uniform(0.05, 0.15), s.rng.uniform(0.3, 1.0)

    def loss(t: np.ndarray) -> np.ndarray:
        x = np.clip(np.asarray(t, float) - t_m, 0.0, None) / tau_p
        return big * (1.0 - (1.0 + x) * np.exp(-x))

    _dry_by(s, loss, lambda t: share * loss(t))


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_cathodic_scale_wedging(s: Session) -> None:
    """A strip in a hard tap-water bath whose plating is mud-cracked on both faces (its cracks opening beyond e0,
    0.05-0.2 of the session's displacement scale, dR/R = k (opening) on the face the bend stretches, k 0.3-0.6, the
    other face 0.5-1 of it): the face the bend stretches under a positive drive is also its cathode, and beyond E_c
    (0.5-0.8 V of drive, width 0.03-0.06 V) its electrolysis makes hydroxide that precipitates the bath's calcium and
    magnesium (calcareous scale) inside its open cracks, in proportion to their opening: the scale wedges them, so
    they can no longer close below its thickness w (growing with the cathodic time spent open, to 0.1-0.3 of the
    scale on the face that gets most by the session's end), each face on its own cathodic excursions. The cracks'
    opening max(e - e0, w): a resistance that rises stepwise through the session and no longer vanishes at rest.
    Gains fall by 0.03-0.08 (displacement) and 0.06-0.15 (current) per unit of dR/R (inject_fresh3._resist). Measured
    (p12_171: k 0.42, e0 0.19, E_c 0.57 V, the wedge to 0.24) displacement RMS -3.8 % (residual 4.0 %, 37x its
    noise), current RMS -0.7 % (residual 1.5 %, 0.91x its noise): the 1 V steps at 1.38 mm by their plateaus' end
    (1.46 mm clean); the 0.45 Hz sines' gain 0.999, 0.998, 0.997, 0.996 block by block (the wedged cracks' resistance
    at the small bends, growing)."""
    ref = ref_disp(s)
    k, o, e0 = s.rng.uniform(0.3, 0.6), s.rng.uniform(0.5, 1.0), s.rng.uniform(0.05, 0.2)
    e_c, w_c, w_end = s.rng.uniform(0.5, 0.8), s.rng.uniform(0.03, 0.06), s.rng.uniform(0.1, 0.3)
    recs = _chrono(s)
    grow = {}
    for r in recs:  # each face's exposure per sample: its opening while it is the cathode beyond E_c
        sig, _ = _split_noise(r)
        e, v = sig / ref, r.cols["v_V"]
        grow[id(r)] = (np.clip(e - e0, 0.0, None) * _logistic((v - e_c) / w_c) / r.fs,
                       np.clip(-e - e0, 0.0, None) * _logistic((-v - e_c) / w_c) / r.fs)
    total = np.array([sum(float(np.sum(g[f])) for g in grow.values()) for f in (0, 1)])
    rate = w_end / max(float(total.max()), 1e-12)
    wedge, so_far = {}, np.zeros(2)
    for r in recs:
        ga, gb = grow[id(r)]
        wa, wb = so_far[0] + rate * np.cumsum(ga), so_far[1] + rate * np.cumsum(gb)
        wedge[id(r)] = (wa, wb)
        so_far = np.array([wa[-1], wb[-1]]) if wa.size else so_far

    def law(r: Rec, e: np.ndarray) -> np.ndarray:
        wa, wb = wedge[id(r)]
        return k * (np.maximum(np.clip(e - e0, 0.0, None), wa) + o * np.maximum(np.clip(-e - e0, 0.0, None), wb))

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


def sr_pump_fretted_bridges(s: Session) -> None:
    """A strip whose plating is mud-cracked on both faces (cracks opening beyond e0, 0.1-0.3 of the session's
    displacement scale, dR/R = k ((e - e0)+ + o (-e - e0)+), k 0.15-0.4, the other face o 0.5-1 of it), the cracks'
    metal bridges touching: a rotary vane vacuum pump on the same bench (a colleague's desiccator or filtration) runs
    in 2-4 spells of 5-20 min (log, each starting inside a recorded series), and its vibration frets the bridges'
    contacts: while it runs their contact resistance is up (the gauge x 1 + g_r, g_r 0.1-0.4), and the wear stays
    (the gauge growing with the pump's running time so far, to x 1 + g_w, g_w 0.3-1, by its last spell's end). Gains
    fall by 0.03-0.08 (displacement) and 0.06-0.15 (current) per unit of dR/R (inject_fresh3._resist), the gauge per
    sample. Measured (s001_170: two spells of 15 min, from the 900 kPa block's 0.66 Hz sine and the 1300 kPa block's
    6.4 Hz one; k 0.39, e0 0.11, g_r 0.16, g_w 0.71) displacement RMS -7.4 % (residual 8.0 %, 250x its noise),
    current RMS -1.4 % (residual 4.7 %, 13x its noise): the 1 V steps at 4.30, 4.32, 4.16, 4.05 mm by their plateaus'
    end block by block (4.69-4.72 mm clean); 40 of the 68 series touched (the small sines open no crack)."""
    k, o, e0 = s.rng.uniform(0.15, 0.4), s.rng.uniform(0.5, 1.0), s.rng.uniform(0.1, 0.3)
    g_r, g_w = s.rng.uniform(0.1, 0.4), s.rng.uniform(0.3, 1.0)
    spells = _bursts(s, int(s.rng.integers(2, 5)), (300.0, 1200.0))
    tg, on = _on_grid(s, spells)
    worn = np.cumsum(on)
    worn = worn / max(float(worn[-1]), 1e-12)

    def law(r: Rec, e: np.ndarray) -> np.ndarray:
        t = r.cols["t_s"]
        gauge = k * (1.0 + g_w * np.interp(t, tg, worn) + g_r * np.interp(t, tg, on))
        return gauge * (np.clip(e - e0, 0.0, None) + o * np.clip(-e - e0, 0.0, None))

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_zener_input_clamp(s: Session) -> None:
    """The laser's analogue output (2 mm/V) read on a DAQ terminal block whose inputs the lab protected with
    back-to-back low-voltage Zener diodes to ground (a clamp for a +-5 V card), the laser's output resistance R_o
    100-470 Ohm (log) in series: a low-voltage Zener breaks down by tunnelling, with a soft knee, I = 5 mA exp((|V| -
    V_c)/V_k) (V_c, the pair's voltage at 5 mA, 1.05-1.3 times the session's largest reading; V_k 0.12-0.25 V), so
    the largest readings lose R_o I to the clamp: the reading V = V_L - R_o I(V), odd, compressive at the top,
    nothing at the small ones. Tabulated and interpolated (slope 1 at rest); displacement only. Measured (paper_169:
    V_c 4.83 V, V_k 0.25 V, R_o 470 Ohm) displacement RMS -0.9 % (residual 1.5 %, 93x its noise): the 1 V steps at
    8.43 mm by their plateaus' end (8.82-8.83 mm clean), 10 um short 2 s after their fall; the sines within 0.01 %."""
    big = _largest(s) or ref_disp(s)
    v_top = big / LASER_M_PER_V
    v_c, v_k, r_o = s.rng.uniform(1.05, 1.3) * v_top, s.rng.uniform(0.12, 0.25), lu(s.rng, 100.0, 470.0)
    vr = np.linspace(-2.0 * v_top, 2.0 * v_top, 8001)
    vl = vr + r_o * np.sign(vr) * 5e-3 * (np.exp((np.abs(vr) - v_c) / v_k) - math.exp(-v_c / v_k))
    _static_map(s, vr * LASER_M_PER_V, vl * LASER_M_PER_V)


def ld_slack_root_sleeve(s: Session) -> None:
    """A loose silicone sleeve (a length of tubing, or heat-shrink never shrunk, slid over the root to keep the jaws'
    edge off the plating) over the strip's first l_s (0.1-0.25 L) beyond the clamp: with its clearance it does not
    touch the strip at small bends, but beyond the curvature at which the bent strip's faces meet its wall (that of a
    bend of 0.3-0.6 of the session's largest, uniform curvature) the sleeve bends with it and resists, its stiffness
    a share beta 0.2-0.6 of the strip's there (a smooth contact, a knee 0.1 of that curvature wide): the root's
    curvature grows by 1/(1 + beta) of the excess, the rest of the strip as before, w(L) = kappa_s l_s (L - l_s/2) +
    kappa (L - l_s)^2/2. Odd, compressing the large bends from a knee. Tabulated and interpolated (slope 1 at rest);
    displacement only. Measured (p12_171: l_s 0.19 L, the knee at 0.35 of the largest bend, beta 0.58) displacement
    RMS -5.8 % (residual 6.3 %, 59x its noise): the 1 V steps at 1.34 mm by their plateaus' end (1.46 mm clean) and
    0.98 mm 2 s after their fall (1.05 mm clean); the 1 V harmonics' gain 0.974, the 0.5 V sines within 0.01 %."""
    big = _largest(s) or ref_disp(s)
    length = float(s.specimen["length_m"])
    l_s, c_c, beta = s.rng.uniform(0.1, 0.25) * length, s.rng.uniform(0.3, 0.6), s.rng.uniform(0.2, 0.6)
    dg = np.linspace(-2.0 * big, 2.0 * big, 8001)
    kap, k_c = 2.0 * dg / length**2, 2.0 * c_c * big / length**2
    wid = 0.1 * k_c
    excess = wid * (np.logaddexp(0.0, (np.abs(kap) - k_c) / wid) - np.logaddexp(0.0, -k_c / wid))
    kap_s = np.sign(kap) * (np.abs(kap) - excess * beta / (1.0 + beta))
    yg = kap_s * l_s * (length - l_s / 2.0) + kap * (length - l_s) ** 2 / 2.0
    yg = yg / ((yg[4001] - yg[3999]) / (dg[4001] - dg[3999]))  # the lab's calibration at rest
    _static_map(s, yg, dg)


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_dimmed_led_lights(s: Session) -> None:
    """The lab's LED ceiling lamps on a leading-edge (triac) dimmer, which the operator turns down at one re-clamping
    after the first (drawn; 0-60 s before the setting: the laser's receiver saw the lamps' glare) and leaves: the
    triac fires at the phase alpha (60-130 deg) of each half cycle into the LED drivers' input capacitors, which take
    a narrow charging spike (tau_c 50-300 us, log) at each firing, of alternating sign; the spikes' field in the
    bench's wiring reaches the laser's cable (1.5-5 um, log) and the current amplifier's input (10-40 uA, log) at
    each odd harmonic of the line (50 or 60 Hz, inject_fresh12._line_f) up to the 15th with the spikes' spectrum,
    exp(-(n sigma)^2/2) (sigma = 2 pi f tau_c), phase n (w t - alpha), as the DAQ samples them (aliased where the
    rate is low). Nothing before the dimming (the lamps' own drivers filtered at full power). Displacement and
    current. Measured (paper_169: 50 Hz, dimmed at the 3062 kPa setting, alpha 110 deg, tau_c 150 us, 1.6 um and 19
    uA a harmonic) displacement residual 0.066 % of its RMS (4.0x its noise), current residual 0.72 % (0.54x its
    noise): the last two blocks' 34 series touched."""
    f0 = _line_f(s)
    _, t_set = _later_setting(s)
    t_dim = t_set - s.rng.uniform(0.0, 60.0)
    alpha, tau_c = np.deg2rad(s.rng.uniform(60.0, 130.0)), lu(s.rng, 5e-5, 3e-4)
    amp = {"disp_m": lu(s.rng, 1.5e-6, 5e-6), "i_A": lu(s.rng, 1e-5, 4e-5)}
    phase = {col: s.rng.uniform(0.0, 2.0 * np.pi) for col in amp}
    sigma = 2.0 * np.pi * f0 * tau_c
    orders = np.arange(1, 16, 2)
    weights = np.exp(-0.5 * (orders * sigma) ** 2)
    for r in s.series():
        t = r.cols["t_s"]
        on = np.clip((t - t_dim) / 0.5, 0.0, 1.0)  # the dimmer's knob turned over half a second
        if not np.any(on):
            continue
        for col, a_ in amp.items():
            w = 2.0 * np.pi * f0 * t + phase[col]
            wave = sum(wn * np.cos(n * (w - alpha)) for n, wn in zip(orders.tolist(), weights.tolist()))
            r.cols[col] = r.cols[col] + a_ * on * wave


def mp_ac_ionizer_bar(s: Session) -> None:
    """An AC static eliminator (an ionising bar of the kind labs keep against static on plastics: emitter pins at 7
    kV from a mains step-up transformer) that the operator switches on at 1-2 re-clampings (drawn; 0-30 s before the
    setting, to neutralise the strip in air and the cuvette's plastic after handling them) and leaves on for 10-40
    min (log): the bar's high voltage at the line reaches the laser's cable (2-6 um, log) and the current amplifier's
    input (10-40 uA, log) capacitively, with the pins' corona current pulses near the voltage's peaks, which differ
    between the half cycles (a glow corona on the positive, Trichel pulses on the negative): odd harmonics (3rd
    0.2-0.4, 5th 0.1-0.2) and even ones from the asymmetry (2nd 0.1-0.3, 4th 0.05-0.12), phases drawn, at the line
    (50 or 60 Hz, inject_fresh12._line_f). Displacement and current, while it is on (1 s edges). Measured (s001_170:
    60 Hz, on from the 1300 kPa setting for 36 min, 5.9 um and 19 uA at the fundamental) displacement residual 0.18 %
    of its RMS (5.6x its noise), current residual 0.37 % (0.99x its noise): 34 of the 68 series touched."""
    f0 = _line_f(s)
    sets = _settings(s)
    n_on = min(int(s.rng.integers(1, 3)), len(sets))
    picks = sorted(s.rng.choice(len(sets), size=n_on, replace=False).tolist())
    spells = []
    for k in picks:
        a = sets[k][0] - s.rng.uniform(0.0, 30.0)
        spells.append((a, a + lu(s.rng, 600.0, 2400.0)))
    harm = {2: s.rng.uniform(0.1, 0.3), 3: s.rng.uniform(0.2, 0.4), 4: s.rng.uniform(0.05, 0.12),
            5: s.rng.uniform(0.1, 0.2)}
    amp = {"disp_m": lu(s.rng, 2e-6, 6e-6), "i_A": lu(s.rng, 1e-5, 4e-5)}
    phase = {col: s.rng.uniform(0.0, 2.0 * np.pi, 6) for col in amp}
    for r in s.series():
        t = r.cols["t_s"]
        on = np.zeros(t.size)
        for a, b in spells:
            on = np.maximum(on, np.clip(np.minimum(t - a, b - t), 0.0, 1.0))
        if not np.any(on):
            continue
        for col, a_ in amp.items():
            w = 2.0 * np.pi * f0 * t
            wave = np.cos(w + phase[col][0]) + sum(hn * np.cos(n * w + phase[col][n]) for n, hn in harm.items())
            r.cols[col] = r.cols[col] + a_ * on * wave


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_negative_imag_spectra(s: Session) -> None:
    """The impedance analyser's software exports Z' and -Z'' (the columns of a Nyquist plot, as many EIS packages
    write them), and the lab's conversion script copies them into z_re_ohm and z_im_ohm as they come: every
    spectrum's imaginary part with the wrong sign, a capacitive strip reading as an inductive one (|Z| unchanged, the
    phase mirrored). The time series untouched. Measured (paper_169 and s001_170) every spectrum's phase mirrored
    (its median -14.9 deg to +14.9 deg, and -7.1 to +7.1 deg), |Z| unchanged; no time series touched."""
    for r in s.recs:
        if not r.series:
            r.cols["z_im_ohm"] = -r.cols["z_im_ohm"]


def out_dsp_amp_requantised(s: Session) -> None:
    """The drive amplifier a compact DSP class-D module whose input converter re-quantises the command (its ADC's
    code LSB 4-12 mV, log: 9 to 11 bits over its input range, rounding to the nearest code), the monitor v_V taken at
    the module's input: the strip is driven by a staircase of the logged drive, each code step a small voltage step
    the strip's admittance answers with a current spike (LSB over the series resistance) and a little bend,
    unmonitored. The error e = Q(v) - v (v the drive's signal, inject_fresh26._split_noise) through the preset's
    admittance and displacement transfer functions at each record's pressure with the session's history (2 s);
    current and displacement. Measured (s001_170: LSB 8.5 mV; p12_171: 5.9 mV) current residual 1.2 % of its RMS in
    both (3.4x and 0.75x its noise), displacement 0.10 % and 0.11 % (3.2x and 1.0x its noise)."""
    lsb = lu(s.rng, 4e-3, 1.2e-2)
    e = {}
    for r in s.series():
        v, _ = _split_noise(r, "v_V")
        e[id(r)] = np.round(v / lsb) * lsb - v
    di, dd = _through_strip(s, e)
    for r in s.series():
        r.cols["i_A"] = r.cols["i_A"] + di[id(r)]
        r.cols["disp_m"] = r.cols["disp_m"] + dd[id(r)]


def out_eddy_damped_magnet(s: Session) -> None:
    """A small magnet glued at the tip (left from another day's magnetic readout) beside the clamp stand's aluminium
    block, on one side (drawn) at a gap g0 1.5-3 times the session's largest bend: the block's eddy currents brake
    the magnet, a force against its velocity growing steeply as it nears the block, c (g0/(g0 - y))^4, its share of
    the first mode's damping dzeta 0.03-0.12 at rest. Through the first mode (labrig.physics.transfer.modal_set at
    each record's pressure): the extra damping at rest exactly (the mode's ratio, inject_fresh2._map_through), the
    gap's part to first order (inject_fresh3._through_x on the damping force), the laser's noise kept. Neither a
    delay nor a gain: the resonance flattened, more on one side. Displacement only. Measured (paper_169: the gap 1.9
    largest bends, dzeta 0.10; p12_171: 2.7, 0.11) displacement residual 0.80 % and 0.40 % of its RMS (49x and 3.8x
    its noise): on the paper strip the 3 Hz sines (its first mode at 3.3 Hz) at gain 0.67-0.80 (-10 to -14 deg) and
    the 9.4 Hz ones +5 deg; on the 12 mm strip the 20 Hz sines (20.6 Hz) at 0.51-0.72 (-8 to -20 deg); the steps 20
    um short at their plateaus' end on the paper strip."""
    from labrig.physics import transfer

    big = _largest(s) or ref_disp(s)
    side, g0, dz = _sign(s), s.rng.uniform(1.5, 3.0) * big, s.rng.uniform(0.03, 0.12)
    modes: dict[float, tuple[float, float]] = {}

    def mode(r: Rec) -> tuple[float, float]:
        p = float(r.entry["pressure_kPa"])
        if p not in modes:
            ms = transfer.modal_set(_spec(s, r))
            modes[p] = (float(ms.omega[0]), float(ms.xi[0]))
        return modes[p]

    def ratio(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        w1, z1 = mode(r)
        return lambda z: (1.0 + 2.0 * z1 * z / w1 + (z / w1) ** 2) / (1.0 + 2.0 * (z1 + dz) * z / w1 + (z / w1) ** 2)

    def damped(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        w1, z1 = mode(r)
        return lambda z: 1.0 / (1.0 + 2.0 * (z1 + dz) * z / w1 + (z / w1) ** 2)

    _map_through(s, ratio, 2.0)
    force = {}
    for r in s.series():
        sig, _ = _split_noise(r)
        w1, _ = mode(r)
        gap = np.clip(1.0 - side * sig / g0, 0.05, None)
        force[id(r)] = -(2.0 * dz / w1) * (gap**-4 - 1.0) * np.gradient(sig, r.cols["t_s"])
    extra = _through_x(s, force, damped, 2.0)
    for r in s.series():
        r.cols["disp_m"] = r.cols["disp_m"] + extra[id(r)]


def out_mux_ron_drive(s: Session) -> None:
    """The drive reaches the strip through the lab's switch box (a CMOS analogue multiplexer on +-5 V that routes the
    strip to the DAQ's drive or to the impedance analyser), the monitor v_V at the amplifier's output before it: the
    switch's on-resistance (R0 10-40 Ohm, log, at 0 V, which the fit's series resistance takes up) falls away from
    mid supply, R0 (1 - a v^2) (a 0.15-0.4 at 1 V), so the strip gets an extra e = i R0 a v^2 of drive where the
    current is large and the drive far from zero: the steps' charging spikes, the 1 V harmonics' and the fast sines'
    crests. e (the current's and the drive's signals, inject_fresh26._split_noise) through the preset's admittance
    and displacement transfer functions at each record's pressure with the session's history (2 s); current and
    displacement. Measured (s001_170: R0 18.6 Ohm, a 0.29; p12_171: 23.9 Ohm, 0.36) current residual 1.6 % and 3.1 %
    of its RMS (4.3x and 1.9x its noise), displacement 0.53 % and 0.40 % (17x and 3.8x its noise): the steps' spikes
    +0.5 and +1.5 mA, the 20 Hz sines' gain 1.017 and 1.034 (+0.05 and +0.2 deg)."""
    r0, a = lu(s.rng, 10.0, 40.0), s.rng.uniform(0.15, 0.4)
    e = {}
    for r in s.series():
        v, _ = _split_noise(r, "v_V")
        i, _ = _split_noise(r, "i_A")
        e[id(r)] = i * r0 * a * v**2
    di, dd = _through_strip(s, e)
    for r in s.series():
        r.cols["i_A"] = r.cols["i_A"] + di[id(r)]
        r.cols["disp_m"] = r.cols["disp_m"] + dd[id(r)]


FRESH33_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"self_stirred_layer": br_self_stirred_layer, "gravity_perfusion": br_gravity_perfusion},
    "faradaic_current": {"silver_contact_chloriding": far_silver_contact_chloriding,
                         "nickel_hydroxide_film": far_nickel_hydroxide_film},
    "hysteresis": {"threaded_rod_cogging": hy_threaded_rod_cogging, "carbon_flex_sensor": hy_carbon_flex_sensor},
    "time_delay": {"ldv_autorange": td_ldv_autorange, "controller_throttling": td_controller_throttling},
    "sensor_offset": {"capillary_volume_readout": so_capillary_volume_readout,
                      "fbg_shape_sensing": so_fbg_shape_sensing},
    "clamp_relaxation": {"water_ballast_lever": cr_water_ballast_lever,
                         "thermal_ratchet_thread": cr_thermal_ratchet_thread},
    "dehydration": {"ac_reevaporation": dh_ac_reevaporation, "fenton_ionomer_attack": dh_fenton_ionomer_attack},
    "strain_resistance": {"cathodic_scale_wedging": sr_cathodic_scale_wedging,
                          "pump_fretted_bridges": sr_pump_fretted_bridges},
    "large_deflection": {"zener_input_clamp": ld_zener_input_clamp, "slack_root_sleeve": ld_slack_root_sleeve},
    "mains_pickup": {"dimmed_led_lights": mp_dimmed_led_lights, "ac_ionizer_bar": mp_ac_ionizer_bar},
    "unexplained": {"negative_imag_spectra": out_negative_imag_spectra, "dsp_amp_requantised": out_dsp_amp_requantised,
                    "eddy_damped_magnet": out_eddy_damped_magnet, "mux_ron_drive": out_mux_ron_drive},
}
inject.register_forms(FRESH33_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def v_two_rate_sines(s: Session) -> None:
    """A data logger with a trigger-switched rate (the monitor rate before its trigger and the record rate after it, as
    test-and-measurement loggers offer to keep files small), its trigger set at the end of each stepped sine's settling
    cycles: every stepped sine's settling part (its settle_cycles of the drive's period from the record's first sample;
    the first third of its whole cycles when the manifest does not say) kept at 1/k of the rate (every k-th sample of
    the stream from the first, k 4, 5 or 8 for the session, no averaging), its measured cycles at the full rate from the
    first sample at or after the switch; the harmonics (no settling), the steps, the spectra and the manifest as they
    were, the session clock kept. The import contract asks t_s strictly increasing, not evenly spaced; ``labrig import``
    takes it and ``labrig export`` writes the rows back as written."""
    k = int(s.rng.choice([4, 5, 8]))
    for r in s.series():
        f = r.entry.get("frequency_Hz")
        if r.kind != "stepped_sine" or not f:
            continue
        t = r.cols["t_s"]
        settle = r.entry.get("settle_cycles")
        if settle is None:
            settle = float(round(math.floor((t[-1] - t[0]) * float(f) + 0.01) / 3))
        t_sw = float(t[0]) + float(settle) / float(f)
        n_sw = int(np.searchsorted(t, t_sw - 1e-9))
        if n_sw < 2 * k:
            continue
        keep = np.r_[np.arange(0, n_sw, k), np.arange(n_sw, t.size)]
        r.cols = {c: x[keep] for c, x in r.cols.items()}


inject.VARIANTS.update({"two_rate_sines": v_two_rate_sines})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_169", "s001_170", "p12_171"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 7 / 6 effect cases on seeds 169-171
    "back_relaxation": [("self_stirred_layer", 169, P, "settled_sines"),
                        ("gravity_perfusion", 171, T, "dropped_packets")],
    "faradaic_current": [("silver_contact_chloriding", 169, P, "cathodic_positive"),
                         ("nickel_hydroxide_film", 171, T, "fixed_decimals")],
    "hysteresis": [("threaded_rod_cogging", 169, P, "spectra_last"), ("carbon_flex_sensor", 170, S, "coherent_sines")],
    "time_delay": [("ldv_autorange", 169, P, "trigger_clock"), ("controller_throttling", 170, S, "short_pretrigger")],
    "sensor_offset": [("capillary_volume_readout", 169, P, "swinging_door"),
                      ("fbg_shape_sensing", 170, S, "two_rate_sines")],
    "clamp_relaxation": [("water_ballast_lever", 170, S, "merged_loadcell"),
                         ("thermal_ratchet_thread", 171, T, "log_steps")],
    "dehydration": [("ac_reevaporation", 170, S, "split_spectra"), ("fenton_ionomer_attack", 171, T, "eis_descending")],
    "strain_resistance": [("cathodic_scale_wedging", 171, T, "fir_decimated"),
                          ("pump_fretted_bridges", 170, S, "stop_trigger")],
    "large_deflection": [("zener_input_clamp", 169, P, "block_clock"), ("slack_root_sleeve", 171, T, "two_rate_sines")],
    "mains_pickup": [("dimmed_led_lights", 169, P, "eis_two_passes"), ("ac_ionizer_bar", 170, S, "minimal_manifest")],
    "unexplained": [("negative_imag_spectra", 169, P, "midnight_clock"),
                    ("negative_imag_spectra", 170, S, "tared_records"),
                    ("dsp_amp_requantised", 170, S, "scan_hold"), ("dsp_amp_requantised", 171, T, "host_timed"),
                    ("eddy_damped_magnet", 169, P, "harmonics_as_free"),
                    ("eddy_damped_magnet", 171, T, "cycle_averaged"),
                    ("mux_ron_drive", 170, S, "measured_pressures"), ("mux_ron_drive", 171, T, "shortened_shuffled")],
}
CLEAN = [(169, P, "two_rate_sines"), (169, P, "no_loadcell"), (170, S, "loadcell_dropout"),
         (170, S, "reversed_laser"), (171, T, "two_rate_sines"), (171, T, "no_spectra")]


def fresh33_cases(only: str | None = None) -> list[Case]:
    """The thirty-fourth held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds
    169-171)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh33_cases, "inject_fresh33", "fresh33")
