"""Devices that are not plain sampled sensors: LEDs, cameras, emitters and receivers, and their wiring.

- LED: `set(v)` lights the LED's shapes: 0 is off (their own colour), 1..n picks `color[v−1]`
  (non-gradual), a gradual LED with one colour scales it by v/255, one with no colour reads v as
  0xRRGGBB.
- Camera: rendered by MuJoCo offscreen from the device camera (see `offscreen`) at the Camera's
  `near`, into a BGRA image (rows from the top) in a shared-memory block of its own that the
  controller reads (`{"shm": name}`); a new block, under a new name, when the size changes; plain
  bytes in the message when shared memory is unavailable. `Simulation.close` unlinks the blocks.
  `noise` adds Gaussian noise of σ = noise × 255 to every channel (none with noise off). With a
  Recognition node, `recognitionEnable(p)` adds `"objects"` to a sample every p ms (see `recognition`),
  with `"has_segmentation"` (the node's `segmentation` field) and, once the controller enabled it,
  the `"segmentation"` image (see `segmentation`).
- Emitter/Receiver: packets sent during a step reach the receivers of the same type (radio,
  serial, infra-red) on the same channel (−1 on either side: every channel), on other robots,
  within `range` at the next basic step; radio ignores obstacles,
  infra-red needs a line of sight and each end within the other's `aperture` cone. Receivers
  queue them until their next sample.

Not honoured yet: Emitter `baudRate`, `byteSize`, `bufferSize`; Receiver noise
fields; Camera `noiseMaskUrl`, `lens`, `lensFlare`, `bloomThreshold` (see `camera_effects` for Focus and
motionBlur, `recognition` and `segmentation` for the rest);
serial emitters (treated as radio).
"""

from __future__ import annotations

import math
import weakref
from multiprocessing import shared_memory
from typing import TYPE_CHECKING, Any

import mujoco
import numpy as np

from wbtc.compile.device import led_material
from wbtc.compile.light import MATERIAL_AMBIENT
from wbtc.compile.table import DeviceEntry, plain_fields
from wbtc.runtime import camera_effects, segmentation, tone
from wbtc.runtime.camera_projection import Optics
from wbtc.runtime.recognition import Settings, Target, recognize, targets
from wbtc.runtime.sensors import Sensor
from wbtc.scene.model import Node

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation


