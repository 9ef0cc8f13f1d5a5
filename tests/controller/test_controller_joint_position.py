"""Node.setJointPosition: the C library's index checks per joint type, and what reaches the simulator."""

from __future__ import annotations

import controller_sim
from controller_sim import make_init

sim = controller_sim.sim  # the fake-simulator fixture (see controller_sim.py)

SUPERVISOR = make_init([], supervisor=True)
NODES = {
    "BALL": {"id": 7, "def": "BALL", "type": "BallJoint", "base_type": "BallJoint", "proto": False, "parent": 0},
    "HINGE2": {"id": 8, "def": "HINGE2", "type": "Hinge2Joint", "base_type": "Hinge2Joint", "proto": False,
               "parent": 0},
    "SLIDER": {"id": 9, "def": "SLIDER", "type": "SliderJoint", "base_type": "SliderJoint", "proto": False,
               "parent": 0},
    "BOX": {"id": 10, "def": "BOX", "type": "Solid", "base_type": "Solid", "proto": False, "parent": 0},
}


def test_indices_are_checked_as_webots_checks_them(sim) -> None:
    fake = sim(
        """
        from controller import Supervisor
        supervisor = Supervisor()
        ball, hinge2, slider, box = (supervisor.getFromDef(name) for name in ("BALL", "HINGE2", "SLIDER", "BOX"))
        ball.setJointPosition(0.6, 3)
        ball.setJointPosition(0.6, 4)
        ball.setJointPosition(0.6, 0)
        hinge2.setJointPosition(0.2, 2)
        hinge2.setJointPosition(0.2, 3)
        slider.setJointPosition(0.1)
        slider.setJointPosition(0.1, 2)
        box.setJointPosition(0.1, 1)
        supervisor.step()
        """,
        SUPERVISOR,
    )
    for name in ("BALL", "HINGE2", "SLIDER", "BOX"):
        fake.answer("getFromDef", name, -1, result=NODES[name])
    assert fake.step() == (32, [
        (-1, "node.setJointPosition", 7, 0.6, 3),
        (-1, "node.setJointPosition", 8, 0.2, 2),
        (-1, "node.setJointPosition", 9, 0.1, 1),
    ])
    rc, _, err = fake.finish()
    assert rc == 0
    function = "Error: wb_supervisor_node_set_joint_position() called with"
    assert err.splitlines() == [
        f"{function} an invalid 'index'. BallJoint only supports index 1, 2, or 3.",
        f"{function} an invalid 'index'. Only values greater than or equal to 1 are supported.",
        f"{function} an invalid 'index'. Hinge2Joint only supports index 1 or 2.",
        f"{function} an invalid 'index'. SliderJoint and HingeJoint only support index 1.",
        f"{function} a 'node' argument which is not a joint node.",
    ]
