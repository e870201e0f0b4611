"""The ``rocking`` command line (rocking.cli) and the plotting helpers (rocking.plot)."""

from __future__ import annotations

import json
import math
import subprocess
import sys
import types
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from cli_helpers import assert_one_line_error, run_main
from click.testing import CliRunner

import rocking
from rocking.cli import cli
from rocking.motions import OneSine, Sine
from rocking.units import G

# ----------------------------------------------------------------------------- helpers


def invoke(*args):
    """Run the click group in-process; returns the click Result (exceptions propagate)."""
    res = CliRunner().invoke(cli, [str(a) for a in args], catch_exceptions=False)
    assert res.exit_code == 0, res.output
    return res


def rocking_command() -> list[str]:
    """The venv's ``rocking`` executable, or ``python -m rocking.cli``."""
    exe = Path(sys.executable).parent / "rocking"
    return [str(exe)] if exe.exists() else [sys.executable, "-m", "rocking.cli"]


def run_subprocess(*args):
    return subprocess.run([*rocking_command(), *map(str, args)], capture_output=True,
                          text=True, timeout=120)


SINE = ["--motion", "sine", "--freq", "5", "--amp", "5mm", "--duration", "2"]


# ----------------------------------------------------------------------------- params


def test_params_json_width_height():
    res = invoke("params", "--width", "0.17", "--height", "1.0", "--json")
    d = json.loads(res.output)
    assert {"alpha", "p", "mu", "R"} <= set(d)
    assert abs(d["alpha"] - math.atan(0.085 / 0.5)) < 1e-12
    R = math.hypot(0.085, 0.5)
    assert d["R"] == pytest.approx(R, rel=1e-12)
    assert d["p"] == pytest.approx(math.sqrt(3 * G / (4 * R)), rel=1e-12)
    assert d["mu"] == pytest.approx(rocking.housner_mu(d["alpha"]), rel=1e-12)
    assert d["uplift_acceleration"] == pytest.approx(G * math.tan(d["alpha"]), rel=1e-12)
    for k in ("alpha", "p", "mu", "R"):
        assert isinstance(d[k], float)


def test_params_width_units():
    a = json.loads(invoke("params", "--width", "170mm", "--height", "1m", "--json").output)
    b = json.loads(invoke("params", "--width", "0.17", "--height", "1", "--json").output)
    assert a["alpha"] == pytest.approx(b["alpha"], rel=1e-14)
    assert a["R"] == pytest.approx(b["R"], rel=1e-14)


def test_params_specimen_sets():
    d = json.loads(invoke("params", "--specimen", "2", "--json").output)
    assert d["alpha"] == 0.168 and d["p"] == 3.81 and d["mu"] == 0.958
    assert d["specimen"] == 2 and d["params"] == "theoretical"
    e = json.loads(invoke("params", "--specimen", "2", "--params", "experimental",
                          "--json").output)
    assert (e["alpha"], e["p"], e["mu"]) == (0.163, 4.05, 0.973)
    g = json.loads(invoke("params", "--specimen", "2", "--params", "geometric",
                          "--json").output)
    assert g["alpha"] == pytest.approx(math.atan(0.085 / 0.5), rel=1e-12)


def test_params_text_output():
    out = invoke("params", "--specimen", "2").output
    assert "alpha" in out and "deg" in out and "1/s" in out and "uplift" in out
    assert "0.168" in out and "3.81" in out


# ----------------------------------------------------------------------------- simulate


