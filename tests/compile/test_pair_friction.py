"""ContactProperties between two non-default materials: explicit pairs, the other contacts keep the default μ."""

from pathlib import Path

import mujoco
import numpy as np

from wbtc.pipeline import compile_world

#: A gripper finger (material "gripper") and a stick (material "stick") with μ 10 between them, both on
#: a floor of the default material (μ 1 by default, 0.3 here through a ("default", "default") law).
_WORLD = """#VRML_SIM R2023b utf8
WorldInfo {
  contactProperties [
    ContactProperties { material1 "gripper" material2 "stick" coulombFriction [ 10 ] }
    ContactProperties { material1 "stick" material2 "gripper" coulombFriction [ 2 ] }
    ContactProperties { coulombFriction [ 0.3 ] }
  ]
}
Solid {
  children [ Shape { geometry DEF FLOOR Plane { size 10 10 } } ]
  boundingObject USE FLOOR
}
DEF STICK Solid {
  translation 0 0 0.05
  children [ Shape { geometry DEF STICK_BOX Box { size 0.4 0.1 0.1 } } ]
  contactMaterial "stick"
  boundingObject USE STICK_BOX
  physics Physics { }
}
DEF FINGER Solid {
  translation 0 1 0.05
  children [ Shape { geometry DEF FINGER_BOX Box { size 0.1 0.1 0.1 } } ]
  name "finger"
  contactMaterial "gripper"
  boundingObject USE FINGER_BOX
  physics Physics { }
}
"""


def _compile(tmp_path: Path):  # noqa: ANN202
    world = tmp_path / "pair.wbt"
    world.write_text(_WORLD)
    return compile_world(world)[0]


def _box(model: mujoco.MjModel, half: float) -> int:
    return next(g for g in range(model.ngeom) if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_BOX
                and abs(model.geom_size[g][0] - half) < 1e-9 and model.geom_contype[g])


def test_the_two_materials_touch_through_a_pair_with_their_own_mu(tmp_path: Path) -> None:
    result = _compile(tmp_path)
    model = result.model
    stick, finger = _box(model, 0.2), _box(model, 0.05)
    assert model.npair == 1
    assert {int(model.pair_geom1[0]), int(model.pair_geom2[0])} == {stick, finger}
    # The first ContactProperties of the two materials, not the later one in the other order.
    np.testing.assert_allclose(model.pair_friction[0][:2], [10, 10])
    assert model.pair_dim[0] == 3
    # Each geom keeps the world's default μ for every other contact (the floor's).
    np.testing.assert_allclose(model.geom_friction[[stick, finger], 0], [0.3, 0.3])
    assert not any("approximated" in w.message for w in result.warnings)


def test_the_stick_slides_on_the_floor_with_the_default_mu(tmp_path: Path) -> None:
    model = _compile(tmp_path).model
    data = mujoco.MjData(model)
    stick = model.geom_bodyid[_box(model, 0.2)]
    dof = model.jnt_dofadr[model.body_jntadr[stick]]
    mujoco.mj_step(model, data, nstep=20)  # settle
    data.qvel[dof] = 1.0  # 1 m/s along x
    start = data.time
    while data.qvel[dof] > 0.5:
        mujoco.mj_step(model, data)
    # Coulomb friction of 0.3 slows it by 0.3 g: 0.5 m/s off in 0.17 s (with μ 10, in 5 ms).
    assert abs((data.time - start) - 0.5 / (0.3 * 9.81)) < 0.01
