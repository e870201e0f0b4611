"""Polar plot of a directional table (:func:`rocking.shapes.directional_parameters`)."""

from __future__ import annotations

import numpy as np

from ..units import G
from .directional import weakest_direction


def plot_directional(table, *, title: str | None = None, weakest=None):
    """A :class:`matplotlib.figure.Figure` with two polar panels against the direction of
    shaking ``phi``: the smaller critical angle ``alpha_min`` (deg) and the smaller uplift
    acceleration ``min(uplift_plus, uplift_minus)`` (g; dashed: the 3-D body's,
    ``uplift_3d``, lower where the shaking crosses a support edge obliquely), the weakest
    direction marked: ``weakest`` (a :class:`rocking.shapes.Direction`, e.g. the exact
    :meth:`rocking.shapes.Shape.weakest`) or, when None, the table's
    (:func:`rocking.shapes.weakest_direction`); named as everywhere by the ``phi`` whose
    "+" side is the weak one. No pyplot state is touched.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import trimesh
    >>> from rocking.shapes import Shape
    >>> box = Shape.from_trimesh(trimesh.creation.box(extents=(0.4, 0.6, 2.0)), density=2000.0)
    >>> from rocking.shapes import directional_parameters, plot_directional
    >>> fig = plot_directional(directional_parameters(box, 36), title="box")
    >>> type(fig).__name__, len(fig.axes)
    ('Figure', 2)
    """
    from matplotlib.figure import Figure

    weak = weakest_direction(table) if weakest is None else weakest
    order = np.argsort(table["phi"].to_numpy() % (2 * np.pi))
    phi = table["phi"].to_numpy()[order]
    alpha = np.degrees(table["alpha_min"].to_numpy()[order])
    uplift = np.minimum(table["uplift_plus"].to_numpy(),
                        table["uplift_minus"].to_numpy())[order] / G
    up3 = (np.minimum(table["uplift_3d_plus"].to_numpy(), table["uplift_3d_minus"].to_numpy())
           [order] / G if "uplift_3d_plus" in table.columns else None)
    closed = len(phi) > 2 and np.ptp(phi) > 1.5 * np.pi
    if closed:
        phi, alpha, uplift = (np.append(a, a[0]) for a in (phi, alpha, uplift))
        up3 = None if up3 is None else np.append(up3, up3[0])
    fig = Figure(figsize=(10, 4.8), layout="constrained")
    for k, (values, label) in enumerate(((alpha, "alpha_min (deg)"),
                                         (uplift, "uplift acceleration (g)"))):
        ax = fig.add_subplot(1, 2, k + 1, projection="polar")
        ax.plot(phi, values, color="C0", lw=1.5, label="planar block")
        if k == 1 and up3 is not None:
            ax.plot(phi, up3, color="C1", lw=1.0, ls="--",
                    label="3-D body (resultant leaves the support)")
        w = weak.alpha * 180.0 / np.pi if k == 0 else weak.uplift_g
        ax.plot([weak.phi, weak.phi], [0.0, w], color="C3", lw=1.2)
        ax.plot([weak.phi], [w], "o", color="C3",
                label=f"weakest: phi = {weak.phi_deg:.1f} deg, side {weak.side}")
        ax.set_ylim(0.0, 1.1 * float(np.nanmax(values)))
        ax.set_title(label, fontsize=10)
        if k == 1:
            fig.legend(*ax.get_legend_handles_labels(), loc="outside lower center", ncol=3,
                       fontsize=8)
    if title:
        fig.suptitle(title)
    return fig


__all__ = ["plot_directional"]
