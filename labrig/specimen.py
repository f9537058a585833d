"""The strip on the bench and who ran it: the ``[sample]`` of a rig file, or ``labrig run --sample FILE.toml``.

A specimen file (DESIGN.md 6) holds the import manifest's ``[specimen]`` table (geometry in SI, medium)
plus ``name`` (required) and optional ``temperature_C``, ``batch`` and ``notes``, and an ``[operator]``
table (``name``, optional ``notes``)::

    [specimen]
    name = "strip-B7"
    length_m = 0.030
    width_m = 0.005
    thickness_m = 0.0002
    clamp_area_m2 = 2.5e-5
    medium = "water"
    temperature_C = 22.5
    batch = "2026-11 Nafion 117"

    [operator]
    name = "A. Researcher"

A rig file carries the same tables as ``[sample.specimen]`` and ``[sample.operator]``; without them its
``[sample] preset`` (default "paper") names the strip. The specimen is stored in ``/entry/sample``, the
operator in ``/entry/user`` (NeXus NXsample, NXuser); the clamp force of each pressure and the fit's
geometry come from it.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Literal

from pydantic import Field, ValidationError

from labrig.errors import validation_error
from labrig.safe_read import read_text_file
from labrig.validation import LongText, NonEmptyText, StrictModel, Text

MAX_SPECIMEN_FILE_BYTES = 1 << 20


class Specimen(StrictModel):
    """The strip's geometry and medium: an import manifest's ``[specimen]`` (DESIGN.md 6), in SI."""

    length_m: float = Field(gt=0, lt=1)
    width_m: float = Field(gt=0, lt=1)
    thickness_m: float = Field(gt=0, lt=0.01)
    clamp_area_m2: float = Field(gt=0, lt=0.01)
    medium: Literal["water", "air"]


class SpecimenCfg(Specimen):
    """The import manifest's ``[specimen]`` plus what names the strip and its conditions (strict: labrig.validation)."""

    name: NonEmptyText
    temperature_C: float | None = Field(None, gt=-273.15, lt=200)
    batch: Text | None = None
    notes: LongText | None = None


class OperatorCfg(StrictModel):
    name: NonEmptyText
    notes: LongText | None = None


class SpecimenFile(StrictModel):
    specimen: SpecimenCfg
    operator: OperatorCfg | None = None


def load_specimen_file(path: str | Path) -> SpecimenFile:
    """Read and check a specimen file; ``BadInput`` (exit 2) naming the file and the field."""
    data = read_text_file(path, "specimen file", MAX_SPECIMEN_FILE_BYTES, toml=True)
    try:
        return SpecimenFile.model_validate(data)
    except ValidationError as exc:
        raise validation_error(exc, str(path)) from None


def sample_record(spec: SpecimenCfg) -> dict[str, Any]:
    """What ``/entry/sample`` holds for a described strip (no preset: the fit takes this geometry)."""
    return {k: v for k, v in spec.model_dump().items() if v is not None}


def user_record(op: OperatorCfg | None) -> dict[str, Any]:
    return {} if op is None else {k: v for k, v in op.model_dump().items() if v is not None}
