"""Joint stops as ODE's stop rows in the compiled model (wbtc.compile.joint_stops)."""

from pathlib import Path

import mujoco
import pytest

from wbtc.compile import joint_stops
from wbtc.compile.soft_contact import Softness, row_terms
from wbtc.pipeline import compile_world

#: A motor turning a light gear (4e-8 kg m²) that carries a 0.16 kg pendulum on a hinge free within
#: +-0.1 rad (stopERP 0, as Webots' HingeJointWithBacklash), and a second arm whose stops keep
#: WorldInfo's ERP and CFM (or its own stopCFM).
_WORLD = """#VRML_SIM R2025a utf8
WorldInfo {{ basicTimeStep 16 gravity 0 {world} }}
Robot {{
  children [
    HingeJoint {{
      jointParameters HingeJointParameters {{ axis 0 0 1 }}
      device [ RotationalMotor {{ name "motor" }} ]
      endPoint Solid {{
        name "gear"
        children [
          HingeJoint {{
            jointParameters HingeJointParameters {{ axis 0 0 1 minStop -0.1 maxStop 0.1 stopERP 0 }}
            endPoint Solid {{
              translation 0 -0.2 0
              name "pendulum"
              boundingObject Box {{ size 0.02 0.4 0.02 }}
              physics Physics {{ }}
            }}
          }}
        ]
        physics Physics {{ density -1 mass 0.1 centerOfMass [ 0 0 0 ] inertiaMatrix [ 4e-8 4e-8 4e-8, 0 0 0 ] }}
      }}
    }}
    HingeJoint {{
      jointParameters HingeJointParameters {{ axis 0 0 1 anchor 1 0 0 minStop -0.5 maxStop 0.5 {arm} }}
      endPoint Solid {{
        translation 1 -0.2 0
        name "arm"
        boundingObject Box {{ size 0.02 0.4 0.02 }}
        physics Physics {{ }}
      }}
    }}
  ]
  name "rig"
  controller "<none>"
}}
"""


def _model(tmp_path: Path, world: str = "", arm: str = "") -> mujoco.MjModel:
    path = tmp_path / "stops.wbt"
    path.write_text(_WORLD.format(world=world, arm=arm), encoding="utf-8")
    result, _ = compile_world(path)
    assert result.warnings == []
    return result.model


def _limit_row(model: mujoco.MjModel, joint: str, position: float) -> tuple[float, float, float]:
    """(R, K·imp, B) of the joint's limit row with the joint at `position` (past its upper stop)."""
    data = mujoco.MjData(model)
    joint_id = model.joint(joint).id
    data.qpos[model.jnt_qposadr[joint_id]] = position
    mujoco.mj_forward(model, data)
    (row,) = [i for i in range(data.nefc) if data.efc_type[i] == mujoco.mjtConstraint.mjCNSTR_LIMIT_JOINT
              and data.efc_id[i] == joint_id]
    # MuJoCo's direct solref is (-K·dmax², -B·dmax) with dmax = imp: K·imp and B are solref / -imp.
    stiffness, damping = -model.jnt_solref[joint_id] / float(model.jnt_solimp[joint_id, 0])
    return float(data.efc_R[row]), float(stiffness), float(damping)


def test_a_light_links_stop_with_stop_erp_0_is_odes_hard_row(tmp_path: Path) -> None:
    model = _model(tmp_path)
    dof = model.jnt_dofadr[model.joint("rig/pendulum").id]
    # ODE's row at the 2 ms substep: ERP 0 is a pure damper 1 / CFM, so CFM_s = CFM and R = 1e-5 / 0.002.
    r, k_imp, b = _limit_row(model, "rig/pendulum", 0.15)
    assert r == pytest.approx(5e-3, rel=1e-9)
    assert k_imp == 0.0  # stopERP 0: the penetration is never pushed back
    assert b == pytest.approx(1 / 0.002, rel=1e-9)  # the velocity into the stop is stopped within a substep
    # The gear's dof weighs 1 / 4e-8 + 1 / I_pendulum: its diagApprox is lowered to the largest that MuJoCo's
    # impedance (at most 0.9999) can still give R with.
    assert model.dof_invweight0[dof] == pytest.approx(5e-3 * 0.9999 / 1e-4, rel=1e-9)
    assert model.jnt_solimp[model.joint("rig/pendulum").id, 0] == pytest.approx(0.9999)


@pytest.mark.parametrize(("world", "arm", "erp", "cfm"), [
    ("", "", 0.2, 1e-5),  # stopERP and stopCFM -1: WorldInfo's defaults
    ("ERP 0.4 CFM 1e-4", "", 0.4, 1e-4),  # WorldInfo's own
    ("ERP 0.4 CFM 1e-4", "stopCFM 1e-6", 0.4, 1e-6),  # the joint's stopCFM, WorldInfo's ERP
])
def test_a_stop_takes_its_erp_and_cfm_from_its_parameters_or_worldinfo(tmp_path, world, arm, erp, cfm) -> None:
    model = _model(tmp_path, world, arm)
    # ODE's ERP and CFM at 16 ms are a spring and damper, re-expressed at the 2 ms substep.
    kp, kd = erp / (0.016 * cfm), (1 - erp) / cfm
    cfm_s = 1 / (0.002 * kp + kd)
    r, k_imp, b = _limit_row(model, "rig/arm", 0.55)
    assert r == pytest.approx(cfm_s / 0.002, rel=1e-9)
    assert k_imp == pytest.approx(0.002 * kp * cfm_s / 0.002**2, rel=1e-9)
    assert b == pytest.approx(1 / 0.002, rel=1e-9)
    assert joint_stops.stop_softness(None, erp, cfm) == Softness(erp, cfm)
    assert row_terms(Softness(erp, cfm), 0.016, 0.002).r == pytest.approx(r, rel=1e-9)
