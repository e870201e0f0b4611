"""
Is my statue safe?
==================

A marble statue stands on the top floor of a five-storey building. How likely is it to
overturn in the next 50 years, and would a seismically isolated base help? End to end:

1. the statue's mesh and its weakest direction of shaking;
2. the site's hazard curve (an OpenQuake engine export);
3. records selected and scaled to the site's design spectrum (EN 1998-1);
4. the floor's motion (the building as a linear filter);
5. the fragility (multiple-stripe analysis of the rocking block);
6. the annual frequency of overturning and its probability in 50 years, with and without
   isolation.

Everything is small so that the page builds in seconds (7 records, 9 levels); a real study
would use more records and levels, or a campaign (:doc:`plot_campaign_dask`).
"""

# %%
# 1. The statue and its weakest direction
# ---------------------------------------
# The package ships a small synthetic statue (a binary PLY mesh in m). Its rocking
# parameters depend on the direction ``phi`` of the shaking, and the two sides of one
# direction differ: per side, the slenderness ``alpha`` (Eq 2 of Peña et al. 2007 for a
# rectangle, the angle between the vertical and the line from the pivot to the centre of
# mass for a general body), the frequency parameter ``p = sqrt(m g R / I_O)`` (Eq 3 for a
# rectangle) and Housner's restitution (Eq 4 for a rectangle, the angular-momentum argument
# for a general body). The block uplifts when the floor acceleration exceeds
# ``g tan(alpha)`` towards that side (Eq 1 at ``theta = 0``).

# sphinx_gallery_thumbnail_number = 4
import tempfile
import warnings
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
from matplotlib.ticker import FormatStrFormatter, NullFormatter

import rocking
import rocking.analysis as A
from rocking.buildings import Building, FloorMotion
from rocking.errors import PlausibilityWarning
from rocking.motions import DesignSpectrum, builtin_records, load_builtin
from rocking.shapes import directional_parameters, load_example, plot_directional, weakest_direction
from rocking.units import G

shape = load_example(density=2600.0)                    # kg/m^3, marble
table = directional_parameters(shape, 72)               # every 5 degrees
weak = weakest_direction(table)
statue = rocking.Block.from_shape(shape, weak.phi)
print(f"mass {shape.mass:.0f} kg, height {shape.height:.2f} m, centre of mass "
      f"{shape.h:.2f} m above the base")
print(f"weakest direction {weak.phi_deg:.0f} deg, side {weak.side}: alpha = "
      f"{weak.alpha:.3f} rad, uplift at {weak.uplift_g:.3f} g")
print(statue)
fig = plot_directional(table)
fig.axes[0].set_rticks([5, 10, 15])              # fewer radial labels: deg
fig.axes[1].set_rticks([0.1, 0.2, 0.3])          # g

# %%
# Every model takes the statue's two sides, the isolated base included. For comparison
# only, the body with its *weak* side on both sides (its own restitution, from angular
# momentum): :doc:`plot_asymmetric_fragility` shows why the statue is about as fragile
# as that body, and why a stand-in with the weak side's ``mu`` (the restitution of an
# impact onto the strong pivot) is not.

geo = shape.parameters(weak.phi)
b_weak = min(geo["b_plus"], geo["b_minus"])             # m: the weak side's pivot
proxy = rocking.Block.from_geometry(geo["h"], b_weak, b_weak, geo["radius_of_gyration"],
                                    name="statue, weak side on both sides")
print(proxy)

# %%
# 2. The site's hazard curve
# --------------------------
# The hazard comes as an OpenQuake engine export ``hazard_curve-mean-PGA_<id>.csv``: a
# metadata comment line (``investigation_time``, ``imt``), then one row per site with
# the probabilities of exceedance ``poe`` of each PGA level (g) in the investigation time.
# We write an **ILLUSTRATIVE** one here (a power law with 0.25 g at 475 years, slope 3:
# not the hazard of any site; put your own export in its place). ``from_openquake`` turns
# ``poe`` in ``T`` years into annual rates ``-ln(1 - poe)/T``.

