"""Webots' Connector: presence of a compatible peer in position, lock and unlock, docking by a weld.

Frames: since R2022a a connector docks along its +x axis and aligns its rotations about +z (the
docking surface is its y-z plane); before R2022a it docked along +z and aligned its y axes. Each
connector checks the peer with its own tolerances: origins closer than `distanceTolerance`, docking
axes opposite within `axisTolerance`, and (when `numberOfRotations` > 0) the rotation axes at one of
the n allowed angles about the docking axis within `rotationTolerance`. Types must be compatible
(symmetric with symmetric, active with passive) and the `model` strings equal. Presence reads 1 or
0, and -1 for a passive connector.

A connection is made when a connector is locked while a peer is present: at `lock()`, or later
with `autoLock`, or at the start for connectors written locked and in position; the peer must be
locked too when the connector's `unilateralLock` is FALSE. It is the connector's MuJoCo weld
(`compile.device`) pointed at the peer's body; with `snap` the weld pulls the peer so that the two
frames coincide, docking axes opposite and rotations at the nearest allowed angle, else it keeps
the pose they had. `unlock()` breaks it (both sides must unlock when `unilateralUnlock` is FALSE).
Connectors on plain Solids (no robot) take part as peers.

Not honoured yet: `tensileStrength` and `shearStrength` (a connection never breaks by force).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import mujoco
import numpy as np

from wbtc.compile.table import DeviceEntry
from wbtc.runtime.grippers import stiff_weld
from wbtc.runtime.sensors import Sensor

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation


class Connector(Sensor):
    """One Connector (of a robot, or of a plain Solid: then it has no controller)."""

    def __init__(self, entry: DeviceEntry, sim: Simulation, skip_bodies: frozenset[int]) -> None:
        super().__init__(entry, sim, skip_bodies)
        f = entry.fields
        self.sim = sim
        self.kind = str(f.get("type", "symmetric"))
        self.model_name = str(f.get("model", ""))
        self.locked = bool(f.get("isLocked", False))
        self.auto_lock = bool(f.get("autoLock", False))
        self.unilateral_lock = bool(f.get("unilateralLock", True))
        self.unilateral_unlock = bool(f.get("unilateralUnlock", True))
        self.distance_tolerance = float(f.get("distanceTolerance", 0.01))
        self.axis_tolerance = float(f.get("axisTolerance", 0.2))
        self.rotation_tolerance = float(f.get("rotationTolerance", 0.2))
        self.rotations = int(f.get("numberOfRotations", 4))
        self.snap = bool(f.get("snap", True))
        self.weld = sim.model.equality(entry.weld).id if entry.weld else -1
        # (docking axis, rotation axis) as columns of the site's frame.
        self.axes = (2, 1) if entry.legacy_axes else (0, 2)
        self.peer: Connector | None = None
        self.owns_weld = False

    # -- geometry --------------------------------------------------------------------------------------------
    def _frame(self) -> tuple[np.ndarray, np.ndarray]:
        data = self.sim.data
        return data.site_xpos[self.site], data.site_xmat[self.site].reshape(3, 3)

    def in_position(self, other: Connector) -> bool:
        """Whether `other` is in position for this connector (its own tolerances)."""
        pos, rot = self._frame()
        other_pos, other_rot = other._frame()
        if float(np.linalg.norm(other_pos - pos)) >= self.distance_tolerance:
            return False
        dock, other_dock = rot[:, self.axes[0]], other_rot[:, other.axes[0]]
        if _angle(dock, -other_dock) >= self.axis_tolerance:
            return False
        if self.rotations <= 0:
            return True
        offset = _angle_about(rot[:, self.axes[1]], other_rot[:, other.axes[1]], dock)
        step = 2 * math.pi / self.rotations
        return abs(offset - step * round(offset / step)) < self.rotation_tolerance

    def compatible(self, other: Connector) -> bool:
        """Types that can dock (symmetric with symmetric, active with passive) and the same model."""
        kinds = {self.kind, other.kind}
        return self.model_name == other.model_name and (kinds == {"symmetric"} or kinds == {"active", "passive"})

    def present(self) -> Connector | None:
        """The first compatible peer in position, if any."""
        for other in self.sim.connectors:
            if other is not self and other.site != self.site and self.compatible(other) and self.in_position(other):
                return other
        return None

    # -- device ---------------------------------------------------------------------------------------------
    def sample(self, sim: Simulation) -> int:
        """Presence: 1, 0, or -1 for a passive connector."""
        if self.kind == "passive":
            return -1
        return int(self.present() is not None)

    def command(self, op: str, args: tuple) -> None:
        """lock, unlock and presence sampling."""
        if op == "lock" and self.kind != "passive":
            self.locked = True
            self.try_connect()
        elif op == "unlock" and self.kind != "passive":
            self.locked = False
            peer = self.peer
            if peer is not None and (self.unilateral_unlock or not peer.locked):
                self.disconnect()
        elif op == "enablePresence":
            self.enable(int(args[0]), self.sim.time_ms)
        elif op == "disablePresence":
            self.enable(0, self.sim.time_ms)

    def update(self) -> None:
        """Before a step: a locked connector with autoLock (or written locked) docks to a peer in position."""
        if self.locked and self.peer is None and (self.auto_lock or self.sim.time_ms == 0.0):
            self.try_connect()

    def try_connect(self) -> None:
        """Dock to the peer in position, when there is one and the locking rules allow it."""
        if self.peer is not None or self.weld < 0 or self.kind == "passive":
            return
        other = self.present()
        if other is None or other.peer is not None or not (self.unilateral_lock or other.locked):
            return
        self._weld_to(other)
        self.peer, other.peer, self.owns_weld = other, self, True

    def disconnect(self) -> None:
        """Break this connector's connection (both sides forget it)."""
        peer = self.peer
        if peer is None:
            return
        owner = self if self.owns_weld else peer
        self.sim.data.eq_active[owner.weld] = 0
        for side in (self, peer):
            side.peer, side.owns_weld = None, False

    def _weld_to(self, other: Connector) -> None:
        model, data = self.sim.model, self.sim.data
        body, other_body = int(model.site_bodyid[self.site]), int(model.site_bodyid[other.site])
        target = _pose(data.xpos[other_body], data.xmat[other_body].reshape(3, 3))
        if self.snap:
            pos, rot = self._frame()
            other_pos, other_rot = other._frame()
            docked = _pose(pos, self._docked_axes(rot, other_rot, other))
            # The peer's body moves with its connector: keep the body-to-connector offset it has now.
            offset = np.linalg.inv(_pose(other_pos, other_rot)) @ target
            target = docked @ offset
        relative = np.linalg.inv(_pose(data.xpos[body], data.xmat[body].reshape(3, 3))) @ target
        quat = np.zeros(4)
        mujoco.mju_mat2Quat(quat, relative[:3, :3].reshape(9).copy())
        model.eq_obj1id[self.weld], model.eq_obj2id[self.weld] = body, other_body
        # MuJoCo's body weld: anchor on body2, body2's origin and orientation in body1's frame, torquescale.
        model.eq_data[self.weld, :11] = [0.0, 0.0, 0.0, *relative[:3, 3], *quat, 1.0]
        stiff_weld(model, self.weld)
        data.eq_active[self.weld] = 1

    def _docked_axes(self, rot: np.ndarray, other_rot: np.ndarray, other: Connector) -> np.ndarray:
        """The peer connector's orientation once snapped: docking axes opposite, rotation at an allowed angle."""
        dock = rot[:, self.axes[0]]
        reference = rot[:, self.axes[1]]
        if self.rotations > 0:
            step = 2 * math.pi / self.rotations
            offset = _angle_about(reference, other_rot[:, other.axes[1]], dock)
            turn = step * round(offset / step)
            # Rodrigues: `reference` turned by `turn` about `dock` (perpendicular to it).
            spin = reference * math.cos(turn) + np.cross(dock, reference) * math.sin(turn)
        else:
            spin = other_rot[:, other.axes[1]] - dock * float(other_rot[:, other.axes[1]] @ dock)
            spin = spin / max(float(np.linalg.norm(spin)), 1e-12)
        axes = np.zeros((3, 3))
        axes[:, other.axes[0]], axes[:, other.axes[1]] = -dock, spin
        third = 3 - other.axes[0] - other.axes[1]
        # A right-handed frame: x = y × z, y = z × x, z = x × y.
        axes[:, third] = np.cross(axes[:, (third + 1) % 3], axes[:, (third + 2) % 3])
        return axes


def _pose(pos: np.ndarray, rot: np.ndarray) -> np.ndarray:
    pose = np.eye(4)
    pose[:3, :3], pose[:3, 3] = rot, pos
    return pose


def _angle(a: np.ndarray, b: np.ndarray) -> float:
    cosine = float(a @ b) / max(float(np.linalg.norm(a) * np.linalg.norm(b)), 1e-12)
    return math.acos(min(max(cosine, -1.0), 1.0))


def _angle_about(a: np.ndarray, b: np.ndarray, axis: np.ndarray) -> float:
    """The signed angle from `a` to `b` about `axis`, both projected on the plane normal to it."""
    a = a - axis * float(a @ axis)
    b = b - axis * float(b @ axis)
    return math.atan2(float(np.cross(a, b) @ axis), float(a @ b))
