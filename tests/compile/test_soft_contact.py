"""ODE's soft contact (softERP, softCFM) and hard Coulomb friction in the compiled model (wbtc.compile.soft_contact)."""

import json
from pathlib import Path

import mujoco
import pytest

from wbtc.compile import soft_contact
from wbtc.compile.context import CompileOptions
from wbtc.pipeline import compile_world

#: A floor, a 100 kg box (1 x 1 x 0.2 m) and a 0.1 kg box (0.1 x 0.1 x 0.02 m), both on it.
_WORLD = """#VRML_SIM R2023b utf8
WorldInfo {{
  basicTimeStep {step}
  contactProperties [ {laws} ]
}}
Solid {{ contactMaterial "{floor}" boundingObject Plane {{ size 20 20 }} }}
DEF HEAVY Solid {{
  translation 0 0 0.1
  boundingObject Box {{ size 1 1 0.2 }}
  physics Physics {{ density -1 mass 100 }}
}}
DEF LIGHT Solid {{
  translation 3 0 0.01
  name "light"
  boundingObject Box {{ size 0.1 0.1 0.02 }}
  physics Physics {{ density -1 mass 0.1 }}
}}
"""


def _model(tmp_path: Path, step: int = 32, laws: str = "", floor: str = "default",
           ode: bool = True) -> mujoco.MjModel:
    world = tmp_path / "boxes.wbt"
    world.write_text(_WORLD.format(step=step, laws=laws, floor=floor))
    result, _ = compile_world(world, CompileOptions(ode_contacts=ode))
    return result.model


def _settle(model: mujoco.MjModel, seconds: float = 1.0) -> mujoco.MjData:
    data = mujoco.MjData(model)
    for _ in range(round(seconds / model.opt.timestep)):
        mujoco.mj_step(model, data)
    return data


@pytest.mark.parametrize(("step", "laws", "kp"), [
    (32, "", 0.2 / (0.032 * 0.001)),  # Webots' default contact: 6250 N/m per point at 32 ms
    (16, "", 0.2 / (0.016 * 0.001)),  # 12500 N/m at 16 ms
    (32, "ContactProperties { softERP 0.4 softCFM 0.0001 }", 0.4 / (0.032 * 0.0001)),
])
def test_a_resting_box_sinks_by_its_weight_over_odes_contact_spring(tmp_path, step, laws, kp):
    data = _settle(_model(tmp_path, step, laws))
    # Each box rests on its four corners: depth = m g / (4 kp), for any mass (a 100 kg box at 32 ms: 3.92 cm).
    assert 0.1 - data.qpos[2] == pytest.approx(100 * 9.81 / (4 * kp), rel=1e-4)
    assert 0.01 - data.qpos[9] == pytest.approx(0.1 * 9.81 / (4 * kp), rel=1e-3)


def test_static_geoms_leave_their_contacts_to_the_moving_body(tmp_path):
    model = _model(tmp_path)
    floor = next(g for g in range(model.ngeom) if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_PLANE)
    assert model.geom_solmix[floor] == 0.0
    assert list(model.geom_solref[floor]) == list(soft_contact.STATIC_SOLREF)
    heavy = next(g for g in range(model.ngeom) if model.body_mass[model.geom_bodyid[g]] == 100.0)
    diag = float(model.body_invweight0[model.geom_bodyid[heavy], 0])
    terms = soft_contact.row_terms(soft_contact.Softness(), 0.032, model.opt.timestep)
    assert model.geom_solimp[heavy, 0] == pytest.approx(diag / (diag + terms.r))
    assert model.geom_solmix[heavy] == pytest.approx(diag)
    assert model.opt.impratio == soft_contact.FRICTION_IMPRATIO
    assert model.opt.noslip_iterations == soft_contact.NOSLIP_ITERATIONS


@pytest.mark.parametrize(("speed", "floor", "laws", "mu"), [
    (1.0, "default", "", 1.0),
    (3.0, "default", "", 1.0),
    # A floor whose material has a ContactProperties: its priority pairs it with each moving geom.
    (1.0, "ice", 'ContactProperties { material1 "ice" coulombFriction [ 0.2 ] }', 0.2),
])
def test_a_sliding_box_slides_as_coulomb_says_without_hopping(tmp_path, speed, floor, laws, mu):
    model = _model(tmp_path, laws=laws, floor=floor)
    data = _settle(model)
    rest, start = data.qpos[[2, 9]].copy(), data.qpos[[0, 7]].copy()
    data.qvel[0] = data.qvel[6] = speed
    highest = rest.copy()
    for _ in range(round(2.5 / model.opt.timestep)):
        mujoco.mj_step(model, data)
        highest = [max(highest[0], data.qpos[2]), max(highest[1], data.qpos[9])]
    # Coulomb: v^2 / (2 mu g), within 5 % (a 1 m/s slide stops 3 % short; ODE's 32 ms Euler steps: 30 %).
    # MuJoCo's default contact hopped a box slid at 3 m/s by 1.9 cm, and ODE's soft normal rows with stiff
    # friction rows in the same solve by 7 cm (100 kg); the noslip pass solves the friction.
    for travelled in (data.qpos[0] - start[0], data.qpos[7] - start[1]):
        assert travelled == pytest.approx(speed**2 / (2 * mu * 9.81), rel=0.05)
    assert highest[0] - rest[0] < 1e-5
    assert highest[1] - rest[1] < 3e-3 * speed / 3.0
    assert rest[0] == pytest.approx(0.1 - 100 * 9.81 / (4 * 6250), rel=1e-4)  # the pair has ODE's softness too


def test_without_the_option_contacts_stay_mujocos_and_soft_fields_are_listed(tmp_path):
    model = _model(tmp_path, laws="ContactProperties { softCFM 0.0001 }", ode=False)
    assert model.opt.noslip_iterations == 0 and model.opt.impratio == 1.0
    assert {tuple(model.geom_solref[g]) for g in range(model.ngeom)} == {(0.01, 1.0)}
    data = _settle(model)
    assert 0.1 - data.qpos[2] < 1e-3  # the 100 kg box hardly sinks
    world = tmp_path / "boxes.wbt"
    result, _ = compile_world(world)
    assert any("softCFM" in w.message and "not honoured" in w.message for w in result.warnings)
    result, _ = compile_world(world, CompileOptions(ode_contacts=True))
    assert not any("softCFM" in w.message for w in result.warnings)


_ROBOT = """#VRML_SIM R2025a utf8
WorldInfo { basicTimeStep 32 }
Solid { boundingObject Plane { size 10 10 } }
Robot {
  translation 0 0 0.1
  boundingObject Box { size 1 1 0.2 }
  physics Physics { density -1 mass 100 }
  controller "<none>"
}
"""


@pytest.mark.parametrize(("flags", "height"), [([], 0.1), (["--ode-contacts"], 0.1 - 100 * 9.81 / (4 * 6250))])
def test_wbtc_run_takes_the_option(tmp_path, flags, height):
    from typer.testing import CliRunner

    from wbtc.cli import app

    world = tmp_path / "heavy.wbt"
    world.write_text(_ROBOT)
    outcome = CliRunner().invoke(app, ["run", str(world), "--headless", "--json", "--duration", "1", *flags])
    assert outcome.exit_code == 0, outcome.output
    robot = json.loads(outcome.output.strip().splitlines()[-1])["robots"][0]
    assert robot["position"][2] == pytest.approx(height, abs=1e-4)
