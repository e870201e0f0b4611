"""The ``rocking`` command line.

::

    rocking params --specimen 2 [--params theoretical|experimental|geometric] [--json]
    rocking params --width 0.17 --height 1.0 [--mass 228] [--json]
    rocking simulate --specimen 2 --params experimental --motion sine --freq 5 --amp 5mm \\
        --duration 25 --out out/
    rocking simulate --specimen 2 --record quake.AT2 --units g --load-factor 1.2 --out out/
    rocking reproduce --out results [--quick]

Quantities accept units at the edge (``170mm``, ``0.3g``, ``5Hz``, ``9.6deg``); see
:func:`rocking.units.parse_quantity`. Bad input -- a :class:`~rocking.errors.RockingError`
from the library or a usage error from click -- is reported by :func:`main` as one line
``error: <message>`` on stderr with exit code 2, never as a traceback.
"""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

import click

from . import __version__
from ._validate import as_float
from .blocks import PARAM_SETS
from .errors import ParameterError, RecordError, RockingError

PULSES = ("one-sine", "one-cosine", "half-sine", "rectangular", "ricker")
HARMONIC = ("sine", "hanning")
MOTION_CHOICES = (*HARMONIC, *PULSES, "free", "record")
UNITS_HELP = "g, m/s^2 or cm/s^2"


# ----------------------------------------------------------------------------- parsing
def _qty(text, kind: str, name: str, default_unit: str | None = None) -> float | None:
    """``text`` as an SI float (None stays None)."""
    if text is None:
        return None
    from .units import parse_quantity

    return parse_quantity(text, kind, name=name, default_unit=default_unit)


def _number(text, name: str, units: tuple[str, ...] = ()) -> float | None:
    """A plain finite number, optionally followed by one of ``units`` (e.g. ``1/s``)."""
    if text is None:
        return None
    s = str(text).strip()
    for u in units:
        if s.lower().endswith(u):
            s = s[: -len(u)].strip()
            break
    return as_float(name, s)


def _amplitude(text, motion: str) -> tuple[str, float]:
    """``--amp`` as ``("length", m)`` or ``("acceleration", m/s^2)``, checked >= 0."""
    from .units import ACCELERATION, LENGTH, split_quantity

    parts = split_quantity(text)
    if parts is None:  # not a number: let parse_quantity word the error
        _qty(text, "length" if motion in HARMONIC else "acceleration", "amp")
    unit = parts[1]
    if motion in HARMONIC:
        hint = ("a table displacement with a length unit such as 5mm "
                "(or an acceleration such as 0.3g)")
        if unit in ACCELERATION:
            kind = "acceleration"
        elif not unit:
            raise ParameterError(f"amp needs a unit for --motion {motion}: {hint}; got {text!r}")
        else:
            kind = "length"
    else:
        hint = "an acceleration with a unit such as 0.3g or 2.8m/s2"
        if unit in LENGTH:
            raise ParameterError(f"amp for --motion {motion} is a peak acceleration, not a "
                                 f"length: give {hint}; got {text!r}")
        if not unit:
            raise ParameterError(f"amp needs a unit for --motion {motion}: {hint}; got {text!r}")
        kind = "acceleration"
    value = _qty(text, kind, "amp")
    if value < 0:
        raise ParameterError(f"amp must be >= 0: {hint}; got {text!r}")
    return kind, value


def _positive(value, name: str, unit: str):
    if value is not None and not value > 0:
        raise ParameterError(f"{name} must be > 0 {unit}; got {value:g}")
    return value


