"""`wbtc run --record`: MP4 and GIF videos of the Viewpoint decode with the expected frame counts; labels; follow."""

import json
import math
import shutil
from pathlib import Path

import av
import mujoco
import numpy as np
import pytest
from PIL import Image
from typer.testing import CliRunner

from wbtc.cli import app
from wbtc.pipeline import compile_world
from wbtc.runtime.record import Recorder
from wbtc.runtime.simulation import Simulation

FIXTURES = Path(__file__).parent / "fixtures"


def _record(folder: Path, name: str, *args: str) -> tuple[dict, str]:
    for file in ("record_circle.wbt", "drive.py"):
        shutil.copy(FIXTURES / file, folder / file)
    result = CliRunner().invoke(app, ["run", str(folder / "record_circle.wbt"), "--headless", "--json",
                                      "--record", str(folder / name), *args])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout.strip().splitlines()[-1]), result.output


def _expected(sim_time: float, fps: int) -> int:
    return math.floor(sim_time * fps + 1e-6) + 1


def test_mp4_of_a_10_s_run_decodes_to_the_expected_frames_and_the_robot_moves(tmp_path):
    data, _ = _record(tmp_path, "run.mp4", "--duration", "10")
    assert data["sim_time"] == pytest.approx(10.0)
    with av.open(str(tmp_path / "run.mp4")) as container:
        stream = container.streams.video[0]
        assert (stream.codec_context.name, stream.average_rate) == ("h264", 25)
        frames = [frame.to_ndarray(format="rgb24") for frame in container.decode(video=0)]
    assert len(frames) == _expected(data["sim_time"], 25) == 251
    assert frames[0].shape == (480, 640, 3)
    changes = [float(np.abs(a.astype(int) - b).mean()) for a, b in zip(frames, frames[1:], strict=False)]
    assert sum(change > 0.05 for change in changes) >= 0.9 * len(changes)  # the robot moves all along
    assert np.abs(frames[0].astype(int) - frames[125]).max() > 100
    assert sorted(p.name for p in tmp_path.iterdir()) == ["drive.py", "record_circle.wbt", "run.mp4"]


def test_gif_decodes_with_pillow_to_the_expected_frames(tmp_path):
    data, _ = _record(tmp_path, "run.gif", "--duration", "10")
    with Image.open(tmp_path / "run.gif") as gif:
        assert gif.size == (320, 240)
        count, durations, first = gif.n_frames, [], np.asarray(gif.convert("RGB"))
        for index in range(count):
            gif.seek(index)
            durations.append(gif.info["duration"])
        last = np.asarray(gif.convert("RGB"))
    assert count == _expected(data["sim_time"], 10) == 101
    assert sum(durations) == 100 * count  # plays in real time
    assert np.abs(first.astype(int) - last).max() > 100


def test_html_record_is_an_animation_page_of_the_whole_run(tmp_path):
    import re

    data, _ = _record(tmp_path, "run.html", "--duration", "2")
    text = (tmp_path / "run.html").read_text(encoding="utf-8")
    page = json.loads(re.search(r'<script id="wbtc-animation" type="application/json">(.*?)</script>', text,
                                re.S).group(1))
    # From time 0, a frame every two basic steps of 16 ms (at most 60 a second): 63 frames to 1.984 s, and
    # the run's last state at 2 s.
    assert page["duration"] == pytest.approx(data["sim_time"]) == pytest.approx(2.0)
    assert len(page["frames"]) == 64 and page["frames"][-2]["t"] == pytest.approx(1.984)
    robot = page["bodies"].index(data["robots"][0]["name"])
    last = [p for f in page["frames"] for p in f["p"] if p[0] == robot][-1]
    assert last[1:3] == pytest.approx(data["robots"][0]["position"][:2], abs=1e-4)
    assert not list(tmp_path.glob(".*part*"))


@pytest.mark.parametrize(("name", "message"), [("no_such_folder/run.mp4", "cannot write"),
                                               ("no_such_folder/run.html", "cannot write"),
                                               ("run.avi", "not an .mp4, .gif or .html")])
