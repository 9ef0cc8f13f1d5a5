"""What compiling a scene gives (`CompileResult`), apart from the compiler itself.

Kept in a module of its own so that a run whose world comes from `wbtc.world_cache` unpickles its
result without importing the compile stage (the body builder, geometry, devices): about a fifth of
wbtc's own import time at start-up.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import mujoco

from wbtc.compile.context import CompileOptions
from wbtc.compile.table import DeviceTable
from wbtc.errors import Diagnostic
from wbtc.scene.model import Scene


@dataclass
class CompileResult:
    """What compiling a scene gives.

    Attributes:
        model: the compiled model.
        table: the DeviceTable for the runtime.
        warnings: Webots fields not honoured yet, unreadable files, approximations.
        texture_paths: each MuJoCo texture's image file.
        scene: the scene that was compiled, and `options` how (to compile it again for `spec`).
    """

    model: mujoco.MjModel
    table: DeviceTable
    warnings: list[Diagnostic] = field(default_factory=list)
    texture_paths: dict[str, str] = field(default_factory=dict)
    scene: Scene | None = None
    options: CompileOptions | None = None
    built_spec: mujoco.MjSpec | None = field(default=None, repr=False)

    @property
    def spec(self) -> mujoco.MjSpec:
        """The MuJoCo spec (write MJCF with `spec.to_xml()`; textures are in `spec.assets`).

        A spec does not pickle: a result read back from `wbtc.world_cache` compiles its scene again
        the first time its spec is asked for (the same scene and options give the same elements).
        """
        if self.built_spec is None:
            from wbtc.compile.compiler import compile_scene  # the compile stage, only now

            self.built_spec = compile_scene(self.scene, self.options).built_spec
        return self.built_spec

    def __getstate__(self) -> dict:
        """Everything but the spec (see `spec`)."""
        return {**self.__dict__, "built_spec": None}

    def summary(self) -> str:
        """The one-line summary `wbtc compile` prints."""
        m = self.model
        devices = sum(len(r.devices) for r in self.table.robots)
        return (f"{m.nbody - 1} bodies, {m.njnt} joints, {m.nu} actuators, {m.ngeom} geoms, "
                f"{len(self.table.robots)} robots, {devices} devices")
