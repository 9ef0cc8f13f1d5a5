"""``Motion``: plays ``.motion`` files (poses of named motors over time), entirely on the controller side."""

from __future__ import annotations

import re
import weakref

from . import _session

_HEADER = "#WEBOTS_MOTION"
_VERSION = "V1.0"
_TIME = re.compile(r"[0-9:]+")


def _time(token: str) -> int | None:
    """``[[minutes:]seconds:]milliseconds`` in ms, None when malformed."""
    if not _TIME.fullmatch(token) or token.count(":") > 2:
        return None
    parts = token.split(":")
    if any(not p for p in parts):
        return None
    values = [0] * (3 - len(parts)) + [int(p) for p in parts]
    return values[0] * 60000 + values[1] * 1000 + values[2]


def _tokens(line: str) -> list[str]:
    return [t for t in re.split(r"[,\r\n]", line) if t]


def _load(filename: str) -> tuple[list[str], list[int], list[list[float | None]]] | None:
    def fail(message: str) -> None:
        _session.error(f"Error: wbu_motion_new(): {message}")

    try:
        with open(filename) as file:
            lines = file.read().split("\n")
    except OSError:
        fail(f"could not open '{filename}' file.")
        return None
    header = _tokens(lines[0]) if lines and lines[0] else []
    if not header:
        fail(f"file '{filename}' is empty.")
        return None
    if header[0] != _HEADER:
        fail(f"invalid motion file header in file '{filename}'.")
        return None
    if len(header) < 2:
        fail(f"unexpected end of file '{filename}'.")
        return None
    if header[1] != _VERSION:
        fail(f"unsupported version number '{header[1]}' in motion file '{filename}'.")
        return None
    joints, times, poses = header[2:], [], []
    for number, line in enumerate(lines[1:], start=2):
        tokens = _tokens(line)
        if not tokens:
            break
        time = _time(tokens[0])
        if time is None:
            fail(f"expected <time value> but found '{tokens[0]}', in file '{filename}', line {number}.")
            return None
        if times and time <= times[-1]:
            fail(f"illegal (non-increasing) time sequence detected in file '{filename}', line {number}.")
            return None
        if len(tokens) < 2:
            fail(f"pose name expected in file '{filename}', line {number}.")
            return None
        if len(tokens) < 2 + len(joints):
            fail(f"missing data in file '{filename}', line {number}.")
            return None
        if len(tokens) > 2 + len(joints):
            fail(f"unexpected extra data '{tokens[2 + len(joints)]}', in file '{filename}', line {number}.")
            return None
        pose: list[float | None] = []
        for token in tokens[2:]:
            try:
                pose.append(None if token == "*" else float(token))
            except ValueError:
                fail(f"expected <double value>, but found '{token}', in file '{filename}', line {number}.")
                return None
        times.append(time)
        poses.append(pose)
    if not joints or not poses:
        _session.error(f"Error: wbu_motion_new(): file '{filename}' must contain at least one joint and one pose.")
        return None
    return joints, times, poses


class Motion:
    """A motion file; while playing, each ``step()`` sets the target positions of its motors (linear interpolation)."""

    def __init__(self, filename: str) -> None:
        self._valid = False
        if not filename:
            _session.error("Error: wbu_motion_new() called with NULL or empty 'filename' argument.")
            return
        loaded = _load(filename)
        if loaded is None:
            return
        self._joints, self._times, self._poses = loaded
        session = _session.require()
        self._motors: list[_session.DeviceState | None] = []
        for name in self._joints:
            state = session.find(name)
            if state is None:
                _session.error(
                    f"Warning: wbu_motion_new(): ignoring joint '{name}', specified in file '{filename}', "
                    "but not found in this robot."
                )
            self._motors.append(state)
        self._elapsed = 0
        self._playing = self._reverse = self._loop = False
        self._valid = True
        session.motions.insert(0, weakref.ref(self))

    def _ok(self, function: str, null: str = "NULL argument") -> bool:
        if not self._valid:
            _session.error(f"Error: {function}() called with {null}.")
        return self._valid

    def _position(self, joint: int) -> float | None:
        times, elapsed, last = self._times, self._elapsed, len(self._times) - 1
        if elapsed <= times[0]:
            return self._poses[0][joint]
        if elapsed >= times[last]:
            return self._poses[last][joint]
        for a in range(last):
            if times[a] <= elapsed <= times[a + 1]:
                start, end = self._poses[a][joint], self._poses[a + 1][joint]
                if start is None or end is None:
                    return None
                return start + (elapsed - times[a]) * (end - start) / (times[a + 1] - times[a])
        return None

    def _play_step(self, duration: int) -> None:
        """Called by ``Robot.step`` before sending the step: actuate, then advance the time."""
        if not self._playing:
            return
        session = _session.require()
        for joint, state in enumerate(self._motors):
            if state is None:
                continue
            position = self._position(joint)
            if position is None:
                continue
            if state.type in ("RotationalMotor", "LinearMotor"):
                state.target = position
                session.queue(state.tag, "setPosition", position)
            else:
                _session.error(f'Error: unexpeced type for device "{self._joints[joint]}".')
        end = self.getDuration()
        if self._reverse:
            if self._elapsed <= 0:
                self._elapsed, self._playing = (end, True) if self._loop else (0, False)
            else:
                self._elapsed -= duration
        elif self._elapsed >= end:
            self._elapsed, self._playing = (0, True) if self._loop else (end, False)
        else:
            self._elapsed += duration

    def isValid(self) -> bool:
        """Whether the file was loaded."""
        return self._valid

    def play(self) -> None:
        """Start (or resume) playing; from the other end if it was over."""
        if not self._ok("wbu_motion_play", "NULL 'motion' argument"):
            return
        self._playing = True
        if self._reverse and self._elapsed <= 0:
            self._elapsed = self.getDuration()
        elif not self._reverse and self._elapsed >= self.getDuration():
            self._elapsed = 0

    def stop(self) -> None:
        """Pause playing."""
        if self._ok("wbu_motion_stop"):
            self._playing = False

    def setLoop(self, loop: bool) -> None:
        """Loop at the end."""
        if self._ok("wbu_motion_set_loop"):
            self._loop = bool(loop)

    def setReverse(self, reverse: bool) -> None:
        """Play backwards."""
        if self._ok("wbu_motion_set_reverse"):
            self._reverse = bool(reverse)

    def isOver(self) -> bool:
        """Whether a non-looping motion reached its end."""
        if not self._ok("wbu_motion_is_over"):
            return False
        if self._loop:
            return False
        return self._elapsed <= 0 if self._reverse else self._elapsed >= self.getDuration()

    def getDuration(self) -> int:
        """Time of the last pose (ms)."""
        return self._times[-1] if self._ok("wbu_motion_get_duration") else -1

    def getTime(self) -> int:
        """Current position in the motion (ms)."""
        return self._elapsed if self._ok("wbu_motion_get_time") else -1

    def setTime(self, time: int) -> None:
        """Jump to ``time`` ms (clamped to [0, duration])."""
        if self._ok("wbu_motion_set_time"):
            self._elapsed = max(0, min(int(time), self.getDuration()))

    time = property(getTime, setTime, doc="Current position in the motion (ms).")
    duration = property(getDuration, doc="Time of the last pose (ms).")