def _material_names(model: mujoco.MjModel) -> set[str]:
    return {model.material(i).name for i in range(model.nmat)}


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
        self.lights = [(model.light(name).id, intensity, ambient) for name, intensity, ambient in entry.lights]
        lit = led_material(entry)
        self.lit = model.material(lit).id if self.geoms and lit in _material_names(model) else -1

    def set(self, value: int, model: mujoco.MjModel) -> None:
        """Light the LED's shapes for `value` (see the module docstring)."""
        self.value = int(value)
        colour = self.colour()
        for g in self.geoms:
            if colour is None:
                model.geom_rgba[g] = self.rgba[g]
                model.geom_matid[g] = self.matid[g]
            else:
                # A lit LED glows in its colour (Webots' emissiveColor), not in its material's.
                model.geom_rgba[g] = [*colour, 1.0]
                model.geom_matid[g] = self.lit
                if self.lit >= 0:
                    model.mat_rgba[self.lit] = [*colour, 1.0]
        self._light_up(colour, model)

    def _light_up(self, colour: list[float] | None, model: mujoco.MjModel) -> None:
        """Webots switches an LED's lights on in its colour (their `color` field), and off with it."""
        for light, intensity, ambient in self.lights:
            model.light_active[light] = colour is not None
            if colour is not None:
                rgb = np.asarray(colour, dtype=float)
                model.light_diffuse[light] = rgb * intensity
                model.light_specular[light] = rgb * intensity * 0.3
                model.light_ambient[light] = np.clip(rgb * ambient * MATERIAL_AMBIENT, 0.0, 1.0)

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
    """A Camera rendered by MuJoCo into a shared-memory BGRA image, with optional object recognition.

    `period`/`next_due` are the image's; recognition has its own (`recognition_period`,
    `recognition_due`). The camera ticks while either is on (`period` reads the image period, else
    the recognition one) and a sample carries whichever is due: the image, `"objects"`, or both.
    """

    def __init__(self, entry: DeviceEntry, sim: Simulation, skip_bodies: frozenset[int]) -> None:
        self.image_period = 0
        self.recognition_period = 0
        self.recognition_due = math.inf
        self.segmentation_enabled = False
        super().__init__(entry, sim, skip_bodies)
        self.sim = sim
        self.width = int(entry.fields.get("width", 64))
        self.height = int(entry.fields.get("height", 64))
        self.near = float(entry.fields.get("near", 0.01))
        self.fov = float(entry.fields.get("fieldOfView", 0.785398))
        self.noise = float(entry.fields.get("noise", 0.0))
        self.exposure = float(entry.fields.get("exposure", 1.0))
        self.motion_blur = float(entry.fields.get("motionBlur", 0.0))
        self._blurred: np.ndarray | None = None  # the last image's linear levels, with motion blur
        focus = entry.node.get("focus") if entry.node is not None else None
        self.focus = (float(focus.get("focalDistance")), float(focus.get("focalLength"))) \
            if isinstance(focus, Node) else (0.0, 0.0)
        # Before R2023a a `spherical TRUE` Camera was what `projection "cylindrical"` is now.
        projection = str(entry.fields.get("projection", "planar"))
        self.projection = "cylindrical" if entry.fields.get("spherical") and projection == "planar" else projection
        self.camera = sim.model.camera(entry.camera).id
        recognition = entry.node.get("recognition") if entry.node is not None else None
        self.recognition = Settings.of(plain_fields(recognition)) if isinstance(recognition, Node) else None
        self._targets: list[Target] | None = None
        self._targets_model: Any = None
        self._colours: tuple[Any, np.ndarray] | None = None  # (model, segmentation colour of each geom)
        self.block: shared_memory.SharedMemory | None = None
        self.pixels: np.ndarray | None = None  # (height, width, 4) BGRA, over the block when there is one
        self._finalizer: weakref.finalize | None = None
        self.use_shared = True

    @property
    def period(self) -> int:  # type: ignore[override]
        """The image period, else the recognition period (what makes the simulation tick the camera)."""
        return self.image_period or self.recognition_period

    @period.setter
    def period(self, value: int) -> None:
        self.image_period = int(value)

    @property
    def value(self) -> Any:
        """The last sample (what the next step reply sends)."""
        return self._value

    @value.setter
    def value(self, value: Any) -> None:
        # A sample naming another camera's block (carried over from a camera this one replaces) is
        # dropped: that block may be gone; the controller keeps its last image until the next sample.
        if isinstance(value, dict) and value.get("shm") and (self.block is None or value["shm"] != self.block.name):
            value = {**value, "shm": None, "data": None}
        self._value = value

    def command(self, op: str, args: tuple) -> None:
        """Recognition on/off, the field of view and the exposure (the controller has checked the values)."""
        if op == "recognitionEnable" and self.recognition is not None:
            self.recognition_period = max(int(args[0]), 0)
            now = self.sim.time_ms
            self.recognition_due = now + self.recognition_period if self.recognition_period > 0 else math.inf
        elif op == "recognitionDisable":
            self.recognition_period, self.recognition_due = 0, math.inf
        elif op in ("enableSegmentation", "disableSegmentation"):
            self.segmentation_enabled = op == "enableSegmentation"
        elif op == "setExposure":
            self.exposure = float(args[0])
        elif op == "setFocalDistance":
            self.focus = (float(args[0]), self.focus[1])
        elif op == "setFov":
            self.fov = float(args[0])
            fovy = 2 * math.atan(math.tan(self.fov / 2) * self.height / max(self.width, 1))
            self.sim.model.cam_fovy[self.camera] = math.degrees(fovy)

    def tick(self, sim: Simulation, now_ms: float) -> None:
        """Render and/or recognize when due; both land in one value until the reply takes it."""
        value: dict[str, Any] | None = None
        if self.image_period > 0 and now_ms + 1e-9 >= self.next_due:
            value = self.sample(sim)
            self.next_due += self.image_period
        if self.recognition_period > 0 and now_ms + 1e-9 >= self.recognition_due:
            base = value or {"shm": None, "data": None, "width": self.width, "height": self.height}
            value = {**base, "objects": self.recognize(sim), **self.segment(sim)}
            self.recognition_due += self.recognition_period
        if value is None:
            return
        if self.fresh and isinstance(self._value, dict):  # not sent yet: keep what this sample does not renew
            value = {**self._value, **{k: v for k, v in value.items() if v is not None}}
        self.value = value
        self.fresh = True

    def recognize(self, sim: Simulation) -> list[dict[str, Any]]:
        """The recognition objects seen now (see `recognition`)."""
        if self.recognition is None:
            return []
        if self._targets is None or self._targets_model is not sim.model:
            self._targets, self._targets_model = targets(sim), sim.model
        pos, mat = self.frame(sim)
        return recognize(sim, self._targets, np.asarray(pos), mat, self.optics(), self.recognition, self.skip_bodies)

    def segment(self, sim: Simulation) -> dict[str, Any]:
        """Whether the Recognition node has `segmentation` on, and the segmentation image when it is asked for.

        Webots turns the segmentation off when the field goes FALSE; the image (BGRA bytes) travels in
        the message.
        """
        allowed = self.recognition is not None and self.recognition.segmentation
        self.segmentation_enabled = self.segmentation_enabled and allowed
        if not self.segmentation_enabled:
            return {"has_segmentation": allowed}
        if self._colours is None or self._colours[0] is not sim.model:
            self._colours = (sim.model, segmentation.geom_colours(sim.model, getattr(sim.table, "recognizable", [])))
        pos, mat = self.frame(sim)
        image = segmentation.render(sim, np.asarray(pos), mat, self.optics(), self._colours[1])
        return {"has_segmentation": True, "segmentation": image.tobytes()}

    def optics(self) -> Optics:
        """The camera's image geometry."""
        return Optics(self.fov, self.width, self.height, self.projection)

    def sample(self, sim: Simulation) -> dict[str, Any]:
        """Render into the BGRA image (with Gaussian noise); the value names the block (or carries the bytes)."""
        renderer = sim.renderer(self.width, self.height, precise=True)
        blurs = self.motion_blur > 0 and self.image_period > 0
        focuses = self.focus[0] > 0 and self.focus[1] > 0
        if blurs or focuses:  # Webots' effects work in linear light, before its tone curve
            levels = renderer.draw(sim.data, self.camera, self.near, spots=sim.laser_spots(), exposure=None)
            levels = camera_effects.unclip(levels)
            if focuses:
                levels = camera_effects.depth_of_field(levels, renderer.last_depth(), *self.focus)
            if blurs:
                levels = self._blurred = camera_effects.motion_blur(levels, self._blurred, self.image_period,
                                                                    self.motion_blur)
            rgb = tone.map_levels(levels, self.exposure)
        else:
            rgb = renderer.draw(sim.data, self.camera, self.near, spots=sim.laser_spots(), exposure=self.exposure)
        pixels = self._image()
        if self.noise > 0 and sim.noise_rng is not None:
            # Webots: σ = noise × 255 on every channel, independently per pixel and per sample.
            noisy = rgb[::-1, :, ::-1] + sim.noise_rng.normal(0.0, self.noise * 255.0, rgb.shape)
            np.copyto(pixels[:, :, :3], np.clip(np.rint(noisy), 0, 255).astype(np.uint8))
        else:
            np.copyto(pixels[:, :, :3], rgb[::-1, :, ::-1])  # rows from the top, RGB to BGR
        if self.block is not None:
            return {"shm": self.block.name, "data": None, "width": self.width, "height": self.height}
        return {"shm": None, "data": pixels.tobytes(), "width": self.width, "height": self.height}

    def _image(self) -> np.ndarray:
        """The BGRA image buffer for the current size (alpha 255), in shared memory when possible."""
        shape = (self.height, self.width, 4)
        if self.pixels is not None and self.pixels.shape == shape:
            return self.pixels
        self.release()
        if self.use_shared:
            try:
                self.block = shared_memory.SharedMemory(create=True, size=4 * self.width * self.height)
            except OSError:  # no /dev/shm (or it is full): send the pixels in the messages
                self.use_shared = False
        if self.block is not None:
            self._finalizer = weakref.finalize(self, _unlink, self.block)
            self.pixels = np.ndarray(shape, dtype=np.uint8, buffer=self.block.buf)
        else:
            self.pixels = np.empty(shape, dtype=np.uint8)
        self.pixels[:, :, 3] = 255
        return self.pixels

    def release(self) -> None:
        """Unlink the shared-memory block (a later sample makes a new one)."""
        self.pixels = None
        if self._finalizer is not None:
            self._finalizer()
            self._finalizer = None
        self.block = None


