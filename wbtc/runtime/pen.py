"""A Pen in the simulator: while it writes, it inks the shape it points at, every step.

Each basic step, a Pen whose `write` is on casts a ray from its origin along its writing direction
(Webots: the node's -z axis; -y in files older than R2022a, whose devices looked along -z with y up)
through the visual shapes, its own body excepted. Where the ray first meets a shape within
`maxDistance` (0: no limit) and that shape is paintable (every Shape of a world with a Pen gets a
texture of its own, Webots' paint layer, an untextured one in its colour: `compile.paintable`),
Webots' stroke is painted into the layer around the hit's texture coordinate (`pen_uv`): a disc
whose diameter is `leadSize` x the image's width (an untextured shape's default layer side) / the
radius of the geometry's bounding sphere, in texels, with `inkDensity` as the stroke's opacity.

Colour conventions: the model's textures hold sRGB bytes (cameras linearise them at upload:
`offscreen`), while Webots lays a paint layer over the texture and blends it in linear light, the ink's
colour taken as it is written (see `Canvas`, whose rules are what Webots' pen test reads). So each
painted texture keeps that layer in floats (`Simulation.canvases`); the shown colour of the painted
texels is written back as sRGB bytes, without rounding piling up stroke after stroke.

Cameras, the window and recordings see the ink once the texture is marked changed
(`Simulation.texture_changed`); infra-red distance sensors read it too, as in Webots.

WorldInfo `inkEvaporation` fades the ink as Webots' does (`evaporate`): before the pens paint, each
step multiplies the coverage of every inked texel by exp(-inkEvaporation x step), until it is below
0.001; the ink keeps its colour.

Not honoured yet: ink on shapes whose texture a Display draws on; a supervisor's recompile of the
world (the textures start again from their images); ink in `animationStartRecording` pages.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import mujoco
import numpy as np

from wbtc.compile.table import DeviceEntry
from wbtc.runtime import pen_uv, tone

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation


class Pen:
    """One Pen device: its ink, whether it writes, and where it paints."""

    def __init__(self, entry: DeviceEntry, sim: Simulation) -> None:
        model = sim.model
        self.entry = entry
        fields = entry.fields
        self.site = model.site(entry.site).id if entry.site else -1
        self.body = int(model.site_bodyid[self.site]) if self.site >= 0 else -1
        self.colour = np.asarray(fields.get("inkColor", [0.0, 0.0, 0.0]), dtype=float)[:3]
        self.density = float(fields.get("inkDensity", 0.5))
        self.lead = max(float(fields.get("leadSize", 0.002)), 0.0)
        self.max_distance = float(fields.get("maxDistance", 0.0))
        self.write = bool(fields.get("write", True))
        # The writing direction is a column of the site's rotation: -z (R2022a on), or -y before.
        self.axis = 1 if entry.legacy_axes else 2
        # Paintable geoms of this model: their textures and stroke scales (compile.paintable), by id.
        self.targets = {model.geom(geom).id: (model.texture(texture).id, scale, zoom, kind)
                        for geom, (texture, scale, zoom, kind) in sim.table.paintable.items()}
        self._triangles: dict[int, pen_uv.Triangles | None] = {}
        self._round: dict[int, tuple[float, float]] = {}  # a Cylinder mesh's radius and half height

    def command(self, op: str, args: tuple) -> None:
        """Apply one command from the controller (`write`, `setInkColor`)."""
        if op == "write":
            self.write = bool(args[0])
        elif op == "setInkColor":
            rgb = int(args[0]) & 0xFFFFFF
            self.colour = np.array([(rgb >> 16) & 0xFF, (rgb >> 8) & 0xFF, rgb & 0xFF], dtype=float) / 255.0
            self.density = min(max(float(args[1]), 0.0), 1.0)

    def paint(self, sim: Simulation) -> None:
        """Ink what the pen points at, if it writes (called once per basic step, after the physics)."""
        if not self.write or self.site < 0 or not self.targets:
            return
        data = sim.data
        start = np.array(data.site_xpos[self.site])
        direction = -np.array(data.site_xmat[self.site].reshape(3, 3)[:, self.axis])
        reach = self.max_distance if self.max_distance > 0 else math.inf
        distance, geom = sim.rays.cast(start, direction, reach, True, frozenset({self.body}), self.body)
        target = self.targets.get(geom)
        if target is None or not math.isfinite(distance):
            return  # nothing within reach, or a shape without a texture of its own: Webots paints nothing
        if target[3] == "Cylinder":
            centre = self._on_cylinder(sim, geom, start, direction)
        else:
            found = self._locate(sim, geom, start, direction)
            centre = None if found is None else pen_uv.texture_point(*found)
        if centre is None:
            return
        if np.any(centre < 0.0) or np.any(centre > 1.0):
            return  # a repeated texture's copy: Webots paints the layer's own coordinates only
        # Webots' stroke: leadSize x image width / bounding radius texels across (at least 1), a disc of
        # half that (both rounded down), in texels of Webots' layer; a layer that repeats the image is
        # `zoom` times finer.
        half = max(int(self.lead * target[1]), 1) // 2
        self._ink(sim, target[0], centre, round(half * target[2]))

    def _locate(self, sim: Simulation, geom: int, start: np.ndarray,
                direction: np.ndarray) -> tuple[pen_uv.Triangles, int, np.ndarray] | None:
        """The hit triangle of paintable mesh geom `geom` and the hit's barycentric weights."""
        model, data = sim.model, sim.data
        mesh = int(model.geom_dataid[geom])
        if model.geom_type[geom] != mujoco.mjtGeom.mjGEOM_MESH or mesh < 0:
            return None
        if mesh not in self._triangles:
            self._triangles[mesh] = pen_uv.triangles(model, mesh)
        tris = self._triangles[mesh]
        if tris is None:
            return None
        # The ray in the geom's frame, where MuJoCo keeps the mesh's vertices.
        rotation = data.geom_xmat[geom].reshape(3, 3)
        origin = rotation.T @ (start - data.geom_xpos[geom])
        hit = pen_uv.locate(tris, origin, rotation.T @ direction)
        if hit is None:
            return None
        return tris, hit[0], hit[1]

    def _on_cylinder(self, sim: Simulation, geom: int, start: np.ndarray, direction: np.ndarray) -> np.ndarray | None:
        """The layer coordinate where the ray meets paintable Cylinder `geom`'s round shape, as Webots picks it."""
        model, data = sim.model, sim.data
        mesh = int(model.geom_dataid[geom])
        if model.geom_type[geom] != mujoco.mjtGeom.mjGEOM_MESH or mesh < 0:
            return None
        # MuJoCo keeps the vertices recentred and turned (v_geom = R^T (v - mesh_pos), R = mesh_quat's
        # rotation); the cylinder's own frame (axis z, centred, scale included) is v = R v_geom + mesh_pos.
        turn = np.zeros(9)
        mujoco.mju_quat2Mat(turn, model.mesh_quat[mesh])
        turn = turn.reshape(3, 3)
        shift = np.array(model.mesh_pos[mesh], dtype=float)
        if mesh not in self._round:
            adr, count = int(model.mesh_vertadr[mesh]), int(model.mesh_vertnum[mesh])
            own = model.mesh_vert[adr:adr + count].astype(float) @ turn.T + shift
            self._round[mesh] = (float(np.hypot(own[:, 0], own[:, 1]).max()), float(np.abs(own[:, 2]).max()))
        radius, half_height = self._round[mesh]
        rotation = data.geom_xmat[geom].reshape(3, 3)
        origin = turn @ (rotation.T @ (start - data.geom_xpos[geom])) + shift
        return pen_uv.cylinder_point(origin, turn @ (rotation.T @ direction), radius, half_height)

    def _ink(self, sim: Simulation, texture: int, centre: np.ndarray, half: int) -> None:
        """Lay the ink on the texels under the lead and mark the texture changed."""
        pixels = _pixels(sim, texture)
        height, width = pixels.shape[:2]
        canvas = sim.canvases.get(texture)
        if canvas is None:  # made at the texture's first stroke
            canvas = sim.canvases[texture] = Canvas(pixels[..., :3])
        rows, cols = pen_uv.lead_texels(centre, half, width, height)
        _show(sim, texture, rows, cols, canvas.lay(rows, cols, self.colour, self.density))