levels_g = np.geomspace(0.05, 3.0, 20)
rate = (1.0 / 475.0) * (levels_g / 0.25) ** -3.0
poe = 1.0 - np.exp(-rate * 50.0)
folder = Path(tempfile.mkdtemp())
path = folder / "hazard_curve-mean-PGA_0.csv"
path.write_text(
    "#,,,\"generated_by='ILLUSTRATIVE power law, not a hazard model', kind='mean', "
    "investigation_time=50.0, imt='PGA'\"\n"
    + "lon,lat,depth," + ",".join(f"poe-{x:.7f}" for x in levels_g) + "\n"
    + "12.50000,41.90000,0.00000," + ",".join(f"{q:.6e}" for q in poe) + "\n")
curve = A.HazardCurve.from_openquake(path, site=(12.5, 41.9),
                                     label="ILLUSTRATIVE hazard (not a site's)")
pga475, pga2475 = curve.im_at_return_period([475.0, 2475.0])
print(curve)
print(f"PGA with 10 % in 50 years (475 years): {pga475:.3f} g; "
      f"2 % in 50 years (2475 years): {pga2475:.3f} g")

# %%
# 3. Records
# ----------
# EN 1998-1 3.2.3.1.2: at least 7 records for the mean response, whose mean 5 %-damped
# spectrum is nowhere below 90 % of the target over the periods of interest. The target
# is the EC8 Type 1 spectrum on ground C whose PGA, ``S ag`` (S = 1.15 for ground C), is the
# curve's 475-year PGA: the curve above is taken as the hazard of the *surface* PGA at the
# site (site effects included, as a site-specific study gives it), the IM the fragility
# below is fitted to. (A national model's curve is usually on rock, ``ag``: its PGA
# would then be multiplied by S first.) The periods of interest of
# a rocking block are the pulse periods that govern overturning, ``2 pi/(10 p)`` to
# ``2 pi/p`` (``A.default_periods``). The candidates are the horizontal components
# shipped with the package (PEER NGA).

names = [n for n in builtin_records(three_component=True) if not n.upper().endswith("UP")]
candidates = [load_builtin(n) for n in names]
S_C = 1.15                                                 # EN 1998-1 Table 3.2
target = DesignSpectrum.ec8(pga475 * G / S_C, ground="C")  # m/s^2; PGA = S ag = pga475
sel = A.select_records(candidates, target, A.default_periods(statue), n=7, max_scale=4.0)
records = sel.records(candidates)
print(f"{len(candidates)} candidates, {len(records)} selected; compliant: "
      f"{sel.compliant}, min ratio {sel.min_ratio:.2f}, RMS log misfit {sel.misfit:.3f}")
print(pd.DataFrame({"record": [r.name for r in records], "scale": sel.scales,
                    "PGA (g)": [r.pga / G for r in records]}).round(3).to_string(index=False))
ax = sel.plot()
for axis in (ax.xaxis, ax.yaxis):
    axis.set_major_formatter(FormatStrFormatter("%g"))
    axis.set_minor_formatter(NullFormatter())
ax.set_xticks([0.2, 0.3, 0.5, 1.0, 2.0])
ax.set_yticks([1, 2, 5, 10])

# %%
# 4. The floor
# ------------
# A light object does not act back on the building (mass ratio below about 1 %), so the
# building is a linear filter of the ground acceleration (modal superposition; FEMA E-74,
# EN 1998-1 4.3.5): a 5-storey shear building with a fundamental period of 0.5 s and 5 %
# damping, the statue on its roof (floor 5).

building = Building.shear(5, period=0.5, damping=0.05)
roof = [FloorMotion(r, building, floor=5) for r in records]
amp = np.array([f.pfa / r.pga for f, r in zip(roof, records, strict=True)])
print(f"peak floor acceleration / PGA on the roof: median {np.median(amp):.2f} "
      f"(from {amp.min():.2f} to {amp.max():.2f})")

fig, ax = plt.subplots(figsize=(7.5, 3.0), layout="constrained")
t = np.linspace(0.0, 15.0, 3001)
ax.plot(t, roof[0].acceleration(t) / G, lw=0.7, color="tab:red", label="roof")
ax.plot(t, records[0].acceleration(t) / G, lw=0.7, color="0.2", label="ground")
ax.axhline(weak.uplift_g, color="tab:blue", ls="--", lw=0.8,
           label="uplift of the weak side, g tan(alpha)")
