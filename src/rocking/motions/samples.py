"""Sampled accelerograms as plain arrays: what processing, spectra and io work on, without
a :class:`~rocking.motions.Record` (and without importing :mod:`rocking.motions.base`, which
computes a motion's default intensity measures with :mod:`rocking.motions.processing`)."""

from __future__ import annotations

import numpy as np

from ..errors import RecordError


def is_sampled(obj) -> bool:
    """True for a sampled accelerogram: an object with ``acc`` (m/s^2), ``dt`` (s) and
    ``values`` (``acc`` times its load factor), such as a
    :class:`~rocking.motions.records.Record`."""
    return all(hasattr(obj, a) for a in ("acc", "dt", "values"))


def as_samples(acc) -> np.ndarray:
    """``acc`` as a contiguous 1-D float64 array of at least 2 finite samples."""
    try:
        a = np.asarray(acc, dtype=np.float64)
    except (TypeError, ValueError):
        raise RecordError("the accelerogram must be a 1-D array of numbers") from None
    if a.ndim != 1 or a.size < 2:
        raise RecordError(f"the accelerogram must be a 1-D array of at least 2 samples, got "
                          f"shape {a.shape}")
    if not np.all(np.isfinite(a)):
        raise RecordError("the accelerogram has a non-finite value (NaN or inf)")
    return np.ascontiguousarray(a)
