"""
A campaign on a Dask cluster
============================

A study declared once in a TOML spec runs by chunks into a store that can be stopped,
resumed, verified and reported on, here on a ``dask.distributed`` ``LocalCluster`` of two
workers (the same code runs on a remote scheduler, e.g. a SLURM cluster through
dask-jobqueue: pass its address). The study: specimens 3 and 4 of Peña et al. (2007)
(Table II E parameters) under eight of the paper's spectrum-compatible earthquakes scaled
to six PGA stripes, 96 runs in 6 chunks, and the risk on the EN 1998-1 code approximation
of the hazard.
"""

# %%
# The spec
# --------
# Every key is checked before anything runs (a bad one is one ``SpecError`` naming it).
# Quantities carry their units (``"0.25g"``); stripe levels of ``im = "pga"`` are in
# m/s^2.

import tempfile
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np
from distributed import Client, LocalCluster
from scipy.stats import norm

from rocking import campaign
from rocking.campaign.report import report

SPEC = """
[campaign]
name = "gallery-dask"
seed = 7
model = "housner"

[[blocks]]
specimen = 3
params = "experimental"

[[blocks]]
specimen = 4
params = "experimental"

[motions]
kind = "earthquake"                 # the paper's synthetic earthquakes (Section 3.3)
number = [1, 2, 3, 4, 5, 6, 7, 8]
im = "pga"                          # m/s^2
levels = {start = 1.5, stop = 6.0, num = 6, spacing = "log"}

[hazard]
pga_475 = "0.25g"                   # EN 1998-1 2.1(4): lambda = (1/475) (a/a_475)^-k,
k = 3                               # an approximation, labelled so in the report
t_years = 50

[run]
chunk_size = 16
"""
spec = campaign.parse_spec(SPEC)
est = campaign.estimate(spec)
print(f"{est['n_sims']} runs in {est['n_chunks']} chunks of {est['chunk_size']}: "
      f"{est['shape']}")

# %%
# Running on a LocalCluster
# -------------------------
# Two Dask workers with one thread each. Here they are threads of this process
# (``processes=False``: nothing to start, and the script runs as it is, without an
# ``if __name__ == "__main__"`` guard); :func:`rocking.campaign.local_cluster` (what
# ``rocking campaign run --executor dask --dask-local 2`` uses) gives process workers
# instead, each with its share of the cores for numba. On every worker each chunk is one
# compiled batch; results come back to this process, which writes the store (the workers
# need no shared disk). Leaving the ``with`` blocks closes the client and the cluster.

store = Path(tempfile.mkdtemp()) / "store"
with LocalCluster(n_workers=2, threads_per_worker=1, processes=False,
                  dashboard_address=None) as cluster, Client(cluster) as client:
    print(f"{len(client.scheduler_info()['workers'])} workers, "
          f"{sum(client.nthreads().values())} threads")
    status = campaign.run(spec, store, executor="dask", scheduler=cluster.scheduler_address,
                          progress=False)
print(f"{status['sims_done']} of {status['n_sims']} runs done, "
      f"{status['chunks_done']} chunks, complete: {status['complete']}, "
      f"problems: {status['problems'] or 'none'}")

# %%
# The store
# ---------
# One row per simulation, each chunk verified against its record (sha256) when loaded.
# Every row is the same whatever the executor or the chunk size: run ``sim_id`` draws
# from its own seed.

table = campaign.load(store)
print(table[["sim_id", "block_name", "motion", "level", "pga", "max_abs_theta",
             "overturned"]].head(8).to_string(index=False))
print(table.groupby(["block_name", "level"])["overturned"].mean().unstack().round(2))

# %%
# The report
# ----------
# The report of ``rocking campaign report``: P(overturn) per stripe with Wilson
# intervals, the lognormal fragility per block (maximum likelihood), and with the
# ``[hazard]`` the annual frequency of overturning and its probability in 50 years.

res = report(table, campaign.Store(store).manifest, store / "report", n_boot=200)
frag = res["fragility"]
frag = frag[frag["fit"] == "overturning"].set_index("block_name")
print(frag[["n", "n_exceed", "median", "median_se", "beta", "beta_se"]].round(3))
risk = res["risk"]
risk = risk[risk["fit"] == "overturning"].set_index("block_name")
print(risk[["median", "beta", "annual_frequency", "tail_share", "probability"]]
      .to_string(float_format=lambda v: f"{v:.3g}"))
print("hazard:", risk["hazard"].iloc[0])
print("report files:", ", ".join(sorted(f.name for f in res["files"])))

# %%
# The fragility curves (``Phi(ln(PGA / median) / beta)``) with the stripes' observed
# fractions.

fig, ax = plt.subplots(figsize=(6.5, 4.0), layout="constrained")
x = np.geomspace(1.0, 10.0, 200)
for (name, g), colour in zip(table.groupby("block_name"), ("tab:blue", "tab:red"), strict=True):
    p = g.groupby("level")[["im", "overturned"]].mean()
    ax.plot(p["im"], p["overturned"], "o", color=colour, label=f"{name}: stripes")
    f = frag.loc[name]
    ax.plot(x, norm.cdf(np.log(x / f["median"]) / f["beta"]), color=colour,
            label=f"fit: median {f['median']:.2f} m/s², beta {f['beta']:.2f}")
ax.set(xscale="log", xlabel="PGA (m/s²)", ylabel="P(overturn | PGA)",
       title="Specimens 3 and 4 (Table II E), 8 earthquakes x 6 stripes")
ax.set_xticks([1, 2, 3, 5, 10], labels=["1", "2", "3", "5", "10"])
ax.grid(alpha=0.3, which="both")
ax.legend(fontsize=8)
