"""Webots' recognition rules on small worlds: the frustum's crossing rule for objects with no corner in view,
points pushed away from a side plane, omnidirectional (spherical) cameras seeing behind them, occlusion 2's
corner rays, non-planar image positions, and the segmentation image."""

import math
from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.camera_projection import Optics, project
from wbtc.runtime.devices import Camera
from wbtc.runtime.simulation import Simulation

# A robot at the origin whose camera looks along +x (ENU world: y left, z up), and the objects given.
WORLD = """#VRML_SIM R2023b utf8
WorldInfo { basicTimeStep 32 }
OBJECTS
Robot {
  children [
    Camera {
      name "camera"
      width 32
      height 24
      fieldOfView FOV
      projection "PROJECTION"
      recognition Recognition { occlusion OCCLUSION segmentation TRUE }
    }
  ]
  controller "<none>"
}
"""


def _solid(name: str, translation: str, geometry: str, colour: str = "1 0 0", rotation: str = "0 0 1 0",
           children: str = "") -> str:
    colours = f"recognitionColors [ {colour} ]" if colour else ""
    return f"""Solid {{
  translation {translation}
  rotation {rotation}
  children [ Shape {{ geometry DEF G_{name.replace(' ', '_')} {geometry} }} {children} ]
  name "{name}"
  model "{name}"
  boundingObject USE G_{name.replace(' ', '_')}
  {colours}
}}
"""


def _camera(tmp_path: Path, objects: str, fov: float = 1.0, projection: str = "planar",
            occlusion: int = 0) -> tuple[Simulation, Camera]:
    world = tmp_path / "recognition_rules.wbt"
    world.write_text(WORLD.replace("OBJECTS", objects).replace("FOV", str(fov)).replace("PROJECTION", projection)
                     .replace("OCCLUSION", str(occlusion)))
    result, _ = compile_world(world)
    sim = Simulation(result)
    mujoco.mj_kinematics(sim.model, sim.data)
    camera = next(s for r in sim.robots for s in r.sensors.values() if isinstance(s, Camera))
    return sim, camera


def _models(camera: Camera, sim: Simulation) -> list[str]:
    return sorted(obj["model"] for obj in camera.recognize(sim))


def test_a_bar_across_the_view_with_no_corner_in_it_is_seen_but_one_beside_it_is_not(tmp_path):
    # 4 m long, 2 m ahead: its corners are outside the left and right planes (the view is 2·tan(0.5)·2 = 2.2 m
    # wide there) and between the top and bottom ones, Webots' "crossing" case. The second bar lies along the
    # view, wholly left of it: every corner outside the left plane only.
    sim, camera = _camera(tmp_path, _solid("across", "2 0 0", "Box { size 0.1 4 0.1 }")
                          + _solid("beside", "2 3 0", "Box { size 2 0.1 0.1 }"))
    (across,) = camera.recognize(sim)
    assert across["model"] == "across"
    sim.close()


def test_an_edge_on_plate_reaching_into_the_view_is_seen_by_its_inner_corners(tmp_path):
    # A thin plate seen edge-on (its plane holds the view axis' direction): the corners of its far end are in view.
    sim, camera = _camera(tmp_path, _solid("plate", "3 0.9 0", "Box { size 2 0.01 0.5 }"))
    assert _models(camera, sim) == ["plate"]
    sim.model.body_pos[sim.model.body(sim.table.recognizable[0].body).id] = [3, 2.5, 0]  # its far end out too
    mujoco.mj_kinematics(sim.model, sim.data)
    assert _models(camera, sim) == []
    sim.close()


def test_a_corner_outside_a_side_plane_moves_away_from_it_as_in_webots(tmp_path):
    # A 0.2 m cube whose far left corners stick out of the left plane: Webots moves such a point p by
    # n (n·p) (n the plane's inward unit normal), to twice its distance outside, and keeps the box around.
    half = 0.5  # half the field of view
    y = 1.0 * math.tan(half)  # the left plane at 1 m ahead
    sim, camera = _camera(tmp_path, _solid("cube", f"1 {y} 0", "Box { size 0.2 0.2 0.2 }"))
    (cube,) = camera.recognize(sim)
    t = math.tan(np.float32(half))
    normal = np.array([t, -1.0, 0.0]) / math.hypot(t, 1.0)
    kept = []
    for cx in (0.9, 1.1):
        for cy in (y - 0.1, y + 0.1):
            for cz in (-0.1, 0.1):
                p = np.array([cx, cy, cz])
                d = float(normal @ p)
                kept.append(p + normal * d if d < 0 else p)
    kept = np.array(kept)
    low, high = kept.min(axis=0), kept.max(axis=0)
    assert cube["position"] == pytest.approx(list((low + high) / 2), abs=1e-6)
    assert cube["size"] == pytest.approx([high[0] - low[0], high[1] - low[1]], abs=1e-6)  # x and y extents
    assert high[1] > y + 0.1 + 0.01  # the box grew outwards, not inwards
    sim.close()


