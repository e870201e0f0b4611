"""
Why an asymmetric statue is not its weak side
=============================================

Two results of issue 31 looked wrong:

* the example statue, shaken along its weakest direction, was *more* fragile than a
  symmetric stand-in with its weak side's ``alpha``, ``p`` and ``mu`` on both sides (median
  0.50 g against 0.59 g);
* a body of :meth:`rocking.Block.from_geometry` with ``mu = 0.9`` on both sides became
  more fragile when only its strong side was widened (median 7.76 to 6.69 m/s^2).

Neither is a bug of the models (``tests/test_asymmetric_fragility.py`` checks the
mechanism below against closed forms and against the discrete element model, which rocks
the statue's outline with its true mass and inertia). Both come from the impacts of an
asymmetric body, ``Block.from_geometry`` and :mod:`rocking.models.housner`: an impact
that ends rocking on side ``s`` lands on the other pivot ``o`` with the angular velocity
``mu_s theta'`` (angular momentum about the new pivot), so its kinetic energy becomes

.. math:: E_o = \\mu_s^2 \\, \\frac{I_o}{I_s}\\, E_s .

The page runs in about half a minute.
"""

# sphinx_gallery_thumbnail_number = 2

# %%
# 1. The strong side hands its excursions to the weak side
# --------------------------------------------------------
# Free rocking from a tilt of half the strong side's ``alpha``: the potential energy of
# a tilt ``theta`` is ``m g R_s (cos(alpha_s - theta) - cos(alpha_s))``, about ``m g b_s
# theta``: larger on the strong side (``b_s > b_w``) than on the weak one at the same
# angle. After the impact the block reaches on its weak side a *larger* angle than it
# left on the strong side (here 0.148 to 0.174 rad: 50 % of ``alpha_s``, then 71 % of
# ``alpha_w``), while a symmetric body with two weak sides, released from the same angle,
# comes back smaller. The DEM (dots), an independent model of the same body, agrees.

import warnings

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.ticker import FormatStrFormatter, NullFormatter

import rocking
import rocking.analysis as A
from rocking.errors import PlausibilityWarning
from rocking.motions import seed_earthquakes
from rocking.shapes import example_mesh_path, load_shape, parse_direction, resolve_direction
from rocking.units import G

shape = load_shape(example_mesh_path(), density=2600.0)
q = shape.parameters(resolve_direction(shape, parse_direction("weakest")))
h, bp, bm, rg = q["h"], q["b_plus"], q["b_minus"], q["radius_of_gyration"]
statue = rocking.Block.from_mesh(example_mesh_path(), density=2600.0, direction="weakest")
weak_side = "+" if statue.alpha_plus < statue.alpha_minus else "-"
b_w, b_s = (bp, bm) if weak_side == "+" else (bm, bp)
# the symmetric bodies of either side (their own restitutions, from angular momentum)
weak = rocking.Block.from_geometry(h, b_w, b_w, rg, name="weak side on both sides")
strong = rocking.Block.from_geometry(h, b_s, b_s, rg, name="strong side on both sides")
# the stand-in of issue 31: the weak side's alpha, p and mu_w, the restitution of an impact
# that ends rocking on the weak side and lands on the *strong* pivot
mu_w = statue.mu_plus if weak_side == "+" else statue.mu_minus
stand_in = rocking.Block.from_params(weak.alpha, weak.p, mu_w, name="stand-in (mu_w)")
print(statue)
print(f"restitutions: statue {statue.mu_plus:.4f} / {statue.mu_minus:.4f} (+/-), energy "
      f"ratio per impact {statue.impact_energy_ratios()[0]:.4f}; weak body {weak.mu:.4f} "
      f"({weak.mu ** 2:.4f}); stand-in {mu_w:.4f} ({mu_w ** 2:.4f})")

s_sign = 1.0 if weak_side == "-" else -1.0  # theta of the strong side
a_s = statue.alpha_minus if weak_side == "+" else statue.alpha_plus
th0 = 0.5 * a_s * s_sign
free = rocking.simulate(statue, None, theta0=th0, duration=2.5)
dem = rocking.simulate(statue, None, model="dem", theta0=th0, duration=2.5)
sym = rocking.simulate(weak, None, theta0=th0, duration=2.5)

fig1, ax = plt.subplots(figsize=(7.0, 3.6), layout="constrained")
ax.plot(free.t, free.theta, color="tab:red", lw=1.6, label="statue (classical, both sides)")
ax.plot(dem.t[::8], dem.theta[::8], ".", color="k", ms=3, label="statue (DEM of its outline)")
ax.plot(sym.t, sym.theta, color="tab:blue", lw=1.2, ls="--",
        label="weak side on both sides (symmetric body)")
for a, txt in ((statue.alpha_plus, "alpha+"), (-statue.alpha_minus, "alpha-")):
    ax.axhline(a, color="0.5", lw=0.7, ls=":")
    ax.text(2.45, a, txt, ha="right", va="bottom" if a > 0 else "top", fontsize=8)
ax.set(xlabel="time (s)", ylabel="theta (rad)",
       title="free rocking from half the strong side's alpha")
ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
ax.grid(alpha=0.3)

