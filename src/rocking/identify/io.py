"""Records from CSV files: :func:`read_record_csv` and :func:`from_csv`.

``pandas`` (heavy) is imported when a file is read, not with the package.
"""

from __future__ import annotations

from pathlib import Path

from ..errors import RecordError
from .pipeline import free_rocking
from .record import angle_factor
from .result import FreeRockingFit

_T_NAMES = ("t", "time", "time_s", "t_s", "time (s)", "t (s)", "seconds", "s")
_A_NAMES = ("theta", "angle", "rotation", "theta_rad", "theta_deg", "rocking", "rocking_angle")


def read_record_csv(path, units: str = "rad", time_col=None, angle_col=None):
    """``(t, theta)`` (s, rad) from a CSV file with a time and an angle column.

    The columns are chosen by name or 0-based index (``time_col``, ``angle_col``); by
    default a column named ``t``/``time`` and one named ``theta``/``angle``, else the
    first two columns. Files without a header, ``#`` comments and ``,``/``;``/tab/space
    separators are accepted. ``units`` is that of the angle column.

    Examples
    --------
    A simulated free-rocking record written as CSV (columns ``t, theta, omega``):

    >>> import rocking
    >>> from rocking.identify import read_record_csv
    >>> block = rocking.specimen(2)
    >>> path = rocking.simulate(block, theta0=0.1, duration=1.0).to_csv("rocking.csv")
    >>> t, theta = read_record_csv("rocking.csv")
    >>> t.size, float(theta[0])
    (501, 0.1)
    """
    import pandas as pd

    factor = angle_factor(units)
    path = Path(path)
    if not path.is_file():
        raise RecordError(f"record file not found: {path}")
    try:
        lines = [ln for ln in path.read_text().splitlines()
                 if ln.strip() and not ln.lstrip().startswith("#")]
    except (OSError, UnicodeDecodeError) as e:
        raise RecordError(f"{path}: cannot read as text ({e})") from None
    if not lines:
        raise RecordError(f"{path}: no data lines")
    first = lines[0]
    sep = next((c for c in (",", ";", "\t") if c in first), r"\s+")
    fields = [f.strip() for f in (first.split() if sep == r"\s+" else first.split(sep))]
    header = 0 if not all(_is_number(f) for f in fields if f) else None
    try:
        df = pd.read_csv(path, sep=sep, engine="python", comment="#", header=header,
                         skip_blank_lines=True)
    except (pd.errors.ParserError, pd.errors.EmptyDataError, ValueError) as e:
        raise RecordError(f"{path}: cannot read as CSV ({' '.join(str(e).split())})") from None
    if df.shape[1] < 2:
        raise RecordError(f"{path}: needs at least two columns (time and angle), found "
                          f"{df.shape[1]}")
    cols = [str(c).strip() for c in df.columns]
    low = [c.lower() for c in cols]

    def pick(spec, names, default):
        if spec is None:
            for nm in names:
                if nm in low:
                    return low.index(nm)
            return default
        if isinstance(spec, int) or (isinstance(spec, str) and spec.strip().isdigit()
                                     and spec.strip().lower() not in low):
            i = int(spec)
            if not 0 <= i < len(cols):
                raise RecordError(f"{path}: column index {i} out of range (0..{len(cols) - 1})")
            return i
        key = str(spec).strip().lower()
        if key not in low:
            raise RecordError(f"{path}: no column {spec!r}; columns are {', '.join(cols)}")
        return low.index(key)

    it = pick(time_col, _T_NAMES, 0)
    ia = pick(angle_col, _A_NAMES, 1 if it != 1 else 0)
    if it == ia:
        raise RecordError(f"{path}: the time and angle columns are the same ({cols[it]!r})")
    try:
        t = pd.to_numeric(df.iloc[:, it]).to_numpy(dtype=float)
        a = pd.to_numeric(df.iloc[:, ia]).to_numpy(dtype=float)
    except (TypeError, ValueError) as e:
        raise RecordError(f"{path}: non-numeric value in the time or angle column ({e})")\
            from None
    return t, a * factor


def _is_number(x) -> bool:
    try:
        float(x)
    except (TypeError, ValueError):
        return False
    return True


def from_csv(path, units: str = "rad", time_col=None, angle_col=None, **kw) -> FreeRockingFit:
    """:func:`free_rocking` on a CSV record (see :func:`read_record_csv`); ``kw`` go to it.

    ``units`` is that of the angle column (``"rad"`` or ``"deg"``); a numeric ``offset`` or
    ``min_amplitude`` in ``kw`` is in the same units.

    Examples
    --------
    Specimen 2 identified back from its simulated free rocking, saved as CSV:

    >>> import rocking
    >>> from rocking.identify import from_csv
    >>> block = rocking.specimen(2)
    >>> r = rocking.simulate(block, theta0=0.6 * block.alpha, duration=6.0, dt_out=0.002)
    >>> path = r.to_csv("free_rocking.csv")
    >>> fit = from_csv("free_rocking.csv")
    >>> round(fit.alpha, 3), round(fit.p, 2), round(fit.mu, 3)
    (0.168, 3.81, 0.958)
    """
    t, a = read_record_csv(path, units=units, time_col=time_col, angle_col=angle_col)
    f = angle_factor(units)
    return free_rocking(t, a / f, units=units, **kw)