def test_a_bad_record_path_is_a_clear_error(tmp_path, name, message):
    shutil.copy(FIXTURES / "record_circle.wbt", tmp_path / "record_circle.wbt")
    result = CliRunner().invoke(app, ["run", str(tmp_path / "record_circle.wbt"), "--headless", "--duration", "1",
                                      "--record", str(tmp_path / name)])
    assert result.exit_code == 1
    assert message in result.output and "Traceback" not in result.output
    assert "simulated" not in result.output  # it stopped before running


@pytest.fixture
def sim():
    result, _ = compile_world(FIXTURES / "record_circle.wbt")
    simulation = Simulation(result)
    yield simulation
    simulation.close()


def test_supervisor_labels_are_drawn_over_the_frames(sim, tmp_path):
    recorder = Recorder(sim, tmp_path / "labels.gif")
    plain = recorder.frame(sim)
    sim.labels = {1: ("SCORE", 0.05, 0.05, 0.15, 0xFF0000, 0.0, "Arial"),
                  0: ("hidden", 0.5, 0.5, 0.1, 0x00FF00, 1.0, "Arial")}
    labelled = recorder.frame(sim)
    recorder.abort()
    changed = np.abs(labelled.astype(int) - plain).max(axis=2) > 0
    rows, cols = np.nonzero(changed)
    assert rows.max() < 0.25 * 240 and cols.max() < 0.5 * 320  # the red label only, at the top left
    red = labelled[changed]
    assert (red[:, 0] > 200).mean() > 0.5 and red[:, 1].mean() < 120
    assert not (tmp_path / "labels.gif").exists() and list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("kind", ["Tracking Shot", "Mounted Shot", "Pan and Tilt Shot", "None"])
def test_the_viewpoint_follows_the_robot_as_webots_follow_types_do(sim, tmp_path, kind):
    sim.table.viewpoint.update(follow="e-puck", followType=kind)
    recorder = Recorder(sim, tmp_path / "follow.gif")
    camera = sim.model.camera("viewpoint").id
    start_cam, start_mat = sim.data.cam_xpos[camera].copy(), sim.data.cam_xmat[camera].reshape(3, 3).copy()
    robot = sim.robots[0].body
    sim.data.qpos[:3] += [0.2, 0.1, 0.0]
    start_robot = sim.data.xpos[robot].copy()
    sim.data.qpos[3:7] = [math.cos(math.pi / 4), 0.0, 0.0, math.sin(math.pi / 4)]  # turned 90° left
    mujoco.mj_forward(sim.model, sim.data)
    _, pose = recorder.follow.view(sim)
    recorder.abort()
    if kind == "None":
        assert pose is None
        return
    position, rotation = pose
    if kind == "Tracking Shot":
        assert np.allclose(position, start_cam + [0.2, 0.1, 0.0]) and np.allclose(rotation, start_mat)
    elif kind == "Mounted Shot":
        turn = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
        assert np.allclose(position, [0.2, 0.1, 0.0] + turn @ start_cam, atol=1e-6)
        assert np.allclose(rotation, turn @ start_mat, atol=1e-6)
    else:
        assert np.allclose(position, start_cam)
        before, after = start_robot - start_cam, sim.data.xpos[robot] - position
        # The robot is seen in the same direction from the camera as at the start.
        assert np.allclose(rotation.T @ after / np.linalg.norm(after), start_mat.T @ before / np.linalg.norm(before))


def test_frames_follow_the_viewpoint_exposure(sim, tmp_path):
    # Webots' 3D view tone-maps at the Viewpoint's exposure: a darker exposure darkens every lit pixel.
    recorder = Recorder(sim, tmp_path / "exposure.gif")
    normal = recorder.frame(sim).astype(int)
    sim.table.viewpoint["exposure"] = 0.25
    dark = recorder.frame(sim).astype(int)
    recorder.abort()
    lit = normal.sum(axis=2) > 30
    assert lit.mean() > 0.5
    assert (dark.sum(axis=2)[lit] < normal.sum(axis=2)[lit]).mean() > 0.9
