"""Named, typed model parameters in SI units.

Units used throughout (the interpretation of seed 000's Table 1 is in docs/model.md, section 2):

* per-unit-length line parameters of one strip of width W: R_s in ohm/m (per electrode), the shunt
  branch resistances R and R_p in ohm*m, the CPE coefficient Q0 in S*s^n/m;
* clamp-area values with the same per-length units, lumped over the clamp length ``clamp_length``;
  the contact resistance as a specific (area) resistance in ohm*m^2, lumped over the clamp area.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import ClassVar, Literal

import numpy as np


@dataclass(frozen=True)
class Fluid:
    name: str
    density: float  # kg/m^3
    viscosity: float  # Pa*s (dynamic)


WATER_25C = Fluid("water", 997.0, 0.89e-3)
AIR_25C = Fluid("air", 1.184, 1.849e-5)


@dataclass(frozen=True)
class Geometry:
    length: float  # m, free length L (x = 0 at the clamp edge)
    width: float  # m, W
    thickness: float  # m, h
    clamp_length: float  # m, extent of the clamp along the strip
    clamp_width: float  # m

    @property
    def clamp_area(self) -> float:
        return self.clamp_length * self.clamp_width

    @property
    def second_moment(self) -> float:
        """I = W h^3 / 12 (m^4)."""
        return self.width * self.thickness**3 / 12.0

    @property
    def cross_section(self) -> float:
        return self.width * self.thickness


@dataclass(frozen=True)
class LineElectrical:
    """Distributed RC line with a CPE shunt branch (seed 000, fig. 2, eq. 2-4), per unit length."""

    R_s: float  # ohm/m, surface resistance of one electrode
    R: float  # ohm*m, resistance in series with the CPE
    R_p: float  # ohm*m, leak (bulk) resistance
    Q0: float  # S*s^n/m, CPE coefficient (eq. 1)
    n: float  # CPE index, 0 < n <= 1


@dataclass(frozen=True)
class ClampElectrical:
    """Clamp-area values of Table 1 (seed 000), in SI per-length / specific units."""

    r_cont: float  # ohm*m^2, specific contact resistance of one electrode/clamp interface
    R_sc: float  # ohm/m
    R_c: float  # ohm*m
    R_pc: float  # ohm*m
    Q0c: float  # S*s^n/m
    n_c: float


@dataclass(frozen=True)
class Mechanics:
    E: float  # Pa, static Young's modulus
    density: float  # kg/m^3 of the IPMC (Nafion + platinum)
    gamma: float  # viscoelastic coefficient of eq. 23 (dimensionless)
    alpha: float  # J/C, stress per charge density (eq. 15)
    mu_v: float | None = None  # kg/m: fixed mass per length (Table 3 practice); None = rho A + m_a(omega) (Sader)


@dataclass(frozen=True)
class Specimen:
    """Everything the seed-000 model needs for one strip in one clamp state."""

    geometry: Geometry
    fluid: Fluid
    line: LineElectrical
    clamp: ClampElectrical
    mechanics: Mechanics
    Kt_bar: float  # non-dimensional torsional spring k_t L / (E I), eq. 31
    pressure: float | None = None  # Pa, clamping pressure this state belongs to (None: not from a law)
    n_modes: int = 10
    sensor_x: float | None = None  # m, laser spot position; None = the tip (x = L)
    # m: the sensor reads a rigid flag or target fixed to the strip at sensor_x, this far beyond it along the strip's
    # tangent: w(x) + lever w'(x) (a reflective tab past the tip, docs/diagnosis.md "Families"); 0 = the strip itself
    sensor_lever: float = 0.0
    charge: Literal["capacitive", "total"] = "capacitive"  # which current charges the strip, docs/model.md 4.2
    modal_force: Literal["virtual_work", "paper"] = "virtual_work"  # docs/model.md 4.3

    def with_(self, **changes) -> "Specimen":
        return replace(self, **changes)

    @property
    def x_sensor(self) -> float:
        return self.geometry.length if self.sensor_x is None else self.sensor_x


@dataclass(frozen=True)
class Table1Row:
    """One row of seed 000 Table 1 exactly as printed (mixed units)."""

    pressure_kPa: float
    R_cont_mohm_cm2: float
    R_sc_ohm_per_cm: float
    R_c_ohm_cm: float
    R_pc_ohm_cm: float
    Q0c_per_cm: float
    n_c: float

    def to_si(self) -> ClampElectrical:
        return ClampElectrical(
            r_cont=self.R_cont_mohm_cm2 * 1e-3 * 1e-4,  # mohm*cm^2 -> ohm*m^2
            R_sc=self.R_sc_ohm_per_cm * 100.0,  # ohm/cm -> ohm/m
            R_c=self.R_c_ohm_cm * 0.01,  # ohm*cm -> ohm*m
            R_pc=self.R_pc_ohm_cm * 0.01,
            Q0c=self.Q0c_per_cm * 100.0,  # S*s^n/cm -> S*s^n/m
            n_c=self.n_c,
        )


TABLE1 = (
    Table1Row(612, 54.1281, 22.53, 7.5, 2.529e4, 0.0021, 0.58),
    Table1Row(1837, 43.12, 22.53, 11.26, 3.35e4, 0.0015, 0.64),
    Table1Row(3062, 38.75, 22.53, 14.0, 3.83e4, 0.0011, 0.63),
    Table1Row(4287, 40.5, 22.53, 13.25, 2.24e4, 0.0012, 0.65),
)

# Table 2: first natural frequency (Hz) and K_t bar per clamping pressure (kPa).
TABLE2_PRESSURE_KPA = (612.0, 1837.0, 3062.0, 4287.0)
TABLE2_F1_HZ = (3.29, 3.54, 3.78, 3.29)
TABLE2_KT_BAR = (4.17, 5.67, 8.02, 4.17)

# Table 3: E (MPa), xi_1, mu_v (kg/m), gamma, alpha (J/C).
TABLE3 = {"E_MPa": 313.0, "xi1": 0.18, "mu_v": 0.02, "gamma": 0.14, "alpha": 0.105}


@dataclass(frozen=True)
class HammersteinParams:
    """Seed 001 grey box (its Fig. 2): a nonlinear electric stage V_in -> I_abs, then a linear I_abs -> delta stage.

    Electric stage (seed 001 Fig. 3, DESIGN.md 4): R_s in series with [C_dl(v) || i_nl(v)], state v = v_c;
    the nonlinear law ``law`` is one of labrig.physics.hammerstein.LAWS, which lists the parameters it uses.
    Mechanical stage: delta(s) = K/(s + eps) * wn^2/(s^2 + 2 zeta wn s + wn^2) * I_abs(s).
    Defaults: seed 001's 20 x 5 x 0.2 mm strip in air (a few mA/V, first mode 25 Hz, ~0.5 mm/V slow).
    """

    law: Literal["poly", "butler_volmer", "varcap"] = "poly"
    R_s: float = 150.0  # ohm, electrode + contact series resistance
    C_dl: float = 2e-3  # F, double-layer capacitance (tau = R_s C_dl = 0.3 s)
    g1: float = 5e-4  # S, linear leak (all laws)
    g3: float = 1e-3  # A/V^3 (= S/V^2), cubic conductance (poly)
    i0: float = 2e-4  # A, exchange current (butler_volmer)
    v_t: float = 0.25  # V, effective thermal voltage n R T / F of the sinh branch (butler_volmer)
    c2: float = 0.3  # 1/V^2, C(v) = C_dl (1 + c2 v^2) (varcap)
    K: float = 0.25  # m/C = m/(A s), bending per charge of the leaky integrator
    eps: float = 0.2  # 1/s, integrator leak (back-relaxation)
    wn: float = 2 * math.pi * 25.0  # rad/s, first mode in air
    zeta: float = 0.05  # damping ratio of the first mode

    # (lower, upper, scale): the box searched by labrig.fit.hammerstein; "log" = searched in log x.
    BOUNDS: ClassVar[dict[str, tuple[float, float, str]]] = {
        "R_s": (5.0, 2000.0, "log"),
        "C_dl": (1e-4, 5e-2, "log"),
        "g1": (1e-6, 1e-2, "log"),
        "g3": (0.0, 2e-2, "lin"),
        "i0": (1e-6, 1e-2, "log"),
        "v_t": (0.02, 2.0, "log"),
        "c2": (0.0, 5.0, "lin"),
        "K": (1e-3, 1e2, "log"),
        "eps": (1e-3, 10.0, "log"),
        "wn": (2 * math.pi * 2.0, 2 * math.pi * 300.0, "log"),
        "zeta": (0.005, 0.8, "log"),
    }

    def vector(self, names: tuple[str, ...] | list[str]) -> np.ndarray:
        """The values of ``names`` as a float vector (the column order of simulate_batch's theta)."""
        return np.array([float(getattr(self, n)) for n in names])

    def with_vector(self, names: tuple[str, ...] | list[str], values) -> "HammersteinParams":
        """A copy with ``names`` set from ``values`` (inverse of :meth:`vector`)."""
        return replace(self, **{n: float(x) for n, x in zip(names, values, strict=True)})

    def as_dict(self, names: tuple[str, ...] | list[str]) -> dict[str, float]:
        return {n: float(getattr(self, n)) for n in names}
