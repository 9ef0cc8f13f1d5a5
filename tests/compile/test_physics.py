"""Physical checks of compiled worlds: rest, free fall, joint zero positions, axes, masses, motors, friction, time.

Each check compiles a small world of tests/compile/fixtures/worlds and asserts numbers Webots would give
(see /work/shared/reference/webots.md sections 1.7, 2 and 4 for the rules).
"""

import math
from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.compile.context import CompileOptions
from wbtc.compile.frames import axis_angle_quat, quat_to_mat
from wbtc.pipeline import compile_world

WORLDS = Path(__file__).parent / "fixtures" / "worlds"


def compile_fixture(name: str, options: CompileOptions | None = None):
    """The CompileResult of a fixture world; no warning is expected from these worlds."""
    result, expansion = compile_world(WORLDS / name, options)
    assert expansion.warnings == [] and result.warnings == [], (expansion.warnings, result.warnings)
    return result


def step_for(model: mujoco.MjModel, data: mujoco.MjData, seconds: float) -> None:
    for _ in range(round(seconds / model.opt.timestep)):
        mujoco.mj_step(model, data)


def same_rotation(q1: np.ndarray, q2: np.ndarray) -> float:
    """The largest difference between the rotation matrices of two quaternions."""
    return float(np.abs(quat_to_mat(np.asarray(q1)) - quat_to_mat(np.asarray(q2))).max())


# ----------------------------------------------------------------------------------------- the e-puck


def test_epuck_rests_on_the_arena_with_wheels_held() -> None:
    result = compile_fixture("epuck_rest.wbt")
    model = result.model
    robot = result.table.robot("e-puck")
    assert robot is not None
    body = model.body(robot.body).id
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    start = data.xpos[body].copy()
    assert np.allclose(start, [0, 0, 0], atol=1e-9)
    for _ in range(round(2.0 / model.opt.timestep)):
        data.ctrl[:] = 0.0  # velocity target 0: the wheels hold
        mujoco.mj_step(model, data)
    drift = np.linalg.norm(data.xpos[body] - start)
    assert drift < 1e-3, f"the e-puck drifted {drift * 1000:.3f} mm in 2 s"
    assert np.abs(data.qvel).max() < 1e-2


def test_epuck_total_mass_is_body_plus_two_wheels() -> None:
    result = compile_fixture("epuck_rest.wbt")
    body = result.model.body(result.table.robot("e-puck").body).id
    assert result.model.body_subtreemass[body] == pytest.approx(0.15 + 2 * 0.005, abs=1e-12)
    assert result.model.body_mass[body] == pytest.approx(0.15, abs=1e-12)


# ----------------------------------------------------------------------------------------- free fall


def test_box_dropped_from_one_metre_touches_the_floor_at_0_45_s() -> None:
    result = compile_fixture("drop_box.wbt")
    model = result.model
    box, floor = model.body("box").id, model.body("floor").id
    data = mujoco.MjData(model)

    def touching() -> bool:
        for contact in data.contact[:data.ncon]:
            bodies = {int(model.geom_bodyid[contact.geom1]), int(model.geom_bodyid[contact.geom2])}
            if bodies == {box, floor}:
                return True
        return False

    while not touching():
        assert data.time < 1.0, "the box never reached the floor"
        mujoco.mj_step(model, data)
    # Free fall of the box's bottom face through 0.95 m: sqrt(2 × 0.95 / 9.81) = 0.440 s.
    assert data.time == pytest.approx(0.45, abs=0.02)
    assert data.time == pytest.approx(math.sqrt(2 * 0.95 / 9.81), abs=2 * model.opt.timestep)


# ----------------------------------------------------------------------------------------- joints


def test_hinge_position_is_the_reference_of_the_written_pose() -> None:
    # webots.md 2.4: axis 1 0 0, position -0.05, endPoint rotation -1 0 0 1.6208 => zero pose -1 0 0 1.5708.
    result = compile_fixture("pendulum.wbt")
    model = result.model
    pendulum = model.body("base/pendulum").id
    joint = model.joint("base/pendulum")
    data = mujoco.MjData(model)
    assert data.qpos[joint.qposadr[0]] == pytest.approx(-0.05, abs=1e-12)
    mujoco.mj_kinematics(model, data)
    assert same_rotation(data.xquat[pendulum], axis_angle_quat((-1, 0, 0), 1.6208)) < 1e-9
    assert np.allclose(data.xpos[pendulum], [0, 0.079900021, 0.5 - 0.013998333], atol=1e-9)
    data.qpos[joint.qposadr[0]] = 0.0
    mujoco.mj_kinematics(model, data)
    assert same_rotation(data.xquat[pendulum], axis_angle_quat((-1, 0, 0), 1.5708)) < 1e-6
    # Undoing the position turns the pendulum about the anchor (0 0 -0.01): it stands 0.08 m along y.
    assert np.allclose(data.xpos[pendulum], [0, 0.08, 0.49], atol=1e-6)


