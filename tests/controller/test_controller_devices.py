"""LED, Pen, Speaker, Display, Connector and friends: their commands and local state."""

from __future__ import annotations

import os

import controller_sim
from controller_sim import device, json_lines, make_init

sim = controller_sim.sim  # the fake-simulator fixture (see controller_sim.py)

DEVICES = [
    device(0, "led", "LED", {"color": [[1, 0, 0], [0, 1, 0]], "gradual": False}),
    device(1, "pen", "Pen"),
    device(2, "speaker", "Speaker"),
    device(3, "display", "Display", {"width": 32, "height": 16}),
    device(4, "connector", "Connector"),
    device(5, "gripper", "VacuumGripper"),
    device(6, "radar", "Radar"),
    device(7, "range", "RangeFinder", {"width": 2, "height": 2, "maxRange": 4.0}),
    device(8, "altimeter", "Altimeter"),
    device(9, "camera", "Camera", {"width": 2, "height": 1}),
]


def test_actuator_commands_and_local_state(sim) -> None:
    fake = sim(
        """
        import json
        from controller import Robot, LED, Speaker
        robot = Robot()
        led, pen, speaker = robot.getDevice("led"), robot.getDevice("pen"), robot.getDevice("speaker")
        display, connector = robot.getDevice("display"), robot.getDevice("connector")
        gripper = robot.getDevice("gripper")
        print(json.dumps([led.get(), led.value, display.getWidth(), display.getHeight(), connector.isLocked(),
                          gripper.isOn(), speaker.getEngine(), speaker.getLanguage()]))
        led.set(True)
        led.value = 2
        pen.write(False)
        pen.setInkColor(0xFF0000, 0.5)
        Speaker.playSound(speaker, speaker, "sounds/beep.wav", 1.0, 1.0, 0.0, False)
        speaker.speak("hello", 0.8)
        display.setColor(0x00FF00)
        display.drawLine(0, 0, 10, 5)
        image = display.imageNew(b"\\x00" * 16, display.BGRA, 2, 2)
        display.imagePaste(image, 1, 1, False)
        display.attachCamera(robot.getDevice("camera"))
        connector.lock()
        gripper.turnOn()
        print(json.dumps([led.get(), connector.isLocked(), gripper.isOn(), image]))
        robot.step()
        """,
        make_init(DEVICES),
    )
    _, commands = fake.step()
    assert commands == [
        (0, "set", 1),
        (0, "set", 2),
        (1, "write", False),
        (1, "setInkColor", 0xFF0000, 0.5),
        (2, "playSound", 2, "sounds/beep.wav", 1.0, 1.0, 0.0, False),
        (2, "speak", "hello", 0.8),
        (3, "setColor", 0x00FF00),
        (3, "drawLine", 0, 0, 10, 5),
        (3, "imageNew", 1, b"\x00" * 16, 6, 2, 2),
        (3, "imagePaste", 1, 1, 1, False),
        (3, "attachCamera", 9),
        (4, "lock"),
        (5, "turnOn"),
    ]
    rc, out, err = fake.finish()
    # The sound file is not there: Webots warns (and the library keeps it playing, see below).
    assert (rc, err) == (0, "WARNING: Sound file 'sounds/beep.wav' not found. The sound file should be defined "
                            "relatively to the controller, the PROTO or absolutely.\n")
    assert json_lines(out) == [[0, 0, 32, 16, False, False, "pico", "en-US"], [2, True, True, 1]]


def test_presence_radar_range_finder_and_altimeter_values(sim) -> None:
    fake = sim(
        """
        import json
        from controller import Robot
        robot = Robot()
        connector, radar = robot.getDevice("connector"), robot.getDevice("radar")
        range_finder, altimeter = robot.getDevice("range"), robot.getDevice("altimeter")
        connector.enablePresence(32)
        radar.enable(32)
        range_finder.enable(32)
        altimeter.enable(32)
        print(connector.getPresence())
        robot.step()
        targets = [[t.distance, t.receiver_power, t.speed, t.azimuth] for t in radar.getTargets()]
        print(json.dumps([connector.getPresence(), radar.getNumberOfTargets(), targets, altimeter.getValue()]))
        print(json.dumps([range_finder.getRangeImage(), range_finder.getRangeImageArray(),
                          range_finder.saveImage("depth.png", 100), range_finder.saveImage("missing/depth.png", 100)]))
        """,
        make_init(DEVICES),
    )
    values = {4: 1, 6: [(2.0, -40.0, 0.5, 0.1)], 7: {"ranges": [1.0, 2.0, 3.0, float("inf")]}, 8: 12.5}
    assert fake.step(values=values)[1] == [(4, "enablePresence", 32), (6, "enable", 32), (7, "enable", 32),
                                           (8, "enable", 32)]
    rc, out, err = fake.finish()
    assert (rc, err) == (0, "")
    assert out.splitlines()[0] == "-1"
    assert json_lines("\n".join(out.splitlines()[1:])) == [
        [1, 1, [[2.0, -40.0, 0.5, 0.1]], 12.5],
        # A folder that does not exist: -1, as Webots' (an OSError stopped the controller).
        [[1.0, 2.0, 3.0, float("inf")], [[1.0, 2.0], [3.0, float("inf")]], 0, -1],
    ]
    assert os.path.getsize(fake.path.parent / "depth.png") > 50


def test_speaker_plays_a_wav_for_its_length_and_speaks_for_an_estimate(sim, tmp_path) -> None:
    # Webots' library marks a sound playing from the call until the simulator says it is over: wbtc
    # counts a WAV file's length at its pitch (0.5 s at pitch 2: 0.25 s), a looped or unreadable sound
    # never ends, and speech lasts an estimate of 0.3 s + 13 characters a second.
    import wave

    with wave.open(str(tmp_path / "beep.wav"), "wb") as clip:
        clip.setnchannels(1)
        clip.setsampwidth(2)
        clip.setframerate(8000)
        clip.writeframes(b"\x00\x00" * 4000)
    fake = sim(
        """
        import json
        from controller import Robot, Speaker
        robot = Robot()
        speaker = robot.getDevice("speaker")
        before = [speaker.isSoundPlaying("beep.wav"), speaker.isSoundPlaying(None), speaker.isSpeaking()]
        Speaker.playSound(speaker, speaker, "beep.wav", 1.0, 2.0, 0.0, False)
        Speaker.playSound(speaker, None, "missing.wav", 1.0, 1.0, 0.0, False)
        speaker.speak("hello world", 1.0)
        print(json.dumps(before + [speaker.isSoundPlaying("beep.wav"), speaker.isSpeaking()]))
        for _ in range(3):
            robot.step(128)
            print(json.dumps([speaker.isSoundPlaying("beep.wav"), speaker.isSoundPlaying("missing.wav"),
                              speaker.isSpeaking()]))
        speaker.stop(None)
        print(json.dumps([speaker.isSoundPlaying(None), speaker.isSpeaking()]))
        """,
        make_init(DEVICES),
    )
    for time in (0.128, 0.256, 1.28):
        fake.step(time=time)
    code, out, err = fake.finish()
    assert code == 0, err
    assert json_lines(out) == [[False, False, False, True, True],
                               [True, True, True],     # 0.128 s: all three still going
                               [False, True, True],    # 0.256 s: the beep (0.25 s) is over
                               [False, True, False],   # 1.28 s: "hello world" (1.15 s) too; missing never ends
                               [False, False]]
    assert "Sound file 'missing.wav' not found" in err
