"""``rocking simulate`` with a 3-D model (``--model rigid3d``): the body, the pair of
horizontal components, the text report, summary and plots.

::

    rocking simulate --model rigid3d --mesh statue.ply --density 2600 \\
        --pair H1.AT2 H2.AT2 --vertical UP.AT2 --heading 30 --out out/
    rocking simulate --model rigid3d --box 0.4 0.4 1.2 --record Rinaldi228 --direction 30
    rocking simulate --model rigid3d --cylinder 0.2 1.0 --pair Rinaldi228 Rinaldi318

**The body** (:func:`rocking.blocks.factory.make_body`): ``--mesh FILE`` (the whole mesh:
mass properties from it, contact on its hull; ``--density`` or ``--mass``, ``--up``,
``--mesh-units``, ``--repair``), ``--box LX LY LZ`` (m; ``--density`` or ``--mass``,
default 1000 kg/m^3: the motion does not depend on the mass), ``--cylinder R H`` (m), or
a rectangular block (``--width``, ``--height``: a box as deep as it is wide) or a
``--specimen`` (its box). ``--alpha``, ``--p``, ``--mu`` describe a planar block and are
refused.

**The motion.** ``--pair H1 H2``: two horizontal components (files, in ``--units``, or
built-in record names such as ``Rinaldi228``), with ``--vertical UP`` optionally, as a
:class:`rocking.motions.HorizontalPair` (azimuths from the NGA headers when both state
one); ``--heading`` (deg) is the body's x axis counter-clockwise from the first component
(the model's option ``heading``). ``--load-factor`` scales the three components,
``--vertical-factor`` the vertical one instead. Any single motion of ``rocking simulate``
(``--record``, ``--motion``, ``--earthquake``, with ``--vertical``) acts along
``--direction``.

**--direction** is one quantity for every model: the direction of shaking from the body's
x axis, counter-clockwise looking down (bare number: deg; ``0.5rad``; ``weakest`` or
``strongest``, of the body's support). A planar model rocks a ``--mesh``'s planar block in
that direction; ``rigid3d`` takes it as its option ``direction``: where a single horizontal
motion acts (and where ``--tilt0`` leans). With ``--pair`` the orientation is
``--heading``: ``--direction`` is then refused unless ``--tilt0`` is given (it only says
where the tilt leans), and ``--heading`` without ``--pair`` is refused (a single motion
ignores it).

**Outputs** (``--out``): ``response.csv`` (the state, then ``tilt``, ``slide``, ``twist``),
``summary.json`` and three plots (:mod:`rocking.plot3d`): ``tilt_slide_twist.png``,
``com_path.png`` (the centre of mass seen from above) and ``overturn_azimuth.png`` (the
lean of the up axis on a compass, the overturning azimuth marked); the page
``motion.html`` (:func:`rocking.viewer3d.write_html`: the motion played in a browser,
three.js inlined, no network) unless ``--no-html``; and with ``--animate`` the animation
``motion.gif`` (:func:`rocking.viewer3d.animate`).

The page is on by default because it costs nothing next to the run (about 0.01 s; about
0.7 MB, three.js's share fixed) and is the only way to see a 3-D motion whole; the GIF is
asked for, because it costs about 2 s of drawing per 5 s of motion, many times a box's
run (0.1 s), and a long record's free motion makes it long.
"""

from __future__ import annotations

import math
import textwrap
from pathlib import Path

from .._validate import as_float
from ..errors import ParameterError
from ..units import G
from .common import MESH_FLAGS, in_flag_words, mesh_flags, one_line, read_record_arg

PLOTS = ("tilt_slide_twist.png", "com_path.png", "overturn_azimuth.png")
"""The plots that ``--out`` writes for a 3-D model."""

PAGE = "motion.html"
"""The page that ``--out`` writes for a 3-D model (unless ``--no-html``)."""

ANIMATION = "motion.gif"
"""The animation that ``--out --animate`` writes for a 3-D model."""


def is_3d(model: str) -> bool:
    """True for a registered model of a 3-D body (:func:`rocking.models.is_3d`:
    ``rigid3d``)."""
    from ..models import is_3d as three_d  # lazy: the models import numba

    return three_d(model)


def refuse_3d_flags(model: str, box, cylinder, pair) -> None:
    """``--box``, ``--cylinder`` and ``--pair`` need a 3-D model."""
    for flag, v in (("box", box), ("cylinder", cylinder), ("pair", pair)):
        if v:
            what = ("two horizontal components" if flag == "pair" else "a 3-D body")
            raise ParameterError(f"{flag}: --{flag} ({what}) needs a 3-D model: --model "
                                 f"rigid3d (--model {model} is planar)")


def refuse_viewer_flags(model: str, html, animate) -> None:
    """``--html`` and ``--animate`` show a 3-D body: refused for a planar model."""
    for flag, v in (("html", html), ("animate", animate)):
        if v:
            raise ParameterError(f"{flag}: --{flag} shows a 3-D body's motion: --model "
                                 f"rigid3d (--model {model} is planar)")


