"""Keyboard: getKey() hands out the keys of the last sample one per call, then -1."""

from __future__ import annotations

import controller_sim
from controller_sim import make_init

sim = controller_sim.sim  # the fake-simulator fixture (see controller_sim.py)


def test_get_key_sequence(sim) -> None:
    fake = sim(
        """
        from controller import Robot, Keyboard
        robot = Robot()
        keyboard = robot.getKeyboard()
        print(keyboard.getSamplingPeriod(), keyboard is robot.keyboard)
        keyboard.getKey()
        keyboard.enable(32)
        print(keyboard.getKey())
        for _ in range(3):
            robot.step()
            keys = []
            while True:
                key = keyboard.getKey()
                if key == -1:
                    break
                keys.append(key)
            print(keys, keyboard.getKey())
        print(Keyboard.SHIFT, Keyboard.CONTROL, Keyboard.ALT, Keyboard.KEY, Keyboard.UP, Keyboard.NUMPAD_END)
        """,
        make_init(),
    )
    assert fake.step(keys=[ord("A"), 316 | 0x10000]) == (32, [(-1, "keyboardEnable", 32)])
    fake.step()
    fake.step(keys=list(range(ord("A"), ord("A") + 9)))
    rc, out, err = fake.finish()
    assert rc == 0
    assert out.splitlines() == [
        "0 True",
        "-1",
        "[65, 65852] -1",
        "[] -1",
        "[65, 66, 67, 68, 69, 70, 71] -1",
        "65536 131072 262144 65535 315 382",
    ]
    assert err == "Error: wb_keyboard_get_key() called for a disabled device! Please use: wb_keyboard_enable().\n"


def test_keyboard_built_directly_is_enabled_and_get_key_spells_keys(sim) -> None:
    fake = sim(
        """
        from controller import Robot, Keyboard
        robot = Robot()
        keyboard = Keyboard()
        print(keyboard.getSamplingPeriod(), robot.getKeyboard().getSamplingPeriod())
        robot.step()
        print(repr(keyboard.get_key()), repr(keyboard.get_key()), repr(robot.keyboard.get_key()))
        keyboard.disable()
        robot.step()
        """,
        make_init(basic_time_step=16.0),
    )
    assert fake.step(keys=[317 | 0x10000, ord("W") | 0x20000 | 0x40000, 366]) == (16, [(-1, "keyboardEnable", 16)])
    assert fake.step() == (16, [(-1, "keyboardDisable")])
    rc, out, err = fake.finish()
    assert (rc, err) == (0, "")
    assert out.splitlines() == ["16 16", "'shift-down' 'control-atl-W' 'page up'"]
