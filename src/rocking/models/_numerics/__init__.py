"""Compiled numerical building blocks shared by the model kernels (no physics of a model)."""
