"""`animationStartRecording`: one self-contained HTML page that plays the run back in a browser.

Webots writes an .html page that loads its web viewer from cyberbotics.com and plays a recorded
scene. wbtc writes a single .html file that needs no network: the scene's visual geoms (MuJoCo's
primitives and meshes, with their colours), the pose of every body that carries one at each frame
(only the poses that changed), LED colour changes and supervisor labels, and a small WebGL player
(`player/animation.js`: orbit, pan, zoom, play/pause, time slider) that draws them. Frames are taken
every basic time step, or every few steps so that they come at most 60 times a simulated second.
Poses are in the model's frame (ENU, z up), whatever the world's own axes. `wbtc run --record
FILE.html` writes the same page for a whole run (`PageRecorder`).

Textured planes, boxes and meshes carry their texture (see `animation_textures`); other textured
geoms show the texture's mean colour.

Not honoured yet: the scene's lights (the player lights from the camera, with an ambient term),
height fields, bodies a supervisor adds after the recording started (the ones it started with are
followed by name).
"""

from __future__ import annotations

import contextlib
import json
import math
import os
from importlib import resources
from pathlib import Path
from typing import TYPE_CHECKING, Any

import mujoco
import numpy as np

from wbtc.compile.context import VISUAL_GROUP
from wbtc.errors import WbtcError
from wbtc.runtime.animation_textures import Textures, mesh_uv

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation

_KINDS = {
    mujoco.mjtGeom.mjGEOM_PLANE: "plane", mujoco.mjtGeom.mjGEOM_SPHERE: "sphere",
    mujoco.mjtGeom.mjGEOM_CAPSULE: "capsule", mujoco.mjtGeom.mjGEOM_ELLIPSOID: "ellipsoid",
    mujoco.mjtGeom.mjGEOM_CYLINDER: "cylinder", mujoco.mjtGeom.mjGEOM_BOX: "box",
    mujoco.mjtGeom.mjGEOM_MESH: "mesh",
}
#: MuJoCo's default geom colour: a geom that has it shows its material's colour instead.
_DEFAULT_RGBA = (0.5, 0.5, 0.5, 1.0)
_MAX_FPS = 60.0


class AnimationRecorder:
    """Collects a run's frames from `start` on and writes the HTML page at `close`."""

    def __init__(self, sim: Simulation, path: Path) -> None:
        self.path = Path(path)
        self.period_ms = sim.step_ms * max(1, math.ceil(1000.0 / _MAX_FPS / sim.step_ms - 1e-9))
        self.start_ms = sim.time_ms
        self.due_ms = sim.time_ms
        self.scene = _scene(sim)
        self.geoms = [int(g) for g in self.scene.pop("geom_ids")]
        self.textured = {g for g, entry in zip(self.geoms, self.scene["geoms"], strict=True) if "texture" in entry}
        self.names: list[str] = self.scene["bodies"]
        self.generation = sim.generation
        self.ids = [sim.model.body(name).id for name in self.names]
        self.frames: list[dict[str, Any]] = []
        self.last_poses: dict[int, list[float]] = {}
        # What the run changes is a geom's own rgba (LEDs); materials stay. Frames compare those raw
        # values and resolve the drawn colour (material, texture mean) only for the geoms that changed.
        self.raw_rgba = np.array(sim.model.geom_rgba[self.geoms])
        self.last_labels: dict[str, list] = {}
        self(sim)

    def __call__(self, sim: Simulation, last: bool = False) -> None:
        """Take a frame when one is due (call after every step); `last`: now, unless one was just taken."""
        if last:
            if self.frames and self.frames[-1]["t"] >= round((sim.time_ms - self.start_ms) / 1000.0, 6):
                return
        elif sim.time_ms + 1e-9 < self.due_ms:
            return
        else:
            self.due_ms += self.period_ms
        if sim.generation != self.generation:
            self._follow(sim)
        frame: dict[str, Any] = {"t": round((sim.time_ms - self.start_ms) / 1000.0, 6), "p": self._poses(sim)}
        colours = self._colours(sim)
        if colours:
            frame["c"] = colours
        labels = {str(k): [str(v[0]), float(v[1]), float(v[2]), float(v[3]), f"#{int(v[4]) & 0xFFFFFF:06x}",
                           float(v[5])] for k, v in sorted(sim.labels.items())}
        if labels != self.last_labels:
            frame["l"], self.last_labels = labels, labels
        self.frames.append(frame)

    def _follow(self, sim: Simulation) -> None:
        """After a recompile, find the recorded bodies again by name (-1: gone)."""
        ids = []
        for name in self.names:
            try:
                ids.append(sim.model.body(name).id)
            except KeyError:
                ids.append(-1)
        self.ids, self.generation = ids, sim.generation
        self.geoms = [-1] * len(self.geoms)  # geom ids changed too: colours are no longer followed

    def _poses(self, sim: Simulation) -> list[list[float]]:
        changed = []
        for index, body in enumerate(self.ids):
            if body < 0:
                continue
            pose = [round(float(v), 5) for v in (*sim.data.xpos[body], *sim.data.xquat[body])]
            if self.last_poses.get(index) != pose:
                self.last_poses[index] = pose
                changed.append([index, *pose])
        return changed

    def _colours(self, sim: Simulation) -> list[list[float]]:
        if not self.geoms or self.geoms[0] < 0:  # no geoms, or no longer followed (see _follow)
            return []
        current = sim.model.geom_rgba[self.geoms]
        changed = []
        for index in np.flatnonzero(np.abs(current - self.raw_rgba).max(axis=1) > 1e-4):
            self.raw_rgba[index] = current[index]
            geom = self.geoms[index]
            rgba = _rgba(sim.model, geom, geom in self.textured)
            changed.append([int(index), *(round(float(v), 4) for v in rgba)])
        return changed

    def close(self) -> None:
        """Write the page (atomically: a reader never sees half of it)."""
        data = dict(self.scene, frames=self.frames, duration=self.frames[-1]["t"] if self.frames else 0.0)
        page = _page(data, self.path.stem)
        temp = self.path.with_name(f".{self.path.name}.part")
        temp.write_text(page, encoding="utf-8")
        os.replace(temp, self.path)