def check_viewer_flags(out, html, animate) -> None:
    """``--html`` and ``--animate`` write into ``--out``: refused without it."""
    for flag, v in (("html", html), ("animate", animate)):
        if v and out is None:
            raise ParameterError(f"{flag}: --{flag} writes into the --out folder; give "
                                 "--out DIR")


def write_viewer(resp, title: str, folder: Path, *, html: bool = True,
                 gif: bool = False) -> tuple[str, ...]:
    """The page :data:`PAGE` (``html``) and the animation :data:`ANIMATION` (``gif``) of
    ``resp`` into ``folder``; returns the names written."""
    from ..viewer3d import animate, write_html  # lazy: matplotlib

    names = []
    if html:
        write_html(resp, folder / PAGE, title=title)
        names.append(PAGE)
    if gif:  # 12 frames/s; a response over 2 min plays faster (at most 1441 frames)
        t_end = float(resp.t[-1])
        animate(resp, folder / ANIMATION, speed=max(1.0, math.ceil(t_end / 120.0)))
        names.append(ANIMATION)
    return tuple(names)


def make_body(specimen, params, width, height, alpha, p, mu, box, cylinder):
    """``(shape, info, direction text or None)`` of the body flags (module docstring)."""
    from ..blocks.factory import make_body as build

    for flag, v in (("alpha", alpha), ("p", p), ("mu", mu)):
        if v is not None:
            raise ParameterError(f"{flag}: --{flag} describes a planar block; a 3-D body "
                                 "takes its shape: --mesh, --box, --cylinder, --width/"
                                 "--height or --specimen")
    meshed = mesh_flags()
    direction = meshed.pop("direction", None)
    given = [f for f, v in (("--specimen", specimen), ("--width/--height", width or height),
                            ("--mesh", meshed.get("mesh")), ("--box", box),
                            ("--cylinder", cylinder)) if v]
    if len(given) != 1:
        raise ParameterError("block: give " + ("only one of " + " or ".join(given) if given
                                               else "--mesh FILE, --box LX LY LZ, --cylinder "
                                               "R H, --width W --height H or --specimen N"))
    mapping: dict = {k: v for k, v in meshed.items()}
    if box:
        mapping["box"] = list(box)
    elif cylinder:
        mapping["cylinder"] = list(cylinder)
    elif specimen is not None:
        mapping |= {"specimen": specimen, **({"params": params} if params else {})}
    elif width or height:
        mapping |= {k: v for k, v in (("width", width), ("height", height)) if v is not None}
    for k in ("density", "mass"):
        if k in mapping and isinstance(mapping[k], str):
            mapping[k] = mapping[k].strip().removesuffix("kg/m^3").removesuffix("kg")
            mapping[k] = as_float(k, mapping[k])
    if "mesh" not in mapping:
        for k in ("up", "units", "repair"):
            if k in mapping:
                raise ParameterError(f"{MESH_FLAGS[k][2:]} applies to --mesh only")
    if not (box or cylinder or "mesh" in mapping) and ("density" in mapping):
        raise ParameterError("density applies to --mesh, --box or --cylinder")
    words = {k: (MESH_FLAGS.get(k, "--" + k)[2:], v) for k, v in mapping.items()}
    try:
        shape = build(mapping)
    except ParameterError as e:
        raise type(e)(one_line(in_flag_words(e, words))) from None
    info = {"form": given[0].lstrip("-").split("/")[0],
            **{k: v for k, v in mapping.items() if k not in ("params",)},
            "name": shape.name, "mass": shape.mass, "height": shape.height, "h": shape.h,
            "support_area": shape.support_area, "contact_points": shape.contact_points}
    if params:
        info["params"] = params
    return shape, info, direction


def direction_deg(shape, text) -> float:
    """``--direction`` for the body ``shape``: degrees counter-clockwise from its x axis (a
    bare number in deg, ``0.5rad``, ``weakest``, ``strongest``)."""
    from ..blocks.factory import mesh_direction, resolve_direction

    phi = resolve_direction(shape, mesh_direction(text))
    deg = math.degrees(phi)
    return deg - 360.0 if deg > 180.0 else deg


