"""Objects rest on the floor at Webots' heights: their collision shapes reach as far below their origin as Webots'."""

import math
from pathlib import Path

import mujoco
import numpy as np
import pytest
from conftest import simulation_of

from wbtc.pipeline import compile_world

# Where each object's origin rests on a floor at z = 0, from the lowest point of Webots' bounding objects:
# the chair's casters (radius 0.027 m, axles 0.027 m up), the hammer's handle and head (13.5 mm below its
# axis), the screwdriver's handle (radius 0.012 m), the paint bucket's bottom disc (1.2 mm above its origin),
# the apple's and the orange's spheres (radius 0.05 m: their default translation), the rubber duck's bottom
# plate (20.5 mm below its origin), the can's cylinder (half its 0.1222 m), the soccer ball's sphere.
REST = {"OfficeChair": 0.0, "Hammer": 0.0135, "Screwdriver": 0.012, "PaintBucket": -0.0012, "Apple": 0.05,
        "Orange": 0.05, "RubberDuck": 0.0205, "Can": 0.0611, "SoccerBall": 0.113}
# How far each may settle: the hammer touches the floor with the lowest of its head's boxes alone and
# tips onto its handle (radius 0.0121 m), 0.8 mm lower; the others rest on their lowest points.
SETTLE = {"Hammer": 1e-3}


def _on_a_floor(objects: str) -> str:
    """A world of `objects` on a 4 m floor."""
    return f"#VRML_SIM R2025a utf8\nWorldInfo {{ basicTimeStep 16 }}\nFloor {{ size 4 4 }}\n{objects}\n"


def _joints(model: mujoco.MjModel, kind: mujoco.mjtJoint) -> list[int]:
    """The model's joints of one type."""
    return [j for j in range(model.njnt) if model.jnt_type[j] == kind]


def _posed(tmp_path: Path, objects: str) -> tuple[mujoco.MjModel, mujoco.MjData]:
    """The compiled model of a world of `objects`, and its data at the written pose."""
    world = tmp_path / "objects.wbt"
    world.write_text(f"#VRML_SIM R2025a utf8\nWorldInfo {{ }}\n{objects}\n")
    result, _ = compile_world(world)
    data = mujoco.MjData(result.model)
    mujoco.mj_forward(result.model, data)
    return result.model, data


def _moved(tmp_path: Path, world: str, bodies: list[str]) -> dict[str, np.ndarray]:
    """How far each of `bodies` (DEF names; those without a joint are left out) moves in 1 s of `world`."""
    sim = simulation_of(tmp_path, world)
    try:
        mujoco.mj_forward(sim.model, sim.data)
        bodies = [b for b in bodies if sim.model.body(b).jntnum[0] > 0]
        start = {b: sim.data.body(b).xpos.copy() for b in bodies}
        while sim.time < 1.0:
            sim.step()
        return {b: sim.data.body(b).xpos - start[b] for b in bodies}
    finally:
        sim.close()


@pytest.mark.parametrize("proto", sorted(REST))
def test_an_object_placed_at_its_resting_height_stays_there(tmp_path: Path, proto: str):
    world = f"""#VRML_SIM R2025a utf8
WorldInfo {{ basicTimeStep 16 }}
Floor {{ size 4 4 }}
DEF OBJECT {proto} {{ translation 0 0 {REST[proto]} name "object" }}
"""
    moved = _moved(tmp_path, world, ["OBJECT"])["OBJECT"]
    # was up to 2 cm (the chair fell; the apple and the orange fell 25 mm, the duck's spheres rose 7 mm)
    assert abs(float(moved[2])) < SETTLE.get(proto, 3e-4)


def test_the_office_chair_seat_swivels_on_its_base(tmp_path: Path):
    sim = simulation_of(tmp_path, _on_a_floor("OfficeChair { }"))
    try:
        model = sim.model
        hinges = _joints(model, mujoco.mjtJoint.mjJNT_HINGE)
        assert len(hinges) == 1
        joint = hinges[0]
        assert list(model.jnt_axis[joint]) == [0.0, 0.0, 1.0]
        assert model.dof_damping[model.jnt_dofadr[joint]] == pytest.approx(1.0)
        masses = sorted(round(float(m), 6) for m in model.body_mass if m > 0)
        assert masses == [3.0, 6.0]  # Webots' seat and base
    finally:
        sim.close()


