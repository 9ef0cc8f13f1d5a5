"""wbtc's Hey5 hands (TiagoRightHey5, TiagoLeftHey5) and TIAGo Titanium: Webots' devices, limits, masses,
the fingers curling when driven, and the palm where Webots' numbers put it."""

from pathlib import Path

import mujoco
import numpy as np
import pytest
from conftest import simulation_of
from test_tiago_arms import ARM_MASSES, BASE, BASE_MASS, BODY_MASS, FRONT, HEAD, LIFT, MOUNT, TORSO, _pose

from wbtc.runtime.simulation import Simulation

HEADER = "#VRML_SIM R2025a utf8\nWorldInfo { basicTimeStep 16 }\n"
FINGERS = ["index", "middle", "ring", "little"]
CONNECTOR = 1000 * 0.013 * 0.002 * 0.012  # Webots' default Physics on the 13 x 2 x 12 mm connector box
HAND_MASS = 0.4 + (0.014 + 0.009 + 0.015 + 2 * CONNECTOR) + 4 * (0.018 + 2 * 0.009 + 0.015 + 3 * CONNECTOR)


def _motors(side: str) -> list[str]:
    """Webots' motor order: the thumb's five, then each finger's seven."""
    thumb = ["thumb_abd", "thumb_virtual_1", "thumb_flex_1", "thumb_virtual_2", "thumb_flex_2"]
    steps = ["abd", "virtual_1", "flex_1", "virtual_2", "flex_2", "virtual_3", "flex_3"]
    return [f"hand_{side}_{m}_joint" for m in thumb + [f"{f}_{s}" for f in FINGERS for s in steps]]


def _devices(side: str) -> list[str]:
    return [n for m in _motors(side) for n in (m, f"{m}_sensor")]


def _links(side: str) -> dict[str, float]:
    """Each finger link's name and Webots' mass."""
    links = {f"hand_{side}_thumb_abd_link": 0.014, f"hand_{side}_thumb_virtual_1_link": CONNECTOR,
             f"hand_{side}_thumb_flex_1_link": 0.009, f"hand_{side}_thumb_virtual_2_link": CONNECTOR,
             f"hand_{side}_thumb_flex_3": 0.015}
    for f in FINGERS:
        links |= {f"hand_{side}_{f}_abd_link": 0.018, f"hand_{side}_{f}_flex_3_link": 0.015}
        links |= {f"hand_{side}_{f}_virtual_{k}_link": CONNECTOR for k in (1, 2, 3)}
        links |= {f"hand_{side}_{f}_flex_{k}_link": 0.009 for k in (1, 2)}
    return links


def _hand(tmp_path: Path, proto: str) -> Simulation:
    """The hand alone on a fixed Robot (no Physics: it stays put)."""
    return simulation_of(tmp_path, HEADER + f'Robot {{ controller "<none>" children [ {proto} {{ }} ] }}\n')


def _joint(sim: Simulation, name: str) -> int:
    device = next(d for d in sim.robots[0].entry.devices if d.name == name)
    return sim.model.joint(device.joint).qposadr[0]


def _command(sim: Simulation, name: str, value: float) -> None:
    robot = sim.robots[0]
    tag = [d.name for d in robot.entry.devices].index(name)
    robot.motors[tag].apply("setPosition", (value,), sim.time_ms)


def _frame(sim: Simulation, body: str) -> np.ndarray:
    pose = np.eye(4)
    index = sim.model.body(body).id
    pose[:3, :3], pose[:3, 3] = sim.data.xmat[index].reshape(3, 3), sim.data.xpos[index]
    return pose


@pytest.mark.parametrize(("proto", "side", "palm"), [("TiagoRightHey5", "right", "right Hey5 hand"),
                                                     ("TiagoLeftHey5", "left", "left Hey5 hand")])