# ----------------------------------------------------------------------------- blocks
def _make_block(specimen, params, width, height, mass, alpha, p, mu, allow_classical: bool):
    """Build the block from exactly one of: specimen, width/height, alpha/p/mu."""
    from .blocks import Block, specimen_ids
    from .blocks import specimen as get_specimen

    sources = [s for s, given in (("--specimen", specimen is not None),
                                  ("--width/--height", width is not None or height is not None),
                                  ("--alpha", alpha is not None)) if given]
    if len(sources) > 1:
        raise ParameterError(f"block: give only one of {' or '.join(sources)}")
    if not sources:
        what = ("--specimen N, --width W --height H, or --alpha A --p P --mu M"
                if allow_classical else "--specimen N or --width W --height H")
        raise ParameterError(f"block: give {what}")
    if params is not None and specimen is None:
        raise ParameterError("params applies to --specimen only")
    if mass is not None and specimen is not None:
        raise ParameterError("mass applies to --width/--height only (the specimens "
                             "have their Table I mass)")

    info: dict = {}
    if specimen is not None:
        ids = specimen_ids()
        try:
            n = int(str(specimen).strip())
        except ValueError:
            raise ParameterError(f"specimen must be one of {ids}, got {specimen!r}") from None
        ps = params or "theoretical"
        block = get_specimen(n, params=ps)
        info.update(specimen=n, params=ps)
    elif width is not None or height is not None:
        if width is None or height is None:
            missing = "width" if width is None else "height"
            raise ParameterError(f"{missing} is required with --width/--height "
                                 f"(full size, e.g. 0.17 or 170mm)")
        w = _qty(width, "length", "width", default_unit="m")
        h = _qty(height, "length", "height", default_unit="m")
        mval = _number(mass, "mass", ("kg",))
        block = Block.rectangular(w, h, mass=mval, name="rectangular block")
        info.update(width=block.width, height=block.height, mass=block.mass)
    else:
        if p is None or mu is None:
            missing = [n for n, v in (("p", p), ("mu", mu)) if v is None]
            raise ParameterError(f"{' and '.join(missing)} required with --alpha "
                                 f"(give --alpha A --p P --mu M)")
        a = _qty(alpha, "angle", "alpha", default_unit="rad")
        block = Block.from_params(a, _number(p, "p", ("1/s", "rad/s")), _number(mu, "mu"),
                                  name="block")
        info.update(alpha=block.alpha, p=block.p, mu=block.mu)
        return block, info
    # overrides on a specimen or a rectangle
    changes = {}
    if p is not None:
        changes["p"] = _number(p, "p", ("1/s", "rad/s"))
    if mu is not None:
        changes["mu"] = _number(mu, "mu")
    if changes:
        block = block.with_params(**changes)
        info.update({f"{k}_override": v for k, v in changes.items()})
    return block, info


def _block_lines(block) -> list[str]:
    from .units import G

    lines = []
    if block.name:
        lines.append(f"block           {block.name}")
    lines += [
        f"alpha           {block.alpha:.6g} rad = {math.degrees(block.alpha):.4g} deg",
        f"p               {block.p:.6g} 1/s",
        f"mu              {block.mu:.6g}",
    ]
    if block.R is not None:
        lines.append(f"R               {block.R:.6g} m")
    if block.width is not None:
        lines.append(f"width x height  {block.width:g} m x {block.height:g} m")
    if block.mass is not None:
        lines.append(f"mass            {block.mass:g} kg")
    if block.I_O is not None:
        lines.append(f"I_O             {block.I_O:.6g} kg m^2")
    ua = block.uplift_acceleration
    lines.append(f"uplift g tan(a)  {ua:.6g} m/s^2 = {ua / G:.4g} g")
    return lines


