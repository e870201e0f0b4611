"""Shared helper of the CLI tests (imported by the test modules; pytest puts tests/ on
sys.path)."""

from __future__ import annotations

import pytest

from rocking.cli import main


def run_main(capsys, *args):
    """:func:`rocking.cli.main` in-process: ``(exit code, stdout, stderr)``."""
    with pytest.raises(SystemExit) as exc:
        main([str(a) for a in args])
    out, err = capsys.readouterr()
    return exc.value.code, out, err
