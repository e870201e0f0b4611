"""The building catalog: every kind built from one mapping, declared keys, clear errors."""

from __future__ import annotations

import numpy as np
import pytest

from rocking.buildings import Building
from rocking.buildings import catalog as BC
from rocking.errors import ParameterError
from rocking.units import parse_quantity


def test_sdof_and_modal_equal_their_constructors():
    a = BC.make_building({"kind": "sdof", "period": "400ms", "damping_ratio": "5%"})
    b = Building.sdof(0.4, 0.05)
    for x, y in zip(a.modal_factors(floor=1), b.modal_factors(floor=1), strict=True):
        assert np.array_equal(x, y)
    shapes, gam = [[0.4, 1.0], [1.0, -0.6]], [1.3, -0.35]
    m = BC.make_building({"kind": "modal", "periods": [1.2, 0.35], "shapes": shapes,
                          "participation": gam, "damping_ratio": 0.03})
    om, ze, gp = m.modal_factors(floor=2)
    assert np.allclose(om, 2 * np.pi / np.array([1.2, 0.35]), rtol=1e-15)
    assert np.array_equal(ze, [0.03, 0.03])
    assert np.array_equal(gp, np.array(gam) * np.array(shapes[1]))


def test_percent_is_a_ratio():
    assert parse_quantity("5%", "ratio") == pytest.approx(0.05, rel=1e-15)
    assert parse_quantity("0.05", "ratio", default_unit="") == 0.05


@pytest.mark.parametrize("mapping, key", [
    ({"kind": "sdof", "period": 0.5, "damping_ratio": 5}, "damping_ratio"),
    ({"kind": "sdof", "period": -1.0}, "period"),
    ({"kind": "sdof"}, "period"),
    ({"kind": "tower", "period": 1.0}, "kind"),
    ({"kind": "sdof", "period": 1.0, "storeys": 3}, "storeys"),
    ({"kind": "shear", "period": 1.0, "storeys": 0}, "storeys"),
    ({"kind": "continuous", "period": 1.0, "stiffness_ratio": -1}, "stiffness_ratio"),
    ({"kind": "modal", "periods": [1.0], "shapes": [[1.0]], "participation": [1.0, 2.0]},
     "participation"),
])
def test_bad_buildings_name_the_key(mapping, key):
    with pytest.raises(ParameterError, match=key):
        BC.make_building(mapping)


def test_floor_and_height_ratio_checks():
    b = Building.sdof(0.5)
    with pytest.raises(ParameterError, match="floor"):
        b.modal_factors(floor=2)
    with pytest.raises(ParameterError, match="height_ratio"):
        b.modal_factors(height_ratio=0.5)
    with pytest.raises(ParameterError, match="floor or height_ratio"):
        b.modal_factors()
    assert np.array_equal(b.modal_factors(floor=0)[2], [0.0])


def test_table_lists_every_kind_and_key():
    rows = BC.table()
    for name, k in BC.KINDS.items():
        assert [r["name"] for r in rows if r["kind"] == name] == list(k.Params.names())


def test_shear_and_continuous_equal_their_constructors():
    a = BC.make_building({"kind": "shear", "storeys": 4, "period": 0.6,
                          "damping_ratio": "3%"})
    b = Building.shear(4, 0.6, 0.03)
    c = BC.make_building({"kind": "continuous", "period": 1.1, "stiffness_ratio": 8.0,
                          "n_modes": 4, "storeys": 5})
    d = Building.continuous(1.1, 8.0, 0.05, n_modes=4, n_floors=5)
    for (x, y), where in (((a, b), {"floor": 3}), ((c, d), {"height_ratio": 0.7}),
                          ((c, d), {"floor": 5})):
        for u, v in zip(x.modal_factors(**where), y.modal_factors(**where), strict=True):
            assert np.array_equal(u, v)
    assert a.periods[0] == pytest.approx(0.6, rel=1e-12)
