"""Devices that are not plain sampled sensors: LEDs, cameras, emitters and receivers, and their wiring.

- LED: `set(v)` lights the LED's shapes: 0 is off (their own colour), 1..n picks `color[v−1]`
  (non-gradual), a gradual LED with one colour scales it by v/255, one with no colour reads v as
  0xRRGGBB.
- Camera: rendered by MuJoCo offscreen from the device camera (shadows and reflections off) and
  sent as BGRA bytes, rows from the top.
- Emitter/Receiver: packets sent during a step reach the receivers on the same channel (−1 on
  either side: every channel) within `range` at the next basic step; radio ignores obstacles,
  infra-red needs a line of sight. Receivers queue them until their next sample.

Not honoured yet: Emitter `aperture`, `baudRate`, `byteSize`, `bufferSize`; Receiver noise
fields; Camera noise, recognition and `exposure`; serial emitters (treated as radio).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import mujoco
import numpy as np

from wbtc.compile.table import DeviceEntry
from wbtc.runtime.sensors import Sensor

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation


class Led:
    """An LED's colour state."""

    def __init__(self, entry: DeviceEntry, model: mujoco.MjModel) -> None:
        self.entry = entry
        self.geoms = [model.geom(name).id for name in entry.geoms]
        self.rgba = {g: model.geom_rgba[g].copy() for g in self.geoms}
        self.matid = {g: int(model.geom_matid[g]) for g in self.geoms}
        self.colors = [list(c) for c in entry.fields.get("color", [[1, 0, 0]])]
        self.gradual = bool(entry.fields.get("gradual", False))
        self.value = 0

    def set(self, value: int, model: mujoco.MjModel) -> None:
        """Light the LED's shapes for `value` (see the module docstring)."""
        self.value = int(value)
        colour = self.colour()
        for g in self.geoms:
            if colour is None:
                model.geom_rgba[g] = self.rgba[g]
                model.geom_matid[g] = self.matid[g]
            else:
                model.geom_rgba[g] = [*colour, 1.0]
                model.geom_matid[g] = -1  # a lit LED shows its own colour, not its material's

    def colour(self) -> list[float] | None:
        """The lit colour, or None when off."""
        v = self.value
        if v <= 0:
            return None
        if not self.gradual:
            return self.colors[v - 1] if v <= len(self.colors) else None
        if len(self.colors) == 1:
            return [c * min(v, 255) / 255 for c in self.colors[0]]
        return [((v >> 16) & 255) / 255, ((v >> 8) & 255) / 255, (v & 255) / 255]


class Camera(Sensor):
    """A Camera rendered by MuJoCo."""

    def __init__(self, entry: DeviceEntry, sim: Simulation, skip_bodies: frozenset[int]) -> None:
        super().__init__(entry, sim, skip_bodies)
        self.width = int(entry.fields.get("width", 64))
        self.height = int(entry.fields.get("height", 64))
        self.camera = sim.model.camera(entry.camera).id

    def sample(self, sim: Simulation) -> dict[str, Any]:
        """The image as BGRA bytes."""
        rgb = sim.render(self.camera, self.width, self.height)
        bgra = np.empty((self.height, self.width, 4), dtype=np.uint8)
        bgra[..., 0], bgra[..., 1], bgra[..., 2], bgra[..., 3] = rgb[..., 2], rgb[..., 1], rgb[..., 0], 255
        return {"shm": None, "data": bgra.tobytes(), "width": self.width, "height": self.height}


class Receiver(Sensor):
    """A Receiver: packets arrive continuously, the controller gets them at each sample."""

    def __init__(self, entry: DeviceEntry, sim: Simulation, skip_bodies: frozenset[int]) -> None:
        super().__init__(entry, sim, skip_bodies)
        self.channel = int(entry.fields.get("channel", 0))
        self.kind = str(entry.fields.get("type", "radio"))
        self.incoming: list[tuple] = []

    def sample(self, sim: Simulation) -> list[tuple]:
        """Packets received since the last sample."""
        packets, self.incoming = self.incoming, []
        return packets


class Emitter:
    """An Emitter's channel and range."""

    def __init__(self, entry: DeviceEntry, model: mujoco.MjModel) -> None:
        self.entry = entry
        self.site = model.site(entry.site).id
        self.channel = int(entry.fields.get("channel", 0))
        self.range = float(entry.fields.get("range", -1))
        self.kind = str(entry.fields.get("type", "radio"))


def deliver(sim: Simulation, packets: list[tuple[Emitter, bytes]], receivers: list[Receiver]) -> None:
    """Hand the packets sent during the last step to every receiver that can hear them."""
    for emitter, data in packets:
        origin = sim.data.site_xpos[emitter.site].copy()
        for receiver in receivers:
            if receiver.period <= 0 or receiver.site == emitter.site:
                continue
            if -1 not in (emitter.channel, receiver.channel) and emitter.channel != receiver.channel:
                continue
            pos, mat = receiver.frame(sim)
            delta = origin - pos
            dist = float(np.linalg.norm(delta))
            if emitter.range >= 0 and dist > emitter.range:
                continue
            direction = delta / dist if dist > 0 else np.array([1.0, 0.0, 0.0])
            if "infra-red" in (emitter.kind, receiver.kind):
                hit, _ = sim.rays.cast(pos, direction, dist, False, receiver.skip_bodies)
                if hit < dist - 1e-3:
                    continue
            strength = 1.0 / (dist * dist) if dist > 0 else math.inf
            receiver.incoming.append((data, emitter.channel, strength, [float(c) for c in mat.T @ direction]))
