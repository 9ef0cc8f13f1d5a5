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


def test_textured_geoms_carry_their_image_and_repeat(tmp_path):
    import base64
    import io

    from PIL import Image

    scene, _ = load_world(FIXTURES / "textured.wbt")
    sim = Simulation(compile_scene(scene), noise=False)
    recorder = AnimationRecorder(sim, tmp_path / "a.html")
    recorder.close()
    sim.close()
    data = _data(tmp_path / "a.html")
    # One image for the three shapes: ground_stripe.png (100 x 100) as a 128 x 128 PNG (WebGL 1 repeats
    # only power-of-two textures).
    assert len(data["textures"]) == 1 and data["textures"][0].startswith("data:image/png;base64,")
    with Image.open(io.BytesIO(base64.b64decode(data["textures"][0].split(",", 1)[1]))) as image:
        assert image.size == (128, 128)
    textured = {g["type"]: g for g in data["geoms"] if "texture" in g}
    assert sorted(textured) == ["box", "mesh", "plane"]
    assert textured["box"]["texture"] == {"tex": 0, "repeat": [2.0, 1.0]}  # TextureTransform scale 2 1
    assert textured["plane"]["texture"] == {"tex": 0, "repeat": [1.0, 1.0]}
    # The colour is the material's own (white): the texture multiplies it in the player, not its mean.
    assert textured["plane"]["rgba"] == [1.0, 1.0, 1.0, 1.0]
    floor = data["meshes"][textured["mesh"]["mesh"]]
    assert len(floor["uv"]) == 2 * len(floor["faces"])
    assert max(floor["uv"]) == pytest.approx(2.0)  # two tiles along each side


def test_the_player_maps_texture_coordinates_as_mujoco_does():
    # The player computes a plane's and a box's texture coordinates in its vertex shader from the
    # unit shape; here that arithmetic, fed with the player's own maps, against the coordinates that
    # wbtc's infra-red rays read (runtime.surface, which follows MuJoCo's renderer).
    import numpy as np

    player = (Path(__file__).parents[2] / "wbtc" / "runtime" / "player" / "animation.js").read_text(encoding="utf-8")
    context = quickjs.Context()
    context.eval(player)
    scene, _ = load_world(FIXTURES / "textured.wbt")
    sim = Simulation(compile_scene(scene), noise=False)
    model = sim.model
    plane, box = (next(g for g in range(model.ngeom) if model.geom_type[g] == kind and model.geom_matid[g] >= 0)
                  for kind in (0, 6))

    def mapping(geom: int, kind: str) -> dict:
        entry = {"type": kind, "size": model.geom_size[geom].tolist(),
                 "texture": {"tex": 0, "repeat": model.mat_texrepeat[model.geom_matid[geom]].tolist()}}
        return json.loads(context.eval(f"JSON.stringify(WbtcPlayer.texturing({json.dumps(entry)}))"))

    a, b, c, d = mapping(plane, "plane")["map"]
    size = model.geom_size[plane]
    for x, y in [(-1, 1), (1, -1), (0.3, 0.2), (-0.7, -0.1)]:
        expected = sim.surface._uv(plane, int(model.geom_matid[plane]), np.array([x * size[0], y * size[1], 0]))
        assert [a * x + b, c * y + d] == pytest.approx(expected.tolist())
    m = mapping(box, "box")["map"]
    half = model.geom_size[box]
    for unit in [(1, 0.2, -0.5), (-0.4, -1, 0.9), (0.1, 0.6, 1)]:
        axis = int(np.argmax(np.abs(unit)))
        p = [v for k, v in enumerate(unit) if k != axis]  # the face's two other axes, in order
        expected = sim.surface._uv(box, int(model.geom_matid[box]), np.array(unit) * half)
        assert [(p[0] + 1) / 2 * m[0], (1 - p[1]) / 2 * m[2]] == pytest.approx(expected.tolist())
    # An infinite plane (size 0): half an image per metre, shifted by half an image, drawn 50 m wide.
    infinite = {"type": "plane", "size": [0, 0, 1], "texture": {"tex": 0, "repeat": [1, 1]}}
    a, b, c, d = json.loads(context.eval(f"JSON.stringify(WbtcPlayer.texturing({json.dumps(infinite)}).map)"))
    # The unit point (0.02, 0.04) is (1 m, 2 m) on the 50 m wide drawing: u = 0.5 · 1 - 0.5, v = -0.5 · 2 - 0.5.
    assert [a * 0.02 + b, c * 0.04 + d] == pytest.approx([0.5 * 1.0 - 0.5, -0.5 * 2.0 - 0.5])
    sim.close()
