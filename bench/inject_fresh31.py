"""A thirty-second held-out set for the diagnosis (issue 12), fresh31, written without sight of the diagnosis (its code,
its doc, its tests, its results).

Two forms per catalogue effect, each from the physics of a cause a lab could meet and different from every form of
bench/inject.py (FORMS, EXTRA_FORMS, FRESH_FORMS), bench/inject_fresh2.py to bench/inject_fresh29.py and the simulated
bench (mock_devices/effects.py): some depending on the amplitude or the rate (an outer-sphere redox tracer left in the
cuvette whose Marcus kinetics bend its Tafel line, an LVDT's push rod rubbing its bore harder as the tip tilts, a
digital multimeter's integrating aperture on the current, the tip's slope read from the electrode's own resistance, a
cyanoacrylate-glued target whose edge cracks the plating as the glue cures, iron oxidised onto whichever face is the
anode, a rotary encoder's lever, jaws with radiused lips the strip lies down on at the large bends), some on the
history, the clamp pressure or the session's events (a magnetic stirrer thinning the bath's boundary layer in spells,
the bath sparged with nitrogen from one re-clamping on, the root's pinned domains scrambled by each squeeze, the clamp's
body dragged along its rail by each tightening, the bench knocked once, locking pliers as the clamp, the strip drawn
through an oil slick at each re-clamping, the strip dropped once, a lift's soft-starter) and some on time (a strip
stored dry re-swelling, a ferroresonant line regulator warming up); lab wiring or sensors among them (the DMM, the
class-D amplifier's monitor filter, the LVDT, the electrode's resistance, the encoder, the regulator, the lift's riser).
Four structures outside the catalogue (truth "unexplained": the load cell's bridge sharing a ground return with the
drive; the laser's zero warmed by the drive amplifier's heatsink beside it; spectra exported area-normalised; the laser
moved to the strip's other side at one re-clamping); clean sessions. All on three bases of new seeds (163-165: the
paper strip, the seed-001 strip on its own sweep, the paper strip 14 mm free) and on the earlier sets' data-shape
variants plus one new here: a generic waveform logger that writes the large-signal sine tests as plain captures
(``harmonics_as_free``).

Same pipeline as bench/inject.py (``labrig export`` -> inject -> ``labrig import``); the tools of inject and
inject_fresh2 to inject_fresh29 are reused (importing inject_fresh29 registers the earlier sets' lookups too), and the
forms, bases, preset and variant of this set are registered into inject's lookups at import, none replaced. Strengths
are drawn from the case's seed (uniform unless "log"); each form's docstring ends with the change it made on its case,
measured in memory against the clean base (relative RMS change over all series, form only, no variant; "noise": the
column's sample-to-sample noise at rest, inject_fresh15.rest_noise).

Run: python bench/inject_fresh31.py --make-only [--jobs 1] [--cache .cache/validation] [--only NAME] [--limit N]
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np
from scipy import signal, special

import inject
import inject_fresh29  # noqa: F401  (registers every earlier set's forms, bases, presets and variants)
from inject import Case, Rec, Session, lu, map_disp, ref_disp
from inject_fresh2 import _chrono, _map_through, _spec
from inject_fresh3 import _resist, _sign, _through_x
from inject_fresh4 import _clamp_law
from inject_fresh6 import _bursts
from inject_fresh9 import _dry_by, _session_grid
from inject_fresh10 import _lag_varying, _station
from inject_fresh12 import _line_f
from inject_fresh14 import _largest
from inject_fresh16 import _grid_of
from inject_fresh22 import _table_map
from inject_fresh24 import _by_pressure_start
from inject_fresh25 import _setting_of
from inject_fresh26 import _later_setting, _split_noise
from inject_fresh29 import _first_mode, _grid_lag, _logistic

# the paper's strip 14 mm free (earlier sets used 15-29 and 31-45 mm, 30 mm is the paper preset itself and the seed-001
# strip is 20 mm): its 1 V step peaks at 1.98 mm, well inside the laser's +-20 mm (2 mm/V on the DAQ's +-10 V) and 3600x
# the laser's 0.55 um noise at rest. Preset "paper_14", base "p14_165", registered in
# every process importing this module
inject.register_free_length("paper_14", 0.014)

inject.BASES.update({
    "paper_163": ("paper-sweep", "paper", 163),
    "s001_164": (str(inject.REPO / "bench" / "sweeps" / "paper-sweep-seed001.toml"), "seed001", 164),
    "p14_165": ("paper-sweep", "paper_14", 165),
})


# ------------------------------------------------------------------------------------------------ tools


def _on_grid(s: Session, windows: list[tuple[float, float]], dt: float = 1.0) -> tuple[np.ndarray, np.ndarray]:
    """A grid over the session (from 2 s before it) and the share of each cell inside any of ``windows``."""
    tg = _session_grid(s, dt, 2.0)
    on = np.zeros(tg.size)
    for a, b in windows:
        on = np.maximum(on, np.clip((np.minimum(tg + dt, b) - np.maximum(tg, a)) / dt, 0.0, 1.0))
    return tg, on


def _settings(s: Session) -> list[tuple[float, float]]:
    """Every clamp setting (time, pressure) in time order (inject_fresh25._setting_of)."""
    setting = _setting_of(s)
    return sorted((setting(p, a), p) for p, a in _by_pressure_start(s).items())


def _relay_states(state: np.ndarray, ev: np.ndarray) -> np.ndarray:
    """Relays' states sample by sample: ``ev`` (samples, relays) holds 1 or -1 (or 0) where a relay is set and nan
    where it holds; each starts from ``state`` (relays,)."""
    ev = np.vstack([state[None, :], ev])
    idx = np.where(np.isnan(ev), 0, np.arange(ev.shape[0])[:, None])
    return ev[np.maximum.accumulate(idx, axis=0), np.arange(ev.shape[1])[None, :]][1:]


def _boxcar_late(t: np.ndarray, x: np.ndarray, lag: float, width: float) -> np.ndarray:
    """x averaged over [t - lag - width/2, t - lag + width/2] (its running integral interpolated, the record's first
    value held before its start)."""
    t, x = np.asarray(t, float), np.asarray(x, float)
    pad = lag + width + 2.0 * float(np.median(np.diff(t)))
    tt, xx = np.r_[t[0] - pad, t], np.r_[x[0], x]
    c = np.r_[0.0, np.cumsum(0.5 * (xx[1:] + xx[:-1]) * np.diff(tt))]
    a, b = t - lag - 0.5 * width, t - lag + 0.5 * width
    return (np.interp(b, tt, c) - np.interp(a, tt, c)) / width


# ------------------------------------------------------------------------------------------------ back relaxation


def br_dry_stored_resoaking(s: Session) -> None:
    """A strip stored dry between sessions (in a desiccator, against fouling) and soaked 60-600 s before the first
    record: its first, fast stage of water uptake is over by then, the slow second stage (the polymer's network relaxing
    to take more water, tau_s 1000-3000 s, log) runs through the session. The back-flow through the membrane (the
    reading d - K2 x, x the lag of d) grows with the free water that can flow back and speeds up as the channels widen:
    K2 = K_inf (1 - dk e^-u/tau_s), tau = tau_inf (1 + sl e^-u/tau_s) (K_inf 0.5-0.9, tau_inf 2-8 s, log, dk 0.3-0.6, sl
    0.5-1.5, u from the soaking). Through inject_fresh10._lag_varying (sample by sample through the session, carried
    over the rests); displacement only. Measured (paper_163) displacement RMS -52 % (residual 60 %, 3400x its noise):
    the 1 V steps at 5.87, 3.86, 3.05, 2.76 mm by their plateaus' end block by block (8.82-8.83 mm clean)."""
    k_inf, tau_inf = s.rng.uniform(0.5, 0.9), lu(s.rng, 2.0, 8.0)
    dk, sl = s.rng.uniform(0.3, 0.6), s.rng.uniform(0.5, 1.5)
    t_soak, tau_s = s.t0 - s.rng.uniform(60.0, 600.0), lu(s.rng, 1000.0, 3000.0)

    def state(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        left = np.exp(-np.clip(np.asarray(t, float) - t_soak, 0.0, None) / tau_s)
        return k_inf * (1.0 - dk * left), tau_inf * (1.0 + sl * left)

    _lag_varying(s, state)


def br_stirrer_spells(s: Session) -> None:
    """A strip whose back-flow leaves through its faces into the bath (the anode side draws its water back from the
    bath, the cathode side gives its excess up to it) across the unstirred boundary layer of a still cuvette (100-300
    um): the layer sets the back-flow's rate. A magnetic stirrer under the cuvette, switched on by the operator in 3-6
    spells of 60-300 s (log) to mix the bath, thins the layer: the rate rises by a factor m (1.5-3) while the flow runs,
    the flow spinning up and down with tau_f 10-40 s (log). K2 0.5-0.9, tau_0 3-10 s (log) in still water. Through
    inject_fresh10._lag_varying; displacement only. Measured (p14_165) displacement RMS -47 % (residual 49 %, 690x its
    noise): the 1 V steps at 1.02 mm by their plateaus' end (1.98 mm clean; no spell fell on a step)."""
    k2, tau0, m = s.rng.uniform(0.5, 0.9), lu(s.rng, 3.0, 10.0), s.rng.uniform(1.5, 3.0)
    spells = _bursts(s, int(s.rng.integers(3, 7)), (60.0, 300.0))
    tau_f = lu(s.rng, 10.0, 40.0)
    tg, on = _on_grid(s, spells)
    flow = _grid_lag(on, 1.0, tau_f)

    def state(t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        f = np.interp(np.asarray(t, float), tg, flow)
        return np.full(f.shape, k2), tau0 / (1.0 + (m - 1.0) * f)

    _lag_varying(s, state)


# ------------------------------------------------------------------------------------------------ faradaic current


def far_marcus_tracer(s: Session) -> None:
    """The cuvette last used for cyclic voltammetry with an outer-sphere redox tracer (ferrocenemethanol or
    hexaammineruthenium, 0.1-1 mM) and rinsed with water only: the tracer left in the bath shuttles between the strip's
    faces, oxidised at whichever is the anode and reduced at the other. Its electron transfer follows Marcus-Hush-
    Chidsey kinetics, not Butler-Volmer: the rate grows more slowly than exponentially as the overpotential nears the
    reorganisation energy lambda (0.5-1.0 eV: 19-39 kT), so its Tafel line bends over. Each face takes half the drive,
    eta = v/2 (in kT/e); the net rate k_ox(eta) - k_red(eta) by Zeng et al.'s closed form of the MHC integral, scaled to
    i_1 (0.1-0.4 mA at 1 V, log): odd and memoryless, steep at 0.5 V, flattening towards 1 V. The current only. Measured
    (paper_163) current RMS +0.9 % (residual 3.6 %, 2.8x its noise): +0.26 mA on the 1 V steps' plateaus (0.98 mA for
    0.72 in the first block)."""
    lam = s.rng.uniform(0.5, 1.0) / 0.025693  # kT at 25 C
    i1 = lu(s.rng, 1e-4, 4e-4)

    def k_red(eta: np.ndarray) -> np.ndarray:  # the reduction rate at overpotential eta (kT/e), Zeng et al. 2014
        return (np.sqrt(np.pi * lam) / (1.0 + np.exp(np.clip(eta, -60.0, 60.0)))
                * special.erfc((lam - np.sqrt(1.0 + np.sqrt(lam) + eta**2)) / (2.0 * np.sqrt(lam))))

    def net(v: np.ndarray) -> np.ndarray:
        eta = 0.5 * np.asarray(v, float) / 0.025693
        return k_red(-eta) - k_red(eta)

    scale = i1 / float(net(np.array([1.0]))[0])
    for r in s.series():
        r.cols["i_A"] = r.cols["i_A"] + scale * net(r.cols["v_V"])


def far_nitrogen_sparge(s: Session) -> None:
    """Oxygen reduced on whichever face is the cathode (a wave from E0 0.2-0.4 V of drive, width 0.05-0.1 V, to its
    diffusion-limited current i_L 0.1-0.4 mA, log, in the air-saturated bath) until, at one re-clamping after the first
    (drawn; bubbling from 0-30 s after that setting), the operator starts sparging the bath with nitrogen to take the
    oxygen out for the remaining blocks: the bubbles stir the bath at once (the diffusion layer thins: i_L times m,
    1.5-3, the stream spinning up over 10-30 s), while the dissolved oxygen falls as exp(-u/tau_p) (tau_p 120-600 s,
    log): the reduction current jumps up, then dies away. i = sign(v) i_L c(t) (1 + (m - 1) f(t)) wave(|v|); odd,
    memoryless within a record. The current only. Measured (p14_165: the sparge from the last block on) current RMS +3.3
    % (residual 6.7 %, 4.3x its noise): +0.29 mA on the 1 V steps' plateaus in the first three blocks, +0.25 mA in the
    last."""
    e0, b, i_l = s.rng.uniform(0.2, 0.4), s.rng.uniform(0.05, 0.1), lu(s.rng, 1e-4, 4e-4)
    m, tau_p = s.rng.uniform(1.5, 3.0), lu(s.rng, 120.0, 600.0)
    _, t_set = _later_setting(s)
    t_sp, spin = t_set + s.rng.uniform(0.0, 30.0), s.rng.uniform(10.0, 30.0)
    for r in s.series():
        t, v = r.cols["t_s"], r.cols["v_V"]
        u = np.clip(t - t_sp, 0.0, None)
        c = np.exp(-u / tau_p)
        stir = 1.0 + (m - 1.0) * -np.expm1(-u / spin)
        r.cols["i_A"] = r.cols["i_A"] + np.sign(v) * i_l * c * stir * _logistic((np.abs(v) - e0) / b)


# ------------------------------------------------------------------------------------------------ hysteresis


def hy_lvdt_core_friction(s: Session) -> None:
    """No laser: an LVDT (a +-10 mm stroke) whose ferrite core rides on a thin glass-fibre push rod glued at the tip,
    sliding in the LVDT's PTFE-lined bore: the rod's Coulomb friction holds the tip until the strip's bend pulls past
    it, a play on the bend of radius r0 (0.01-0.04 of the session's largest bend, log) at rest. The rod tilts with the
    tip's slope (2 d/L) and presses on the bore's lips, so the friction grows with the bend: r = r0 (1 + c |u|/D) (c
    1-3, D the largest bend), loops that widen with the amplitude and do not shrink as the drive slows. Sample by sample
    through the session in time order (the rests carried at the held position), the LVDT's noise kept as the laser's was
    (inject_fresh26._split_noise); displacement only. Measured (paper_163) displacement RMS -1.6 % (residual 6.6 %, 380x
    its noise): the 1 V steps held 0.47 mm short of their plateau (8.36 mm for 8.82-8.83 clean)."""
    big = _largest(s) or ref_disp(s)
    r0, c = lu(s.rng, 0.01, 0.04) * big, s.rng.uniform(1.0, 3.0)
    y = 0.0
    for r in _chrono(s):
        u, noise = _split_noise(r)
        rad = (r0 * (1.0 + c * np.abs(u) / big)).tolist()
        out = np.empty(u.size)
        for k, (uk, rk) in enumerate(zip(u.tolist(), rad)):
            y = min(max(y, uk - rk), uk + rk)
            out[k] = y
        r.cols["disp_m"] = out + noise


def hy_squeezed_root_domains(s: Session) -> None:
    """Pinned cluster domains in the strip's root near the jaws' edge, each a relay on the drive (switching up at a_j,
    down at -a_j, a_j 0.1-0.5 V spread over 12 domains: a loop that stays as the drive slows), their pinning set by the
    pads' squeeze: thresholds times (p/p_min)^g (g 0.1-0.25), so the heavy blocks' loops narrow to the large drives.
    Each tightening's shear scrambles them: at every setting every domain is reset to neutral, so each block starts on a
    virgin curve. Their switched share bends the strip by K (0.04-0.1 of the session's displacement scale) through its
    first mode (labrig.physics.transfer.modal_set, inject_fresh3._through_x); displacement only. Measured (s001_164)
    displacement RMS +2.8 % (residual 4.8 %, 150x its noise): the 1 V steps +0.08 mm by their plateaus' end (4.77-4.80
    mm for 4.69-4.72 clean)."""
    n = 12
    k = s.rng.uniform(0.04, 0.1)
    a = np.sort(s.rng.uniform(0.1, 0.5, n))
    g = s.rng.uniform(0.1, 0.25)
    p_min = min(s.pressures())
    sets = _settings(s)
    scale = k * ref_disp(s)
    state, bend, t_last = np.zeros(n), {}, -np.inf
    for r in _chrono(s):
        t, v = r.cols["t_s"], r.cols["v_V"]
        if any(t_last < ts <= float(t[0]) for ts, _ in sets):
            state = np.zeros(n)  # the squeeze scrambled them
        th = a * (float(r.entry["pressure_kPa"]) / p_min) ** g
        ev = np.where(v[:, None] >= th[None, :], 1.0, np.where(v[:, None] <= -th[None, :], -1.0, np.nan))
        filled = _relay_states(state, ev)
        state, t_last = filled[-1].copy(), float(t[-1])
        bend[id(r)] = scale * filled.mean(axis=1)
    moved = _through_x(s, bend, _first_mode(s), 2.0)
    for r in s.series():
        r.cols["disp_m"] = r.cols["disp_m"] + moved[id(r)]


# ------------------------------------------------------------------------------------------------ time delay


def td_dmm_aperture(s: Session) -> None:
    """The drive current read not by the DAQ but by a digital multimeter on the shunt (a 6.5-digit DMM in its digitising
    mode, the DAQ's inputs all taken), triggered by the DAQ's sample clock and merged onto its rows by the logging
    script on each reading's arrival: each reading integrates over the DMM's aperture, set once for the session to fit
    the fastest record's sample period (0.2-0.8 of it: 0.2-0.8 ms at 1 kHz), and is stamped at its end plus the bus's
    latency (0.2-1.5 ms, log): the current a boxcar of that width, late by half of it plus the latency, the steps'
    charging spikes rounded. The current only. Measured (paper_163: an aperture of 0.29 ms, late by 1.47 ms) current RMS
    -0.18 % (residual 12 %, 8.8x its noise): the 1 V steps' current peaks 23.8-25.5 mA (26.3-28.2 mA clean); the 20 Hz
    sines' current -10.8 deg, gain 0.998; the 0.1 Hz records' -0.09 deg."""
    fs_max = max(r.fs for r in s.series())
    width = s.rng.uniform(0.2, 0.8) / fs_max
    lag = 0.5 * width + lu(s.rng, 2e-4, 1.5e-3)
    for r in s.series():
        r.cols["i_A"] = _boxcar_late(r.cols["t_s"], r.cols["i_A"], lag, width)


def td_monitor_rc_filter(s: Session) -> None:
    """The drive from a class-D power amplifier (a compact audio-type module: a PWM stage at 250-500 kHz behind its LC
    output filter), whose switching residue on the DAQ's voltage monitor the lab filters away with the RC low-pass the
    terminal block has pads for (a series resistor into a film capacitor across the channel's input: tau = RC 0.5-2 ms,
    log, e.g. 10 kOhm and 47-200 nF): the monitor v_V lags the drive the strip feels by about tau at the drives'
    frequencies, its gain within 1.5 % up to 20 Hz, the steps' recorded edge rounded, so the current and the bend seem
    to lead the drive. The RC exact for the drive linear between samples (the ramp-invariant first-order lag), settled
    on each record's first sample (the rest before it); v_V only. Measured (p14_165, tau 0.96 ms) drive monitor residual
    2.1 % of its RMS (50x its noise), every time series touched: the 1 V steps' first sample past the edge 0.42 V short
    of the drive; the monitor's phase -0.03 deg at 0.1 Hz, -3.2 deg at 9.4 Hz and -6.9 deg at 20 Hz (0.95-0.96 ms at
    every rate), its gain 0.992 at 20 Hz."""
    tau = lu(s.rng, 5e-4, 2e-3)
    for r in s.series():
        x = r.cols["v_V"]
        a = math.exp(-1.0 / (r.fs * tau))
        k = r.fs * tau * (1.0 - a)
        b = [1.0 - k, k - a]
        zi = signal.lfilter_zi(b, [1.0, -a]) * x[0]
        r.cols["v_V"] = signal.lfilter(b, [1.0, -a], x, zi=zi)[0]


# ------------------------------------------------------------------------------------------------ sensor offset


def so_rail_clamp_shift(s: Session) -> None:
    """The clamp's body held on the stand's dovetail rail by a thumb screw, the laser aimed at the tip once at the first
    setting: each later tightening's torque (growing with the force step) drags the body forward along the rail, the
    strip with it, so the fixed spot lands ever further inboard, at L - delta_k: the shift per setting c (p_k - p_k-1)/
    p_max with the whole sweep's delta 0.05-0.15 L. A station fixed within each block and stepping inboard block by
    block, read through the strip's transfer functions at the innermost one and interpolated in (x/L)^2
    (inject_fresh10._station, exact for the quasi-static uniform curvature); displacement only. Measured (p14_165)
    displacement RMS -7.5 % (residual 9.6 %, 130x its noise): the 1 V steps at 1.98, 1.88, 1.78, 1.68 mm by their
    plateaus' end block by block (1.98 mm clean)."""
    sets = _settings(s)
    total = s.rng.uniform(0.05, 0.15)
    steps = [max(p - q, 0.0) for (_, q), (_, p) in zip(sets, sets[1:])]
    share = np.cumsum([0.0] + steps) / max(sum(steps), 1e-12)
    station = [(ts, 1.0 - total * sh) for (ts, _), sh in zip(sets, share)]

    def frac(r: Rec) -> np.ndarray:
        t0 = float(r.cols["t_s"][0])
        f = 1.0
        for ts, x in station:
            if ts <= t0:
                f = x
        return np.full(r.cols["t_s"].size, f)

    _station(s, frac, 1.0 - total)


def so_surface_resistance_sensing(s: Session) -> None:
    """No laser: the bend read from the strip's own electrode (self-sensing, as IPMC labs do for closed loop): a
    four-wire measurement of one face's surface resistance between contacts at the root and a clip near the tip (at x_c
    0.85-0.97 L: the clip needs the last millimetres), on a small 5-10 kHz carrier that a lock-in separates from the
    drive. The resistance follows the face's mean strain between the contacts, so its change reads the integral of the
    curvature, the slope at x_c, calibrated to the tip's height in place by a slow bend against a micrometer (at 1 mHz):
    right at rest and the slow drives, but the higher modes bend the strip differently from that slope, so above the
    first resonance the reading's gain and phase depart (zeros move, poles stay). Through the beam's transfer functions
    (labrig.physics.transfer.displacement_tf at x_c and x_c - 0.02 L, their difference) with the session's history
    (inject_fresh2._through); displacement only. Measured (s001_164, x_c 0.89 L) displacement RMS -0.14 % (residual 0.41
    %, 13x its noise): the 1 V steps within 0.2 % (4.68-4.71 mm for 4.69-4.72 clean); the 0.1 Hz records' gain 0.989
    (-0.7 deg), the 3 Hz sines' 0.92 (-3.3 deg), the 20 Hz sines' 0.73-0.75 (0 deg)."""
    from labrig.physics import transfer

    dx, xc = 0.02, s.rng.uniform(0.85, 0.97)
    z0 = np.array([2j * np.pi * 1e-3])

    def H(r: Rec) -> Callable[[np.ndarray], np.ndarray]:
        sp = _spec(s, r)
        sc = sp.with_(sensor_x=xc * sp.geometry.length)
        sm = sp.with_(sensor_x=(xc - dx) * sp.geometry.length)

        def slope(z: np.ndarray) -> np.ndarray:
            return transfer.displacement_tf(z, sc) - transfer.displacement_tf(z, sm)

        cal = complex((transfer.displacement_tf(z0, sp) / slope(z0))[0]).real

        def h(z: np.ndarray) -> np.ndarray:
            with np.errstate(divide="ignore", invalid="ignore"):
                return cal * slope(z) / transfer.displacement_tf(z, sp)

        return h

    _map_through(s, H, 2.0)


# ------------------------------------------------------------------------------------------------ clamp relaxation


def cr_knocked_bench(s: Session) -> None:
    """The bench knocked once (a colleague leaning on it, a heavy bottle set down), at a moment inside a recorded series
    (drawn): the clamp's screw thread settles by a fraction of a micrometre and the held gap opens, the force dropping
    at once by j (4-10 %); the pads then recover a share rho (0.2-0.4) of the drop (the viscoelastic stress recovery
    after an unloading step) over tau 20-80 s (log), until the next setting resets the force. The other blocks
    untouched. Through the preset's clamp law (inject_fresh4._clamp_law), the load cell showing it. Measured (s001_164)
    load cell residual 1.3 % of its RMS; displacement residual 0.002 % of its RMS (0.05x its noise: the seed-001 strip's
    clamp law moves its bend little), current 0.09 % (0.24x)."""
    (a, _), = _bursts(s, 1, (1.0, 1.0))
    j, rho, tau = s.rng.uniform(0.04, 0.1), s.rng.uniform(0.2, 0.4), lu(s.rng, 20.0, 80.0)
    sets = _settings(s)
    nxt = min([ts for ts, _ in sets if ts > a], default=np.inf)

    def rel(t: np.ndarray, p: float, t_first: float) -> np.ndarray:
        t = np.asarray(t, float)
        u = t - a
        drop = j * (1.0 - rho * -np.expm1(-np.clip(u, 0.0, None) / tau))
        return np.where((u >= 0.0) & (t < nxt), 1.0 - drop, 1.0)

    _clamp_law(s, rel)


def cr_locking_pliers(s: Session) -> None:
    """Locking pliers (a Vise-Grip type, its jaws padded) as the clamp, its adjusting screw turned at each setting and
    the handles snapped over centre: the pads creep under the held jaws, r ln(1 + u/tau) (tau 5-30 s, log), and near the
    over-centre point the linkage is ever stiffer the harder it is set, so the same creep costs the heavy settings a
    larger share of their force: r = r_top (p/p_max)^m (r_top 1.5-4 % per e-fold of time, m 0.5-1.5). From each setting
    (inject_fresh25._setting_of) through the preset's clamp law (inject_fresh4._clamp_law), the load cell showing it.
    Measured (paper_163) the load cell at 0.990, 0.973, 0.944, 0.911 of its setting by the 1 V steps' ends block by
    block; displacement residual 0.15 % of its RMS (8.7x its noise), current 0.82 % (0.62x)."""
    r_top, m, tau = s.rng.uniform(0.015, 0.04), s.rng.uniform(0.5, 1.5), lu(s.rng, 5.0, 30.0)
    setting = _setting_of(s)
    p_max = max(s.pressures())

    def rel(t: np.ndarray, p: float, t_first: float) -> np.ndarray:
        u = np.clip(np.asarray(t, float) - setting(p, t_first), 0.0, None)
        return 1.0 - r_top * (p / p_max) ** m * np.log1p(u / tau)

    _clamp_law(s, rel)


# ------------------------------------------------------------------------------------------------ dehydration


def dh_ferric_anode_deposit(s: Session) -> None:
    """A bath of well water (or of a tap on old iron pipes: Fe2+ 0.1-0.5 mg/l): beyond v_f (0.3-0.6 V of drive, width
    0.05-0.1 V) the anodic face oxidises the ferrous iron, which precipitates there as ferric hydroxide and stays,
    blocking the face's pores: each face's blocked share th = th_max (1 - exp(-Q_f/Q_s)) grows with its own anodic
    charge through the gate (second by second, inject_fresh16._grid_of; th_max 0.2-0.5, the session's charge filling 1-3
    e-folds) and never recedes. The faces' capacitances in series: the conductance falls as 1 - 2 (1 - th_A)(1 -
    th_B)/(2 - th_A - th_B), the gain with it (0.6-1 of it), relative to the first record; the spectra at the next
    series' start (inject_fresh9._dry_by). Measured (p14_165) displacement RMS -12 % (residual 15 %, 210x its noise),
    current RMS -23 % (residual 25 %, 16x its noise): the 1 V steps at 1.95, 1.76, 1.64, 1.56 mm by their plateaus' end
    block by block (1.98 mm clean); the impedance 1.17, 1.31, 1.41x in the later blocks' spectra."""
    v_f, w = s.rng.uniform(0.3, 0.6), s.rng.uniform(0.05, 0.1)
    th_max, folds, share = s.rng.uniform(0.2, 0.5), s.rng.uniform(1.0, 3.0), s.rng.uniform(0.6, 1.0)
    gate = lambda v: _logistic((np.abs(v) - v_f) / w)  # noqa: E731
    tg, qa = _grid_of(s, "i_A", lambda i, v: np.abs(i) * gate(v) * (v > 0), 5.0)
    _, qb = _grid_of(s, "i_A", lambda i, v: np.abs(i) * gate(v) * (v < 0), 5.0)
    q_s = max(float(np.sum(qa) + np.sum(qb)) / 2.0, 1e-30) / folds
    tha, thb = th_max * -np.expm1(-np.cumsum(qa) / q_s), th_max * -np.expm1(-np.cumsum(qb) / q_s)
    cond = 1.0 - 2.0 * (1.0 - tha) * (1.0 - thb) / (2.0 - tha - thb)
    c0 = float(np.interp(s.t0, tg, cond))

    def loss(t: np.ndarray) -> np.ndarray:
        return (np.interp(np.asarray(t, float), tg, cond) - c0) / (1.0 - c0)

    _dry_by(s, lambda t: share * loss(t), loss)


def dh_surface_oil_slick(s: Session) -> None:
    """A film of oil on the bath's surface (silicone oil from the stirrer bar's bearing, or hand cream from bare
    fingers), and at each re-clamping the strip lifted through it and lowered back: each passage coats a share a_k
    (0.04-0.12, drawn per passage) of what is still open of its faces, the oil then creeping into the plating's pores
    over tau_c (60-300 s, log), blocking them for good: the open share 1 - th steps down at every setting after the
    first and sinks a little further within each block. The gain falls with the open share (0.6-1 of it), the
    conductance with it, relative to the first record; the spectra at the next series' start (inject_fresh9._dry_by).
    Measured (paper_163) displacement RMS -5.4 % (residual 7.4 %, 420x its noise), current RMS -11 % (residual 15 %, 11x
    its noise): the 1 V steps at 8.82, 8.66, 8.14, 7.74 mm by their plateaus' end block by block; the impedance 1.01,
    1.12, 1.22x in the later blocks' spectra."""
    tau_c, share = lu(s.rng, 60.0, 300.0), s.rng.uniform(0.6, 1.0)
    passes = [(ts, s.rng.uniform(0.04, 0.12)) for ts, _ in _settings(s)[1:]]

    def loss(t: np.ndarray) -> np.ndarray:
        t = np.asarray(t, float)
        open_ = np.ones(t.shape)
        for ts, a in passes:
            open_ = open_ * (1.0 - a * -np.expm1(-np.clip(t - ts, 0.0, None) / tau_c))
        return 1.0 - open_

    _dry_by(s, lambda t: share * loss(t), loss)


# ------------------------------------------------------------------------------------------------ strain resistance


def sr_dropped_strip(s: Session) -> None:
    """At one re-clamping after the first (drawn) the strip slips from the tweezers and is bent sharply where it is
    caught: both faces' plating cracks across. From that block on, each face's cracks open beyond e0 (0.1-0.3 of the
    session's displacement scale) when it is stretched, dR/R = k ((e - e0)+ + o (-e - e0)+) (k 0.15-0.4, the other face
    o 0.6-1 of it: the fold went both ways); before it the plating's own fine cracks, at q 0.05-0.2 of that. Gains fall
    by 0.03-0.08 (displacement) and 0.06-0.15 (current) per unit of dR/R (inject_fresh3._resist). Measured (p14_165:
    dropped before the last block) displacement RMS -1.3 % (residual 1.8 %, 25x its noise), current RMS -0.1 % (residual
    0.8 %, 0.5x its noise): the 1 V steps at 1.96 mm by their plateaus' end in the first three blocks and 1.89 mm in the
    last (1.98 mm clean); 36 of the 68 time series touched."""
    k, o, e0, q = s.rng.uniform(0.15, 0.4), s.rng.uniform(0.6, 1.0), s.rng.uniform(0.1, 0.3), s.rng.uniform(0.05, 0.2)
    _, t_drop = _later_setting(s)

    def law(r: Rec | None, e: np.ndarray) -> np.ndarray:
        after = r is None or float(r.cols["t_s"][0]) > t_drop
        e = np.asarray(e, float)
        return (1.0 if after else q) * k * (np.clip(e - e0, 0.0, None) + o * np.clip(-e - e0, 0.0, None))

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


def sr_glued_target_edge(s: Session) -> None:
    """A reflective target (a cover-slip chip) glued with cyanoacrylate on one face (drawn) over the tip's last 15-30 %,
    300-1200 s before the first record: the glue's stiff edge concentrates the face's strain there, and the plating
    cracks across at that edge when the face is stretched, beyond e0 (0.3-0.6 of the session's displacement scale): dR/R
    = k (kt e - e0)+ on that face only (k 0.1-0.25), one-sided. The glue cures through the session (its modulus rising,
    tau 600-1800 s, log, from the gluing), so the concentration grows, kt = 1 + (kt_inf - 1)(1 - e^-u/tau) (kt_inf
    1.3-2): the same bend cracks more as the session goes on. Gains fall by 0.03-0.08 (displacement) and 0.06-0.15
    (current) per unit of dR/R (inject_fresh3._resist). Measured (s001_164) displacement RMS -6.1 % (residual 6.6 %,
    210x its noise), current RMS -0.9 % (residual 2.9 %, 7.9x its noise): the 1 V steps at 4.38, 4.29, 4.25, 4.23 mm by
    their plateaus' end block by block (4.69-4.72 mm clean); 27 of the 68 time series touched."""
    side, k, e0 = _sign(s), s.rng.uniform(0.1, 0.25), s.rng.uniform(0.3, 0.6)
    kt_inf, tau = s.rng.uniform(1.3, 2.0), lu(s.rng, 600.0, 1800.0)
    t_g = s.t0 - s.rng.uniform(300.0, 1200.0)

    def law(r: Rec | None, e: np.ndarray) -> np.ndarray:
        t_mid = s.t1 if r is None else float(np.mean(r.cols["t_s"]))
        kt = 1.0 + (kt_inf - 1.0) * -math.expm1(-(t_mid - t_g) / tau)
        return k * np.clip(kt * side * np.asarray(e, float) - e0, 0.0, None)

    _resist(s, law, (0.03, 0.08), (0.06, 0.15))


# ------------------------------------------------------------------------------------------------ large deflection


def ld_encoder_lever(s: Session) -> None:
    """No laser: a rotary encoder (a 14-bit magnetic one) whose lever, pivoted a (2-5 times the session's largest bend)
    beyond the tip on the strip's axis, takes the tip's pin in a slot: the lever turns by atan(d/a) as the tip moves
    across, and the lab's script converts the angle to a height by the small-angle rule, a theta, calibrated at rest.
    The arctangent falls behind at the large bends: odd, compressing the 1 V records. Tabulated and interpolated (slope
    1 at rest, inject_fresh22._table_map); displacement only. Measured (s001_164) displacement RMS -1.1 % (residual 1.2
    %, 38x its noise): the 1 V steps at 4.60-4.63 mm by their plateaus' end (4.69-4.72 mm clean)."""
    a = s.rng.uniform(2.0, 5.0) * (_largest(s) or ref_disp(s))
    _table_map(s, lambda d: a * np.arctan(d / a))


def ld_radiused_jaw_lips(s: Session) -> None:
    """Jaws whose pads end in a radiused lip (radius R_j) reaching l (0.06-0.15 L) past the clamp line (a lab's remedy
    against cracking the plating at the root): the strip bends free of the lip while its curvature stays below 1/R_j,
    but a larger actuation curvature lays it down on the lip, whose radius then holds its curvature over that length:
    the tip loses (kappa - 1/R_j) l (L - l/2), a knee at d_c = L^2/(2 R_j) (0.4-0.8 of the session's largest bend),
    smoothed over 5 % of it as the contact rolls on. Odd (both jaws), the 1 V records compressed. Tabulated and
    interpolated (slope 1 at rest, inject_fresh22._table_map); displacement only. Measured (p14_165) displacement RMS
    -4.2 % (residual 5.1 %, 71x its noise): the 1 V steps at 1.82 mm by their plateaus' end (1.98 mm clean)."""
    big = _largest(s) or ref_disp(s)
    ell, d_c = s.rng.uniform(0.06, 0.15), s.rng.uniform(0.4, 0.8) * big
    g = 2.0 * ell * (1.0 - 0.5 * ell)
    wd = 0.05 * d_c

    def reading(d: np.ndarray) -> np.ndarray:
        over = wd * np.logaddexp(0.0, (np.abs(d) - d_c) / wd)
        return d - np.sign(d) * g * over

    _table_map(s, reading)


# ------------------------------------------------------------------------------------------------ mains pickup


def mp_lift_soft_starter(s: Session) -> None:
    """The building's lift, its motor on the riser behind the lab's wall, started and stopped by a thyristor
    soft-starter: trips come at random (20-60 an hour in a busy building's working day, the first starting while a
    record runs, each 10-40 s of running, log); during each 2-4 s ramp up (and 1-2 s down) the phase-angle control chops
    the motor's current (3rd 0.2-0.4, 5th 0.1-0.2, 7th 0.05-0.1 of the fundamental, the current rising), then the bypass
    contactor closes and the line alone runs until the stop. The riser's field reaches the laser's cable (4-12 um at
    full current, log) and the current amplifier's input (20-60 uA, log), phase locked to the line (50 or 60 Hz,
    inject_fresh12._line_f). Displacement and current, in the trips only. Measured (paper_163) displacement residual
    0.084 % of its RMS (4.8x its noise), current residual 0.27 % (0.2x its noise): 15 of the 68 time series touched, a
    line of 10-17 um and 30-53 uA peak in those."""
    f0 = _line_f(s)
    rate = s.rng.uniform(20.0, 60.0) / 3600.0
    n = max(1, int(s.rng.poisson(rate * (s.t1 - s.t0))))
    (first, _), = _bursts(s, 1, (1.0, 1.0))  # one trip starts while a record runs, the others anywhere
    trips = []
    for k in range(n):
        a = first if k == 0 else s.t0 + s.rng.uniform(0.0, 1.0) * (s.t1 - s.t0)
        up, run, down = s.rng.uniform(2.0, 4.0), lu(s.rng, 10.0, 40.0), s.rng.uniform(1.0, 2.0)
        trips.append((a, up, run, down))
    h = (s.rng.uniform(0.2, 0.4), s.rng.uniform(0.1, 0.2), s.rng.uniform(0.05, 0.1))
    amp = {"disp_m": lu(s.rng, 4e-6, 1.2e-5), "i_A": lu(s.rng, 2e-5, 6e-5)}
    phase = {col: s.rng.uniform(0.0, 2.0 * np.pi) for col in amp}
    for r in s.series():
        t = r.cols["t_s"]
        size, chop = np.zeros(t.size), np.zeros(t.size)
        for a, up, run, down in trips:
            u = t - a
            ramp_up = (u >= 0) & (u < up)
            running = (u >= up) & (u < up + run)
            ramp_dn = (u >= up + run) & (u < up + run + down)
            size = np.where(ramp_up, 0.3 + 0.7 * u / up, size)
            size = np.where(running, 1.0, size)
            size = np.where(ramp_dn, 1.0 - (u - up - run) / down, size)
            chop = np.where(ramp_up | ramp_dn, 1.0, chop)
        if not np.any(size):
            continue
        for col, a_ in amp.items():
            w = 2.0 * np.pi * f0 * t + phase[col]
            wave = np.cos(w) + chop * (h[0] * np.cos(3 * w) + h[1] * np.cos(5 * w) + h[2] * np.cos(7 * w))
            r.cols[col] = r.cols[col] + a_ * size * wave


def mp_ferroresonant_regulator(s: Session) -> None:
    """An old ferroresonant (constant-voltage) line regulator under the bench, feeding the laser's controller and
    switched on with the bench 0-600 s before the first record: its saturating core's stray flux, square-topped, rich in
    odd harmonics, reaches the laser's cable (1.5-5 um, log) and the current amplifier's input (8-30 uA, log) at the
    line (50 or 60 Hz, inject_fresh12._line_f). As its resonant capacitor and core warm (tau 600-1800 s, log) the core
    saturates less hard: the 3rd harmonic falls from 0.3-0.45 of the fundamental to 0.5-0.8 of that, the 5th alike, the
    fundamental rising 3-8 %. Displacement and current, every series. Measured (s001_164) displacement residual 0.14 %
    of its RMS (4.6x its noise), current residual 0.55 % (1.5x its noise)."""
    f0 = _line_f(s)
    t_on, tau = s.t0 - s.rng.uniform(0.0, 600.0), lu(s.rng, 600.0, 1800.0)
    h3, h5 = s.rng.uniform(0.3, 0.45), s.rng.uniform(0.1, 0.2)
    fall, rise = s.rng.uniform(0.5, 0.8), s.rng.uniform(0.03, 0.08)
    amp = {"disp_m": lu(s.rng, 1.5e-6, 5e-6), "i_A": lu(s.rng, 8e-6, 3e-5)}
    phase = {col: s.rng.uniform(0.0, 2.0 * np.pi) for col in amp}
    for r in s.series():
        t = r.cols["t_s"]
        warm = -np.expm1(-np.clip(t - t_on, 0.0, None) / tau)
        hk = 1.0 - (1.0 - fall) * warm
        for col, a_ in amp.items():
            w = 2.0 * np.pi * f0 * t + phase[col]
            wave = (1.0 + rise * warm) * np.cos(w) - hk * (h3 * np.cos(3 * w) - h5 * np.cos(5 * w))
            r.cols[col] = r.cols[col] + a_ * wave


# ------------------------------------------------------------------------------------------------ outside the catalogue


def out_loadcell_ground_loop(s: Session) -> None:
    """The load cell's bridge (2 mV/V on 5 V of excitation: 10 mV over its 98 N span, about 10 uV per 0.01 kgf) wired to
    its indicator through a cable whose shield and signal ground share a return with the drive amplifier's output stage
    (the indicator and the amplifier on one bench supply): the strip's current, flowing back through r_g (10-40 mOhm,
    log) of that shared ground, adds r_g i to the bridge's millivolts, c = 100-400 N/A (log) of apparent force, either
    sign by the wiring. The indicator's digital filter (a first-order lag, tau_f 0.1-0.4 s, log) smooths it and its
    display's 0.01 kgf steps quantise it: the force reading jumps at every step's edge (the charging spike) and breathes
    with the sines' current, while the clamp, the strip and the other channels do not change at all. A first-order lag
    exact for the current held over each sample, settled on each record's first sample; force_N only. Measured
    (paper_163: -390 N/A, tau_f 0.12 s) load cell residual 1.6 % of its RMS (0.71 N), up to 3.0 N (31 counts) at the
    steps' edges, 98 % of the samples moved; (p14_165: +104 N/A, 0.21 s) 0.25 % (0.11 N), up to 0.49 N (5 counts), 67 %
    moved."""
    c, tau_f = _sign(s) * lu(s.rng, 100.0, 400.0), lu(s.rng, 0.1, 0.4)
    q = 0.0980665
    for r in s.series():
        if "force_N" not in r.cols:
            continue
        x = r.cols["i_A"]
        a = math.exp(-1.0 / (r.fs * tau_f))
        seen = signal.lfilter([1.0 - a], [1.0, -a], x, zi=[a * x[0]])[0]
        r.cols["force_N"] = np.round((r.cols["force_N"] + c * seen) / q) * q


def out_amplifier_heat_zero(s: Session) -> None:
    """The laser head clamped beside the drive amplifier's heatsink (the one free spot on the stand): the head's zero
    follows its temperature, and the heatsink's follows the amplifier's dissipation, its output stage dropping the rest
    of its +-V_s rails (12-15 V) at the strip's current, V_s |i|, second by second (inject_fresh16._grid_of), through a
    thermal lag tau (60-240 s, log): the zero drifts by z (10-40 um, log, either sign) at the session's hottest, rising
    through each block's large records and cooling over the rests. An offset on the displacement that depends on the
    drive's power, not on the strip's bend. Displacement only. Measured (paper_163, p14_165) displacement residual 0.46
    % and 2.6 % of its RMS (26x and 37x its noise)."""
    v_s, tau = s.rng.uniform(12.0, 15.0), lu(s.rng, 60.0, 240.0)
    z = _sign(s) * lu(s.rng, 1e-5, 4e-5)
    tg, load = _grid_of(s, "i_A", lambda i, v: np.abs(i) * (v_s - np.abs(v)), 600.0)
    heat = _grid_lag(load, 1.0, tau)
    heat = heat / max(float(np.max(heat)), 1e-30)
    map_disp(s, lambda r, d: d + z * np.interp(r.cols["t_s"], tg, heat))


def out_area_normalised_spectra(s: Session) -> None:
    """The impedance analyser's software left with an electrode area entered (the strip's plated area as the lab worked
    it out with calipers, width times free plus clamped length, its ragged plated edges read within 10 %: 0.9-1.1 of
    1.36 cm^2 for the 30 mm paper strip, of 1.5 for the seed-001 strip, of 0.72 for the 14 mm one) and exporting
    area-normalised impedance (Ohm cm^2) into the columns the lab labels z_re_ohm and z_im_ohm: every spectrum scaled by
    that number, its shape untouched, while the time series' currents say the strip's true impedance. No time series
    touched. Measured (s001_164: x1.44; p14_165: x0.75) the spectra's |Z| +44 % and -25 % at every frequency, their
    phase untouched."""
    sp = s.specimen
    width = float(sp["width_m"])
    area = width * (float(sp["length_m"]) + float(sp["clamp_area_m2"]) / width) * 1e4 * s.rng.uniform(0.9, 1.1)
    for r in s.recs:
        if not r.series:
            r.cols["z_re_ohm"] = r.cols["z_re_ohm"] * area
            r.cols["z_im_ohm"] = r.cols["z_im_ohm"] * area


def out_laser_moved_across(s: Session) -> None:
    """At one re-clamping after the first (drawn) the laser's stand is moved to the strip's other side (it was in the
    way of the clamp's knob) and re-aimed at the tip, its reference distance a little different: from that block on the
    displacement reads mirrored (the head counts the distance towards itself as positive) with a new zero (0.05-0.5 mm,
    log, either sign), and nothing in the files says so. Displacement only. Measured (paper_163: from the 1837 kPa
    block, -0.15 mm; p14_165: from the 3062 kPa block, +0.21 mm) displacement residual 176 % and 131 % of its RMS: the
    later blocks' 1 V steps at -8.98 and -1.77 mm."""
    _, t_move = _later_setting(s)
    off = _sign(s) * lu(s.rng, 5e-5, 5e-4)
    map_disp(s, lambda r, d: -d + off if float(r.cols["t_s"][0]) > t_move else d)


FRESH31_FORMS: dict[str, dict[str, Callable[[Session], None]]] = {
    "back_relaxation": {"dry_stored_resoaking": br_dry_stored_resoaking, "stirrer_spells": br_stirrer_spells},
    "faradaic_current": {"marcus_tracer": far_marcus_tracer, "nitrogen_sparge": far_nitrogen_sparge},
    "hysteresis": {"lvdt_core_friction": hy_lvdt_core_friction, "squeezed_root_domains": hy_squeezed_root_domains},
    "time_delay": {"dmm_aperture": td_dmm_aperture, "monitor_rc_filter": td_monitor_rc_filter},
    "sensor_offset": {"rail_clamp_shift": so_rail_clamp_shift,
                      "surface_resistance_sensing": so_surface_resistance_sensing},
    "clamp_relaxation": {"knocked_bench": cr_knocked_bench, "locking_pliers": cr_locking_pliers},
    "dehydration": {"ferric_anode_deposit": dh_ferric_anode_deposit, "surface_oil_slick": dh_surface_oil_slick},
    "strain_resistance": {"dropped_strip": sr_dropped_strip, "glued_target_edge": sr_glued_target_edge},
    "large_deflection": {"encoder_lever": ld_encoder_lever, "radiused_jaw_lips": ld_radiused_jaw_lips},
    "mains_pickup": {"lift_soft_starter": mp_lift_soft_starter, "ferroresonant_regulator": mp_ferroresonant_regulator},
    "unexplained": {"loadcell_ground_loop": out_loadcell_ground_loop,
                    "amplifier_heat_zero": out_amplifier_heat_zero,
                    "area_normalised_spectra": out_area_normalised_spectra,
                    "laser_moved_across": out_laser_moved_across},
}
inject.register_forms(FRESH31_FORMS)


# ------------------------------------------------------------------------------------------------ variants


def v_harmonics_as_free(s: Session) -> None:
    """A lab whose large-signal sine tests are logged by its general-purpose waveform logger (a LabVIEW VI or a script
    that knows nothing of the protocol), not by the frequency-response tool that takes the stepped sines: each harmonic
    record is written as a plain capture, kind "free" (the contract's kind for a time series with any drive), named
    and labelled by the logger's counter ("capture_007.csv", label "capture 007"), with no frequency_Hz, amplitude_V,
    settle_cycles or cycles in the manifest. The samples, the clock and every other record untouched; the drive's
    frequency and amplitude are only in the data. Valid under the import contract (free needs no key but kind, file and
    pressure_kPa); ``labrig import`` takes all four cases and ``labrig export`` writes them back as free records with
    the values bit for bit."""
    n = 0
    for r in s.recs:
        if r.kind == "harmonic":
            n += 1
            r.entry = {"kind": "free", "file": f"capture_{n:03d}.csv", "label": f"capture {n:03d}",
                       "pressure_kPa": r.entry["pressure_kPa"]}


inject.VARIANTS.update({"harmonics_as_free": v_harmonics_as_free})

# ------------------------------------------------------------------------------------------------ the cases

P, S, T = "paper_163", "s001_164", "p14_165"
PLAN = {  # effect: its two forms, each once (form, seed, base, variant); 7 / 6 / 7 effect cases on seeds 163-165
    "back_relaxation": [("dry_stored_resoaking", 163, P, "settled_sines"),
                        ("stirrer_spells", 165, T, "eis_descending")],
    "faradaic_current": [("marcus_tracer", 163, P, "shortened_shuffled"), ("nitrogen_sparge", 165, T, "spectra_last")],
    "hysteresis": [("lvdt_core_friction", 163, P, "measured_pressures"),
                   ("squeezed_root_domains", 164, S, "swinging_door")],
    "time_delay": [("dmm_aperture", 163, P, "dropped_packets"), ("monitor_rc_filter", 165, T, "asrun")],
    "sensor_offset": [("rail_clamp_shift", 165, T, "harmonics_as_free"),
                      ("surface_resistance_sensing", 164, S, "scan_hold")],
    "clamp_relaxation": [("knocked_bench", 164, S, "float32_time"), ("locking_pliers", 163, P, "merged_loadcell")],
    "dehydration": [("ferric_anode_deposit", 165, T, "stop_trigger"), ("surface_oil_slick", 163, P, "split_spectra")],
    "strain_resistance": [("dropped_strip", 165, T, "cycle_averaged"), ("glued_target_edge", 164, S, "log_steps")],
    "large_deflection": [("encoder_lever", 164, S, "coherent_sines"), ("radiused_jaw_lips", 165, T, "fir_decimated")],
    "mains_pickup": [("lift_soft_starter", 163, P, "short_pretrigger"),
                     ("ferroresonant_regulator", 164, S, "harmonics_as_free")],
    "unexplained": [("loadcell_ground_loop", 163, P, "two_pressures"),
                    ("loadcell_ground_loop", 165, T, "eis_two_passes"),
                    ("amplifier_heat_zero", 163, P, "host_timed"), ("amplifier_heat_zero", 165, T, "no_loadcell"),
                    ("area_normalised_spectra", 164, S, "trigger_clock"),
                    ("area_normalised_spectra", 165, T, "block_clock"),
                    ("laser_moved_across", 163, P, "midnight_clock"), ("laser_moved_across", 165, T, "fixed_decimals")],
}
CLEAN = [(163, P, "harmonics_as_free"), (163, P, "tared_records"), (164, S, "loadcell_dropout"),
         (164, S, "reversed_laser"), (165, T, "harmonics_as_free"), (165, T, "no_spectra")]


def fresh31_cases(only: str | None = None) -> list[Case]:
    """The thirty-second held-out set: 20 effect cases (every form once), 8 outside the catalogue, 6 clean (seeds
    163-165)."""
    return inject.plan_cases(PLAN, CLEAN, only)


if __name__ == "__main__":
    inject.make_set_main(fresh31_cases, "inject_fresh31", "fresh31")