# ----------------------------------------------------------------------------- motions
def _make_motion(motion, freq, amp, tp, duration, record, units, dt, load_factor,
                 earthquake=None):
    """``(motion or None, description dict, duration for simulate)``."""
    from . import motions as M

    if earthquake is not None:
        if motion is not None or record is not None:
            raise ParameterError("earthquake: --earthquake cannot be combined with --motion "
                                 "or --record")
        for name, val in (("freq", freq), ("amp", amp), ("tp", tp), ("units", units),
                          ("dt", dt)):
            if val is not None:
                raise ParameterError(f"{name} does not apply to --earthquake")
        from .motions.synthetic import earthquake_motion

        try:
            n = int(str(earthquake))
        except ValueError:
            raise ParameterError(f"earthquake must be a whole number from 1 to 30, "
                                 f"got {earthquake!r}") from None
        lf = 1.0 if load_factor is None else as_float("load-factor", load_factor)
        m = earthquake_motion(n, lf)
        dur = _positive(_qty(duration, "time", "duration", default_unit="s"), "duration", "s")
        if dur is None:  # capture the free rocking after the record ends
            dur = m.duration + 5.0
        desc = {"type": "earthquake", "number": n, "load_factor": lf, "dt": m.dt,
                "pga": m.pga, "repr": repr(m)}
        return m, desc, dur

    if motion is None:
        if record is None:
            raise ParameterError(f"motion: give --motion ({', '.join(MOTION_CHOICES[:-1])}) "
                                 f"or --record FILE")
        motion = "record"
    if motion == "record" and record is None:
        raise ParameterError("record: --motion record needs --record FILE")
    if record is not None and motion != "record":
        raise ParameterError(f"record: --record cannot be combined with --motion {motion}")
    if motion != "record":
        for name, val in (("units", units), ("dt", dt)):
            if val is not None:
                raise ParameterError(f"{name} applies to --record only")

    f = _positive(_qty(freq, "frequency", "freq", default_unit="hz"), "freq", "Hz")
    tpv = _positive(_qty(tp, "time", "tp", default_unit="s"), "tp", "s")
    dur = _positive(_qty(duration, "time", "duration", default_unit="s"), "duration", "s")
    lf = 1.0 if load_factor is None else as_float("load-factor", load_factor)

    def unused(*names):
        given = {"freq": freq, "amp": amp, "tp": tp}
        for n in names:
            if given[n] is not None:
                raise ParameterError(f"{n} does not apply to --motion {motion}")

    def need(name, value, example):
        if value is None:
            raise ParameterError(f"{name} is required for --motion {motion} (e.g. {example})")

    desc: dict = {"type": motion}
    if motion == "free":
        unused("freq", "amp", "tp")
        if dur is None:
            raise ParameterError("duration is required for --motion free (s > 0), "
                                 "e.g. --duration 10")
        desc["load_factor"] = lf
        return None, desc, dur

    if motion == "record":
        unused("freq", "amp", "tp")
        dtv = _positive(_qty(dt, "time", "dt", default_unit="s"), "dt", "s")
        u = "g" if units is None else units
        try:
            rec = M.Record.from_file(record, units=u, dt=dtv)
        except RockingError:
            raise
        except (OSError, ValueError, UnicodeError) as e:
            raise RecordError(f"record: cannot read {record}: {e}") from None
        m = rec
        desc.update(file=str(record), units=u, dt=rec.dt, n=len(rec), pga=rec.pga)
    elif motion in HARMONIC:
        unused("tp")
        need("freq", f, "--freq 5Hz")
        need("amp", amp, "--amp 5mm")
        if dur is None:
            raise ParameterError(f"duration is required for --motion {motion} (s > 0), "
                                 f"e.g. --duration 25")
        kind, a = _amplitude(amp, motion)
        cls = M.Sine if motion == "sine" else M.HanningSine
        if kind == "acceleration":
            X = a / (2.0 * math.pi * f) ** 2
        else:
            X = a
        m = cls(f, X, dur)
        desc.update(freq=f, amplitude=X, acc_amplitude=X * (2.0 * math.pi * f) ** 2,
                    duration=dur)
        dur = None
    else:
        need("amp", amp, "--amp 0.3g")
        _, a = _amplitude(amp, motion)
        if motion == "ricker":
            if f is not None and tpv is not None:
                raise ParameterError("ricker: give --freq (peak frequency) or --tp (= 1/freq), "
                                     "not both")
            if f is None and tpv is None:
                raise ParameterError("freq is required for --motion ricker (peak frequency, "
                                     "e.g. --freq 2Hz; or --tp 0.5s)")
            fp = f if f is not None else 1.0 / tpv
            m = M.Ricker(a, fp, duration=dur)
            desc.update(amplitude=a, fp=fp, tc=m.tc, duration=m.duration)
        else:
            unused("freq")
            need("tp", tpv, "--tp 0.5s")
            cls = {"one-sine": M.OneSine, "one-cosine": M.OneCosine,
                   "half-sine": M.HalfSine, "rectangular": M.Rectangular}[motion]
            m = cls(a, tpv, duration=dur)
            desc.update(amplitude=a, tp=tpv, duration=m.duration)
        dur = None
    if lf != 1.0:
        m = m.scaled(lf)
    desc["load_factor"] = lf
    desc["repr"] = repr(m)
    return m, desc, dur