def test_simulate_writes_files_and_matches_library(tmp_path):
    out = tmp_path / "run"
    res = invoke("simulate", "--specimen", 2, "--params", "experimental", "--model", "housner",
                 "--motion", "sine", "--freq", 5, "--amp", "5mm", "--duration", 5,
                 "--out", out)
    assert "max |theta|" in res.output and "overturned" in res.output
    assert "impacts" in res.output
    for f in ("response.csv", "summary.json", "theta.png"):
        assert (out / f).is_file(), f
    df = pd.read_csv(out / "response.csv")
    assert list(df.columns) == ["t", "theta", "omega"]
    # the 5 s sine, then free rocking until the block is at rest
    assert df["t"].iloc[0] == 0.0 and df["t"].iloc[-1] > 5.0
    alpha = rocking.specimen(2, "experimental").alpha  # at rest below 1e-3 alpha
    assert abs(df["theta"].iloc[-1]) < 1e-3 * alpha
    s = json.loads((out / "summary.json").read_text())
    assert {"max_abs_theta", "overturned", "n_impacts", "model", "specimen", "params",
            "inputs", "motion"} <= set(s)
    assert s["specimen"] == 2 and s["params"] == "experimental"
    assert s["inputs"]["motion"]["type"] == "sine"
    assert s["inputs"]["motion"]["amplitude"] == pytest.approx(0.005)
    assert (out / "theta.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"

    ref = rocking.simulate(rocking.specimen(2, params="experimental"),
                           Sine(freq=5.0, amplitude=0.005, duration=5.0), model="housner")
    assert s["max_abs_theta"] == ref.max_abs_theta
    assert s["overturned"] == ref.overturned
    assert s["n_impacts"] == ref.n_impacts
    assert ref.max_abs_theta > 0
    np.testing.assert_allclose(df["theta"].to_numpy(), ref.theta, rtol=1e-8, atol=1e-12)


def test_sine_below_uplift_does_not_rock(tmp_path):
    # 5 mm at 1 Hz is 0.197 m/s^2, far below g tan(0.168) = 1.66 m/s^2
    invoke("simulate", "--specimen", 2, "--motion", "sine", "--freq", "1Hz", "--amp", "5mm",
           "--duration", 5, "--out", tmp_path)
    s = json.loads((tmp_path / "summary.json").read_text())
    assert s["max_abs_theta"] == 0.0
    assert s["overturned"] is False and s["n_impacts"] == 0


def test_simulate_without_out_prints_summary(tmp_path):
    res = invoke("simulate", "--specimen", 2, *SINE)
    assert "max |theta|" in res.output
    assert not list(tmp_path.iterdir())


def test_pulse_with_acceleration_amplitude_and_load_factor(tmp_path):
    invoke("simulate", "--specimen", 2, "--motion", "one_sine", "--amp", "0.25g", "--tp",
           "0.5", "--load-factor", "1.5", "--duration", "4", "--out", tmp_path)
    s = json.loads((tmp_path / "summary.json").read_text())
    ref = rocking.simulate(rocking.specimen(2), OneSine(0.25 * G, 0.5, duration=4.0).scaled(1.5))
    assert s["max_abs_theta"] == ref.max_abs_theta
    assert s["overturned"] == ref.overturned
    assert s["inputs"]["motion"]["load_factor"] == 1.5


def test_sine_amplitude_as_acceleration():
    a = invoke("simulate", "--specimen", 2, "--motion", "sine", "--freq", 5, "--amp",
               f"{0.005 * (2 * math.pi * 5) ** 2}m/s2", "--duration", 2).output
    b = invoke("simulate", "--specimen", 2, *SINE).output
    line = [x for x in a.splitlines() if x.startswith("max |theta|")]
    assert line == [x for x in b.splitlines() if x.startswith("max |theta|")]


def test_free_rocking_and_classical_params(tmp_path):
    invoke("simulate", "--alpha", "9.6deg", "--p", "3.81", "--mu", "0.95", "--motion", "free",
           "--theta0", "2deg", "--duration", 3, "--out", tmp_path)
    s = json.loads((tmp_path / "summary.json").read_text())
    block = rocking.Block.from_params(math.radians(9.6), 3.81, 0.95)
    ref = rocking.simulate(block, None, duration=3.0, theta0=math.radians(2.0))
    assert s["max_abs_theta"] == pytest.approx(math.radians(2.0), rel=1e-9)
    assert s["max_abs_theta"] == ref.max_abs_theta
    assert s["n_impacts"] == ref.n_impacts > 0


def test_mu_override_and_linear(tmp_path):
    invoke("simulate", "--width", "170mm", "--height", "1", "--mu", "0.9", "--motion", "free",
           "--theta0", "0.05", "--duration", 2, "--linear", "--dt-out", "0.01",
           "--out", tmp_path)
    s = json.loads((tmp_path / "summary.json").read_text())
    block = rocking.Block.rectangular(0.17, 1.0, mu=0.9)
    ref = rocking.simulate(block, None, duration=2.0, theta0=0.05, linear=True, dt_out=0.01)
    assert s["block"]["mu"] == 0.9
    assert s["n_impacts"] == ref.n_impacts
    df = pd.read_csv(tmp_path / "response.csv")
    assert len(df) == len(ref.t) and df["t"].iloc[1] == pytest.approx(0.01)


def test_record_file(tmp_path):
    t = np.arange(0, 3.0 + 1e-9, 0.01)
    acc = 3.0 * np.sin(2 * np.pi * 2.0 * t)
    f = tmp_path / "rec.csv"
    pd.DataFrame({"t": t, "acc": acc}).to_csv(f, index=False)
    out = tmp_path / "out"
    invoke("simulate", "--specimen", 2, "--record", f, "--units", "m/s^2", "--out", out)
    s = json.loads((out / "summary.json").read_text())
    ref = rocking.simulate(rocking.specimen(2),
                           rocking.motions.Record.from_file(f, units="m/s^2"))
    assert s["max_abs_theta"] == ref.max_abs_theta > 0
    assert s["inputs"]["motion"]["type"] == "record"


def test_model_choice_comes_from_registry(monkeypatch):
    from rocking import models

    res = CliRunner().invoke(cli, ["simulate", "--help"])
    assert "housner" in res.output
    monkeypatch.setitem(models.MODELS, "zzz", models.MODELS["housner"])
    res = CliRunner().invoke(cli, ["simulate", "--help"])
    assert "zzz" in res.output


# ----------------------------------------------------------------------------- models, --option


def test_commands_registered_and_modules():
    import importlib

    assert {"params", "simulate", "reproduce", "models", "motion", "dem-params",
            "identify"} <= set(cli.commands)
    for name in ("common", "params", "simulate", "motion", "dem", "identify", "reproduce",
                 "models"):
        importlib.import_module(f"rocking.cli.{name}")
    from rocking.cli.dem import dem_params
    from rocking.cli.identify import identify
    from rocking.cli.motion import motion

    assert cli.commands["dem-params"] is dem_params
    assert cli.commands["identify"] is identify
    assert cli.commands["motion"] is motion


def test_models_command_lists_registry():
    from rocking.models import MODELS

    out = invoke("models").output
    for name, cls in MODELS.items():
        assert f"{name}: {cls.label}" in out
        for d in cls.Options.describe():
            assert d["name"] in out and d["help"] in out
    data = json.loads(invoke("models", "--json").output)
    assert [m["name"] for m in data] == list(MODELS)
    for m in data:
        assert [o["name"] for o in m["options"]] == [
            d["name"] for d in MODELS[m["name"]].Options.describe()]
        assert {"name", "default", "unit", "range", "help", "kind"} <= set(m["options"][0])


def test_option_passes_model_options(tmp_path):
    invoke("simulate", "--specimen", 2, "--motion", "free", "--theta0", "0.05",
           "--duration", 2, "--option", "rtol=1e-10", "--option", "rest-tol=1e-5",
           "--out", tmp_path)
    s = json.loads((tmp_path / "summary.json").read_text())
    assert s["inputs"]["options"] == {"rtol": 1e-10, "rest_tol": 1e-5}
    ref = rocking.simulate(rocking.specimen(2), None, duration=2.0, theta0=0.05, rtol=1e-10,
                           rest_tol=1e-5)
    assert s["max_abs_theta"] == ref.max_abs_theta
    assert s["n_impacts"] == ref.n_impacts
    df = pd.read_csv(tmp_path / "response.csv")
    np.testing.assert_allclose(df["theta"].to_numpy(), ref.theta, rtol=1e-8, atol=1e-12)


def test_option_ccrr_matches_library():
    res = invoke("simulate", "--specimen", 2, "--model", "ccrr", "--option", "rtol=1e-7",
                 "--motion", "free", "--theta0", "0.05", "--duration", 2)
    ref = rocking.simulate(rocking.specimen(2), None, model="ccrr", duration=2.0, theta0=0.05,
                           rtol=1e-7)
    assert f"impacts     {ref.n_impacts}" in res.output


def test_option_linear_is_the_linear_flag(tmp_path):
    """``--option linear=true`` (listed by ``rocking models``) is the small-angle model."""
    a, b = tmp_path / "a", tmp_path / "b"
    for out, extra in ((a, ["--option", "linear=true"]), (b, ["--linear"])):
        invoke("simulate", "--specimen", 2, "--motion", "free", "--theta0", "0.05",
               "--duration", 2, *extra, "--out", out)
    sa = json.loads((a / "summary.json").read_text())
    sb = json.loads((b / "summary.json").read_text())
    assert sa["model"] == sb["model"] == "housner-linear"
    assert sa["max_abs_theta"] == sb["max_abs_theta"] and sa["n_impacts"] == sb["n_impacts"]


def test_option_value_parsing():
    from rocking.cli.common import option_value, parse_options

    assert option_value("true") is True and option_value("False") is False
    assert option_value("none") is None
    assert option_value("3") == 3 and isinstance(option_value("3"), int)
    assert option_value("1e-8") == 1e-8 and option_value(" 0.5 ") == 0.5
    assert option_value("paper") == "paper"
    assert parse_options(("a=1", "b-c=x")) == {"a": 1, "b_c": "x"}


def test_dem_flags_are_model_options():
    from rocking.cli.simulate import flag_options, model_options

    # the friction angle goes to the model in rad (issue 17)
    assert flag_options("dem", "20deg", "1e6N/m", "paper") == {
        "friction_angle": pytest.approx(math.radians(20.0), rel=1e-15), "stiffness": 1e6,
        "damping": "paper"}
    assert flag_options("dem", None, None, "Calibrated") == {"damping": "calibrated"}
    assert model_options("dem", (), "0.3rad", "1e6N/m", "0.001") == {
        "friction_angle": 0.3, "stiffness": 1e6, "damping": 0.001}
    with pytest.warns(DeprecationWarning, match="20deg"):  # a bare number: degrees
        bare = flag_options("dem", "20", None, None)
    assert bare == flag_options("dem", "20deg", None, None)
    assert model_options("dem", ("cohesion=5",), None, None, "0.001s") == {
        "cohesion": 5, "damping": 0.001}


def test_dem_damping_words_validate():
    from rocking.cli.simulate import model_options

    assert model_options("dem", (), None, None, "paper") == {"damping": "paper"}


BAD_OPTIONS = [
    (["--option", "bogus=1"], "bogus"),
    (["--option", "rtol=5"], "rtol"),
    (["--option", "rtol=abc"], "rtol"),
    (["--option", "rtol"], "KEY=VALUE"),
    (["--option", "=1"], "KEY=VALUE"),
    (["--option", "rtol=1e-8", "--option", "rtol=1e-9"], "twice"),
    (["--option", "dt_out=0.01"], "dt_out"),
    (["--option", "linear=maybe"], "linear"),
    (["--model", "ccrr", "--option", "l=-1"], "l must"),
    (["--model", "ccrr", "--option", "linear=true"], "linear"),
    (["--stiffness", "1e6"], "stiffness applies to --model dem only"),
    (["--friction-angle", "20"], "friction-angle applies to --model dem only"),
    (["--damping", "paper"], "damping applies to --model dem only"),
    (["--model", "dem", "--friction-angle", "95deg"], "friction-angle must be in [0, "),
    (["--model", "dem", "--friction-angle", "2rad"], "friction-angle must be in [0, "),
    (["--model", "dem", "--friction-angle", "30m"], "friction-angle"),
    (["--model", "dem", "--stiffness", "-1"], "stiffness"),
    (["--model", "dem", "--damping", "lots"], "damping"),
    (["--model", "dem", "--damping", "-1"], "damping"),
    (["--model", "dem", "--stiffness", "1e6", "--option", "stiffness=2e6"], "twice"),
    (["--model", "dem", "--option", "geometry=cube"], "geometry"),
]


@pytest.mark.parametrize(("extra", "name"), BAD_OPTIONS,
                         ids=[" ".join(a) for a, _ in BAD_OPTIONS])
def test_bad_option_is_one_line_error(capsys, extra, name):
    code, out, err = run_main(capsys, "simulate", "--specimen", "2", "--motion", "free",
                              "--theta0", "0.05", "--duration", "1", *extra)
    assert_one_line_error(code, err, name)


FREE = ["simulate", "--specimen", "2", "--motion", "free", "--theta0", "0.05"]


def test_output_guard_names_cli_options(capsys):
    code, out, err = run_main(capsys, *FREE, "--duration", "1e9")
    assert_one_line_error(code, err, "--dt-out")
    assert "--duration" in err and "GB" in err
    assert "dt_out" not in err


def test_subprocess_output_guard():
    r = run_subprocess(*FREE, "--duration", "1e9")
    assert_one_line_error(r.returncode, r.stderr, "--dt-out")
    assert "MemoryError" not in r.stderr and r.stdout == ""


def test_simulation_error_exit_1(capsys):
    # a constant CCRR step far too large for the default l: a numerical failure
    code, out, err = run_main(capsys, *FREE, "--model", "ccrr", "--option", "dt=0.5",
                              "--duration", "2")
    assert code == 1, err
    assert "Traceback" not in err and len(err.strip().splitlines()) == 1
    assert err.startswith("error: ") and "dt" in err


def test_simulation_error_mapping(capsys, monkeypatch):
    from rocking import models

    def failing(*args, **kwargs):
        raise rocking.errors.SimulationError("integration failed\n  near t = 1 s")

    monkeypatch.setattr(models, "simulate", failing)
    code, out, err = run_main(capsys, *FREE, "--duration", "2")
    assert code == 1
    assert err == "error: integration failed near t = 1 s\n"


# ----------------------------------------------------------------------------- reproduce


def test_reproduce_calls_report(tmp_path, monkeypatch, capsys):
    calls = []

    def fake_reproduce(out, quick=False, progress=True, **kw):
        calls.append((Path(out), quick, kw))
        p = Path(out) / "index.html"
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_text("<html></html>")
        return p

    fake = types.ModuleType("rocking.report")
    fake.reproduce = fake_reproduce
    monkeypatch.setitem(sys.modules, "rocking.report", fake)
    monkeypatch.setattr(rocking, "report", fake, raising=False)
    res = invoke("reproduce", "--out", tmp_path / "res", "--quick")
    assert calls == [(tmp_path / "res", True, {})]  # no full=: works with an older report
    assert res.output.strip() == str(tmp_path / "res" / "index.html")
    invoke("reproduce", "--out", tmp_path / "res", "--full")
    assert calls[-1] == (tmp_path / "res", False, {"full": True})
    invoke("reproduce", "--out", tmp_path / "res", "--jobs", "3")
    assert calls[-1] == (tmp_path / "res", False, {"jobs": 3})
    n = len(calls)
    code, _, err = run_main(capsys, "reproduce", "--out", str(tmp_path / "res"), "--jobs", "0")
    assert_one_line_error(code, err, "--jobs")
    assert len(calls) == n


def test_reproduce_failed_sections_exit_1(tmp_path, monkeypatch, capsys):
    class ReportError(RuntimeError):
        def __init__(self, path, failed):
            self.path = Path(path)
            super().__init__(f"1 report section(s) failed (x: boom); written anyway: {path}")

    def fake_reproduce(out, quick=False, progress=True):
        raise ReportError(Path(out) / "index.html", {"x": "boom"})

    fake = types.ModuleType("rocking.report")
    fake.reproduce, fake.ReportError = fake_reproduce, ReportError
    monkeypatch.setitem(sys.modules, "rocking.report", fake)
    monkeypatch.setattr(rocking, "report", fake, raising=False)
    code, out, err = run_main(capsys, "reproduce", "--out", tmp_path)
    assert code == 1
    assert out.strip() == str(tmp_path / "index.html")
    assert err.startswith("error: 1 report section(s) failed") and "Traceback" not in err
    assert len(err.strip().splitlines()) == 1


# ----------------------------------------------------------------------------- main()


def test_version_and_help(capsys):
    code, out, _ = run_main(capsys, "--version")
    assert code == 0 and rocking.__version__ in out
    code, out, _ = run_main(capsys, "--help")
    assert code == 0 and "simulate" in out and "params" in out
    code, out, _ = run_main(capsys, "simulate", "--help")
    assert code == 0 and "--amp" in out


def test_main_success(capsys):
    code, out, err = run_main(capsys, "params", "--specimen", "3", "--json")
    assert code == 0 and err == ""
    assert json.loads(out)["alpha"] == 0.119


BAD = [
    (["params"], "specimen"),
    (["params", "--specimen", "2", "--width", "0.17"], "specimen"),
    (["params", "--specimen", "9"], "specimen"),
    (["params", "--specimen", "two"], "specimen"),
    (["params", "--specimen", "2", "--params", "foo"], "params"),
    (["params", "--width", "-0.17", "--height", "1"], "width"),
    (["params", "--width", "nan", "--height", "1"], "width"),
    (["params", "--width", "inf", "--height", "1"], "width"),
    (["params", "--width", "0.17", "--height", "0"], "height"),
    (["params", "--width", "0.17"], "height"),
    (["params", "--width", "0.17", "--height", "1", "--mass", "-3"], "mass"),
    (["params", "--width", "0.17furlong", "--height", "1"], "width"),
    (["params", "--bogus"], "--bogus"),
    (["simulate", "--specimen", "2", "--motion", "sine", "--freq", "5", "--amp", "-5mm",
      "--duration", "2"], "amp must be in [0, inf)"),
    (["simulate", "--specimen", "2", "--motion", "sine", "--freq", "5", "--amp", "5",
      "--duration", "2"], "amp"),
    (["simulate", "--specimen", "2", "--motion", "one_sine", "--amp", "5mm", "--tp", "0.5"],
     "amp"),
    (["simulate", "--specimen", "2", "--motion", "one_sine", "--amp", "0.3", "--tp", "0.5"],
     "amp"),
    (["simulate", "--specimen", "2", "--motion", "one_sine", "--amp", "-0.3g", "--tp", "0.5"],
     "amp must be in [0, inf)"),
    (["simulate", "--specimen", "2", "--motion", "one_sine", "--amp", "0.3g"], "tp"),
    (["simulate", "--specimen", "2", "--motion", "one_sine", "--amp", "0.3g", "--tp", "0"],
     "tp"),
    (["simulate", "--specimen", "7", *SINE], "specimen"),
    (["simulate", *SINE], "specimen"),
    (["simulate", "--alpha", "2", "--p", "3", "--mu", "0.9", *SINE], "alpha"),
    (["simulate", "--alpha", "0", "--p", "3", "--mu", "0.9", *SINE], "alpha"),
    (["simulate", "--alpha", "0.2", "--p", "3", "--mu", "1.5", *SINE], "mu"),
    (["simulate", "--alpha", "0.2", "--p", "3", "--mu", "0", *SINE], "mu"),
    (["simulate", "--alpha", "0.2", "--p", "-3", "--mu", "0.9", *SINE], "p must"),
    (["simulate", "--alpha", "0.2", *SINE], "mu"),
    (["simulate", "--specimen", "2", "--mu", "nan", *SINE], "mu"),
    (["simulate", "--specimen", "2", "--width", "0.2", "--height", "1", *SINE], "specimen"),
    (["simulate", "--width", "0", "--height", "1", *SINE], "width"),
    (["simulate", "--specimen", "2", "--model", "nope", *SINE], "model"),
    (["simulate", "--specimen", "2", "--motion", "earthquake"], "motion"),
    (["simulate", "--specimen", "2"], "motion"),
    (["simulate", "--specimen", "2", "--motion", "sine", "--freq", "0", "--amp", "5mm",
      "--duration", "2"], "freq"),
    (["simulate", "--specimen", "2", "--motion", "sine", "--freq", "5mm", "--amp", "5mm",
      "--duration", "2"], "freq"),
    (["simulate", "--specimen", "2", "--motion", "sine", "--freq", "5", "--amp", "5mm"],
     "duration"),
    (["simulate", "--specimen", "2", "--motion", "sine", "--freq", "5", "--amp", "5mm",
      "--duration", "-1"], "duration"),
    (["simulate", "--specimen", "2", "--motion", "free", "--max-free-time", "-2"],
     "max-free-time"),
    (["simulate", "--specimen", "2", "--motion", "free", "--duration", "1", "--theta0", "2"],
     "theta0"),
    (["simulate", "--specimen", "2", "--motion", "free", "--duration", "1", "--omega0", "x"],
     "omega0"),
    (["simulate", "--specimen", "2", *SINE, "--load-factor", "abc"], "load-factor"),
    (["simulate", "--specimen", "2", *SINE, "--dt-out", "0"], "dt_out"),
    (["simulate", "--specimen", "2", *SINE, "--units", "g"], "units"),
    (["simulate", "--specimen", "2", "--record", "/nonexistent/quake.AT2"], "record"),
]


@pytest.mark.parametrize(("args", "name"), BAD, ids=[" ".join(a) for a, _ in BAD])
def test_bad_input_is_one_line_error(capsys, args, name):
    code, out, err = run_main(capsys, *args)
    assert_one_line_error(code, err, name)


def _record_file(tmp_path, text, name="rec.csv"):
    p = tmp_path / name
    p.write_text(text)
    return p


@pytest.mark.parametrize(("text", "extra", "name"), [
    ("t,acc\n0,0\n0.01,0.1\n0.02,nan\n", [], "nan"),
    ("", [], "empty"),
    ("t,acc\n0,0\n0.01,abc\n0.02,0.3\n", [], "rec.csv"),
    ("0\n0.1\n0.2\n", ["--dt", "0.01", "--units", "furlong/s2"], "units"),
    ("0\n0.1\n0.2\n", ["--dt", "-0.01"], "dt"),
])
def test_bad_record_is_one_line_error(capsys, tmp_path, text, extra, name):
    f = _record_file(tmp_path, text)
    code, out, err = run_main(capsys, "simulate", "--specimen", "2", "--record", f, *extra)
    assert_one_line_error(code, err, name)


# ----------------------------------------------------------------------------- subprocess


def test_subprocess_bare_amplitude():
    r = run_subprocess("simulate", "--specimen", "2", "--motion", "sine", "--freq", "5",
                       "--amp", "5", "--duration", "2")
    assert_one_line_error(r.returncode, r.stderr, "amp")
    assert "unit" in r.stderr and "5mm" in r.stderr


def test_subprocess_negative_amplitude():
    r = run_subprocess("simulate", "--specimen", "2", "--motion", "sine", "--freq", "5",
                       "--amp", "-5mm", "--duration", "2")
    assert_one_line_error(r.returncode, r.stderr, "error: amp must be in [0, inf)")


def test_subprocess_unknown_specimen():
    r = run_subprocess("params", "--specimen", "5")
    assert_one_line_error(r.returncode, r.stderr, "specimen")
    assert "[1, 4]" in r.stderr


def test_subprocess_usage_errors():
    r = run_subprocess("params", "--specimen", "2", "--nope")
    assert_one_line_error(r.returncode, r.stderr, "--nope")
    r = run_subprocess("simulate", "--specimen", "2", "--model", "nope", *SINE)
    assert_one_line_error(r.returncode, r.stderr, "model")
    assert "housner" in r.stderr


def test_subprocess_success_and_version(tmp_path):
    r = run_subprocess("--version")
    assert r.returncode == 0 and rocking.__version__ in r.stdout
    r = run_subprocess("params", "--width", "0.17", "--height", "1.0", "--json")
    assert r.returncode == 0, r.stderr
    assert abs(json.loads(r.stdout)["alpha"] - math.atan(0.085 / 0.5)) < 1e-12


# ----------------------------------------------------------------------------- plot


def test_plot_helpers(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    from rocking.plot import figure, plot_motion, plot_response, plot_responses, save_figure

    block = rocking.specimen(2)
    calm = rocking.simulate(block, Sine(5.0, 0.005, 2.0))
    over = rocking.simulate(block, OneSine(0.5 * G, 0.5))
    assert over.overturned

    fig, ax = figure()
    assert plot_response(over, ax=ax, label="one-sine", show_alpha=True) is ax
    assert "deg" in ax.get_ylabel() and "(s)" in ax.get_xlabel()
    assert any("overturned" in t.get_text() for t in ax.texts)
    ydata = np.concatenate([ln.get_ydata() for ln in ax.lines])
    assert np.nanmax(np.abs(ydata)) == pytest.approx(90.0)
    p = save_figure(fig, tmp_path / "sub" / "over.png")
    assert p.read_bytes()[:4] == b"\x89PNG"

    fig, ax = figure()
    plot_response(calm, ax=ax, deg=False)
    assert "rad" in ax.get_ylabel()
    np.testing.assert_allclose(ax.lines[0].get_ydata(), calm.theta)

    fig, ax = figure()
    plot_responses([calm, over], ["calm", "pulse"], ax=ax)
    assert [t.get_text() for t in ax.get_legend().get_texts()] == ["calm", "pulse"]
    with pytest.raises(rocking.ParameterError, match="labels"):
        plot_responses([calm, over], ["one"], ax=ax)

    fig, ax = figure()
    plot_motion(Sine(5.0, 0.005, 2.0), ax=ax)
    assert "m/s" in ax.get_ylabel()
    assert np.max(np.abs(ax.lines[0].get_ydata())) == pytest.approx(
        0.005 * (2 * math.pi * 5) ** 2, rel=1e-3)
    save_figure(ax, tmp_path / "motion.png")
    assert (tmp_path / "motion.png").is_file()
