"""Ctrl-C and SIGTERM during `wbtc run`: end the run at the next step, as if its duration were reached.

Webots has no terminal to interrupt; its closest equivalent is quitting the simulation, after which
every controller's `step()` returns -1 and gets a moment to clean up. A first SIGINT or SIGTERM while
the world is stepping does just that: the step in progress is finished, controllers get -1 and one
second to exit, a video or page being recorded is written up to that moment, the trace file ends
with a complete row, and the summary is printed with the reason. `wbtc run` then exits with the
usual shell code (130 for SIGINT, 143 for SIGTERM).

A second signal, or a first one while nothing is stepping (waiting for an `<extern>` controller to
connect, compiling), stops at once through KeyboardInterrupt: nothing half-written is kept.

Controllers `wbtc run` starts ignore SIGINT (the controller library's `start`): they stay in wbtc's
process group, so that a batch's time-out still kills them, and the terminal's Ctrl-C ends each one
through `step()` returning -1 rather than with a KeyboardInterrupt traceback of its own.
"""

from __future__ import annotations

import signal
import sys
import threading
from types import FrameType, TracebackType

#: The reasons printed in the summary, by signal.
_NAMES = {signal.SIGINT: "Ctrl-C", signal.SIGTERM: "SIGTERM"}


class Stopped(KeyboardInterrupt):
    """The run stopped at once on a signal (`signal`: its number, for the exit code 128 + it)."""

    def __init__(self, number: int) -> None:
        super().__init__(number)
        self.signal = number


class StopSignals:
    """While entered (main thread only), SIGINT and SIGTERM ask the run to stop instead of killing it.

    Attributes:
        received: the first signal received while armed, or None.
        armed: whether a signal stops the run softly (set while the world steps).
    """

    def __init__(self) -> None:
        self.received: int | None = None
        self.armed = False
        self._previous: dict[int, object] = {}

    def __enter__(self) -> StopSignals:
        if threading.current_thread() is threading.main_thread():  # signal.signal works there only
            for number in _NAMES:
                self._previous[number] = signal.signal(number, self._handle)
        return self

    def __exit__(self, kind: type[BaseException] | None, exc: BaseException | None,
                 tb: TracebackType | None) -> None:
        for number, handler in self._previous.items():
            signal.signal(number, handler)  # type: ignore[arg-type]
        self._previous.clear()

    def _handle(self, number: int, frame: FrameType | None) -> None:
        if not self.armed or self.received is not None:
            raise Stopped(number)
        self.received = number
        print(f"\nwbtc: {_NAMES[number]}: the run ends after this step (again to stop at once)",
              file=sys.stderr, flush=True)

    def reason(self) -> str:
        """The summary's end reason for the received signal."""
        return f"interrupted ({_NAMES.get(self.received or 0, 'signal')})"

    def exit_code(self) -> int:
        """The shell's code for the received signal: 128 + its number (call it once one was received)."""
        return 128 + int(self.received or 0)
