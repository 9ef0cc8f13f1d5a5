"""The wire module's framing, and checks that the child package stays pure standard library, Python 3.8 syntax."""

from __future__ import annotations

import ast
import pickle
import socket
import struct
import sys
import threading

import pytest
from controller_sim import CHILD_PATH

from wbtc._child.controller import wire

PACKAGE = CHILD_PATH / "controller"


def test_frames_round_trip_over_a_socket() -> None:
    a, b = socket.socketpair()
    with a, b:
        message = ("step", 32, [(0, "setPosition", float("inf")), (-1, "setCustomData", "é"), (3, "send", b"\x00")])
        wire.send_frame(a, message)
        wire.send_frame(a, {"status": 0, "values": {1: [1.0, 2.0]}, "keys": None})
        assert wire.recv_frame(b) == message
        assert wire.recv_frame(b) == {"status": 0, "values": {1: [1.0, 2.0]}, "keys": None}
        a.close()
        with pytest.raises(wire.WireClosed):
            wire.recv_frame(b)


def test_frame_reader_splits_joined_frames_and_joins_split_ones() -> None:
    a, b = socket.socketpair()
    with a, b:
        reader = wire.FrameReader(b)
        big = {"data": bytes(range(256)) * 1000}  # 256 kB: more than one recv brings
        first, second = wire.encode(("step", 16, [])), wire.encode(big)
        a.sendall(first + second[:3])  # two frames in one chunk, the second cut inside its header
        assert reader.read() == ("step", 16, [])
        sender = threading.Thread(target=lambda: [a.sendall(second[3:10]), a.sendall(second[10:])])
        sender.start()
        assert reader.read() == big
        sender.join()
        a.close()
        with pytest.raises(wire.WireClosed):
            reader.read()


def test_frame_layout_is_a_little_endian_length_and_a_protocol_4_pickle() -> None:
    frame = wire.encode({"a": 1})
    payload = pickle.dumps({"a": 1}, protocol=4)
    assert frame == struct.pack("<I", len(payload)) + payload


def test_frames_naming_globals_are_refused() -> None:
    with pytest.raises(pickle.UnpicklingError, match="builtins only"):
        wire.decode(pickle.dumps(complex(1, 2), protocol=4))


def test_numpy_values_and_builtin_subclasses_travel_as_plain_builtins() -> None:
    import enum

    import numpy as np

    class Channel(enum.IntEnum):
        TWO = 2

    class Name(str, enum.Enum):  # noqa: UP042 (the mixin whose str() is "Name.LEFT", not its value)
        LEFT = "left"

    message = ("step", 32, [(0, "setVelocity", np.float64(1.5)), (-1, "field.set", 4, -1, list(np.arange(3.0))),
                            (2, "setChannel", Channel.TWO), (-1, "setCustomData", Name.LEFT),
                            (3, "send", np.frombuffer(b"ab", dtype=np.uint8)), (4, "pose", np.eye(2))])
    decoded = wire.decode(wire.encode(message)[4:])
    assert decoded == ("step", 32, [(0, "setVelocity", 1.5), (-1, "field.set", 4, -1, [0.0, 1.0, 2.0]),
                                    (2, "setChannel", 2), (-1, "setCustomData", "left"), (3, "send", [97, 98]),
                                    (4, "pose", [[1.0, 0.0], [0.0, 1.0]])])
    assert [type(v) for v in (decoded[2][0][2], decoded[2][2][2], decoded[2][3][2])] == [float, int, str]
    # A plain message is pickled once, as is: the byte 0x93 inside data does not make it "not plain".
    assert wire.encode((b"\x93", "\x93")) == wire.encode((b"\x93", "\x93"))
    assert wire.decode(wire.encode((b"\x93", "\x93"))[4:]) == (b"\x93", "\x93")


def test_a_reused_encoder_writes_the_bytes_of_a_fresh_pickler() -> None:
    shared, items = "ps0", [1.5, 2.5]  # repeated objects: the pickler's memo refers back to them
    messages = [{"status": 0, "time": 0.064, "values": {3: 70.25, 4: shared, 5: shared}},
                ("step", 64, [(5, "setVelocity", 5.0), (6, "setVelocity", -5.0)]),
                {"a": items, "b": [items, items], "c": shared},
                {"image": bytes(range(256)) * 5000},  # larger than the buffer an encoder keeps
                ("call", -1, "getFromDef", ("BOX", -1))]

    def fresh(obj: object) -> bytes:
        payload = pickle.dumps(obj, protocol=4)
        return struct.pack("<I", len(payload)) + payload

    for _ in range(2):
        for message in messages:
            assert wire.encode(message) == fresh(message)
        with pytest.raises(TypeError):  # a refused message leaves nothing behind for the next one
            wire.encode({"x": shared, "y": complex(1, 2)})
    frames: list[bytes] = []
    threads = [threading.Thread(target=lambda: frames.extend(wire.encode(m) for m in messages * 50))
               for _ in range(2)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert sorted(frames) == sorted(fresh(m) for m in messages * 100)


def test_values_that_cannot_be_made_plain_are_refused_by_the_sender() -> None:
    with pytest.raises(TypeError, match="not plain data"):
        wire.encode(("step", 32, [(0, "setVelocity", complex(1, 2))]))


@pytest.mark.parametrize(
    ("url", "expected"),
    [
        ("unix:/tmp/s.sock", ("/tmp/s.sock", None)),
        ("unix:/tmp/s.sock?robot=e-puck", ("/tmp/s.sock", "e-puck")),
        ("unix:/tmp/s.sock?robot=my%20robot", ("/tmp/s.sock", "my robot")),
    ],
)
def test_parse_url(url: str, expected: tuple) -> None:
    assert wire.parse_url(url) == expected


def test_parse_url_rejects_other_schemes() -> None:
    with pytest.raises(ValueError, match="unix:"):
        wire.parse_url("tcp://localhost:1234/robot")


MODULES = sorted(PACKAGE.glob("*.py"))


@pytest.mark.parametrize("path", MODULES, ids=[p.name for p in MODULES])
def test_child_modules_are_python_3_8_syntax_and_standard_library_only(path) -> None:
    source = path.read_text()
    tree = ast.parse(source, feature_version=(3, 8))
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.level == 0:
            names = [node.module or ""]
        else:
            continue
        for name in names:
            top = name.split(".")[0]
            assert top == "__future__" or top in sys.stdlib_module_names, f"{path.name} imports {name}"
    if path.name != "__init__.py":
        assert "from __future__ import annotations" in source, f"{path.name} needs postponed annotations"
