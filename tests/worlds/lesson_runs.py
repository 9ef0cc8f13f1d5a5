"""Helpers of the lesson-world tests: run a world of `worlds/` headless and read what it printed.

`run_world` runs `wbtc run WORLD --headless --duration S --json --trace F.csv` (in process, like the
other runtime tests) and returns the JSON summary, the output (controllers' lines are prefixed by
`[robot name] `) and every robot's trace as poses with an unwrapped yaw. `probed_world` copies a
world and the shipped controllers into a temporary project where one robot runs the lesson through
`probe_controller.py` (which prints LED changes, sensor reads, camera brightness, supervisor fields).
"""

from __future__ import annotations

import csv
import json
import math
import re
import shutil
from dataclasses import dataclass
from pathlib import Path
from typing import NamedTuple

from typer.testing import CliRunner

from wbtc.cli import app

WORLDS = Path(__file__).resolve().parents[2] / "worlds"
PROBE = Path(__file__).resolve().parent / "probe_controller.py"

# e-puck geometry (protos/robots/E-puck.proto, as Webots' E-puck.proto): wheel radius 0.02 m, wheels at
# y = +-0.026 m (axle 0.052 m), maximum wheel speed 6.28 rad/s; the body is a cylinder of radius 0.037 m.
EPUCK_WHEEL = 0.02
EPUCK_AXLE = 0.052
EPUCK_RADIUS = 0.037


class Pose(NamedTuple):
    """A robot's pose at one time: position (m) and heading (rad, unwrapped, counter-clockwise)."""

    t: float
    x: float
    y: float
    z: float
    yaw: float


@dataclass
class Run:
    """One headless run."""

    data: dict
    output: str
    trace: dict[str, list[Pose]]

    def robot(self, name: str) -> dict:
        """The `--json` entry of a robot."""
        return next(r for r in self.data["robots"] if r["name"] == name)

    def lines(self, name: str) -> list[str]:
        """What a robot's controller printed, one line each, prefix removed."""
        prefix = f"[{name}] "
        return [line[len(prefix):] for line in self.output.splitlines() if line.startswith(prefix)]

    def probe(self, name: str) -> list[tuple[float, str]]:
        """The probe's lines of a robot as (time, text)."""
        found = []
        for line in self.lines(name):
            match = re.match(r"probe t=([0-9.]+) (.*)", line)
            if match:
                found.append((float(match[1]), match[2]))
        return found

    def at(self, name: str, t: float) -> Pose:
        """The traced pose nearest to time t."""
        return min(self.trace[name], key=lambda p: abs(p.t - t))

    def between(self, name: str, t0: float, t1: float) -> list[Pose]:
        """The traced poses with t0 <= t <= t1."""
        return [p for p in self.trace[name] if t0 - 1e-9 <= p.t <= t1 + 1e-9]


def speed(a: Pose, b: Pose) -> float:
    """Mean speed (m/s) along the straight line from pose a to pose b."""
    return math.hypot(b.x - a.x, b.y - a.y) / (b.t - a.t)


def _heading(axis: list[float], angle: float) -> float:
    x, y, z = axis
    norm = math.sqrt(x * x + y * y + z * z) or 1.0
    x, y, z = x / norm, y / norm, z / norm
    c, s = math.cos(angle), math.sin(angle)
    # The world direction of the robot's +x axis (Rodrigues), projected on the floor.
    return math.atan2(y * x * (1 - c) + z * s, c + x * x * (1 - c))


def read_trace(path: Path) -> dict[str, list[Pose]]:
    """Every robot's poses from a `--trace` CSV, yaw unwrapped over the run."""
    trace: dict[str, list[Pose]] = {}
    with path.open(newline="", encoding="utf-8") as stream:
        for row in csv.DictReader(stream):
            poses = trace.setdefault(row["robot"], [])
            yaw = _heading([float(row["axis_x"]), float(row["axis_y"]), float(row["axis_z"])], float(row["angle"]))
            if poses:
                previous = poses[-1].yaw
                yaw = previous + (yaw - previous + math.pi) % (2 * math.pi) - math.pi
            poses.append(Pose(float(row["time"]), float(row["x"]), float(row["y"]), float(row["z"]), yaw))
    return trace


def run_world(world: Path, duration: float, out: Path, keys: str | None = None) -> Run:
    """Run a world headless for `duration` simulated seconds; files go to the folder `out`."""
    out.mkdir(parents=True, exist_ok=True)
    trace = out / f"{world.stem}.csv"
    args = ["run", str(world), "--headless", "--duration", str(duration), "--json", "--trace", str(trace)]
    if keys is not None:
        (out / "keys.txt").write_text(keys, encoding="utf-8")
        args += ["--keys", str(out / "keys.txt")]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    assert "Traceback" not in result.output, result.output
    data = json.loads(result.stdout.strip().splitlines()[-1])
    return Run(data, result.output, read_trace(trace))


def probed_world(project: Path, world: str, probes: dict[str, tuple[str, ...]],
                 replace: dict[str, str] | None = None) -> Path:
    """Copy `worlds/WORLD.wbt` and the shipped controllers to `project`; each robot whose controller is a
    key of `probes` runs it through the probe with those options; `replace` edits the world's text.
    Returns the copied world's path (in `project/worlds`, its controllers in `project/controllers`)."""
    shutil.copytree(WORLDS / "controllers", project / "controllers", dirs_exist_ok=True)
    (project / "controllers" / "probe").mkdir(exist_ok=True)
    shutil.copy(PROBE, project / "controllers" / "probe" / "probe.py")
    text = (WORLDS / f"{world}.wbt").read_text(encoding="utf-8")
    for old, new in (replace or {}).items():
        assert old in text, f"{world}.wbt has no {old!r}"
        text = text.replace(old, new)
    for controller, options in probes.items():
        lesson = project / "controllers" / controller / f"{controller}.py"
        args = " ".join(f'"{a}"' for a in (lesson.as_posix(), *options))
        text, count = re.subn(rf'(\n\s*)controller "{controller}"',
                              rf'\1controller "probe"\1controllerArgs [ {args} ]', text)
        assert count == 1, f"{world}.wbt has {count} robots running {controller}"
    (project / "worlds").mkdir(parents=True, exist_ok=True)
    copy = project / "worlds" / f"{world}.wbt"
    copy.write_text(text, encoding="utf-8")
    return copy
