"""Everything a campaign spec can get wrong is found before the store is created: each case
is a SpecError from parse_spec with one line naming the key and what it allows, and
`rocking campaign run SPEC --out DIR` exits 2 with one `error:` line and leaves no DIR."""

from __future__ import annotations

import os
import re

import pytest

from rocking import campaign
from rocking.campaign.spec import MAX_RECORD_DURATION
from rocking.cli import main
from rocking.errors import SpecError

BASE = """
[campaign]
name = "checks"
seed = 3
model = "housner"
{campaign}

[[blocks]]
specimen = 2
params = "experimental"
{blocks}

[motions]
{motions}

[uncertain]
{uncertain}
"""
BUILTIN = 'kind = "builtin"\nname = ["RSN126_GAZLI_GAZ000"]\nload_factors = [0.5]'


def spec(campaign="", blocks="", motions=BUILTIN, uncertain=""):
    return BASE.format(campaign=campaign, blocks=blocks, motions=motions,
                       uncertain=uncertain)


def _garbage(d):
    (d / "garbage.csv").write_bytes(b"time,acc\n0.0,0.1\n0.01,zero point two\n")
    return spec(motions='kind = "record"\nfile = ["garbage.csv"]')


def _binary(d):
    (d / "binary.at2").write_bytes(bytes(range(256)) * 8)
    return spec(motions='kind = "record"\nfile = ["binary.at2"]')


def _directory(d):
    (d / "folder.csv").mkdir()
    return spec(motions='kind = "record"\nfile = ["folder.csv"]')


# case: (spec text, or a function of the spec's folder returning it; the key named;
#        a pattern the message must also match: the allowed range or the reason)
CASES = {
    "record file that cannot be parsed": (_garbage, "motions.file[0]", "garbage.csv"),
    "record file that is not text": (_binary, "motions.file[0]", "binary.at2"),
    "record path that is a folder": (_directory, "motions.file[0]", "no such file"),
    "noise < 0 (fixed)": (spec(uncertain='noise = {dist = "fixed", value = -0.05}'),
                          "uncertain.noise", r"100% .*outside \[0, inf\) m/s\^2"),
    "noise < 0 (uniform)": (spec(uncertain='noise = {dist = "uniform", low = -0.1, '
                                           'high = 0.01}'),
                            "uncertain.noise", r"90\.9% .*outside \[0, inf\)"),
    "noise centred on 0": (spec(uncertain='noise = {dist = "normal", mean = 0.0, '
                                          'std = 0.05}'),
                           "uncertain.noise", r"50% .*at most 1%"),
    "extreme cov": (spec(uncertain='alpha = {dist = "normal", cov = 5.0}'),
                    "uncertain.alpha", r"outside \(0, pi/2\) rad; at most 1% .*0\.43"),
    "cov just over the bound": (spec(uncertain='p = {dist = "normal", cov = 0.45}'),
                                "uncertain.p", r"std/mean <= 0\.43"),
    "mu mostly above 1": (spec(uncertain='mu = {dist = "normal", std = 0.05}'),
                          "uncertain.mu", r"outside \(0, 1\]"),
    "cov of a zero mean": (spec(uncertain='theta0 = {dist = "normal", cov = 0.1}'),
                           "uncertain.theta0.cov", "mean != 0"),
    "theta0 beyond alpha": (spec(uncertain='theta0 = {dist = "normal", mean = 0.0, '
                                           'std = 0.07}'),
                            "uncertain.theta0", r"beyond \+-alpha .*at most 1%"),
    "theta0 beyond the alpha of the second block": (
        spec(blocks="[[blocks]]\nalpha = 0.05\np = 3.0\nmu = 0.9",
             uncertain='theta0 = {dist = "uniform", low = -0.06, high = 0.06}'),
        "uncertain.theta0", r"blocks\[1\] = 0\.05 rad"),
    "stochastic duration 1e9": (
        spec(motions='kind = "stochastic"\nn = 2\nduration = 1e9'),
        "motions.duration", r"must be in \(0, 10000\]"),
    "stochastic dt that would allocate too much": (
        spec(motions='kind = "stochastic"\nn = 2\ndt = 1e-7'),
        "motions.dt", r"samples; at most 1e\+07"),
    "stochastic high-pass that lasts for ever": (
        spec(motions='kind = "stochastic"\nn = 2\nomega_c = 1e-7'),
        "motions.omega_c", r"at most 10000 s"),
    "sine duration 1e9": (
        spec(motions='kind = "sine"\nfrequency = [2.0]\namplitude = 1.0\nduration = 1e9'),
        "motions.duration", r"must be in \(0, 10000\]"),
    "sine cycles 1e9": (
        spec(motions='kind = "sine"\nfrequency = [2.0]\namplitude = 1.0\ncycles = 1e9'),
        "motions.cycles", r"at most 10000 s"),
    "pulse duration 1e9": (
        spec(motions='kind = "one_sine"\nperiod = [0.5]\namplitude = 1.0\nduration = 1e9'),
        "motions.duration", r"must be in \(0, 10000\]"),
    "record glob that matches nothing": (
        spec(motions='kind = "record"\nfile = "recs/*.AT2"'),
        "motions.file", "no file matches"),
    "simulation count beyond int64": (
        spec(campaign="samples = 1000000000",
             motions='kind = "stochastic"\nn = 10000000\n'
                     'load_factors = {start = 0.5, stop = 1.5, num = 1000}',
             uncertain='amplitude = {dist = "uniform", low = 0.9, high = 1.1}'),
        "campaign.samples", r"1e\+19 simulations .*at most 2\^63 - 1"),
    "dist given as a list": (spec(uncertain='alpha = {dist = ["normal"], cov = 0.02}'),
                             "uncertain.alpha.dist", "must be one of normal"),
    "cov = true": (spec(uncertain='alpha = {dist = "normal", cov = true}'),
                   "uncertain.alpha.cov", "got bool True"),
    "cov as a string": (spec(uncertain='alpha = {dist = "normal", cov = "0.02"}'),
                        "uncertain.alpha.cov", "got str"),
    "fixed value = false": (spec(uncertain='mu = {dist = "fixed", value = false}'),
                            "uncertain.mu.value", "got bool False"),
    "threshold = true": (spec(campaign="thresholds = [true, 0.5]"),
                         "campaign.thresholds[0]", "got bool True"),
    "load factor = true": (spec(motions=BUILTIN.replace("[0.5]", "[true]")),
                           "motions.load_factors[0]", "got bool True"),
    "duration = true": (spec(campaign="duration = true"), "campaign.duration", "bool"),
    "model option = true": (spec() + "\n[options.housner]\nrest_tol = true\n",
                            "options.housner.rest_tol", "bool"),
    "max_free_time = true": (spec(campaign="max_free_time = true"),
                             "campaign.max_free_time", "bool"),
    "max_free_time < 0": (spec(campaign="max_free_time = -1.0"),
                          "campaign.max_free_time", r"must be in \[0, 10000\]"),
    "max_free_time with a duration": (spec(campaign="duration = 20.0\nmax_free_time = 5.0"),
                                      "campaign.max_free_time", "only without"),
}


