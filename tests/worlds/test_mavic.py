"""worlds/mavic_2_pro.wbt: the Mavic 2 Pro takes off, holds 1 m, and the arrow keys fly it."""

import math

import pytest
from lesson_runs import WORLDS, run_world


def _held(key: str, start: float, end: float) -> str:
    """A key held down: pressed at every 8 ms step (a key script line is one press)."""
    return "".join(f"{start + 0.008 * k:.3f} {key}\n" for k in range(int((end - start) / 0.008) + 1))


@pytest.fixture(scope="module")
def hover(tmp_path_factory):
    return run_world(WORLDS / "mavic_2_pro.wbt", 9, tmp_path_factory.mktemp("hover"))


def test_it_takes_off_and_holds_one_metre(hover):
    pose = hover.trace["Mavic 2 PRO"]
    assert pose[0].z == pytest.approx(0.065, abs=0.002)  # on its legs
    assert hover.at("Mavic 2 PRO", 1.0).z == pytest.approx(0.065, abs=0.002)  # one second on the ground
    assert max(p.z for p in pose) < 1.6  # the cubic altitude term overshoots a little
    assert hover.at("Mavic 2 PRO", 9.0).z == pytest.approx(1.0, abs=0.1)


def test_up_flies_it_forward_and_right_turns_it_right(hover, tmp_path):
    # UP held from 6 to 8 s: it pitches nose down and gains ground along its heading.
    up = run_world(WORLDS / "mavic_2_pro.wbt", 9, tmp_path / "up", keys=_held("UP", 6.0, 8.0))
    start, plain, flown = hover.at("Mavic 2 PRO", 6.0), hover.at("Mavic 2 PRO", 9.0), up.at("Mavic 2 PRO", 9.0)
    heading = (math.cos(start.yaw), math.sin(start.yaw))
    ahead = (flown.x - plain.x) * heading[0] + (flown.y - plain.y) * heading[1]
    assert ahead > 0.5
    # RIGHT held from 6 to 8 s: it turns clockwise (the yaw falls) compared with the plain flight.
    right = run_world(WORLDS / "mavic_2_pro.wbt", 9, tmp_path / "right", keys=_held("RIGHT", 6.0, 8.0))
    assert right.at("Mavic 2 PRO", 9.0).yaw - plain.yaw < -0.5
