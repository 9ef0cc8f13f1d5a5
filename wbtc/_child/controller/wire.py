"""The connection between a controller process and the wbtc simulator.

Standard library only: this module is imported by controller processes (any Python >= 3.8) and may be imported
by the simulator side too (``wbtc._child.controller.wire``) so that both ends frame messages the same way.

Transport
    ``WBTC_CONTROLLER_FD`` holds the number of an inherited, connected AF_UNIX SOCK_STREAM socket. Otherwise
    ``WBTC_CONTROLLER_URL`` (extern controllers) is ``unix:/path/to/socket[?robot=NAME]``: the child connects to
    that path and first sends the frame ``("hello", NAME or None)``. With neither set, ``Robot()`` prints a message
    to stderr and exits with code 1.

Frames (both ways)
    A 4-byte little-endian unsigned length, then a pickle (protocol 4) of builtins only (dict, list, tuple, str,
    bytes, float, int, bool, None). The child refuses to unpickle anything that names a global (class, function).

INIT, simulator -> child, first frame on connection
    ``{"robot": {"name", "model", "custom_data", "basic_time_step" (float ms), "project_path", "world_path",
    "supervisor" (bool), "synchronization" (bool), "coordinate_system" ("ENU"/"NUE"/"EUN")}, "time": float s,
    "devices": [{"tag": int, "name": str, "type": Webots base node type name ("RotationalMotor", "DistanceSensor",
    ...), "model": str, "fields": {Webots field name: plain value}, ...}]}``. Lookup tables are lists of
    ``[in, out, noise]`` rows, colours ``[r, g, b]`` lists; an SFNode field (Camera ``focus``/``zoom``/
    ``recognition``) is read as None or a dict of that node's fields (optionally nested under a ``"fields"`` key).
    Motors add ``"position"`` (initial joint position), ``"sensor"`` and ``"brake"`` (tags or None); position
    sensors add ``"motor"`` and ``"brake"``, brakes ``"motor"`` and ``"sensor"`` (tags or None). Tags are
    the ``getDeviceByIndex`` indices. The keyboard is no device.

Step, child -> simulator
    ``("step", duration_ms: int, commands: list)``: the calls buffered since the previous step, in call order, as
    tuples ``(tag, op, *args)``; robot-level ones use tag -1. Values are already validated the way Webots' C
    library does (the simulator applies maxVelocity clamping and prints that warning itself). Ops:

    * sensors: ``("enable", period_ms)``, ``("disable",)``;
    * motors: ``setPosition``, ``setVelocity``, ``setAcceleration``, ``setAvailableForce``, ``setAvailableTorque``,
      ``setControlPID`` (p, i, d), ``setForce``, ``setTorque``, ``enableForceFeedback``/``enableTorqueFeedback``
      (period), ``disableForceFeedback``/``disableTorqueFeedback``;
    * LED ``("set", int)``; Pen ``("write", bool)``, ``("setInkColor", rgb_int, density)``;
    * Emitter ``("send", bytes)``, ``("setChannel", c)``, ``("setRange", r)``; Receiver ``("setChannel", c)``;
    * Camera ``("setFov", f)``, ``("setExposure", e)``, ``("setFocalDistance", d)``, ``("recognitionEnable", p)``,
      ``("recognitionDisable",)``, ``("enableSegmentation",)``, ``("disableSegmentation",)``; Lidar
      ``("enablePointCloud",)``, ``("disablePointCloud",)``, ``("setFrequency", f)``;
    * Speaker, Display, Brake, Connector, VacuumGripper, Skin: the method name with its arguments, e.g.
      ``(left, "playSound", right_tag, sound, volume, pitch, balance, loop)``, ``("drawLine", x1, y1, x2, y2)``.
      Display image handles are ints allocated by the child and passed first (``("imageNew", handle, data,
      format, width, height)``, ``("imageCopy", handle, x, y, w, h)``, ``("imageLoad", handle, abs_path)``);
    * robot: ``(-1, "setCustomData", s)``, ``(-1, "keyboardEnable", p)``, ``(-1, "keyboardDisable")``,
      ``(-1, "batterySensorEnable", p)``, ``(-1, "batterySensorDisable")``.

Step reply, simulator -> child
    ``{"status": 0 or -1, "time": float s, "values": {tag: value}, "keys": [int] (optional), "battery": float
    (optional)}``. ``values`` holds only the sensors sampled during that step. Value shapes: DistanceSensor,
    PositionSensor, LightSensor, Altimeter, TouchSensor (bumper/force), motor feedback -> float; TouchSensor
    force-3d, Accelerometer, Gyro, Compass -> [3 floats]; GPS -> [x, y, z, vx, vy, vz]; InertialUnit -> [x, y, z, w];
    Receiver -> list of (data: bytes, channel: int, signal_strength: float, direction: [3 floats]) appended to its
    queue; Camera -> {"shm": shared-memory block name or None, "data": BGRA bytes or None, "width", "height",
    "objects": [recognition dicts], "has_segmentation": bool, "segmentation": BGRA bytes (optional)}; Lidar ->
    {"ranges": [floats], "points": [(x, y, z, layer, time)] (optional)}; RangeFinder -> {"ranges": [floats]} or a
    camera-like dict of float32 bytes; Radar -> list of
    (distance, received_power, speed, azimuth); Connector/VacuumGripper presence -> int. ``keys`` lists the keys
    down at that keyboard sample. After status -1, ``step()`` returns -1 for good and the process has one second
    to exit; a closed socket also makes ``step()`` return -1.

Calls (synchronous queries, e.g. for the Supervisor API)
    ``("call", tag, op, args_tuple)`` answered by ``{"result": value}`` or ``{"error": message}`` (the child prints
    the message to stderr verbatim). A call frame carries no buffered commands; those only travel with ``step``.
    Calls are refused child-side between ``stepBegin`` and ``stepEnd``, as in Webots. ``(-1, "saveImage", abs_path,
    quality, width, height, rgba_bytes)`` (any robot) has the simulator write a JPEG (``saveImage`` of Camera and
    RangeFinder), answered 0 or -1. Used so far by
    ``Skin.getBoneOrientation``/``getBonePosition`` (ops of those names, args ``(index, absolute)``).

Supervisor (robots whose ``supervisor`` field is TRUE; every op uses tag -1)
    A *node ref* is the dict ``{"id": int (Webots unique id, root 0), "def": str, "type": str (getTypeName: the
    PROTO name for PROTO instances), "base_type": str (getBaseTypeName), "proto": bool, "parent": int (-1 for
    the root)}``. A *field ref* is ``{"id": int (allocated by the simulator, stable for the run), "name": str,
    "type": int (Webots WB_SF_*/WB_MF_* code), "count": int (-1 for SF fields)}``. Field values: SFBool bool,
    SFInt32 int, SFFloat float, SFVec2f/SFVec3f/SFColor/SFRotation lists of 2/3/3/4 floats, SFString str,
    SFNode node ref or None; MF items likewise, one at a time.

    Calls (answered at once, the world as of the last step):
    ``("getRoot",)``, ``("getSelf",)`` -> node ref; ``("getFromDef", name, proto_node_id or -1)`` (dotted
    ``"A.B"`` paths resolved by the simulator), ``("getFromId", id)``, ``("getFromDevice", tag)`` -> node ref or
    None; ``("node.getField", id, name, base: bool)``, ``("node.getFieldByIndex", id, index, base)`` -> field
    ref or None; ``("node.getNumberOfFields", id, base)`` -> int (``base`` False: ``getField``, which for a
    PROTO instance means its interface fields; True: ``getBaseNodeField``/``getProtoField``, the fields of the
    built-in node the PROTO expands to); ``("node.getPosition", id)`` -> [3];
    ``("node.getOrientation", id)`` -> [9] row-major; ``("node.getPose", id, from_id or -1)`` -> [16] row-major;
    ``("node.getCenterOfMass", id)`` -> [3]; ``("node.getVelocity", id)`` -> [6]; ``("node.getContactPoints",
    id, include_descendants)`` -> list of ``([x, y, z], node_id)``; ``("node.getStaticBalance", id)`` -> bool;
    ``("node.exportString", id)`` -> str; ``("field.get", field_id, index)`` (index -1 for SF) -> value;
    ``("field.getCount", field_id)`` -> int; ``("simulationGetMode",)`` -> int.

    Commands (buffered with the step, applied in order before it runs, as Webots applies them):
    ``("simulationQuit", status)``, ``("simulationReset",)``, ``("simulationResetPhysics",)``,
    ``("simulationSetMode", mode)``, ``("worldReload",)``, ``("worldSave", filename or None)``,
    ``("worldLoad", abs_path)``,
    ``("exportImage", abs_path, quality)``, ``("movieStartRecording", abs_path, width, height, codec, quality,
    acceleration, caption)``, ``("movieStopRecording",)``, ``("animationStartRecording", abs_path)``,
    ``("animationStopRecording",)``, ``("setLabel", id, text, x, y, size, color_rgb_int, transparency, font)``;
    ``("node.resetPhysics", id)``, ``("node.restartController", id)``, ``("node.remove", id)``,
    ``("node.saveState", id, name)``, ``("node.loadState", id, name)``, ``("node.setJointPosition", id, position,
    index)``,
    ``("node.setVelocity", id, [6])``, ``("node.addForce", id, [3], relative)``, ``("node.addForceWithOffset",
    id, [3], [3], relative)``, ``("node.addTorque", id, [3], relative)``; ``("field.set", field_id, index,
    value)``, ``("field.insert", field_id, index, value)``, ``("field.remove", field_id, index)``,
    ``("field.importMFNode", field_id, position, vrml_text)``, ``("field.importSFNode", field_id, vrml_text)``,
    ``("field.removeSF", field_id)``. After ``simulationQuit`` the next step replies status -1.
    Until the next step, the child answers a ``get`` of a field it has just set with the value it set.

    Flush (a call; the one exception to "calls carry no commands"): ``("flush", commands)``, ``commands`` being
    a step frame's list, asks the simulator to apply them now, in order, with no time passing, and to answer
    None. Webots performs node removal, MF inserts/removals and node imports at once, so the child queues those
    (``node.remove``, ``field.insert``, ``field.remove``, ``field.importMFNode``, ``field.importSFNode``,
    ``field.removeSF``) and then flushes every buffered command; later calls then see their effect (e.g.
    ``getFromDef`` of a DEF just imported, the new ``field.getCount``), and sets already applied are asked anew.
    An error answer leaves the commands buffered: they go with the next step.

Notes for the simulator side
    * Webots' C library keeps only the last value of each kind of command per step; here every call is sent, in
      order, so applying them in order gives the same final state.
    * A camera's shared-memory block stays mapped by name: give a resized or re-created block a new name.
    * Start the child with ``python -u`` (or ``PYTHONUNBUFFERED=1``) so that its prints are not block-buffered.
"""

