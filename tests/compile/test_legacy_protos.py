"""Library robots and floors in worlds written before R2022a (RUB PROTOs then, FLU ones in wbtc's library)."""

import math

import numpy as np
import pytest
from conftest import simulation_of

from wbtc.proto.expand import expand_scene
from wbtc.runtime import poses
from wbtc.scene import build_scene
from wbtc.vrml import parse_text

# An R2021b world in NUE axes (x north, y up, z east), as Webots wrote them: the E-puck was RUB
# (x right, y up, z back), turned a quarter turn about the world's up; its turret holds a 5 cm mast
# written in those RUB axes; the floor is 4 m along x and 2 m along z; the wall (4 m long, 2.4 m high,
# 0.2 m thick) and the box (0.3 m high) stood along y, their sizes written (x, height, z).
WORLD = """#VRML_SIM R2021b utf8
WorldInfo {
  coordinateSystem "NUE"
}
Floor {
  size 4 2
}
Wall {
  translation 0 0 -1
  size 4 2.4 0.2
}
WoodenBox {
  translation -1 0.15 0.5
  size 0.1 0.3 0.2
}
E-puck {
  translation 1 0.01 0.5
  rotation 0 1 0 1.5708
  controller "<none>"
  turretSlot [
    Solid {
      translation 0 0.05 0
      name "mast"
    }
  ]
}
"""


@pytest.fixture
def sim(tmp_path):
    simulation = simulation_of(tmp_path, WORLD, "old.wbt")
    yield simulation
    simulation.close()


def test_an_old_world_e_puck_stands_where_and_as_it_was_placed(sim):
    to_model = sim.to_model
    body = sim.robots[0].body
    axes = sim.data.xmat[body].reshape(3, 3)
    # Upright: its up is the world's up (NUE y, the model's z).
    assert axes[:, 2] == pytest.approx(to_model @ [0, 1, 0], abs=1e-5)
    # Facing its old forward (RUB −z) turned a quarter turn about y: the world's −x (south).
    assert axes[:, 0] == pytest.approx(to_model @ [-1, 0, 0], abs=1e-5)
    assert sim.data.xpos[body] == pytest.approx(to_model @ [1, 0.01, 0.5], abs=1e-9)
    # The mast the old file put 5 cm up the turret is 5 cm above it, not beside it.
    # (The turret slot is 0.0486 m above the robot's origin.)
    mast = sim.data.xpos[sim.model.body("e-puck/mast").id] - sim.data.xpos[body]
    assert mast @ (to_model @ [0, 1, 0]) == pytest.approx(0.0486 + 0.05, abs=1e-3)


def test_the_old_floor_is_level_and_spans_x_and_z(sim):
    floor = next(g for g in range(sim.model.ngeom) if sim.model.geom_type[g] == 0)  # its Plane
    normal = sim.data.geom_xmat[floor].reshape(3, 3)[:, 2]
    assert normal == pytest.approx(sim.to_model @ [0, 1, 0], abs=1e-9)
    half = sim.model.geom_size[floor][:2]
    extent = np.abs(sim.data.geom_xmat[floor].reshape(3, 3)[:, :2]) @ half
    assert sim.from_model @ extent == pytest.approx([2.0, 0.0, 1.0], abs=1e-9)
    for _ in range(60):  # the robot settles on it
        sim.step()
    assert sim.data.xpos[sim.robots[0].body] @ (sim.to_model @ [0, 1, 0]) == pytest.approx(0.0, abs=2e-3)


def test_the_supervisor_reads_the_rotation_the_old_file_wrote(sim):
    node = sim.robots[0].entry.node
    translation, rotation = poses.local_pose(sim, node)
    assert translation == pytest.approx([1, 0.01, 0.5], abs=1e-9)
    assert rotation == pytest.approx([0, 1, 0, 1.5708], abs=1e-6)
    assert poses.set_local_pose(sim, node, None, [0, 1, 0, 0.5])
    assert poses.local_pose(sim, node)[1] == pytest.approx([0, 1, 0, 0.5], abs=1e-6)
    assert sim.data.xmat[sim.robots[0].body].reshape(3, 3)[:, 2] == pytest.approx(sim.to_model @ [0, 1, 0],
                                                                                   abs=1e-6)