class PageRecorder:
    """`wbtc run --record FILE.html`: the whole run as an animation page (a `RunOptions.on_step` hook)."""

    def __init__(self, sim: Simulation, path: Path) -> None:
        """Start recording at the world's first state.

        Raises:
            WbtcError: the page's folder does not exist.
        """
        if not path.parent.is_dir():
            raise WbtcError(f"--record: cannot write {path}: its folder does not exist")
        self.path, self.sim = path, sim
        self.recorder = AnimationRecorder(sim, path)

    def __call__(self, sim: Simulation) -> bool:
        """After each basic step: take a frame when one is due (the run goes on)."""
        self.recorder(sim)
        return True

    def close(self) -> None:
        """Write the page, ending with the run's last state (an aborted run writes nothing)."""
        try:
            self.recorder(self.sim, last=True)
            self.recorder.close()
        except OSError as exc:
            with contextlib.suppress(OSError):
                self.path.with_name(f".{self.path.name}.part").unlink()
            raise WbtcError(f"--record: cannot write {self.path}: {exc.strerror or exc}") from None

    def abort(self) -> None:
        """Nothing to drop: the page is only written by `close`."""


def _scene(sim: Simulation) -> dict[str, Any]:
    """The visual geoms, the bodies carrying them, the meshes and the Viewpoint camera."""
    model = sim.model
    bodies: dict[int, int] = {}
    geoms, geom_ids, meshes = [], [], {}
    textures = Textures(model)
    for g in range(model.ngeom):
        kind = _KINDS.get(int(model.geom_type[g]))
        if int(model.geom_group[g]) != VISUAL_GROUP or kind is None:
            continue
        texture = textures.describe(g)
        rgba = _rgba(model, g, texture is not None)
        if rgba[3] <= 0:
            continue
        body = int(model.geom_bodyid[g])
        entry: dict[str, Any] = {
            "type": kind, "body": bodies.setdefault(body, len(bodies)),
            "size": [round(float(v), 6) for v in model.geom_size[g]],
            "pos": [round(float(v), 6) for v in model.geom_pos[g]],
            "quat": [round(float(v), 6) for v in model.geom_quat[g]],
            "rgba": [round(float(v), 4) for v in rgba],
        }
        if texture is not None:
            entry["texture"] = texture
        if kind == "mesh":
            mesh = int(model.geom_dataid[g])
            entry["mesh"] = meshes.setdefault(mesh, len(meshes))
        geoms.append(entry)
        geom_ids.append(g)
    return {
        "format": "wbtc-animation-1",
        "basicTimeStep": sim.step_ms,
        "bodies": [model.body(b).name for b in bodies],
        "geoms": geoms,
        "geom_ids": geom_ids,
        "meshes": [_mesh(model, m) for m in sorted(meshes, key=meshes.get)],
        "textures": textures.urls,
        "camera": _camera(sim),
        "background": [round(float(v), 4) for v in model.vis.rgba.haze[:3]],
    }