def test_a_hand_has_webots_devices_limits_and_masses(tmp_path: Path, proto: str, side: str, palm: str):
    sim = _hand(tmp_path, proto)
    try:
        entry, model = sim.table.robots[0], sim.model
        assert [d.name for d in entry.devices] == _devices(side)
        fields = {d.name: d.fields for d in entry.devices}
        for name in _motors(side):
            motor = fields[name]
            low, high = (0, 1.57) if "thumb_abd" in name else (-0.52, 0.52) if "_abd" in name else (0, 0.79)
            assert (motor.get("minPosition", 0), motor["maxPosition"]) == pytest.approx((low, high)), name
            assert (motor["maxVelocity"], motor["maxTorque"]) == pytest.approx((2, 2)), name
            assert motor["multiplier"] == 1  # Webots' Hey5 drives every joint with its own motor
        assert model.body_mass[model.body(f"robot/{palm}").id] == pytest.approx(0.4)
        for link, mass in _links(side).items():
            assert model.body_mass[model.body(f"robot/{link}").id] == pytest.approx(mass), link
        assert model.body_subtreemass[model.body(f"robot/{palm}").id] == pytest.approx(HAND_MASS)  # 0.646 kg
        # Each abduction hinge is Webots' (axis, anchor) in the palm's frame: x the axis, p on it.
        abduction = {"right": {"index": ((0, 1, 0), (0.1265, 0.0042, 0.0265)),
                               "little": ((0, 1, 0), (0.1165, 0.0042, -0.032)),
                               "thumb": ((-0.9191, 0, 0.3939), (0.0901, 0.0134, 0.038))},
                     "left": {"index": ((0, -1, 0), (-0.1264, 0, 0.0269)),
                              "little": ((0, -1, 0), (-0.1165, 0, -0.032)),
                              "thumb": ((-0.9191, 0, -0.3939), (-0.0914, 0.0134, 0.0374))}}[side]
        mujoco.mj_kinematics(model, sim.data)
        frame = _frame(sim, f"robot/{palm}")
        for finger, (axis, anchor) in abduction.items():
            joint = model.joint(next(d.joint for d in entry.devices if d.name == f"hand_{side}_{finger}_abd_joint"))
            axis = np.asarray(axis) / np.linalg.norm(axis)
            world_axis = sim.data.xaxis[joint.id]
            assert frame[:3, :3].T @ world_axis == pytest.approx(axis, abs=1e-4), finger
            offset = frame[:3, :3].T @ (sim.data.xanchor[joint.id] - frame[:3, 3]) - np.asarray(anchor)
            assert np.linalg.norm(offset - (offset @ axis) * axis) == pytest.approx(0, abs=1e-6), finger
    finally:
        sim.close()


@pytest.mark.parametrize(("proto", "side", "palm"), [("TiagoRightHey5", "right", "right Hey5 hand"),
                                                     ("TiagoLeftHey5", "left", "left Hey5 hand")])
def test_driving_the_finger_motors_curls_the_fingers(tmp_path: Path, proto: str, side: str, palm: str):
    sim = _hand(tmp_path, proto)
    try:
        tips = [f"robot/hand_{side}_{f}_flex_3_link" for f in FINGERS]
        reach = 1 if side == "right" else -1  # the fingers reach along the palm's +x (right) or -x (left)

        def where(body: str) -> np.ndarray:  # a body's position in the palm's frame
            return (np.linalg.inv(_frame(sim, f"robot/{palm}")) @ _frame(sim, body))[:3, 3]

        mujoco.mj_kinematics(sim.model, sim.data)
        start = [where(tip) for tip in tips]
        thumb = where(f"robot/hand_{side}_thumb_flex_3")
        assert min(reach * p[0] for p in start) > 0.17  # stretched out beyond the palm's 0.143 m
        curl = [m for m in _motors(side) if "virtual" in m or "flex" in m]
        for name in curl:
            _command(sim, name, 0.79)
        for _ in range(60):  # 0.96 s: 0.79 rad at 2 rad/s takes 0.4 s
            sim.step()
        for name in curl:
            assert sim.data.qpos[_joint(sim, name)] == pytest.approx(0.79, abs=0.02), name
        # Six hinges of 0.79 rad fold each finger over the palm's +y face (where the thumb sits): every tip
        # ends 5 cm short of its start and 1.5 cm further towards +y; the thumb's tip swings 3 cm towards them.
        for before, tip in zip(start, tips, strict=True):
            after = where(tip)
            assert reach * after[0] < reach * before[0] - 0.05, tip
            assert after[1] > before[1] + 0.015, tip
        assert where(f"robot/hand_{side}_thumb_flex_3")[2] < thumb[2] - 0.03
    finally:
        sim.close()


