"""Parameter presets: ``paper`` (seed 000's strip in water, Tables 1-3) and ``seed001`` (seed 001's strip in air)."""

from __future__ import annotations

from dataclasses import dataclass, replace

from labrig.physics import hydro
from labrig.physics.clamp import ClampLaw, paper_clamp_law
from labrig.physics.params import (
    AIR_25C,
    TABLE1,
    TABLE3,
    WATER_25C,
    Geometry,
    HammersteinParams,
    LineElectrical,
    Mechanics,
    Specimen,
)

PAPER_PRESSURES_KPA = (612.0, 1837.0, 3062.0, 4287.0)
# Seed 001 gives no clamping pressure. Its clamp is 10 x 5 mm, so seed 000's 3062 kPa would be 153 N, past the
# rig's 90 N safety limit (and the 98 N load cell); 1000 kPa (50 N) sits inside Table 1's range (612-4287 kPa).
SEED001_PRESSURE_KPA = 1000.0


@dataclass(frozen=True)
class Preset:
    name: str
    base: Specimen  # the specimen at ``default_pressure_kPa``
    clamp_law: ClampLaw
    default_pressure_kPa: float
    hammerstein: HammersteinParams
    description: str

    def specimen(self, pressure_kPa: float | None = None, **changes) -> Specimen:
        """The specimen clamped at ``pressure_kPa`` (clamp-area electrical values and K_t bar from the law)."""
        p = (self.default_pressure_kPa if pressure_kPa is None else float(pressure_kPa)) * 1e3
        sp = replace(self.base, clamp=self.clamp_law.clamp_at(p), Kt_bar=self.clamp_law.kt_bar_at(p), pressure=p)
        return replace(sp, **changes) if changes else sp


def line_for_width(width_m: float) -> LineElectrical:
    """The paper's free-strip line (Table 1, least squeezed row) for a strip of the same material ``width_m`` wide."""
    return _line_from_table1(0, width_scale=width_m / PAPER_WIDTH_M)


def _line_from_table1(row_index: int, width_scale: float = 1.0) -> LineElectrical:
    """The free strip's line: seed 000 says the distributed values equal Table 1's; we take the least
    squeezed row (612 kPa). Per-length values scale with width (admittances up, resistances down)."""
    c = TABLE1[row_index].to_si()
    return LineElectrical(
        R_s=c.R_sc / width_scale, R=c.R_c / width_scale, R_p=c.R_pc / width_scale, Q0=c.Q0c * width_scale, n=c.n_c
    )


PAPER_WIDTH_M = 0.004


def _paper() -> Preset:
    geom = Geometry(length=0.030, width=PAPER_WIDTH_M, thickness=0.22e-3, clamp_length=0.004, clamp_width=0.004)
    # density chosen so mu_v(omega_1) = rho A + m_a = 0.02 kg/m (Table 3) at f1 = 3.78 Hz (3062 kPa)
    m_a = float(hydro.added_mass(2 * 3.141592653589793 * 3.78, geom.width, WATER_25C))
    rho = (TABLE3["mu_v"] - m_a) / geom.cross_section
    law = paper_clamp_law()
    base = Specimen(
        geometry=geom,
        fluid=WATER_25C,
        line=_line_from_table1(0),
        clamp=law.clamp_at(3062e3),
        mechanics=Mechanics(
            E=TABLE3["E_MPa"] * 1e6, density=rho, gamma=TABLE3["gamma"], alpha=TABLE3["alpha"], mu_v=TABLE3["mu_v"]
        ),
        Kt_bar=law.kt_bar_at(3062e3),
        pressure=3062e3,
    )
    return Preset("paper", base, law, 3062.0, HammersteinParams(), "seed 000: 30 x 4 x 0.22 mm strip, 4 x 4 mm clamp, water at 25 C")


def _seed001() -> Preset:
    geom = Geometry(length=0.020, width=0.005, thickness=0.20e-3, clamp_length=0.010, clamp_width=0.005)
    paper = _paper()
    law = paper_clamp_law()
    base = replace(
        paper.base,
        geometry=geom,
        fluid=AIR_25C,
        line=line_for_width(geom.width),
        clamp=law.clamp_at(SEED001_PRESSURE_KPA * 1e3),
        mechanics=replace(paper.base.mechanics, density=2000.0, mu_v=None),  # in air: rho A + tiny m_a(omega)
        Kt_bar=law.kt_bar_at(SEED001_PRESSURE_KPA * 1e3),
        pressure=SEED001_PRESSURE_KPA * 1e3,
    )
    return Preset("seed001", base, law, SEED001_PRESSURE_KPA, HammersteinParams(),
                  "seed 001: 20 mm free, 10 mm clamped, 0.2 x 5 mm, in air, clamped at 1000 kPa (50 N)")


_PRESETS = {"paper": _paper, "seed001": _seed001}


def names() -> list[str]:
    return sorted(_PRESETS)


def get(name: str) -> Preset:
    try:
        return _PRESETS[name]()
    except KeyError:
        raise KeyError(f"unknown preset {name!r} (known: {', '.join(names())})") from None
