"""ArduPilot SITL's JSON backend protocol: the binary servo packet it sends and the JSON state
line it reads back (``libraries/SITL/examples/JSON/readme.md`` of ArduPilot).

The packet, little-endian: ``uint16 magic, uint16 frame_rate, uint32 frame_count, uint16
pwm[n]`` with ``magic`` 18458 and n = 16 (40 bytes), or 29569 and n = 32 (72 bytes,
``SERVO_32_ENABLE``). ``frame_rate`` is the frame rate SITL asks for (Hz), ``frame_count``
counts frames from SITL's start (it goes back to 0 when SITL restarts; a frame sent again after
a silence keeps its count). The answer is one JSON object on a line of its own (``"\\n"`` before
and after), whose vectors SITL's parser reads as ``[x, y, z]`` with a comma and a space between
the numbers: :func:`state_line` writes them so.
"""

from __future__ import annotations

import json
import math
import struct
from dataclasses import dataclass

import numpy as np

MAGIC_16, MAGIC_32 = 18458, 29569
_HEADER = struct.Struct("<HHI")
_SIZES = {MAGIC_16: _HEADER.size + 2 * 16, MAGIC_32: _HEADER.size + 2 * 32}


class ProtocolError(ValueError):
    """A packet that is not SITL's servo packet (one line: what arrived, what was expected)."""


@dataclass(frozen=True)
class ServoPacket:
    """One frame of SITL's servo outputs.

    Parameters
    ----------
    frame_rate : int
        The frame rate SITL asks for, Hz.
    frame_count : int
        The frame's number since SITL started.
    pwm : tuple of int
        The channels' pulse widths, us (channel 1 first).
    """

    frame_rate: int
    frame_count: int
    pwm: tuple

    def channel(self, number: int) -> int:
        """The pulse width of channel ``number`` (1-based, as ArduPilot's SERVOn), us.

        Parameters
        ----------
        number : int
            The channel, 1 to 16 (or 32).
        """
        return self.pwm[number - 1]


def parse_servo_packet(data: bytes) -> ServoPacket:
    """The servo packet in ``data``.

    Parameters
    ----------
    data : bytes
        One UDP datagram.

    Raises
    ------
    ProtocolError
        Its size or magic is not a servo packet's.
    """
    if len(data) < _HEADER.size:
        raise ProtocolError(f"a packet of {len(data)} bytes is not a servo packet (40 bytes with magic "
                            f"{MAGIC_16}, or 72 with {MAGIC_32})")
    magic, rate, count = _HEADER.unpack_from(data)
    if magic not in _SIZES or len(data) != _SIZES[magic]:
        raise ProtocolError(f"a packet of {len(data)} bytes with magic {magic} is not a servo packet "
                            f"(40 bytes with magic {MAGIC_16}, or 72 with {MAGIC_32})")
    n = (len(data) - _HEADER.size) // 2
    return ServoPacket(rate, count, struct.unpack_from(f"<{n}H", data, _HEADER.size))


def servo_packet(pwm, frame_rate: int = 400, frame_count: int = 0) -> bytes:
    """The bytes SITL sends for ``pwm`` (16 channels: magic 18458; 32: magic 29569).

    Parameters
    ----------
    pwm : sequence of int
        16 or 32 pulse widths, us.
    frame_rate : int
        Hz.
    frame_count : int
        The frame's number.
    """
    pwm = [int(v) for v in pwm]
    magic = {16: MAGIC_16, 32: MAGIC_32}.get(len(pwm))
    if magic is None:
        raise ValueError(f"a servo packet has 16 or 32 channels, got {len(pwm)}")
    return _HEADER.pack(magic, int(frame_rate), int(frame_count)) + struct.pack(f"<{len(pwm)}H", *pwm)


def state_line(state: dict) -> bytes:
    """The JSON line SITL reads: ``state`` with every number finite, between two newlines.

    Parameters
    ----------
    state : dict
        ``timestamp`` (s), ``imu`` {``gyro``, ``accel_body``}, ``position``, ``velocity``,
        ``quaternion`` and optionally ``windvane`` {``direction``, ``speed``} (:mod:`.state`).

    Raises
    ------
    ValueError
        A number is not finite (SITL would read it as garbage).
    """
    def plain(value):
        if isinstance(value, dict):
            return {k: plain(v) for k, v in value.items()}
        if isinstance(value, np.ndarray):
            value = value.tolist()
        if isinstance(value, (list, tuple)):
            return [plain(v) for v in value]
        number = float(value)
        if not math.isfinite(number):
            raise ValueError(f"the state for SITL holds a non-finite number ({number})")
        return number

    return ("\n" + json.dumps(plain(state), separators=(",", ":")) + "\n").encode()