# Containers and furniture that others rest on or in: (the object, where Webots' bounding object puts the
# upper face of its floor, bed or seat, and where on it a cube is set). The metal box's lowest corner
# lies 0.17 mm below its origin (its end strips are turned 0.015 rad); the wooden chair's legs end 0.44 mm
# above its origin.
HOLDERS = {
    "Chair": ("Chair { physics Physics { density 300 } }", 0.5, 0.0),
    "WoodenChair": ("WoodenChair { translation 0 0 -0.00044 physics Physics { density 300 } }", 0.482 - 0.00044, 0.0),
    "Armchair": ("Armchair { physics Physics { density 100 } }", 0.45, 0.1),
    "MetalStorageBox": ("MetalStorageBox { translation 0 0 0.00017 mass 10 }", 0.004 + 0.00017, 0.0),
    "PlasticCrate": ("PlasticCrate { mass 2 }", 0.021, 0.0),
    "Bed": ("Bed { }", 0.65, 0.3),
    "Sofa": ("Sofa { physics Physics { density -1 mass 30 } }", 0.45, 0.2),
    "WoodenPallet": ("WoodenPallet { mass 20 }", 0.14, 0.0),
    "WoodenPalletStack": ("WoodenPalletStack { palletMass 10 }", 1.12, 0.0),
    "FruitBowl": ("FruitBowl { }", 0.01, 0.0),
    "StraightStairs": ("StraightStairs { }", 0.15, -0.1),  # on the first tread, centred on the origin
    "StraightStairs, under its first tread": ("StraightStairs { }", 0.0, 0.0),  # the risers are open
    # Webots' FloorLight: a base disc 0.05 m high (radius 0.15 m) and a globe of radius 0.2 m centred 1.524 m up.
    "FloorLight base": ("FloorLight { }", 0.05, 0.1),
    "FloorLight globe": ("FloorLight { }", 1.724, 0.0),
    "FloorLight scaled": ("FloorLight { scale 2 }", 0.1, 0.2),  # Webots' `scale` field (unknown before)
}


@pytest.mark.parametrize("proto", sorted(HOLDERS))
def test_a_cube_set_on_a_holder_at_webots_height_stays_there(tmp_path: Path, proto: str):
    holder, top, x = HOLDERS[proto]
    world = f"""#VRML_SIM R2025a utf8
WorldInfo {{ basicTimeStep 16 }}
Floor {{ size 4 4 }}
DEF HOLDER {holder}
DEF CUBE SolidBox {{ translation {x} 0 {top + 0.05} size 0.1 0.1 0.1 physics Physics {{ }} name "cube" }}
"""
    moved = _moved(tmp_path, world, ["HOLDER", "CUBE"])
    assert "CUBE" in moved
    for body, shift in moved.items():  # the cube fell or was pushed up by 1.1 to 12.5 cm when the shapes
        # differed from Webots' (onto Chair's, WoodenChair's and Armchair's seats: 4.0, 3.2 and 3.0 cm; the fruit
        # bowl was a solid drum, 6 cm up; the stairs were 0.2 m further along x, solid down to the floor: the cube
        # fell 15 cm from the first tread or was pushed 5 cm aside from under it; the floor light's base was
        # 3 cm low and narrower, its globe a 0.19 m wide cylinder topped 12 cm lower)
        assert float(np.linalg.norm(shift)) < 3e-4, body


# Road surfaces a cube is set on, where Webots' bounding objects put them: (the road, and the point (x, y,
# height of the surface) under the cube's centre). A 7 m road's crash barrier path is 0.06 + 0.05 * 7 m beyond
# the road edge and its rail is 0.07 to 0.17 m inside the path, 0.4 to 0.8 m high; sidewalks widen
# linearly from start to end; Road's way-points control a cubic B-spline, which passes 1/6 of the way
# from its corner way-point towards each neighbour ((P0 + 4 P1 + P2) / 6); a curved road's surface has no
# gaps where its straight pieces meet; RoadIntersection's sidewalks widen from 0 at the centre polygon to
# their full width where neighbouring sidewalks meet (0.8 m along each road of 4).
_CORNER = ((0 + 4 * 10 + 10) / 6, (0 + 4 * 0 + 10) / 6)
_LEFT = (-math.sqrt(0.5), math.sqrt(0.5))  # the B-spline turns through 45 degrees at its corner
ROAD_SURFACES = {
    "barrier rail": ("StraightRoadSegment { rightBarrier TRUE }", (5, -(3.5 + 0.41 - 0.12), 0.8)),
    "widening sidewalk": ("StraightRoadSegment { endingRoadBorderWidth 2 leftBorderBoundingObject TRUE }",
                          (9.5, 5.2, 0.15)),
    "curved road joint": ("CurvedRoadSegment { roadBoundingObject TRUE }",
                          (13.3 * math.sin(math.pi / 8), 13.3 * math.cos(math.pi / 8), 0.0)),
    "B-spline road": ("Road { wayPoints [0 0 0, 10 0 0, 10 10 0] roadBoundingObject TRUE }",
                      (_CORNER[0] + 3.2 * _LEFT[0], _CORNER[1] + 3.2 * _LEFT[1], 0.0)),
    "intersection sidewalk": ("RoadIntersection { startRoadBorderboundingObject TRUE }",
                              (3.5 * math.sqrt(0.5) + 0.6 * math.sqrt(0.5) + 3.8 * math.sqrt(0.5),
                               3.5 * math.sqrt(0.5) + 0.6 * math.sqrt(0.5) - 3.8 * math.sqrt(0.5), 0.15)),
}


