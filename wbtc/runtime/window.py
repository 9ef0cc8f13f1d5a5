"""The window of `wbtc run` with a display: the world from its Viewpoint, an overlay, Webots' keys.

wbtc draws the window itself (GLFW and MuJoCo's renderer) rather than through MuJoCo's passive
viewer: its panels, its own key bindings and its window size are not Webots'. The scene is drawn
offscreen through Webots' colour pipeline (`offscreen`, `tone`), as camera images and recordings, and
copied into the window under the overlays. The window:

- opens at 80 % of the screen, seeing the scene from the world's `Viewpoint` (position, orientation,
  fieldOfView, and its `follow`, as recordings do); dragging the mouse turns the view (left button),
  moves it (right button, or left with Shift) and the wheel zooms, as in Webots' 3D view;
- shows in its top-right corner the simulated time (Webots' h:mm:ss:mmm), the real-time factor and
  the mode, and draws supervisor labels at their positions, sizes and colours;
- paces the run to the wall clock unless in fast mode, and takes Webots' simulation keys (see
  `controls.Controls`); every other key goes to the robots' Keyboard devices.

Not honoured yet: clicking to select or drag an object, the Viewpoint's `near` and `followSmoothness`.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

import glfw
import mujoco
import numpy as np

from wbtc.runtime.controls import Controls, webots_key
from wbtc.runtime.labels import LabelPainter
from wbtc.runtime.offscreen import Offscreen
from wbtc.runtime.record import Follow, viewpoint_camera

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation

#: Seconds between two frames: real time, fast mode, paused.
FRAME_S = {"run": 1 / 60, "fast": 1 / 10, "pause": 1 / 30}
SCREEN_SHARE = 0.8


class Window:
    """One window on a running simulation; its `sync` is the run's `on_step` hook."""

    def __init__(self, sim: Simulation, world: Path, on_reset: Callable[[], None] | None = None) -> None:
        """Open the window.

        Raises:
            RuntimeError: GLFW cannot start or open a window on this display.
        """
        if not glfw.init():
            raise RuntimeError("GLFW cannot start on this display")
        mode = glfw.get_video_mode(glfw.get_primary_monitor())
        width, height = int(mode.size.width * SCREEN_SHARE), int(mode.size.height * SCREEN_SHARE)
        glfw.window_hint(glfw.SAMPLES, 4)
        self.world_name = world.name
        self.window = glfw.create_window(width, height, f"wbtc: {world.name}", None, None)
        if not self.window:
            glfw.terminate()
            raise RuntimeError("GLFW cannot open a window on this display")
        glfw.set_window_pos(self.window, (mode.size.width - width) // 2, (mode.size.height - height) // 2)
        glfw.make_context_current(self.window)
        glfw.swap_interval(0)
        self.controls = Controls()
        self.on_reset = on_reset
        self.labels = LabelPainter()
        self.sprites: dict[tuple, tuple[np.ndarray, int, int] | None] = {}
        self.option = mujoco.MjvOption()
        self.camera = mujoco.MjvCamera()
        self.free = False  # False: the Viewpoint (and its follow); True: the user's own camera
        self.mouse: tuple[float, float] | None = None
        self.button = -1
        self.generation = -1
        self.anchor = (time.perf_counter(), sim.time)  # pacing counts from this (wall, sim) pair
        self.speed = (time.perf_counter(), sim.time, 0.0)  # (wall, sim, factor) of the last estimate
        self.last_frame = 0.0
        self.frame_cost = 0.0  # seconds the last frame took to draw
        self._offscreen: tuple[tuple[int, int, int], Offscreen] | None = None  # (size, generation), renderer
        self._build(sim)
        self._callbacks(sim)
        self._draw(sim)

    # -- model ----------------------------------------------------------------------------------------
    def _build(self, sim: Simulation) -> None:
        """Scene and GL context for the simulation's (new) model; the view is kept."""
        self.scene = mujoco.MjvScene(sim.model, maxgeom=20000)
        self.context = mujoco.MjrContext(sim.model, mujoco.mjtFontScale.mjFONTSCALE_150)
        self.uploaded: dict[int, int] = {}  # texture versions this context has (see Simulation.texture_changed)
        self.follow = Follow(sim)
        viewpoint = viewpoint_camera(sim)
        if viewpoint >= 0:  # the free camera opens as wide as the Viewpoint
            sim.model.vis.global_.fovy = float(sim.model.cam_fovy[viewpoint])
        self.generation = sim.generation

    def _view(self, sim: Simulation) -> None:
        """Point `self.camera` for this frame."""
        if self.controls.follow >= 0 and self.controls.follow < len(sim.robots):
            body = sim.robots[self.controls.follow].body
            if self.camera.type != mujoco.mjtCamera.mjCAMERA_TRACKING or self.camera.trackbodyid != body:
                self._to_free(sim)
                self.camera.type, self.camera.trackbodyid = mujoco.mjtCamera.mjCAMERA_TRACKING, body
            return
        if self.camera.type == mujoco.mjtCamera.mjCAMERA_TRACKING:
            self.camera.type = mujoco.mjtCamera.mjCAMERA_FREE
        if self.free:
            return
        camera, pose = self.follow.view(sim)
        if camera < 0:
            mujoco.mjv_defaultFreeCamera(sim.model, self.camera)
            self.free = True
            return
        self.camera.type, self.camera.fixedcamid = mujoco.mjtCamera.mjCAMERA_FIXED, camera
        if pose is not None:
            sim.data.cam_xpos[camera], sim.data.cam_xmat[camera] = pose[0], np.asarray(pose[1]).reshape(9)

    def _to_free(self, sim: Simulation) -> None:
        """Turn the current view into MuJoCo's free camera (orbiting a point ahead), seamlessly."""
        if self.free:
            return
        self.free = True
        camera, pose = self.follow.view(sim)
        if camera < 0:
            return
        pos, mat = pose if pose is not None else (sim.data.cam_xpos[camera], sim.data.cam_xmat[camera])
        pos, forward = np.asarray(pos, float), -np.asarray(mat, float).reshape(3, 3)[:, 2]  # cameras look along -z
        # Orbit about where the view meets the ground (z = 0), or 2 m ahead when it looks up.
        reach = -pos[2] / forward[2] if forward[2] < -0.05 else 2.0
        reach = min(max(reach, 0.2), 50.0)
        cam = self.camera
        cam.type = mujoco.mjtCamera.mjCAMERA_FREE
        cam.lookat[:] = pos + reach * forward
        cam.distance = reach
        cam.azimuth = math.degrees(math.atan2(forward[1], forward[0]))
        cam.elevation = math.degrees(math.asin(max(-1.0, min(1.0, forward[2]))))

    # -- input ----------------------------------------------------------------------------------------
    def _callbacks(self, sim: Simulation) -> None:
        def on_key(window: object, key: int, scancode: int, action: int, mods: int) -> None:
            if action == glfw.RELEASE:
                return
            if not self.controls.key(key, mods, len(sim.robots)):
                code = webots_key(key, mods)
                if code is not None:
                    sim.keys_down.append(code)

        def on_button(window: object, button: int, action: int, mods: int) -> None:
            self.button = button if action == glfw.PRESS else -1
            self.mouse = glfw.get_cursor_pos(window) if action == glfw.PRESS else None

        def on_move(window: object, x: float, y: float) -> None:
            if self.mouse is None or self.button < 0:
                return
            shift = glfw.get_key(window, glfw.KEY_LEFT_SHIFT) == glfw.PRESS
            if self.button == glfw.MOUSE_BUTTON_RIGHT or (shift and self.button == glfw.MOUSE_BUTTON_LEFT):
                action = mujoco.mjtMouse.mjMOUSE_MOVE_V
            elif self.button == glfw.MOUSE_BUTTON_LEFT:
                action = mujoco.mjtMouse.mjMOUSE_ROTATE_V
            else:
                action = mujoco.mjtMouse.mjMOUSE_ZOOM
            self._move(sim, action, x - self.mouse[0], y - self.mouse[1])
            self.mouse = (x, y)

        def on_scroll(window: object, dx: float, dy: float) -> None:
            self._move(sim, mujoco.mjtMouse.mjMOUSE_ZOOM, 0.0, -20.0 * dy)

        glfw.set_key_callback(self.window, on_key)
        glfw.set_mouse_button_callback(self.window, on_button)
        glfw.set_cursor_pos_callback(self.window, on_move)
        glfw.set_scroll_callback(self.window, on_scroll)

    def _move(self, sim: Simulation, action: int, dx: float, dy: float) -> None:
        self._to_free(sim)
        _, height = glfw.get_window_size(self.window)
        # The scene last drawn holds the view the move is relative to (the offscreen renderer's).
        scene = self._offscreen[1].scene if self._offscreen is not None else self.scene
        mujoco.mjv_moveCamera(sim.model, action, dx / max(height, 1), dy / max(height, 1), scene, self.camera)

    # -- the run's hook -------------------------------------------------------------------------------
    def sync(self, sim: Simulation) -> bool:
        """After each basic step: draw, pace, wait while paused; False once the window is closed."""
        if sim.generation != self.generation:
            self._build(sim)
        glfw.poll_events()
        self._take_reset(sim)
        self._measure(sim)
        self._pace(sim)
        while self.controls.paused and not glfw.window_should_close(self.window):
            if self.controls.steps > 0:  # one basic step, then paused again
                self.controls.steps -= 1
                break
            self._draw(sim)
            glfw.wait_events_timeout(FRAME_S["pause"])
            if self._take_reset(sim):
                break
            self.anchor = (time.perf_counter(), sim.time)
        # A frame is due after the frame period, and never takes more than half the wall clock: a
        # software renderer (Mesa on a virtual display) then draws fewer frames, not a slower run.
        period = max(FRAME_S["fast" if self.controls.fast else "run"], 2.0 * self.frame_cost)
        if time.perf_counter() - self.last_frame >= period:
            self._draw(sim)
        return not glfw.window_should_close(self.window)

    def _take_reset(self, sim: Simulation) -> bool:
        if not self.controls.reset:
            return False
        self.controls.reset = False
        if self.on_reset is not None:
            self.on_reset()
        self.anchor = (time.perf_counter(), 0.0)
        return True

    def _pace(self, sim: Simulation) -> None:
        """Sleep until the wall clock catches up with simulated time (not in fast mode)."""
        if self.controls.fast or self.controls.paused:
            self.anchor = (time.perf_counter(), sim.time)
            return
        wall, start = self.anchor
        if sim.time < start:  # the clock went back (a reset)
            self.anchor = (time.perf_counter(), sim.time)
            return
        delay = wall + (sim.time - start) - time.perf_counter()
        if delay > 0:
            time.sleep(delay)

    def _measure(self, sim: Simulation) -> None:
        """The real-time factor, re-estimated twice a second."""
        wall, start, factor = self.speed
        now = time.perf_counter()
        if now - wall >= 0.5:
            factor = (sim.time - start) / (now - wall) if sim.time >= start else 0.0
            self.speed = (now, sim.time, factor)

    # -- drawing --------------------------------------------------------------------------------------
    def _draw(self, sim: Simulation) -> None:
        start = self.last_frame = time.perf_counter()
        glfw.make_context_current(self.window)
        width, height = glfw.get_framebuffer_size(self.window)
        viewport = mujoco.MjrRect(0, 0, width, height)
        saved = sim.data.cam_xpos.copy(), sim.data.cam_xmat.copy()
        self._view(sim)
        # The scene goes through Webots' colour pipeline as camera images and recordings do (linear
        # colours, its light terms, the tone curve at the Viewpoint's exposure): drawn offscreen, then
        # copied into the window, under the overlays.
        exposure = float((sim.table.viewpoint or {}).get("exposure", 1.0))
        rgb = self._renderer(sim, width, height).draw(sim.data, -1, exposure=exposure, view=self.camera)
        sim.data.cam_xpos[:], sim.data.cam_xmat[:] = saved
        glfw.make_context_current(self.window)
        from OpenGL import GL

        GL.glWindowPos2i(0, 0)
        GL.glDrawPixels(width, height, GL.GL_RGB, GL.GL_UNSIGNED_BYTE, np.ascontiguousarray(rgb))
        if sim.labels:
            self._labels(sim, viewport)
        names, values = self.overlay(sim)
        mujoco.mjr_overlay(mujoco.mjtFont.mjFONT_NORMAL, mujoco.mjtGridPos.mjGRID_TOPRIGHT, viewport, names, values,
                           self.context)
        if self.controls.help:
            mujoco.mjr_overlay(mujoco.mjtFont.mjFONT_NORMAL, mujoco.mjtGridPos.mjGRID_TOPLEFT, viewport,
                               *self.controls.help_text(), self.context)
        glfw.swap_buffers(self.window)
        glfw.set_window_title(self.window, f"wbtc: {self.world_name} {clock(sim.time)}")
        self.frame_cost = time.perf_counter() - start

    def _renderer(self, sim: Simulation, width: int, height: int) -> Offscreen:
        """The offscreen renderer of the window's size and model (made again when either changes)."""
        key = (width, height, sim.generation)
        if self._offscreen is None or self._offscreen[0] != key:
            if self._offscreen is not None:
                self._offscreen[1].close()
            renderer = Offscreen(sim.model, width, height, antialias=True, textures=sim.texture_versions,
                                 camera_light=sim.camera_light(), light_boost=sim.light_boost())
            self._offscreen = (key, renderer)
        return self._offscreen[1]

    def _labels(self, sim: Simulation, viewport: mujoco.MjrRect) -> None:
        """Supervisor labels, each drawn as an image blended over the frame at its place.

        (MuJoCo's own mjr_drawPixels draws nothing into a GLFW window here, so OpenGL's is used.)
        """
        from OpenGL import GL

        GL.glDisable(GL.GL_DEPTH_TEST)
        GL.glEnable(GL.GL_BLEND)
        GL.glBlendFunc(GL.GL_SRC_ALPHA, GL.GL_ONE_MINUS_SRC_ALPHA)
        for _, label in sorted(sim.labels.items()):
            key = (label, viewport.width, viewport.height)
            if key not in self.sprites:
                self.sprites[key] = self.labels.sprite(label, viewport.width, viewport.height)
            sprite = self.sprites[key]
            if sprite is None:
                continue
            image, x, y = sprite
            rows, cols = image.shape[:2]
            bottom = viewport.height - y - rows  # OpenGL counts rows from the bottom
            if x >= viewport.width or bottom >= viewport.height:
                continue
            skip_left, skip_bottom = max(-x, 0), max(-bottom, 0)
            part = np.ascontiguousarray(image[::-1][skip_bottom:, skip_left:])
            if part.size == 0:
                continue
            GL.glWindowPos2i(max(x, 0), max(bottom, 0))
            GL.glDrawPixels(part.shape[1], part.shape[0], GL.GL_RGBA, GL.GL_UNSIGNED_BYTE, part)
        if len(self.sprites) > 256:  # labels that change every step: keep the cache small
            self.sprites.clear()

    def overlay(self, sim: Simulation) -> tuple[str, str]:
        """The top-right overlay: names and values (time, speed, mode, followed robot)."""
        controls = self.controls
        mode = "paused" if controls.paused else "fast" if controls.fast else "real time"
        names, values = ["time", "speed", "mode"], [clock(sim.time), f"{self.speed[2]:.2f}x", mode]
        if 0 <= controls.follow < len(sim.robots):
            names.append("follow")
            values.append(sim.robots[controls.follow].entry.name)
        return "\n".join(names), "\n".join(values)

    def close(self) -> None:
        """Close the window."""
        if self._offscreen is not None:
            self._offscreen[1].close()
            self._offscreen = None
        if self.window:
            glfw.destroy_window(self.window)
            self.window = None
        glfw.terminate()


def clock(seconds: float) -> str:
    """Simulated time as Webots shows it: h:mm:ss:mmm."""
    ms = int(round(seconds * 1000))
    return f"{ms // 3_600_000}:{ms // 60_000 % 60:02d}:{ms // 1000 % 60:02d}:{ms % 1000:03d}"
