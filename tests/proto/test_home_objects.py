"""wbtc's Fridge, BunchOfSunFlowers, Radiator and WateringCan: Webots' interfaces, sizes and masses, behaviour."""

from collections.abc import Iterator
from pathlib import Path

import mujoco
import numpy as np
import pytest
from conftest import simulation_of

from wbtc.runtime.simulation import Simulation

FRIDGE_WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/objects/kitchen/fridge/protos/Fridge.proto"
WorldInfo {
  basicTimeStep 8
}
Floor {
  size 10 10
}
DEF FRIDGE Fridge {
  translation 1 0 0
  rotation 0 0 1 1.5708
  mainColor 0.9 0.9 0.95
}
DEF BALL Solid {
  translation 1 0 2.2
  children [
    DEF BALL_SHAPE Shape {
      geometry Sphere {
        radius 0.05
      }
    }
  ]
  boundingObject USE BALL_SHAPE
  physics Physics {
    density -1
    mass 0.1
  }
}
"""


def _collision_geoms(sim: Simulation, body: int) -> list[int]:
    """The collision geoms of `body`, in model order."""
    model = sim.model
    return [
        g
        for g in range(model.ngeom)
        if model.geom_bodyid[g] == body and (model.geom_contype[g] or model.geom_conaffinity[g])
    ]


def _ball(name: str, x: float, y: float, z: float, radius: float = 0.05) -> str:
    """A 0.1 kg ball Solid DEF'd `name` at (x, y, z)."""
    return (
        f"DEF {name} Solid {{\n  translation {x} {y} {z}\n  children [\n    Shape {{\n      geometry Sphere {{\n"
        f'        radius {radius}\n      }}\n    }}\n  ]\n  name "{name.lower()}"\n'
        f"  boundingObject Sphere {{\n    radius {radius}\n  }}\n"
        "  physics Physics {\n    density -1\n    mass 0.1\n  }\n}\n"
    )


def _steps(sim: Simulation, seconds: float) -> None:
    """Advance `sim` by `seconds` of simulated time."""
    for _ in range(round(seconds * 1000 / sim.step_ms)):
        sim.step()


@pytest.fixture
def fridge(tmp_path: Path) -> Iterator[Simulation]:
    simulation = simulation_of(tmp_path, FRIDGE_WORLD, "fridge.wbt")
    yield simulation
    simulation.close()


def test_the_fridge_is_static_with_two_8_kg_doors_on_limited_damped_hinges(fridge: Simulation) -> None:
    model = fridge.model
    cabinet = model.body(fridge.table.bodies["FRIDGE"]).id
    assert model.body_jntnum[cabinet] == 0 and model.body_weldid[cabinet] == 0  # no physics: fixed
    for name in ("upper fridge door", "lower fridge door"):
        door = model.body(name)
        assert model.body_parentid[door.id] == cabinet
        assert model.body_mass[door.id] == pytest.approx(8.0)
        joint = model.joint(name)
        assert list(joint.range) == pytest.approx([-0.01, 1.7])
        assert joint.damping[0] == pytest.approx(1.0)
    # The fridge's frame is rotated by 90 degrees: the doors face +y, their hinges on the -x side.
    mujoco.mj_forward(model, fridge.data)
    upper = fridge.data.xpos[model.body("upper fridge door").id]
    assert upper == pytest.approx([1 - 0.34, 0.36, 1.55], abs=1e-3)


def test_a_ball_rests_on_the_1_8_m_roof_and_a_pulled_door_swings_open_to_its_stop(fridge: Simulation) -> None:
    model, data = fridge.model, fridge.data
    ball = model.body(fridge.table.bodies["BALL"]).id
    lower = model.body("lower fridge door").id
    lower_q = model.jnt_qposadr[model.joint("lower fridge door").id]
    upper_q = model.jnt_qposadr[model.joint("upper fridge door").id]
    _steps(fridge, 1.0)
    assert data.xpos[ball][2] == pytest.approx(1.85, abs=2e-3)
    assert data.qpos[lower_q] == pytest.approx(0.0, abs=1e-3)  # closed doors stay closed
    data.xfrc_applied[lower, 3:] = [0.0, 0.0, 4.0]  # pull the lower door open (4 N·m about +z)
    _steps(fridge, 0.5)
    assert 0.2 < data.qpos[lower_q] < 1.5  # swinging
    _steps(fridge, 2.0)
    assert data.qpos[lower_q] == pytest.approx(1.7, abs=0.02)  # held by its stop
    assert data.qpos[upper_q] == pytest.approx(0.0, abs=1e-3)
    assert data.xpos[ball][2] == pytest.approx(1.85, abs=2e-3)
    assert np.isfinite(data.qpos).all()


