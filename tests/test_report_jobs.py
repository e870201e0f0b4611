"""The report's sections built in worker processes (``reproduce(..., jobs=N)``, issue 33):
the same page and files as one after the other, a worker's warnings raised in the caller,
a failing section shown and reported, bad ``jobs`` refused."""

from __future__ import annotations

import multiprocessing
import re
import sys
from pathlib import Path

import pytest

from rocking import _compile_notice
from rocking.errors import ParameterError
from rocking.report import SECTIONS, ReportError, reproduce

sys.path.insert(0, str(Path(__file__).parent))
import report_worker_sections  # noqa: E402,F401  (registers the zz_ sections)

# registered only while a test of this file runs (the session's quick report must not
# meet them); a worker registers them again by importing the module
ZZ = {k: SECTIONS.pop(k) for k in list(SECTIONS) if k.startswith("zz_")}
OK = ["zz_ok", "zz_warn"]


@pytest.fixture(autouse=True)
def zz_sections():
    SECTIONS.update(ZZ)
    yield
    for k in ZZ:
        SECTIONS.pop(k, None)


def _page(index: Path) -> str:
    """The page without its provenance footer (wall-clock times)."""
    text = index.read_text(encoding="utf-8")
    return text[:text.index('<section id="provenance"')]


def test_two_jobs_same_page_and_files_as_one(tmp_path):
    one, two = tmp_path / "one", tmp_path / "two"
    with pytest.warns(UserWarning, match="zz: a warning raised in a worker"):
        a = reproduce(one, progress=False, only=OK, jobs=1)
    with pytest.warns(UserWarning, match="zz: a warning raised in a worker"):
        b = reproduce(two, progress=False, only=OK, jobs=2)
    assert _page(a) == _page(b)
    files = sorted(p.name for p in one.iterdir() if p.name != "index.html")
    assert files == ["zz_ok_table.csv"]
    assert files == sorted(p.name for p in two.iterdir() if p.name != "index.html")
    assert (one / files[0]).read_bytes() == (two / files[0]).read_bytes()
    # page order is the registry's, whatever order the workers finish in
    assert re.findall(r'<section id="(zz_\w+)">', _page(b)) == OK


def test_a_failing_section_in_a_worker_is_shown_and_reported(tmp_path, capsys):
    with pytest.raises(ReportError) as err, pytest.warns(UserWarning):
        reproduce(tmp_path, progress=True, only=["zz_ok", "zz_warn", "zz_fail"], jobs=2)
    assert "zz_fail" in str(err.value)
    page = (tmp_path / "index.html").read_text(encoding="utf-8")
    assert "ValueError: zz: this section fails on purpose" in page
    assert "<p>ok</p>" in page and "<p>warned</p>" in page
    log = capsys.readouterr().err
    assert "2 jobs" in log and log.count("] A section") == 3


@pytest.mark.parametrize("jobs", [0, -1, 1.5, True, "2"])
def test_bad_jobs_refused(tmp_path, jobs):
    with pytest.raises(ParameterError, match="jobs must be an integer >= 1"):
        reproduce(tmp_path, progress=False, only=OK, jobs=jobs)


def test_sections_of_main_or_doctests_run_in_the_caller(tmp_path):
    """A section a worker cannot import (here: defined in a function) is built by the
    caller, beside the workers."""
    from rocking.report import section

    @section("zz_local", "A section defined in a function", order=999)
    def build(ctx):
        return f"<p>local {multiprocessing.current_process().name}</p>"

    try:
        index = reproduce(tmp_path, progress=False, only=["zz_local", "zz_ok"], jobs=2)
    finally:
        del SECTIONS["zz_local"]
    assert "<p>local MainProcess</p>" in index.read_text(encoding="utf-8")


def test_compile_notice_said_once_across_processes(capsys):
    """Processes sharing a flag (the report's workers) write the line once in all."""
    from numba import njit

    flag = multiprocessing.get_context("spawn").Value("b", 0)

    def fresh():
        @njit(cache=False)
        def f(x):
            return x + 1.0
        return f

    try:
        _compile_notice.share(flag)
        for already in (1, 0):
            flag.value = already
            saved, _compile_notice._said = _compile_notice._said, False
            try:
                assert _compile_notice.compile_notice(fresh())(1.0) == 2.0
            finally:
                _compile_notice._said = saved
            err = capsys.readouterr().err
            assert err.count(_compile_notice.MESSAGE) == (0 if already else 1)
            assert flag.value == 1
    finally:
        _compile_notice.share(None)