# %%
# 2. The statue against its weak side
# ------------------------------------
# Fragility curves of the ground PGA from the paper's 30 spectrum-compatible earthquakes
# (:func:`rocking.motions.seed_earthquakes`), each also with its sign reversed so that
# neither side of the statue is favoured by the records. The statue's median is that of
# the body with its weak side on both sides (within the spread of the record set): it
# has one weak side instead of two, but the strong side feeds the weak one (section 1).
# The stand-in of the issue is stronger than both: its restitution ``mu_w`` belongs to
# an impact onto the strong pivot and loses more energy (``mu_w^2``) than an impact of
# the weak body onto its own weak pivot. A symmetric stand-in is not needed any more:
# every model takes the asymmetric block (issue 31).

records = seed_earthquakes()
records = records + [r.scaled(-1.0) for r in records]
stripes = np.geomspace(0.3, 1.6, 10)                    # g
motions = [r.scaled(s * G / r.pga) for s in stripes for r in records]
im = np.repeat(stripes, len(records))
fits = {}
for name, block in (("statue", statue), ("weak side on both sides", weak),
                    ("stand-in (mu_w)", stand_in), ("strong side on both sides", strong)):
    res = rocking.simulate_many(block, motions, max_free_time=5.0)
    fits[name] = A.fragility(im, res.overturned, im_name="PGA", im_unit="g", n_boot=0)
for name, fit in fits.items():
    print(f"{name:28s} median {fit.median:.3f} g, beta {fit.beta:.2f}")

# %%
# 3. One restitution for both sides of an asymmetric body
# --------------------------------------------------------
# Widening the strong side (``b_s``, with ``h``, ``b_w`` and ``r_g`` kept) makes it stiffer
# still: with the restitutions of angular momentum the impacts onto and off the wide side
# also lose more (``mu_+ mu_-`` falls from 0.88 to 0.61), and beyond ``b_s / b_w`` of
# about 1.3 the body becomes *less* fragile, as a wider body should. With ``mu = 0.9``
# imposed on both sides nothing offsets the stiffer side, and the impact that lands on
# the wide side keeps ``0.81 I_s / I_w`` of the energy: above 1 (energy created) from
# ``b_s / b_w`` of about 2.9 here. ``Block.from_geometry`` warns about restitutions that
# create energy (:meth:`rocking.Block.impact_energy_ratios`).

H, B_W, R_G = 0.5, 0.1, 0.25                                  # m
widths = np.array([0.1, 0.13, 0.16, 0.2, 0.25, 0.3])          # b_s, m
eq = seed_earthquakes()[:30]
levels = np.geomspace(0.5, 20.0, 12)                          # m/s^2
mots = [r.scaled(s / r.pga) for s in levels for r in eq]
pga = np.repeat(levels, len(eq))
medians = {"angular momentum": [], "mu = 0.9 on both sides": []}
ratios = []
for b_s in widths:
    for key, mu in (("angular momentum", None), ("mu = 0.9 on both sides", 0.9)):
        with warnings.catch_warnings():  # mu = 0.9 creates energy at the widest (said)
            warnings.simplefilter("ignore", PlausibilityWarning)
            body = rocking.Block.from_geometry(H, B_W, b_s, R_G, mu=mu)
        res = rocking.simulate_many(body, mots, max_free_time=5.0)
        medians[key].append(A.fragility(pga, res.overturned, n_boot=0).median)
        if mu is not None:
            ratios.append(max(body.impact_energy_ratios()))

fig2, (a1, a2) = plt.subplots(1, 2, figsize=(10.0, 3.8), layout="constrained")
x = np.geomspace(0.2, 2.5, 200)
styles = {"statue": ("tab:red", "-"), "weak side on both sides": ("tab:blue", "--"),
          "stand-in (mu_w)": ("tab:orange", "-."), "strong side on both sides": ("tab:green", ":")}
for name, fit in fits.items():
    c, ls = styles[name]
    a1.plot(x, fit.probability(x), color=c, ls=ls, lw=1.6,
            label=f"{name} ({fit.median:.2f} g)")
a1.set(xscale="log", xlabel="ground PGA (g)", ylabel="P(overturn | PGA)",
       title="the statue, its weak side, the stand-in")
a1.legend(fontsize=7, loc="upper left")
a1.grid(alpha=0.3, which="both")
a1.set_xticks([0.3, 0.5, 1.0, 2.0])
a1.xaxis.set_major_formatter(FormatStrFormatter("%g"))
a1.xaxis.set_minor_formatter(NullFormatter())
for (key, m), c, mk in zip(medians.items(), ("tab:purple", "tab:gray"), "os", strict=True):
    a2.plot(widths / B_W, m, marker=mk, color=c, label=key)
a2.set(xlabel="b_s / b_w (strong side widened)", ylabel="fragility median PGA (m/s^2)",
       title=f"from_geometry(h={H}, b_w={B_W}, r_g={R_G})")
a2.legend(fontsize=8)
a2.grid(alpha=0.3)
print("largest energy ratio of an impact with mu = 0.9:",
      ", ".join(f"{w / B_W:.1f}: {r:.3f}" for w, r in zip(widths, ratios, strict=True)))