def test_a_spherical_camera_sees_behind_it_except_straight_behind(tmp_path):
    objects = (_solid("behind side", "-1 0.6 0.3", "Sphere { radius 0.1 }")
               + _solid("straight behind", "-1 0 0", "Sphere { radius 0.1 }")
               + _solid("ahead", "1 0 0", "Sphere { radius 0.1 }"))
    sim, camera = _camera(tmp_path, objects, fov=6.28, projection="spherical")
    found = {obj["model"]: obj for obj in camera.recognize(sim)}
    assert sorted(found) == ["ahead", "behind side"]  # Webots' back wedge is about 0.0016 rad wide
    side = found["behind side"]
    assert side["position"] == pytest.approx([-1, 0.6, 0.3], abs=1e-6)
    assert side["size"] == pytest.approx([0.2, 0.2], abs=1e-6)
    # Equidistant fisheye: the centre's angle from the axis over fovX is its distance from the image centre,
    # towards (-y, -z): up and left.
    angle = math.acos(-1 / math.sqrt(1 + 0.6**2 + 0.3**2))
    radius = angle / 6.28
    expected = (31 * (0.5 - radius * 0.6 / math.hypot(0.6, 0.3)), 23 * (0.5 - radius * 0.3 / math.hypot(0.6, 0.3)))
    assert side["position_on_image"] == pytest.approx(expected, abs=1.5)
    sim.close()


def test_occlusion_2_needs_every_corner_ray_blocked(tmp_path):
    # A wide target 3 m ahead behind a small post: the post blocks the ray to the centre (occlusion 1 hides the
    # target) but not the rays to its corners (occlusion 2 sees it); a wall blocks every ray.
    target = _solid("target", "3 0 0", "Box { size 0.2 1 1 }")
    post = _solid("post", "1.5 0 0", "Box { size 0.1 0.1 0.1 }", colour="")
    wall = _solid("wall", "1.5 0 0", "Box { size 0.1 3 3 }", colour="")
    for occlusion, blocker, seen in ((1, post, []), (2, post, ["target"]), (2, wall, [])):
        sim, camera = _camera(tmp_path, target + blocker, occlusion=occlusion)
        assert _models(camera, sim) == seen, (occlusion, blocker)
        sim.close()


def test_cylindrical_and_spherical_projections_follow_webots():
    spherical = Optics(6.28, 256, 256, "spherical")
    assert project(np.array([1.0, 0.0, 1e-9]), spherical) == (127, 127)  # on the axis: the centre
    # 90° to the left: a quarter turn over 6.28 rad from the centre, to the left.
    assert project(np.array([0.0, 1.0, 1e-12]), spherical) == (int(255 * (0.5 - (math.pi / 2) / 6.28)), 127)
    # Exactly on the horizontal plane Webots divides 0 by 0: u is NaN, which its clamp turns into the right edge.
    assert project(np.array([0.5, 1.0, 0.0]), spherical) == (255, 127)
    cylindrical = Optics(3.0, 256, 256, "cylindrical")
    u, v = project(np.array([math.cos(0.5), math.sin(0.5), 0.0]), cylindrical)
    assert (u, v) == (int(255 * (0.5 - 0.5 / 3.0)), 127)  # azimuth over fovX; the horizon row
    # A view 0.3 rad wide on 256 × 256 is covered by one row of sub-cameras: Webots' 1.27 correction.
    assert Optics(0.3, 256, 256, "cylindrical").correction() == 1.27


def test_segmentation_image_colours_recognizable_shapes_and_leaves_the_rest_black(tmp_path):
    inner = "Solid { translation 0 0 0.3 children [ Shape { geometry Box { size 0.05 0.05 0.05 } } ] }"
    objects = (_solid("red", "1 0 0", "Sphere { radius 0.2 }", colour="1 0 0 0 1 0", children=inner)
               + _solid("plain", "1 -0.4 0", "Box { size 0.1 0.1 0.1 }", colour=""))
    sim, camera = _camera(tmp_path, objects)
    camera.command("enableSegmentation", ())
    segment = camera.segment(sim)
    assert segment["has_segmentation"] is True
    image = np.frombuffer(segment["segmentation"], dtype=np.uint8).reshape(24, 32, 4)
    assert list(image[12, 16]) == [0, 0, 255, 255]  # BGRA: the first recognition colour, red
    assert list(image[0, 0]) == [0, 0, 0, 255]  # the background
    optics = camera.optics()
    u, v = project(np.array([1.0, -0.4, 0.0]), optics)
    assert list(image[v, u]) == [0, 0, 0, 255]  # a shape of a Solid without recognition colours
    u, v = project(np.array([1.0, 0.0, 0.3]), optics)
    assert list(image[v, u]) == [0, 0, 255, 255]  # a nested Solid's shape takes its ancestor's colour
    camera.recognition.segmentation = False  # the field turned off: no image, and the request is dropped
    assert camera.segment(sim) == {"has_segmentation": False}
    assert camera.segmentation_enabled is False
    sim.close()
