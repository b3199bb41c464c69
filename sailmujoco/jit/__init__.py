"""Compiled kernels: the one decorator every numba kernel is built with, its on-disk cache, and the
notice shown while numba compiles."""
