r"""Free-rocking identification of ``alpha``, ``p`` and ``mu`` (Peña et al. 2007, Sec. 4.1).

The paper calibrates the classical model on free-rocking tests: ``alpha`` and ``p`` minimise
an error surface between measured and predicted times of the rocking peaks (Eq 13), and
``mu`` follows from the energy of successive amplitudes (Eq 12). :func:`free_rocking` does
the same on a measured record::

    import rocking.identify as ri
    fit = ri.free_rocking(t, theta, units="deg")        # or ri.from_csv("test.csv")
    fit.alpha, fit.p, fit.mu, fit.alpha_std             # rad, 1/s, -, rad
    fit.plot_error_surface(); fit.plot_fit(theoretical=rocking.specimen(2))

The time model is the exact quarter period ``T(r)`` of the classical model, the energy
integral (Eq 11 as printed is not this integral; :mod:`.time_model`). Each half-cycle of
amplitude ``r_k`` rises from the crossing before it to its peak in ``T(r_k)`` and falls back
in ``T(r_k)``; the impact between half-cycles scales the velocity, so the next one has its
own ``r_{k+1}``. The measured peaks and crossings (:mod:`.events`, refined by fitting each
half-cycle with the exact classical one, :mod:`.shape`) give rise and fall times, and
``alpha`` and ``p`` minimise their weighted error (Eq 13, :mod:`.fits`).

**What limits the accuracy.** For small amplitudes ``T ~ sqrt(2 r / alpha) / p``: the times
only fix ``p sqrt(alpha)``, and ``alpha`` and ``p`` separate through the departure from this
law at amplitudes comparable with ``alpha``. A record whose swings are all small compared
with ``alpha``, or a heavily damped block with few half-cycles, gives correlated and
uncertain ``alpha`` and ``p`` (see ``alpha_std``, ``p_std`` and ``alpha_p_corr``); the
release from a large angle helps most (:mod:`.release`).

**Restitution.** ``mu_n`` follows Eq 12 with the fitted ``alpha`` and the first used
amplitude as ``r_0`` (the release, when it is used); ``mu`` is their mean and ``mu_std``
their spread (standard deviation).

All angles are in rad, times in s (the ``units`` argument converts a record in degrees).

Modules, in the order of the pipeline (:mod:`.pipeline`): :mod:`.record` (input, noise),
:mod:`.offset`, :mod:`.events`, :mod:`.time_model` (Eq 11 corrected, Eq 13), :mod:`.shape`
and :mod:`.release` (exact half-cycle fits), :mod:`.timing` (measured times and weights),
:mod:`.fits` (Eq 13 least squares, uncertainties, Eq 12), :mod:`.result`
(:class:`FreeRockingFit`), :mod:`.io` (CSV records).
"""

from ..errors import IdentificationError
from .io import from_csv, read_record_csv
from .pipeline import free_rocking
from .result import FreeRockingFit
from .time_model import quarter_time, sigma_surface

__all__ = ["free_rocking", "from_csv", "read_record_csv", "quarter_time", "sigma_surface",
           "FreeRockingFit", "IdentificationError"]