ax.set(xlabel="time (s)", ylabel="acceleration (g)",
       title=f"{records[0].name}, scaled by {sel.scales[0]:.3g} (the selection)")
ax.legend(fontsize=8, loc="lower right")
ax.grid(alpha=0.3)

# %%
# 5. Fragility
# ------------
# Multiple-stripe analysis (Baker 2015): each record is scaled to each of 9 ground PGAs,
# filtered by the building and run (:func:`rocking.simulate_many`: one compiled batch per
# configuration). The classical model integrates Eq 1 between impacts and applies Eq 4's
# restitution (per side) at each impact. Five configurations:
#
# * ``free``: the statue as it stands (asymmetric sides);
# * ``free, proxy``: the body with its weak side on both sides (for comparison);
# * ``isolated, 0.2 m`` and ``isolated, 0.4 m``: the statue on an isolated base plate
#   (linear isolator, ``T_b`` = 2.5 s, 10 % damping, plate mass = statue mass) in a moat
#   with a clearance of 0.20 m or 0.40 m. A run that reaches the clearance stops: the
#   plate hits the wall, and such a run counts as a failure (not as a survivor);
# * ``isolated, no moat``: the same without a wall (the plate moves as far as it must):
#   failure is overturning only.
#
# The fragility is a lognormal curve of the *ground* PGA (the hazard's IM), fitted by
# maximum likelihood (probit GLM on ``ln PGA``).

stripes = np.geomspace(0.05, 1.6, 9)                       # g
ground = [r.scaled(s * G / r.pga) for s in stripes for r in records]
im = np.repeat(stripes, len(records))
motions = {"ground": ground, "roof": [FloorMotion(g, building, floor=5) for g in ground]}
ISOLATION = dict(isolation_period=2.5, isolation_damping=0.10, mass_ratio=1.0)  # s, -, -
MOATS = (0.20, 0.40, None)                 # m: clearance to the moat's wall (None: no wall)


def isolated(moat):
    return "isolated, no moat" if moat is None else f"isolated, {moat:g} m"

runs = {}
for where, mots in motions.items():
    runs[where, "free"] = rocking.simulate_many(statue, mots, max_free_time=5.0)
    runs[where, "free, proxy"] = rocking.simulate_many(proxy, mots, max_free_time=5.0)
    with warnings.catch_warnings():
        # the isolated model derives the restitution from the momentum of block and
        # plate, not from the block's mu (it says so with a PlausibilityWarning)
        warnings.simplefilter("ignore", PlausibilityWarning)
        for moat in MOATS:
            runs[where, isolated(moat)] = rocking.simulate_many(
                statue, mots, model="isolated", clearance=moat, max_free_time=5.0,
                **ISOLATION)


def failed(res):
    """Overturned, or (isolated) the plate reached the clearance."""
    out = np.asarray(res.overturned, dtype=bool)
    if "clearance_exceeded" in res.outputs:
        out = out | np.asarray(res.outputs["clearance_exceeded"], dtype=bool)
    return out


for (where, config), res in runs.items():
    if config.startswith("isolated"):
        wall = np.asarray(res.outputs["clearance_exceeded"], dtype=bool)
        print(f"{where:6s} {config:18s}: {int(res.overturned.sum()):2d} overturned, "
              f"{int(wall.sum()):2d} reached the wall, of {wall.size} runs; largest base "
              f"displacement {np.nanmax(res.outputs['max_base_displacement']):.2f} m")


fits = {}
for key, res in runs.items():
    fits[key] = A.fragility(im, failed(res), im_name="PGA", im_unit="g", n_boot=200,
                            label=" / ".join(key))

# %%
# 6. Risk: annual frequency and 50-year probability
# -------------------------------------------------
# The annual frequency of overturning integrates the fragility over the hazard curve
# (Cornell et al. 2002): ``lambda_f = integral P(f | PGA) |d lambda / d PGA| d PGA``,
# with the curve extended beyond its ends as a power law (``tail share``: how much of
# the result comes from there). The probability in 50 years is ``1 - exp(-50 lambda_f)``.

