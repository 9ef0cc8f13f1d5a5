"""A batch plan (`wbtc batch PLAN.toml`): what to run, read and checked before any run starts.

```toml
world = "worlds/epuck_obstacles.wbt"   # or worlds = [...]
duration = 30                           # simulated seconds of each run
seeds = [1, 2, 3]                       # or {start = 0, stop = 10}; default: the world's randomSeed
timeout = 60                            # wall-clock seconds of one run
memory_mb = 2048                        # address-space limit of each process of a run
output = "results.csv"                  # .csv, .jsonl or .parquet
grader = "grader.py:grade"              # optional: grade(result) -> score or (score, message)
trace = true                            # keep each robot's per-step pose for the grader
physics_step = 2                        # longest MuJoCo substep, ms (as `wbtc run --physics-step`)
ode_contacts = false                    # ODE's soft contacts and bounce (as `wbtc run --ode-contacts`)

[controllers]                           # robot name = a folder (one run per .py in it), a file,
"e-puck" = "submissions/"               # a glob, or a list of those

[args]                                  # robot name = a list of alternatives (each a list of strings)
"e-puck" = [["--speed", "2"], ["--speed", "4"]]

[fields]                                # NODE.field = a list of alternatives, or a range
"BOX.translation" = [[0.2, 0, 0.05], [0.3, 0, 0.05]]
"WorldInfo.basicTimeStep" = {start = 8, stop = 32, step = 8}
```

Every combination of worlds, controllers, args, field values and seeds is one run. Relative
paths are read from the plan's folder. Every mistake is a `WbtcError` at the plan's line.
"""

from __future__ import annotations

import difflib
import glob
import importlib.util
import inspect
import itertools
import json
import math
import re
import tomllib
from collections.abc import Callable
from pathlib import Path
from typing import Any

from pydantic import BaseModel

from wbtc.errors import Diagnostic, Span, WbtcError

TOP_KEYS = ("world", "worlds", "duration", "seeds", "timeout", "memory_mb", "output", "grader", "trace",
            "physics_step", "ode_contacts", "controllers", "args", "fields")
OUTPUT_SUFFIXES = (".csv", ".jsonl", ".parquet")


class Job(BaseModel):
    """One run of a plan: everything a worker needs, and the parameters that go into its table row."""

    index: int
    world: str
    controllers: dict[str, str] = {}
    args: dict[str, list[str]] = {}
    fields: dict[str, Any] = {}
    seed: int | None = None
    duration: float | None = None
    timeout: float = 600.0
    memory_mb: int | None = None
    trace: bool = True
    physics_step: float = 2.0
    ode_contacts: bool = False
    params: dict[str, str] = {}  # the table's parameter columns, as written there

    @property
    def key(self) -> str:
        """What identifies the run across an interrupted batch and its `--resume`."""
        return json.dumps(self.params, sort_keys=True)


