"""Emitter and Receiver: send encodings, channels, ranges and the receiver's packet queue."""

from __future__ import annotations

import struct

import controller_sim
from controller_sim import device, json_lines, make_init

sim = controller_sim.sim  # the fake-simulator fixture (see controller_sim.py)

RADIO = [
    device(0, "emitter", "Emitter", {"channel": 1, "range": 5.0, "maxRange": 10.0, "allowedChannels": []}),
    device(1, "receiver", "Receiver", {"channel": 1, "allowedChannels": [1, 2]}),
    device(2, "small", "Emitter", {"bufferSize": 8}),
]


def test_emitter_send_encodings(sim) -> None:
    fake = sim(
        """
        from controller import Robot, Emitter
        robot = Robot()
        emitter = robot.getDevice("emitter")
        emitter.send("hello")
        emitter.send("héllo")
        emitter.send(b"\\x00\\x01\\x02")
        emitter.send(b"abcdef", 2)
        emitter.send([1.5, -2.25])
        emitter.send((3, 4, 5))
        emitter.send([True, False])
        emitter.send(["a", "b"])
        emitter.send([])
        emitter.send(3.0)
        emitter.send("")
        small = robot.getDevice("small")
        small.send(b"12345")
        small.send(b"6789")
        small.send(b"678")
        robot.step()
        """,
        make_init(RADIO),
    )
    _, commands = fake.step()
    assert commands == [
        (0, "send", b"hello"),
        (0, "send", "héllo".encode()),
        (0, "send", b"\x00\x01\x02"),
        (0, "send", b"ab"),
        (0, "send", struct.pack("2d", 1.5, -2.25)),
        (0, "send", struct.pack("3i", 3, 4, 5)),
        (0, "send", struct.pack("2i", 1, 0)),
        (2, "send", b"12345"),
        (2, "send", b"678"),
    ]
    rc, out, err = fake.finish()
    assert (rc, out) == (0, "")
    assert err.splitlines() == [
        "Emitter.send(): unsupported data type list: <class 'list'>",
        "Emitter.send(): empty list",
        "Emitter.send(): unsupported data type: <class 'float'>",
        "Error: wb_emitter_send(): invalid size=0 argument.",
    ]


def test_emitter_channel_and_range(sim) -> None:
    fake = sim(
        """
        import json
        from controller import Robot, Emitter
        robot = Robot()
        emitter = robot.getDevice("emitter")
        broadcast = Emitter.CHANNEL_BROADCAST
        print(json.dumps([emitter.getChannel(), emitter.getRange(), emitter.getBufferSize(), broadcast]))
        emitter.setChannel(-2)
        emitter.setChannel(Emitter.CHANNEL_BROADCAST)
        emitter.setRange(20)
        emitter.setRange(-3)
        emitter.range = 2.5
        print(json.dumps([emitter.getChannel(), emitter.getRange()]))
        robot.step()
        """,
        make_init(RADIO),
    )
    assert fake.step() == (32, [(0, "setChannel", -1), (0, "setRange", 10.0), (0, "setRange", 2.5)])
    rc, out, err = fake.finish()
    assert rc == 0
    assert json_lines(out) == [[1, 5.0, -1, -1], [-1, 2.5]]
    assert err.splitlines() == [
        "Error: wb_emitter_set_channel() called with an invalid channel=-2. Please use a channel inside the range "
        "[-1,inf).",
        "Error: wb_emitter_set_range(): invalid range=-3.000000 argument.",
    ]