def test_titanium_has_webots_devices_and_masses(tmp_path: Path):
    sim = simulation_of(tmp_path, HEADER + 'Floor { size 20 20 }\nTiagoTitanium { controller "<none>" }\n')
    try:
        entry, model = sim.table.robots[0], sim.model
        arm = [n for k in range(1, 8) for n in (f"arm_{k}_joint", f"arm_{k}_joint_sensor")]
        assert [d.name for d in entry.devices] == (LIFT + arm + _devices("right") + HEAD
                                                   + ["Hokuyo URG-04LX-UG01"] + BASE)
        total = BASE_MASS + BODY_MASS + 0.16 + sum(ARM_MASSES) + HAND_MASS  # 72.20 kg with the Hokuyo
        assert model.body_subtreemass[model.body(entry.body).id] == pytest.approx(total)
        assert model.body_subtreemass[model.body("TIAGo Titanium/right Hey5 hand").id] == pytest.approx(HAND_MASS)
    finally:
        sim.close()


def _titanium_palm(angles) -> np.ndarray:
    """The Hey5 palm's world pose from Webots' numbers: torso, front-arm mount, the seven hinges (each
    endPoint's written pose turned about its hinge by the angle less the written position), the wrist
    connector, its slot Pose and TiagoRightHey5's default placement."""
    pose = _pose(TORSO, (0, 0, 1, 0))
    for step in MOUNT["front"]:
        pose = pose @ _pose(*step)
    for (axis, anchor, written, translation, rotation, _), angle in zip(FRONT, angles, strict=True):
        turn = _pose((0, 0, 0), (*axis, angle - written))
        turn[:3, 3] = np.asarray(anchor) - turn[:3, :3] @ np.asarray(anchor)
        pose = pose @ turn @ _pose(translation, rotation)
    pose = pose @ _pose((0, 0, 0.012725), (-0.5774, -0.5774, -0.5774, 2.0944)) @ _pose((0, 0, 0), (0, 0, 1, -1.5708))
    return pose @ _pose((0, 0, 0), (0, 0, -1, -1.5708))


def test_the_titanium_palm_is_where_webots_numbers_put_it(tmp_path: Path):
    sim = simulation_of(tmp_path, HEADER + 'Floor { size 20 20 }\nTiagoTitanium { controller "<none>" }\n')
    try:
        model, data = sim.model, sim.data
        palm = "TIAGo Titanium/right Hey5 hand"
        start = [0.071, 0, 0, 0, 0, 0, 0]
        assert _frame(sim, palm) == pytest.approx(_titanium_palm(start), abs=2e-4)
        # At Webots' initial pose the arm stretches out level to the right; the fingers point further right.
        fingers = _frame(sim, palm)[:3, 0]
        assert fingers == pytest.approx([0, -1, 0], abs=0.02)
        bent = [1.2, -0.6, -1.5, 1.8, 0.7, -1.0, 1.3]
        for k, angle in enumerate(bent, start=1):
            data.qpos[_joint(sim, f"arm_{k}_joint")] = angle
        mujoco.mj_kinematics(model, data)
        assert _frame(sim, palm) == pytest.approx(_titanium_palm(bent), abs=2e-4)
    finally:
        sim.close()