from __future__ import annotations

import io
import os
import struct

# The C modules behind `pickle` and `socket`: the same Unpickler and socket objects, without importing
# `re` (pickle) and `enum`/`functools` (socket), which cost a controller's start-up about 8 ms.
try:
    import _pickle as pickle
except ImportError:  # a Python without the C accelerator
    import pickle  # type: ignore[no-redef]
import _socket as socket

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any

PROTOCOL = 4
_HEADER = struct.Struct("<I")


class WireClosed(EOFError):
    """The other end closed the connection."""


class _BuiltinsOnly(pickle.Unpickler):
    def find_class(self, module: str, name: str) -> Any:
        raise pickle.UnpicklingError(f"wbtc wire: refusing to load {module}.{name}; frames hold builtins only")


class _NotPlain(Exception):
    """Raised while pickling an object that is not an exact builtin."""


class _PlainPickler(pickle.Pickler):
    """A pickler that stops at the first object that is not an exact builtin.

    The C pickler calls `reducer_override` for every object except None, booleans and exact ints, floats,
    bytes, strings, dicts, sets, lists and tuples: plain data pickles at full speed, anything else (a numpy
    number, an IntEnum member, a class) stops it, and `encode` makes the message plain first.
    """

    def reducer_override(self, obj: Any) -> Any:
        raise _NotPlain


