"""Every script in ``benchmarks/`` runs to its end in its ``--quick`` mode (tiny inputs,
every section), so that none rots unnoticed.

The scripts run one after another in one fresh interpreter (``quick_benchmarks.py``: one
start, one import of the package and one load of numba's cached kernels for all of
them), each as ``python SCRIPT --quick`` would run it, from its own working directory
with ``TMPDIR`` in its own temporary folder (the scripts' stores, specs and caches go
there) and the session's record cache (``ROCKING_CACHE_DIR``, see ``conftest.py``); what
a script changes in the environment is put back before the next. Each test checks its
script's exit status, that no traceback was printed and that the script's last section
printed its figures. About 40 s for all of them on 2 cores with numba's cache warm;
``bench_campaign.py``, with its Dask cluster and fresh processes, is the longest (about
12 s).
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

BENCH = Path(__file__).resolve().parent.parent / "benchmarks"
SCRIPTS = sorted(p.name for p in BENCH.glob("*.py")
                 if p.name.startswith(("bench_", "study_")))
TIMEOUT = 300  # s: a cold numba cache compiles the kernels first (minutes on 2 cores)

# a line printed by each script's last section (its figures were printed)
LAST = {
    "bench_campaign.py": "== summary",
    "bench_campaign_profile.py": "Amdahl's law, speed-up without",
    "bench_ccrr.py": "record by record",
    "bench_contract.py": "goal: >= 0.97",
    "bench_dem.py": "goal (20 s of motion",
    "bench_floors.py": "context, floors / the ground motion itself",
    "bench_fragility_fit.py": "fragility_curves, 3 states",
    "bench_fragility_study.py": ", total ",
    "bench_housner.py": "batch: overturned / rocked",
    "bench_identify.py": "at 50 Hz",
    "bench_isolated.py": "throughput ratio isolated/housner",
    "bench_import.py": "import rocking; rocking.simulate",
    "bench_motions.py": "pyrotd",
    "bench_overturning.py": "mavroeidis_papageorgiou ",
    "bench_rigid3d.py": "cost per hull vertex",
    "bench_rigid3d_campaign.py": "10^4 runs extrapolated",
    "bench_selection.py": "(goal < 5 s)",
    "bench_shapes.py": "total (goal < 2 s)",
    "bench_step_loop.py": "min..max of pairs",
    "bench_stochastic.py": "records/s",
    "bench_taylor.py": "(compiled reference)",
    "bench_vertical.py": "GroundMotion(h, v)",
    "study_rest_tol.py": "ccrr section:",
    "study_rigid3d_convergence.py": "box       runs with unconverged steps",
}


def test_every_script_is_listed():
    assert SCRIPTS and set(SCRIPTS) == set(LAST), "add the new script to LAST"


@pytest.fixture(scope="module")
def quick_runs(request, tmp_path_factory):
    """Run the ``--quick`` mode of every script this session tests, in one fresh
    interpreter; returns the folder of their outputs (``<script>.out``, ``.err``,
    ``.rc``, and ``<stem>/tmp``)."""
    out = tmp_path_factory.mktemp("bench")
    wanted = [item.callspec.params["script"] for item in request.session.items
              if item.path == Path(__file__) and item.originalname == "test_quick"]
    # distributed may log a worker's failed heartbeat, with its traceback, while a
    # LocalCluster shuts down (a race of its own, seen once in 14 runs): not ours to flag
    env = dict(os.environ, MPLBACKEND="Agg", DASK_LOGGING__DISTRIBUTED="critical")
    cmd = [sys.executable, str(Path(__file__).parent / "quick_benchmarks.py"), str(out),
           str(TIMEOUT), *(str(BENCH / s) for s in wanted)]
    p = subprocess.run(cmd, cwd=out, env=env, capture_output=True, text=True,
                       timeout=TIMEOUT * len(wanted) + 60)
    (out / "runner.log").write_text(f"exit {p.returncode}\n{p.stdout}\n{p.stderr}")
    return out


@pytest.mark.parametrize("script", SCRIPTS)
def test_quick(script, quick_runs):
    rc_file = quick_runs / f"{script}.rc"
    runner = (quick_runs / "runner.log").read_text()
    assert rc_file.exists(), f"{script} did not finish: the runner said\n{runner[-3000:]}"
    rc = int(rc_file.read_text())
    stdout = (quick_runs / f"{script}.out").read_text()
    stderr = (quick_runs / f"{script}.err").read_text()
    tail = f"\n--- stdout\n{stdout[-3000:]}\n--- stderr\n{stderr[-3000:]}"
    assert rc == 0, f"{script} --quick exited with {rc}{tail}"
    assert "Traceback" not in stderr, tail
    assert LAST[script] in stdout, f"{script}: last section missing{tail}"
    # the stores and specs were removed (only what Dask or numba may leave in TMPDIR)
    tmp = quick_runs / script.removesuffix(".py") / "tmp"
    left = [q.name for q in tmp.iterdir() if q.name.startswith(("bench-", "rocking-bench"))]
    assert not left, f"{script} left {left} in its temporary directory"
