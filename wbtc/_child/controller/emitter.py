"""``Emitter``: sends packets to receivers on a channel."""

from __future__ import annotations

import struct

from . import _session
from .device import Device, checked

NAN = _session.NAN


def _allowed(state: _session.DeviceState, channel: int, function: str) -> bool:
    if channel < -1:
        _session.error(
            f"Error: {function}() called with an invalid channel={channel}. Please use a channel inside the range "
            "[-1,inf)."
        )
        return False
    allowed = [int(c) for c in state.field("allowedChannels", [])]
    if allowed and channel not in allowed:
        _session.error(
            f"Error: {function}() called with channel={channel}, which is not between allowed channels. "
            "Please use an allowed channel."
        )
        return False
    return True


class Emitter(Device):
    """An Emitter node; packets sent during a step travel with that step's commands."""

    CHANNEL_BROADCAST = -1
    _C = "wb_emitter"
    _TYPES = ("Emitter",)

    def __init__(self, name: str | int) -> None:
        super().__init__(name)

    @staticmethod
    def _setup(state: _session.DeviceState, session: _session.Session) -> None:
        state.channel = int(state.field("channel", 0))
        state.max_range = float(state.field("maxRange", -1.0))
        state.range = float(state.field("range", -1.0))
        state.buffer_size = int(state.field("bufferSize", -1))

    @checked("send", None)
    def send(self, message: str | bytes | list | tuple, length: int | None = None) -> None:
        """Send a str (UTF-8), bytes (the first ``length`` bytes) or a list/tuple of floats, ints or bools.

        A list is packed with ``struct`` in native byte order after its first element: floats as doubles (``d``),
        ints and bools as ``i`` (a bool is an int to ``isinstance``, as in Webots' package).
        """
        if isinstance(message, bytes):
            data = message if length is None else message[:length]
        elif isinstance(message, str):
            data = message.encode()
        elif isinstance(message, (list, tuple)):
            if len(message) == 0:
                _session.error("Emitter.send(): empty list")
                return
            if isinstance(message[0], float):
                code = "d"
            elif isinstance(message[0], int):
                code = "i"
            else:
                _session.error(f"Emitter.send(): unsupported data type list: {type(message)}")
                return
            data = struct.pack(f"{len(message)}{code}", *message)
        else:
            _session.error(f"Emitter.send(): unsupported data type: {type(message)}")
            return
        if len(data) < 1:
            _session.error(f"Error: wb_emitter_send(): invalid size={len(data)} argument.")
            return
        state = self._s
        if state.buffer_size != -1:
            used = sum(len(c[2]) for c in _session.require().commands if c[0] == state.tag and c[1] == "send")
            if len(data) > state.buffer_size - used:
                return  # Webots drops a packet that does not fit in the emission buffer
        self._queue("send", bytes(data))

    @checked("get_buffer_size", -1)
    def getBufferSize(self) -> int:
        """The ``bufferSize`` field (-1: unlimited)."""
        return self._s.buffer_size

    @checked("get_channel", -1)
    def getChannel(self) -> int:
        """The current channel."""
        return self._s.channel

    @checked("set_channel")
    def setChannel(self, channel: int) -> None:
        """Emit on ``channel`` from now on (-1: broadcast)."""
        channel = int(channel)
        if _allowed(self._s, channel, "wb_emitter_set_channel"):
            self._s.channel = channel
            self._queue("setChannel", channel)

    @checked("get_range", NAN)
    def getRange(self) -> float:
        """The current range (m, -1: infinite)."""
        return self._s.range

    @checked("set_range")
    def setRange(self, range: float) -> None:
        """Set the range (m), clipped to ``maxRange``; -1 means ``maxRange``."""
        value = float(range)
        if value < 0.0 and value != -1.0:
            _session.error(f"Error: wb_emitter_set_range(): invalid range={value:f} argument.")
            return
        state = self._s
        if value == -1.0 or (state.max_range != -1.0 and value > state.max_range):
            value = state.max_range
        state.range = value
        self._queue("setRange", value)

    buffer_size = property(getBufferSize, doc="The bufferSize field.")
    channel = property(getChannel, setChannel, doc="The channel.")
    range = property(getRange, setRange, doc="The range.")
