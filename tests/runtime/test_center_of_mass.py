"""Supervisor getCenterOfMass and getContactPoints on Webots' center_of_mass_and_contact_points world.

Robot 1 (a box on four cylinder legs, Physics with the given centerOfMass) carries a descendant Solid
(another leg, default Physics): the centre of mass is that of the whole tree, in the world's (NUE) axes.
"""

import math
from pathlib import Path

import pytest

from wbtc.compile.compiler import compile_scene
from wbtc.pipeline import load_world
from wbtc.runtime import supervisor_queries
from wbtc.runtime.simulation import Simulation
from wbtc.runtime.supervisor import SupervisorError, SupervisorHub

WORLD = Path(__file__).parents[1] / "conformance" / "api" / "worlds" / "center_of_mass_and_contact_points.wbt"


@pytest.fixture(scope="module")
def hub():
    scene, _ = load_world(WORLD)
    sim = Simulation(compile_scene(scene), noise=False)
    supervisor = next(r for r in sim.robots if r.entry.name == "robot")
    yield SupervisorHub(sim, scene, WORLD), supervisor, sim
    sim.close()


def _robot_1(hub, supervisor) -> tuple[int, int]:
    secondary = hub.call(supervisor, "getFromDef", ("SECONDARY_SOLID", -1))
    return secondary["parent"], secondary["id"]


def test_the_centre_of_mass_sums_the_solid_tree_in_world_axes(hub):
    hub, supervisor, _ = hub
    robot, _ = _robot_1(hub, supervisor)
    com = hub.call(supervisor, "node.getCenterOfMass", (robot,))
    # Density 1000 on both: the box (0.1 m side) and four legs (r 0.015, h 0.05) of robot 1, whose given
    # centerOfMass is 6.193 mm below its origin, and the descendant's leg centred 5 cm below it.
    leg = math.pi * 0.015 ** 2 * 0.05 * 1000
    own, child, origin = 0.001 * 1000 + 4 * leg, leg, 0.074888
    y = (own * (origin - 0.00619306) + child * (origin - 0.05)) / (own + child)
    assert com == pytest.approx([0.0, y, 0.0], abs=1e-9)
    # Webots' reference after its first step (the test allows 1e-5 in all): the robot rests where ODE left it.
    assert sum(abs(a - b) for a, b in zip(com, [0.0, 0.067383, 0.0], strict=True)) < 1e-5


def test_contact_points_belong_to_the_solid_or_its_descendants(hub):
    hub, supervisor, sim = hub
    robot, secondary = _robot_1(hub, supervisor)
    own = hub.call(supervisor, "node.getContactPoints", (robot, False))
    with_descendants = hub.call(supervisor, "node.getContactPoints", (robot, True))
    # MuJoCo's cylinder-plane collider gives 3 points per resting leg (a triangle on the rim) where ODE's
    # gives 4 (a cross): 12 + 4 with the e-puck's box (which starts 4.5 mm inside robot 1's box) and 15 + 4
    # here, against Webots' 16 + 4 and 24.
    assert len(own) == 16 and len(with_descendants) == 19
    assert {node for _, node in own} == {robot}
    assert [node for _, node in with_descendants].count(secondary) == 3
    # Solid by Solid, the node's own first (Webots: the last point is the descendant's).
    assert [node for _, node in with_descendants] == [robot] * 16 + [secondary] * 3
    # The legs' points lie on the floor, half their 0.112 mm depth (ODE's rest depth, as the world saved it).
    on_floor = [point for point, _ in with_descendants if abs(point[1]) < 1e-3]
    assert len(on_floor) == 15 and all(abs(point[1] + 0.000056) < 1e-6 for point in on_floor)


def test_a_solid_inside_another_lists_its_own_points_but_no_descendants(hub):
    # WbSolid::extractContactPoints counts a point for includeDescendants when one of its solids' topSolid()
    # is the node: only a top Solid has such points.
    hub, supervisor, _ = hub
    _, secondary = _robot_1(hub, supervisor)
    assert len(hub.call(supervisor, "node.getContactPoints", (secondary, False))) == 3
    assert hub.call(supervisor, "node.getContactPoints", (secondary, True)) == []
    box = hub.call(supervisor, "getFromDef", ("SLOT_SOLID", -1))["id"]  # in the e-puck's turret slot
    assert len(hub.call(supervisor, "node.getContactPoints", (box, False))) == 4
    assert hub.call(supervisor, "node.getContactPoints", (box, True)) == []


def test_robot_1_is_statically_balanced_on_its_legs(hub):
    # Webots' check: the centre of mass projects, along gravity, inside the hull of the contact points.
    hub, supervisor, _ = hub
    robot, _ = _robot_1(hub, supervisor)
    assert hub.call(supervisor, "node.getStaticBalance", (robot,)) is True


def test_static_balance_wants_a_top_solid(hub):
    hub, supervisor, _ = hub
    _, secondary = _robot_1(hub, supervisor)
    with pytest.raises(SupervisorError) as error:
        hub.call(supervisor, "node.getStaticBalance", (secondary,))
    assert str(error.value) == ("Warning: wb_supervisor_node_get_static_balance() can exclusively be used with a "
                                "top Solid")


def test_the_support_polygon_is_the_hull_of_the_points():
    # Four legs' crosses (the inner points fall inside), and a point past an edge.
    points = [(x + dx, y + dy) for x in (-1.0, 1.0) for y in (-1.0, 1.0)
              for dx, dy in ((0.2, 0.0), (-0.2, 0.0), (0.0, 0.2), (0.0, -0.2))]
    hull = supervisor_queries._convex_hull(points)
    assert len(hull) == 8 and set(hull) <= set(points)
    assert supervisor_queries._inside((0.0, 0.0), hull)
    assert supervisor_queries._inside((1.2, 0.0), hull)  # on an edge
    assert not supervisor_queries._inside((1.21, 0.0), hull)
    assert supervisor_queries._convex_hull([(0.0, 0.0), (1.0, 1.0), (2.0, 2.0)]) == [(0.0, 0.0), (2.0, 2.0)]