def _text(case, tmp_path):
    text, key, pattern = CASES[case]
    return (text(tmp_path) if callable(text) else text), key, pattern


@pytest.mark.parametrize("case", sorted(CASES))
def test_spec_error_names_the_key_and_leaves_no_store(tmp_path, capsys, case):
    text, key, pattern = _text(case, tmp_path)
    path = tmp_path / "spec.toml"
    path.write_text(text)
    with pytest.raises(SpecError) as exc:
        campaign.read_spec(path)
    msg = str(exc.value)
    assert msg.startswith(f"spec: {key}: "), msg
    assert re.search(pattern, msg), msg
    assert "\n" not in msg
    store = tmp_path / "store"
    with pytest.raises(SystemExit) as code:
        main(["campaign", "run", str(path), "--out", str(store)])
    out, err = capsys.readouterr()
    assert code.value.code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ") and key in lines[0], err
    assert "Traceback" not in err
    assert not store.exists()


@pytest.mark.skipif(not hasattr(os, "geteuid") or os.geteuid() == 0,
                    reason="root reads any file")
def test_a_record_file_without_read_permission(tmp_path):
    src = tmp_path / "r.csv"
    src.write_text("# dt = 0.01 s\n0.0\n0.1\n-0.1\n0.0\n")
    src.chmod(0)
    text = spec(motions='kind = "record"\nfile = ["r.csv"]')
    with pytest.raises(SpecError, match=r"^spec: motions\.file\[0\]: cannot read"):
        campaign.parse_spec(text, base_dir=tmp_path)


def test_the_bounds_themselves_are_accepted(tmp_path):
    """What the checks allow still parses: a cov just under 0.43, a record of the longest
    duration, a simulation count near (not beyond) the int64 limit, max_free_time 0."""
    s = campaign.parse_spec(spec(uncertain='p = {dist = "normal", cov = 0.42}'))
    assert "p" in s.uncertain
    s = campaign.parse_spec(spec(motions='kind = "sine"\nfrequency = [2.0]\namplitude = 1.0\n'
                                         f'duration = {MAX_RECORD_DURATION}'))
    assert s.motions["params"]["duration"] == MAX_RECORD_DURATION
    s = campaign.parse_spec(spec(
        campaign="samples = 1000000000",
        motions='kind = "stochastic"\nn = 10000000\nload_factors = {start = 0.5, stop = 1.5, '
                'num = 900}',
        uncertain='amplitude = {dist = "uniform", low = 0.9, high = 1.1}'))
    assert s.n_sims == 10 ** 16 * 900 and s.n_sims < 2 ** 63  # exact: Python ints
    s = campaign.parse_spec(spec(campaign="max_free_time = 0.0"))
    assert s.max_free_time == 0.0
    assert campaign.parse_spec(spec()).max_free_time is None
    # a record file that reads is accepted and hashed by its content
    from rocking.motions.io import _builtin_dir
    rec = next(_builtin_dir().glob("RSN126_GAZLI_GAZ000*"))
    s = campaign.parse_spec(spec(motions=f'kind = "record"\nfile = ["{rec}"]'))
    assert len(s.motions["digests"][0]) == 16