def _pixels(sim: Simulation, texture: int) -> np.ndarray:
    """The model's bytes of `texture` as (rows, columns, channels), a view."""
    model = sim.model
    width, height = int(model.tex_width[texture]), int(model.tex_height[texture])
    channels = int(model.tex_nchannel[texture])
    adr = int(model.tex_adr[texture])
    return model.tex_data[adr:adr + width * height * channels].reshape(height, width, channels)


def _show(sim: Simulation, texture: int, rows: np.ndarray, cols: np.ndarray, shown: np.ndarray) -> None:
    """Write texels' shown linear colours into the model's texture as sRGB bytes; renderers upload it again."""
    _pixels(sim, texture)[rows, cols, :3] = np.rint(tone.srgb(shown) * 255.0).astype(np.uint8)
    sim.texture_changed(texture)


def evaporate(sim: Simulation) -> None:
    """Fade every pen's ink by one basic step of WorldInfo.inkEvaporation (nothing when it is 0)."""
    rate = float(getattr(sim.table, "ink_evaporation", 0.0))
    if rate <= 0.0 or not sim.canvases:
        return
    factor = math.exp(-rate * sim.step_ms / 1000.0)
    for texture, canvas in sim.canvases.items():
        faded = canvas.fade(factor)
        if faded is not None:
            _show(sim, texture, *faded)


