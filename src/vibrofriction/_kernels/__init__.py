"""Numba kernels on plain floats: closed forms, event roots, steady state.

Nothing here imports from the rest of the package; the public layer
(:mod:`vibrofriction.solver`) converts parameters and wraps results.
"""