def make_pair(pair, vertical, vertical_factor, units, dt, load_factor):
    """``(HorizontalPair, description)`` of ``--pair H1 H2`` (files or built-in names),
    ``--vertical`` and the load factors."""
    from ..motions import HorizontalPair

    lf = 1.0 if load_factor is None else as_float("load-factor", load_factor)
    r1, s1 = read_record_arg(pair[0], "pair", units, dt)
    r2, s2 = read_record_arg(pair[1], "pair", units, dt)
    v, sv, fv = None, None, lf
    if vertical is not None:
        v, sv = read_record_arg(vertical, "vertical", units, dt)
        if vertical_factor is not None:
            fv = as_float("vertical-factor", vertical_factor)
        v = v.scaled(fv) if fv != 1.0 else v
    elif vertical_factor is not None:
        raise ParameterError("vertical-factor applies with --vertical V.AT2 only")
    try:
        hp = HorizontalPair.from_records(r1.scaled(lf) if lf != 1.0 else r1,
                                         r2.scaled(lf) if lf != 1.0 else r2, vertical=v,
                                         name=f"{Path(str(pair[0])).stem} + "
                                              f"{Path(str(pair[1])).stem}")
    except ParameterError as e:
        raise ParameterError(f"pair: {one_line(e)}") from None
    desc = {"type": "pair", "files": [s1, s2], "units": "g" if units is None else units,
            "dt": hp.dt, "n": hp.n, "pga_components": list(hp.pga_components),
            "peak_resultant": hp.peak_resultant, "load_factor": lf,
            "azimuths_deg": None if hp.azimuths is None else list(hp.azimuths_deg),
            "repr": repr(hp)}
    if v is not None:
        desc.update(vertical=sv, vertical_factor=fv, pga_vertical=v.pga)
    return hp, desc


def check_orientation(options: dict, pair: bool, direction) -> None:
    """``--heading`` needs ``--pair``; ``--direction`` with ``--pair`` needs ``--tilt0``
    (module docstring: never an option that the run would ignore)."""
    if "heading" in options and not pair:
        raise ParameterError("heading applies to --pair (two horizontal components); a "
                             "single horizontal motion acts along --direction")
    if pair and direction is not None and not options.get("tilt0"):
        raise ParameterError("direction: with --pair the body's orientation is --heading "
                             "(deg from the first component); --direction only says where "
                             "--tilt0 leans")


def summary_block(shape, info: dict) -> dict:
    """summary.json's ``inputs.block`` of a 3-D body."""
    d = shape.describe()
    return {**info, **{k: d[k] for k in ("volume", "density", "vertices", "triangles",
                                          "support_area", "contact_points")}}


def text_lines(resp, shape, model: str, mdesc: dict, options: dict,
               fdesc: dict | None = None) -> list[str]:
    """The text report of a 3-D run (before the model's outputs, which follow; ``fdesc``:
    the floor it stands on, ``--building``)."""
    turn = (f", heading {options.get('heading', 0.0):g} deg" if mdesc.get("type") == "pair"
            else f", direction {options.get('direction', 0.0):g} deg"
            if mdesc.get("type") != "free" else "")
    on = "" if fdesc is None else (
        f" on {fdesc['where']} of the {fdesc['building']['name']} (peak floor acceleration "
        f"{fdesc['floor_pga'] / G:.3g} g)")
    lines = [f"body        {shape!r}",
             f"motion      {mdesc.get('repr', 'free motion')}{on}  [{model}{turn}]",
             f"max tilt    {math.degrees(resp.max_tilt):.4g} deg ({resp.max_tilt:.6g} rad)",
             (f"overturned  yes, at t = {resp.overturn_time:.4g} s, towards "
              f"{resp.overturn_azimuth:.4g} deg (counter-clockwise from x)")
             if resp.overturned else "overturned  no"]
    up = "-" if math.isnan(resp.uplift_time) else f"t = {resp.uplift_time:.4g} s"
    lines.append(f"uplift      {up}")
    if mdesc.get("vertical"):
        lines.append(f"vertical    {mdesc['vertical']} x {mdesc['vertical_factor']:g} "
                     f"(peak {mdesc['pga_vertical'] / G:.3g} g)")
    return lines


def motion_title(mdesc: dict, options: dict) -> str:
    """A short description of a pair for plot titles."""
    names = " + ".join(Path(str(f)).stem.replace(" (built-in)", "") for f in mdesc["files"])
    v = f" + vertical {Path(str(mdesc['vertical'])).stem}" if mdesc.get("vertical") else ""
    lf = mdesc.get("load_factor", 1.0)
    return (f"pair {names}{v}, heading {options.get('heading', 0.0):g} deg"
            + (f", load factor {lf:g}" if lf != 1.0 else ""))


def write_plots(resp, title: str, folder: Path) -> None:
    """The three plots of :data:`PLOTS` into ``folder``."""
    from ..plot import save_figure
    from ..plot3d import plot_com_path, plot_histories3d, plot_overturn_azimuth

    axes = plot_histories3d(resp, title=title)
    save_figure(axes[0].figure, folder / PLOTS[0])
    ax = plot_com_path(resp, title=textwrap.fill(title, 58)
                       + "\ncentre of mass seen from above")
    save_figure(ax.figure, folder / PLOTS[1])
    ax = plot_overturn_azimuth(resp)
    save_figure(ax.figure, folder / PLOTS[2])