# ----------------------------------------------------------------------------- commands
def _block_options(f):
    opts = [
        click.option("--specimen", metavar="N",
                     help="Specimen of Pena et al. (2007), Table I (1-4)."),
        click.option("--params", "params_set", type=click.Choice(PARAM_SETS),
                     help="Parameter set of a specimen (default theoretical)."),
        click.option("--width", metavar="W", help="Full width 2b (bare number: m; or 170mm)."),
        click.option("--height", metavar="H", help="Full height 2h (bare number: m)."),
    ]
    for o in reversed(opts):
        f = o(f)
    return f


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, "--version", prog_name="rocking")
def cli():
    """Dynamics of rocking rigid blocks (Pena et al. 2007).

    SI units inside; units are explicit at the edges (--amp 5mm, 0.3g; --freq 5Hz).
    """


@cli.command("params")
@_block_options
@click.option("--mass", metavar="M", help="Mass (kg), with --width/--height.")
@click.option("--json", "as_json", is_flag=True, help="Print a JSON object (SI units).")
def params_cmd(specimen, params_set, width, height, mass, as_json):
    """Classical parameters alpha, p, mu, R of a block (Eqs 2-4)."""
    block, info = _make_block(specimen, params_set, width, height, mass, None, None, None,
                              allow_classical=False)
    if as_json:
        d = {k: (None if v is None else float(v)) for k, v in block.params().items()}
        d.update(
            alpha_deg=math.degrees(block.alpha),
            uplift_acceleration=block.uplift_acceleration,
            uplift_acceleration_g=block.uplift_acceleration / _g(),
            width=block.width, height=block.height, mass=block.mass, I_O=block.I_O,
            name=block.name,
        )
        d.update({k: v for k, v in info.items() if k in ("specimen", "params")})
        click.echo(json.dumps(d, indent=2))
    else:
        click.echo("\n".join(_block_lines(block)))


def _g():
    from .units import G

    return G


def _model_names():
    from .models import MODELS

    return list(MODELS)


class _ModelChoice(click.ParamType):
    """A choice among :data:`rocking.models.MODELS`, read at run time."""

    name = "model"

    def get_metavar(self, param, ctx=None):  # click >= 8.2 passes ctx
        return "[" + "|".join(_model_names()) + "]"

    def convert(self, value, param, ctx):
        names = _model_names()
        key = str(value).strip().lower()
        if key not in names:
            self.fail(f"{value!r} is not one of {', '.join(names)}", param, ctx)
        return key


@cli.command("simulate")
@_block_options
@click.option("--alpha", metavar="A", help="Critical angle (bare number: rad; or 9.6deg).")
@click.option("--p", metavar="P", help="Frequency parameter p (1/s); overrides a specimen's.")
@click.option("--mu", metavar="MU", help="Coefficient of restitution in (0, 1]; overrides.")
@click.option("--model", type=_ModelChoice(), default="housner", show_default=True,
              help="Rocking model.")
@click.option("--motion", type=click.Choice(MOTION_CHOICES),
              help="Base motion (--record FILE implies record).")
@click.option("--freq", metavar="F", help="Frequency (Hz): sine/hanning; ricker peak frequency.")
@click.option("--amp", metavar="AMP",
              help="sine/hanning: table displacement with a unit (5mm); "
                   "pulses: peak acceleration (0.3g, 2.8m/s2).")
@click.option("--tp", metavar="T", help="Pulse period/length (s).")
@click.option("--duration", metavar="T",
              help="Simulated time (s); default the motion's (required for sine, "
                   "hanning, free).")
@click.option("--record", type=click.Path(exists=True, dir_okay=False),
              help="Accelerogram file (.AT2, CSV or columns).")
@click.option("--units", metavar="U", help=f"Units of the record: {UNITS_HELP} (default g).")
@click.option("--dt", metavar="DT", help="Time step of a one-column record (s).")
@click.option("--earthquake", metavar="N",
              help="One of the paper's 30 synthetic EC8 records (1-30), see 'rocking motion'.")
@click.option("--load-factor", metavar="F", help="Scale the motion (default 1).")
@click.option("--theta0", metavar="ANGLE", help="Initial angle (bare number: rad; or 2deg).")
@click.option("--omega0", metavar="W", help="Initial angular velocity (rad/s).")
@click.option("--linear", is_flag=True, help="Small-angle (linearised) equation of motion.")
@click.option("--dt-out", metavar="DT", help="Output time step (s; default 0.002).")
@click.option("--friction-angle", metavar="DEG",
              help="dem: contact friction angle (degrees, default 30).")
