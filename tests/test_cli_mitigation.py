"""``rocking simulate`` with the mitigation models (issue 19): a flag per declared model
option (generated from the declarations), units at the edge, the model's row outputs in
the text and ``--json`` output; ``rocking models`` shows the flags.

Physics checks: a block on a linear isolator that never uplifts moves with its plate as one
oscillator, so the plate's peak displacement and absolute acceleration are the record's
elastic spectral displacement and acceleration at the isolation period and damping
(:func:`rocking.motions.spectra.response_spectra`, an independent exact recurrence); a
rigid anchor holds until the ground acceleration reaches ``g tan(alpha)(1 + 2q)``
(Makris and Zhang 2001), carrying ``(a/(g tan(alpha)) - 1)/2`` of the weight before.
"""

from __future__ import annotations

import json
import math
import re

import pytest
from cli_helpers import assert_one_line_error, run_main
from click.testing import CliRunner

import rocking
from rocking.cli import cli
from rocking.cli.common import ModelFlagsCommand, models_with_option, option_declarations
from rocking.cli.simulate import model_options
from rocking.motions import catalog
from rocking.motions.spectra import response_spectra
from rocking.units import G

ISSUE = ["--model", "isolated", "--isolation-period", "2.5", "--isolation-damping", "10%",
         "--clearance", "0.15m"]
RINALDI = ["--specimen", "2", "--record", "Rinaldi228"]


def invoke(*args):
    res = CliRunner().invoke(cli, [str(a) for a in args], catch_exceptions=False)
    assert res.exit_code == 0, res.output
    return res.stdout


def run_json(*args) -> dict:
    return json.loads(invoke("simulate", *args, "--json"))


def printed(text: str, name: str) -> str:
    """The value printed on the line of the row output ``name``."""
    m = re.search(rf"^{name}\s+(.+)$", text, re.M)
    assert m, text
    return m.group(1)


@pytest.fixture(scope="module")
def rinaldi():
    return catalog.build("builtin", name="Rinaldi228")


# ----------------------------------------------------------------------------- the issue's line
def test_issue_command_line_matches_library(rinaldi):
    """The issue's command line runs; what it prints (text and --json) is the library's run
    with the same options, and the moat stops the run with |u| at the clearance."""
    ref = rocking.simulate(rocking.specimen(2), rinaldi, model="isolated",
                           isolation_period=2.5, isolation_damping=0.1, clearance=0.15)
    d = run_json(*RINALDI, *ISSUE)
    assert d["inputs"]["options"] == {"isolation_period": 2.5, "isolation_damping": 0.1,
                                      "clearance": 0.15}
    for key in ("max_base_displacement", "max_plate_acceleration", "clearance_exceeded",
                "clearance_time"):
        assert d[key] == ref.info[key], key
        assert d["row_outputs"][key]["value"] == ref.info[key], key
    units = {k: v["unit"] for k, v in d["row_outputs"].items()}
    assert units == {"max_base_displacement": "m", "max_plate_acceleration": "m/s^2",
                     "clearance_exceeded": "", "clearance_time": "s"}
    # the contract of the moat: the run stops where |u| reaches the clearance
    assert d["clearance_exceeded"] is True
    assert d["max_base_displacement"] == pytest.approx(0.15, rel=1e-9)
    assert d["duration"] == pytest.approx(d["clearance_time"], abs=2e-3)

    text = invoke("simulate", *RINALDI, *ISSUE)
    disp = printed(text, "max_base_displacement")
    assert disp.endswith(" m")
    assert float(disp.split()[0]) == pytest.approx(ref.info["max_base_displacement"],
                                                   rel=1e-5)
    acc = printed(text, "max_plate_acceleration")
    assert float(acc.split()[0]) == pytest.approx(ref.info["max_plate_acceleration"],
                                                  rel=1e-5)
    assert " m/s^2 (" in acc and acc.endswith(" g)")
    assert printed(text, "clearance_exceeded").startswith("yes")
    when = printed(text, "clearance_time")
    assert when.endswith(" s")
    assert float(when.split()[0]) == pytest.approx(ref.info["clearance_time"], rel=1e-5)


