"""Boat parameters: their types and the registered boats, in one place to import them from.

:mod:`sailmujoco.boat_params` holds the frozen dataclasses (SI units), :mod:`sailmujoco.boats`
the boats' parameter factories (every number with its source) and :data:`BOATS`, the registry
:func:`get_boat` reads.
"""

from __future__ import annotations

from .boat_params import BoatParams, Foil, Sail
from .boats import BOATS, get_boat, register_boat, saoud_robot, viel_boat, wille_yacht

__all__ = ["BOATS", "BoatParams", "Foil", "Sail", "get_boat", "register_boat", "saoud_robot", "viel_boat",
           "wille_yacht"]
