"""Webots' motor model on top of the compiler's velocity servos.

Every basic time step a motor computes the velocity Webots would ask ODE for and hands it to its
MuJoCo actuator as the servo's target, with the servo's gain limited so that its torque stays within
the available torque, and the joint's armature set to gain × timestep (the servo's implicit damping,
which the contact solver then sees, as ODE solves its motors with the contacts):

- position control (the default, and after any finite `setPosition`): a PID on the position
  error, `Vc = P·e + I·∫e + D·(e_prev − e)/ts`, clamped to the requested velocity;
- velocity control (`setPosition(inf)`): the requested velocity, signed;
- either way the change of Vc is limited by `acceleration` (when not -1);
- torque/force control (`setTorque`/`setForce`): a constant effort, the servo gain set to zero. Its
  feedback is what the joint's own constraint gives along the axis, its stops (`joint_limit_force`):
  Webots adds the torque to the bodies (`dJointAddHingeTorque`), outside the joint feedback it reads,
  so a free joint reads about 0, not the command.

A motor that cannot reach its velocity within the step even with its whole available torque (the
joint's inertia, bias forces and damping say so; contacts are not counted) gives that torque for the
whole step instead, as ODE's force-limited motor does (`_saturate`).

A motor whose joint pushes other links through a joint stop acting in the step (`runtime.joint_stops`;
Webots' backlash joints: a light gear pushing its endPoint) moves them all: its gain grows with the
inertia the stop adds (`_coupled`), as ODE solves the motor and the stop together.

An untouched motor targets the joint's initial position, so it holds the joint (Webots' rule).

Brake devices add their damping constant to their joint's damping (see commands).

The joint's damping (`dampingConstant`, brakes) does not slow a motor below its velocity while the
available torque allows, as with ODE's motor (`_damping_lead`). Coupled motors (`multiplier`) are
relayed by the controller library.

Joints of trees without any Physics move by Webots' kinematic rule instead (`kinematic_motors`).

Under `--ode-contacts` a motor in position or velocity control is ODE's motor row instead of the servo
(`motor_rows`): the same velocity command, asked of a constraint row bounded by the available torque.
"""

from __future__ import annotations

import math
import sys
from typing import Any

import mujoco
import numpy as np

from wbtc.compile.table import DeviceEntry
from wbtc.runtime import kinematic_motors, motor_rows, ode_solve
from wbtc.runtime.joint_stops import Engaged


