"""The CLI stays thin: no function of ``rocking.cli`` above a cyclomatic complexity of 20
(ruff's mccabe rule C901). A command parses its options into a request object and calls
the Python API; its decisions belong in small helpers or in the API."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

import rocking

CLI = Path(rocking.__file__).resolve().parent / "cli"
MAX_COMPLEXITY = 20


def test_cli_functions_are_not_too_complex():
    pytest.importorskip("ruff")
    proc = subprocess.run(
        [sys.executable, "-m", "ruff", "check", "--isolated", "--select", "C901",
         "--config", f"lint.mccabe.max-complexity = {MAX_COMPLEXITY}",
         "--output-format", "concise", "--no-cache", str(CLI)],
        capture_output=True, text=True, check=False)
    assert proc.returncode == 0, (
        f"functions of rocking.cli above complexity {MAX_COMPLEXITY}:\n"
        f"{proc.stdout}{proc.stderr}")
