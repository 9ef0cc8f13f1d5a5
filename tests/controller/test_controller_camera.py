"""Camera: BGRA bytes from inline data or shared memory, pixel helpers, the getImageArray quirk, recognition."""

from __future__ import annotations

import struct
import zlib
from multiprocessing import shared_memory

import controller_sim
from controller_sim import device, json_lines, make_init

sim = controller_sim.sim  # the fake-simulator fixture (see controller_sim.py)

WIDTH, HEIGHT = 3, 2
# pixel (x, y) has B = 10x + y, G = 100 + 10x + y, R = 200 + 10x + y, A = 255
IMAGE = bytes(
    b for y in range(HEIGHT) for x in range(WIDTH) for b in (10 * x + y, 100 + 10 * x + y, 200 + 10 * x + y, 255)
)

CAMERAS = [
    device(0, "camera", "Camera", {"width": WIDTH, "height": HEIGHT, "fieldOfView": 0.84, "near": 0.0055,
                                   "zoom": {"minFieldOfView": 0.5, "maxFieldOfView": 1.0},
                                   "recognition": {"fields": {"maxRange": 10, "segmentation": False}}}),
    device(1, "plain", "Camera", {}),
]

SCRIPT = """
    import json
    from controller import Robot, Camera
    robot = Robot()
    camera = robot.getDevice("camera")
    camera.enable(32)
    print(json.dumps(camera.getImage()))
    robot.step()
    image = camera.getImage()
    print(json.dumps([image.hex(), len(image), camera.getWidth(), camera.getHeight(), image == camera.image]))
    print(json.dumps([[Camera.imageGetRed(image, 3, x, y), Camera.imageGetGreen(image, 3, x, y),
                       Camera.imageGetBlue(image, 3, x, y), Camera.imageGetGray(image, 3, x, y)]
                      for y in range(2) for x in range(3)]))
    print(json.dumps(camera.getImageArray()))
    print(json.dumps(camera.saveImage("shot.png", 100)))
"""


def _expected_lines() -> list:
    pixels = [[IMAGE[i + 2], IMAGE[i + 1], IMAGE[i]] for i in range(0, len(IMAGE), 4)]
    quirk = [pixels[0:2], pixels[2:4], pixels[4:6]]  # width lists of height pixels, in memory order
    helpers = [[200 + 10 * x + y, 100 + 10 * x + y, 10 * x + y, (300 + 30 * x + 3 * y) / 3]
               for y in range(2) for x in range(3)]
    return [None, [IMAGE.hex(), 24, 3, 2, True], helpers, quirk, 0]


def _png_pixels(path) -> bytes:
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    width, height = struct.unpack(">II", data[16:24])
    idat = data[data.index(b"IDAT") + 4:data.index(b"IEND") - 8]
    raw = zlib.decompress(idat)
    assert (width, height) == (WIDTH, HEIGHT)
    return b"".join(raw[1 + y * (1 + 4 * width):(y + 1) * (1 + 4 * width)] for y in range(height))


def test_camera_image_from_inline_data(sim, tmp_path) -> None:
    fake = sim(SCRIPT, make_init(CAMERAS))
    assert fake.step(values={0: {"shm": None, "data": IMAGE, "width": WIDTH, "height": HEIGHT}}) == (
        32, [(0, "enable", 32)])
    rc, out, err = fake.finish()
    assert (rc, err) == (0, "")
    assert json_lines(out) == _expected_lines()
    rgba = bytes(b for i in range(0, len(IMAGE), 4) for b in (IMAGE[i + 2], IMAGE[i + 1], IMAGE[i], IMAGE[i + 3]))
    assert _png_pixels(tmp_path / "shot.png") == rgba


def test_camera_image_from_shared_memory(sim) -> None:
    block = shared_memory.SharedMemory(create=True, size=4096)
    try:
        block.buf[: len(IMAGE)] = IMAGE
        fake = sim(SCRIPT, make_init(CAMERAS))
        fake.step(values={0: {"shm": block.name, "data": None, "width": WIDTH, "height": HEIGHT}})
        rc, out, err = fake.finish()
    finally:
        block.close()
        block.unlink()
    assert (rc, err) == (0, "")
    assert json_lines(out) == _expected_lines()


def test_disabled_camera_and_optics(sim) -> None:
    fake = sim(
        """
        import json
        from controller import Robot
        robot = Robot()
        camera, plain = robot.getDevice("camera"), robot.getDevice("plain")
        print(json.dumps([camera.getImage(), camera.getImageArray()]))
        print(json.dumps([camera.getFov(), camera.getMinFov(), camera.getMaxFov(), camera.getNear(),
                          plain.getWidth(), plain.getHeight(), plain.getFov(), plain.getMinFov(), plain.getNear()]))
        camera.setFov(1.2)
        camera.setFov(0.7)
        camera.setExposure(-1)
        plain.setFocalDistance(1)
        robot.step()
        print(camera.getFov())
        """,
        make_init(CAMERAS),
    )
    assert fake.step() == (32, [(0, "setFov", 0.7)])
    rc, out, err = fake.finish()
    assert rc == 0
    assert json_lines(out) == [[None, None], [0.84, 0.5, 1.0, 0.0055, 64, 64, 0.785398, 0.785398, 0.01], 0.7]
    disabled = "Error: wb_camera_get_image() called for a disabled device! Please use: wb_camera_enable()."
    assert err.splitlines() == [
        disabled,
        disabled,
        "Error: wb_camera_set_fov() out of zoom range [0.500000, 1.000000].",
        "Error: 'exposure' argument of wb_camera_set_exposure() can't be negative.",
        "Error: wb_camera_set_focal_distance() out of focus range [0.000000, 0.000000].",
    ]