class Motor:
    """The runtime state of one RotationalMotor or LinearMotor."""

    def __init__(self, entry: DeviceEntry, model: mujoco.MjModel, robot_name: str) -> None:
        self._setup(entry, robot_name)
        self.actuator = model.actuator(entry.actuator).id
        joint = model.joint(entry.joint).id
        self.qpos_adr = int(model.jnt_qposadr[joint])
        self.dof_adr = int(model.jnt_dofadr[joint])
        self.kv = float(model.actuator_gainprm[self.actuator, 0])
        self.static_friction = float(model.dof_frictionloss[self.dof_adr])  # the joint's own, as compiled
        self.stiffness = self.kv  # this step's highest gain: kv, more while stops hold other joints (`_coupled`)
        self.gain = self.kv
        self._kinematic: tuple[mujoco.MjModel | None, int] = (None, -1)  # (model, its holding equality)

    def _setup(self, entry: DeviceEntry, robot_name: str) -> None:
        """The Webots motor's own state, from its fields (whatever drives it in MuJoCo)."""
        fields = entry.fields
        self.entry = entry
        self.robot_name = robot_name
        self.max_velocity = float(fields.get("maxVelocity", 10.0))
        self.max_torque = float(fields.get("maxTorque", fields.get("maxForce", 10.0)))
        self.min_position = float(fields.get("minPosition", 0.0))
        self.max_position = float(fields.get("maxPosition", 0.0))
        pid = fields.get("controlPID", [10.0, 0.0, 0.0])
        self.p, self.i, self.d = (float(v) for v in pid)
        self.acceleration = float(fields.get("acceleration", -1.0))
        self.target = float(entry.initial_position)
        self.velocity = self.max_velocity
        self.available = self.max_torque
        self.torque: float | None = None
        self.integral = 0.0
        self.prev_error = 0.0
        self.command = 0.0
        self.row_command: float | None = None  # this step's velocity for ODE's motor row (motor_rows), if any
        self.kinematic_velocity = 0.0  # Webots' current velocity of a kinematic joint (see kinematic_motors)
        self.feedback_period = 0  # torque/force feedback sampling period, ms (0: disabled)
        self.feedback_due = math.inf
        self.feedback_value: float | None = None  # sampled since the last reply, else None
        self.step_force: float | None = None  # the mean force of the last step, when feedback is on
        self.metered = False  # a battery counts this motor's effort: keep its mean force per step too
        # The servo gain last written into a model (and that model): rewritten only when it changes.
        self._written: tuple[mujoco.MjModel | None, float] = (None, math.nan)
        self._unit: tuple[np.ndarray, np.ndarray] | None = None  # `_mobility`'s unit vector on the dof, its M⁻¹ column
        # (MjData, MjModel, qpos, qvel, ctrl, dof_damping): views made once per MjData and MjModel.
        self._views: tuple[Any, ...] = (None, None)

    def apply(self, op: str, args: tuple, now_ms: float = 0.0) -> None:
        """One command from the controller (`now_ms`: when it applies, for feedback sampling)."""
        if op in ("enableTorqueFeedback", "enableForceFeedback"):
            self.enable_feedback(int(args[0]), now_ms)
        elif op in ("disableTorqueFeedback", "disableForceFeedback"):
            self.enable_feedback(0, now_ms)
        elif op == "setPosition":
            self.torque = None
            target = float(args[0])
            if math.isfinite(target) and self.min_position != self.max_position:
                target = min(max(target, self.min_position), self.max_position)
            self.target = target
        elif op == "setVelocity":
            v = float(args[0])
            if abs(v) > self.max_velocity:
                print(f"WARNING: {self.robot_name}: \"{self.entry.name}\": The requested velocity {v:g} exceeds "
                      f"'maxVelocity' = {self.max_velocity:g}.", file=sys.stderr)
                v = math.copysign(self.max_velocity, v)
            self.velocity = v
        elif op == "setAcceleration":
            self.acceleration = float(args[0])
        elif op in ("setAvailableTorque", "setAvailableForce"):
            self.available = min(max(float(args[0]), 0.0), self.max_torque)
        elif op == "setControlPID":
            self.p, self.i, self.d = (float(v) for v in args[:3])
            self.integral = self.prev_error = 0.0
        elif op in ("setTorque", "setForce"):
            self.torque = min(max(float(args[0]), -self.available), self.available)

    def update(self, model: mujoco.MjModel, data: mujoco.MjData, ts: float, stops: Engaged | None = None) -> None:
        """Set the actuator for the next basic time step (`ts` seconds).

        Args:
            model: the model.
            data: its data.
            ts: the basic time step, in seconds.
            stops: the stops that act during this step (`runtime.joint_stops`).
        """
        if self._kinematic[0] is not model:  # looked up once per model (a recompile makes another)
            self._kinematic = (model, kinematic_motors.holding_equality(model, self.entry.joint))
        if self._kinematic[1] >= 0:
            kinematic_motors.move(self, model, data, ts, self._kinematic[1])
            return
        if ode_solve.applies(model):  # --ode-contacts: ODE's motor row instead of the servo
            motor_rows.update(self, model, data, ts)
            return
        a = self.actuator
        if self.torque is not None:
            # Force control: a plain motor (gain 1, no velocity feedback), as ODE's constant force.
            self.plain(model)
            data.ctrl[a] = self.torque
            return
        views = self._views
        if views[0] is not data or views[1] is not model:  # every MjData/MjModel array read is a new view
            views = self._views = (data, model, data.qpos, data.qvel, data.ctrl, model.dof_damping)
        _, _, qpos, qvel, ctrl, damping = views
        wanted = self.velocity_command(ts, float(qpos[self.qpos_adr]))
        velocity = float(qvel[self.dof_adr])
        coupled = self._coupled(model, data, stops, wanted - velocity)
        self.stiffness = self.kv if coupled is None else max(self.kv, self.kv * coupled[1] / coupled[0])
        mobility = self._limit_gain(model, data, velocity, wanted)
        if coupled is not None:
            mobility = coupled[0]  # what the motor moves now, for `_saturate`
        if self.gain < self.stiffness and self._saturate(model, data, wanted, velocity, ts, mobility):
            return
        if self._written[0] is not model or self._written[1] != self.gain:
            model.actuator_gainprm[a, 0] = self.gain
            model.actuator_biasprm[a, 2] = -self.gain
            # The servo's damping, integrated implicitly through the mass matrix (see tune_servos).
            model.dof_armature[self.dof_adr] = self.gain * model.opt.timestep
            self._written = (model, self.gain)
        ctrl[a] = wanted + self._damping_lead(float(damping[self.dof_adr]), velocity, wanted)

    def plain(self, model: mujoco.MjModel) -> None:
        """Make the actuator a plain motor (gain 1, no velocity feedback): its ctrl is then a force."""
        model.actuator_gainprm[self.actuator, 0] = 1.0
        model.actuator_biasprm[self.actuator, 2] = 0.0
        model.dof_armature[self.dof_adr] = 0.0  # Webots joints have none; it only served the servo
        self._written = (None, math.nan)

    def _saturate(self, model: mujoco.MjModel, data: mujoco.MjData, wanted: float, velocity: float,
                  ts: float, mobility: float | None = None) -> bool:
        """Push with the whole available torque for this step when the joint cannot reach `wanted` in it.

        ODE solves a motor as a velocity constraint with a force limit: when reaching the velocity within
        the step takes more than the available torque, the motor gives exactly that torque for the whole
        step. wbtc's servo, capped at the step's start, would ease off as the joint speeds up. The torque
        needed is the velocity change over the step times the joint's effective inertia (from MuJoCo's
        mass matrix, without the servo's own armature), plus the bias forces (gravity, Coriolis) on it and
        its damping at the velocity asked for, less its other passive forces; contacts are not in it, so a
        wheel on the floor keeps the servo.
        """
        d = self.dof_adr
        if mobility is None:  # not found by _limit_gain this step
            mobility = self._mobility(model, data)
        if mobility <= 0.0:
            return False
        # The joint's damping counts at the velocity the step ends with (MuJoCo integrates it implicitly).
        damping = float(model.dof_damping[d])
        passive = float(data.qfrc_passive[d]) + damping * velocity - damping * wanted
        needed = (wanted - velocity) / (ts * mobility) + float(data.qfrc_bias[d]) - passive
        if abs(needed) <= self.available:
            return False
        a = self.actuator
        self.plain(model)
        data.ctrl[a] = math.copysign(self.available, needed)
        return True

    def current_velocity(self) -> float:
        """Webots' current velocity of the motor: the ramped command, or the kinematic joint's speed."""
        return self.kinematic_velocity if self._kinematic[1] >= 0 else self.command

    def _damping_lead(self, damping: float, velocity: float, wanted: float) -> float:
        """How far past `wanted` to aim so that the joint's damping does not slow the servo down.

        Webots' ODE motor reaches its velocity against the joint's `dampingConstant` (and brakes) as long as
        the available torque allows; a servo alone would settle at gain / (gain + damping) of it (a Rosbot
        wheel, damping 5, at 4.05 of 5 rad/s). The lead adds the damping's torque at `wanted`, within what
        the available torque leaves (`damping`: the joint's; `velocity`: the joint's now).
        """
        if damping <= 0.0 or self.gain <= 1e-9:
            return 0.0
        room = max(self.available - self.gain * abs(wanted - velocity), 0.0)
        return min(max(damping * wanted, -room), room) / self.gain

    def velocity_command(self, ts: float, position: float) -> float:
        """The velocity Webots asks for this step.

        The requested one in velocity control, else the PID's towards the target (clamped to the
        requested velocity); either way its change is limited by `acceleration`.
        """
        if math.isinf(self.target):
            wanted = self.velocity
        else:
            error = self.target - position
            self.integral += error * ts
            derivative = (error - self.prev_error) / ts  # as WbMotor: the error's rate of change
            self.prev_error = error
            wanted = self.p * error + self.d * derivative + self.i * self.integral
            limit = abs(self.velocity)
            wanted = min(max(wanted, -limit), limit)
        if self.acceleration > 0:
            step = self.acceleration * ts
            wanted = min(max(wanted, self.command - step), self.command + step)
        self.command = wanted
        return wanted

    def _limit_gain(self, model: mujoco.MjModel, data: mujoco.MjData, velocity: float,
                    wanted: float) -> float | None:
        """Keep the servo's effort within the available torque by lowering its gain only as far as needed.

        The servo's force is gain × (target − velocity) and only shrinks as the joint catches up; what
        the joint feels over a substep h is gain × (target − the velocity the substep ends with),
        because the servo's damping is implicit (the armature gain × h, see
        compile.device.tune_servos). For a joint of inertia I, damping c and bias forces b that is
        gain·N / (I + h·(gain + c)) with N = I·e + h·(c·target + b): a servo far from its velocity
        gives much less than gain × e. The gain is the largest that keeps this within the available
        torque A, for the joint's inertia with every other joint free and with every other joint
        held (the torque is monotonic in I, so it then holds in between). A constraint on the joint
        can add any inertia (a wheel's contact pushing its robot, the joint's own stop); then the
        bound is the explicit force, gain × e ≤ A. Capping the gain at the start of each basic step
        keeps the effort within the limit without clamping, which would break the implicit damping.
        Webots' ODE motor, a velocity constraint with a force limit, reaches its velocity within the
        step whenever the available torque allows; so does the servo of a free joint now (coupled
        motors keep their ratios; a capped gain lagged them by v² / 2a).

        Returns:
            The joint's mobility (see `_mobility`) when it was needed here, for `_saturate`; else None.
        """
        error = wanted - velocity
        if abs(error) * self.stiffness <= self.available:
            self.gain = self.stiffness
            return None
        if self._constrained(model, data):
            self.gain = max(self.available / abs(error), 1e-12)
            return None
        d, h, available = self.dof_adr, float(model.opt.timestep), self.available
        damping = float(model.dof_damping[d])
        # Bias forces (gravity, Coriolis) less the passive ones other than the damping (springs).
        bias = float(data.qfrc_bias[d]) - float(data.qfrc_passive[d]) - damping * velocity
        gain = self.stiffness
        # The torque is monotonic in the inertia, so its bound holds between the joint's inertia with
        # every other joint free (1 / mobility) and with every other joint held (M's diagonal).
        mobility = self._mobility(model, data)
        for inertia in (1.0 / mobility if mobility > 0.0 else math.inf, self._held_inertia(model, data)):
            if math.isinf(inertia):
                gain = min(gain, available / abs(error))
                continue
            # The servo gives gain·(target − v_new) over a substep h, v_new from the implicit step
            # (I + h·(gain + c))·v_new = I·v + h·(gain·target − bias): gain·N / (I + h·(gain + c)) with
            # N = I·e + h·(c·target + bias), at most A when gain·(|N| − h·A) ≤ A·(I + h·c).
            excess = abs(inertia * error + h * (damping * wanted + bias)) - h * available
            if excess > 0.0:
                gain = min(gain, available * (inertia + h * damping) / excess)
        self.gain = max(gain, 1e-12)
        return mobility

    def _mobility(self, model: mujoco.MjModel, data: mujoco.MjData) -> float:
        """(M⁻¹)_dd without the servo's armature: the inverse of the joint's inertia with every other joint free."""
        d = self.dof_adr
        if self._unit is None or self._unit[0].shape[1] != model.nv:
            unit = np.zeros((1, model.nv))
            unit[0, d] = 1.0
            self._unit = (unit, np.zeros((1, model.nv)))
        unit, solved = self._unit
        mujoco.mj_solveM(model, data, solved, unit)
        value = float(solved[0, d])
        return value / max(1.0 - float(model.dof_armature[d]) * value, 1e-12)  # Sherman-Morrison

    def _coupled(self, model: mujoco.MjModel, data: mujoco.MjData, stops: Engaged | None,
                 change: float) -> tuple[float, float] | None:
        """The joint's mobility with the stops it pushes held, and without them; None if it pushes none.

        ODE solves a motor as a velocity row with the stop rows, so a motor whose joint drives other
        links through a stop (a backlash gear pushing its endPoint) moves them all at its velocity,
        up to its available torque. The servo's gain, kv, was sized for the joint's inertia with
        every other joint free (`compile.device.tune_servos`): for a gear of 4e-8 kg m² it could not
        move a pendulum 200 000 times heavier within a step. While stops of its tree act, the gain
        is kv times the ratio of the joint's inertia with them held to its inertia without (both
        with the other servos' armatures, without its own): the same margin over what it now moves.

        A stop counts unless the joint's motion takes its joint away from it: its predicted
        velocity, with the motor's velocity `change` of this step and every other joint free, does
        not point out of the stop. A motor reversing away from a stop moves its own link only, as
        ODE's one-sided stop row lets it.

        The mobility with dofs S held is (M⁻¹)_dd − (M⁻¹)_dS ((M⁻¹)_SS)⁻¹ (M⁻¹)_Sd (M's block
        inverse), less the servo's own armature as in `_mobility`.
        """
        if stops is None or not len(stops.dofs):
            return None
        d = self.dof_adr
        mine = (stops.dofs != d) & (model.dof_treeid[stops.dofs] == model.dof_treeid[d])
        if not mine.any():
            return None
        others, sides = stops.dofs[mine], stops.sides[mine]
        units = np.zeros((1 + len(others), model.nv))
        units[0, d] = 1.0
        units[np.arange(1, len(others) + 1), others] = 1.0
        solved = np.zeros_like(units)
        mujoco.mj_solveM(model, data, solved, units)
        free = float(solved[0, d])
        if free <= 0.0:
            return None
        # How each stop's joint would move: its velocity now plus its share of the motor's change.
        predicted = data.qvel[others] + solved[0, others] / free * change
        pushed = sides * predicted >= -1e-12
        if not pushed.any():
            return None
        rows = np.flatnonzero(pushed)
        held = others[rows]
        across = solved[0, held]
        coupled = free - float(across @ np.linalg.solve(solved[1 + rows][:, held], across))
        if coupled <= 0.0:
            return None
        armature = float(model.dof_armature[d])
        return (coupled / max(1.0 - armature * coupled, 1e-12), free / max(1.0 - armature * free, 1e-12))

    def _held_inertia(self, model: mujoco.MjModel, data: mujoco.MjData) -> float:
        """The joint's inertia with every other joint held: its mass-matrix diagonal less the servo's armature."""
        d = self.dof_adr
        diagonal = int(model.M_rowadr[d]) + int(model.M_rownnz[d]) - 1  # data.M: CSR rows, the diagonal last
        return max(float(data.M[diagonal]) - float(model.dof_armature[d]), 0.0)

    def _constrained(self, model: mujoco.MjModel, data: mujoco.MjData) -> bool:
        """Whether a constraint acts on the joint now: a contact of a body it moves, its stops, a weld."""
        count = data.nefc
        if not count:
            return False
        if model.opt.jacobian == mujoco.mjtJacobian.mjJAC_SPARSE or (
                model.opt.jacobian == mujoco.mjtJacobian.mjJAC_AUTO and model.nv >= 60):
            used = int(data.efc_J_rowadr[count - 1] + data.efc_J_rownnz[count - 1])
            return bool((data.efc_J_colind[:used] == self.dof_adr).any())
        return bool(data.efc_J[: count * model.nv].reshape(count, model.nv)[:, self.dof_adr].any())

    def feedback(self, data: mujoco.MjData) -> float:
        """The torque/force the motor's joint gave over the last step (its mean over the substeps)."""
        if self.step_force is not None:
            return self.step_force
        return float(data.actuator_force[self.actuator])

    def joint_limit_force(self, model: mujoco.MjModel, data: mujoco.MjData) -> float:
        """The force or torque the joint's stops give along its axis now (0 away from them)."""
        joint = int(model.dof_jntid[self.dof_adr])
        count = data.nefc
        rows = (data.efc_type[:count] == mujoco.mjtConstraint.mjCNSTR_LIMIT_JOINT) & (data.efc_id[:count] == joint)
        if not rows.any():
            return 0.0
        # A limit row pushes away from the stop it is at: up from the lower one, down from the upper one.
        low, high = model.jnt_range[joint]
        position = float(data.qpos[self.qpos_adr])
        sign = 1.0 if abs(position - low) <= abs(position - high) else -1.0
        return sign * float(data.efc_force[:count][rows].sum())

    def enable_feedback(self, period: int, now_ms: float) -> None:
        """`enableTorqueFeedback(p)`/`enableForceFeedback(p)`; 0 disables (first value p ms later)."""
        self.feedback_period = int(period)
        self.feedback_due = now_ms + self.feedback_period if self.feedback_period > 0 else math.inf

    def sample_feedback(self, data: mujoco.MjData, now_ms: float) -> None:
        """Sample the feedback when due (after the physics step)."""
        if now_ms + 1e-9 >= self.feedback_due:
            self.feedback_value = self.feedback(data)
            self.feedback_due += self.feedback_period

