"""The isolated model's notice about the restitution it derives (issue 31, item 11): a
campaign says it once, not once per chunk, and on the command line it is one
``warning:`` line above the progress bar (``tqdm.write``), not inside it."""

from __future__ import annotations

import re
import warnings

from cli_helpers import run_main

from rocking import campaign

NOTICE = "derives the impact restitution"

SPEC = """
[campaign]
name = "notice"
seed = 5
model = "housner"
duration = 3.0

[[blocks]]
alpha = 0.25
p = 2.2
mu = {mu}

[motions]
kind = "sine"
frequency = [1.0, 2.5]
amplitude = 1.0
cycles = 2
load_factors = [0.8, 2.0, 4.0]

[[mitigation]]
name = "none"

[[mitigation]]
name = "iso"
model = "isolated"
isolation_period = "2.5s"

[run]
chunk_size = 2
"""


def test_a_campaign_says_the_notice_once(tmp_path):
    """6 chunks run the isolated model, each building it again: one notice (a block of
    its own, so that no other test has said it before in this process)."""
    spec = tmp_path / "spec.toml"
    spec.write_text(SPEC.format(mu=0.9137))
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        status = campaign.run(spec, tmp_path / "store", progress=False)
    assert status["complete"] and status["chunks_done"] == 6
    notices = [w for w in seen if NOTICE in str(w.message)]
    assert len(notices) == 1 and "own mu = 0.9137" in str(notices[0].message)


def test_the_command_line_prints_it_once_above_the_progress_bar(tmp_path, capsys):
    spec = tmp_path / "spec.toml"
    spec.write_text(SPEC.format(mu=0.9141))
    code, out, err = run_main(capsys, "campaign", "run", spec, "--out", tmp_path / "store")
    assert code == 0, err
    assert err.count(NOTICE) == 1
    assert "12 of 12 simulations done (6 chunks)" in out
    # the bar redraws with carriage returns: the warning is a line of its own
    pieces = re.split(r"[\r\n]", err)
    said = [p for p in pieces if NOTICE in p]
    assert len(said) == 1 and said[0].startswith("warning: model 'isolated'")
    assert "sim/s" in err  # the bar was drawn
