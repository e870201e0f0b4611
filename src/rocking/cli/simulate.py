"""``rocking simulate``: one block under one base motion, with any registered model.

::

    rocking simulate --specimen 2 --params experimental --motion sine --freq 5 --amp 5mm \\
        --duration 25 --out out/
    rocking simulate --specimen 2 --record quake.AT2 --units g --load-factor 1.2 --out out/
    rocking simulate --specimen 2 --model ccrr --option rtol=1e-9 --motion free \\
        --theta0 0.05 --duration 5

``--model`` is a name of :data:`rocking.models.MODELS` and ``--option KEY=VALUE``
(repeatable) passes an option of that model's ``Options`` (``rocking models`` lists them);
the model validates the options. The DEM flags ``--friction-angle``, ``--stiffness`` and
``--damping`` are the options of the same names, for the models that have them.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import click

from .._atomic import atomic_write
from .._validate import as_float, in_range
from ..errors import ParameterError
from ..units import ACCELERATION, LENGTH, G, split_quantity
from .common import (
    CONTEXT,
    ModelChoice,
    block_options,
    check_positive,
    json_default,
    make_block,
    models_with_option,
    number,
    parse_options,
    positive_quantity,
    quantity,
    read_record_arg,
    validate_options,
)

PULSES = ("one-sine", "one-cosine", "half-sine", "rectangular", "ricker")
HARMONIC = ("sine", "hanning")
MOTION_CHOICES = (*HARMONIC, *PULSES, "free", "record")
UNITS_HELP = "g, m/s^2 or cm/s^2"


# ----------------------------------------------------------------------------- motions
def amplitude(text, motion: str) -> tuple[str, float]:
    """``--amp`` as ``("length", m)`` or ``("acceleration", m/s^2)``, checked >= 0."""
    parts = split_quantity(text)
    if parts is None:  # not a number: let parse_quantity word the error
        quantity(text, "length" if motion in HARMONIC else "acceleration", "amp")
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
    value = quantity(text, kind, "amp")
    if value < 0:
        raise ParameterError(f"amp must be >= 0: {hint}; got {text!r}")
    return kind, value


def make_motion(motion, freq, amp, tp, duration, record, units, dt, load_factor,
                earthquake=None, vertical=None, vertical_factor=None):
    """``(motion or None, description dict, duration for simulate)``."""
    from .. import motions as M  # lazy: the motions import numba

    if vertical is None and vertical_factor is not None:
        raise ParameterError("vertical-factor applies with --vertical V.AT2 only")
    if vertical is not None and record is None:
        raise ParameterError("vertical: --vertical needs the horizontal --record FILE")

    if earthquake is not None:
        if motion is not None or record is not None:
            raise ParameterError("earthquake: --earthquake cannot be combined with --motion "
                                 "or --record")
        for name, val in (("freq", freq), ("amp", amp), ("tp", tp), ("units", units),
                          ("dt", dt)):
            if val is not None:
                raise ParameterError(f"{name} does not apply to --earthquake")
        from ..motions.synthetic import earthquake_motion

        try:
            n = int(str(earthquake))
        except ValueError:
            raise ParameterError(f"earthquake must be a whole number from 1 to 30, "
                                 f"got {earthquake!r}") from None
        lf = 1.0 if load_factor is None else as_float("load-factor", load_factor)
        m = earthquake_motion(n, lf)
        # default (None): the run goes on after the record until the block has settled
        dur = positive_quantity(duration, "time", "duration", "s", "s")
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

    f = positive_quantity(freq, "frequency", "freq", "hz", "Hz")
    tpv = positive_quantity(tp, "time", "tp", "s", "s")
    dur = positive_quantity(duration, "time", "duration", "s", "s")
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
        unused("freq", "amp", "tp")  # no --duration: until at rest or overturned
        desc["load_factor"] = lf
        return None, desc, dur

    if motion == "record":
        unused("freq", "amp", "tp")
        dtv = positive_quantity(dt, "time", "dt", "s", "s")
        u = "g" if units is None else units
        rec, src = read_record_arg(M, record, "record", units, dtv)
        m = rec
        desc.update(file=src, units=u, dt=rec.dt, n=len(rec), pga=rec.pga)
        if vertical is not None:
            vrec, vsrc = read_record_arg(M, vertical, "vertical", units, dtv)
            fv = (None if vertical_factor is None
                  else as_float("vertical-factor", vertical_factor))
            lf0 = 1.0 if load_factor is None else as_float("load-factor", load_factor)
            m = M.GroundMotion(rec, vrec).scaled(lf0, vertical=fv)
            desc.update(vertical=vsrc, vertical_factor=lf0 if fv is None else fv,
                        pga=m.pga, pga_vertical=m.pga_vertical,  # as run (scaled)
                        repr=f"{m.horizontal!r} + vertical {m.vertical!r}")
            desc["load_factor"] = lf0
            return m, desc, dur
    elif motion in HARMONIC:
        unused("tp")
        need("freq", f, "--freq 5Hz")
        need("amp", amp, "--amp 5mm")
        if dur is None:
            raise ParameterError(f"duration is required for --motion {motion} (s > 0), "
                                 f"e.g. --duration 25")
        kind, a = amplitude(amp, motion)
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
        _, a = amplitude(amp, motion)
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
        # a pulse's --duration is the run's length exactly (None: until settled)
    if lf != 1.0:
        m = m.scaled(lf)
    if "pga" in desc:
        desc["pga"] = m.pga  # as run, with the load factor
    desc["load_factor"] = lf
    desc["repr"] = repr(m)
    return m, desc, dur


# ----------------------------------------------------------------------------- model options
def flag_options(model: str, friction_angle, stiffness, damping) -> dict:
    """The options given by their own flags, parsed; an error for a model without them."""
    given = {"friction_angle": friction_angle, "stiffness": stiffness, "damping": damping}
    opts = {}
    for key, val in given.items():
        if val is None:
            continue
        flag = key.replace("_", "-")
        owners = models_with_option(key)
        if model not in owners:
            raise ParameterError(f"{flag} applies to --model {' or '.join(owners)} only")
        if key == "friction_angle":
            opts[key] = in_range(flag, number(val, flag, ("deg",)), 0.0, 90.0,
                                 shown="[0, 90) degrees", lo_open=False)
        elif key == "stiffness":
            opts[key] = check_positive(number(val, flag, ("n/m",)), flag, "N/m")
        else:
            d = str(val).strip().lower()
            if d in ("calibrated", "paper"):
                opts[key] = d
            else:
                opts[key] = as_float(flag, number(d, flag, ("s",)))
                if opts[key] < 0:
                    raise ParameterError(f"damping must be >= 0 s, 'calibrated' or 'paper'; "
                                         f"got {val!r}")
    return opts


def model_options(model: str, pairs, friction_angle, stiffness, damping) -> dict:
    """``--option KEY=VALUE`` pairs and the DEM flags as one options dict, checked by the
    model (unknown names, ranges)."""
    opts = parse_options(pairs)
    flags = flag_options(model, friction_angle, stiffness, damping)
    both = sorted(set(opts) & set(flags))
    if both:
        raise ParameterError(f"option {both[0]} given twice (--{both[0].replace('_', '-')} "
                             f"and --option {both[0]}=...)")
    opts.update(flags)
    validate_options(model, opts)
    return opts


# ----------------------------------------------------------------------------- command
@click.command("simulate", context_settings=CONTEXT)
@block_options(classical=True)
@click.option("--model", type=ModelChoice(), default="housner", show_default=True,
              help="Rocking model (see 'rocking models').")
@click.option("--option", "model_opts", multiple=True, metavar="KEY=VALUE",
              help="A model option, repeatable (e.g. --option rtol=1e-9); "
                   "'rocking models' lists them.")
@click.option("--motion", type=click.Choice(MOTION_CHOICES),
              help="Base motion (--record FILE implies record).")
@click.option("--freq", metavar="F", help="Frequency (Hz): sine/hanning; ricker peak frequency.")
@click.option("--amp", metavar="AMP",
              help="sine/hanning: table displacement with a unit (5mm); "
                   "pulses: peak acceleration (0.3g, 2.8m/s2).")
@click.option("--tp", metavar="T", help="Pulse period/length (s).")
@click.option("--duration", metavar="T",
              help="Simulated time (s), exactly. Default: the motion, then free motion "
                   "until the block is at rest or has overturned (at most --max-free-time "
                   "more). Required for sine and hanning (the motion's length).")
@click.option("--max-free-time", "max_free_time", metavar="T",
              help="Cap of the free motion after the ground motion ends (s; default 60).")
@click.option("--record", metavar="FILE",
              help="Accelerogram file (.AT2, CSV or columns), or a built-in record's name "
                   "(e.g. Rinaldi228).")
@click.option("--vertical", metavar="FILE",
              help="Vertical accelerogram (positive upwards; same --units and --dt), or a "
                   "built-in record's name (e.g. RinaldiUP).")
@click.option("--vertical-factor", "vertical_factor", metavar="F",
              help="Scale of the vertical component (default: the load factor).")
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
def simulate_cmd(specimen, params_set, width, height, alpha, p, mu, model, model_opts, motion,
                 freq, amp, tp, duration, max_free_time, record, vertical, vertical_factor,
                 units, dt, earthquake, load_factor, theta0, omega0, linear, friction_angle,
                 stiffness, damping, dt_out, out):
    """Simulate one block under one base motion."""
    from ..models import simulate  # lazy: the models import numba

    block, binfo = make_block(specimen, params_set, width, height, None, alpha, p, mu,
                              allow_classical=True)
    mot, mdesc, sim_dur = make_motion(motion, freq, amp, tp, duration, record, units, dt,
                                      load_factor, earthquake, vertical, vertical_factor)
    options = model_options(model, model_opts, friction_angle, stiffness, damping)
    linear = bool(linear) or bool(options.pop("linear", False))  # --linear = --option linear=1
    th0 = quantity(theta0, "angle", "theta0", default_unit="rad")
    om0 = number(omega0, "omega0", ("rad/s", "1/s"))
    run = {}
    if dt_out is not None:
        run["dt_out"] = positive_quantity(dt_out, "time", "dt_out", "s", "s")
    if max_free_time is not None:
        if sim_dur is not None:
            raise ParameterError("max-free-time applies without --duration only (--duration "
                                 "is the run's length exactly)")
        mft = quantity(max_free_time, "time", "max-free-time", default_unit="s")
        if not mft >= 0.0:
            raise ParameterError(f"max-free-time must be >= 0 s, got {max_free_time!r}")
        run["max_free_time"] = mft
    resp = simulate(block, mot, model=model, duration=sim_dur,
                    theta0=0.0 if th0 is None else th0, omega0=0.0 if om0 is None else om0,
                    linear=linear, **run, **options)

    summary = resp.summary()
    inputs = {"block": {**binfo, "alpha": block.alpha, "p": block.p, "mu": block.mu,
                        "R": block.R, "name": block.name},
              "model": model, "linear": bool(linear), "motion": mdesc,
              "theta0": th0 or 0.0, "omega0": om0 or 0.0}
    if options:
        inputs["options"] = options
    inputs.update(run)
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
    if not resp.settled and not resp.lifted_off:
        fix = "extend --duration" if sim_dur is not None else "raise --max-free-time"
        click.echo(f"warning: still rocking at the end (t = {resp.duration:.4g} s): the "
                   f"outcome may change; {fix}", err=True)
    if "vertical" in mdesc:
        lo = ("-" if not resp.lifted_off else f"yes, at t = {resp.lift_off_time:.4g} s: "
              "g + a_v <= 0, the block leaves the ground and the run stops there")
        click.echo(f"vertical    {mdesc['vertical']} x {mdesc['vertical_factor']:g} "
                   f"(peak {mdesc['pga_vertical'] / G:.3g} g)")
        click.echo(f"lift-off    {lo}")

    if out is not None:
        folder = Path(out)
        folder.mkdir(parents=True, exist_ok=True)
        resp.to_csv(folder / "response.csv")
        atomic_write(folder / "summary.json",
                     json.dumps(summary, indent=2, default=json_default))
        _theta_png(resp, block, mdesc, folder / "theta.png")
        click.echo(f"wrote       {folder / 'response.csv'}, summary.json, theta.png")


# ----------------------------------------------------------------------------- figure
def _motion_title(d: dict) -> str:
    """A short description of the motion for plot titles."""
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
    if kind == "record" and "vertical" in d:
        vf = d.get("vertical_factor", lf)
        tail = (f", load factor {lf:g}" + (f" ({vf:g} vertical)" if vf != lf else "")
                if lf != 1.0 or vf != 1.0 else "")
        return (f"record {Path(d['file']).name} + vertical {Path(d['vertical']).name} "
                f"(PGA {d['pga'] / G:.3g} g, {d['pga_vertical'] / G:.3g} g vertical){tail}")
    if kind == "record":
        return f"record {Path(d['file']).name} (PGA {d['pga'] / G:.3g} g){tail}"
    if kind == "earthquake":
        return f"earthquake {d['number']} (PGA {d['pga'] / G:.3g} g){tail}"
    return "free rocking"


def _theta_png(resp, block, mdesc, path):
    from ..plot import figure, plot_response, save_figure  # lazy: matplotlib

    fig, ax = figure()
    title = f"{block.name or 'block'}: {_motion_title(mdesc)}"
    plot_response(resp, ax=ax, show_alpha=True, title=title)
    save_figure(fig, path)


__all__ = ["simulate_cmd", "make_motion", "amplitude", "model_options", "MOTION_CHOICES"]
