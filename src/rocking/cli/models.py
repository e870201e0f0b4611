"""``rocking models``: the registered models and their options (``Options.describe()``).

::

    rocking models            # name, label and options table of each model
    rocking models --json
"""

from __future__ import annotations

import json

import click

from .common import CONTEXT, json_default, model_classes, options_table


def models_dict() -> list[dict]:
    """One dict per registered model: ``name``, ``label``, ``options`` (describe())."""
    out = []
    for name, cls in model_classes().items():
        opts = [{**d, "kind": getattr(d.get("kind"), "__name__", str(d.get("kind")))}
                for d in cls.Options.describe()]
        out.append({"name": name, "label": cls.label, "options": opts})
    return out


@click.command("models", context_settings=CONTEXT)
@click.option("--json", "as_json", is_flag=True, help="Print JSON.")
def models_cmd(as_json):
    """List the rocking models and their options (for simulate --model/--option)."""
    if as_json:
        click.echo(json.dumps(models_dict(), indent=2, default=json_default))
        return
    blocks = []
    for name, cls in model_classes().items():
        blocks.append("\n".join([f"{name}: {cls.label}", *options_table(cls)]))
    click.echo("\n\n".join(blocks))
    click.echo("\nset an option with: rocking simulate --model NAME --option KEY=VALUE")


__all__ = ["models_cmd", "models_dict"]