def encode(obj: Any) -> bytes:
    """Return one frame (length header and pickle) for a message of builtins.

    Values that came from a controller's own code may be numpy numbers or arrays, or subclasses of
    builtins: they are made plain first, as Webots' C library reads any number-like argument.

    Raises:
        TypeError: something in the message is not plain data and cannot be made so.
    """
    # A pickler and its buffer are reused (one per thread at a time: list.pop and append are atomic):
    # making them costs more than pickling a step's few values. Its memo is cleared first, so every
    # frame is the bytes a fresh pickler writes.
    encoder = _ENCODERS.pop() if _ENCODERS else _Encoder()
    try:
        return encoder.frame(obj)
    except (_NotPlain, pickle.PicklingError, AttributeError, TypeError):
        try:
            payload = pickle.dumps(plain(obj), protocol=PROTOCOL)  # builtins only now: nothing to refuse
        except (pickle.PicklingError, AttributeError, TypeError) as exc:
            raise TypeError(f"wbtc: a value passed to the controller API is not plain data (numbers, strings, "
                            f"bytes, lists, tuples, dicts, None): {exc}") from None
        return _HEADER.pack(len(payload)) + payload
    finally:
        _ENCODERS.append(encoder)


class _Encoder:
    """A `_PlainPickler` writing after a length header into its own buffer."""

    _BIG = 1 << 20  # a buffer that grew past this (camera images) is not kept

    def __init__(self) -> None:
        self._renew()

    def _renew(self) -> None:
        self.buffer = io.BytesIO()
        self.pickler = _PlainPickler(self.buffer, protocol=PROTOCOL)

    def frame(self, obj: Any) -> bytes:
        """The frame of `obj`; raises what the pickler raises (`_NotPlain` and others)."""
        buffer = self.buffer
        buffer.seek(0)
        buffer.truncate()
        buffer.write(_NO_SIZE)
        self.pickler.clear_memo()
        self.pickler.dump(obj)
        end = buffer.tell()
        buffer.seek(0)
        buffer.write(_HEADER.pack(end - _HEADER.size))
        frame = buffer.getvalue()
        if end > self._BIG:
            self._renew()  # let a large buffer go
        return frame


