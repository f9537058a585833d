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


scheduler_option = click.option("--scheduler", metavar="ADDRESS", default=None,
                                help="dask.distributed scheduler (or env DASK_SCHEDULER_ADDRESS): populations, or a batch of sessions, run there")


def print_outcomes(outcomes: list, as_json: bool, summary: Any) -> None:
    """One session: its object as before. Several: {"sessions": [{"path", "result" | "error"}...]}."""
    if as_json:
        if len(outcomes) == 1 and outcomes[0].error is None:
            print_json(outcomes[0].result)
        elif len(outcomes) > 1:
            print_json({"sessions": [{"path": o.path, "result": o.result, "error": o.error} for o in outcomes]})
    else:
        for o in outcomes:
            if o.error is None:
                if len(outcomes) > 1:
                    click.echo(f"== {o.path}")
                summary(o.result)
    for o in outcomes:
        if o.error is not None:
            click.echo(f"labrig: error: {o.error}", err=True)


def exit_code(outcomes: list) -> int:
    """0 when every session has a result; 2 when a session was bad input; 1 when one failed otherwise."""
    if all(o.error is None for o in outcomes):
        return 0
    return 2 if all(o.bad_input for o in outcomes if o.error is not None) else 1