class Canvas:
    """Webots' paint layer over one texture: the ink's colour and coverage per texel, in floats.

    The layer lies over the texture's own colours: shown = texture · (1 − coverage) + ink · coverage, in
    linear light. A stroke of density d adds d to the coverage (at most 1), and its colour mixes with
    the ink already there, weighted by coverage and density:

        ink' = (ink · coverage + stroke · d) / (coverage + d)
        coverage' = min(coverage + d, 1)

    These are the rules Webots' pen test reads: density-0.1 red strokes over white leave 0.9, 0.8,
    0.7, 0.6 of the linear green after one to four strokes (its camera reads 201, 195, 189, 178) and
    none after ten (0); a density-1 purple stroke over density-1 green shows their mean (154, 178, 167).
    The stroke's colour enters as written, without the sRGB decoding textures get: a 0xFA8A0A stroke
    reads (206, 171, 58) in Webots' camera, the tone curve of (250, 138, 10) / 255 taken as linear.
    """

    def __init__(self, srgb: np.ndarray) -> None:
        self.base = tone.linear(srgb / 255.0).astype(np.float32)  # the texture's own linear colours
        self.original_red = (srgb[..., 0] / 255.0).astype(np.float32)  # as written, for infra-red (`surface`)
        self.ink = np.zeros_like(self.base)
        self.coverage = np.zeros(self.base.shape[:2], dtype=np.float32)

    def lay(self, rows: np.ndarray, cols: np.ndarray, colour: np.ndarray, density: float) -> np.ndarray:
        """One stroke of `colour` (0-1, as written) at `density` on some texels; returns their shown linear colour."""
        coverage = self.coverage[rows, cols][:, None]
        weight = coverage + density
        mixed = np.where(weight > 0, (self.ink[rows, cols] * coverage + colour * density) / np.maximum(weight, 1e-12),
                         colour)
        coverage = np.minimum(weight, 1.0)
        self.ink[rows, cols] = mixed
        self.coverage[rows, cols] = coverage[:, 0]
        return self.base[rows, cols] * (1.0 - coverage) + mixed * coverage

    def fade(self, factor: float) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
        """Multiply the coverage of the texels still inked (above 0.001) by `factor`.

        Returns:
            The faded texels' rows, columns and shown linear colours, or None when none was left.
        """
        rows, cols = np.nonzero(self.coverage > 0.001)
        if not len(rows):
            return None
        coverage = self.coverage[rows, cols] * np.float32(factor)
        self.coverage[rows, cols] = coverage
        cover = coverage[:, None]
        return rows, cols, self.base[rows, cols] * (1.0 - cover) + self.ink[rows, cols] * cover

