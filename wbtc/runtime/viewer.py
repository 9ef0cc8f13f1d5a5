"""MuJoCo's interactive viewer on a running simulation (`wbtc run` with a display).

Keys typed in the viewer reach the robots' Keyboard devices (GLFW codes turned into Webots'),
supervisor labels show as its top-left overlay text, and when a supervisor changes the world so
that it is compiled again (a robot spawned or removed, a PROTO field changed, a reset) the viewer
is opened anew on the new model, keeping the user's camera.

Not honoured yet: the labels' positions, colours and sizes (the overlay lists their texts).
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

import mujoco

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation

# GLFW key codes the viewer reports, to Webots' (letters and digits are ASCII in both).
GLFW_KEYS = {262: 316, 263: 314, 264: 317, 265: 315, 266: 366, 267: 367, 268: 313, 269: 312, 32: 32}
_CAMERA = ("type", "fixedcamid", "trackbodyid", "lookat", "distance", "azimuth", "elevation")


class LiveViewer:
    """The viewer window, reopened whenever the simulation's model is swapped."""

    def __init__(self, sim: Simulation, launch: Callable[..., Any] | None = None) -> None:
        if launch is None:
            import mujoco.viewer

            launch = mujoco.viewer.launch_passive
        self._launch = launch
        self._on_key = lambda code: sim.keys_down.append(GLFW_KEYS.get(code, code))
        self.handle = launch(sim.model, sim.data, key_callback=self._on_key)
        self.generation = sim.generation

    def sync(self, sim: Simulation) -> bool:
        """Show the latest step; False once the user has closed the window."""
        if not self.handle.is_running():
            return False
        if sim.generation != self.generation:
            self._reopen(sim)
        if sim.labels and hasattr(self.handle, "set_texts"):
            # Supervisor labels (setLabel) as the viewer's top-left overlay text, in id order.
            text = "\n".join(label[0] for _, label in sorted(sim.labels.items()) if label[0])
            try:
                self.handle.set_texts((None, int(mujoco.mjtGridPos.mjGRID_TOPLEFT), text, ""))
            except (TypeError, ValueError):  # older viewers take other shapes: labels stay in recordings only
                pass
        self.handle.sync()
        return True

    def _reopen(self, sim: Simulation) -> None:
        """A new window on the new model; the camera stays where the user left it."""
        camera = {name: _copy(getattr(self.handle.cam, name)) for name in _CAMERA}
        self.handle.close()
        self.handle = self._launch(sim.model, sim.data, key_callback=self._on_key)
        for name, value in camera.items():
            setattr(self.handle.cam, name, value)
        self.generation = sim.generation

    def close(self) -> None:
        """Close the window."""
        self.handle.close()


def _copy(value: Any) -> Any:
    return value.copy() if hasattr(value, "copy") else value


def open_viewer(sim: Simulation) -> LiveViewer | None:
    """The viewer, or None (with a note) when this display cannot show one."""
    try:
        return LiveViewer(sim)
    except Exception as exc:  # no usable GL on this display: run headless instead
        print(f"wbtc: the viewer cannot open ({exc}); running headless", file=sys.stderr)
        return None
