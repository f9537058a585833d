"""The ``labrig`` command line. Exit codes (DESIGN.md 6): 0 ok, 2 bad input, 3 instrument or safety fault, 1 other."""

from __future__ import annotations

import os
import sys

import click

from labrig import __version__
from labrig.errors import BadInput, SafetyTrip


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="labrig")
def app() -> None:
    """Instrument control, acquisition, fitting and diagnosis for IPMC actuators."""


def _register() -> None:
    from labrig.cli import analysis_cmds, diagnose_cmd, model, run_cmd

    app.add_command(model.model)
    app.add_command(analysis_cmds.fit_cmd)
    app.add_command(diagnose_cmd.diagnose_cmd)
    app.add_command(run_cmd.run_cmd)
    app.add_command(run_cmd.sim_cmd)
    from labrig.cli import session_cmds

    session_cmds.register(app)
    from labrig.cli import live_cmds
    live_cmds.register(app)
    from labrig.cli import report_cmd

    app.add_command(report_cmd.report_cmd)


def main(argv: list[str] | None = None) -> int:
    """Entry point: one clear line on stderr for bad input (exit 2) and instrument faults (exit 3)."""
    _register()
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
    except Exception as exc:  # instrument faults carry their device name
        from drivers.errors import InstrumentError

        if isinstance(exc, InstrumentError):
            click.echo(f"labrig: instrument fault: {exc}", err=True)
            return 3
        raise


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
