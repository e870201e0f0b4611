"""Run benchmark scripts in their ``--quick`` mode one after another in this interpreter
(``test_benchmarks.py`` starts it once, in a fresh process, for all of them: one
interpreter start, one import of the package and one load of numba's cached kernels
instead of one per script).

Each script runs as ``python SCRIPT --quick`` would run it (``runpy.run_path`` with
``__name__ == "__main__"``, ``sys.argv``), from its own working directory with its own
temporary folder (``TMPDIR`` and :data:`tempfile.tempdir`); its stdout and stderr go to
``<out>/<script>.out`` and ``.err``, its exit status to ``<out>/<script>.rc`` (1 and the
traceback on stderr for an exception, the code of a ``SystemExit``, 124 past the time
limit). What a script may change for the next one is put back after it: the environment,
the working directory, numba's thread count.

Usage: ``python quick_benchmarks.py OUT TIMEOUT SCRIPT...`` (paths of the scripts).
"""

from __future__ import annotations

import os
import runpy
import signal
import sys
import tempfile
import traceback
from pathlib import Path


class TimeLimit(Exception):
    """The script ran past its time limit."""


def _alarm(signum, frame):
    raise TimeLimit


def run_one(script: Path, out: Path, timeout: int) -> int:
    """Run ``script --quick`` (module doc); returns its exit status."""
    name = script.name
    work = out / name.removesuffix(".py")
    tmp = work / "tmp"
    tmp.mkdir(parents=True)
    env0, cwd0, argv0, path0 = dict(os.environ), os.getcwd(), sys.argv, list(sys.path)
    threads0 = None
    if "numba" in sys.modules:
        threads0 = sys.modules["numba"].get_num_threads()
    os.environ["TMPDIR"] = str(tmp)
    tempfile.tempdir = str(tmp)
    os.chdir(work)
    sys.argv = [str(script), "--quick"]
    sys.path.insert(0, str(script.parent))
    rc = 0
    # redirected at the file descriptors, not sys.stdout/sys.stderr: a logging handler
    # made during one script (distributed's) writes into the file of the script running
    saved = [os.dup(1), os.dup(2)]
    with open(out / f"{name}.out", "wb") as fo, open(out / f"{name}.err", "wb") as fe:
        sys.stdout.flush()
        sys.stderr.flush()
        os.dup2(fo.fileno(), 1)
        os.dup2(fe.fileno(), 2)
        signal.signal(signal.SIGALRM, _alarm)
        signal.alarm(timeout)
        try:
            runpy.run_path(str(script), run_name="__main__")
        except SystemExit as e:
            rc = e.code if isinstance(e.code, int) else (0 if e.code is None else 1)
        except TimeLimit:
            rc = 124
            print(f"{name} --quick still running after {timeout} s", file=sys.stderr)
        except BaseException:  # noqa: BLE001 - reported as the script's failure
            rc = 1
            traceback.print_exc()
        finally:
            signal.alarm(0)
            sys.stdout.flush()
            sys.stderr.flush()
            os.dup2(saved[0], 1)
            os.dup2(saved[1], 2)
            for fd in saved:
                os.close(fd)
    os.environ.clear()
    os.environ.update(env0)
    tempfile.tempdir = None
    os.chdir(cwd0)
    sys.argv, sys.path[:] = argv0, path0
    if "numba" in sys.modules:
        numba = sys.modules["numba"]
        numba.set_num_threads(threads0 if threads0 is not None
                              else numba.config.NUMBA_NUM_THREADS)
    (out / f"{name}.rc").write_text(f"{rc}\n")
    return rc


def main(argv: list[str]) -> int:
    out, timeout, scripts = Path(argv[0]), int(argv[1]), [Path(a) for a in argv[2:]]
    for script in scripts:
        run_one(script, out, timeout)
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
