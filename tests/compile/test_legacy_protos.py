"""Library robots and floors in worlds written before R2022a (RUB PROTOs then, FLU ones in wbtc's library)."""

import numpy as np
import pytest
from conftest import simulation_of

from wbtc.runtime import poses

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
