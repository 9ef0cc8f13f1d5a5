"""A Solid's mass and inertia from several bounding objects (Webots' api/motor arm), about its hinge.

Physics `density -1, mass 1` shares the mass by volume (density × volume with one density, scaled to the
mass); each cylinder keeps ODE's own inertia (½ m r² about its axis, m (3 r² + h²) / 12 across), turned
with its Transform and moved to the common centre of mass (parallel axes).
"""

import math
from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.pipeline import compile_world

WORLD = Path(__file__).parents[1] / "conformance" / "api" / "worlds" / "motor.wbt"


def _arm_inertia_about_the_hinge() -> tuple[float, float]:
    """(mass, inertia about the hinge axis through its anchor) of the motor world's arm, as compiled."""
    result, _ = compile_world(WORLD)
    model = result.model
    # The hinges without an end point carry no mass; the arm is the one with Physics.
    hinges = [j for j in range(model.njnt) if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_HINGE]
    joint = max(hinges, key=lambda j: model.body_mass[model.jnt_bodyid[j]])
    body = int(model.jnt_bodyid[joint])
    rot = np.zeros(9)
    mujoco.mju_quat2Mat(rot, model.body_iquat[body])
    rot = rot.reshape(3, 3)
    inertia = rot @ np.diag(model.body_inertia[body]) @ rot.T  # about the centre of mass, body axes
    axis = model.jnt_axis[joint] / np.linalg.norm(model.jnt_axis[joint])
    offset = model.body_ipos[body] - model.jnt_pos[joint]
    across = offset - axis * (offset @ axis)
    mass = float(model.body_mass[body])
    return mass, float(axis @ inertia @ axis + mass * across @ across)


def test_the_arm_of_two_cylinders_has_0_00492_kg_m2_about_its_hinge():
    mass, inertia = _arm_inertia_about_the_hinge()
    thick, thin = math.pi * 0.02 ** 2 * 0.05, math.pi * 0.005 ** 2 * 0.3  # volumes: the share of the 1 kg
    m_thick, m_thin = thick / (thick + thin), thin / (thick + thin)
    # The thick cylinder stands on the hinge axis; the thin one lies across it, its centre 0.1 m out.
    expected = 0.5 * m_thick * 0.02 ** 2 + m_thin * (3 * 0.005 ** 2 + 0.3 ** 2) / 12 + m_thin * 0.1 ** 2
    assert mass == pytest.approx(1.0)
    assert inertia == pytest.approx(expected, rel=1e-9)
    assert inertia == pytest.approx(0.00491989, abs=1e-8)  # x 5 rad/s^2: the 0.02460 N m wbtc reads
