"""A pinched loop in the displacement path: memory that only acts past a threshold of the bend.

A superelastic wire or fibre bent with the strip (a nitinol core, a shape-memory polymer's fibres), a contact that
only slips once the bend has loaded it, a stop that yields past its own travel: below the threshold the strip reads
as linear; loaded past x_f the element transforms (or slips) at a constant force, a soft plateau, and the reading
gains w per unit of bend beyond it, up to the element's full travel E; unloaded it holds until the bend comes back
down to x_r < x_f, and returns along the lower plateau. The loop is flag-shaped on each side of rest, pinched at
zero (no remanent bend), rate-independent. On each side it is a play of half-width (x_f - x_r)/2 on the bend less its
centre (x_f + x_r)/2, clipped to [0, E]:

    y = d + w (S(d) - S(-d)),  S(x) = clip(play_r(x - x_c), 0, E),  x_c = (x_f + x_r)/2, r = (x_f - x_r)/2

(on loading from rest the play follows x - x_f, on unloading x - x_r: ``catalogue._play``). The sines by their
periodic state over a cycle (fundamental and 3rd harmonic, as ``catalogue._play_df``), the step's prediction read
through it as it stands.
"""

from __future__ import annotations

import numpy as np

from labrig.diagnose.catalogue import Context, _drive, _play, baseline

# the largest x_r / x_f: a flag whose return threshold is within a fifth of its forward one has hardly a loop, and a
# memoryless knee in the reading (a laser's linearisation table run out, a stop) fits it as well: with it free to 1,
# fresh26's table knee (a large deflection) and fresh21's dead pixel (outside the catalogue) read as hysteresis at
# 0.986 and 1.000, while the memories the flag was right on read 0.00-0.51 (seen sets; docs/diagnosis.md)
REVERSE_SHARE_MAX = 0.8
_N = 64  # points per cycle of the sines' periodic state
_CYCLES = 2  # the first cycle settles the plays from rest, the second is read


def flag_reading(d: np.ndarray, w: float, x_f: float, x_r: float, travel: float) -> np.ndarray:
    """The reading of bend ``d`` (m) through the pinched loop, from rest."""
    x_c, r = 0.5 * (x_f + x_r), 0.5 * (x_f - x_r)
    d = np.asarray(d, float)
    side = lambda x: np.clip(_play(x - x_c, r), 0.0, travel)  # noqa: E731
    return d + w * (side(d) - side(-d))


def flag_df(a: np.ndarray, w: float, x_f: float, x_r: float, travel: float) -> tuple[np.ndarray, np.ndarray]:
    """Describing function of the reading's change at sine amplitudes ``a``: its fundamental and 3rd harmonic over
    the amplitude (complex, cosine phase), in the periodic state."""
    th = 2 * np.pi * np.arange(_CYCLES * _N) / _N
    n1, n3 = np.zeros(len(a), complex), np.zeros(len(a), complex)
    for k, ak in enumerate(np.atleast_1d(a)):
        if ak <= x_f:
            continue  # never past the threshold: nothing but the linear reading
        y = flag_reading(ak * np.cos(th), w, x_f, x_r, travel)[-_N:] - ak * np.cos(th[-_N:])
        c = np.fft.rfft(y) / _N * 2
        n1[k], n3[k] = c[1] / ak, c[3] / ak
    return n1, n3


def flag_output(th, ctx: Context):
    """``flag_reading`` on the displacement: weight w, thresholds x_f (um) and x_r = share x_f, travel E (um)."""
    w, x_f_um, share, travel_um = th
    x_f, travel = x_f_um * 1e-6, travel_um * 1e-6
    x_r = share * x_f
    p = baseline(ctx)
    if ctx.sines:
        y = p.Hd * np.array([_drive(s) for s in ctx.sines])
        a = np.abs(y)
        n1, n3 = flag_df(a, w, x_f, x_r, travel)
        g1 = 1 + n1
        p.hd[:, 1] = p.hd[:, 1] + n3 / g1 * (y / np.where(a > 0, a, 1.0)) ** 2
        p.Hd = p.Hd * g1
    for k, d in enumerate(p.step_d):
        p.step_d[k] = flag_reading(d, w, x_f, x_r, travel)
    return p


def largest_bend(ctx: Context) -> float:
    """The largest bend (m) the steps or sines read (0.1 mm at least)."""
    return max([float(np.max(np.abs(st.d))) for st in ctx.steps if np.size(st.d)] +
               [abs(complex(h * _drive(s))) for s, h in zip(ctx.sines, ctx.Hd)] + [1e-4])


def flag_start(ctx: Context) -> np.ndarray:
    """A start read off the data: the threshold at 0.4 of the largest bend the steps or sines read, the reverse at
    half of it, the travel that bend (a loop that opens within the records)."""
    big = largest_bend(ctx)
    return np.array([0.05, 0.4 * big * 1e6, 0.5, big * 1e6])
