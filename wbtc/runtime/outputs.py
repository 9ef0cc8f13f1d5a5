"""What a run reads and writes besides the simulation: key scripts, traces, the headless summary.

- `--keys FILE`: one `time_s key` per line (`#` comments allowed); a key is a character (`a`,
  `A`, `1`), a Webots key name (`UP`, `DOWN`, `LEFT`, `RIGHT`, `HOME`, `END`, `PAGEUP`,
  `PAGEDOWN`) or an integer code, optionally with `SHIFT+`, `CONTROL+`, `ALT+` prefixes. A press is
  down during the step it falls in and until each robot's keyboard next samples, which reads it once.
- `--trace FILE.csv`: every robot's pose (world frame, axis-angle) each basic time step.
"""

from __future__ import annotations

import csv
from pathlib import Path
from typing import IO

from wbtc.errors import Diagnostic, Span, WbtcError
from wbtc.runtime.runner import RunOutcome
from wbtc.runtime.simulation import Simulation

# Webots' key codes (include/controller/c/webots/keyboard.h).
KEY_CODES = {"END": 312, "HOME": 313, "LEFT": 314, "UP": 315, "RIGHT": 316, "DOWN": 317, "PAGEUP": 366,
             "PAGEDOWN": 367, "NUMPAD_HOME": 375, "NUMPAD_LEFT": 376, "NUMPAD_UP": 377, "NUMPAD_RIGHT": 378,
             "NUMPAD_DOWN": 379, "NUMPAD_END": 382, "SPACE": 32, "ENTER": 4, "ESCAPE": 27}
MODIFIERS = {"SHIFT": 0x10000, "CONTROL": 0x20000, "CTRL": 0x20000, "ALT": 0x40000}


def key_code(text: str) -> int | None:
    """A key as written in a key script to Webots' code (None if unknown)."""
    code = 0
    *mods, key = text.split("+") if len(text) > 1 else [text]
    for mod in mods:
        if mod.upper() not in MODIFIERS:
            return None
        code |= MODIFIERS[mod.upper()]
    if len(key) == 1:
        return code | ord(key.upper())  # Webots reports letters in upper case
    if key.upper() in KEY_CODES:
        return code | KEY_CODES[key.upper()]
    return code | int(key) if key.isdigit() else None


def read_keys(path: Path) -> list[tuple[float, int]]:
    """Parse a key script; errors name the line."""
    keys, errors = [], []
    for number, raw in enumerate(path.read_text(encoding="utf-8").splitlines(), start=1):
        line = raw.split("#", 1)[0].strip() if not raw.strip().startswith("# ") else ""
        if not line:
            continue
        parts = line.split()
        code = key_code(parts[1]) if len(parts) == 2 else None
        try:
            when = float(parts[0])
        except ValueError:
            when = -1.0
        if code is None or when < 0:
            errors.append(Diagnostic("a key line is `TIME_S KEY`, e.g. `1.5 UP` or `2 a`", Span(str(path), number, 1),
                                     source_line=raw))
            continue
        keys.append((when, code))
    if errors:
        raise WbtcError(errors[0].message, diagnostics=errors)
    return keys


class TraceWriter:
    """Writes every robot's pose each basic time step to a CSV file."""

    def __init__(self, stream: IO[str]) -> None:
        self.writer = csv.writer(stream)
        self.writer.writerow(["time", "robot", "x", "y", "z", "axis_x", "axis_y", "axis_z", "angle"])

    def __call__(self, sim: Simulation) -> None:
        """Record one step."""
        for robot in sim.robots:
            pos, rot = sim.robot_pose(robot)
            self.writer.writerow([f"{sim.time:.6g}", robot.entry.name, *(f"{v:.9g}" for v in pos),
                                  *(f"{v:.9g}" for v in rot)])


def summary(outcome: RunOutcome) -> str:
    """The headless end-of-run summary: time, speed, where each robot went."""
    data = outcome.to_json()
    lines = [f"{Path(outcome.world).name}: {data['sim_time']:.2f} s simulated in {data['wall_time']:.2f} s "
             f"({data['realtime_factor']:.0f}x real time); ended: {outcome.end_reason}"]
    for robot in data["robots"]:
        x, y, z = robot["position"]
        code = "" if robot["exit_code"] is None else f", exit code {robot['exit_code']}"
        lines.append(f"  {robot['name']} ({robot['controller'] or 'no controller'}: {robot['status']}{code}): "
                     f"at ({x:.3f}, {y:.3f}, {z:.3f}), travelled {robot['distance']:.3f} m")
    return "\n".join(lines)