class Plan(BaseModel):
    """A plan read and checked."""

    path: str
    worlds: list[str]
    duration: float | None = None
    seeds: list[int | None] = [None]
    timeout: float = 600.0
    memory_mb: int | None = 4096
    output: str
    grader: str | None = None
    trace: bool = True
    physics_step: float = 2.0
    ode_contacts: bool = False
    controllers: dict[str, list[str]] = {}
    args: dict[str, list[list[str]]] = {}
    fields: dict[str, list[Any]] = {}
    robots: list[str] = []  # every robot of the plan's worlds, in order (the table's robot columns)

    def jobs(self) -> list[Job]:
        """Every run of the plan, in a fixed order."""
        base = Path(self.path).parent
        axes: list[list[tuple[str, str, Any]]] = [[("world", w, w) for w in self.worlds]]
        axes += [[(f"controller.{r}", _shown(p, base), p) for p in files] for r, files in self.controllers.items()]
        axes += [[(f"args.{r}", " ".join(a), a) for a in alts] for r, alts in self.args.items()]
        axes += [[(f"field.{k}", json.dumps(v), v) for v in alts] for k, alts in self.fields.items()]
        axes.append([("seed", "" if s is None else str(s), s) for s in self.seeds])
        jobs = []
        for index, combo in enumerate(itertools.product(*axes)):
            params = {name: shown for name, shown, _ in combo}
            values = {name: value for name, _, value in combo}
            params["world"] = _shown(values["world"], base)
            jobs.append(Job(
                index=index, world=values["world"], seed=values["seed"], duration=self.duration,
                timeout=self.timeout, memory_mb=self.memory_mb, trace=self.trace, params=params,
                physics_step=self.physics_step, ode_contacts=self.ode_contacts,
                controllers={n[11:]: v for n, v in values.items() if n.startswith("controller.")},
                args={n[5:]: v for n, v in values.items() if n.startswith("args.")},
                fields={n[6:]: v for n, v in values.items() if n.startswith("field.")}))
        return jobs

    def load_grader(self) -> Callable[[Any], Any] | None:
        """The grader function (checked by `read_plan`)."""
        return _load_grader(self.grader, Path(self.path).parent) if self.grader else None


def _shown(path: str, base: Path) -> str:
    try:
        return str(Path(path).relative_to(base.resolve()))
    except ValueError:
        return path


class _Lines:
    """Where each key of a TOML file is written (tomllib gives no positions)."""

    def __init__(self, path: Path, text: str) -> None:
        self.path = path
        self.lines = text.splitlines()
        self.where: dict[tuple[str, str], tuple[int, int]] = {}
        table = ""
        for number, raw in enumerate(self.lines, start=1):
            line = raw.strip()
            if line.startswith("[") and not line.startswith("[["):
                table = line.strip("[] ")
                self.where.setdefault(("", table), (number, raw.index("[") + 1))
                continue
            if "=" in line and not line.startswith("#"):
                key = line.split("=", 1)[0].strip().strip('"').strip("'")
                self.where.setdefault((table, key), (number, raw.index(line[0]) + 1))

    def error(self, message: str, table: str, key: str, hint: str | None = None) -> WbtcError:
        number, column = self.where.get((table, key), self.where.get(("", table), (1, 1)))
        source = self.lines[number - 1] if number <= len(self.lines) else ""
        return WbtcError(message, diagnostics=[Diagnostic(message, Span(str(self.path), number, column), hint=hint,
                                                          source_line=source)])


def read_plan(path: Path) -> Plan:
    """Read and check a plan: its worlds load, robots and fields exist, the grader imports.

    Raises:
        WbtcError: at the plan's line, for the first mistake found.
    """
    if not path.is_file():
        raise WbtcError(f"no such plan file: {path}")
    text = path.read_text(encoding="utf-8")
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        found = re.search(r"at line (\d+), column (\d+)", str(exc))
        line, col = (int(found[1]), int(found[2])) if found else (1, 1)
        raise WbtcError(f"the plan is not valid TOML: {str(exc).split(' (at')[0]}",
                        Span(str(path), line, col)) from None
    lines = _Lines(path, text)
    base = path.resolve().parent
    for key in data:
        if key not in TOP_KEYS:
            close = difflib.get_close_matches(key, TOP_KEYS, n=1)
            raise lines.error(f"unknown plan key '{key}'", "", key, f"did you mean '{close[0]}'?" if close else None)
    worlds = _worlds(data, lines, base)
    output = str(data.get("output", "results.csv"))
    if Path(output).suffix.lower() not in OUTPUT_SUFFIXES:
        raise lines.error(f"the output table must be a .csv, .jsonl or .parquet file, not '{output}'", "", "output")
    if Path(output).suffix.lower() == ".parquet" and importlib.util.find_spec("pyarrow") is None:
        raise lines.error("a .parquet table needs pyarrow: pip install 'wbtc[batch]'", "", "output")
    plan = Plan(path=str(path.resolve()), worlds=worlds, output=str(base / output),
                duration=_number(data, "duration", lines, positive=True),
                timeout=_number(data, "timeout", lines, positive=True) or 600.0,
                memory_mb=int(_number(data, "memory_mb", lines, positive=True) or 4096),
                trace=bool(data.get("trace", True)), seeds=_seeds(data, lines),
                physics_step=_number(data, "physics_step", lines, positive=True) or 2.0,
                ode_contacts=_flag(data, "ode_contacts", lines),
                controllers=_controllers(data.get("controllers", {}), lines, base),
                args=_args(data.get("args", {}), lines), fields=_fields(data.get("fields", {}), lines))
    if "grader" in data:
        plan.grader = str(data["grader"])
        try:
            _load_grader(plan.grader, base)
        except WbtcError as exc:
            raise lines.error(str(exc.diagnostics[0].message), "", "grader") from None
    plan.robots = _check_worlds(plan, lines)
    return plan


