"""Cylinder, Capsule and Cone drawn without the parts their `side`, `top` or `bottom` turn off."""

from pathlib import Path

import mujoco
import numpy as np

from wbtc.pipeline import compile_world

WORLD = """#VRML_SIM R2025a utf8
WorldInfo { }
Solid {
  children [
    Shape { geometry Capsule { radius 0.1 height 0.4 top FALSE bottom FALSE } }
    Shape { geometry Cylinder { radius 0.1 height 0.4 side FALSE subdivision 8 } }
    Shape { geometry Cone { bottomRadius 0.1 height 0.4 bottom FALSE } }
    Shape { geometry Cylinder { radius 0.1 height 0.4 } }
  ]
  boundingObject Capsule { radius 0.1 height 0.4 top FALSE }
  physics Physics { }
}
"""


def _mesh_vertices(model: mujoco.MjModel, geom: int) -> np.ndarray:
    mesh = model.geom_dataid[geom]
    start, count = model.mesh_vertadr[mesh], model.mesh_vertnum[mesh]
    # Back in the geom's own frame: MuJoCo recentres and turns a mesh's vertices.
    turn = np.zeros(9)
    mujoco.mju_quat2Mat(turn, model.mesh_quat[mesh])
    return model.mesh_vert[start:start + count] @ turn.reshape(3, 3).T + model.mesh_pos[mesh]


def test_parts_turned_off_are_not_drawn_and_bounding_objects_stay_whole(tmp_path: Path) -> None:
    (tmp_path / "open.wbt").write_text(WORLD, encoding="utf-8")
    model = compile_world(tmp_path / "open.wbt")[0].model
    visual = [g for g in range(model.ngeom) if model.geom_contype[g] == 0]
    kinds = [int(model.geom_type[g]) for g in visual]
    assert kinds == [mujoco.mjtGeom.mjGEOM_MESH] * 3 + [mujoco.mjtGeom.mjGEOM_CYLINDER]
    tube, caps, cone = (_mesh_vertices(model, g) for g in visual[:3])
    # The capsule's tube alone: every vertex on the radius, none beyond the cylinder's ends.
    assert np.allclose(np.hypot(tube[:, 0], tube[:, 1]), 0.1)
    assert np.abs(tube[:, 2]).max() <= 0.2 + 1e-6  # float32 vertices
    # The cylinder's two caps alone: vertices at z = +-0.2 only (rims and centres), 8 sides each.
    assert np.allclose(np.abs(caps[:, 2]), 0.2)
    assert np.isclose(np.hypot(caps[:, 0], caps[:, 1]).max(), 0.1)
    # The cone's side alone: nothing on its base but the rim.
    base = cone[np.isclose(cone[:, 2], cone[:, 2].min())]
    assert np.allclose(np.hypot(base[:, 0], base[:, 1]), 0.1)
    collision = [g for g in range(model.ngeom) if model.geom_contype[g] != 0]
    assert [int(model.geom_type[g]) for g in collision] == [mujoco.mjtGeom.mjGEOM_CAPSULE]