@pytest.mark.parametrize("case", sorted(ROAD_SURFACES))
def test_a_cube_set_on_a_road_part_at_webots_place_stays_there(tmp_path: Path, case: str):
    road, (x, y, top) = ROAD_SURFACES[case]
    world = f"""#VRML_SIM R2025a utf8
WorldInfo {{ basicTimeStep 16 }}
{road}
DEF CUBE SolidBox {{ translation {x} {y} {top + 0.05} size 0.1 0.1 0.1 physics Physics {{ }} name "cube" }}
"""
    shift = _moved(tmp_path, world, ["CUBE"])["CUBE"]
    # the cube fell 0.65 m to 5 m where wbtc's road parts were elsewhere (the rail 0.6 m further out and
    # 5 cm lower, the B-spline road up to 2.6 m away) or missing (gaps, the widening parts of sidewalks)
    assert float(np.linalg.norm(shift)) < 3e-4


def test_a_solid_pipe_lying_on_a_face_of_webots_ring_rests_at_its_apothem(tmp_path: Path):
    # 24 boxes whose corners lie on the radius, the first centred 7.5 degrees from +x: the face centred
    # at 277.5 degrees points down, radius * cos(7.5 degrees) below the axis.
    z = 0.2 * math.cos(math.pi / 24)
    world = f"""#VRML_SIM R2025a utf8
WorldInfo {{ basicTimeStep 16 }}
Floor {{ size 4 4 }}
DEF PIPE SolidPipe {{
  translation 0 0 {z} rotation 0.55046172 0.62768129 0.55046172 2.0205424349
  radius 0.2 thickness 0.02 height 0.5 physics Physics {{ }}
}}
"""
    assert float(np.linalg.norm(_moved(tmp_path, world, ["PIPE"])["PIPE"])) < 3e-4  # 3.4 mm up before


def test_cabinet_doors_turn_and_drawers_slide_as_in_webots(tmp_path: Path):
    sim = simulation_of(tmp_path, _on_a_floor("Cabinet { }"))
    try:
        model, data = sim.model, sim.data
        hinges = _joints(model, mujoco.mjtJoint.mjJNT_HINGE)
        sliders = _joints(model, mujoco.mjtJoint.mjJNT_SLIDE)
        assert len(hinges) == 2 and len(sliders) == 4  # the default layout's two doors and four drawers (none before)
        ranges = sorted(tuple(round(float(v), 2) for v in model.jnt_range[j]) for j in hinges)
        assert ranges == [(-1.57, 0.01), (-0.01, 1.57)]  # each door opens outwards, away from its hinge side
        assert all(model.dof_damping[model.jnt_dofadr[j]] == pytest.approx(5.0) for j in hinges + sliders)
        masses = sorted(round(float(model.body_subtreemass[model.jnt_bodyid[j]]), 4) for j in hinges + sliders)
        assert masses == [1.81, 1.81, 1.85, 1.85, 1.85, 3.85]  # 1.5 or 3.5 kg, the parts' 10 g, the 0.3 kg handle
        mujoco.mj_forward(model, data)
        assert data.ncon == 0  # nothing touches: doors and drawers clear the frame and the shelves
        start = data.qpos.copy()
        while sim.time < 0.5:
            sim.step()
        assert abs(data.qpos - start).max() < 1e-6  # closed, they stay closed
        while sim.time < 1.5:  # pull every door and drawer outwards
            for j in hinges:
                data.qfrc_applied[model.jnt_dofadr[j]] = 2.0 if model.jnt_range[j][1] > 1 else -2.0
            for j in sliders:
                data.qfrc_applied[model.jnt_dofadr[j]] = 5.0
            sim.step()
        opened = [abs(float(data.qpos[model.jnt_qposadr[j]])) for j in hinges + sliders]
        assert all(o > 0.19 for o in opened)  # doors swing wide open, drawers come out to their stops
    finally:
        sim.close()


