"""``Speaker``: plays sound files and speaks text (the simulator decides what is audible)."""

from __future__ import annotations

from . import _session
from .device import Device, checked

_ENGINES = ("pico", "microsoft")


class Speaker(Device):
    """A Speaker node; commands reach the simulator at the next step, under the method's name."""

    _C = "wb_speaker"
    _TYPES = ("Speaker",)

    def __init__(self, name: str | int) -> None:
        super().__init__(name)

    @staticmethod
    def _setup(state: _session.DeviceState, session: _session.Session) -> None:
        state.engine = "pico"
        state.language = "en-US"

    @staticmethod
    def playSound(
        left: Speaker, right: Speaker | None, sound: str, volume: float, pitch: float, balance: float, loop: bool
    ) -> None:
        """Play a sound file on a left and a right speaker (they may be the same, or right None)."""
        if left is None or left._s is None:
            _session.error("Error: wb_speaker_play_sound(): invalid device tag.")
            return
        right_tag = None if right is None or right._s is None else right._tag
        left._queue("playSound", right_tag, str(sound), float(volume), float(pitch), float(balance), bool(loop))

    @checked("stop")
    def stop(self, sound: str | None = None) -> None:
        """Stop one sound, or every sound when ``sound`` is None."""
        self._queue("stop", sound)

    @checked("is_sound_playing", False)
    def isSoundPlaying(self, sound: str) -> bool:
        """Whether the sound is playing (wbtc does not know: False)."""
        return False

    @checked("set_engine", False)
    def setEngine(self, engine: str) -> bool:
        """Choose the text-to-speech engine ("pico" or "microsoft")."""
        if engine not in _ENGINES:
            return False
        self._s.engine = engine
        self._queue("setEngine", engine)
        return True

    @checked("set_language", False)
    def setLanguage(self, language: str) -> bool:
        """Choose the text-to-speech language, e.g. "en-US"."""
        self._s.language = str(language)
        self._queue("setLanguage", str(language))
        return True

    @checked("get_language", "")
    def getLanguage(self) -> str:
        """The text-to-speech language."""
        return self._s.language

    @checked("get_engine", "")
    def getEngine(self) -> str:
        """The text-to-speech engine."""
        return self._s.engine

    @checked("is_speaking", False)
    def isSpeaking(self) -> bool:
        """Whether the speaker is speaking (wbtc does not know: False)."""
        return False

    @checked("speak")
    def speak(self, text: str, volume: float) -> None:
        """Speak ``text`` at ``volume`` in [0, 1]."""
        self._queue("speak", str(text), float(volume))