_ENCODERS: list[_Encoder] = []
_NO_SIZE = bytes(_HEADER.size)


def plain(obj: Any) -> Any:
    """`obj` with numpy numbers and arrays as Python numbers and lists, builtin subclasses as builtins.

    Raises:
        TypeError: something in `obj` is none of those.
    """
    kind = type(obj)
    if kind in (str, bytes, bool, int, float, type(None)):
        return obj
    if isinstance(obj, dict):
        return {plain(key): plain(value) for key, value in obj.items()}
    if isinstance(obj, (list, tuple)):
        items = [plain(value) for value in obj]
        return items if isinstance(obj, list) else tuple(items)
    tolist = getattr(obj, "tolist", None)
    if callable(tolist) and kind.__module__.split(".")[0] == "numpy":
        return plain(tolist())
    for base in (bool, int, float, str, bytes):  # IntEnum members, float subclasses, ...
        if isinstance(obj, base):
            return base.__str__(obj) if base is str else base(obj)
    if isinstance(obj, (bytearray, memoryview)):
        return bytes(obj)
    raise TypeError(f"a {kind.__name__}")


def decode(payload: bytes) -> Any:
    """Unpickle a frame's payload, refusing anything but builtins."""
    return _BuiltinsOnly(io.BytesIO(payload)).load()


