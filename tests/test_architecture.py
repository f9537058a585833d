"""The house keeps its floors (docs/architecture.md): the import contracts of pyproject.toml hold on today's code."""

from pathlib import Path

from importlinter.cli import lint_imports

ROOT = Path(__file__).resolve().parents[1]


def test_import_contracts_hold(monkeypatch):
    monkeypatch.chdir(ROOT)  # the contracts are read from the project's pyproject.toml
    assert lint_imports(no_cache=True) == 0  # 0: every contract kept; the failing contract is printed otherwise