def test_hinge_stops_are_radians() -> None:
    result = compile_fixture("pendulum.wbt")
    joint = result.model.joint("base/pendulum")
    assert joint.limited[0] == 1
    assert joint.range.tolist() == pytest.approx([-1.6, 1.6], abs=1e-12)


def test_slider_position_is_the_reference_of_the_written_pose() -> None:
    result = compile_fixture("mechanism.wbt")
    model = result.model
    carriage, bob = model.body("rig/carriage").id, model.body("rig/bob").id
    slider = model.joint("rig/carriage")
    assert slider.type[0] == mujoco.mjtJoint.mjJNT_SLIDE
    assert slider.range.tolist() == pytest.approx([-0.2, 0.3], abs=1e-12)
    data = mujoco.MjData(model)
    assert data.qpos[slider.qposadr[0]] == pytest.approx(0.1, abs=1e-12)
    mujoco.mj_kinematics(model, data)
    assert np.allclose(data.xpos[carriage], [0.1, 0, 1], atol=1e-12)
    assert np.allclose(data.xpos[bob], [0.1, 0, 0.77], atol=1e-12)
    data.qpos[slider.qposadr[0]] = 0.0
    mujoco.mj_kinematics(model, data)
    assert np.allclose(data.xpos[carriage], [0, 0, 1], atol=1e-12)
    assert np.allclose(data.xpos[bob], [0, 0, 0.77], atol=1e-12)
    # The Hinge2Joint's second axis has stops of ±0.5 rad; the BallJoint has no stops.
    assert model.joint("rig/head(1)").range.tolist() == pytest.approx([-0.5, 0.5], abs=1e-12)
    assert model.joint("rig/bob").type[0] == mujoco.mjtJoint.mjJNT_BALL


def test_position_sensor_reads_the_written_position() -> None:
    result = compile_fixture("pendulum.wbt")
    sensor = result.table.robot("base").device("pendulum sensor")
    assert sensor is not None and sensor.type == "PositionSensor"
    assert sensor.joint == "base/pendulum" and sensor.initial_position == -0.05


# ----------------------------------------------------------------------------------------- axes


def _trajectories(name: str, seconds: float) -> tuple[mujoco.MjModel, np.ndarray, np.ndarray]:
    result = compile_fixture(name)
    model = result.model
    data = mujoco.MjData(model)
    positions, orientations = [], []
    for _ in range(round(seconds / model.opt.timestep)):
        mujoco.mj_step(model, data)
        positions.append(data.xpos.copy())
        orientations.append(data.xmat.copy())
    return model, np.array(positions), np.array(orientations)


def test_nue_world_moves_like_the_same_world_written_in_enu() -> None:
    nue = compile_fixture("ball_nue.wbt")
    enu = compile_fixture("ball_enu.wbt")
    assert nue.table.coordinate_system == "NUE" and enu.table.coordinate_system == "ENU"
    assert nue.model.opt.gravity.tolist() == enu.model.opt.gravity.tolist() == [0.0, 0.0, -9.81]
    # The NUE file writes the ball at (x north, y up, z east) = (0.12, 0.6, 0.1): ENU (0.1, 0.12, 0.6).
    nue_to_enu = nue.table.to_model
    assert np.allclose(nue_to_enu @ [0.12, 0.6, 0.1], [0.1, 0.12, 0.6], atol=0)
    nue_model, nue_pos, nue_rot = _trajectories("ball_nue.wbt", 1.0)
    enu_model, enu_pos, enu_rot = _trajectories("ball_enu.wbt", 1.0)
    assert [nue_model.body(i).name for i in range(nue_model.nbody)] == \
        [enu_model.body(i).name for i in range(enu_model.nbody)]
    ball, can = enu_model.body("ball").id, enu_model.body("can").id
    assert np.allclose(nue_pos[0, ball], nue_to_enu @ [0.12, 0.6, 0.1], atol=1e-4)
    # Something moves: the ball lands on the ramp and rolls off it, the can falls and rolls away.
    assert np.linalg.norm(enu_pos[-1, ball] - enu_pos[0, ball]) > 0.5
    assert np.linalg.norm(enu_pos[-1, can] - enu_pos[0, can]) > 0.3
    assert np.abs(nue_pos - enu_pos).max() < 1e-6
    # A body's own axes are NUE axes in the NUE file: its orientation is the ENU one times NUE -> ENU.
    nue_rot = nue_rot.reshape(*nue_rot.shape[:2], 3, 3)
    enu_rot = enu_rot.reshape(*enu_rot.shape[:2], 3, 3)
    assert np.abs(nue_rot[:, 1:] - enu_rot[:, 1:] @ nue_to_enu).max() < 1e-6