def _recv_exactly(sock: socket.socket, size: int) -> bytes:
    buffer = bytearray(size)
    view = memoryview(buffer)
    got = 0
    while got < size:
        n = sock.recv_into(view[got:], size - got)
        if n == 0:
            raise WireClosed("the connection was closed")
        got += n
    return bytes(buffer)


def send_frame(sock: socket.socket, obj: Any) -> None:
    """Send one message as a frame."""
    sock.sendall(encode(obj))


def recv_frame(sock: socket.socket) -> Any:
    """Receive one message; raises WireClosed when the peer has closed the connection."""
    (size,) = _HEADER.unpack(_recv_exactly(sock, _HEADER.size))
    return decode(_recv_exactly(sock, size))


class FrameReader:
    """Receives frames from one socket, a whole frame in one ``recv`` when it has all arrived.

    Lockstep frames are small and arrive whole, so one system call usually brings header and payload
    (``recv_frame`` makes two, and copies); bytes past the frame are kept for the next one.
    """

    _CHUNK = 1 << 16

    def __init__(self, sock: socket.socket) -> None:
        self.sock = sock
        self._pending = b""

    def read(self) -> Any:
        """The next message; raises WireClosed when the peer has closed the connection."""
        data = self._pending or self._more()
        while len(data) < _HEADER.size:
            data += self._more()
        end = _HEADER.size + _HEADER.unpack_from(data)[0]
        if len(data) < end:
            parts, have = [data], len(data)
            while have < end:
                chunk = self._more(end - have)
                parts.append(chunk)
                have += len(chunk)
            data = b"".join(parts)
        self._pending = data[end:]
        return decode(data[_HEADER.size:end])

    def _more(self, wanted: int = 0) -> bytes:
        chunk = self.sock.recv(max(wanted, self._CHUNK))
        if not chunk:
            raise WireClosed("the connection was closed")
        return chunk


def parse_url(url: str) -> tuple[str, str | None]:
    """Split ``unix:/path/to/socket[?robot=NAME]`` into the socket path and the robot name (or None)."""
    from urllib.parse import parse_qs, unquote  # only extern controllers need it

    if not url.startswith("unix:"):
        raise ValueError(f"unsupported controller URL {url!r}: expected unix:/path/to/socket[?robot=NAME]")
    rest = url[len("unix:"):]
    path, _, query = rest.partition("?")
    robots = parse_qs(query).get("robot") if query else None
    return unquote(path), (robots[0] if robots else None)


class Wire:
    """A framed, blocking connection to the simulator."""

    def __init__(self, sock: socket.socket) -> None:
        self.sock = sock
        self.reader = FrameReader(sock)

    @classmethod
    def from_environment(cls, environ: dict[str, str] | None = None) -> Wire | None:
        """Connect as the environment says (FD first, then URL); None when neither variable is set.

        Raises:
            OSError: the inherited socket or the URL's socket cannot be used.
            ValueError: a variable holds something malformed.
        """
        env = os.environ if environ is None else environ
        fd = env.get("WBTC_CONTROLLER_FD")
        if fd:
            sock = socket.socket(fileno=int(fd))
            os.set_inheritable(sock.fileno(), False)
            return cls(sock)
        url = env.get("WBTC_CONTROLLER_URL")
        if url:
            path, robot = parse_url(url)
            sock = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
            sock.connect(path)
            wire = cls(sock)
            wire.send(("hello", robot))
            return wire
        return None

    def send(self, obj: Any) -> None:
        """Send one message."""
        self.sock.sendall(encode(obj))  # send_frame's one line: a call less on every step

    def recv(self) -> Any:
        """Receive one message (raises WireClosed at end of stream)."""
        return self.reader.read()

    def close(self) -> None:
        """Close the socket."""
        try:
            self.sock.close()
        except OSError:
            pass