def test_isolated_flags_give_the_elastic_spectrum(rinaldi):
    """Without uplift, block and plate are one oscillator of the isolation period and
    damping: max |u| = Sd(T, zeta), max |A| = Sa(T, zeta) of the record (as run: times the
    load factor); no moat, no clearance event (null time)."""
    d = run_json(*RINALDI, "--load-factor", "0.5", "--model", "isolated",
                 "--isolation-period", "2500ms", "--isolation-damping", "0.1")
    assert d["n_impacts"] == 0 and d["uplift_time"] is None  # the precondition
    s = response_spectra(rinaldi.scaled(0.5), 2.5, 0.1)
    assert d["max_base_displacement"] == pytest.approx(float(s["sd"]), rel=1e-3)
    assert d["max_plate_acceleration"] == pytest.approx(float(s["sa"]), rel=1e-3)
    assert d["clearance_exceeded"] is False and d["clearance_time"] is None
    assert d["row_outputs"]["clearance_time"]["value"] is None
    text = invoke("simulate", *RINALDI, "--load-factor", "0.5", "--model", "isolated",
                  "--isolation-period", "2.5s", "--isolation-damping", "10%")
    assert printed(text, "clearance_exceeded") == "no"
    assert printed(text, "clearance_time") == "-"


# ----------------------------------------------------------------------------- units at the edge
UNIT_PAIRS = [
    ("isolation_damping", "10%", "0.1", 0.1),
    ("isolation_period", "2.5", "2.5s", 2.5),
    ("isolation_period", "2500ms", "2.5", 2.5),
    ("clearance", "15cm", "0.15m", 0.15),
    ("clearance", "150mm", "0.15", 0.15),
    ("radius", "250cm", "2.5", 2.5),
    ("max_step", "0.5ms", "5e-4", 5e-4),
]


@pytest.mark.parametrize(("name", "a", "b", "si"), UNIT_PAIRS,
                         ids=[f"{n}={a}={b}" for n, a, b, _ in UNIT_PAIRS])
def test_units_at_the_edge(name, a, b, si):
    opts_a = model_options("isolated", (), flags={name: a})
    opts_b = model_options("isolated", (), flags={name: b})
    assert opts_a[name] == pytest.approx(opts_b[name], rel=1e-14)
    assert opts_a[name] == pytest.approx(si, rel=1e-14)
    # --option KEY=VALUE reads a quantity the same way
    opt = model_options("isolated", (f"{name}={a}",))
    assert opt[name] == pytest.approx(si, rel=1e-14)


def test_percent_and_centimetres_run_as_ratio_and_metres():
    """``10%`` is ``0.1`` and ``15cm`` is ``0.15m`` end to end; a different damping gives a
    different run (the comparison can fail)."""
    base = [*RINALDI, "--model", "isolated", "--isolation-period", "2.5"]
    a = run_json(*base, "--isolation-damping", "10%", "--clearance", "15cm")
    b = run_json(*base, "--isolation-damping", "0.1", "--clearance", "0.15m")
    c = run_json(*base, "--isolation-damping", "0.1", "--option", "clearance=0.15")
    assert a == b
    for key in ("max_base_displacement", "clearance_time", "max_plate_acceleration"):
        assert c[key] == a[key]
    other = run_json(*base, "--isolation-damping", "20%", "--clearance", "15cm")
    assert other["clearance_time"] != a["clearance_time"]


def test_none_is_the_automatic_default():
    assert model_options("isolated", (), flags={"clearance": "none"}) == {"clearance": None}
    assert model_options("dem", (), flags={"settled": True}) == {"settled": True}


# ----------------------------------------------------------------------------- refusals
FREE = ["simulate", "--specimen", "2", "--motion", "free", "--theta0", "0.05", "--duration",
        "1"]
BAD_VALUES = [
    (["--isolation-period", "-2.5"], "isolation-period", "(0, 100] s"),
    (["--isolation-period", "0s"], "isolation-period", "(0, 100] s"),
    (["--isolation-period", "3m"], "isolation-period", "time unit"),
    (["--isolation-damping", "abc"], "isolation-damping", "abc"),
    (["--isolation-damping", "-5%"], "isolation-damping", "[0, 1]"),
    (["--isolation-damping", "10"], "isolation-damping", "[0, 1]"),  # 10 %: "10%"
    (["--clearance", "-1m"], "clearance", "(0, 1000] m"),
    (["--clearance", "1kg"], "clearance", "length unit"),
    (["--isolation", "spring"], "isolation", "linear, pendulum"),
    (["--mass-ratio", "nan"], "mass-ratio", "mass-ratio"),
]


@pytest.mark.parametrize(("extra", "name", "detail"), BAD_VALUES,
                         ids=[" ".join(a) for a, _, _ in BAD_VALUES])