def _geom_axes(name: str) -> np.ndarray:
    result = compile_fixture(name)
    data = mujoco.MjData(result.model)
    mujoco.mj_kinematics(result.model, data)
    return data.geom_xmat.reshape(-1, 3, 3)[:, :, 2]


def test_legacy_cylinder_axis_is_local_y() -> None:
    legacy = _geom_axes("cylinder_r2021a.wbt")
    modern = _geom_axes("cylinder_r2023b.wbt")
    # The Solid turns 0.7 rad about z; the cylinder's axis is its local y: (-sin 0.7, cos 0.7, 0).
    expected = [-math.sin(0.7), math.cos(0.7), 0.0]
    assert len(legacy) == len(modern) == 2  # visual and bounding cylinder
    for axis in (*legacy, *modern):
        assert np.allclose(axis, expected, atol=1e-9)
    assert np.abs(legacy - modern).max() < 1e-9


def test_nue_legacy_cylinder_and_plane_face_up() -> None:
    result = compile_fixture("nue_legacy.wbt")
    model = result.model
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    axes = data.geom_xmat.reshape(-1, 3, 3)[:, :, 2]
    floor = model.body("floor").id
    robot = model.body(result.table.robot("legacy").body).id
    for geom in range(model.ngeom):
        if model.geom_bodyid[geom] in (floor, robot):
            # The floor Plane's normal and the chassis Cylinder's axis: NUE y (up) = ENU z.
            assert np.allclose(axes[geom], [0, 0, 1], atol=1e-9), model.geom(geom).name


@pytest.mark.parametrize(("world", "device", "look"), [
    ("epuck_rest.wbt", "camera", [1.0, 0.0, 0.0]),  # R2022a+: a camera looks along its +x, z up
    ("two_wheel_robot.wbt", "cam", [1.0, 0.0, 0.0]),
    # Before R2022a along its -z, y up: NUE -z is ENU -x, turned 0.3 rad about up by the Robot.
    ("nue_legacy.wbt", "eye", [-math.cos(0.3), -math.sin(0.3), 0.0]),
])
def test_cameras_look_along_the_webots_axis(world: str, device: str, look: list[float]) -> None:
    result = compile_fixture(world)
    model = result.model
    entry = result.table.robots[0].device(device)
    assert entry is not None and entry.camera
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    axes = data.cam_xmat[model.camera(entry.camera).id].reshape(3, 3)
    assert np.allclose(-axes[:, 2], look, atol=1e-6)  # MuJoCo cameras look along their -z
    assert np.allclose(axes[:, 1], [0, 0, 1], atol=1e-6)  # and their +y is up


# ----------------------------------------------------------------------------------------- masses


def test_density_times_volume_and_given_masses() -> None:
    model = compile_fixture("masses.wbt").model
    assert model.body("box density").mass[0] == pytest.approx(500 * 0.1 * 0.2 * 0.3, rel=1e-12)
    assert model.body("box density").mass[0] == pytest.approx(3.0, rel=1e-12)
    assert model.body("sphere density").mass[0] == pytest.approx(4.18879, abs=1e-5)
    assert model.body("given mass").mass[0] == pytest.approx(2.0, abs=0)
    # A box's inertia about its centre: m (b² + c²) / 12 ...
    assert model.body("box density").inertia.tolist() == pytest.approx(
        [3.0 * (0.2**2 + 0.3**2) / 12, 3.0 * (0.1**2 + 0.3**2) / 12, 3.0 * (0.1**2 + 0.2**2) / 12], rel=1e-9)
    assert model.body("sphere density").inertia.tolist() == pytest.approx([0.4 * 4.18879 * 0.01] * 3, rel=1e-5)


def test_center_of_mass_and_inertia_matrix_overrides() -> None:
    model = compile_fixture("masses.wbt").model
    body = model.body("overrides")
    assert body.mass[0] == 2.0
    assert body.ipos.tolist() == pytest.approx([0.01, 0.02, 0.03], abs=1e-12)
    # inertiaMatrix [I11 I22 I33], [I12 I13 I23]: MuJoCo keeps the principal moments and their axes.
    written = np.array([[0.1, 0.01, 0.0], [0.01, 0.2, 0.0], [0.0, 0.0, 0.3]])
    assert sorted(body.inertia) == pytest.approx(np.linalg.eigvalsh(written).tolist(), rel=1e-9)
    rot = quat_to_mat(body.iquat)
    assert np.allclose(rot @ np.diag(body.inertia) @ rot.T, written, atol=1e-9)


