"""``Speaker``: plays sound files and speaks text; what is playing, as Webots' controller library knows it.

Webots' library marks a sound as playing when the controller starts it and clears it when the
simulator reports it over (or when the controller stops it); text-to-speech likewise. wbtc plays no
audio, so "over" comes from simulated time: a WAV file lasts its frames / rate / pitch (read from the
file, found as Webots looks for it: beside the controller, else as given), a looped sound until it is
stopped, and a sound file that cannot be read never ends, as in Webots (its simulator warns and never
reports it over). Spoken text lasts an estimate (see `speech_seconds`): Webots' pico engine renders
the audio, wbtc does not.
"""

from __future__ import annotations

import math
import sys
import wave

from . import _session
from .device import Device, checked

_ENGINES = ("pico", "microsoft")

#: Speech rate of the estimate: characters per second (about 150 words a minute) and a start-up pause.
_CHARS_PER_S, _SPEECH_PAUSE_S = 13.0, 0.3


def speech_seconds(text: str) -> float:
    """How long wbtc counts `text` as being spoken: an estimate at a common text-to-speech rate."""
    return _SPEECH_PAUSE_S + len(text) / _CHARS_PER_S


def sound_seconds(sound: str, pitch: float) -> float:
    """A WAV file's duration at `pitch`; inf (never over) when it cannot be read, with Webots' warning."""
    try:
        with wave.open(sound, "rb") as clip:
            return clip.getnframes() / clip.getframerate() / max(pitch, 1e-9)
    except FileNotFoundError:
        print(f"WARNING: Sound file '{sound}' not found. The sound file should be defined relatively to the "
              "controller, the PROTO or absolutely.", file=sys.stderr)
    except (OSError, EOFError, wave.Error):
        print(f"WARNING: Impossible to play '{sound}'. Make sure the file format is supported (8 or 16 bits, "
              "mono or stereo wave).", file=sys.stderr)
    return math.inf


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
        state.sounds = {}  # sound file -> the simulated time it is over (inf: looped, or unreadable)
        state.speech_over = -math.inf  # the simulated time the text being spoken is over

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
        now = _session.require().time
        end = math.inf if loop else now + sound_seconds(str(sound), float(pitch))
        for speaker in (left, right):
            if speaker is not None and speaker._s is not None:
                speaker._s.sounds[str(sound)] = end

    @checked("stop")
    def stop(self, sound: str | None = None) -> None:
        """Stop one sound, or every sound and the speech when ``sound`` is None."""
        self._queue("stop", sound)
        if sound is None:
            self._s.sounds.clear()
            self._s.speech_over = -math.inf
        else:
            self._s.sounds.pop(str(sound), None)

    @checked("is_sound_playing", False)
    def isSoundPlaying(self, sound: str | None) -> bool:
        """Whether the sound is playing; with None, whether anything is (a sound, or speech)."""
        now = _session.require().time
        if not sound:
            return now < self._s.speech_over or any(now < end for end in self._s.sounds.values())
        return now < self._s.sounds.get(str(sound), -math.inf)

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
        """Whether the speaker is speaking (for the estimated duration of its text)."""
        return _session.require().time < self._s.speech_over

    @checked("speak")
    def speak(self, text: str, volume: float) -> None:
        """Speak ``text`` at ``volume`` in [0, 1]."""
        self._queue("speak", str(text), float(volume))
        self._s.speech_over = _session.require().time + speech_seconds(str(text))