def _unlink(block: shared_memory.SharedMemory) -> None:
    try:
        block.close()
    except BufferError:  # a view is still exported; the mapping goes with the process
        pass
    try:
        block.unlink()
    except FileNotFoundError:
        pass


class Receiver(Sensor):
    """A Receiver: packets arrive continuously, the controller gets them at each sample."""

    def __init__(self, entry: DeviceEntry, sim: Simulation, skip_bodies: frozenset[int]) -> None:
        super().__init__(entry, sim, skip_bodies)
        self.channel = int(entry.fields.get("channel", 0))
        self.kind = str(entry.fields.get("type", "radio"))
        self.aperture = float(entry.fields.get("aperture", -1))
        self.owner: int | None = None  # id of the robot's table entry, set by the simulation (no delivery to oneself)
        self.incoming: list[tuple] = []

    def sample(self, sim: Simulation) -> list[tuple]:
        """Packets received since the last sample."""
        packets, self.incoming = self.incoming, []
        return packets

    def tick(self, sim: Simulation, now_ms: float) -> None:
        """Sample when due; samples not sent to the controller yet add up.

        Webots queues every packet, so a `step(3 × basicTimeStep)` brings the packets of all three periods.
        """
        if now_ms + 1e-9 >= self.next_due:
            packets = self.sample(sim)
            self.value = self.value + packets if self.fresh and isinstance(self.value, list) else packets
            self.fresh = True
            self.next_due += self.period