def test_bad_values_are_one_line_errors(capsys, extra, name, detail):
    code, _, err = run_main(capsys, *FREE, "--model", "isolated", *extra)
    assert_one_line_error(code, err, name)
    assert detail in err
    assert f"error: {name}" in err  # the flag's name, not the library's


def test_bad_anchored_values(capsys):
    for extra, name in ((["--anchor-strength", "-0.1"], "anchor-strength"),
                        (["--anchors", "glue"], "anchors"),
                        (["--anchor-stiffness", "0"], "anchor-stiffness")):
        code, _, err = run_main(capsys, *FREE, "--model", "anchored", *extra)
        assert_one_line_error(code, err, name)


WRONG_MODEL = [("housner", ["--isolation-period", "2.5"], "isolation_period"),
               ("housner", ["--clearance", "0.15m"], "clearance"),
               ("isolated", ["--anchor-strength", "0.3"], "anchor_strength"),
               ("anchored", ["--isolation", "pendulum"], "isolation"),
               ("dem", ["--rest-tol", "1e-6"], "rest_tol"),
               ("isolated", ["--stiffness", "1e6"], "stiffness")]


@pytest.mark.parametrize(("model", "extra", "option"), WRONG_MODEL,
                         ids=[f"{m} {' '.join(a)}" for m, a, _ in WRONG_MODEL])
def test_flag_for_a_model_without_the_option(capsys, model, extra, option):
    """Exit 2, one line naming the flag and every model that has the option."""
    code, _, err = run_main(capsys, *FREE, "--model", model, *extra)
    flag = option.replace("_", "-")
    assert_one_line_error(code, err, flag)
    owners = models_with_option(option)
    assert model not in owners and owners
    assert f"{flag} applies to --model {' or '.join(owners)} only" in err


@pytest.mark.parametrize("pair", ["isolation_period=3", "isolation-period=3"])
def test_flag_and_option_together(capsys, pair):
    code, _, err = run_main(capsys, *FREE, "--model", "isolated", "--isolation-period",
                            "2.5", "--option", pair)
    assert_one_line_error(code, err, "isolation_period")
    assert "twice" in err


# ----------------------------------------------------------------------------- anchored
def test_anchored_flags_rigid_anchor_closed_forms():
    """A half-sine pulse below ``g tan(alpha)(1 + 2q)``: no uplift, the anchor carries
    ``(a/(g tan(alpha)) - 1)/2`` of the weight; above: it breaks at the uplift, when the
    pulse reaches that threshold, ``t = Tp/pi asin(threshold/A)``."""
    block = rocking.specimen(2)
    thr = G * math.tan(block.alpha)
    q, tp = 0.2, 0.5

    def run(k, strength):
        return run_json("--specimen", "2", "--motion", "half_sine", "--amp",
                        f"{k * thr!r}m/s^2", "--tp", tp, "--model", "anchored",
                        "--anchor-strength", strength, "--anchors", "rigid")

    below = run(1.2, "0.2")
    assert below["uplift_time"] is None and below["n_impacts"] == 0
    assert below["max_anchor_force"] == pytest.approx((1.2 - 1.0) / 2.0, rel=1e-3)
    assert not below["anchor_broken_plus"] and not below["anchor_broken_minus"]
    assert below == run(1.2, "20%")

    above = run(2.0, "0.2")
    t_break = tp / math.pi * math.asin((1.0 + 2.0 * q) / 2.0)
    times = [t for t in (above["anchor_break_time_plus"], above["anchor_break_time_minus"])
             if t is not None]
    assert times == [pytest.approx(t_break, abs=1e-6)]
    assert above["uplift_time"] == pytest.approx(t_break, abs=1e-6)
    assert above["max_anchor_force"] == pytest.approx(q, rel=1e-12)
    assert above["row_outputs"]["anchor_break_time_plus"]["unit"] == "s"


def test_anchored_elastic_flags_match_library(rinaldi):
    args = ["--model", "anchored", "--anchors", "elastic", "--anchor-stiffness", "200",
            "--anchor-strength", "0.05"]
    text = invoke("simulate", *RINALDI, "--load-factor", "0.4", *args)
    ref = rocking.simulate(rocking.specimen(2), rinaldi.scaled(0.4), model="anchored",
                           anchors="elastic", anchor_stiffness=200.0, anchor_strength=0.05)
    force = printed(text, "max_anchor_force")
    assert float(force.split()[0]) == pytest.approx(ref.info["max_anchor_force"], rel=1e-5)
    assert "fraction of the block's weight" in force
    for side in ("plus", "minus"):
        broke = printed(text, f"anchor_broken_{side}")
        assert broke.startswith("yes") == ref.info[f"anchor_broken_{side}"]
        when = printed(text, f"anchor_break_time_{side}")
        t = ref.info[f"anchor_break_time_{side}"]
        assert (when == "-") if math.isnan(t) else float(when.split()[0]) == \
            pytest.approx(t, rel=1e-5)