def test_old_walls_and_boxes_stand_up_with_their_old_sizes(sim):
    def box(name: str) -> tuple[np.ndarray, np.ndarray]:
        """Centre and half extents (world axes) of a body's collision box."""
        body = sim.model.body(name).id
        geom = next(g for g in range(sim.model.ngeom) if sim.model.geom_bodyid[g] == body
                    and sim.model.geom_type[g] == 6 and sim.model.geom_group[g] == 3)
        axes = sim.data.geom_xmat[geom].reshape(3, 3)
        half = np.abs(sim.from_model @ axes) @ sim.model.geom_size[geom]
        return sim.from_model @ sim.data.geom_xpos[geom], half

    # The wall (its box is the inner Solid of the PROTO) stands on the floor: 2.4 m high (y), 4 m long
    # (x), 0.2 m thick (z), around z = -1.
    centre, half = box("solid")
    assert half == pytest.approx([2.0, 1.2, 0.1], abs=1e-9)
    assert centre == pytest.approx([0.0, 1.2, -1.0], abs=1e-9)
    # The box is 0.3 m high, centred where it was put.
    centre, half = box("wooden box")
    assert half == pytest.approx([0.05, 0.15, 0.1], abs=1e-9)
    assert centre == pytest.approx([-1.0, 0.15, 0.5], abs=1e-9)


def test_a_drone_built_along_z_before_r2022a_is_left_as_the_old_world_turned_it(tmp_path):
    # Webots' R2020 Mavic world stood its drone (already z-up then) up itself with this rotation.
    world = """#VRML_SIM R2020a utf8
WorldInfo {
  coordinateSystem "NUE"
}
Mavic2Pro {
  translation 0 0.1 0
  rotation 0 -0.7071067811865475 -0.7071067811865475 -3.14159
  controller "<none>"
}
"""
    sim = simulation_of(tmp_path, world, "mavic.wbt")
    up = sim.data.xmat[sim.robots[0].body].reshape(3, 3)[:, 2]
    assert up == pytest.approx(sim.to_model @ [0, 1, 0], abs=1e-4)
    sim.close()


def test_an_old_world_thymio_feels_gravity_along_its_old_y(tmp_path):
    # Its accelerometer read along the RUB axes of the R2021b Thymio2: 1 g is 23 of its units on y.
    world = """#VRML_SIM R2021b utf8
WorldInfo {
  coordinateSystem "NUE"
}
Floor {
  size 4 4
}
Thymio2 {
  controller "<none>"
}
"""
    sim = simulation_of(tmp_path, world, "thymio.wbt")
    robot = sim.robots[0]
    tag = next(t for t, d in enumerate(robot.entry.devices) if d.name == "acc")
    for _ in range(60):
        sim.step()
    x, y, z = robot.sensors[tag].sample(sim)
    assert y == pytest.approx(9.81 * 32 / 13.65, rel=0.02)
    assert abs(x) < 0.5 and abs(z) < 0.5
    sim.close()


def test_webots_6_e_puck_distance_sensors_of_a_world_s_own_robot_look_out_tilted_up(tmp_path):
    # A V6 world's own e-puck (y up, forward -z) with two sensors of Webots 6's library name.
    world = """#VRML_SIM V6.0 utf8
WorldInfo { }
DifferentialWheels {
  children [
    EPuck_DistanceSensor { translation 0.01 0.033 -0.03 rotation 0 1 0 1.27 name "ps0" }
    EPuck_DistanceSensor { translation 0.031 0.033 0 name "ps2" }
  ]
  controller "<none>"
}
"""
    simulation = simulation_of(tmp_path, world, "v6.wbt")
    sensors = {s.entry.name: s for s in simulation.robots[0].sensors.values()}
    assert sorted(sensors) == ["ps0", "ps2"]
    _, right = sensors["ps2"].frame(simulation)
    # An old world's axes are NUE: its +x (north; the e-puck's right) is wbtc's +y. ps2 looks there,
    # 0.16 rad above the horizon.
    assert right[:, 0] == pytest.approx([0.0, np.cos(0.16), np.sin(0.16)], abs=1e-6)
    assert sensors["ps0"].kind == "infra-red"  # the e-puck's, with its lookup table
    simulation.close()


