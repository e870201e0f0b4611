"""``rocking models``: the registered models, their options (``Options.describe()``), the
flag of each option in ``rocking simulate`` and the model's row outputs.

::

    rocking models            # name, label, options table (with flags) of each model
    rocking models isolated   # one model
    rocking models --json

The flags are those that ``rocking simulate`` generates from the declarations
(:class:`rocking.cli.common.ModelFlagsCommand`), asked of that command through the
command group (this module imports no other command module); an option without a flag of
its own shows ``--option NAME=``.
"""

from __future__ import annotations

import dataclasses
import json

import click

from ..errors import ParameterError
from .common import CONTEXT, ModelFlagsCommand, json_default, model_classes, options_table


def simulate_flags(ctx: click.Context | None = None) -> dict | None:
    """``{option name: flag}`` of ``rocking simulate`` (None when this command runs outside
    the ``rocking`` group, which holds ``simulate``)."""
    ctx = ctx or click.get_current_context(silent=True)
    if ctx is None:
        return None
    root = ctx.find_root()
    group = root.command
    if not isinstance(group, click.Group):
        return None
    sim = group.get_command(root, "simulate")
    return sim.flag_of() if isinstance(sim, ModelFlagsCommand) else None


def models_dict(flags: dict | None = None, names=None) -> list[dict]:
    """One dict per registered model (or per one of ``names``): ``name``, ``label``,
    ``options`` (describe(), with ``flag``: the flag of ``rocking simulate`` or None when
    ``flags`` is given), ``row_outputs`` (``name``, ``unit``, ``flag``, ``help``: the
    model's own outputs), ``outputs`` (every declared output, ``Model.outputs``),
    ``states`` (``Model.state_names``; ``"per body"`` where the bodies decide, as in the
    DEM) and ``tags``."""
    out = []
    for name, cls in model_classes().items():
        if names is not None and name not in names:
            continue
        opts = [{**d, "kind": getattr(d.get("kind"), "__name__", str(d.get("kind")))}
                for d in cls.Options.describe()]
        if flags is not None:
            for d in opts:
                d["flag"] = flags.get(d["name"])
        rows = [dict(r._asdict()) for r in getattr(cls, "row_outputs", ())]
        states = cls.state_names if isinstance(cls.state_names, tuple) else None
        out.append({"name": name, "label": cls.label, "options": opts, "row_outputs": rows,
                    "outputs": [dict(o._asdict()) for o in cls.outputs],
                    "states": list(states) if states is not None else "per body",
                    "tags": dict(cls.tags)})
    return out


def _row_output_lines(cls) -> list[str]:
    rows = getattr(cls, "row_outputs", ())
    if not rows:
        return []
    width = max(len(r.name) for r in rows)
    return ["  outputs (printed by rocking simulate):", *(
        f"    {r.name:<{width}}  {'flag' if r.flag else (r.unit or '-'):<6}  {r.help}"
        for r in rows)]


@dataclasses.dataclass(frozen=True)
class ModelsRequest:
    """``rocking models``'s options, read and checked (:meth:`from_options`): the models to
    list and the flags of ``rocking simulate``."""

    classes: dict
    """``{name: model class}``: every registered model, or the one NAME."""
    flags: dict | None
    """``{option name: flag}`` of ``rocking simulate`` (:func:`simulate_flags`)."""
    as_json: bool

    @classmethod
    def from_options(cls, *, name, as_json):
        """The request of the command's options (click's values), in the current click
        context (for the flags)."""
        classes = model_classes()
        if name is not None:
            key = name.strip().lower()
            if key not in classes:
                raise ParameterError(f"model must be one of {', '.join(classes)}; got "
                                     f"{name!r}")
            classes = {key: classes[key]}
        return cls(classes=classes, flags=simulate_flags(), as_json=as_json)


@click.command("models", context_settings=CONTEXT)
@click.argument("name", required=False)
@click.option("--json", "as_json", is_flag=True, help="Print JSON.")
def models_cmd(**options):
    """List the rocking models (or model NAME), their options and the flags of
    simulate that set them."""
    req = ModelsRequest.from_options(**options)
    classes, flags = req.classes, req.flags
    if req.as_json:
        click.echo(json.dumps(models_dict(flags, list(classes)), indent=2,
                              default=json_default))
        return
    blocks = []
    for key, cls in classes.items():
        blocks.append("\n".join([f"{key}: {cls.label}", *options_table(cls, flags),
                                 *_row_output_lines(cls)]))
    click.echo("\n\n".join(blocks))
    how = "--FLAG VALUE (the flag column) or " if flags is not None else ""
    click.echo(f"\nset an option with: rocking simulate --model NAME {how}--option KEY=VALUE")


__all__ = ["models_cmd", "models_dict", "simulate_flags"]
