"""A Camera's recognition segmentation image: each recognizable object's pixels in its colour, the rest black.

Webots renders every shape, with no lighting, in the first `recognitionColors` colour of the
nearest Solid above it that has one (black when none has), over a black background, with the
camera's own projection and no far limit (WbCamera's segmentation camera; WbShape sets the
colours). wbtc casts one ray per pixel centre (see `camera_projection.pixel_rays`) from the camera
against the visual geoms, so planar, cylindrical and spherical images come out of the same code;
the image is BGRA, rows from the top, alpha 255, as the camera image.

Not honoured yet: shapes hidden from this camera by a supervisor's `setVisibility`, transparent
shapes (MuJoCo's rays skip geoms of alpha 0, Webots draws them), `lens` distortion, `near`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import mujoco
import numpy as np

from wbtc.compile.context import VISUAL_GROUP
from wbtc.runtime.camera_projection import Optics, pixel_rays

if TYPE_CHECKING:
    from wbtc.compile.table import Recognizable
    from wbtc.runtime.simulation import Simulation


def geom_colours(model: mujoco.MjModel, recognizable: list[Recognizable]) -> np.ndarray:
    """BGRA of each geom (one more row, black, for 'no hit'): its nearest coloured Solid's first colour."""
    colour_of_body: dict[int, np.ndarray] = {}
    for entry in recognizable:
        if not entry.colors:
            continue
        try:
            body = model.body(entry.body).id
        except KeyError:
            continue
        r, g, b = (int(round(min(max(float(c), 0.0), 1.0) * 255)) for c in entry.colors[0][:3])
        colour_of_body[body] = np.array([b, g, r, 255], dtype=np.uint8)
    black = np.array([0, 0, 0, 255], dtype=np.uint8)
    by_body = []
    for body in range(model.nbody):
        walk = body
        while walk > 0 and walk not in colour_of_body:
            walk = int(model.body_parentid[walk])
        by_body.append(colour_of_body.get(walk, black))
    colours = np.array([by_body[int(b)] for b in model.geom_bodyid] + [black], dtype=np.uint8)
    return colours.reshape(-1, 4)


def render(sim: Simulation, origin: np.ndarray, rotation: np.ndarray, optics: Optics,
           colours: np.ndarray) -> np.ndarray:
    """The segmentation image (height, width, 4) BGRA seen from a camera frame (model-frame pose)."""
    rays = pixel_rays(optics).reshape(-1, 3) @ np.asarray(rotation).T
    count = len(rays)
    geoms = np.full(count, -1, dtype=np.int32)
    dist = np.empty(count)
    groups = np.zeros(6, dtype=np.uint8)
    groups[VISUAL_GROUP] = 1
    mujoco.mj_multiRay(sim.model, sim.data, np.asarray(origin, dtype=float), np.ascontiguousarray(rays).reshape(-1),
                       groups, 1, -1, geoms, dist, None, count, mujoco.mjMAXVAL)
    return colours[geoms].reshape(optics.height, optics.width, 4)  # -1 picks the last row: black
