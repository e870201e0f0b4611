r"""Mass properties of a closed triangle mesh: volume, centre of mass, inertia tensor.

By the divergence theorem the volume integrals of 1, x, x x^T over the solid become sums
over the boundary triangles (Eberly, "Polyhedral mass properties (revisited)", 2002;
Mirtich 1996); trimesh's :func:`trimesh.triangles.mass_properties` implements Eberly's
formulas, vectorised. The vertices are first moved to their mean (the integrals of x x^T
about a far origin would cancel catastrophically). The inertia tensor is about the centre
of mass, in the tensor convention

.. math:: I = \int (|r|^2 \mathbf 1 - r r^T)\, dm ,

(products of inertia with a minus sign), so that ``u . I . u`` is the moment of inertia
about the axis ``u`` through the centre of mass. The tests check these numbers against an
independent computation (:mod:`rocking.testing.mesh_reference`: signed tetrahedra summed in
plain Python) and closed forms.

Mass: exactly one of ``density`` (kg/m^3) and ``mass`` (kg).
"""

from __future__ import annotations

import numpy as np

from .._validate import check_plausible, positive, warn_implausible
from ..errors import ParameterError


def volume_properties(vertices, faces) -> dict:
    """``volume`` (m^3), ``com`` (3,) (m) and ``inertia`` (3, 3) per unit density (m^5,
    about the centre of mass) of the solid bounded by the triangles (outward normals)."""
    from trimesh.triangles import mass_properties

    v = np.asarray(vertices, dtype=np.float64)
    origin = v.mean(axis=0)
    props = mass_properties((v - origin)[np.asarray(faces)], density=1.0)
    volume = float(props["volume"])
    com = np.asarray(props["center_mass"], dtype=np.float64) + origin
    inertia = np.asarray(props["inertia"], dtype=np.float64)
    inertia = 0.5 * (inertia + inertia.T)
    return {"volume": volume, "com": com, "inertia": inertia}


DENSE = 8000.0
"""A density derived from a given mass (kg/m^3) above which a plausibility warning asks
whether the mass and the mesh belong together (denser than steel and cast iron; a solid
bronze or lead body is rare, a hollow statue's closed mesh gives less)."""


def resolve_mass(volume: float, density=None, mass=None) -> tuple[float, float]:
    """``(mass, density)`` from exactly one of them (kg/m^3 or kg). A density outside
    :data:`rocking.PLAUSIBLE_LIMITS` (given, or the mass over the volume) gets a
    :class:`~rocking.errors.UnitSlipWarning`; a mass that makes the body denser than
    :data:`DENSE` a plausibility warning."""
    if (density is None) == (mass is None):
        raise ParameterError("give exactly one of density (kg/m^3) and mass (kg), got "
                             + ("both" if density is not None else "neither"))
    if density is not None:
        density = positive("density", density, "kg/m^3")
        check_plausible("density", density, "density")
        return density * volume, density
    mass = positive("mass", mass, "kg")
    rho = mass / volume
    if check_plausible("density", rho, "the mass over the mesh's volume",
                       shown=f"{mass:g} kg / {volume:.4g} m^3 = {rho:,.4g} kg/m^3",
                       hint="the mesh in other units (units='mm'), or the mass not in kg?"):
        if rho > DENSE:
            warn_implausible(f"the mass over the mesh's volume is {mass:g} kg / "
                             f"{volume:.4g} m^3 = {rho:,.0f} kg/m^3, denser than steel "
                             "(7,850): is the mass that of this mesh, and the mesh to scale "
                             "(units)?")
    return mass, rho


__all__ = ["resolve_mass", "volume_properties"]
