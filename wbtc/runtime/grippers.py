"""Webots' VacuumGripper: while on, it holds the first solid its bounding object touches, until turned off.

The compiler gives each VacuumGripper an inactive MuJoCo weld (`compile.device`: body1 the gripper's
body, body2 the world). Before every step, a gripper that is on and holds nothing looks at the
contacts of its body: the first one with a moving body of another robot or of no robot is welded
to it where it is now (body2 becomes that body, the relative pose is the current one), as Webots
joins the two with a fixed joint. `turnOff` releases it. The presence sample reads 1 while
something is held, else 0.

Not honoured yet: `contactPoints` (one contact point is enough here), `tensileStrength` and
`shearStrength` (the weld never breaks).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import mujoco
import numpy as np

from wbtc.compile.table import DeviceEntry
from wbtc.runtime.sensors import Sensor

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation


class VacuumGripper(Sensor):
    """One VacuumGripper: on/off, what it holds, its weld."""

    def __init__(self, entry: DeviceEntry, sim: Simulation, skip_bodies: frozenset[int]) -> None:
        super().__init__(entry, sim, skip_bodies)
        self.sim = sim
        self.on = bool(entry.fields.get("isOn", False))
        self.weld = sim.model.equality(entry.weld).id if entry.weld else -1
        self.held = -1
        self.robot_bodies = skip_bodies

    def command(self, op: str, args: tuple) -> None:
        """turnOn, turnOff and presence sampling."""
        if op == "turnOn":
            self.on = True
        elif op == "turnOff":
            self.on = False
            self.release()
        elif op == "enablePresence":
            self.enable(int(args[0]), self.sim.time_ms)
        elif op == "disablePresence":
            self.enable(0, self.sim.time_ms)

    def sample(self, sim: Simulation) -> int:
        """1 while something is held, else 0."""
        return int(self.held >= 0)

    def update(self, sim: Simulation) -> None:
        """Before a step: a gripper that is on and free takes hold of what it touches."""
        if not self.on or self.held >= 0 or self.weld < 0:
            return
        model, data = sim.model, sim.data
        bodies = model.geom_bodyid
        for contact in data.contact[:data.ncon]:
            pair = int(bodies[contact.geom1]), int(bodies[contact.geom2])
            if self.body not in pair:
                continue
            other = pair[1] if pair[0] == self.body else pair[0]
            if other != self.body and other not in self.robot_bodies and _moves(model, other):
                self.hold(sim, other)
                return

    def hold(self, sim: Simulation, body: int) -> None:
        """Weld `body` to the gripper where it is now (as Webots' fixed joint, overlap included)."""
        model, data = sim.model, sim.data
        rot = data.xmat[self.body].reshape(3, 3)
        # MuJoCo's body weld keeps body2's origin at relpos in body1's frame and body2's orientation at
        # relquat from body1's (data: anchor on body2, relpos, relquat, torquescale).
        relpos = rot.T @ (data.xpos[body] - data.xpos[self.body])
        relquat = np.zeros(4)
        mujoco.mju_mulQuat(relquat, _conjugate(data.xquat[self.body]), data.xquat[body])
        model.eq_obj2id[self.weld] = body
        model.eq_data[self.weld, :11] = [0.0, 0.0, 0.0, *relpos, *relquat, 1.0]
        stiff_weld(model, self.weld)
        data.eq_active[self.weld] = 1
        self.held = body

    def release(self) -> None:
        """Let go of what is held."""
        if self.weld >= 0:
            self.sim.data.eq_active[self.weld] = 0
        self.held = -1


def stiff_weld(model: mujoco.MjModel, weld: int) -> None:
    """Make a weld as stiff as MuJoCo keeps stable (time constant 2 × timestep, critical damping).

    Webots joins docked bodies with an ODE fixed joint, which does not give way; MuJoCo's default
    weld (0.02 s) lets a held 0.5 kg box sag 2 mm.
    """
    model.eq_solref[weld] = [2 * model.opt.timestep, 1.0]


def _conjugate(quat: np.ndarray) -> np.ndarray:
    return np.array([quat[0], -quat[1], -quat[2], -quat[3]])


def _moves(model: mujoco.MjModel, body: int) -> bool:
    """Whether a body can move (it or one of its ancestors has a joint): a static solid cannot be lifted."""
    while body > 0:
        if model.body_jntnum[body] > 0:
            return True
        body = int(model.body_parentid[body])
    return False
