"""What would stop `wbtc run` from running a world as its author meant: `wbtc check`'s run checks.

Three checks, each a warning with the location of the node it is about (an error with `--strict`):

- the world compiles (MuJoCo accepts the model); a compile error is reported where it points, and so
  is a Joint that Webots leaves unattached (no Solid above it: its endPoint moves on its own);
- every texture and mesh file it names can be read (a local file that is missing, a `webots://` or
  `http(s)://` one that is neither installed, cached nor downloadable: `wbtc.compile.remote`);
- every robot's controller is a Python controller wbtc can start: found as Webots looks for it
  (`controllers/NAME/NAME.py` beside the world's folder, or in it), else said why not: only C, C++,
  Java or MATLAB sources are there, the Python file sits at `controllers/NAME.py`, or nothing is.
  `<none>` and `<generic>` need nothing; `<extern>` controllers are started by hand.

Not checked yet: a controller's own imports (a module it needs that is not installed) and its
`runtime.ini` interpreter.
"""

from __future__ import annotations

from pathlib import Path

from wbtc.errors import INVALID_VALUE, UNATTACHED_JOINT, UNREADABLE_FILE, Diagnostic, Span, WbtcError
from wbtc.runtime.controllers import NO_CONTROLLER, controller_folders, find_controller
from wbtc.scene.model import Node, Scene

#: Source files of the languages wbtc does not run, by the suffix Webots looks for.
_OTHER_LANGUAGES = {".c": "C", ".cpp": "C++", ".cc": "C++", ".java": "Java", ".m": "MATLAB"}


def run_checks(scene: Scene, world: Path) -> list[Diagnostic]:
    """The reasons `wbtc run` would not run `scene` as meant, as warnings with their locations.

    Args:
        scene: the scene after PROTO expansion.
        world: the world file (controllers are looked for beside it, as `wbtc run` does).
    """
    return _compile_check(scene) + [d for robot in _robots(scene) for d in _controller_check(robot, world)]


def _compile_check(scene: Scene) -> list[Diagnostic]:
    from wbtc.compile.compiler import compile_scene

    try:
        result = compile_scene(scene)
    except WbtcError as exc:
        return [Diagnostic(d.message, d.span, "warning", d.hint) for d in exc.diagnostics]
    return [w for w in result.warnings if w.topic in (UNREADABLE_FILE, UNATTACHED_JOINT, INVALID_VALUE)]


def _robots(scene: Scene) -> list[Node]:
    return [node for node in scene.walk() if node.is_a("Robot")]


def _controller_check(robot: Node, world: Path) -> list[Diagnostic]:
    name = str(robot.get("controller") or "")
    if name in NO_CONTROLLER or name == "<extern>":
        return []
    if find_controller(world, name) is not None:
        return []
    span = _controller_span(robot)
    label = str(robot.get("name"))
    for folder in controller_folders(world):
        source = next((folder / name / f"{name}{suffix}" for suffix in _OTHER_LANGUAGES
                       if (folder / name / f"{name}{suffix}").is_file()), None)
        if source is not None:
            language = _OTHER_LANGUAGES[source.suffix]
            return [Diagnostic(f"robot {label!r}: controller {name!r} is {language} "
                               f"({_shown(source, world)}); wbtc runs Python controllers", span, "warning")]
        loose = folder / f"{name}.py"
        if loose.is_file():
            return [Diagnostic(f"robot {label!r}: controller {name!r} is {_shown(loose, world)}; Webots and wbtc "
                               f"look for controllers/{name}/{name}.py", span, "warning",
                               hint=f"move it to controllers/{name}/{name}.py")]
    return [Diagnostic(f"robot {label!r}: controller {name!r} not found (looked for controllers/{name}/{name}.py "
                       "beside the world's folder and in it)", span, "warning")]


def _controller_span(robot: Node) -> Span | None:
    """Where the controller is named: the field in the world, else the PROTO instance that made the robot."""
    if robot.origin is not None:
        return robot.origin
    return robot.field_spans.get("controller") or robot.span


def _shown(path: Path, world: Path) -> str:
    """`path` relative to the world's project folder when it is inside it."""
    project = world.resolve().parent.parent
    try:
        return str(path.resolve().relative_to(project))
    except ValueError:
        return str(path)
