"""``Keyboard``: the keys pressed in the simulator window (a robot-wide input, not a device)."""

from __future__ import annotations

from . import _session, constants


class Keyboard:
    """The keyboard; ``getKey()`` returns the keys down at the last sample one per call, then -1.

    ``Robot`` creates one disabled instance (``robot.keyboard``); ``Keyboard()`` built directly after ``Robot()``
    enables sampling every ``int(basicTimeStep)`` ms (or the given period). All instances share one state.
    """

    END = constants.KEYBOARD_END
    HOME = constants.KEYBOARD_HOME
    LEFT = constants.KEYBOARD_LEFT
    UP = constants.KEYBOARD_UP
    RIGHT = constants.KEYBOARD_RIGHT
    DOWN = constants.KEYBOARD_DOWN
    PAGEUP = constants.KEYBOARD_PAGEUP
    PAGEDOWN = constants.KEYBOARD_PAGEDOWN
    NUMPAD_HOME = constants.KEYBOARD_NUMPAD_HOME
    NUMPAD_LEFT = constants.KEYBOARD_NUMPAD_LEFT
    NUMPAD_UP = constants.KEYBOARD_NUMPAD_UP
    NUMPAD_RIGHT = constants.KEYBOARD_NUMPAD_RIGHT
    NUMPAD_DOWN = constants.KEYBOARD_NUMPAD_DOWN
    NUMPAD_END = constants.KEYBOARD_NUMPAD_END
    KEY = constants.KEYBOARD_KEY
    SHIFT = constants.KEYBOARD_SHIFT
    CONTROL = constants.KEYBOARD_CONTROL
    ALT = constants.KEYBOARD_ALT

    def __init__(self, sampling_period: int | None = None) -> None:
        session = _session.require()
        if sampling_period != 0:
            self.enable(int(session.basic_time_step) if sampling_period is None else sampling_period)

    def enable(self, samplingPeriod: int) -> None:
        """Sample the keyboard every ``samplingPeriod`` ms (0 disables)."""
        session = _session.require()
        period = int(samplingPeriod)
        session.keys = []
        session.key_pointer = -1
        session.keyboard_period = period
        if period:
            session.queue(_session.ROBOT_TAG, "keyboardEnable", period)
        else:
            session.queue(_session.ROBOT_TAG, "keyboardDisable")

    def disable(self) -> None:
        """Stop sampling the keyboard."""
        self.enable(0)

    def getSamplingPeriod(self) -> int:
        """The sampling period in ms (0: disabled)."""
        return _session.require().keyboard_period

    def getKey(self) -> int:
        """The next key of the last sample (code | SHIFT/CONTROL/ALT modifiers), or -1 when none is left."""
        session = _session.require()
        if session.keyboard_period <= 0:
            _session.error(
                "Error: wb_keyboard_get_key() called for a disabled device! Please use: wb_keyboard_enable()."
            )
        if session.key_pointer == -1 or session.key_pointer >= len(session.keys):
            return -1
        key = session.keys[session.key_pointer]
        session.key_pointer += 1
        return key

    def getKeyCode(self) -> int:
        """Same as ``getKey()``."""
        return self.getKey()

    def get_key(self) -> str:
        """The next key as text, such as ``'shift-a'`` or ``'left'`` (Webots spells the Alt prefix ``'atl-'``)."""
        key = self.getKey()
        text = ""
        if key & Keyboard.SHIFT:
            text += "shift-"
        if key & Keyboard.CONTROL:
            text += "control-"
        if key & Keyboard.ALT:
            text += "atl-"
        key &= Keyboard.KEY
        names = {
            Keyboard.END: "end", Keyboard.HOME: "home", Keyboard.LEFT: "left", Keyboard.RIGHT: "right",
            Keyboard.UP: "up", Keyboard.DOWN: "down", Keyboard.PAGEUP: "page up", Keyboard.PAGEDOWN: "page down",
            Keyboard.NUMPAD_END: "numpad end", Keyboard.NUMPAD_HOME: "numpad home",
            Keyboard.NUMPAD_LEFT: "numpad left", Keyboard.NUMPAD_RIGHT: "numpad right",
            Keyboard.NUMPAD_UP: "numpad up", Keyboard.NUMPAD_DOWN: "numpad down",
        }
        return text + names.get(key, chr(key))

    @property
    def sampling_period(self) -> int:
        """The sampling period; setting it enables the keyboard (None disables)."""
        return self.getSamplingPeriod()

    @sampling_period.setter
    def sampling_period(self, p: int | None) -> None:
        self.enable(0 if p is None else p)
