"""Inputs: rigid blocks, stacks and the paper's specimens (Peña et al. 2007, Eqs 2-4,
Tables I-III)."""

from .block import GRANITE_DENSITY, Block, housner_mu, polygon_properties
from .specimens import PARAM_SETS, SHAPES, paper_data, specimen, specimen_ids
from .stack import Stack

__all__ = ["Block", "Stack", "housner_mu", "polygon_properties", "GRANITE_DENSITY",
           "specimen", "specimen_ids", "paper_data", "PARAM_SETS", "SHAPES"]
