"""The effect catalogue (DESIGN.md 5) as hidden effects of the simulated bench.

Each class is one catalogue name. Effects that change the measured signals work on the bench's
``RecordWindow`` (remembered drive history + record + tail at rest), so filters, delays and hysteresis
see the history the strip has actually lived through, and effects later in the list build on the
result of earlier ones. ``order`` puts combinations in physical order: strip physics, then geometry of
the measurement, then the sensor channel, then pickup. Strength ranges and their reasons: docs/effects.md.
The truth (which effect, its parameters) lives only in these objects, in the bench's process.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np
from scipy import fft as sfft
from scipy import signal

from labrig.physics import hammerstein, transfer
from labrig.physics.params import Specimen
from mock_devices.world import World, Effect, RecordWindow, window_response


class WindowEffect(Effect):
    """An effect on the measured signals, applied to the whole record window (history included)."""

    order = 50

    def transform(self, w: RecordWindow, bench: World) -> tuple[np.ndarray, np.ndarray]:
        """New (displacement, current) over the window."""
        return w.displacement, w.current

    def outputs(self, out: dict[str, np.ndarray], t: np.ndarray, v: np.ndarray, bench: World) -> dict[str, np.ndarray]:
        w = bench.window
        assert w is not None, "outputs() is called by World.run_record after it sets the window"
        d1, c1 = self.transform(w, bench)
        # add only this effect's change, so changes other (non-window) effects made to `out` survive
        dd, dc = w.record(d1 - w.displacement), w.record(c1 - w.current)
        w.displacement, w.current = d1, c1
        return {**out, "disp_m": out["disp_m"] + dd, "i_A": out["i_A"] + dc}


# ---------------------------------------------------------------------------------------- strip physics
@dataclass(repr=False)
class FaradaicCurrent(WindowEffect):
    """Electrolysis / nonlinear conductance in parallel with the strip: i += i_nl(V), no bending.

    Law from labrig.physics.hammerstein (g1 = 0): ``butler_volmer`` 2 i0 sinh(V/(2 v_t)) with
    v_t 0.12-0.25 V, or ``poly`` g3 V^3; scaled so i_nl(1 V) = 0.1-0.6 mA. The analyser sees its
    small-signal conductance d i_nl/dV at its bias.
    """

    law: str
    params: dict[str, float]
    name = "faradaic_current"
    order = 10

    def i_nl(self, v: np.ndarray) -> np.ndarray:
        return hammerstein.LAWS[self.law].i_nl(np.asarray(v, float), {"g1": 0.0, **self.params})

    def transform(self, w: RecordWindow, bench: World) -> tuple[np.ndarray, np.ndarray]:
        return w.displacement, w.current + self.i_nl(w.u)

    def impedance(self, z: np.ndarray, f: np.ndarray, bench: World) -> np.ndarray:
        h = 1e-4  # the analyser's bias is 0 V in every protocol, so the conductance is the slope at 0
        g0 = float((self.i_nl(np.array([h])) - self.i_nl(np.array([-h])))[0] / (2 * h))
        return 1.0 / (1.0 / z + g0)


def play(u: np.ndarray, r: np.ndarray) -> np.ndarray:
    """Play (backlash) operators of thresholds ``r`` on ``u`` from rest, shape (len(u), len(r)).

    Rate-independent, so on each monotone run of u the recursion y_k = clip(y_{k-1}, u_k - r, u_k + r)
    collapses to a clip of the run's starting state: a loop over runs, vectorised within each.
    """
    y = np.empty((u.size, r.size))
    state = np.zeros(r.size)
    d = np.sign(np.diff(u))
    nz = np.flatnonzero(d)
    if nz.size:  # flats take the direction of the last move, so a plateau never splits a run
        d = d[nz[np.maximum(np.searchsorted(nz, np.arange(d.size), side="right") - 1, 0)]]
    ends = np.concatenate([np.flatnonzero(d[1:] != d[:-1]) + 1, [u.size - 1]])  # turning points
    a = 0
    for b in ends:
        seg = u[a : b + 1, None]
        y[a : b + 1] = np.clip(state, seg - r, seg + r)
        state = y[b]
        a = b + 1
    return y


@dataclass(repr=False)
class Hysteresis(WindowEffect):
    """Rate-independent memory of the electromechanical coupling (Prandtl-Ishlinskii).

    delta = H(s) Gamma[V], Gamma[V] = (1 - h) V + h mean_i play_{r_i}[V], r_i evenly over (0, r_max]:
    h 0.3-0.6, r_max 0.3-0.6 V. The current does not see it (the loop is in charge -> strain).
    """

    h: float
    r_max: float
    n_plays: int = 8
    name = "hysteresis"
    order = 20

    def gamma(self, u: np.ndarray) -> np.ndarray:
        r = self.r_max * (np.arange(self.n_plays) + 0.5) / self.n_plays
        return (1 - self.h) * u + self.h * play(u, r).mean(axis=1)

    def transform(self, w: RecordWindow, bench: World) -> tuple[np.ndarray, np.ndarray]:
        du = self.gamma(w.u) - w.u
        sp = w.specimen
        return w.displacement + window_response([lambda s: transfer.displacement_tf(s, sp)], du, w.fs)[0], w.current


@dataclass(repr=False)
class StrainResistance(WindowEffect):
    """Electrode cracking: each electrode's surface resistance R_s grows with its tensile strain.

    Strain e = kappa h/2 with the uniform-curvature reading kappa = 2 delta/x_m^2; the electrode in
    tension (delta > 0: electrode A) gains dR/R = G_A e, the other G_B |e|, G_A 50-250, G_B/G_A 0-0.3
    (plated Pt cracks open on the convex side). With eps(t) = (dR_A + dR_B)/(2 R) the signals follow the
    first-order parameter-varying expansion y = H v + eps(t) (dH/dln R_s) v (same for the current):
    amplitude-dependent phase, and even harmonics because G_A != G_B.
    """

    gauge_pos: float
    gauge_neg: float
    name = "strain_resistance"
    order = 25

    def eps(self, disp: np.ndarray, sp: Specimen) -> np.ndarray:
        e = disp * sp.geometry.thickness / sp.x_sensor**2  # kappa h / 2 with kappa = 2 delta / x^2
        return 0.5 * (self.gauge_pos * np.clip(e, 0, None) + self.gauge_neg * np.clip(-e, 0, None))

    def transform(self, w: RecordWindow, bench: World) -> tuple[np.ndarray, np.ndarray]:
        sp, k = w.specimen, 0.01

        def at(scale: float) -> Specimen:
            return sp.with_(line=replace(sp.line, R_s=sp.line.R_s * scale))

        def sens(tf):  # d tf / d ln R_s, central difference
            return lambda s: (tf(s, at(1 + k)) - tf(s, at(1 - k))) / (2 * k)

        sd, si = window_response([sens(transfer.displacement_tf), sens(transfer.admittance_tf)], w.u, w.fs)
        eps = self.eps(w.displacement, sp)
        return w.displacement + eps * sd, w.current + eps * si


def _lowpass(x: np.ndarray, tau: float, fs: float) -> np.ndarray:
    """1/(tau s + 1), bilinear at fs, from rest (the window starts with the strip at rest)."""
    b, a = signal.bilinear([1.0], [tau, 1.0], fs)
    return signal.lfilter(b, a, x)


@dataclass(repr=False)
class BackRelaxation(WindowEffect):
    """Slow opposing water flux: delta = H(s) (1 - K2/(tau2 s + 1)), K2 0.9-1.4, tau2 3-12 s.

    The slow flux follows the fast bending with lag tau2 and opposes it; K2 > 1 reverses a long step
    (Nafion-Na+). Equivalent to DESIGN's H (1 - K' tau2 s/(tau2 s + 1)) with K' = -K2/(1 - K2) times a
    gain (1 - K2); see docs/effects.md for why the sign is taken this way. Filtered over the window, so the
    slow flux from earlier records carries into this one.
    """

    K2: float
    tau2: float
    name = "back_relaxation"
    order = 30

    def transform(self, w: RecordWindow, bench: World) -> tuple[np.ndarray, np.ndarray]:
        return w.displacement - self.K2 * _lowpass(w.displacement, self.tau2, w.fs), w.current


@dataclass(repr=False)
class Dehydration(Effect):
    """Water loss: alpha(t) = alpha0 exp(-t/tau), tau 1500-5000 s of bench time; the line's CPE Q0 and
    leak conductance 1/R_p fall as exp(-beta t/tau), beta 0.3-1 (less mobile water, fewer mobile ions)."""

    tau: float
    beta: float
    name = "dehydration"

    def specimen(self, sp: Specimen, t: float, bench: World) -> Specimen:
        t = max(t, 0.0)
        a, c = math.exp(-t / self.tau), math.exp(-self.beta * t / self.tau)
        return sp.with_(
            mechanics=replace(sp.mechanics, alpha=sp.mechanics.alpha * a),
            line=replace(sp.line, Q0=sp.line.Q0 * c, R_p=sp.line.R_p / c),
        )


# ------------------------------------------------------------------------------ clamp and measurement
@dataclass(repr=False)
class ClampRelaxation(Effect):
    """Nafion creeps under the clamp: the motor servoes the force for ``servo_s`` after a setting (long
    enough for the runner's clamp check), then holds position and the force relaxes as
    p0 (1 - r (1 - exp(-(t - t_hold)/tau))), r 5-20 %, tau 200-1000 s. The bench's specimen follows the
    force (R_cont, K_t bar), so gain and f1 drift during the records that follow."""

    r: float
    tau: float
    servo_s: float = 60.0
    name = "clamp_relaxation"

    def force(self, f: float, t: float, bench: World) -> float:
        held = t - bench.clamp_set_at - self.servo_s
        return f * (1.0 - self.r * -math.expm1(-max(held, 0.0) / self.tau))


@dataclass(repr=False)
class SensorOffset(Effect):
    """The laser spot at x_m = 0.6-0.9 L instead of the tip: the world reads w(x_m) (poles stay)."""

    fraction: float
    name = "sensor_offset"

    def specimen(self, sp: Specimen, t: float, bench: World) -> Specimen:
        return sp.with_(sensor_x=self.fraction * sp.geometry.length)


@dataclass(repr=False)
class LargeDeflection(WindowEffect):
    """Geometric nonlinearity: the laser reads the height of the bent strip's material point, not the
    linear w. Curvature is uniform over the first lam*L (lam 0.6-1) and the rest is straight; the
    linear reading fixes the rotation theta = delta/(x - l/2), the arc gives
    l (1 - cos theta)/theta + (x - l) sin theta = delta - c delta^3/x^2 + ..., c = 1/6 (lam -> 0) to 1/3."""

    lam: float
    name = "large_deflection"
    order = 40

    def measured(self, d: np.ndarray, x: float) -> np.ndarray:
        ell = min(self.lam * x, x)
        th = d / (x - ell / 2)
        small = np.abs(th) < 1e-4
        ths = np.where(small, 1.0, th)
        arc = np.where(small, ell * th / 2, ell * (1 - np.cos(ths)) / ths)
        return arc + (x - ell) * np.sin(th)

    def transform(self, w: RecordWindow, bench: World) -> tuple[np.ndarray, np.ndarray]:
        return self.measured(w.displacement, w.specimen.x_sensor), w.current


@dataclass(repr=False)
class TimeDelay(WindowEffect):
    """Skew of the displacement channel (laser controller averaging): delta(t - tau), tau 5-40 ms.

    Fractional delay by FFT over the window after removing the end-to-end ramp (so the periodic
    extension has no jump); the ramp is delayed exactly. Gain unchanged, phase -360 f tau degrees.
    """

    tau: float
    name = "time_delay"
    order = 50

    def transform(self, w: RecordWindow, bench: World) -> tuple[np.ndarray, np.ndarray]:
        x = w.displacement
        n = x.size
        ramp = x[0] + (x[-1] - x[0]) * np.arange(n) / max(n - 1, 1)
        X = sfft.rfft(x - ramp) * np.exp(-2j * np.pi * sfft.rfftfreq(n, 1 / w.fs) * self.tau)
        slope = (x[-1] - x[0]) / max(n - 1, 1) * w.fs
        return sfft.irfft(X, n) + ramp - slope * self.tau, w.current


@dataclass(repr=False)
class MainsPickup(WindowEffect):
    """Line-frequency interference on the analog lines: a tone at f_line (50 or 60 Hz, +-0.05 Hz) and a
    weaker 3rd harmonic, phase locked to bench time. Displacement 1-5 um (0.5-2.5 mV at 2 mm/V),
    current 2-10 uA (0.2-1 mV at 10 mA/V); 3rd harmonic 0.1-0.4 of the fundamental. Sampled as the
    DAQ samples it (aliases where fs < 2 f)."""

    f_line: float
    amp_disp: float
    amp_cur: float
    third: float
    phases: tuple[float, float, float, float]
    name = "mains_pickup"
    order = 60

    def _tone(self, t: np.ndarray, amp: float, p1: float, p3: float) -> np.ndarray:
        w = 2 * np.pi * self.f_line
        return amp * (np.sin(w * t + p1) + self.third * np.sin(3 * w * t + p3))

    def transform(self, w: RecordWindow, bench: World) -> tuple[np.ndarray, np.ndarray]:
        t, p = w.t, self.phases
        return w.displacement + self._tone(t, self.amp_disp, p[0], p[1]), w.current + self._tone(t, self.amp_cur, p[2], p[3])


CATALOGUE: dict[str, type[Effect]] = {
    cls.name: cls
    for cls in (BackRelaxation, FaradaicCurrent, Hysteresis, TimeDelay, SensorOffset, ClampRelaxation, Dehydration, StrainResistance, LargeDeflection, MainsPickup)
}
