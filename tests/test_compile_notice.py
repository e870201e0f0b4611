"""A first call that compiles the kernels says so, one line on stderr, once per process;
never when numba's cache is warm (issue 33: 15-55 s of silence looked like a hang).

The subprocesses run the toy sliding model (``tests/sliding_model.py``): its kernels
compile in seconds where the rocking models' take tens of seconds, through the same hook
in ``simulate`` and ``simulate_many``."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
from numba import njit

from rocking import _compile_notice
from rocking._compile_notice import MESSAGE, compile_notice, will_compile

TESTS = Path(__file__).parent

SCRIPT = """
import sys
sys.path.insert(0, {tests!r})
import rocking
from rocking.models import register
from sliding_model import Sliding
register(Sliding)
block = rocking.specimen(3)
for call in {calls!r}:
    if call == "simulate":
        rocking.simulate(block, None, model="sliding", state0=[0.0, 0.8], duration=1.0)
    else:
        motions = [rocking.motions.Rectangular(3.0, 0.5)] * 2
        rocking.simulate_many(block, motions, model="sliding", duration=1.0)
print("done")
"""


def _run(cache: Path, *calls: str) -> str:
    """The stderr of a fresh process that makes ``calls`` with numba's cache in
    ``cache``."""
    env = {**os.environ, "NUMBA_CACHE_DIR": str(cache),
           "PYTHONPATH": os.pathsep.join(p for p in sys.path if p)}
    out = subprocess.run([sys.executable, "-c", SCRIPT.format(tests=str(TESTS), calls=calls)],
                         env=env, capture_output=True, text=True, timeout=600)
    assert out.returncode == 0 and out.stdout.strip() == "done", out.stderr
    return out.stderr


def test_a_cold_cache_says_so_once_and_a_warm_one_never(tmp_path):
    cold = _run(tmp_path, "simulate", "simulate")  # the single-run kernel compiles
    assert cold.count(MESSAGE) == 1 and cold.splitlines()[0] == MESSAGE, cold
    # that one is cached now, the batch kernel is not: simulate_many says so
    half = _run(tmp_path, "simulate", "simulate_many", "simulate_many")
    assert half.count(MESSAGE) == 1, half
    warm = _run(tmp_path, "simulate", "simulate_many")
    assert MESSAGE not in warm, warm


def test_a_kernel_compiled_in_this_process_is_called_directly(monkeypatch, capsys):
    monkeypatch.setattr(_compile_notice, "_said", False)

    @njit(cache=False)
    def twice(x):
        return 2.0 * x

    assert will_compile(twice, (1.0,))
    assert compile_notice(twice)(1.5) == 3.0  # compiles: the line, once
    assert capsys.readouterr().err == MESSAGE + "\n"
    assert not will_compile(twice, (1.0,)) and will_compile(twice, (np.zeros(2),))
    assert compile_notice(twice) is twice  # compiled: no wrapper, no look-up
    monkeypatch.setattr(_compile_notice, "_said", False)
    assert compile_notice(lambda x: x)(2) == 2  # a plain function (NUMBA_DISABLE_JIT)
    assert capsys.readouterr().err == ""