def _worlds(data: dict[str, Any], lines: _Lines, base: Path) -> list[str]:
    key = "worlds" if "worlds" in data else "world"
    value = data.get(key)
    if value is None:
        raise WbtcError("the plan names no world: add `world = \"path/to/world.wbt\"`", Span(str(lines.path), 1, 1))
    worlds = [value] if isinstance(value, str) else list(value)
    resolved = []
    for world in worlds:
        full = (base / str(world)).resolve()
        if not full.is_file():
            raise lines.error(f"no such world file: {world}", "", key)
        resolved.append(str(full))
    return resolved


def _flag(data: dict[str, Any], key: str, lines: _Lines) -> bool:
    value = data.get(key, False)
    if not isinstance(value, bool):
        raise lines.error(f"'{key}' must be true or false, not {value!r}", "", key)
    return value


def _number(data: dict[str, Any], key: str, lines: _Lines, positive: bool = False) -> float | None:
    value = data.get(key)
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, int | float) or (positive and value <= 0):
        raise lines.error(f"'{key}' must be a {'positive ' if positive else ''}number, not {value!r}", "", key)
    return float(value)


def _range(value: dict[str, Any], lines: _Lines, table: str, key: str) -> list[float | int]:
    """`{start, stop, step}` (stop excluded, as Python's range) or `{start, stop, num}` (both ends)."""
    try:
        start, stop = value["start"], value["stop"]
        if "num" in value:
            num = int(value["num"])
            items = [start + (stop - start) * i / max(num - 1, 1) for i in range(num)]
            if all(isinstance(v, int) for v in (start, stop)) and all(float(v).is_integer() for v in items):
                items = [int(v) for v in items]  # {start = 8, stop = 16, num = 3}: 8, 12, 16
            return items
        step = value.get("step", 1)
        count = math.ceil((stop - start) / step - 1e-9)
        items = [start + step * i for i in range(max(count, 0))]
    except (KeyError, TypeError, ZeroDivisionError):
        raise lines.error("a range is {start = A, stop = B, step = S} or {start = A, stop = B, num = N}",
                          table, key) from None
    if not items:
        raise lines.error("this range is empty", table, key)
    return items


def _alternatives(value: Any, lines: _Lines, table: str, key: str) -> list[Any]:
    if isinstance(value, dict):
        return _range(value, lines, table, key)
    if not isinstance(value, list) or not value:
        raise lines.error(f"'{key}' must be a non-empty list of alternatives (one run each) or a range "
                          f"{{start, stop, step}}", table, key)
    return value


def _seeds(data: dict[str, Any], lines: _Lines) -> list[int | None]:
    if "seeds" not in data:
        return [None]
    seeds = _alternatives(data["seeds"], lines, "", "seeds")
    if not all(isinstance(s, int) and not isinstance(s, bool) for s in seeds):
        raise lines.error("seeds must be integers", "", "seeds")
    return [int(s) for s in seeds]


