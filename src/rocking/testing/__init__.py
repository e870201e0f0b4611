"""Plain (scipy) reference implementations used to check the compiled kernels.

They are slow and simple on purpose: each solves the same equations as a model of
:mod:`rocking.models` with a general-purpose integrator (``scipy.integrate.solve_ivp``)
and event location, so that an agreement between the two is an independent check.
"""

from .contract import CHECKS, check_model, model_checks

__all__ = ["CHECKS", "check_model", "model_checks"]