def _collision_boxes(simulation, prefix: str) -> dict[str, tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """Centre, half extents and long axis (world axes) of every collision box of the bodies named `prefix`..."""
    out = {}
    for geom in range(simulation.model.ngeom):
        body = simulation.model.body(simulation.model.geom_bodyid[geom]).name
        box = simulation.model.geom_type[geom] == 6 and simulation.model.geom_group[geom] == 3
        if not body.startswith(prefix) or not box:
            continue
        axes = simulation.from_model @ simulation.data.geom_xmat[geom].reshape(3, 3)
        size = simulation.model.geom_size[geom]
        out[body] = (simulation.from_model @ simulation.data.geom_xpos[geom], np.abs(axes) @ size,
                     axes[:, int(np.argmax(size))])
    return out


def test_an_old_world_thymio_looks_along_its_old_z(tmp_path):
    # Webots' Thymio2 looked along +z with its left wheel on +x until R2021b (its R2019 PROTO:
    # "prox.horizontal.2" at z = +0.0816, "motor.left" at x = +0.05). The maze-runner benchmark
    # (R2020b) turns it half a turn about y to face the maze, along -z.
    world = """#VRML_SIM R2020b utf8
WorldInfo {
  coordinateSystem "NUE"
}
Floor {
}
Thymio2 {
  translation 0 0 0.28
  rotation 0 1 0 3.14159265
  controller "<none>"
}
"""
    simulation = simulation_of(tmp_path, world, "maze.wbt")
    axes = simulation.from_model @ simulation.data.xmat[simulation.robots[0].body].reshape(3, 3)
    assert axes[:, 0] == pytest.approx([0, 0, -1], abs=1e-5)  # forward
    assert axes[:, 1] == pytest.approx([-1, 0, 0], abs=1e-5)  # left
    assert axes[:, 2] == pytest.approx([0, 1, 0], abs=1e-5)  # up
    simulation.close()


def test_old_linked_walls_run_along_z_and_old_maze_blocks_along_x(tmp_path):
    # Webots' R2020b LinkedWalls (wall-following benchmark): segments `length` long along z, `height` high
    # along y, 1 cm thick, the next one turned about y by angle x pi/24 (a positive turn bends towards +x).
    # Its MazeBlock (maze-runner benchmark): `length` along x, 6.5 cm high along y, 1.5 cm thick along z.
    world = """#VRML_SIM R2020b utf8
WorldInfo {
  coordinateSystem "NUE"
}
DEF WALL LinkedWalls {
  translation 5 0.25 0
  angles [ 0 0 2 ]
}
MazeBlock {
  translation 0.36 0.6 0.155
  length 0.2
}
"""
    simulation = simulation_of(tmp_path, world, "walls.wbt")
    walls = _collision_boxes(simulation, "robot/")
    centre, half, along = walls["robot/solid"]
    assert centre == pytest.approx([5, 0.25, 0], abs=1e-9)
    assert half == pytest.approx([0.005, 0.25, 0.5], abs=1e-9)
    assert walls["robot/wall 2"][0] == pytest.approx([5, 0.25, 2], abs=1e-9)
    turn = math.pi / 12
    centre, _, along = walls["robot/wall 3"]
    assert centre == pytest.approx([5 + 0.5 * math.sin(turn), 0.25, 2.5 + 0.5 * math.cos(turn)], abs=1e-9)
    assert abs(along @ [math.sin(turn), 0, math.cos(turn)]) == pytest.approx(1, abs=1e-9)
    centre, half, _ = _collision_boxes(simulation, "maze block")["maze block"]
    assert centre == pytest.approx([0.36, 0.6 + 0.0325, 0.155], abs=1e-9)
    assert half == pytest.approx([0.1, 0.0325, 0.0075], abs=1e-9)
    simulation.close()


def test_an_old_world_road_follows_its_way_points_in_the_old_axes(tmp_path):
    # Before R2022a a Road's way-points were (x, height, z) and `startingAngle` was minus the heading
    # measured from x towards z. This road runs along the old x; it starts turned 0.5 rad towards +z,
    # so its first cross-section (7 m wide) lies along (-sin 0.5, cos 0.5) in the old x-z plane.
    world = """#VRML_SIM R2020b utf8
WorldInfo {
  coordinateSystem "NUE"
}
Road {
  wayPoints [ 0 0 0, 10 0 0 ]
  splineSubdivision 0
  startingAngle [ -0.5 ]
  rightBarrier TRUE
  dashedLine [ FALSE ]
}
"""
    path = tmp_path / "road.wbt"
    path.write_text(world, encoding="utf-8")
    scene, expansion = expand_scene(build_scene(parse_text(world, str(path))), strict=True)
    surface = scene.nodes[1].get("children")[1].get("geometry")
    points = [(p.x, p.y, p.z) if hasattr(p, "x") else tuple(p) for p in surface.get("coord").get("point")]
    # wbtc's Road is drawn in its own (FLU) axes, turned onto the old ones: old (x, y, z) = new (x, z, -y).
    old = [(x, z, -y) for x, y, z in points]
    edge = 3.5 * np.array([-math.sin(0.5), 0, math.cos(0.5)])
    assert np.array(sorted(old[:2])) == pytest.approx(np.array(sorted([tuple(edge), tuple(-edge)])), abs=1e-6)
    assert max(x for x, _, _ in old) == pytest.approx(10, abs=1e-6)  # it ends 10 m along x, on the ground
    assert [y for _, y, _ in old] == pytest.approx([0] * len(old), abs=1e-6)
    # And the model compiles: the crash barrier's blocks are boxes lying along x, not flat along y.
    simulation = simulation_of(tmp_path, world, "road2.wbt")
    simulation.close()