@click.option("--stiffness", metavar="K",
              help="dem: normal contact stiffness per contact point (N/m; default physical, "
                   "a settlement of 1e-7 of the height).")
@click.option("--damping", metavar="B",
              help="dem: stiffness-proportional damping b (s), or 'calibrated' (default: "
                   "matches mu) or 'paper' (Eq 20).")
@click.option("--out", type=click.Path(file_okay=False),
              help="Write response.csv, summary.json and theta.png to this folder.")
def simulate_cmd(specimen, params_set, width, height, alpha, p, mu, model, motion, freq, amp,
                 tp, duration, record, units, dt, earthquake, load_factor, theta0, omega0,
                 linear, friction_angle, stiffness, damping, dt_out, out):
    """Simulate one block under one base motion."""
    from .models import simulate

    block, binfo = _make_block(specimen, params_set, width, height, None, alpha, p, mu,
                               allow_classical=True)
    mot, mdesc, sim_dur = _make_motion(motion, freq, amp, tp, duration, record, units, dt,
                                       load_factor, earthquake)
    options = _dem_options(model, friction_angle, stiffness, damping)
    th0 = _qty(theta0, "angle", "theta0", default_unit="rad")
    om0 = _number(omega0, "omega0", ("rad/s", "1/s"))
    if dt_out is not None:
        options["dt_out"] = _positive(_qty(dt_out, "time", "dt_out", default_unit="s"),
                                      "dt_out", "s")
    resp = simulate(block, mot, model=model, duration=sim_dur,
                    theta0=0.0 if th0 is None else th0, omega0=0.0 if om0 is None else om0,
                    linear=linear, **options)

    summary = resp.summary()
    inputs = {"block": {**binfo, "alpha": block.alpha, "p": block.p, "mu": block.mu,
                        "R": block.R, "name": block.name},
              "model": model, "linear": bool(linear), "motion": mdesc,
              "theta0": th0 or 0.0, "omega0": om0 or 0.0}
    if "dt_out" in options:
        inputs["dt_out"] = options["dt_out"]
    summary["specimen"] = binfo.get("specimen")
    summary["params"] = binfo.get("params")
    summary["inputs"] = inputs

    th = summary["max_abs_theta"]
    click.echo(f"block       {block!r}")
    click.echo(f"motion      {mdesc.get('repr', 'free rocking')}  [{model}"
               f"{', linear' if linear else ''}]")
    click.echo(f"max |theta| {math.degrees(th):.4g} deg ({th:.6g} rad, "
               f"{th / block.alpha:.3g} alpha)")
    if resp.overturned:
        click.echo(f"overturned  yes, at t = {resp.overturn_time:.4g} s")
    else:
        click.echo("overturned  no")
    up = "-" if math.isnan(resp.uplift_time) else f"t = {resp.uplift_time:.4g} s"
    click.echo(f"uplift      {up}")
    click.echo(f"impacts     {resp.n_impacts}")

    if out is not None:
        folder = Path(out)
        folder.mkdir(parents=True, exist_ok=True)
        resp.to_csv(folder / "response.csv")
        (folder / "summary.json").write_text(json.dumps(summary, indent=2, default=_jsonable))
        _theta_png(resp, block, mdesc, folder / "theta.png")
        click.echo(f"wrote       {folder / 'response.csv'}, summary.json, theta.png")


def _dem_options(model, friction_angle, stiffness, damping) -> dict:
    """The DEM-only options of ``simulate``, validated; an error for the other models."""
    given = {"friction-angle": friction_angle, "stiffness": stiffness, "damping": damping}
    if model != "dem":
        for name, val in given.items():
            if val is not None:
                raise ParameterError(f"{name} applies to --model dem only")
        return {}
    opts = {}
    if friction_angle is not None:
        from ._validate import in_range

        opts["friction_angle"] = in_range("friction-angle", _number(friction_angle,
                                          "friction-angle", ("deg",)), 0.0, 90.0,
                                          shown="[0, 90) degrees", lo_open=False)
    if stiffness is not None:
        opts["stiffness"] = _positive(_number(stiffness, "stiffness", ("n/m",)),
                                      "stiffness", "N/m")
    if damping is not None:
        d = str(damping).strip().lower()
        if d in ("calibrated", "paper"):
            opts["damping"] = d
        else:
            opts["damping"] = as_float("damping", _number(d, "damping", ("s",)))
            if opts["damping"] < 0:
                raise ParameterError(f"damping must be >= 0 s, 'calibrated' or 'paper'; "
                                     f"got {damping!r}")
    return opts


