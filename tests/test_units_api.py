"""One unit per parameter name, across the package (issue 17).

Every declared parameter -- a model's options (``rocking.models.MODELS``), a motion kind's
parameters (``rocking.motions.catalog.KINDS``), a block form's keys
(``rocking.blocks.factory.FORMS``) and any other ``rocking.options.Options`` of the package
-- whose name is in ``rocking.options.UNITS`` has that unit, and one name never has two
units. A parameter declared with a ``quantity`` takes a string in its own unit
(``"0.3m/s^2"``) and in another one (``"30deg"``) to the same SI number.
"""

from __future__ import annotations

import dataclasses
import importlib
import math
import pkgutil
from collections import defaultdict

import pytest

import rocking
from rocking.blocks.factory import FORMS
from rocking.models import MODELS
from rocking.motions.catalog import KINDS
from rocking.options import UNITS, Options, check_option
from rocking.units import KINDS as QUANTITIES


def _package_options() -> list[tuple[str, type]]:
    """Every Options dataclass defined in the package (all modules imported)."""
    for m in pkgutil.walk_packages(rocking.__path__, "rocking."):
        if m.name.split(".")[-1] != "__main__":
            importlib.import_module(m.name)
    out, todo = [], list(Options.__subclasses__())
    while todo:
        cls = todo.pop()
        todo += cls.__subclasses__()
        if cls.__module__.startswith("rocking.") and dataclasses.is_dataclass(cls):
            out.append((f"{cls.__module__}.{cls.__qualname__}", cls))
    return out


def declarations() -> list[tuple[str, str, dataclasses.Field]]:
    """``(owner, name, field)`` of every declared parameter: the registries first (named by
    what the user calls them), then the other Options of the package."""
    groups = ([(f"model {n}", c.Options) for n, c in MODELS.items()]
              + [(f"motion kind {n}", k.Params) for n, k in KINDS.items()]
              + [(f"block form {n}", f.Params) for n, f in FORMS.items()])
    seen = {cls for _, cls in groups}
    groups += [(o, cls) for o, cls in _package_options() if cls not in seen]
    return [(owner, f.name, f) for owner, cls in groups for f in dataclasses.fields(cls)
            if f.metadata]


def unit_problems(decls) -> list[str]:
    """Declarations whose unit differs from :data:`UNITS`, and names with two units."""
    bad = [f"{owner}: {name} in {f.metadata.get('unit', '')!r}, not {UNITS[name]!r}"
           for owner, name, f in decls
           if name in UNITS and f.metadata.get("unit", "") != UNITS[name]]
    units = defaultdict(lambda: defaultdict(list))
    for owner, name, f in decls:
        units[name][f.metadata.get("unit", "")].append(owner)
    bad += [f"{name} has {len(u)} units: "
            + "; ".join(f"{k!r} ({', '.join(v)})" for k, v in u.items())
            for name, u in units.items() if len(u) > 1]
    return bad


DECLS = declarations()


def test_the_registries_and_the_package_are_covered():
    owners = {o for o, _, _ in DECLS}
    assert {f"model {n}" for n in MODELS} <= owners
    assert {f"motion kind {n}" for n in KINDS} <= owners
    assert {f"block form {n}" for n in FORMS} <= owners
    names = {n for _, n, _ in DECLS}
    # the shared names of UNITS that the registries declare today
    assert {"amplitude", "frequency", "period", "duration", "friction_angle", "damping",
            "stiffness", "width", "alpha", "nu"} <= names


def test_every_parameter_has_the_unit_of_its_name_and_one_unit_per_name():
    assert unit_problems(DECLS) == []


def test_the_checker_finds_planted_disagreements():
    @dataclasses.dataclass(frozen=True)
    class Bad(Options):
        friction_angle: float = rocking.options.option(30.0, help="in degrees", unit="deg")
        spacing: float = rocking.options.option(1.0, help="in m", unit="m")

    @dataclasses.dataclass(frozen=True)
    class Other(Options):
        spacing: float = rocking.options.option(1.0, help="in mm", unit="mm")

    planted = [("bad", f.name, f) for f in dataclasses.fields(Bad)] + \
              [("other", f.name, f) for f in dataclasses.fields(Other)]
    found = unit_problems(planted)
    assert any("bad: friction_angle in 'deg', not 'rad'" in s for s in found)
    assert any(s.startswith("spacing has 2 units") for s in found)
    assert not any(s.startswith("friction_angle has") for s in found)  # one unit only


QUANTITY_DECLS = [(o, n, f) for o, n, f in DECLS if f.metadata.get("quantity")]


@pytest.mark.parametrize("owner, name, f", QUANTITY_DECLS,
                         ids=[f"{o}.{n}" for o, n, _ in QUANTITY_DECLS])
def test_a_value_with_its_unit_is_the_si_number(owner, name, f):
    """The declared unit is the SI unit of its quantity: "2.5<unit>" is 2.5, and the same
    value in another unit of that quantity converts to the same number."""
    m = f.metadata
    table = QUANTITIES[m["quantity"]]
    unit = m["unit"]
    assert table[unit.lower()] == 1.0, f"{owner}: {name} declared in {unit!r}, not SI"
    x = 0.5 if m.get("hi") is not None and m["hi"] < 2.0 else 2.5
    assert check_option(name, f"{x!r}{unit}", m) == x
    other = next(u for u, k in table.items() if k != 1.0)
    assert check_option(name, f"{x / table[other]!r}{other}", m) == pytest.approx(x,
                                                                                 rel=1e-12)


def test_friction_angle_and_the_other_angles_share_rad():
    """The DEM's friction angle is in rad like the slenderness alpha and the pulse phase
    nu: "30deg" means the same everywhere."""
    dem = {f.name: f for f in dataclasses.fields(MODELS["dem"].Options)}
    blk = {f.name: f for f in dataclasses.fields(FORMS["classical"].Params)}
    mp = {f.name: f for f in dataclasses.fields(KINDS["mavroeidis_papageorgiou"].Params)}
    values = [check_option(n, "30deg", d[n].metadata)
              for n, d in (("friction_angle", dem), ("alpha", blk), ("nu", mp))]
    assert values == [math.radians(30.0)] * 3
