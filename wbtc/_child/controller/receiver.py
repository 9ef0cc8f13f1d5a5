"""``Receiver``: a queue of packets received from emitters."""

from __future__ import annotations

import struct

from . import _session
from .device import checked
from .emitter import _allowed
from .sensor import NAN, Sensor

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any


class _Packet:
    __slots__ = ("data", "channel", "signal_strength", "direction")

    def __init__(self, data: bytes, channel: int, signal_strength: float, direction: list[float]) -> None:
        self.data = data
        self.channel = channel
        self.signal_strength = signal_strength
        self.direction = direction


class Receiver(Sensor):
    """A Receiver node: packets arrive at each sample; read the head of the queue, then ``nextPacket()``."""

    _C = "wb_receiver"
    _TYPES = ("Receiver",)

    @staticmethod
    def _setup(state: _session.DeviceState, session: _session.Session) -> None:
        state.queue = []
        state.channel = int(state.field("channel", 0))
        state.buffer_size = int(state.field("bufferSize", -1))

    @staticmethod
    def _absorb(state: _session.DeviceState, value: Any) -> None:
        for item in value or []:
            if isinstance(item, dict):
                item = (item["data"], item.get("channel", -1), item.get("signal_strength", NAN), item["direction"])
            data, channel, strength, direction = item
            packet = _Packet(bytes(data), int(channel), float(strength), [float(v) for v in direction])
            used = sum(len(p.data) for p in state.queue)
            if state.buffer_size == -1 or len(packet.data) <= state.buffer_size - used:
                state.queue.append(packet)

    def _head(self, function: str) -> _Packet | None:
        if self._s.queue:
            return self._s.queue[0]
        _session.error(f"Error: {function}(): the receiver queue is empty.")
        return None

    @checked("get_queue_length", -1)
    def getQueueLength(self) -> int:
        """The number of packets waiting."""
        return len(self._sampled("get_queue_length").queue)

    @checked("next_packet")
    def nextPacket(self) -> None:
        """Drop the head packet (no effect on an empty queue)."""
        if self._s.queue:
            self._s.queue.pop(0)

    @checked("get_data_size", -1)
    def getDataSize(self) -> int:
        """The size in bytes of the head packet (-1 and an error when the queue is empty)."""
        packet = self._head("wb_receiver_get_data_size")
        return -1 if packet is None else len(packet.data)

    @checked("get_data", b"")
    def getBytes(self) -> bytes:
        """The head packet's data as bytes."""
        packet = self._head("wb_receiver_get_data")
        if packet is None:
            self._head("wb_receiver_get_data_size")
            return b""
        return packet.data

    @checked("get_data", "")
    def getString(self) -> str:
        """The head packet's data decoded as UTF-8."""
        packet = self._head("wb_receiver_get_data")
        return "" if packet is None else packet.data.decode()

    def getData(self) -> str | bytes:
        """The head packet: bytes in a world written before R2023b (that release's API), else as ``getString()``.

        Webots R2023b made ``getData`` a deprecated alias of ``getString``; a controller of an older
        world decodes or unpacks the bytes itself (``getData().decode()``, ``struct.unpack``).
        """
        if _session.written_before(_session.require().webots_version, 2023, "b"):
            return self.getBytes()
        _session.error("DEPRECATION: Receiver.getData is deprecated, please use Receiver.getString instead.")
        return self.getString()

    def getFloats(self) -> tuple[float, ...]:
        """The head packet unpacked as native doubles."""
        data = self.getBytes()
        return struct.unpack(f"{len(data) // 8}d", data)

    def getInts(self) -> tuple[int, ...]:
        """The head packet unpacked as native ints."""
        data = self.getBytes()
        return struct.unpack(f"{len(data) // 4}i", data)

    def getBools(self) -> tuple[bool, ...]:
        """The head packet unpacked as bools (one per byte)."""
        data = self.getBytes()
        return struct.unpack(f"{len(data)}?", data)

    @checked("get_signal_strength", NAN)
    def getSignalStrength(self) -> float:
        """The head packet's signal strength (proportional to 1/r²)."""
        packet = self._head("wb_receiver_get_signal_strength")
        return NAN if packet is None else packet.signal_strength

    @checked("get_emitter_direction")
    def getEmitterDirection(self) -> list[float] | None:
        """The unit vector towards the head packet's emitter, in the receiver's frame."""
        packet = self._head("wb_receiver_get_emitter_direction")
        return None if packet is None else list(packet.direction)

    @checked("get_channel", -1)
    def getChannel(self) -> int:
        """The current channel."""
        return self._s.channel

    @checked("set_channel")
    def setChannel(self, channel: int) -> None:
        """Listen on ``channel`` from now on (-1: every channel)."""
        channel = int(channel)
        if channel < -1 or channel != self._s.channel:
            if _allowed(self._s, channel, "wb_receiver_set_channel"):
                self._s.channel = channel
                self._queue("setChannel", channel)

    queue_length = property(getQueueLength, doc="The number of packets waiting.")
    data_size = property(getDataSize, doc="The head packet's size.")
    #: Webots' ``data`` is a ctypes byte pointer (``receiver.data[0:receiver.data_size]``); bytes slice alike.
    data = property(getBytes, doc="The head packet's data as bytes.")
    string = property(getString, doc="The head packet as a str.")
    signal_strength = property(getSignalStrength, doc="The head packet's signal strength.")
    emitter_direction = property(getEmitterDirection, doc="The direction of the head packet's emitter.")
    channel = property(getChannel, setChannel, doc="The channel.")