def _register_subcommands() -> None:
    """Commands that live in their own modules (one module per concept)."""
    from .cli_dem import dem_params
    from .cli_identify import identify as identify_cmd
    from .cli_motion import motion as motion_group

    cli.add_command(identify_cmd)
    cli.add_command(dem_params)
    cli.add_command(motion_group)


_register_subcommands()


def _jsonable(o):
    try:
        return float(o)
    except (TypeError, ValueError):
        return str(o)


def _motion_title(d: dict) -> str:
    """A short description of the motion for plot titles."""
    from .units import G

    kind = d.get("type")
    lf = d.get("load_factor", 1.0)
    tail = f", load factor {lf:g}" if lf != 1.0 else ""
    if kind in HARMONIC:
        return (f"{kind} {d['freq']:g} Hz, {1e3 * d['amplitude']:.3g} mm "
                f"({d['acc_amplitude'] / G:.3g} g){tail}")
    if kind == "ricker":
        return f"Ricker pulse {d['amplitude'] / G:.3g} g, fp {d['fp']:g} Hz{tail}"
    if kind in PULSES:
        return f"{kind} pulse {d['amplitude'] / G:.3g} g, {d['tp']:g} s{tail}"
    if kind == "record":
        return f"record {Path(d['file']).name} (PGA {d['pga'] / G:.3g} g){tail}"
    return "free rocking"


def _theta_png(resp, block, mdesc, path):
    from .plot import figure, plot_response, save_figure

    fig, ax = figure()
    title = f"{block.name or 'block'}: {_motion_title(mdesc)}"
    plot_response(resp, ax=ax, show_alpha=True, title=title)
    save_figure(fig, path)


@cli.command("reproduce")
@click.option("--out", default="results", show_default=True, type=click.Path(file_okay=False),
              help="Output folder of the report.")
@click.option("--quick", is_flag=True, help="Fewer, shorter simulations (for a smoke test).")
def reproduce_cmd(out, quick):
    """Reproduce the paper's tables and figures into OUT/index.html."""
    try:
        from . import report
    except ImportError as e:
        raise click.ClickException(f"the report module is not available ({e})") from None

    report_error = getattr(report, "ReportError", ())
    try:
        index = report.reproduce(Path(out), quick=quick)
    except report_error as e:  # some sections failed; the page was still written
        click.echo(str(e.path))
        raise click.ClickException(str(e)) from None  # exit code 1
    click.echo(str(index))


# ----------------------------------------------------------------------------- entry
def _one_line(msg: str) -> str:
    return " ".join(str(msg).split())


_NO_ARGS_IS_HELP = getattr(click.exceptions, "NoArgsIsHelpError", ())


def main(argv=None) -> None:
    """Console entry point: run :func:`cli`, turning bad input into ``error: ...`` (exit 2).

    Exits with ``sys.exit(code)``; ``argv`` defaults to ``sys.argv[1:]``.
    """
    try:
        rv = cli.main(args=argv, prog_name="rocking", standalone_mode=False)
        code = rv if isinstance(rv, int) else 0
    except click.exceptions.UsageError as e:
        if isinstance(e, _NO_ARGS_IS_HELP):  # bare `rocking` (click >= 8.2): show help
            click.echo(e.ctx.get_help() if e.ctx else cli.get_help(click.Context(cli)))
            sys.exit(0)
        click.echo(f"error: {_one_line(e.format_message())}", err=True)
        code = 2
    except RockingError as e:
        click.echo(f"error: {_one_line(e)}", err=True)
        code = 2
    except click.exceptions.Abort:
        click.echo("error: aborted", err=True)
        code = 1
    except click.ClickException as e:
        click.echo(f"error: {_one_line(e.format_message())}", err=True)
        code = e.exit_code if e.exit_code else 1
    except OSError as e:
        click.echo(f"error: {_one_line(e)}", err=True)
        code = 1
    sys.exit(code)


if __name__ == "__main__":
    main()
