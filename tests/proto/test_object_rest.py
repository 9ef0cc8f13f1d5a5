"""Objects rest on the floor at Webots' heights: their collision shapes reach as far below their origin as Webots'."""

import math
from pathlib import Path

import mujoco
import numpy as np
import pytest
from conftest import simulation_of

# Where each object's origin rests on a floor at z = 0, from the lowest point of Webots' bounding objects:
# the chair's casters (radius 0.027 m, axles 0.027 m up), the hammer's handle and head (13.5 mm below its
# axis), the screwdriver's handle (radius 0.012 m), the paint bucket's bottom disc (1.2 mm above its origin).
REST = {"OfficeChair": 0.0, "Hammer": 0.0135, "Screwdriver": 0.012, "PaintBucket": -0.0012}
# How far each may settle: the hammer touches the floor with the lowest of its head's boxes alone and
# tips onto its handle (radius 0.0121 m), 0.8 mm lower; the others rest on their lowest points.
SETTLE = {"OfficeChair": 3e-4, "Hammer": 1e-3, "Screwdriver": 3e-4, "PaintBucket": 3e-4}


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
    assert abs(float(moved[2])) < SETTLE[proto]  # was up to 2 cm (the chair fell)


def test_the_office_chair_seat_swivels_on_its_base(tmp_path: Path):
    world = """#VRML_SIM R2025a utf8
WorldInfo { basicTimeStep 16 }
Floor { size 4 4 }
OfficeChair { }
"""
    sim = simulation_of(tmp_path, world)
    try:
        model = sim.model
        hinges = [j for j in range(model.njnt) if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_HINGE]
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
        # differed from Webots' (onto Chair's, WoodenChair's and Armchair's seats: 4.0, 3.2 and 3.0 cm)
        assert float(np.linalg.norm(shift)) < 3e-4, body


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
    world = """#VRML_SIM R2025a utf8
WorldInfo { basicTimeStep 16 }
Floor { size 4 4 }
Cabinet { }
"""
    sim = simulation_of(tmp_path, world)
    try:
        model, data = sim.model, sim.data
        hinges = [j for j in range(model.njnt) if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_HINGE]
        sliders = [j for j in range(model.njnt) if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_SLIDE]
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
