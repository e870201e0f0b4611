"""Campaigns: a study declared once in a TOML spec, run by chunks on a laptop or a Dask
cluster into a resumable Parquet store.

::

    from rocking import campaign
    spec = campaign.read_spec("study.toml")
    campaign.run(spec, "store/")                 # or executor="dask", dask_local=2
    campaign.status("store/")
    df = campaign.load("store/")                 # one row per simulation

Modules: :mod:`~.spec` (the spec and its checks), :mod:`~.plan` (the table of simulations,
``sim_id``, seeds, one chunk's run), :mod:`~.store` (the store), :mod:`~.execute` (local
and Dask executors) and :mod:`~.report` (fragility and P(overturn) from a store).
"""

from .execute import EXECUTORS, estimate, local_cluster, run
from .plan import STREAM, Campaign
from .spec import EXAMPLE_SPEC, CampaignSpec, parse_spec, read_spec
from .store import Store, load


def status(store) -> dict:
    """How many simulations (and chunks) of the store are done and how many remain.

    Examples
    --------
    >>> from pathlib import Path
    >>> from rocking import campaign
    >>> from rocking.campaign import EXAMPLE_SPEC
    >>> _ = Path("pulses.toml").write_text(EXAMPLE_SPEC)
    >>> _ = campaign.run("pulses.toml", "pulses_store", progress=False)
    >>> s = campaign.status("pulses_store")
    >>> s["n_sims"], s["sims_remaining"], s["chunks_done"], s["complete"]
    (4, 0, 2, True)
    """
    return Store(store).status()


__all__ = ["EXAMPLE_SPEC", "CampaignSpec", "Campaign", "Store", "read_spec", "parse_spec",
           "run", "load", "status", "estimate", "local_cluster", "EXECUTORS", "STREAM"]
