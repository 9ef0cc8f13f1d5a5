"""wbtc's Sink, Monitor, Keyboard and ComputerMouse: Webots' interfaces, collision boxes and masses."""

import mujoco
import numpy as np
import pytest

from wbtc.compile.context import COLLISION_GROUP, VISUAL_GROUP
from wbtc.pipeline import compile_world
from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/objects/kitchen/components/protos/Sink.proto"
EXTERNPROTO "webots://projects/objects/computers/protos/Monitor.proto"
EXTERNPROTO "webots://projects/objects/computers/protos/Keyboard.proto"
EXTERNPROTO "webots://projects/objects/computers/protos/ComputerMouse.proto"
WorldInfo { basicTimeStep 8 }
Floor { }
DEF SINK Sink { translation 0 0 0.5 textureUrl ["my_steel.jpg"] }
DEF IN_BASIN Ball { translation 0.1 0 0.7 name "in basin" }
DEF ON_RIM Ball { translation 0.27 0 0.7 name "on rim" }
DEF MONITOR Monitor { translation 1 0 0.01 mass 3 }
DEF BIG Monitor { translation 2 0 0.01 rotation 0 0 1 1.5708 mass 3 scale 2 color 1 1 1 name "big monitor" }
DEF STILL Monitor { translation 3 0 0.3 name "still monitor" }
DEF KEYBOARD Keyboard { translation -1 0 0.05 mass 0.6 color 0.8 0.8 0.8 }
DEF MOUSE ComputerMouse { translation -1 0.4 0.05 }
DEF PAINTED ComputerMouse { translation -1 1 0.2 mass 0 topColor 1 0 0 bottomColor 0 0 1 name "painted mouse" }
"""


def _geoms(model: mujoco.MjModel, body: int, group: int) -> list[int]:
    """The geoms of one body in one geom group."""
    return [g for g in range(model.ngeom) if model.geom_bodyid[g] == body and model.geom_group[g] == group]


def _top(model: mujoco.MjModel, data: mujoco.MjData, body: int) -> float:
    """The highest world z reached by one body's visual boxes and meshes (mesh: its bounding box)."""
    top = -np.inf
    corners = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=float)
    for g in _geoms(model, body, VISUAL_GROUP):
        size = model.geom_size[g] if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_BOX else model.geom_aabb[g][3:]
        centre = data.geom_xpos[g] + (0 if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_BOX
                                      else data.geom_xmat[g].reshape(3, 3) @ model.geom_aabb[g][:3])
        top = max(top, float((centre + (corners * size) @ data.geom_xmat[g].reshape(3, 3).T)[:, 2].max()))
    return top


@pytest.fixture(scope="module")
def settled(tmp_path_factory: pytest.TempPathFactory):
    world = tmp_path_factory.mktemp("office") / "office.wbt"
    world.write_text(WORLD, encoding="utf-8")
    result, _ = compile_world(world)
    sim = Simulation(result, noise=False)
    bodies = {name: sim.model.body(index).id for name, index in result.table.bodies.items()}
    start = {name: sim.data.xpos[body].copy() for name, body in bodies.items()}
    for _ in range(200):  # 1.6 s
        sim.step()
    mujoco.mj_forward(sim.model, sim.data)
    yield sim, bodies, start
    sim.close()


def test_masses_and_collision_boxes_are_webots(settled):
    sim, bodies, _ = settled
    model = sim.model
    assert model.body_mass[bodies["MONITOR"]] == pytest.approx(3)
    assert model.body_mass[bodies["KEYBOARD"]] == pytest.approx(0.6)
    assert model.body_mass[bodies["MOUSE"]] == pytest.approx(0.1)  # the mouse's default mass
    # Sink, a massless monitor and a massless mouse have no physics: welded where they are put.
    for name in ("SINK", "STILL", "PAINTED"):
        assert model.body_jntnum[bodies[name]] == 0
    assert model.body_jntnum[bodies["MONITOR"]] == 1
    monitor = _geoms(model, bodies["MONITOR"], COLLISION_GROUP)
    sizes = sorted(sorted(np.round(2 * model.geom_size[g], 5)) for g in monitor)
    assert sizes == [[0.01176, 0.24738, 0.469], [0.021, 0.073, 0.137], [0.023, 0.075, 0.131]]
    big = sorted(sorted(np.round(2 * model.geom_size[g], 5)) for g in _geoms(model, bodies["BIG"], COLLISION_GROUP))
    assert big == [[2 * v for v in box] for box in sizes]
    (keyboard,) = _geoms(model, bodies["KEYBOARD"], COLLISION_GROUP)
    assert 2 * model.geom_size[keyboard] == pytest.approx([0.13428, 0.41, 0.01])
    (mouse,) = _geoms(model, bodies["MOUSE"], COLLISION_GROUP)
    assert 2 * model.geom_size[mouse] == pytest.approx([0.082, 0.045, 0.03])
    assert len(_geoms(model, bodies["SINK"], COLLISION_GROUP)) == 7


def test_objects_rest_on_the_floor_at_webots_heights(settled):
    sim, bodies, start = settled
    data = sim.data
    assert data.xpos[bodies["MONITOR"]][2] == pytest.approx(0.0005, abs=1e-3)  # the foot reaches 0.5 mm below
    assert data.xpos[bodies["BIG"]][2] == pytest.approx(0.001, abs=1e-3)
    assert data.xpos[bodies["KEYBOARD"]][2] == pytest.approx(0.005, abs=1e-3)  # Webots' box is centred
    assert data.xpos[bodies["MOUSE"]][2] == pytest.approx(0.0, abs=1e-3)
    assert data.xpos[bodies["STILL"]] == pytest.approx(start["STILL"])
    assert data.xpos[bodies["PAINTED"]] == pytest.approx(start["PAINTED"])
    # Upright, and as tall as Webots' monitor (screen top 0.349 m above the foot), twice with scale 2.
    assert sim.data.xmat[bodies["MONITOR"]].reshape(3, 3)[2, 2] == pytest.approx(1, abs=1e-3)
    assert _top(sim.model, data, bodies["MONITOR"]) == pytest.approx(0.349, abs=2e-3)
    assert _top(sim.model, data, bodies["BIG"]) == pytest.approx(0.698, abs=4e-3)
    assert _top(sim.model, data, bodies["KEYBOARD"]) == pytest.approx(0.005 + 0.0091, abs=1e-3)  # keys' tops
    assert _top(sim.model, data, bodies["MOUSE"]) == pytest.approx(0.034, abs=1e-3)  # Webots' shell top


def test_a_ball_falls_into_the_sink_basin_and_another_rests_on_its_rim(settled):
    sim, bodies, _ = settled
    # The sink at z 0.5: the basin's floor is 3.5 cm below the origin, the rim's top 2.7 cm above it.
    assert sim.data.xpos[bodies["IN_BASIN"]][2] == pytest.approx(0.5 - 0.035 + 0.0325, abs=2e-3)
    assert sim.data.xpos[bodies["ON_RIM"]][2] == pytest.approx(0.5 + 0.027 + 0.0325, abs=2e-3)
    colour = sim.model.geom_rgba[_geoms(sim.model, bodies["PAINTED"], VISUAL_GROUP)]
    materials = sim.model.geom_matid[_geoms(sim.model, bodies["PAINTED"], VISUAL_GROUP)]
    if (materials >= 0).all():
        colour = sim.model.mat_rgba[materials]
    assert [list(c[:3]) for c in colour] == [[0, 0, 1], [1, 0, 0]]  # base plate, then shell
