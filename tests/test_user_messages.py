"""Messages a new user reads (issue 31, item 11): the separation of a fragility fit told
the right way round, an empty damage state in words, a damping ratio typed in percent, a
misspelt direction, and a campaign that will run for hours or days announced (or refused)
before it starts."""

from __future__ import annotations

import importlib
import re

import numpy as np
import pytest
from cli_helpers import assert_one_line_error, run_main

from rocking.analysis import fragility, fragility_curves
from rocking.campaign import parse_spec
from rocking.errors import ParameterError
from rocking.shapes import example_mesh_path, parse_direction

STATUE = str(example_mesh_path())
cli_campaign = importlib.import_module("rocking.cli.campaign")  # the module, not the group


def test_a_separated_fit_says_none_below_and_its_numbers_are_true():
    im = np.array([1.0, 2.0, 4.0, 8.52, 10.0, 12.0])
    failed = im >= 8.52
    with pytest.raises(ParameterError) as e:
        fragility(im, failed)
    msg = str(e.value)
    m = re.search(r"every record that failed is at im >= (\S+), none below; every record "
                  r"that did not is at im <= (\S+)\)", msg)
    assert m, msg
    lo, hi = float(m[1]), float(m[2])
    assert np.all(im[failed] >= lo) and not np.any(failed[im < lo])  # none below
    assert np.all(im[~failed] <= hi)
    assert "none above" not in msg and "between im = 4 and 8.52" in msg


def test_an_empty_damage_state_is_a_clear_sentence():
    im = np.repeat([1.0, 2.0, 4.0], 5)
    with pytest.raises(ParameterError) as e:  # nothing damaged at all
        fragility_curves(im, np.zeros(im.size, int), n_boot=0)
    msg = str(e.value)
    assert "(of 0..1)" not in msg and "[1]" not in msg
    assert "no record reached a damage state" in msg and "stronger IM levels" in msg
    # ratios classified with thresholds: no record overturned (the top state)
    ratio = np.tile([0.1, 0.3, 0.6, 0.9, 0.2], 3)
    with pytest.raises(ParameterError) as e:
        fragility_curves(im, ratio=ratio, overturned=np.zeros(im.size, bool),
                         thresholds=(0.25, 0.5), n_boot=0)
    msg = str(e.value)
    assert "damage state 3 (DS3: overturning) of the states 0..3" in msg
    assert "stronger IM levels" in msg and "\n" not in msg
    # every record damaged: state 0 is empty, weaker levels are needed
    with pytest.raises(ParameterError, match=r"state 0 \(undamaged\).*weaker IM levels"):
        fragility_curves(im, np.tile([1, 2], 8)[:im.size], n_boot=0)


def test_a_damping_ratio_typed_in_percent_is_explained(capsys):
    code, out, err = run_main(capsys, "simulate", "--specimen", "2", "--building", "shear",
                              "--storeys", "5", "--building-period", "0.5",
                              "--building-damping", "5", "--floor", "3", "--motion",
                              "ricker", "--amp", "0.3g", "--freq", "2")
    assert_one_line_error(code, err, "building-damping")
    assert "5 % is 0.05" in err and "got '5'" in err
    # a value that is no percentage either gets no such hint
    code, out, err = run_main(capsys, "simulate", "--specimen", "2", "--building", "shear",
                              "--storeys", "5", "--building-period", "0.5",
                              "--building-damping", "500", "--floor", "3", "--motion",
                              "ricker", "--amp", "0.3g", "--freq", "2")
    assert_one_line_error(code, err, "building-damping")
    assert "% is" not in err


def test_a_misspelt_direction_suggests_the_name(capsys, tmp_path):
    with pytest.raises(ParameterError, match="did you mean 'weakest'"):
        parse_direction("weakst")
    with pytest.raises(ParameterError, match="did you mean 'strongest'"):
        parse_direction("Strongst")
    with pytest.raises(ParameterError) as e:
        parse_direction("sideways")
    assert "did you mean" not in str(e.value) and "'weakest' or 'strongest'" in str(e.value)
    code, out, err = run_main(capsys, "simulate", "--mesh", STATUE, "--density", "2600",
                              "--direction", "weakst", "--motion", "ricker", "--amp",
                              "0.3g", "--freq", "2")
    assert_one_line_error(code, err, "direction")
    assert "did you mean 'weakest'?" in err
    spec = SPEC_MESH.format(mesh=STATUE)
    with pytest.raises(ParameterError, match=r"blocks\[0\]\.direction.*did you mean 'weakest'"):
        parse_spec(spec, base_dir=tmp_path)


SPEC_MESH = """\
campaign = {{name = "m", seed = 1, model = "housner"}}
blocks = [{{mesh = "{mesh}", density = 2600, direction = "weakst"}}]
[motions]
kind = "one_sine"
period = 0.5
amplitude = 1.0
load_factors = [1.0]
"""

SPEC_HUGE = """\
campaign = {{name = "huge", seed = 1, model = "housner", samples = {samples}}}
blocks = [{{specimen = 2}}]
[motions]
kind = "one_sine"
period = 0.5
amplitude = 1.0
load_factors = [1.0, 2.0]
[uncertain]
alpha = {{dist = "normal", cov = 0.02}}
[run]
chunk_size = 2
"""


def test_a_campaign_of_a_billion_runs_is_refused_without_yes(tmp_path, capsys):
    """2 x 10^9 runs: the short timing says hundreds of hours; refused before the store is
    made, with the estimate in the one line."""
    spec = tmp_path / "huge.toml"
    spec.write_text(SPEC_HUGE.format(samples=10 ** 9))
    store = tmp_path / "store"
    code, out, err = run_main(capsys, "campaign", "run", spec, "--out", store)
    assert_one_line_error(code, err, "estimated time")
    assert "--yes" in err and "more than a day" in err
    hours = float(re.search(r"estimated time: (\d+) h", err)[1])
    assert hours > 24
    assert not store.exists()


def test_a_long_campaign_prints_its_estimate_first(tmp_path, capsys, monkeypatch):
    """The notice's threshold lowered to 0 s and the bound raised (so the short timing
    runs): one line ``estimated time`` on stderr, then the run completes. Without them, a
    4-run campaign starts without a timing."""
    spec = tmp_path / "small.toml"
    spec.write_text(SPEC_HUGE.format(samples=2))
    code, out, err = run_main(capsys, "campaign", "run", spec, "--out", tmp_path / "a",
                              "--quiet")
    assert code == 0, err
    assert "estimated time" not in err
    monkeypatch.setattr(cli_campaign, "NOTICE_SECONDS", 0.0)
    monkeypatch.setattr(cli_campaign, "SECONDS_PER_RUN_BOUND", {"fast": 1e9, "slow": 1e9})
    code, out, err = run_main(capsys, "campaign", "run", spec, "--out", tmp_path / "b",
                              "--quiet")
    assert code == 0, err
    lines = [ln for ln in err.splitlines() if ln.startswith("estimated time")]
    assert len(lines) == 1 and "4 simulations" in lines[0]
    assert "4 of 4 simulations done" in out
    # a resumed store has nothing left: no timing, no line
    code, out, err = run_main(capsys, "campaign", "run", spec, "--out", tmp_path / "b",
                              "--quiet")
    assert code == 0 and "estimated time" not in err
