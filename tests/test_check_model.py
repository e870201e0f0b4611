"""The executable model contract (rocking.testing.check_model): every check passes for the
registered models and the fourth model of test_model_interface, and each kind of broken
model fails the check that describes its fault, with a message naming it."""

from __future__ import annotations

import re
from dataclasses import dataclass

import pytest
from numba import njit, prange
from test_model_interface import LinearHousner, _linear_kernel

import rocking
from rocking.models import MODELS, ModelOptions, option, row_args, same_block, store_row
from rocking.testing import CHECKS, check_model, model_checks
from rocking.testing.contract import (
    check_batch_rows_equal_single_runs,
    check_chunk_independence,
    check_free_rocking_symmetry,
    check_kernel_params_pure,
    check_motion_symmetry,
    check_options,
)

CONTRACT_MODELS = [*MODELS.values(), LinearHousner]


# -------------------------------------------------------------------- the models pass
@pytest.mark.parametrize("check", CHECKS, ids=lambda c: c.__name__)
@pytest.mark.parametrize("cls", CONTRACT_MODELS, ids=lambda c: c.name)
def test_every_model_passes_every_check(cls, check):
    check(cls)


def test_check_model_runs_every_check_and_takes_names():
    names = [name for name, _ in model_checks(LinearHousner)]
    assert names == [c.__name__ for c in CHECKS] and len(set(names)) == len(names) >= 10
    assert check_model(LinearHousner) is None
    assert check_model("housner") is None  # a registered name


# ------------------------------------------------------------------- broken models fail
@njit(cache=True, parallel=True)
def _batch_with_other_restitution(mp, extra0, rows, blocks):
    """Broken on purpose: the batch loses more energy at impacts than the single run."""
    for i in prange(rows.kinds.shape[0]):
        m = same_block(mp, blocks[i])
        _linear_kernel((m[0], m[1], 0.9 * m[2], m[3]), *row_args(i, rows), rows.res[i],
                       extra0)
        store_row(i, rows)


class BatchDiffers(LinearHousner):
    """A batch row is not the single run (its restitution differs)."""

    name = "broken-batch"
    batch_kernel = _batch_with_other_restitution


@njit(cache=True)
def _kernel_lopsided(mp, kind, prm, samples, t_end, t_quiet, h_scan, y0, dt_out, hist, imp,
                     res, extra):
    """Broken on purpose: a negative initial angle is released from 0.9 of itself."""
    y = y0.copy()
    if y[0] <= 0:
        y[0] *= 0.9
    _linear_kernel(mp, kind, prm, samples, t_end, t_quiet, h_scan, y, dt_out, hist, imp, res,
                   extra)


@njit(cache=True, parallel=True)
def _batch_lopsided(mp, extra0, rows, blocks):
    for i in prange(rows.kinds.shape[0]):
        _kernel_lopsided(same_block(mp, blocks[i]), *row_args(i, rows), rows.res[i], extra0)
        store_row(i, rows)


class Lopsided(LinearHousner):
    """Free rocking is not mirror-symmetric."""

    name = "broken-symmetry"
    kernel = _kernel_lopsided
    batch_kernel = _batch_lopsided


class StoresDtOut(LinearHousner):
    """``kernel_params`` stores its argument (the DEM did until it was fixed)."""

    name = "broken-params"

    def kernel_params(self, dt_out, theta0, omega0):
        self.dt_out = dt_out
        return super().kernel_params(dt_out, theta0, omega0)


@dataclass(frozen=True)
class UncheckedOptions(ModelOptions):
    rest_tol: float = option(1e-12, lo=0.0, hi=1e-2, help="Zeno threshold")

    def __post_init__(self):  # skips the validation of ModelOptions
        pass


class AcceptsAnything(LinearHousner):
    """Options declared with a range that is not enforced."""

    name = "broken-options"
    Options = UncheckedOptions


@pytest.mark.parametrize("cls, failing, detail", [
    (BatchDiffers, check_batch_rows_equal_single_runs, r"row \d+ .*: batch .* != single"),
    (Lopsided, check_free_rocking_symmetry, r"theta0 = \+-.*alpha"),
    (StoresDtOut, check_kernel_params_pure, "kernel_params changed the model's attributes: "
                                            "dt_out added"),
    (AcceptsAnything, check_options, r"option rest_tol=.* was accepted \(declared: \(0, 0.01\]"),
], ids=lambda x: getattr(x, "name", None) or getattr(x, "__name__", ""))
def test_a_broken_model_fails_the_check_that_names_its_fault(cls, failing, detail):
    head = f"{failing.__name__} failed for model {cls.name!r} ({cls.__name__}): "
    with pytest.raises(AssertionError, match=re.escape(head) + detail):
        failing(cls)
    with pytest.raises(AssertionError) as e:
        check_model(cls)
    msg = str(e.value)
    assert msg.startswith(f"check_model({cls.__name__}): ") and head in msg
    assert re.search(detail, msg)


def test_a_check_fails_only_for_its_own_fault():
    """The broken batch is consistent with itself: chunking, symmetry and the options
    still pass, so a failure points at the fault."""
    for check in (check_chunk_independence, check_motion_symmetry, check_options,
                  check_kernel_params_pure):
        check(BatchDiffers)
    with pytest.raises(AssertionError) as e:
        check_model(BatchDiffers)
    failed = re.findall(r"^- (check_\w+) failed", str(e.value), flags=re.M)
    assert failed == ["check_batch_rows_equal_single_runs", "check_blocks_per_row",
                      "check_initial_state_per_row"]


def test_a_class_that_is_not_a_model_fails_first():
    class NoKernels(rocking.models.Model):
        name = "empty"
        label = "empty"

    with pytest.raises(AssertionError, match="check_class_attributes failed for model "
                                             "'empty'.*kernel is not set"):
        check_model(NoKernels)
