"""A visual Plane on a moving robot (a decal): a thin box whose top face is where the plane was."""

from pathlib import Path

import mujoco
import numpy as np

from wbtc.compile.compiler import PLANE_HALF_THICKNESS
from wbtc.pipeline import compile_world

WORLD = Path(__file__).parent / "fixtures" / "worlds" / "plane_decal.wbt"


def test_a_plane_decal_on_a_moving_robot_compiles_as_a_thin_box() -> None:
    result, _ = compile_world(WORLD)
    model, data = result.model, mujoco.MjData(result.model)
    mujoco.mj_forward(model, data)
    red = [g for g in range(model.ngeom) if np.allclose(model.geom_rgba[g, :3], [1, 0, 0])]
    assert len(red) == 1
    decal = red[0]
    assert model.geom_type[decal] == mujoco.mjtGeom.mjGEOM_BOX
    np.testing.assert_allclose(model.geom_size[decal], [0.04, 0.03, PLANE_HALF_THICKNESS])
    # The box's top face is at the plane's height: 0.05 (robot) + 0.0505 (Pose).
    top = data.geom_xpos[decal][2] + PLANE_HALF_THICKNESS
    assert abs(top - 0.1005) < 1e-9
    # The floor's planes (visual and collision), in a static Solid, stay planes.
    planes = [g for g in range(model.ngeom) if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_PLANE]
    assert len(planes) == 2 and all(model.body_weldid[model.geom_bodyid[g]] == 0 for g in planes)