def _rgba(model: mujoco.MjModel, geom: int, textured: bool = False) -> np.ndarray:
    """The colour a geom is drawn with, as MuJoCo draws it.

    Its own colour, unless that is the default and it has a material (then the material's); times the
    material's texture, here its mean colour unless the player draws the texture itself (`textured`).
    """
    rgba = np.array(model.geom_rgba[geom], dtype=float)
    mat = int(model.geom_matid[geom])
    if mat < 0:
        return rgba
    if np.allclose(rgba, _DEFAULT_RGBA):
        rgba = np.array(model.mat_rgba[mat], dtype=float)
    tex = int(model.mat_texid[mat, int(mujoco.mjtTextureRole.mjTEXROLE_RGB)])
    if tex >= 0 and not textured:
        adr, channels = int(model.tex_adr[tex]), int(model.tex_nchannel[tex])
        size = int(model.tex_width[tex]) * int(model.tex_height[tex]) * channels
        texels = np.asarray(model.tex_data[adr:adr + size], dtype=float).reshape(-1, channels)
        rgba[:3] *= texels[:, :3].mean(axis=0) / 255.0 if channels >= 3 else texels[:, 0].mean() / 255.0
    return rgba


def _mesh(model: mujoco.MjModel, mesh: int) -> dict[str, list]:
    """A mesh's vertices (in its geom's frame) and triangles, flattened; its corners' texture coordinates."""
    vadr, vnum = int(model.mesh_vertadr[mesh]), int(model.mesh_vertnum[mesh])
    fadr, fnum = int(model.mesh_faceadr[mesh]), int(model.mesh_facenum[mesh])
    vertices = np.round(model.mesh_vert[vadr:vadr + vnum], 5).ravel().tolist()
    faces = model.mesh_face[fadr:fadr + fnum].ravel().astype(int).tolist()
    uv = mesh_uv(model, mesh)
    return {"vertices": vertices, "faces": faces, **({"uv": uv} if uv is not None else {})}


def _camera(sim: Simulation) -> dict[str, Any]:
    """Where the page's view starts: the world's Viewpoint camera (MuJoCo cameras look along -z)."""
    try:
        cam = sim.model.camera("viewpoint").id
    except KeyError:
        return {"position": [2.0, -2.0, 1.5], "forward": [-0.6, 0.6, -0.5], "fovy": 45.0}
    mat = sim.data.cam_xmat[cam].reshape(3, 3)
    return {"position": [round(float(v), 5) for v in sim.data.cam_xpos[cam]],
            "forward": [round(float(v), 5) for v in -mat[:, 2]], "fovy": float(sim.model.cam_fovy[cam])}


def _page(data: dict[str, Any], title: str) -> str:
    """The HTML page: the data as JSON (with `</` escaped so it cannot end its script) and the player."""
    player = resources.files("wbtc.runtime").joinpath("player/animation.js").read_text(encoding="utf-8")
    payload = json.dumps(data, separators=(",", ":")).replace("</", "<\\/")
    return f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>{_escape(title)} (wbtc animation)</title>
<style>
html, body {{ margin: 0; height: 100%; overflow: hidden; font-family: sans-serif; background: #222; }}
#view {{ width: 100%; height: 100%; display: block; }}
#labels {{ position: absolute; inset: 0; pointer-events: none; }}
#labels div {{ position: absolute; white-space: pre; }}
#bar {{ position: absolute; left: 0; right: 0; bottom: 0; display: flex; gap: 8px; align-items: center;
        padding: 6px 10px; background: rgba(0, 0, 0, 0.55); color: #eee; }}
#bar input {{ flex: 1; }}
</style>
</head>
<body>
<canvas id="view"></canvas>
<div id="labels"></div>
<div id="bar"><button id="play">Pause</button><input id="time" type="range" min="0" step="any" value="0">
<span id="clock">0.00 s</span></div>
<script id="wbtc-animation" type="application/json">{payload}</script>
<script>
{player}
</script>
</body>
</html>
"""


def _escape(text: str) -> str:
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
