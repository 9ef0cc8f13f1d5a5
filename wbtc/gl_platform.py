"""Which OpenGL platform draws wbtc's images, and when it is loaded.

MuJoCo picks its OpenGL platform when it is imported, from `MUJOCO_GL` (GLFW by default, which needs
a display; EGL or OSMesa without one), and loads it then: PyOpenGL and the platform's bindings cost
a run 40-60 ms of start-up even when nothing is ever drawn (a world without cameras, run headless).

- `headless_platform`: EGL when the machine has it, else OSMesa (`wbtc` sets `MUJOCO_GL` to it
  when there is no display, before MuJoCo is imported).
- `import_mujoco_without_gl`: `wbtc run` and `wbtc compile` import MuJoCo with its platform left
  out (`MUJOCO_GL=disable` for the import only); the platform module is imported when the first
  image is drawn (`gl_context`). Other programs that import wbtc get MuJoCo as usual.
- `gl_context`: an OpenGL context of the platform `MUJOCO_GL` names now (a display that does not
  answer turns a run headless after MuJoCo's import, see `wbtc.runtime.launch`).
"""

from __future__ import annotations

import importlib
import os
import sys


def headless_platform() -> str:
    """"egl" when the EGL library loads, else "osmesa".

    Loading the library is how the platform will be used; it costs under a millisecond where
    `ctypes.util.find_library` runs `ldconfig` (about 10 ms).
    """
    import ctypes

    for name in ("libEGL.so.1", "libEGL.so"):
        try:
            ctypes.CDLL(name)
        except OSError:
            continue
        return "egl"
    return "osmesa"


def import_mujoco_without_gl() -> None:
    """Import MuJoCo now, leaving its OpenGL platform to the first image (see the module docstring)."""
    if "mujoco" in sys.modules:
        return
    chosen = os.environ.get("MUJOCO_GL")
    os.environ["MUJOCO_GL"] = "disable"
    try:
        import mujoco  # noqa: F401 - imported for its side effect: MuJoCo without an OpenGL platform
    finally:
        if chosen is None:
            del os.environ["MUJOCO_GL"]
        else:
            os.environ["MUJOCO_GL"] = chosen


def gl_context(width: int, height: int) -> object:
    """An OpenGL context for offscreen images, of the platform `MUJOCO_GL` names now.

    MuJoCo's own `mujoco.GLContext` is used when it has one of that platform. It has none when it
    was imported without a platform (`import_mujoco_without_gl`), and the wrong one when a script
    imported `mujoco` before `wbtc` on a machine without a display (GLFW, which needs one): then the
    platform's module is imported here.
    """
    import mujoco

    platform = os.environ.get("MUJOCO_GL", "").lower() or "glfw"
    if platform in ("1", "on", "true", "enable", "enabled"):
        platform = "glfw"
    bound = getattr(mujoco, "GLContext", None)
    if bound is not None and not (platform in ("egl", "osmesa") and bound.__module__.startswith("mujoco.glfw")):
        return bound(width, height)
    return importlib.import_module(f"mujoco.{platform}").GLContext(width, height)
