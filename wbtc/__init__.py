"""wbtc: Webots worlds and their Python controllers, run in MuJoCo.

The pipeline's stages are plain functions (see README's architecture section):
`wbtc.vrml.parse_file` → `wbtc.scene.build_scene` → `wbtc.proto.expand.expand_scene` →
`wbtc.compile.compiler.compile_scene` → `wbtc.runtime.simulation.Simulation`;
`wbtc.pipeline` chains them. `wbtc.run(world, ...)` runs a world from Python and returns a typed
`wbtc.results.RunResult` (see `wbtc.api`).
"""

from __future__ import annotations

import os


def _choose_headless_gl() -> None:
    """Without a display, pick headless OpenGL before MuJoCo is imported: EGL, else OSMesa."""
    if os.environ.get("MUJOCO_GL") or os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"):
        return
    if os.name != "posix" or os.uname().sysname == "Darwin":
        return  # macOS and Windows render offscreen with their own GL
    from wbtc.gl_platform import headless_platform

    os.environ["MUJOCO_GL"] = headless_platform()
    os.environ.setdefault("PYOPENGL_PLATFORM", os.environ["MUJOCO_GL"])


_choose_headless_gl()


def __getattr__(name: str) -> object:
    """`wbtc.run` is imported on first use: the command line's `check` does not need MuJoCo."""
    if name == "run":
        from wbtc.api import run

        return run
    raise AttributeError(f"module 'wbtc' has no attribute {name!r}")