def test_receiver_queue(sim) -> None:
    fake = sim(
        """
        import json
        from controller import Robot
        robot = Robot()
        receiver = robot.getDevice("receiver")
        receiver.getQueueLength()
        receiver.enable(32)
        print(receiver.getQueueLength())
        robot.step()
        print(receiver.getQueueLength())
        robot.step()
        print(json.dumps([receiver.getQueueLength(), receiver.getString(), receiver.getDataSize(),
                          receiver.getSignalStrength(), receiver.getEmitterDirection(), receiver.getBytes().hex()]))
        receiver.nextPacket()
        print(json.dumps([receiver.getFloats(), receiver.getBytes().hex(), receiver.queue_length,
                          bytes(receiver.data[0:receiver.data_size]).hex()]))
        receiver.nextPacket()
        print(json.dumps([receiver.getInts(), receiver.getData()]))
        receiver.nextPacket()
        receiver.nextPacket()
        print(json.dumps([receiver.getQueueLength(), receiver.getBytes().hex(), receiver.getDataSize(),
                          receiver.getFloats()]))
        receiver.setChannel(2)
        receiver.setChannel(3)
        receiver.setChannel(2)
        print(receiver.getChannel())
        robot.step()
        """,
        make_init(RADIO),
    )
    assert fake.step() == (32, [(1, "enable", 32)])
    packets = [
        (b"hi", 1, 0.5, [1.0, 0.0, 0.0]),
        (struct.pack("2d", 1.0, 2.0), 1, 0.25, [0.0, 1.0, 0.0]),
        (struct.pack("2i", 7, 8), -1, 0.125, [0.0, 0.0, 1.0]),
    ]
    fake.step(values={1: packets})
    assert fake.step() == (32, [(1, "setChannel", 2)])
    rc, out, err = fake.finish()
    assert rc == 0
    lines = out.splitlines()
    assert lines[:2] == ["0", "0"]
    assert json_lines("\n".join(lines[2:])) == [
        [3, "hi", 2, 0.5, [1.0, 0.0, 0.0], "6869"],
        [[1.0, 2.0], struct.pack("2d", 1.0, 2.0).hex(), 2, struct.pack("2d", 1.0, 2.0).hex()],
        [[7, 8], struct.pack("2i", 7, 8).decode()],
        [0, "", -1, []],
        2,
    ]
    assert err.splitlines() == [
        "Error: wb_receiver_get_queue_length() called for a disabled device! Please use: wb_receiver_enable().",
        "DEPRECATION: Receiver.getData is deprecated, please use Receiver.getString instead.",
        "Error: wb_receiver_get_data(): the receiver queue is empty.",
        "Error: wb_receiver_get_data_size(): the receiver queue is empty.",
        "Error: wb_receiver_get_data_size(): the receiver queue is empty.",
        "Error: wb_receiver_get_data(): the receiver queue is empty.",
        "Error: wb_receiver_get_data_size(): the receiver queue is empty.",
        "Error: wb_receiver_set_channel() called with channel=3, which is not between allowed channels. "
        "Please use an allowed channel.",
    ]


def test_receiver_get_data_follows_the_world_release(sim) -> None:
    # A world written before R2023b runs controllers of that release: getData() returned the packet's
    # bytes, which the controller decodes or unpacks itself. From R2023b on it is getString().
    script = """
        import struct
        from controller import Robot
        robot = Robot()
        receiver = robot.getDevice("receiver")
        receiver.enable(32)
        robot.step()
        data = receiver.getData()
        print(type(data).__name__, repr(data))
        receiver.nextPacket()
        if isinstance(data, bytes):  # packed doubles are no UTF-8 text: only the old API can read them
            print(struct.unpack("2d", receiver.getData()))
        robot.step()
        """
    packets = [(b"hi", 1, 0.5, [1.0, 0.0, 0.0]), (struct.pack("2d", 1.5, -2.0), 1, 0.5, [1.0, 0.0, 0.0])]
    outputs = {}
    for version in ("R2021c", "V8.5", "R2023b", ""):
        fake = sim(script, make_init(RADIO, webots_version=version))
        fake.step(values={1: packets})
        fake.step()
        rc, out, err = fake.finish()
        outputs[version] = (rc, out.splitlines(), "DEPRECATION" in err)
    assert outputs["R2021c"] == (0, ["bytes b'hi'", "(1.5, -2.0)"], False)
    assert outputs["V8.5"] == outputs["R2021c"]
    assert outputs["R2023b"][1][0] == "str 'hi'" and outputs["R2023b"][2]
    assert outputs[""][1][0] == "str 'hi'"  # a world without a known release: the current API
