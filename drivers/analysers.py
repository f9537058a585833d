"""The impedance analyser drivers by model (drivers.analyser_models): the one place a new analyser is registered."""

from __future__ import annotations

from typing import Any

from drivers.analyser_models import get
from drivers.hioki_im3590 import HiokiIM3590
from drivers.impedance_analyzer import ImpedanceAnalyzer

DRIVERS = {"IM3590": HiokiIM3590}  # dialect -> driver; every other dialect speaks the E4990A-style SCPI of ImpedanceAnalyzer


def open_analyser(resource: str | Any, model: str, **kwargs: Any) -> Any:
    """The driver for ``model`` on ``resource`` (a VISA name or an open resource such as ``ReplayMessages``)."""
    return DRIVERS.get(get(model).dialect, ImpedanceAnalyzer)(resource, model=model, **kwargs)
