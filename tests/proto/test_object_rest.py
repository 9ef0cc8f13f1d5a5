"""Objects rest on the floor at Webots' heights: their collision shapes reach as far below their origin as Webots'."""

from pathlib import Path

import mujoco
import pytest
from conftest import simulation_of

# Where each object's origin rests on a floor at z = 0, from the lowest point of Webots' bounding objects:
# the chair's casters (radius 0.027 m, axles 0.027 m up), the hammer's handle and head (13.5 mm below its
# axis), the screwdriver's handle (radius 0.012 m), the paint bucket's bottom disc (1.2 mm above its origin).
REST = {"OfficeChair": 0.0, "Hammer": 0.0135, "Screwdriver": 0.012, "PaintBucket": -0.0012}
# How far each may settle: the hammer touches the floor with the lowest of its head's boxes alone and
# tips onto its handle (radius 0.0121 m), 0.8 mm lower; the others rest on their lowest points.
SETTLE = {"OfficeChair": 3e-4, "Hammer": 1e-3, "Screwdriver": 3e-4, "PaintBucket": 3e-4}


@pytest.mark.parametrize("proto", sorted(REST))
def test_an_object_placed_at_its_resting_height_stays_there(tmp_path: Path, proto: str):
    world = f"""#VRML_SIM R2025a utf8
WorldInfo {{ basicTimeStep 16 }}
Floor {{ size 4 4 }}
DEF OBJECT {proto} {{ translation 0 0 {REST[proto]} name "object" }}
"""
    sim = simulation_of(tmp_path, world)
    try:
        mujoco.mj_forward(sim.model, sim.data)
        z0 = float(sim.data.body("OBJECT").xpos[2])
        while sim.time < 1.0:
            sim.step()
        assert abs(float(sim.data.body("OBJECT").xpos[2]) - z0) < SETTLE[proto]  # was up to 2 cm (the chair fell)
    finally:
        sim.close()


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
