"""animationStartRecording: the HTML page wbtc writes, its data, and its player run in QuickJS."""

import json
import re
from pathlib import Path

import pytest
import quickjs
from test_supervisor import _run, _world

from wbtc.compile.compiler import compile_scene
from wbtc.pipeline import load_world
from wbtc.runtime.animation import AnimationRecorder
from wbtc.runtime.simulation import Simulation

FIXTURES = Path(__file__).parent / "fixtures"


def _data(page: Path) -> dict:
    text = page.read_text(encoding="utf-8")
    return json.loads(re.search(r'<script id="wbtc-animation" type="application/json">(.*?)</script>', text,
                                re.S).group(1))


def test_recorded_poses_are_the_simulated_ones(tmp_path):
    scene, _ = load_world(FIXTURES / "referee.wbt")
    sim = Simulation(compile_scene(scene), noise=False)
    ball = sim.model.body("BALL").id
    sim.data.qvel[:3] = [1.0, 0.5, 0.0]  # the ball's free joint comes first: it rolls away
    recorder = AnimationRecorder(sim, tmp_path / "a.html")
    positions = {}
    for _ in range(20):
        sim.step()
        recorder(sim)
        positions[round(sim.time, 3)] = sim.data.xpos[ball].copy()
    recorder.close()
    sim.close()
    data = _data(tmp_path / "a.html")
    assert data["format"] == "wbtc-animation-1" and data["basicTimeStep"] == 16
    # One frame every 2 steps of 16 ms (at most 60 a second), the first at the start: 11 frames.
    assert [f["t"] for f in data["frames"]] == pytest.approx([0.032 * k for k in range(11)], abs=1e-9)
    index = data["bodies"].index("BALL")
    # The first frame holds every body; later ones only what moved (the ball, not the static box).
    assert {p[0] for p in data["frames"][0]["p"]} == set(range(len(data["bodies"])))
    assert data["bodies"].index("BOX") not in {p[0] for f in data["frames"][1:] for p in f["p"]}
    for frame in data["frames"][1:]:
        pose = next(p for p in frame["p"] if p[0] == index)
        assert pose[1:4] == pytest.approx(positions[round(frame["t"], 3)], abs=1e-5)
    ball_geoms = [g for g in data["geoms"] if g["body"] == index]
    assert [(g["type"], g["size"][0]) for g in ball_geoms] == [("sphere", 0.05)]
    assert not (tmp_path / ".a.html.part").exists()


def _play(page: Path, seconds: float) -> dict:
    """Run the page's player in QuickJS with a fake DOM and WebGL (fixtures/play_animation.js)."""
    text = page.read_text(encoding="utf-8")
    payload = re.search(r'<script id="wbtc-animation" type="application/json">(.*?)</script>', text, re.S).group(1)
    player = re.search(r"<script>\n(.*?)\n</script>", text, re.S).group(1)
    context = quickjs.Context()
    context.set("pageData", payload)
    context.eval((FIXTURES / "play_animation.js").read_text(encoding="utf-8"))
    context.eval(player)
    return json.loads(context.eval(f"playFor({seconds})"))


def test_a_supervisor_records_a_page_that_plays_its_run(tmp_path):
    code, _, output = _run(_world(tmp_path, "animation"), "--duration", "2")
    assert code == 0, output
    # A second start with a wrong extension is refused at once, as Webots does.
    assert "[referee] start True False" in output and "[referee] stop True" in output
    assert "should have the '.html' extension" in output
    page = tmp_path / "anim.html"
    data = _data(page)
    times = [f["t"] for f in data["frames"]]
    assert times[0] == 0.0 and times[-1] == pytest.approx(1.0, abs=0.04)
    assert len(times) == pytest.approx(1.0 / 0.032 + 1, abs=1.5)
    assert data["frames"][0]["l"] == {"1": ["goal!", 0.1, 0.2, 0.1, "#00ff00", 0.0]}
    played = _play(page, 0.5)
    frame = data["frames"][played["frame"]]
    assert frame["t"] == pytest.approx(0.5, abs=0.032) and played["clock"] == "0.50 s"
    # Every visual geom is drawn (a capsule would take three calls; this world has none).
    assert played["calls"] == len(data["geoms"])
    assert played["labels"] == [{"text": "goal!", "color": "#00ff00"}]
    # The ball is drawn where the frame put it: its model matrix's translation is the recorded position.
    ball = data["bodies"].index("BALL")
    poses = [p for f in data["frames"][:played["frame"] + 1] for p in f["p"] if p[0] == ball]
    last = poses[-1]
    draw = next(i for i, g in enumerate(data["geoms"]) if g["body"] == ball)
    assert played["models"][draw][12:15] == pytest.approx(last[1:4], abs=1e-6)
    # Played to the end, the player stops there and offers to play again.
    ended = _play(page, 1.5)
    assert ended["play"] == "Play" and ended["frame"] == len(times) - 1 and ended["clock"] == f"{times[-1]:.2f} s"


def test_a_geom_colour_change_is_recorded_once(tmp_path):
    scene, _ = load_world(FIXTURES / "referee.wbt")
    sim = Simulation(compile_scene(scene), noise=False)
    recorder = AnimationRecorder(sim, tmp_path / "a.html")
    index = next(i for i, g in enumerate(recorder.geoms) if sim.model.geom_bodyid[g] == sim.model.body("BALL").id)
    sim.model.geom_rgba[recorder.geoms[index]] = [0.0, 1.0, 0.0, 1.0]  # what an LED does to its shapes
    for _ in range(4):
        sim.step()
        recorder(sim)
    recorder.close()
    sim.close()
    colours = [f.get("c") for f in _data(tmp_path / "a.html")["frames"]]
    assert colours == [None, [[index, 0.0, 1.0, 0.0, 1.0]], None]
