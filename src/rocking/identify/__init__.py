"""Free-rocking identification of ``alpha``, ``p`` and ``mu`` (Peña et al. 2007, Sec. 4.1)."""

from .pipeline import (
    FreeRockingFit,
    IdentificationError,
    free_rocking,
    from_csv,
    quarter_time,
    read_record_csv,
    sigma_surface,
)
from .pipeline import (
    _json_safe as _json_safe,  # for the CLI
)

__all__ = ["free_rocking", "from_csv", "read_record_csv", "quarter_time", "sigma_surface",
           "FreeRockingFit", "IdentificationError"]