# ----------------------------------------------------------------------------- generated flags
def test_every_option_has_a_flag_or_is_documented():
    """Each declared option of each registered model has a generated flag (listed by
    --help) unless its flag is one of the command's own; those are the ones the module
    docstring lists."""
    import rocking.cli.simulate as mod

    cmd = cli.commands["simulate"]
    assert isinstance(cmd, ModelFlagsCommand)
    flags, skipped = cmd.model_flags(), cmd.skipped()
    assert set(flags) | set(skipped) == set(option_declarations())
    assert not set(flags) & set(skipped)
    help_text = invoke("simulate", "--help")
    for flag in flags.values():
        assert flag in help_text
    for name in ("isolated", "anchored"):
        for d in rocking.models.MODELS[name].Options.describe():
            assert d["name"] in flags or d["name"] in skipped
    doc = mod.__doc__.split("Options WITHOUT a flag", 1)[1].split("\n\n", 1)[0]
    assert sorted(re.findall(r"``(\w+)``\s+\(", doc)) == sorted(skipped)
    assert "isolation_period" in flags and "anchor_strength" in flags


def test_a_new_models_options_get_flags(monkeypatch, capsys):
    """A model registered later gets flags for its options without editing the CLI."""
    from dataclasses import dataclass

    from rocking import models
    from rocking.models.base import option

    housner = models.MODELS["housner"]

    @dataclass(frozen=True)
    class GainOptions(housner.Options):
        zz_gain: float = option(1.0, unit="s", lo=0.0, hi=10.0, help="a test option")

    class Gain(housner):
        name = "zzgain"
        Options = GainOptions

    monkeypatch.setitem(models.MODELS, "zzgain", Gain)
    assert "--zz-gain" in invoke("simulate", "--help")
    assert model_options("zzgain", (), flags={"zz_gain": "500ms"}) == {"zz_gain": 0.5}
    code, _, err = run_main(capsys, *FREE, "--zz-gain", "2")
    assert_one_line_error(code, err, "zz-gain applies to --model zzgain only")


def test_models_command_shows_flags_and_outputs():
    out = invoke("models", "isolated")
    assert out.startswith("isolated: ")
    assert "anchored" not in out.split("\n\n")[0].split("\n", 1)[0]
    rows = {line.split()[0]: line for line in out.splitlines() if line.startswith("  ")}
    assert "--isolation-period" in rows["isolation_period"]
    assert "--clearance" in rows["clearance"]
    assert "--option mu=" in rows["mu"]  # --mu is the command's own (it sets mu too)
    assert "max_base_displacement" in out and "clearance_time" in out
    data = json.loads(invoke("models", "anchored", "--json"))
    assert [m["name"] for m in data] == ["anchored"]
    flags = {o["name"]: o["flag"] for o in data[0]["options"]}
    assert flags["anchor_strength"] == "--anchor-strength"
    assert [r["name"] for r in data[0]["row_outputs"]] == [
        r.name for r in rocking.models.MODELS["anchored"].row_outputs]


def test_models_command_unknown_name(capsys):
    code, _, err = run_main(capsys, "models", "bogus")
    assert_one_line_error(code, err, "bogus")


def test_housner_json_has_no_row_outputs():
    d = run_json("--specimen", "2", "--motion", "free", "--theta0", "0.05", "--duration",
                 "1", "--rest-tol", "1e-6")
    assert "row_outputs" not in d
    assert d["inputs"]["options"] == {"rest_tol": 1e-6}


def test_block_mu_is_imposed_where_the_model_has_its_own(capsys):
    """The isolated model derives its restitution unless its option mu is given: the
    block's ``--mu`` is that option (never silently ignored), as ``--option mu=`` is
    (issue 31: ``--alpha A --p P --mu MU`` works, tests/test_asymmetric_mitigation.py)."""
    d = run_json(*FREE[1:], "--model", "isolated", "--mu", "0.9")
    assert d["inputs"]["options"]["mu"] == 0.9
    assert model_options("isolated", ("mu=0.9",)) == {"mu": 0.9}
    assert "--linear" in invoke("models", "housner").split("linear", 1)[1].splitlines()[0]