# ----------------------------------------------------------------------------------------- motors


def test_motor_torque_limit_is_the_actuator_force_range() -> None:
    result = compile_fixture("motor.wbt")
    robot = result.table.robot("stand")
    strong, weak = robot.device("strong motor"), robot.device("weak motor")
    assert strong.actuator and weak.actuator
    model = result.model
    assert model.actuator(strong.actuator).forcerange.tolist() == [-3.0, 3.0]
    assert model.actuator(weak.actuator).forcerange.tolist() == [-1e-4, 1e-4]
    assert model.joint(model.actuator(strong.actuator).trnid[0]).name == strong.joint == "stand/strong wheel"
    assert robot.device("strong sensor").motor == "strong motor" and strong.sensor == "strong sensor"


def test_velocity_target_is_reached_in_the_air() -> None:
    result = compile_fixture("motor.wbt")
    model = result.model
    strong = result.table.robot("stand").device("strong motor")
    actuator, dof = model.actuator(strong.actuator).id, model.joint(strong.joint).dofadr[0]
    data = mujoco.MjData(model)
    data.ctrl[actuator] = 5.0
    step_for(model, data, 0.1)
    assert data.time == pytest.approx(0.1)
    assert data.qvel[dof] == pytest.approx(5.0, abs=5e-3)
    data.ctrl[actuator] = -2.0  # and back the other way
    step_for(model, data, 0.1)
    assert data.qvel[dof] == pytest.approx(-2.0, abs=2e-3)


# ----------------------------------------------------------------------------------------- friction


def test_contact_material_friction() -> None:
    model = compile_fixture("friction.wbt").model
    colliding = [g for g in range(model.ngeom) if model.geom_contype[g] or model.geom_conaffinity[g]]
    by_body: dict[str, list[float]] = {}
    for geom in colliding:
        by_body.setdefault(model.body(model.geom_bodyid[geom]).name, []).append(float(model.geom_friction[geom, 0]))
    assert by_body == {"floor": [1.0], "ice block": [0.1, 0.1], "rubber block": [1.0]}


# ----------------------------------------------------------------------------------------- time


@pytest.mark.parametrize(("world", "options", "timestep", "substeps"), [
    ("timestep_32.wbt", None, 0.002, 16),
    ("timestep_10.wbt", None, 0.002, 5),
    ("timestep_10.wbt", CompileOptions(max_substep_ms=2.0), 0.002, 5),
    ("timestep_32.wbt", CompileOptions(max_substep_ms=4), 0.004, 8),
])
def test_substeps_divide_the_basic_time_step(world, options, timestep, substeps) -> None:
    result = compile_fixture(world, options)
    assert result.model.opt.timestep == pytest.approx(timestep, abs=1e-15)
    assert result.table.substeps == substeps
    assert result.table.substeps * result.model.opt.timestep * 1000 == pytest.approx(result.table.basic_time_step)


_NO_BOUNDS = """#VRML_SIM R2025a utf8
Solid { translation 0 0 1 name "given mass" physics Physics { density -1 mass 2.5 } }
Solid { translation 1 0 1 name "density only" physics Physics { } }
Solid { translation 2 0 1 name "mass over density" boundingObject Box { size 0.1 0.1 0.1 } physics Physics { mass 2 } }
"""


def test_physics_without_bounding_object_uses_webots_default_mass_settings(tmp_path) -> None:
    # Webots (WbSolid::setDefaultMassSettings): the given mass, else 1 kg, with the identity inertia matrix.
    world = tmp_path / "bounds.wbt"
    world.write_text(_NO_BOUNDS, encoding="utf-8")
    result, _ = compile_world(world)
    model = result.model
    assert model.body("given mass").mass[0] == 2.5
    assert model.body("given mass").inertia.tolist() == [1.0, 1.0, 1.0]
    assert model.body("density only").mass[0] == 1.0
    assert model.body("density only").inertia.tolist() == [1.0, 1.0, 1.0]
    # A mass and the default density 1000: Webots ignores the density.
    assert model.body("mass over density").mass[0] == 2.0
    messages = [w.message for w in result.warnings]
    assert messages == ["Undefined inertia matrix: using the identity matrix. Please specify 'boundingObject' or "
                        "'inertiaMatrix' values.",
                        "Mass is invalid because 'boundingObject' is not defined. Using default mass properties: "
                        "mass = 1, inertia matrix = identity"]