def test_recognition(sim) -> None:
    fake = sim(
        """
        import json
        from controller import Robot
        robot = Robot()
        camera, plain = robot.getDevice("camera"), robot.getDevice("plain")
        print(camera.hasRecognition(), plain.hasRecognition(), camera.getRecognitionNumberOfObjects())
        camera.recognitionEnable(64)
        plain.recognitionEnable(64)
        robot.step()
        objects = camera.getRecognitionObjects()
        print(json.dumps([camera.getRecognitionSamplingPeriod(), camera.getRecognitionNumberOfObjects()]))
        o = objects[0]
        print(json.dumps([o.getId(), o.getPosition(), o.getOrientation(), o.getSize(), o.getPositionOnImage(),
                          o.getSizeOnImage(), o.getNumberOfColors(), o.getColors(), o.getModel()]))
        """,
        make_init(CAMERAS),
    )
    obj = {"id": 7, "position": [1.0, 0.0, 0.1], "orientation": [0, 0, 1, 0.5], "size": [0.1, 0.2],
           "position_on_image": [1, 1], "size_on_image": [2, 1], "colors": [[1, 0, 0]], "model": "ball"}
    assert fake.step(values={0: {"objects": [obj]}}) == (32, [(0, "recognitionEnable", 64)])
    rc, out, err = fake.finish()
    assert rc == 0
    lines = out.splitlines()
    assert lines[0] == "True False 0"
    assert json_lines("\n".join(lines[1:])) == [
        [64, 1], [7, [1.0, 0.0, 0.1], [0, 0, 1, 0.5], [0.1, 0.2], [1, 1], [2, 1], 1, [1, 0, 0], "ball"]]
    assert err.splitlines() == [
        "Error: wb_camera_recognition_get_number_of_objects() called for a disabled device! "
        "Please use: wb_camera_recognition_enable().",
        "Error: wb_camera_recognition_enable() called on a Camera without Recognition node.",
    ]


def test_image_is_black_between_the_first_step_and_the_first_sample(sim) -> None:
    # Webots' api/camera_image_update: NULL before the step that follows the enable, then the image
    # memory exists, filled with zeros, until the camera's first sample.
    fake = sim(
        """
        from controller import Robot
        robot = Robot()
        camera = robot.getDevice("camera")
        camera.enable(64)
        print(camera.getImage() is None)
        robot.step(32)
        print(camera.getImage().hex())
        robot.step(32)
        print(camera.getImage()[:4].hex())
        """,
        make_init(CAMERAS),
    )
    fake.step(time=0.032)
    fake.step(time=0.064, values={0: {"shm": None, "data": IMAGE, "width": WIDTH, "height": HEIGHT}})
    rc, out, _ = fake.finish()
    assert rc == 0
    assert out.splitlines() == ["True", "00" * 4 * WIDTH * HEIGHT, IMAGE[:4].hex()]


def test_segmentation_image_follows_the_enable_and_the_field(sim, tmp_path) -> None:
    cameras = [device(0, "camera", "Camera", {"width": WIDTH, "height": HEIGHT,
                                              "recognition": {"fields": {"segmentation": True}}})]
    fake = sim(
        """
        import json
        from controller import Robot
        robot = Robot()
        camera = robot.getDevice("camera")
        camera.recognitionEnable(32)
        print(json.dumps([camera.hasRecognitionSegmentation(), camera.getRecognitionSegmentationImage()]))
        camera.enableRecognitionSegmentation()
        robot.step()
        image = camera.getRecognitionSegmentationImage()
        print(json.dumps([camera.isRecognitionSegmentationEnabled(), image.hex(),
                          camera.getRecognitionSegmentationImageArray(),
                          camera.saveRecognitionSegmentationImage("segmentation.png", 100)]))
        camera.disableRecognitionSegmentation()
        print(json.dumps(camera.getRecognitionSegmentationImage()))
        robot.step()
        print(json.dumps(camera.hasRecognitionSegmentation()))
        camera.enableRecognitionSegmentation()
        """,
        make_init(cameras),
    )
    assert fake.step(values={0: {"objects": [], "has_segmentation": True, "segmentation": IMAGE}}) == (
        32, [(0, "recognitionEnable", 32), (0, "enableSegmentation")])
    # A supervisor turned the Recognition node's segmentation field off.
    assert fake.step(values={0: {"objects": [], "has_segmentation": False}}) == (32, [(0, "disableSegmentation")])
    rc, out, err = fake.finish()
    assert rc == 0
    quirk = _expected_lines()[3]
    assert json_lines(out) == [[True, None], [True, IMAGE.hex(), quirk, 0], None, False]
    assert err.splitlines() == [
        "Error: wb_camera_recognition_enable_segmentation(): segmentation is disabled in Recognition node."]
    rgba = bytes(b for i in range(0, len(IMAGE), 4) for b in (IMAGE[i + 2], IMAGE[i + 1], IMAGE[i], IMAGE[i + 3]))
    assert _png_pixels(tmp_path / "segmentation.png") == rgba
