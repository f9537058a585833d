"""Time responses of any linear transfer function H(s) to any sampled drive, accurate against H(j omega).

Method: the exponential window (numerical inverse Laplace transform on the line Re s = sigma). The drive
u(t), at rest before t = 0 and zero-padded, is multiplied by exp(-sigma t), transformed with an FFT, multiplied
by H(sigma + j omega_k), transformed back and multiplied by exp(sigma t). Because H is evaluated right of its
singularities, this is exact for any causal H, including the fractional CPE (s^n), the distributed line
(sqrt N) and the 1/s of charge, which make an ordinary FFT convolution wrap around; sigma is chosen so the
wrapped part is damped by exp(-sigma T_fft) = 1e-9.

The drive samples are read as a band-limited signal, so a record analysed back by DFT at its own bins
returns H(j omega) exactly (tests/test_physics_transfer.py). H is evaluated exactly on the lowest bins and
on a logarithmic grid above, interpolated with a cubic spline (error < 1e-7 relative), which keeps 600 s
at 1 kHz under a second.
"""

from __future__ import annotations

from typing import Callable, Sequence

import numpy as np
from scipy import fft as sfft
from scipy.interpolate import CubicSpline

TransferFunction = Callable[[np.ndarray], np.ndarray]

DAMPING = 1e9  # exp(sigma T_fft): how far the response's wrapped-around part is attenuated
_EXACT_BINS = 256
_PER_DECADE = 160


def _grid_values(tfs: Sequence[TransferFunction], s_bins: np.ndarray) -> list[np.ndarray]:
    """Each H at s_bins: exact for the first bins, spline in log(omega) above."""
    n = len(s_bins)
    if n <= 4 * _EXACT_BINS:
        return [np.asarray(tf(s_bins), complex) for tf in tfs]
    sigma = s_bins[0].real
    w = s_bins.imag
    w_lo, w_hi = w[_EXACT_BINS - 1], w[-1]
    decades = np.log10(w_hi / w_lo)
    w_log = np.geomspace(w_lo, w_hi, max(int(decades * _PER_DECADE), 8))
    out = []
    for tf in tfs:
        exact = np.asarray(tf(s_bins[:_EXACT_BINS]), complex)
        h_log = np.asarray(tf(sigma + 1j * w_log), complex)
        spline = CubicSpline(np.log(w_log), np.stack([h_log.real, h_log.imag], axis=1))
        rest = spline(np.log(w[_EXACT_BINS:]))
        out.append(np.concatenate([exact, rest[:, 0] + 1j * rest[:, 1]]))
    return out


def transfer_grid(tfs: Sequence[TransferFunction], n: int, fs: float, pad: float = 1.0,
                  damping: float = DAMPING) -> tuple[int, float, list[np.ndarray]]:
    """(nfft, sigma, each H on the grid) for drives of n samples at fs: what ``respond`` needs, computed once for
    any number of drives of that length (a fit that changes only the drive reuses it). ``damping``: exp(sigma
    T_fft); the numerical error at time t comes back lifted by damping^(t / T_fft) (docs/model.md 6)."""
    nfft = sfft.next_fast_len(int(n * (1.0 + pad)) + 16, real=True)
    sigma = np.log(damping) / (nfft / fs)
    return nfft, sigma, _grid_values(tfs, grid_s(nfft, sigma, fs))


def grid_s(nfft: int, sigma: float, fs: float) -> np.ndarray:
    """The Laplace variable at the bins of a ``transfer_grid``: sigma + j omega_k."""
    return sigma + 2j * np.pi * sfft.rfftfreq(nfft, 1.0 / fs)


def respond(u: np.ndarray, fs: float, grid: tuple[int, float, list[np.ndarray]]) -> list[np.ndarray]:
    """Responses to the drive u (at rest at t = 0) of the transfer functions on ``grid`` (``transfer_grid``)."""
    u = np.asarray(u, float)
    n = u.size
    nfft, sigma, Hs = grid
    if n == 0:
        return [np.zeros(0) for _ in Hs]
    t = np.arange(n) / fs
    U = sfft.rfft(u * np.exp(-sigma * t), nfft)
    grow = np.exp(sigma * t)
    return [sfft.irfft(U * H, nfft)[:n] * grow for H in Hs]


def simulate_many(tfs: Sequence[TransferFunction], u: np.ndarray, fs: float, pad: float = 1.0,
                  damping: float = DAMPING) -> list[np.ndarray]:
    """Responses of several transfer functions to the same drive ``u`` sampled at ``fs`` (system at rest at t=0).

    ``pad``: zero padding as a fraction of the record (1.0 doubles it) so the response's own tail has room;
    ``damping``: ``transfer_grid``'s.
    """
    u = np.asarray(u, float)
    if u.size == 0:
        return [np.zeros(0) for _ in tfs]
    return respond(u, fs, transfer_grid(tfs, u.size, fs, pad, damping))


def simulate(tf: TransferFunction, u: np.ndarray, fs: float, pad: float = 1.0, damping: float = DAMPING) -> np.ndarray:
    """Response of one transfer function H(s) to the drive ``u`` (see module docstring)."""
    return simulate_many([tf], u, fs, pad, damping)[0]
