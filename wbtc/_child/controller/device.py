"""``Device``: the base of every device class, a view on the device's state in the session."""

from __future__ import annotations

import functools
from collections.abc import Callable

from . import _session
from .constants import node_type

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any, TypeVar

    F = TypeVar("F", bound="Callable[..., Any]")


def checked(suffix: str, default: Any = None) -> Callable[[F], F]:
    """Make a method print Webots' ``invalid device tag`` error and return ``default`` on an unusable device.

    Args:
        suffix: the C function name after the class prefix, e.g. ``"get_value"`` for ``wb_distance_sensor_get_value``.
        default: what the method returns then (Webots returns NaN, 0 or NULL).
    """

    def wrap(method: F) -> F:
        @functools.wraps(method)
        def guarded(self: Device, *args: Any, **kwargs: Any) -> Any:
            if self._s is None:
                _session.error(f"Error: {self._C}_{suffix}(): invalid device tag.")
                return default
            return method(self, *args, **kwargs)

        return guarded  # type: ignore[return-value]

    return wrap


class Device:
    """A robot device, found by name (``Device('name')``) or by tag (as ``Robot`` creates them)."""

    _C = "wb_device"
    #: Node type names this class accepts; a tag of another type is unusable, as in Webots.
    _TYPES: tuple[str, ...] = ()

    def __init__(self, name: str | int) -> None:
        session = _session.require()
        state: _session.DeviceState | None
        if isinstance(name, int) and not isinstance(name, bool):
            state = session.by_tag.get(name)
        elif not name:
            _session.error("Error: wb_robot_get_device() called with NULL or empty argument.")
            state = None
        else:
            state = session.find(str(name))
            if state is None:
                _session.error(f'Warning: "{name}" device not found.')
        if state is not None and self._TYPES and state.type not in self._TYPES:
            state = None
        self._s = state
        self._tag = state.tag if state is not None else -2

    #: Called with (state, value) for each fresh sample in a step reply; None stores the value as it comes.
    _absorb: Callable[[_session.DeviceState, Any], None] | None = None

    @staticmethod
    def _setup(state: _session.DeviceState, session: _session.Session) -> None:
        """Give a device's state its initial values (called once per tag by ``Robot()``)."""

    def _queue(self, op: str, *args: Any) -> None:
        _session.require().queue(self._tag, op, *args)

    def getName(self) -> str:
        """The device's ``name`` field."""
        return self.name

    def getModel(self) -> str:
        """The device's ``model`` field."""
        return self.model

    def getNodeType(self) -> int:
        """The ``WB_NODE_*`` value of the device's base node type (``Node.DISTANCE_SENSOR``...)."""
        return self.node_type

    @property
    def name(self) -> str:
        """The device's name."""
        return self._s.name if self._s is not None else ""

    @property
    def model(self) -> str:
        """The device's model."""
        return self._s.model if self._s is not None else ""

    @property
    def node_type(self) -> int:
        """The ``WB_NODE_*`` value of the device's type."""
        return node_type(self._s.type) if self._s is not None else 0

    def __repr__(self) -> str:
        return f"<{type(self).__name__} {self.name!r}>"
