"""The pipeline end to end: a world file to an expanded scene, to a compiled MuJoCo model.

Each stage stays callable on its own (`parse_file`, `build_scene`, `expand_scene`,
`compile_scene`); these helpers chain them the way the command line does.
"""

from __future__ import annotations

from pathlib import Path

from wbtc.compile.compiler import CompileResult, compile_scene
from wbtc.compile.context import CompileOptions
from wbtc.errors import WbtcError
from wbtc.proto.expand import expand_scene
from wbtc.proto.instances import Expansion
from wbtc.scene import build_scene
from wbtc.scene.model import Scene
from wbtc.vrml import parse_file


def load_world(path: str | Path, strict: bool = False) -> tuple[Scene, Expansion]:
    """Parse, build and expand a world file.

    Raises:
        WbtcError: the file is missing, or a syntax, schema or PROTO error.
    """
    path = Path(path)
    if not path.is_file():
        raise WbtcError(f"no such world file: {path}")
    return expand_scene(build_scene(parse_file(path)), strict=strict)


def compile_world(path: str | Path, options: CompileOptions | None = None) -> tuple[CompileResult, Expansion]:
    """Load a world and compile it to MuJoCo (see `compile_scene`)."""
    options = options or CompileOptions()
    scene, expansion = load_world(path, strict=options.strict)
    return compile_scene(scene, options), expansion
