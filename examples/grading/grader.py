"""The grader of the e-puck Example 4 assignment: avoid the boxes, stop in front of an obstacle.

`wbtc batch plan.toml` calls `grade(result)` with each run's `wbtc.results.RunResult`. Out of 10:
- 4 points: the e-puck travelled at least 0.10 m;
- 3 points: it moved (as above) and never touched a box or a wall (3 mm of clearance all along);
- 3 points: it ends at rest (under 1 cm in its last second) within 10 cm of an obstacle.
A controller that crashed (any exit code but 0, at any time) or never stepped (the run timed out)
scores 0.
"""

import numpy as np

RADIUS = 0.037  # the e-puck's body radius, m
HALF_ARENA = 0.5  # RectangleArena { floorSize 1 1 }: the walls' inner faces, m
BOXES = [(0.3, 0.2), (-0.25, 0.3), (0.2, -0.3)]  # the WoodenBoxes' centres (0.1 m cubes)
HALF_BOX = 0.05


def clearance(xy: np.ndarray) -> np.ndarray:
    """Gap between the e-puck's body and the nearest wall or box, m, for each (x, y) row."""
    walls = HALF_ARENA - np.abs(xy).max(axis=1)
    gaps = [walls]
    for cx, cy in BOXES:
        dx = np.maximum(np.abs(xy[:, 0] - cx) - HALF_BOX, 0.0)
        dy = np.maximum(np.abs(xy[:, 1] - cy) - HALF_BOX, 0.0)
        gaps.append(np.hypot(dx, dy))
    return np.min(gaps, axis=0) - RADIUS


def grade(result):
    """Score one run: (points out of 10, why)."""
    if result.status != "done":
        return 0, "no grade"
    robot = result.robot("e-puck")
    if robot.status == "crashed":
        last = (robot.stderr.strip().splitlines() or ["no message"])[-1]
        return 0, f"the controller crashed (exit code {robot.exit_code}): {last}"
    trace = robot.trace
    xy = trace.position[:, :2]
    points, notes = 0, []
    if robot.distance >= 0.10:
        points += 4
    else:
        notes.append(f"travelled only {robot.distance:.3f} m")
    gap = clearance(xy)
    if gap.min() < 0.003:
        notes.append(f"touched an obstacle at t = {trace.time[int(gap.argmin())]:.2f} s")
    elif points:
        points += 3
    last_second = xy[trace.time >= trace.time[-1] - 1.0]
    moved = float(np.linalg.norm(last_second[-1] - last_second[0]))
    if moved < 0.01 and gap[-1] < 0.10:
        points += 3
    else:
        notes.append("does not end at rest in front of an obstacle")
    return points, "; ".join(notes) or "all good"
