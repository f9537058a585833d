"""Small pieces shared by the commands: variadic options, JSON and CSV output."""

from __future__ import annotations

import csv
import json
import sys
from pathlib import Path
from typing import Any, Iterable, Sequence

import click
import numpy as np

from labrig.errors import BadInput
from labrig.jsonable import jsonable


class MultiValueOption(click.Option):
    """An option that takes every following value up to the next option: ``--kt 4.17 5.67 8.02``."""

    def __init__(self, *args: Any, **kwargs: Any):
        kwargs.setdefault("multiple", True)
        super().__init__(*args, **kwargs)

    def add_to_parser(self, parser: Any, ctx: click.Context) -> None:
        super().add_to_parser(parser, ctx)
        for name in self.opts:
            opt = parser._long_opt.get(name) or parser._short_opt.get(name)
            if opt is None:
                continue
            original = opt.process

            def process(value: Any, state: Any, _orig=original) -> None:
                values = [value]
                while state.rargs and not state.rargs[0].startswith("--"):
                    values.append(state.rargs.pop(0))
                for v in values:
                    _orig(v, state)

            opt.process = process


def print_json(obj: Any) -> None:
    sys.stdout.write(json.dumps(jsonable(obj), indent=2) + "\n")


def write_csv(path: str | Path, header: Sequence[str], columns: Iterable[np.ndarray]) -> None:
    cols = [np.asarray(c) for c in columns]
    try:
        with open(path, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(header)
            for row in zip(*cols):
                w.writerow([f"{v:.10g}" for v in row])
    except OSError as exc:
        raise BadInput(f"{path}: cannot write ({exc.strerror})") from None
