"""wbtc's CharacterSkin: Webots' interface, a still figure of primitives standing upright and facing +x."""

from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.compile.context import COLLISION_GROUP, VISUAL_GROUP
from wbtc.pipeline import compile_world
from wbtc.runtime.simulation import Simulation

# As in Webots' skin_animated_humans world: skins inside supervisor Robots (one turned to face +y), and
# one skin placed at the root with every field set.
WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/humans/skin_animated_humans/protos/CharacterSkin.proto"
WorldInfo { basicTimeStep 16 }
Floor { size 50 50 }
DEF ROBERT Robot {
  translation -3 -3 0
  children [
    CharacterSkin {
      name "Robert"
      model "Robert"
    }
  ]
  name "robert"
  controllerArgs ["-d" "Robert" "-f" "../../motions/walk.bvh" "-l"]
  supervisor TRUE
}
DEF SANDRA Robot {
  translation 0 -5.3 0
  rotation 0 0 1 1.5708
  children [ CharacterSkin { name "Sandra" } ]
  name "sandra"
  supervisor TRUE
}
DEF SOPHIA Robot {
  translation 2 0 0
  children [
    CharacterSkin {
      translation 0 0 0
      rotation 0.57735 0.57735 0.57735 2.0944
      scale 2 2 2
      name "Sophia"
      model "Sophia"
      castShadows FALSE
    }
  ]
  name "sophia"
}
"""


def _extent(model: mujoco.MjModel, data: mujoco.MjData, body: int) -> tuple[np.ndarray, np.ndarray]:
    """The world-frame bounding box of one body's visual boxes, spheres, cylinders and capsules."""
    low, high = np.full(3, np.inf), np.full(3, -np.inf)
    corners = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=float)
    for g in range(model.ngeom):
        if model.geom_bodyid[g] != body or model.geom_group[g] != VISUAL_GROUP:
            continue
        rot, pos, size = data.geom_xmat[g].reshape(3, 3), data.geom_xpos[g], model.geom_size[g]
        kind = model.geom_type[g]
        if kind == mujoco.mjtGeom.mjGEOM_BOX:
            points = pos + (corners * size) @ rot.T
        elif kind == mujoco.mjtGeom.mjGEOM_CYLINDER:
            points = pos + (corners * [size[0], size[0], size[1]]) @ rot.T
        else:
            half = size[1] if kind == mujoco.mjtGeom.mjGEOM_CAPSULE else 0.0
            ends = pos + np.outer([-half, half], rot[:, 2])
            points = np.vstack([ends - size[0], ends + size[0]])
        low, high = np.minimum(low, points.min(axis=0)), np.maximum(high, points.max(axis=0))
    return low, high


def test_skins_stand_on_the_floor_at_their_heights_and_do_not_collide(tmp_path: Path):
    world = tmp_path / "skins.wbt"
    world.write_text(WORLD, encoding="utf-8")
    result, _ = compile_world(world)
    sim = Simulation(result, noise=False)
    model, data = sim.model, sim.data
    assert [r.name for r in sim.table.robots] == ["robert", "sandra", "sophia"]
    assert all(r.supervisor for r in sim.table.robots[:2])
    for _ in range(20):
        sim.step()
    mujoco.mj_forward(model, data)
    robert, sandra, sophia = (model.body(result.table.bodies[d]).id for d in ("ROBERT", "SANDRA", "SOPHIA"))
    low, high = _extent(model, data, robert)
    assert low[2] == pytest.approx(0.0, abs=1e-6)  # soles on the ground: y-up mesh frame turned to ENU
    assert high[2] == pytest.approx(1.80, abs=1e-3)
    assert (low[:2] + high[:2]) / 2 == pytest.approx([-3, -3], abs=0.05)
    assert high[1] - low[1] > high[0] - low[0]  # shoulders across y, facing +x
    face = max((data.geom_xpos[g][0] for g in range(model.ngeom) if model.geom_bodyid[g] == robert), default=0)
    assert face > -3 + 0.1  # the nose points forward (+x)
    low, high = _extent(model, data, sandra)  # Webots' default character; her robot turned to face +y
    assert (low[2], high[2]) == pytest.approx((0.0, 1.70), abs=1e-3)
    assert high[0] - low[0] > high[1] - low[1]
    low, high = _extent(model, data, sophia)  # scale 2
    assert (low[2], high[2]) == pytest.approx((0.0, 2 * 1.35), abs=1e-3)
    # A Skin is no Solid: no mass, no collision shape, no device; nothing moves.
    assert model.body_mass[[robert, sandra, sophia]] == pytest.approx([0, 0, 0])
    assert not any(model.geom_group[g] == COLLISION_GROUP and model.geom_bodyid[g] in (robert, sandra, sophia)
                   for g in range(model.ngeom))
    assert model.nu == 0 and model.njnt == 0


# Webots' skin_animated_humans world as written in R2021c: z up (the floor turned), the Robot's rotation
# turning the y-up skin, whose default rotation was none then.
OLD_WORLD = """#VRML_SIM R2021c utf8
WorldInfo {
}
Floor {
  rotation 1 0 0 1.5708
  size 50 50
}
DEF ROBERT Robot {
  translation -3 -3 0
  rotation 0.5773509358554485 0.5773489358556708 0.5773509358554485 2.0944
  children [
    CharacterSkin {
      name "Robert"
      model "Robert"
    }
  ]
  name "robert"
  supervisor TRUE
}
"""


def test_an_r2021c_world_leaves_the_skin_unturned(tmp_path: Path):
    # Rendered templates are shared between instances only within one world version: the R2025a Robert of
    # the test above must not be reused here.
    world = tmp_path / "old.wbt"
    world.write_text(OLD_WORLD, encoding="utf-8")
    result, _ = compile_world(world)
    model = result.model
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    low, high = _extent(model, data, model.body(result.table.bodies["ROBERT"]).id)
    assert (low[2], high[2]) == pytest.approx((0.0, 1.80), abs=1e-3)
