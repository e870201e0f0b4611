"""The command line speaks the catalog's vocabulary (issue 17): ``rocking simulate`` builds
every motion through :mod:`rocking.motions.catalog` and every block through
:mod:`rocking.blocks.factory`; ``rocking motions`` and ``rocking blocks`` list them."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from cli_helpers import assert_one_line_error, run_main

import rocking
from rocking import models
from rocking.blocks import factory
from rocking.cli.simulate import MOTION_CHOICES
from rocking.motions import catalog
from rocking.units import ACCELERATION, FREQUENCY, LENGTH, TIME

G = ACCELERATION["g"]
MM, CM = LENGTH["mm"], LENGTH["cm"]


class Captured(Exception):
    """Raised by the stand-in of rocking.models.simulate once it has seen its inputs."""


def captured(monkeypatch, capsys, *args):
    """``rocking simulate --specimen 2 ARGS`` up to the model: ``(block, motion, keyword
    arguments of simulate, stderr)``."""
    seen = {}

    def stand_in(block, motion, **kw):
        seen.update(block=block, motion=motion, kw=kw)
        raise Captured

    monkeypatch.setattr(models, "simulate", stand_in)
    block_given = {"--specimen", "--width", "--alpha"} & set(args)
    with pytest.raises(Captured):
        run_main(capsys, "simulate", *(args if block_given else ("--specimen", "2", *args)))
    return seen["block"], seen["motion"], seen["kw"], capsys.readouterr().err


def same_motion(a, b) -> bool:
    ka, pa, sa = a.spec()
    kb, pb, sb = b.spec()
    return ka == kb and np.array_equal(pa, pb) and np.array_equal(sa, sb)


@pytest.fixture
def files(tmp_path):
    """A two-column record (m/s^2), a one-column one (dt 0.01 s) and a vertical one."""
    t = np.arange(0.0, 2.0 + 1e-9, 0.01)
    h, v = tmp_path / "h.csv", tmp_path / "v.csv"
    h.write_text("t,acc\n" + "\n".join(f"{a:.2f},{3.0 * math.sin(4 * a):.6f}" for a in t))
    v.write_text("t,acc\n" + "\n".join(f"{a:.2f},{-2.0 * math.sin(7 * a):.6f}" for a in t))
    one = tmp_path / "one.txt"
    one.write_text("\n".join(f"{0.2 * math.cos(5 * a):.6f}" for a in t))
    return {"h": str(h), "v": str(v), "one": str(one)}


# (flags of simulate, kind, parameters in SI, load factor, duration of the run)
CASES = [
    (["--motion", "sine", "--freq", "2", "--amp", "5mm", "--duration", "3"],
     "sine", {"frequency": 2.0, "displacement": 5 * MM, "duration": 3.0}, 1.0, None),
    (["--motion", "sine", "--freq", "2Hz", "--amp", "0.3g", "--duration", "3",
      "--param", "phase=0.5"],
     "sine", {"frequency": 2.0, "amplitude": 0.3 * G, "duration": 3.0, "phase": 0.5}, 1.0,
     None),
    (["--motion", "sine", "--freq", "0.5kHz", "--amp", "2um", "--param", "cycles=40"],
     "sine", {"frequency": 0.5 * FREQUENCY["khz"], "displacement": 2 * LENGTH["um"],
              "cycles": 40}, 1.0,
     None),
    (["--motion", "hanning", "--freq", "1.5", "--amp", "2cm", "--duration", "4s",
      "--load-factor", "1.5"],
     "hanning", {"frequency": 1.5, "displacement": 2 * CM, "duration": 4.0}, 1.5, None),
    (["--motion", "hanning", "--freq", "3", "--amp", "2.5m/s^2", "--duration", "2"],
     "hanning", {"frequency": 3.0, "amplitude": 2.5, "duration": 2.0}, 1.0, None),
    (["--motion", "one_sine", "--amp", "0.25g", "--tp", "0.5"],
     "one_sine", {"amplitude": 0.25 * G, "period": 0.5}, 1.0, None),
    (["--motion", "one_cosine", "--amp", "2.5m/s2", "--tp", "400ms", "--duration", "6"],
     "one_cosine", {"amplitude": 2.5, "period": 400 * TIME["ms"], "duration": 6.0}, 1.0, 6.0),
    (["--motion", "half_sine", "--amp", "0.4g", "--tp", "0.3", "--param", "t0=1s"],
     "half_sine", {"amplitude": 0.4 * G, "period": 0.3, "t0": 1.0}, 1.0, None),
    (["--motion", "rectangular", "--amp", "0.2g", "--tp", "0.2", "--load-factor", "-1"],
     "rectangular", {"amplitude": 0.2 * G, "period": 0.2}, -1.0, None),
    (["--motion", "ricker", "--amp", "0.3g", "--freq", "2"],
     "ricker", {"amplitude": 0.3 * G, "frequency": 2.0}, 1.0, None),
    (["--motion", "ricker", "--amp", "0.3g", "--tp", "0.5", "--param", "tc=1",
      "--duration", "5"],
     "ricker", {"amplitude": 0.3 * G, "period": 0.5, "tc": 1.0, "duration": 5.0}, 1.0, 5.0),
    (["--motion", "mavroeidis_papageorgiou", "--amp", "0.2g", "--freq", "1", "--param",
      "gamma=2.5", "--param", "nu=0.3"],
     "mavroeidis_papageorgiou", {"amplitude": 0.2 * G, "frequency": 1.0, "gamma": 2.5,
                                 "nu": 0.3}, 1.0, None),
    (["--motion", "mavroeidis_papageorgiou", "--amp", "3m/s^2", "--freq", "0.8",
      "--param", "gamma=3", "--param", "nu=90deg", "--param", "t0=4"],
     "mavroeidis_papageorgiou", {"amplitude": 3.0, "frequency": 0.8, "gamma": 3.0,
                                 "nu": 90 * math.pi / 180, "t0": 4.0}, 1.0, None),
    (["--record", "{h}", "--units", "m/s^2"],
     "record", {"file": "{h}", "units": "m/s^2"}, 1.0, None),
    (["--motion", "record", "--record", "{one}", "--units", "g", "--dt", "10ms",
      "--load-factor", "2", "--duration", "3"],
     "record", {"file": "{one}", "units": "g", "dt": 0.01}, 2.0, 3.0),
    (["--record", "Rinaldi228"], "builtin", {"name": "Rinaldi228"}, 1.0, None),
    (["--earthquake", "7", "--load-factor", "1.2"],
     "earthquake", {"number": 7}, 1.2, None),
    (["--record", "{h}", "--vertical", "{v}", "--units", "m/s^2", "--vertical-factor", "0.5"],
     "ground_motion", {"file": "{h}", "vertical_file": "{v}", "units": "m/s^2",
                       "vertical_factor": 0.5}, 1.0, None),
    (["--record", "{h}", "--vertical", "{v}", "--units", "m/s^2"],
     "ground_motion", {"file": "{h}", "vertical_file": "{v}", "units": "m/s^2"}, 1.0, None),
    (["--motion", "ec8_earthquake", "--param", "number=2", "--param", "ground=C"],
     "ec8_earthquake", {"number": 2, "ground": "C"}, 1.0, None),
]
NOT_FROM_THE_CLI = {"stochastic"}  # needs a seed and a generator: campaigns only


def _fill(x, files):
    return x.format(**files) if isinstance(x, str) else x


@pytest.mark.parametrize(("args", "kind", "params", "lf", "run"), CASES,
                         ids=[" ".join(c[0]) for c in CASES])
def test_cli_motion_is_the_catalog_motion(monkeypatch, capsys, files, args, kind, params,
                                          lf, run):
    args = [_fill(a, files) for a in args]
    _, motion, kw, err = captured(monkeypatch, capsys, *args)
    assert err == ""
    ref = catalog.build(kind, **{k: _fill(v, files) for k, v in params.items()})
    if lf != 1.0:
        ref = ref.scaled(lf)
    assert type(motion) is type(ref)
    assert same_motion(motion, ref)
    assert kw["duration"] == run


def test_every_kind_but_stochastic_is_reachable():
    assert {c[1] for c in CASES} == set(catalog.KINDS) - NOT_FROM_THE_CLI
    assert set(MOTION_CHOICES) - {"free"} <= set(catalog.KINDS)


def test_vertical_factor_is_absolute_and_defaults_to_the_load_factor(monkeypatch, capsys,
                                                                    files):
    base = catalog.build("ground_motion", file=files["h"], vertical_file=files["v"],
                         units="m/s^2")
    for extra, fh, fv in ((["--load-factor", "2"], 2.0, 2.0),
                          (["--load-factor", "2", "--vertical-factor", "0.5"], 2.0, 0.5)):
        _, motion, _, _ = captured(monkeypatch, capsys, "--record", files["h"], "--vertical",
                                   files["v"], "--units", "m/s^2", *extra)
        assert same_motion(motion, base.scaled(fh, vertical=fv))


ALIASES = sorted(a for a, k in catalog.ALIASES.items() if k in MOTION_CHOICES)
ALIAS_ARGS = {"sine": ["--freq", "2", "--amp", "5mm", "--duration", "2"],
              "ricker": ["--amp", "0.3g", "--freq", "2"],
              "mavroeidis_papageorgiou": ["--amp", "0.3g", "--freq", "1", "--param",
                                          "gamma=2", "--param", "nu=0"]}
PULSE_ARGS = ["--amp", "0.3g", "--tp", "0.5"]


@pytest.mark.parametrize("old", ALIASES)
def test_old_spelling_warns_and_gives_the_same_motion(monkeypatch, capsys, old):
    new = catalog.ALIASES[old]
    extra = ALIAS_ARGS.get(new, PULSE_ARGS)
    _, m_new, _, err_new = captured(monkeypatch, capsys, "--motion", new, *extra)
    _, m_old, _, err_old = captured(monkeypatch, capsys, "--motion", old, *extra)
    assert err_new == ""
    lines = err_old.strip("\n").splitlines()
    assert len(lines) == 1, err_old
    assert lines[0].startswith("warning: ") and "deprecated" in lines[0]
    assert old in lines[0] and f"write '{new}'" in lines[0]
    assert same_motion(m_old, m_new)


def test_old_spelling_runs_with_exit_0(capsys, tmp_path):
    code, out, err = run_main(capsys, "simulate", "--specimen", "2", "--motion", "one-sine",
                              "--amp", "0.3g", "--tp", "0.5", "--out", tmp_path)
    assert code == 0, err
    deprecated = [x for x in err.splitlines() if "deprecated" in x]
    assert len(deprecated) == 1 and deprecated[0].startswith("warning: "), err
    assert "error" not in err and "Traceback" not in err
    s = json.loads((tmp_path / "summary.json").read_text())
    assert s["inputs"]["motion"]["type"] == "one_sine"


def test_summary_keys_of_the_motion(capsys, tmp_path):
    """summary.json describes the motion with the keys it always had."""
    keys = {"sine": {"type", "freq", "amplitude", "acc_amplitude", "duration",
                     "load_factor", "repr"},
            "one_sine": {"type", "amplitude", "tp", "duration", "load_factor", "repr"},
            "ricker": {"type", "amplitude", "fp", "tc", "duration", "load_factor", "repr"}}
    for kind, extra in (("sine", ALIAS_ARGS["sine"]), ("one_sine", PULSE_ARGS),
                        ("ricker", ALIAS_ARGS["ricker"])):
        out = tmp_path / kind
        code, _, err = run_main(capsys, "simulate", "--specimen", "2", "--motion", kind,
                                *extra, "--duration", "2", "--out", out)
        assert code == 0, err
        d = json.loads((out / "summary.json").read_text())["inputs"]["motion"]
        assert set(d) == keys[kind], d


def test_cli_block_is_the_factory_block(monkeypatch, capsys):
    sine = ALIAS_ARGS["sine"]
    for flags, mapping in (
            (["--specimen", "3", "--params", "experimental", "--mu", "0.9"],
             {"specimen": 3, "params": "experimental", "mu": 0.9}),
            (["--width", "170mm", "--height", "1", "--p", "3.5 1/s"],
             {"width": 170 * MM, "height": 1.0, "p": 3.5}),
            (["--alpha", "9.6deg", "--p", "3.81", "--mu", "0.95"],
             {"alpha": 9.6 * math.pi / 180, "p": 3.81, "mu": 0.95})):
        block, _, _, _ = captured(monkeypatch, capsys, *flags, "--motion", "sine", *sine)
        ref = factory.make_block(mapping)
        assert block.params() == ref.params() and block.name == ref.name


def test_friction_angle_in_rad_and_bare_degrees_deprecated(monkeypatch, capsys):
    args = ["--model", "dem", "--motion", "free", "--theta0", "0.01", "--duration", "0.1"]
    _, _, kw, err = captured(monkeypatch, capsys, *args, "--friction-angle", "0.5rad")
    assert kw["friction_angle"] == 0.5 and err == ""
    _, _, kw_deg, err = captured(monkeypatch, capsys, *args, "--friction-angle", "35deg")
    assert kw_deg["friction_angle"] == pytest.approx(math.radians(35.0), rel=1e-15)
    assert err == ""
    _, _, kw_bare, err = captured(monkeypatch, capsys, *args, "--friction-angle", "35")
    assert kw_bare["friction_angle"] == kw_deg["friction_angle"]
    (line,) = err.strip("\n").splitlines()
    assert line.startswith("warning: friction-angle") and "deprecated" in line
    assert "35deg" in line


def test_motions_lists_every_kind_and_parameter(capsys):
    code, out, err = run_main(capsys, "motions")
    assert code == 0 and err == ""
    sections = {s.split(":", 1)[0]: s for s in out.strip().split("\n\n")}
    for name, k in catalog.KINDS.items():
        assert name in sections, name
        rows = sections[name].splitlines()[2:]  # title, table head
        assert [r.split()[0] for r in rows] == [d["name"] for d in k.describe()]
        for d, row in zip(k.describe(), rows, strict=True):
            assert d["help"] in row and (d["unit"] or "-") in row
            assert (d["range"] or "-") in row
    code, out, _ = run_main(capsys, "motions", "--json")
    data = json.loads(out)
    assert [k["name"] for k in data] == list(catalog.KINDS)
    for k in data:
        assert [d["name"] for d in k["parameters"]] == [
            d["name"] for d in catalog.KINDS[k["name"]].describe()]


def test_motions_one_kind(capsys):
    code, out, err = run_main(capsys, "motions", "ricker")
    assert code == 0 and err == ""
    assert out.startswith("ricker:") and "\n\none_sine" not in out
    code, out, err = run_main(capsys, "motions", "mp")
    assert code == 0 and out.startswith("mavroeidis_papageorgiou:")
    assert err.startswith("warning: ") and "deprecated" in err


def test_blocks_lists_every_form_and_key(capsys):
    code, out, err = run_main(capsys, "blocks")
    assert code == 0 and err == ""
    sections = {s.split(":", 1)[0]: s for s in out.strip().split("\n\n")}
    for name, form in factory.FORMS.items():
        assert name in sections, name
        rows = sections[name].splitlines()[2:]
        assert [r.split()[0] for r in rows] == [d["name"] for d in form.describe()]
    data = json.loads(run_main(capsys, "blocks", "--json")[1])
    assert [f["name"] for f in data] == list(factory.FORMS)
    code, out, _ = run_main(capsys, "blocks", "polygon")
    assert code == 0 and out.startswith("polygon:") and "vertices" in out


def test_commands_registered():
    from rocking.cli import cli
    from rocking.cli.catalog import blocks_cmd, motions_cmd

    assert cli.commands["motions"] is motions_cmd
    assert cli.commands["blocks"] is blocks_cmd


MP = ["--motion", "mavroeidis_papageorgiou", "--amp", "0.3g", "--freq", "1"]
SINE = ["--motion", "sine", "--freq", "2", "--amp", "5mm", "--duration", "2"]
BAD = [
    (["motions", "nope"], "kind must be one of"),
    (["blocks", "nope"], "form must be one of"),
    (["simulate", "--specimen", "2", *MP, "--param", "gamma=0.5", "--param", "nu=0"],
     "gamma must be in (1, inf)"),
    (["simulate", "--specimen", "2", *MP, "--param", "nu=0"], "gamma is required"),
    (["simulate", "--specimen", "2", *MP, "--param", "gamma=2", "--param", "nu=2m"], "nu"),
    (["simulate", "--specimen", "2", *SINE, "--param", "bogus=1"], "bogus"),
    (["simulate", "--specimen", "2", *SINE, "--param", "phase"], "KEY=VALUE"),
    (["simulate", "--specimen", "2", *SINE, "--param", "frequency=3"], "twice"),
    (["simulate", "--specimen", "2", *SINE, "--param", "phase=x"], "phase"),
    (["simulate", "--specimen", "2", *SINE[:-2], "--param", "cycles=-1"], "cycles"),
    (["simulate", "--specimen", "2", "--motion", "hanning", *SINE[2:], "--param",
      "phase=0.5"], "phase"),
    (["simulate", "--specimen", "2", "--motion", "free", "--param", "t0=1"], "param"),
    (["simulate", "--specimen", "2", "--motion", "one_sine", "--amp", "0.3g", "--tp", "0.5",
      "--freq", "2"], "freq does not apply"),
    (["simulate", "--specimen", "2", *SINE, "--tp", "1"], "tp does not apply"),
    (["simulate", "--specimen", "2", "--motion", "ricker", "--amp", "0.3g"], "freq or tp"),
    (["simulate", "--specimen", "2", "--motion", "ricker", "--amp", "0.3g", "--freq", "2",
      "--tp", "0.5"], "freq or tp"),
    (["simulate", "--specimen", "2", "--motion", "sine", "--freq", "2", "--duration", "2"],
     "amp"),
    (["simulate", "--specimen", "2", *SINE[:-1], "2e4"], "duration must be in (0, 10000] s"),
    (["simulate", "--specimen", "2", "--motion", "one_sine", "--amp", "0.3g", "--tp",
      "1e5"], "tp must be in (0, 10000] s"),
    (["simulate", "--specimen", "2", "--motion", "one_sine", "--amp", "0.3furlong",
      "--tp", "1"], "amp"),
    (["simulate", "--specimen", "2", "--earthquake", "31"], "earthquake must be in [1, 30]"),
    (["simulate", "--specimen", "2", "--earthquake", "2.5"], "earthquake"),
    (["simulate", "--specimen", "2", "--earthquake", "7", "--amp", "0.3g"], "amp"),
    (["simulate", "--specimen", "2", "--motion", "nope"], "motion"),
    (["simulate", "--specimen", "2", "--motion", "stochastic", "--param", "zeta_f=2"],
     "zeta_f"),
    (["simulate", "--specimen", "2", "--motion", "ground_motion"], "set or file"),
    (["simulate", "--specimen", "2", "--record", "Rinaldi228", "--dt", "0.01"], "--dt"),
    (["simulate", "--specimen", "2", "--model", "dem", "--motion", "free", "--friction-angle",
      "95deg"], "friction-angle must be in [0, "),
    (["simulate", "--specimen", "5", *SINE], "specimen must be in [1, 4]"),
    (["simulate", "--width", "0.2", "--height", "1", "--p", "-1", *SINE], "p must be in"),
    (["simulate", "--width", "0.2", "--height", "1", "--mu", "2", *SINE], "mu must be in"),
    (["simulate", "--alpha", "0.2", "--mu", "0.9", *SINE], "p is required"),
    (["params", "--specimen", "2", "--mass", "3"], "mass does not apply"),
    (["params", "--width", "0.2", "--height", "1", "--params", "experimental"],
     "params does not apply"),
    (["params", "--width", "0.2", "--height", "1", "--mass", "-3kg"], "mass must be in"),
]


@pytest.mark.parametrize(("args", "name"), BAD, ids=[" ".join(a) for a, _ in BAD])
def test_bad_value_is_one_line_error(capsys, args, name):
    code, _, err = run_main(capsys, *args)
    assert_one_line_error(code, err, name)


def test_error_shows_the_value_as_typed(capsys):
    code, _, err = run_main(capsys, "simulate", "--specimen", "2", "--motion", "sine",
                            "--freq", "2", "--amp", "-5mm", "--duration", "2")
    assert_one_line_error(code, err, "amp must be in [0, inf) m")
    assert "'-5mm'" in err


def test_mass_with_its_unit(capsys):
    code, out, err = run_main(capsys, "params", "--width", "0.2", "--height", "1", "--mass",
                              "228kg", "--json")
    assert code == 0, err
    assert json.loads(out)["mass"] == rocking.Block.rectangular(0.2, 1.0, mass=228.0).mass


# every kind of the catalog through --motion and --param: the catalog's own motion
def _param_args(params: dict) -> list[str]:
    return [a for k, v in params.items() for a in ("--param", f"{k}={v}")]


@pytest.mark.parametrize("name", sorted(catalog.KINDS))
def test_every_catalog_kind_through_param(name, tmp_path):
    from test_catalog import EXAMPLES  # one example per kind, checked against the classes

    from rocking.cli.simulate import make_motion

    if name == "record":  # --motion record takes --record FILE (and --dt, --units)
        path = tmp_path / "r.txt"
        path.write_text("\n".join(f"{x:.5f}" for x in np.sin(np.arange(300) / 7.0) * 0.1))
        params = {"file": str(path), "dt": 0.01}
        m, desc, _ = make_motion(name, None, None, None, None, str(path), None, "0.01", None)
    else:
        params = EXAMPLES[name][0]
        pairs = tuple(f"{k}={v}" for k, v in params.items())
        m, desc, _ = make_motion(name, None, None, None, None, None, None, None, None,
                                 params=pairs)
    ref = catalog.build(name, catalog.Context(seed=0), **params)
    (ka, pa, sa), (kb, pb, sb) = m.spec(), ref.spec()
    assert ka == kb and np.array_equal(pa, pb) and np.array_equal(sa, sb)
    assert desc["type"] == name