class Emitter:
    """An Emitter's channel and range."""

    def __init__(self, entry: DeviceEntry, model: mujoco.MjModel) -> None:
        self.entry = entry
        self.site = model.site(entry.site).id
        self.channel = int(entry.fields.get("channel", 0))
        self.range = float(entry.fields.get("range", -1))
        self.kind = str(entry.fields.get("type", "radio"))
        self.aperture = float(entry.fields.get("aperture", -1))
        self.owner: int | None = None  # id of the robot's table entry, set by the simulation (no delivery to oneself)
        self.bodies: frozenset[int] = frozenset()  # its robot's bodies, set by the simulation (see `deliver`)


def _outside_cone(axis: np.ndarray, direction: np.ndarray, aperture: float) -> bool:
    """True when `direction` leaves a cone of full angle `aperture` (-1: no cone) around `axis`."""
    if aperture < 0:
        return False
    return float(np.dot(axis, direction)) < math.cos(aperture / 2.0) - 1e-12


def deliver(sim: Simulation, packets: list[tuple[Emitter, bytes, int]], receivers: list[Receiver]) -> None:
    """Hand the packets sent during the last step to every receiver that can hear them.

    Each packet goes out on the channel its emitter had when `send()` was called (a controller
    may change channels between two sends of one step, as Webots allows).
    """
    for emitter, data, channel in packets:
        origin = sim.data.site_xpos[emitter.site].copy()
        for receiver in receivers:
            same_robot = receiver.owner is not None and receiver.owner == emitter.owner
            if receiver.period <= 0 or receiver.site == emitter.site or same_robot:
                continue  # disabled, or on the emitter's own robot: Webots never delivers those
            if receiver.kind != emitter.kind:
                continue  # radio, serial and infra-red devices only talk to their own kind
            if -1 not in (channel, receiver.channel) and channel != receiver.channel:
                continue
            pos, mat = receiver.frame(sim)
            delta = origin - pos
            dist = float(np.linalg.norm(delta))
            if emitter.range >= 0 and dist > emitter.range:
                continue
            direction = delta / dist if dist > 0 else np.array([1.0, 0.0, 0.0])
            if emitter.kind == "infra-red":
                # Infra-red: the receiver must be in the emitter's cone, the emitter in the receiver's
                # (both around their +x axis), and nothing in between.
                emitter_axis = sim.data.site_xmat[emitter.site].reshape(3, 3)[:, 0]
                if _outside_cone(emitter_axis, -direction, emitter.aperture) or \
                        _outside_cone(mat[:, 0], direction, receiver.aperture):
                    continue
                # Neither robot blocks its own device: an emitter inside its robot's body still sends.
                hit, _ = sim.rays.cast(pos, direction, dist, False, receiver.skip_bodies | emitter.bodies)
                if hit < dist - 1e-3:
                    continue
            strength = 1.0 / (dist * dist) if dist > 0 else math.inf
            receiver.incoming.append((data, channel, strength, [float(c) for c in mat.T @ direction]))
