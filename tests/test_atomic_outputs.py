"""Outputs are written under a temporary name and renamed: a writer that fails half-way
(a full disk, a kill) never leaves a half-written file under the final name."""

from __future__ import annotations

import errno

import matplotlib
import pandas as pd
import pytest

import rocking
from rocking.motions import OneSine
from rocking.plot import figure, save_figure

matplotlib.use("Agg")


def _full_disk(self, *args, **kwargs):
    """A writer that writes a little, then fails as a full disk does."""
    path = args[0] if args else kwargs.get("path_or_buf")
    with open(path, "w") as f:
        f.write("t,theta\n0,")
    raise OSError(errno.ENOSPC, "No space left on device")


def test_response_csv_is_all_or_nothing(tmp_path, monkeypatch):
    r = rocking.simulate(rocking.specimen(2), OneSine(3.0, 0.5), duration=1.0)
    good = r.to_csv(tmp_path / "r.csv")
    assert pd.read_csv(good).shape[0] == r.t.size
    monkeypatch.setattr(pd.DataFrame, "to_csv", _full_disk)
    with pytest.raises(OSError):
        r.to_csv(tmp_path / "new.csv")
    with pytest.raises(OSError):
        r.to_csv(tmp_path / "r.csv")  # over an existing file: the old one stays
    assert sorted(p.name for p in tmp_path.iterdir()) == ["r.csv"]
    assert pd.read_csv(good).shape[0] == r.t.size


def test_figures_are_all_or_nothing(tmp_path, monkeypatch):
    fig, ax = figure()
    ax.plot([0, 1], [0, 1])
    save_figure(fig, tmp_path / "a.png")
    assert (tmp_path / "a.png").read_bytes()[:4] == b"\x89PNG"

    def broken(self, fname, *a, **k):
        with open(fname, "wb") as f:
            f.write(b"\x89PNG half")
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(type(fig), "savefig", broken)
    with pytest.raises(OSError):
        save_figure(fig, tmp_path / "b.png")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.png"]
