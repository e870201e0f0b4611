"""Stacks of rigid blocks for the discrete element model (``model="dem"``).

``Stack([plinth, block])`` or ``Stack([b1, b2, b3])`` lists blocks from the bottom up. Each
block stands on the top face of the one below (the bottom one on the base), centred on it
unless ``offsets`` gives the horizontal offset (m) of the middle of its base face from the
middle of the top face below (for the bottom block: from the origin of the base). Every
block of a stack needs a flat top face if another block stands on it.

Only the discrete element model can simulate a stack::

    stack = rocking.Stack([rocking.specimen(4, "geometric"), rocking.specimen(2, "geometric")])
    r = rocking.simulate(stack, motion, model="dem")
    r.theta_all  # rotation of every block, shape (2, n_t); r.theta is the top block's
"""

from __future__ import annotations

from dataclasses import dataclass

from .._validate import as_float, sequence_of
from ..errors import ParameterError
from .block import Block


@dataclass(frozen=True, init=False)
class Stack:
    """Blocks stacked bottom to top (see the module docstring).

    Examples
    --------
    Specimen 2 on specimen 4, at rest on a still base (discrete element model only):

    >>> import rocking
    >>> stack = rocking.Stack([rocking.specimen(4, "geometric"),
    ...                        rocking.specimen(2, "geometric")])
    >>> len(stack), stack.top.name
    (2, 'specimen 2')
    >>> r = rocking.simulate(stack, model="dem", duration=0.2)
    >>> r.theta_all.shape, float(abs(r.theta_all).max())
    ((2, 101), 0.0)
    """

    blocks: tuple
    offsets: tuple
    name: str

    def __init__(self, blocks, offsets=None, name: str = ""):
        blocks = sequence_of("Stack blocks", blocks, Block, "rocking.Block")
        if offsets is None:
            offsets = (0.0,) * len(blocks)
        else:
            offsets = tuple(as_float(f"offsets[{i}]", o) for i, o in enumerate(offsets))
            if len(offsets) != len(blocks):
                raise ParameterError(f"offsets must have one entry per block "
                                     f"({len(blocks)}), got {len(offsets)}")
        object.__setattr__(self, "blocks", blocks)
        object.__setattr__(self, "offsets", offsets)
        object.__setattr__(self, "name", str(name))

    def __len__(self) -> int:
        return len(self.blocks)

    def __iter__(self):
        return iter(self.blocks)

    def __getitem__(self, i) -> Block:
        return self.blocks[i]

    @property
    def top(self) -> Block:
        """The top block (the one whose angle is ``Response.theta``)."""
        return self.blocks[-1]

    @property
    def mu(self) -> float:
        """The top block's restitution (the default DEM damping is calibrated to it)."""
        return self.blocks[-1].mu

    def __repr__(self) -> str:
        inner = ", ".join(repr(b) for b in self.blocks)
        off = "" if not any(self.offsets) else f", offsets={list(self.offsets)}"
        return f"Stack([{inner}]{off})"
