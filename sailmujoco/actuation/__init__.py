"""Actuators as fitted: what a servo or a sheet winch makes of a controller's command.

The papers' actuators are ideal first-order lags; a fitted servo also turns no faster than its
rated speed, ignores a change inside its deadband, has play in its gear train (backlash) and
moves in steps (its position resolution); a sheet winch pulls in only as fast as its torque
allows against the sheet's load (:mod:`.servo`, :mod:`.winch`).
"""
