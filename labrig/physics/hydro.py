"""Fluid loading of a thin rectangular beam: Sader's hydrodynamic function (seed 000, eq. 19-22).

Sign convention (Sader, J. Appl. Phys. 84, 64, 1998): Im Gamma > 0 is dissipative. The fluid force per
unit length is m_a w'' + c_v w' with m_a = m_d Re Gamma and c_v = +m_d omega Im Gamma. Seed 000 prints
c_v = -m_d omega Im Gamma (eq. 19) and xi = (gamma - m_d Im Gamma / mu_v)/2 (eq. 33), which would make
water *reduce* the damping; docs/model.md shows the numbers and why we use the dissipative sign.
"""

from __future__ import annotations

import numpy as np
from numpy.polynomial.polynomial import polyval
from scipy.special import kve

from labrig.physics.params import Fluid

# Sader 1998, eq. 21a/21b: rectangular correction Omega(omega) = Omega_r + i Omega_i, tau = log10(Re).
_OMEGA_R_NUM = (0.91324, -0.48274, 0.46842, -0.12886, 0.044055, -0.0035117, 0.00069085)
_OMEGA_R_DEN = (1.0, -0.56964, 0.48690, -0.13444, 0.045155, -0.0035862, 0.00069085)
_OMEGA_I_NUM = (-0.024134, -0.029256, 0.016294, -0.00010961, 0.000064577, -0.000044510)
_OMEGA_I_DEN = (1.0, -0.59702, 0.55182, -0.18357, 0.079156, -0.014369, 0.0028361)


def reynolds(omega: np.ndarray | float, width: float, fluid: Fluid) -> np.ndarray:
    """Eq. 22: Re = rho_f omega W^2 / (4 mu_f)."""
    return fluid.density * np.asarray(omega, float) * width**2 / (4.0 * fluid.viscosity)


def gamma_circular(re: np.ndarray | float) -> np.ndarray:
    """Hydrodynamic function of a circular cylinder (the bracket of eq. 21)."""
    z = -1j * np.sqrt(1j * np.asarray(re, float))
    # the exponentially scaled K (kve) keeps the ratio finite at large Re, where K itself underflows
    return 1.0 + 4.0 * kve(1, z) / (z * kve(0, z))


def rectangular_correction(re: np.ndarray | float) -> np.ndarray:
    """Lambda_corr(omega) of eq. 21: Sader's Omega(omega), a ratio of polynomials in log10(Re)."""
    tau = np.log10(np.asarray(re, float))
    return polyval(tau, _OMEGA_R_NUM) / polyval(tau, _OMEGA_R_DEN) + 1j * polyval(tau, _OMEGA_I_NUM) / polyval(
        tau, _OMEGA_I_DEN
    )


def gamma_rect(omega: np.ndarray | float, width: float, fluid: Fluid) -> np.ndarray:
    """Eq. 21: Gamma_rect(omega) for a beam of width ``width`` oscillating at ``omega`` (rad/s)."""
    re = reynolds(omega, width, fluid)
    return rectangular_correction(re) * gamma_circular(re)


def displaced_mass(width: float, fluid: Fluid) -> float:
    """Eq. 20: m_d = rho_f (pi/4) W^2 (kg/m)."""
    return fluid.density * np.pi / 4.0 * width**2


def added_mass(omega: np.ndarray | float, width: float, fluid: Fluid) -> np.ndarray:
    """Eq. 19: m_a = m_d Re Gamma (kg/m)."""
    return displaced_mass(width, fluid) * gamma_rect(omega, width, fluid).real


def fluid_damping(omega: np.ndarray | float, width: float, fluid: Fluid) -> np.ndarray:
    """Eq. 19 with Sader's dissipative sign: c_v = +m_d omega Im Gamma (N s/m^2)."""
    return displaced_mass(width, fluid) * np.asarray(omega, float) * gamma_rect(omega, width, fluid).imag