def test_default_translations_set_objects_where_webots_does(tmp_path: Path):
    # The soccer ball starts 3 mm in the ground (0.11 m for a radius of 0.113 m), the duck 0.5 mm: Webots'
    # defaults, which its contacts push up (wbtc's did too). Both were 0 0 0 (the ball half in the ground).
    world = """#VRML_SIM R2025a utf8
WorldInfo { basicTimeStep 16 }
Floor { size 4 4 }
DEF BALL SoccerBall { }
Pose { translation 1 0 0 children [ DEF DUCK RubberDuck { } ] }
"""
    sim = simulation_of(tmp_path, world)
    try:
        mujoco.mj_forward(sim.model, sim.data)
        assert float(sim.data.body("BALL").xpos[2]) == pytest.approx(0.11)
        assert float(sim.data.body("DUCK").xpos[2]) == pytest.approx(0.02)
    finally:
        sim.close()
    moved = _moved(tmp_path, world, ["BALL", "DUCK"])
    assert float(moved["BALL"][2]) == pytest.approx(0.003, abs=3e-4)
    assert float(moved["DUCK"][2]) == pytest.approx(0.0005, abs=3e-4)


def test_small_objects_have_webots_masses_shapes_damping_and_recognition_colours(tmp_path: Path):
    world = tmp_path / "objects.wbt"
    world.write_text("""#VRML_SIM R2025a utf8
WorldInfo { basicTimeStep 16 }
DEF DUCK RubberDuck { }
DEF BIG_APPLE Apple { scale 2 }
DEF BOWL FruitBowl { }
DEF CAN Can { }
""")
    result, _ = compile_world(world)
    model = result.model
    duck = model.body("DUCK")
    # 400 kg/m3 times the volume of Webots' eight shapes (two boxes, a sphere, four capsules, a cylinder); two
    # spheres made 0.098 kg. Webots' centre of mass is the origin, its damping 0.5 (half the speed a second).
    assert float(duck.mass[0]) == pytest.approx(0.158, abs=5e-4)
    assert list(duck.ipos) == pytest.approx([0, 0, 0])
    assert result.table.linear_damping["DUCK"] == pytest.approx(float(duck.mass[0]) * math.log(2))
    apple = model.body("BIG_APPLE")
    spheres = [g for g in range(model.ngeom) if model.geom_bodyid[g] == apple.id and model.geom_contype[g]]
    assert [round(float(model.geom_size[g][0]), 4) for g in spheres] == [0.1]  # 0.05 m times the scale (was 0.025)
    assert float(apple.mass[0]) == pytest.approx(0.15)
    assert float(model.body("BOWL").mass[0]) == pytest.approx(0.5)
    colours = {r.model: r.colors for r in result.table.recognizable}
    assert colours == {"rubber duck": [[0.87451, 0.756863, 0.113725]], "apple": [[0.59, 0.75, 0.28]],
                       "can": [[0.666667, 0.0, 0.0]]}  # none before


def test_the_stairs_stringers_collide_beside_the_treads(tmp_path: Path):
    model, data = _posed(tmp_path, "StraightStairs { }")
    spans = {}
    for g in range(model.ngeom):
        name = model.body(model.geom_bodyid[g]).name
        if "stringer" in name and model.geom_contype[g] and model.geom_type[g] == mujoco.mjtGeom.mjGEOM_MESH:
            mesh = model.geom_dataid[g]
            start, count = model.mesh_vertadr[mesh], model.mesh_vertnum[mesh]
            points = model.mesh_vert[start:start + count] @ data.geom_xmat[g].reshape(3, 3).T + data.geom_xpos[g]
            spans[name] = np.round(np.concatenate([points.min(0), points.max(0)]), 4).tolist()
    # from the floor under the first tread's front edge to 2 rises above the last tread's back edge, 2 cm thick
    # beside the 1.27 m treads (the stringers did not collide before)
    assert spans == {"right stringer": [-0.2, -0.655, 0.0, 1.8, -0.635, 0.9],
                     "left stringer": [-0.2, 0.635, 0.0, 1.8, 0.655, 0.9]}


def test_the_door_lever_collides_as_webots_rose_bar_and_handles(tmp_path: Path):
    model, data = _posed(tmp_path, "Door { }")
    lever = model.body("door lever").id
    shapes = sorted((mujoco.mjtGeom(model.geom_type[g]).name, round(float(model.geom_size[g][0]), 4),
                     round(float(model.geom_size[g][1]), 4), round(float(data.geom_xpos[g][1]), 3))
                    for g in range(model.ngeom) if model.geom_bodyid[g] == lever and model.geom_contype[g])
    # the rose (radius 3 x 12.5 mm across the 5 cm door), the bar (2 x 6.5 cm + 5 cm) and two handles of 12 cm
    # pointing from the bar (0.4 m from the door's axis) towards the hinge (-y); before: two thin boxes
    # pointing past the door's edge
    assert shapes == [("mjGEOM_CAPSULE", 0.0125, 0.06, 0.34), ("mjGEOM_CAPSULE", 0.0125, 0.06, 0.34),
                      ("mjGEOM_CAPSULE", 0.0125, 0.09, 0.4), ("mjGEOM_CYLINDER", 0.0375, 0.0375, 0.4)]
    assert float(model.body_mass[lever]) == pytest.approx(0.7)
