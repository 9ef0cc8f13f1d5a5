"""The typed result of one run (`wbtc.run`, one row of `wbtc batch`): pydantic models.

`RunResult` holds what `wbtc run --json` prints (time, end reason, each robot's status, exit code,
final pose and distance) plus what a script needs and a terminal does not show: each robot's
captured stdout and stderr, a per-step trace of its pose as numpy arrays, the supervisor's
`simulationQuit` status and the recorded video. In Jupyter a result shows itself as a small table,
with the video inline when the run was recorded.
"""

from __future__ import annotations

import base64
import html
import math
from pathlib import Path
from typing import Any

import numpy as np
from pydantic import BaseModel, ConfigDict, field_serializer, field_validator

#: A run's own status: it ran to its end, or was stopped by its wall-clock timeout. Batch rows add
#: "crashed" (the simulating process died), "error" (the world or the plan is wrong) and "failed"
#: (its worker died twice).
RUN_STATUSES = ("done", "timeout", "crashed", "error", "failed")


class Trace(BaseModel):
    """One robot's pose at the end of every basic time step.

    Attributes:
        time: simulated time of each sample, s, shape (n,).
        position: the robot's position in the world's own axes, m, shape (n, 3).
        rotation: its orientation as axis-angle (x, y, z, angle), shape (n, 4).
    """

    model_config = ConfigDict(arbitrary_types_allowed=True)

    time: np.ndarray
    position: np.ndarray
    rotation: np.ndarray

    @field_validator("time", "position", "rotation", mode="before")
    @classmethod
    def _array(cls, value: Any) -> np.ndarray:
        return np.asarray(value, dtype=float)

    @field_serializer("time", "position", "rotation")
    def _listed(self, value: np.ndarray) -> list:
        return value.tolist()


class RobotResult(BaseModel):
    """One robot at the end of a run.

    Attributes:
        name: the robot's `name` field.
        controller: the controller that ran (the substituted file's name when one was given).
        status: "running" (still stepping when the run ended), "exited" (exit code 0), "crashed"
            (any other exit code), "killed" (stopped by the run's timeout) or "none" (no controller).
        exit_code: the controller process's exit code (None when it had none or was still running).
        position: the final position in the world's own axes, m.
        rotation: the final orientation, axis-angle.
        distance: the path length the robot travelled, m.
        stdout: what the controller printed, line by line as it came.
        stderr: what it wrote to stderr (a traceback, for a crash).
        trace: its pose every basic time step (None when tracing was off).
    """

    name: str
    controller: str
    status: str
    exit_code: int | None
    position: list[float]
    rotation: list[float]
    distance: float
    stdout: str = ""
    stderr: str = ""
    trace: Trace | None = None


class RunResult(BaseModel):
    """What one run did.

    Attributes:
        world: the world file.
        status: one of `RUN_STATUSES`.
        end_reason: why it ended, in words ("duration", "simulationQuit(0)", "wall-clock timeout (5 s)").
        sim_time: simulated seconds.
        wall_time: wall-clock seconds the run took (compiling excluded).
        realtime_factor: sim_time / wall_time.
        quit_status: a supervisor's `simulationQuit` status, if it called it.
        seed: the sensor-noise seed (None: the world's randomSeed).
        robots: every robot, in world order.
        warnings: what loading and compiling the world said, one line each.
        record: the video or page the run wrote, if any.
    """

    world: str
    status: str = "done"
    end_reason: str
    sim_time: float
    wall_time: float
    realtime_factor: float
    quit_status: int | None = None
    seed: int | None = None
    robots: list[RobotResult]
    warnings: list[str] = []
    record: str | None = None

    def robot(self, name: str) -> RobotResult:
        """The robot named `name`.

        Raises:
            KeyError: no robot has that name.
        """
        for robot in self.robots:
            if robot.name == name:
                return robot
        raise KeyError(f"no robot named {name!r} (robots: {', '.join(r.name for r in self.robots)})")

    def summary(self) -> str:
        """The lines `wbtc run` prints at the end of a headless run."""
        factor = f"{self.realtime_factor:.0f}x" if math.isfinite(self.realtime_factor) else "inf"
        lines = [f"{Path(self.world).name}: {self.sim_time:.2f} s simulated in {self.wall_time:.2f} s "
                 f"({factor} real time); ended: {self.end_reason}"]
        for r in self.robots:
            code = "" if r.exit_code is None else f", exit code {r.exit_code}"
            x, y, z = r.position
            lines.append(f"  {r.name} ({r.controller or 'no controller'}: {r.status}{code}): "
                         f"at ({x:.3f}, {y:.3f}, {z:.3f}), travelled {r.distance:.3f} m")
        return "\n".join(lines)

    def __str__(self) -> str:
        return self.summary()

    def _repr_html_(self) -> str:
        """Jupyter's view: the summary as a table, and the recorded video inline."""
        rows = "".join(
            f"<tr><td>{html.escape(r.name)}</td><td>{html.escape(r.controller)}</td><td>{r.status}</td>"
            f"<td>{'' if r.exit_code is None else r.exit_code}</td>"
            f"<td>({', '.join(f'{v:.3f}' for v in r.position)})</td><td>{r.distance:.3f}</td></tr>"
            for r in self.robots)
        head = (f"<p><b>{html.escape(Path(self.world).name)}</b>: {self.sim_time:.2f} s simulated in "
                f"{self.wall_time:.2f} s; {html.escape(self.status)}, ended: {html.escape(self.end_reason)}</p>")
        table = ("<table><tr><th>robot</th><th>controller</th><th>status</th><th>exit code</th>"
                 f"<th>position (m)</th><th>distance (m)</th></tr>{rows}</table>")
        return head + table + _media_html(self.record)


def _media_html(record: str | None) -> str:
    """The recorded video (or replay page) embedded in the notebook's HTML, if the file is there."""
    if not record or not Path(record).is_file():
        return ""
    path = Path(record)
    data = path.read_bytes()
    if path.suffix.lower() == ".html":
        return f'<iframe srcdoc="{html.escape(data.decode("utf-8"))}" width="640" height="480"></iframe>'
    encoded = base64.b64encode(data).decode("ascii")
    if path.suffix.lower() == ".gif":
        return f'<img src="data:image/gif;base64,{encoded}">'
    return f'<video controls width="640" src="data:video/mp4;base64,{encoded}"></video>'