def _controllers(table: dict[str, Any], lines: _Lines, base: Path) -> dict[str, list[str]]:
    result = {}
    for robot, value in table.items():
        files: list[str] = []
        for item in [value] if isinstance(value, str) else list(value):
            target = base / str(item)
            if target.is_dir():
                found = sorted(target.glob("*.py"))
            elif any(c in str(item) for c in "*?["):
                found = sorted(Path(p) for p in glob.glob(str(target)))
            else:
                found = [target] if target.is_file() else []
            if not found:
                raise lines.error(f"no controller file at '{item}' (a folder of .py files, a file or a glob)",
                                  "controllers", robot)
            files += [str(f.resolve()) for f in found]
        result[robot] = files
    return result


def _args(table: dict[str, Any], lines: _Lines) -> dict[str, list[list[str]]]:
    result = {}
    for robot, value in table.items():
        alternatives = _alternatives(value, lines, "args", robot)
        result[robot] = [[str(a) for a in alt] if isinstance(alt, list) else [str(alt)] for alt in alternatives]
    return result


def _fields(table: dict[str, Any], lines: _Lines) -> dict[str, list[Any]]:
    return {key: _alternatives(value, lines, "fields", key) for key, value in table.items()}


def _check_worlds(plan: Plan, lines: _Lines) -> list[str]:
    """Load each world once: the robots the plan names exist, each field value fits its field."""
    from wbtc.pipeline import load_world
    from wbtc.runtime.overrides import find_field, typed_value
    from wbtc.runtime.scene_tree import SceneTree

    robots: list[str] = []
    for world in plan.worlds:
        try:
            scene, _ = load_world(world)
        except WbtcError as exc:
            raise lines.error(f"the world {Path(world).name} does not load: {exc}", "",
                              "worlds" if ("", "worlds") in lines.where else "world") from None
        names = [str(n.get("name")) for n in scene.walk() if n.is_a("Robot")]
        robots += [n for n in names if n not in robots]
        for table in ("controllers", "args"):
            for robot in getattr(plan, table):
                if robot not in names:
                    raise lines.error(f"{Path(world).name} has no robot named '{robot}' (robots: "
                                      f"{', '.join(names) or 'none'})", table, robot)
        tree = SceneTree(scene)
        for key, values in plan.fields.items():
            try:
                _, ref = find_field(tree, key)
                for value in values:
                    typed_value(key, ref.type, value)
            except WbtcError as exc:
                raise lines.error(f"{Path(world).name}: {exc.diagnostics[0].message}", "fields", key) from None
    return robots


def _load_grader(spec: str, base: Path) -> Callable[[Any], Any]:
    """`file.py:function` (or `module:function`) to the function."""
    if ":" not in spec:
        raise WbtcError(f"the grader is `FILE.py:FUNCTION`, not '{spec}'")
    where, name = spec.rsplit(":", 1)
    if where.endswith(".py"):
        file = (base / where).resolve()
        if not file.is_file():
            raise WbtcError(f"the grader file does not exist: {where}")
        module_spec = importlib.util.spec_from_file_location(f"wbtc_grader_{file.stem}", file)
        assert module_spec is not None and module_spec.loader is not None
        module = importlib.util.module_from_spec(module_spec)
        try:
            module_spec.loader.exec_module(module)
        except Exception as exc:  # noqa: BLE001 (any error of the user's file is reported, not raised)
            raise WbtcError(f"the grader file {where} fails to import: {type(exc).__name__}: {exc}") from None
    else:
        try:
            module = importlib.import_module(where)
        except ImportError as exc:
            raise WbtcError(f"the grader module '{where}' cannot be imported: {exc}") from None
    function = getattr(module, name, None)
    if not callable(function):
        raise WbtcError(f"{where} has no function '{name}'")
    try:
        inspect.signature(function).bind(None)
    except TypeError:
        raise WbtcError(f"the grader {name}() must take one argument (the run's result)") from None
    return function
