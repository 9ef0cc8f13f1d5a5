"""wbtc's Pedestrian: its height, its colours, a supervisor Robot whose limbs stay put and turn when written."""

from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.compile.compiler import compile_scene
from wbtc.compile.context import COLLISION_GROUP
from wbtc.pipeline import load_world
from wbtc.runtime.simulation import Simulation
from wbtc.runtime.supervisor import SupervisorHub

WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "https://raw.githubusercontent.com/cyberbotics/webots/R2025a/projects/humans/pedestrian/protos/Pedestrian.proto"
WorldInfo { basicTimeStep 16 }
DEF WALKER Pedestrian {
  controllerArgs ["--trajectory=0 0, 5 0" "--speed=1"]
  shirtColor 0.9 0.1 0.1
  enableBoundingObject TRUE
}
Pedestrian {
  translation 3 0 1.27
  name "statue"
}
"""
PARTS = ["leftArmAngle", "leftLowerArmAngle", "leftHandAngle", "rightArmAngle", "rightLowerArmAngle",
         "rightHandAngle", "leftLegAngle", "leftLowerLegAngle", "leftFootAngle", "rightLegAngle",
         "rightLowerLegAngle", "rightFootAngle", "headAngle"]


@pytest.fixture
def hub(tmp_path: Path):
    world = tmp_path / "pedestrian.wbt"
    world.write_text(WORLD, encoding="utf-8")
    scene, _ = load_world(world)
    sim = Simulation(compile_scene(scene), noise=False)
    yield SupervisorHub(sim, scene, world), sim.robots[0]
    sim.close()


def _extent(sim: Simulation, root: str, group: int) -> tuple[np.ndarray, np.ndarray]:
    """The world-frame bounding box of a robot's boxes, spheres and capsules of one geom group."""
    model, data = sim.model, sim.data
    top = model.body(root).id
    low, high = np.full(3, np.inf), np.full(3, -np.inf)
    corners = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=float)
    for g in range(model.ngeom):
        body = int(model.geom_bodyid[g])
        while body not in (0, top):
            body = int(model.body_parentid[body])
        if body != top or model.geom_group[g] != group:
            continue
        rot, pos, size = data.geom_xmat[g].reshape(3, 3), data.geom_xpos[g], model.geom_size[g]
        if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_BOX:
            points = pos + (corners * size) @ rot.T
            low, high = np.minimum(low, points.min(axis=0)), np.maximum(high, points.max(axis=0))
            continue
        half = size[1] if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_CAPSULE else 0.0
        ends = pos + np.outer([-half, half], rot[:, 2])
        low, high = np.minimum(low, ends.min(axis=0) - size[0]), np.maximum(high, ends.max(axis=0) + size[0])
    return low, high


def test_a_supervisor_robot_of_webots_height_and_colours(hub):
    hub, walker = hub
    sim = hub.sim
    walker_entry, statue = sim.table.robots
    assert (walker_entry.name, walker_entry.controller, statue.name, statue.controller) == (
        "pedestrian", "pedestrian", "statue", "")  # a rigid figure (no controllerArgs) has no controller
    assert walker_entry.supervisor
    low, high = _extent(sim, "statue", 1)
    # Soles 1 cm above the ground, head 1.845 m up (root 1.27 m above the soles).
    assert low[2] == pytest.approx(0.01, abs=0.005)
    assert high[2] == pytest.approx(1.845, abs=0.01)
    model = sim.model
    # The jointed figure has Webots' 13 joints, no mass, and its shirt in the chosen colour.
    joints = [model.joint(j).name for j in range(model.njnt)]
    assert joints[:3] == ["pedestrian/left arm", "pedestrian/left forearm", "pedestrian/left hand"]
    assert len(joints) == 13
    shirt = model.geom(next(g for g in range(model.ngeom) if model.body(int(model.geom_bodyid[g])).name
                            == "pedestrian/body" and model.geom_group[g] == 1)).id
    colour = model.mat_rgba[model.geom_matid[shirt]][:3] if model.geom_matid[shirt] >= 0 else model.geom_rgba[shirt][:3]
    assert colour == pytest.approx([0.9, 0.1, 0.1], abs=0.01)
    # enableBoundingObject gives the walker collision shapes; the statue has none.
    colliding = {model.body(int(model.geom_bodyid[g])).name.split("/")[0] for g in range(model.ngeom)
                 if model.geom_group[g] == COLLISION_GROUP}
    assert colliding == {"pedestrian"}


def test_limbs_stay_put_and_turn_when_the_supervisor_writes_their_angles(hub):
    hub, walker = hub
    sim = hub.sim
    for _ in range(30):  # no Physics, no motors: nothing swings under gravity
        sim.step()
    assert np.abs(sim.data.qpos).max() < 0.01
    foot = sim.data.xpos[sim.model.body("pedestrian/left foot").id].copy()
    me = hub.call(walker, "getSelf", ())
    # Every angle Webots' pedestrian controller writes is a field of the instance.
    assert all(hub.call(walker, "node.getField", (me["id"], name, False)) for name in PARTS)
    field = hub.call(walker, "node.getField", (me["id"], "leftLegAngle", False))
    hub.queue(walker, "field.set", (field["id"], -1, -0.5))  # the thigh swings forwards (about +y)
    assert hub.flush().rebuilt
    sim = hub.sim
    joint = sim.model.joint("pedestrian/left leg")
    assert sim.data.qpos[joint.qposadr[0]] == pytest.approx(-0.5)
    for _ in range(5):
        sim.step()
    assert sim.data.qpos[joint.qposadr[0]] == pytest.approx(-0.5, abs=0.01)
    mujoco.mj_forward(sim.model, sim.data)
    moved = sim.data.xpos[sim.model.body("pedestrian/left foot").id]
    # The foot's frame origin is the torso's centre turned about the hip (-0.04, 0.17, -0.3) by -0.5 rad.
    hip = np.array([-0.04, 0.0, -0.3])
    c, s = np.cos(-0.5), np.sin(-0.5)
    turned = hip + np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]]) @ (np.zeros(3) - hip)
    assert moved - foot == pytest.approx(turned, abs=0.005)  # less the millimetres the held joints give
