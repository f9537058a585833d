"""The ``labrig`` command line. Exit codes (DESIGN.md 6): 0 ok, 2 bad input, 3 instrument or safety fault, 1 other."""

from __future__ import annotations

import importlib
import os
import sys

import click

from labrig import __version__
from labrig.errors import BadInput, SafetyTrip


# command -> "module:attribute". A command's module is imported only when that command runs (click's lazy
# subcommands): the physics behind fit, model and run loads scipy, ~0.5 s that `inspect` or a typo need not pay.
_COMMANDS = {
    "run": "labrig.cli.run_cmd:run_cmd",
    "sim": "labrig.cli.run_cmd:sim_cmd",
    "inspect": "labrig.cli.session_cmds:inspect_cmd",
    "import": "labrig.cli.session_cmds:import_cmd",
    "export": "labrig.cli.session_cmds:export_cmd",
    "fit": "labrig.cli.analysis_cmds:fit_cmd",
    "diagnose": "labrig.cli.diagnose_cmd:diagnose_cmd",
    "report": "labrig.cli.report_cmd:report_cmd",
    "replay": "labrig.cli.live_cmds:replay_cmd",
    "model": "labrig.cli.model:model",
    "check": "labrig.cli.check_cmd:check_cmd",
}


class _LazyGroup(click.Group):
    def list_commands(self, ctx: click.Context) -> list[str]:
        return sorted([*super().list_commands(ctx), *_COMMANDS])

    def get_command(self, ctx: click.Context, name: str) -> click.Command | None:
        if name in _COMMANDS:
            module, attr = _COMMANDS[name].split(":")
            return getattr(importlib.import_module(module), attr)
        return super().get_command(ctx, name)


@click.group(cls=_LazyGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="labrig")
def app() -> None:
    """Instrument control, acquisition, fitting and diagnosis for IPMC actuators."""


def main(argv: list[str] | None = None) -> int:
    """Entry point: one clear line on stderr for bad input (exit 2) and instrument faults (exit 3)."""
    try:
        rc = app.main(args=argv, prog_name="labrig", standalone_mode=False)
        return rc if isinstance(rc, int) else 0  # click returns an Exit's code here instead of raising
    except click.exceptions.Exit as exc:
        return exc.exit_code
    except click.UsageError as exc:
        where = f" {exc.ctx.command_path}" if exc.ctx else ""
        click.echo(f"labrig{where[len(' labrig'):] if where.startswith(' labrig') else where}: error: {exc.format_message()}", err=True)
        return 2
    except click.Abort:
        click.echo("labrig: aborted", err=True)
        return 1
    except BadInput as exc:
        click.echo(f"labrig: error: {exc}", err=True)
        return 2
    except SafetyTrip as exc:
        click.echo(f"labrig: safety trip: {exc}", err=True)
        return 3
    except ModuleNotFoundError as exc:  # an optional piece that is not installed: say what to install
        click.echo(f"labrig: error: {missing_package_line(exc)}", err=True)
        return 2
    except Exception as exc:  # instrument faults carry their device name
        from drivers.errors import InstrumentError

        if isinstance(exc, InstrumentError):
            click.echo(f"labrig: instrument fault: {exc}", err=True)
            return 3
        raise


# top-level module -> the labrig extra (or package) that provides it
_EXTRAS = {"dask": "labrig[cluster]", "distributed": "labrig[cluster]", "pyqtgraph": "pyqtgraph",
           "PySide6": "PySide6-Essentials", "shiboken6": "PySide6-Essentials", "pytest": "labrig[test]"}


def missing_package_line(exc: ModuleNotFoundError) -> str:
    """One line naming the missing module and what to install for it."""
    name = (exc.name or str(exc)).split(".")[0]
    what = _EXTRAS.get(name, name)
    return f"the optional package {name!r} is not installed: pip install '{what}'"


def qt_was_used() -> bool:
    """A QApplication exists in this process (the live window or a replay ran)."""
    qtw = sys.modules.get("PySide6.QtWidgets")
    return qtw is not None and qtw.QApplication.instance() is not None


def end_process(code: int) -> None:
    """Exit with ``code``. After Qt ran, skip interpreter finalisation: PySide6 6.12 + pyqtgraph tear
    their C++ objects down after the Python modules they call into and segfault (exit 139) after a run
    that succeeded. Every session file is closed and flushed by then, so nothing is lost."""
    if qt_was_used():
        sys.stdout.flush()
        sys.stderr.flush()
        os._exit(code)
    sys.exit(code)


def entry() -> None:
    end_process(main())
