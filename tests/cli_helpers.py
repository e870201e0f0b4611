"""Shared helpers of the CLI tests (imported by the test modules; pytest puts tests/ on
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


def assert_one_line_error(code, err, name):
    """Bad input: exit code 2 and one line ``error: ...`` naming ``name``."""
    assert code == 2, err
    assert "Traceback" not in err
    lines = err.strip("\n").splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith("error: "), err
    assert name.lower() in lines[0].lower(), (name, err)