rows = []
for (where, config), fit in fits.items():
    r = A.risk(fit, curve, t_years=50)
    res = runs[where, config]
    row = {"floor": where, "configuration": config, "median PGA (g)": fit.median,
           "beta": fit.beta, "annual frequency": r.annual_frequency,
           "return period (yr)": 1.0 / r.annual_frequency,
           "P in 50 years": r.probability_50, "tail share": r.tail_share}
    if "max_base_displacement" in res.outputs:
        near = im == stripes[np.argmin(abs(np.log(stripes / pga475)))]
        row["isolator demand, 475 yr (m)"] = float(np.median(
            res.outputs["max_base_displacement"][near]))
    rows.append(row)
summary = pd.DataFrame(rows)
pd.set_option("display.width", 120)
print(summary.to_string(index=False, float_format=lambda x: f"{x:.3g}"))

# %%
# The fragility curves against the hazard: on the roof the building's amplification
# moves the free statue's curve to lower ground PGAs. Isolation stops the rocking, but
# the plate then moves about 0.15 m at the 475-year PGA: in a 0.20 m moat it hits the
# wall about as often as the free statue overturns; a 0.40 m moat moves the curve well
# up, to about where the isolated block without any wall has it (the runs that reach
# 0.40 m are, by and large, those that overturn without a wall). Without a wall the
# isolated block still overturns under the strongest motions, whose long-period content
# the isolator does not filter out (Vassiliou and Makris 2012 found that isolation can
# even make small blocks more vulnerable to long-period pulses).

fig, (a1, a2) = plt.subplots(1, 2, figsize=(10.0, 4.0), layout="constrained")
x = np.geomspace(0.02, 3.0, 300)
colours = {"free": "tab:red", "free, proxy": "tab:orange", "isolated, 0.2 m": "tab:cyan",
           "isolated, 0.4 m": "tab:blue", "isolated, no moat": "tab:purple"}
for (where, config), fit in fits.items():
    a1.plot(x, fit.probability(x), color=colours[config], ls="-" if where == "roof" else ":",
            lw=0.9 if config.endswith("no moat") else 1.6, label=f"{config}, {where}")
a1.axvline(pga475, color="0.4", lw=0.8, ls="-.", label="475-year PGA")
a1.set(xscale="log", xlabel="ground PGA (g)", ylabel="P(failure | PGA)",
       title="fragility (solid: roof, dotted: ground)")
a1.legend(fontsize=7, loc="upper left")
a1.grid(alpha=0.3, which="both")
a2.loglog(curve.im, curve.rate, "k.-", lw=1.0)
a2.set(xlabel="PGA (g)", ylabel="annual rate of exceedance (1/yr)",
       title="ILLUSTRATIVE hazard curve (not a site's)")
for T in (475, 2475):
    a2.axhline(1.0 / T, color="0.6", lw=0.7, ls="--")
    a2.text(curve.im[0], 1.0 / T, f"{T} yr", fontsize=8, va="bottom")
a2.grid(alpha=0.3, which="both")
for ax in (a1, a2):
    ax.xaxis.set_major_formatter(FormatStrFormatter("%g"))

# %%
# Which ground motions make the risk of the free statue on the roof:
# :func:`rocking.analysis.plot_risk` draws the hazard, the fragility and the integrand
# ``P(f | PGA) |d lambda / d ln PGA|``.

fig = A.plot_risk(curve, fits["roof", "free"])

# %%
# The answer
# ----------

free_roof = summary.query("floor == 'roof' and configuration == 'free'").iloc[0]
iso = {m: summary.query(f"floor == 'roof' and configuration == '{isolated(m)}'").iloc[0]
       for m in MOATS if m is not None}
print(f"On the roof, as it stands: about 1 in {free_roof['return period (yr)']:.0f} per "
      f"year, {100 * free_roof['P in 50 years']:.1f} % in 50 years.")
for m, row in iso.items():
    print(f"Isolated (T_b = 2.5 s) in a {m:.2f} m moat: about 1 in "
          f"{row['return period (yr)']:.0f} per year, {100 * row['P in 50 years']:.1f} % "
          "in 50 years.")