SUNFLOWERS_WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/objects/plants/protos/BunchOfSunFlowers.proto"
WorldInfo {
  basicTimeStep 8
}
Floor {
  size 10 10
}
DEF STATIC BunchOfSunFlowers {
}
DEF LOOSE BunchOfSunFlowers {
  translation 2 0 0.05
  name "loose sunflowers"
  flowerTextureUrl ["my_flower.png"]
  leavesTextureUrl ["my_leaves.png"]
  physics Physics {
    density -1
    mass 2
  }
}
""" + _ball("BALL", 0, 0, 1.2)


def test_sunflowers_collide_as_a_vase_cylinder_and_a_sphere_and_fall_only_with_physics(tmp_path: Path) -> None:
    sim = simulation_of(tmp_path, SUNFLOWERS_WORLD, "sunflowers.wbt")
    try:
        model, data = sim.model, sim.data
        still, loose = (model.body(sim.table.bodies[name]).id for name in ("STATIC", "LOOSE"))
        ball = model.body(sim.table.bodies["BALL"]).id
        assert model.body_weldid[still] == 0  # physics NULL: static
        assert model.body_mass[loose] == pytest.approx(2.0)
        mujoco.mj_forward(model, data)
        vase, bunch = _collision_geoms(sim, still)
        assert model.geom_type[vase] == mujoco.mjtGeom.mjGEOM_CYLINDER
        assert list(model.geom_size[vase][:2]) == pytest.approx([0.1, 0.324])
        assert data.geom_xpos[vase] == pytest.approx([0, 0, 0.324])
        assert model.geom_type[bunch] == mujoco.mjtGeom.mjGEOM_SPHERE
        assert model.geom_size[bunch][0] == pytest.approx(0.17)
        assert data.geom_xpos[bunch] == pytest.approx([0, 0, 0.78])
        _steps(sim, 1.5)
        assert data.xpos[loose] == pytest.approx([2, 0, 0], abs=2e-3)  # fell 5 cm onto its foot
        assert data.xpos[ball] == pytest.approx([0, 0, 0.95 + 0.05], abs=2e-3)  # on top of the flowers
    finally:
        sim.close()


RADIATOR_WORLD = (
    """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/objects/apartment_structure/protos/Radiator.proto"
WorldInfo {
  basicTimeStep 8
}
Floor {
  size 10 10
}
DEF TEN Radiator {
}
DEF FOUR Radiator {
  translation 2 0 0.3
  name "short radiator"
  numberOfFins 4
  finAppearance PBRAppearance {
    baseColor 1 1 1
  }
}
DEF GHOST Radiator {
  translation 4 0 0.3
  name "radiator without bounding object"
  numberOfFins 3
  enableBoundingObject FALSE
}
"""
    + _ball("BALL", -0.02, 0.24, 1)
    + _ball("FALLING", 4, 0.05, 1)
)


def test_a_radiator_is_one_static_box_sized_by_its_fins_unless_the_bounding_object_is_off(tmp_path: Path) -> None:
    sim = simulation_of(tmp_path, RADIATOR_WORLD, "radiator.wbt")
    try:
        model, data = sim.model, sim.data
        ten, four, ghost = (model.body(sim.table.bodies[name]).id for name in ("TEN", "FOUR", "GHOST"))
        mujoco.mj_forward(model, data)
        for body, fins, x in ((ten, 10, 0), (four, 4, 2)):
            assert model.body_weldid[body] == 0
            (box,) = _collision_geoms(sim, body)
            assert model.geom_type[box] == mujoco.mjtGeom.mjGEOM_BOX
            assert list(model.geom_size[box]) == pytest.approx([0.12, (0.15 + 0.06 * fins) / 2, 0.29])
            assert data.geom_xpos[box] == pytest.approx([x - 0.02, 0.03 * (fins - 2), 0.3])  # 1 cm above the floor
            columns = [
                g
                for g in range(model.ngeom)
                if model.geom_bodyid[g] == body and model.geom_type[g] == mujoco.mjtGeom.mjGEOM_BOX and g != box
            ]
            assert len(columns) == fins
        assert _collision_geoms(sim, ghost) == []
        ball, falling = (model.body(sim.table.bodies[name]).id for name in ("BALL", "FALLING"))
        _steps(sim, 1.5)
        assert data.xpos[ball][2] == pytest.approx(0.59 + 0.05, abs=2e-3)  # on the radiator's top
        assert data.xpos[falling][2] == pytest.approx(0.05, abs=2e-3)  # through the ghost, onto the floor
    finally:
        sim.close()


WATERING_CAN_WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/objects/garden/protos/WateringCan.proto"
WorldInfo {
  basicTimeStep 8
}
Floor {
  size 10 10
}
DEF STATIC WateringCan {
}
DEF LOOSE WateringCan {
  translation 0 2 0.1
  name "loose watering can"
  enablePhysics TRUE
}
""" + _ball("BALL", 0, 0.12, 1)  # beside the handle


def test_a_watering_can_is_static_unless_its_physics_is_on_then_weighs_1_kg_and_stands(tmp_path: Path) -> None:
    sim = simulation_of(tmp_path, WATERING_CAN_WORLD, "watering_can.wbt")
    try:
        model, data = sim.model, sim.data
        still, loose = (model.body(sim.table.bodies[name]).id for name in ("STATIC", "LOOSE"))
        assert model.body_weldid[still] == 0
        assert model.body_mass[loose] == pytest.approx(1.0)
        assert model.body_ipos[loose] == pytest.approx([0, 0, 0.4])
        assert sorted(model.body_inertia[loose]) == pytest.approx([0.636173, 12.381802, 12.381802])
        kinds = [int(model.geom_type[g]) for g in _collision_geoms(sim, still)]
        assert kinds == [mujoco.mjtGeom.mjGEOM_CYLINDER] * 2 + [mujoco.mjtGeom.mjGEOM_CAPSULE] * 6
        mujoco.mj_forward(model, data)
        body = _collision_geoms(sim, still)[0]
        assert model.geom_size[body][:2] == pytest.approx([0.23, 0.27])
        recognised = [r for r in sim.table.recognizable if r.model == "watering can"]
        assert [r.colors for r in recognised] == [[[0.0, 0.2039, 0.0]]] * 2
        ball = model.body(sim.table.bodies["BALL"]).id
        _steps(sim, 1.5)
        assert data.xpos[loose] == pytest.approx([0, 2, 0], abs=2e-3)  # fell 10 cm and stands upright
        assert data.xmat[loose][8] == pytest.approx(1.0, abs=1e-4)
        assert data.xpos[ball][2] == pytest.approx(0.54 + 0.05, abs=2e-3)  # on the body's top
    finally:
        sim.close()
