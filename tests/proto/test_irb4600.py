"""wbtc's ABB IRB 4600/40: Webots' devices in order, its kinematic chain, motors that hold the arm.

The corpus world that uses it (`inverse_kinematics.wbt`) is compiled, stepped and exported by
tests/compile/test_corpus_compile.py."""

from pathlib import Path

import mujoco
import numpy as np
import pytest
from conftest import simulation_of

WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/robots/abb/irb/protos/Irb4600-40.proto"
WorldInfo { basicTimeStep 16 }
Irb4600-40 {
  controller "<none>"
  staticBase TRUE
  handSlot [ Solid { name "tool" } ]
}
"""
MOTORS = "ABCDEF"
LIMITS = {"A": (-3.1415, 3.1415), "B": (-1.5708, 2.61799), "C": (-3.1415, 1.309), "D": (-6.98132, 6.98132),
          "E": (-2.18166, 2.0944), "F": (-6.98132, 6.98132)}
# Webots' Irb4600-40.proto (R2022b): each joint's anchor, which is also its endPoint's translation, and
# its axis (D and F keep HingeJointParameters' default axis 1 0 0); the hand slot is 0.06 m along x
# beyond F.
CHAIN = [((0, 0, 0.159498), (0, 0, 1)), ((0.178445, -0.122498, 0.334888), (0, 1, 0)),
         ((-0.003447, -0.0267, 1.095594), (0, 1, 0)), ((0.340095, 0.149198, 0.174998), (1, 0, 0)),
         ((0.929888, 0, 0), (0, 1, 0)), ((0.125, 0, 0), (1, 0, 0))]
HAND = (0.06, 0, 0)


def _rotation(axis, angle: float) -> np.ndarray:
    x, y, z = axis
    k = np.array([[0, -z, y], [z, 0, -x], [-y, x, 0]], dtype=float)
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k


def _hand(angles) -> np.ndarray:
    """The hand slot's origin, forward kinematics of Webots' numbers (the base at the origin)."""
    position, frame = np.zeros(3), np.eye(3)
    for (offset, axis), angle in zip(CHAIN, angles, strict=True):
        position = position + frame @ np.array(offset)
        frame = frame @ _rotation(axis, angle)
    return position + frame @ np.array(HAND)


@pytest.fixture
def sim(tmp_path: Path):
    simulation = simulation_of(tmp_path, WORLD, "irb.wbt")
    yield simulation
    simulation.close()


def test_devices_in_webots_order_limits_and_masses(sim):
    entry = sim.table.robots[0]
    assert [d.name for d in entry.devices] == [n for m in MOTORS for n in (f"{m} motor", f"{m} sensor")]
    devices = {d.name: d for d in entry.devices}
    for motor, (low, high) in LIMITS.items():
        fields = devices[f"{motor} motor"].fields
        assert (fields["minPosition"], fields["maxPosition"], fields["maxVelocity"], fields["maxTorque"]) == (
            low, high, 10, 10000)
    # Webots' densities over each link's bounding box (the base is pinned: no mass of its own).
    masses = [1150 * 0.621392 * 0.540918 * 0.552493, 500 * 0.279997 * 0.256948 * 1.335994,
              400 * 0.533578 * 0.398651 * 0.472912, 300 * 1.040973 * 0.228038 * 0.195956,
              200 * 0.159731 * 0.130998 * 0.160194, 100 * 0.069993 * 0.125817 * 0.125113]
    model = sim.model
    assert model.body_subtreemass[model.body(entry.body).id] == pytest.approx(sum(masses), rel=1e-6)


def test_the_hand_slot_follows_webots_kinematics(sim):
    model, data = sim.model, sim.data
    tool = model.body("IRB 4600/40/tool").id
    # Zero angles: x = 0.178445 - 0.003447 + 0.340095 + 0.929888 + 0.125 + 0.06 = 1.629981,
    # y = -0.122498 - 0.0267 + 0.149198 = 0, z = 0.159498 + 0.334888 + 1.095594 + 0.174998 = 1.764978.
    assert data.xpos[tool] == pytest.approx([1.629981, 0, 1.764978], abs=1e-6)
    assert _hand([0] * 6) == pytest.approx([1.629981, 0, 1.764978], abs=1e-9)
    # The hand slot's +z points out of the flange (Webots turns it 2π/3 about (1, 1, 1)).
    assert data.xmat[tool].reshape(3, 3)[:, 2] == pytest.approx([1, 0, 0], abs=1e-5)
    angles = [0.5, -0.4, 0.6, 0.7, -0.8, 0.9]
    entry = sim.table.robots[0]
    for device, angle in zip([d for d in entry.devices if d.name.endswith("motor")], angles, strict=True):
        data.qpos[model.joint(device.joint).qposadr[0]] = angle
    mujoco.mj_forward(model, data)
    assert data.xpos[tool] == pytest.approx(_hand(angles), abs=1e-6)


def test_motors_hold_the_arm_against_gravity(sim):
    tool = sim.model.body("IRB 4600/40/tool").id
    start = sim.data.xpos[tool].copy()
    while sim.time < 1.0:  # untouched motors hold their joints (about 100 kg of links beyond B)
        sim.step()
    assert np.linalg.norm(sim.data.xpos[tool] - start) < 1e-3
    assert abs(sim.data.qpos).max() < 1e-3
