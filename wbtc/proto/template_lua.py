"""Lua PROTO templates (``%{ }%``), evaluated with Lua 5.2 through lupa.

Webots (up to R2024b) renders Lua templates with liluat inside a Lua 5.2 state; wbtc reproduces
what a template can observe of that:

* liluat's whitespace trimming: after a code chunk one leading line break of the following text
  is dropped, and before a code chunk the blanks after the text's last line break are dropped
  (``%{-``/``-}%`` force trimming and ``%{+``/``+}%`` prevent it). Lines that only hold a
  statement therefore vanish from the output;
* ``%{= expr }%`` appends strings as they are and numbers in Lua 5.2's ``%.14g`` form (``1``
  for 1.0, ``0.33333333333333`` for 1/3); ``nil`` appends nothing; other values fail;
* the sandbox: the names liluat exposes (``pairs``, ``string``, ``math``, ``os.time``, ...)
  plus ``fields``, ``context``, ``require``, ``io`` and ``print``. ``print`` and
  ``io.stdout:write``/``io.stderr:write`` append their arguments without separators; the
  collected text is split into console lines at line breaks;
* ``require`` gives the standard libraries and wbtc's own versions of Webots' Lua modules
  (``wbcore``, ``wbgeometry``, ``wbrandom``, ``wbrotation``, ``wbvector2``, ``wbvector3``,
  ``wbmath``, ``wbstring``, ``wblimits``, ``wbfile``) and of Lua-GD (``gd``, `wbtc.proto.template_gd`),
  fresh for every render;
* files: Webots runs Lua templates in its temporary folder, so ``io.open`` and ``gd`` resolve a relative
  file name in ``context.temporary_files_path``.

The generated Lua keeps the body's line structure (body line *k* is line *k* of the chunk), so
errors map back to PROTO lines. One Lua runtime per thread is created once; modules are
compiled once and a compiled template is cached by its source.
"""

from __future__ import annotations

import threading
from collections import OrderedDict
from pathlib import Path

from wbtc.errors import ProtoError
from wbtc.proto.template_common import (
    Chunk,
    SourceMap,
    TemplateOutput,
    console_lines,
    line_map,
    lua_string_value,
    number,
    plain_value,
    proto_error,
)
from wbtc.proto.template_gd import GdHost

try:  # Webots embeds Lua 5.2: number formatting and library details follow it.
    import lupa.lua52 as _lupa
except ImportError:  # pragma: no cover - lupa builds without the 5.2 runtime
    import lupa as _lupa

_LUA_DIR = Path(__file__).with_name("js") / "lua"

#: Modules templates may ``require``.
MODULES = ("gd", "wbcore", "wbfile", "wbgeometry", "wblimits", "wbmath", "wbrandom", "wbrotation",
           "wbstring", "wbvector2", "wbvector3")

#: Time limit of one render, in seconds of CPU time.
TIME_LIMIT = 60.0

_CACHE_SIZE = 256
_LUA_SPACE = " \t\n\v\f\r"


class LuaEngine:
    """A Lua runtime with the prelude and the template modules loaded."""

    def __init__(self) -> None:
        # No `python` object in Lua: templates have no business reaching into the host.
        self._runtime = _lupa.LuaRuntime(unpack_returned_tuples=True, register_eval=False,
                                         register_builtins=False)
        self._runtime.execute((_LUA_DIR / "_prelude.lua").read_text(encoding="utf-8"))
        # Item access: attribute names starting with "__" would be mangled inside the class.
        lua_globals = self._runtime.globals()
        # Lua-GD's images are drawn by the host; the module reaches these functions, templates do not.
        self._gd = GdHost()
        lua_globals["__wb_gd"] = self._runtime.table_from(self._gd.functions())
        for name in MODULES:
            source = (_LUA_DIR / f"{name}.lua").read_text(encoding="utf-8")
            lua_globals["__wb_register_module"](name, source)
        self._compile = lua_globals["__wb_compile"]
        self._forget = lua_globals["__wb_forget"]
        self._render = lua_globals["__wb_render"]
        self._compiled: OrderedDict[str, int] = OrderedDict()

    def render(self, chunks: list[Chunk], source_map: SourceMap, fields: dict, context: dict,
               proto_path: str) -> TemplateOutput:
        """Evaluate a split Lua template.

        Args:
            chunks: the body split by `split_template` (after `strip_lua_vrml_comments`).
            source_map: maps body lines to PROTO file places.
            fields: template fields (``{name: {"value": v, "defaultValue": d}}``).
            context: the template context from `context_values`.
            proto_path: the PROTO file, for messages.

        Returns:
            The generated text and console lines.

        Raises:
            ProtoError: syntax or runtime error, located in the PROTO.
        """
        code = lua_source(chunks, source_map)
        template_id = self._compiled.get(code)
        if template_id is None:
            template_id, message = self._compile(code)
            if template_id is None:
                raise _error(str(message), None, source_map, chunks, proto_path)
            self._compiled[code] = template_id
            if len(self._compiled) > _CACHE_SIZE:
                self._forget(self._compiled.popitem(last=False)[1])
        else:
            self._compiled.move_to_end(code)

        lua_fields = self._table(fields)
        lua_context = self._table(context)
        folder = str(context.get("temporary_files_path") or "")
        self._gd.reset(folder)
        try:
            ok, text, out_text, err_text, message, line, segments = self._render(
                template_id, lua_fields, lua_context, TIME_LIMIT, folder)
        finally:
            self._gd.reset("")
        stdout = console_lines(str(out_text or ""))
        stderr = console_lines(str(err_text or ""))
        if not ok:
            raise _error(str(message), line, source_map, chunks, proto_path)
        text = str(text)
        numbers = [int(float(n)) for n in str(segments).split(",")] if segments else []
        # Webots shows the error stream first.
        return TemplateOutput(text, stdout, stderr, stderr + stdout, line_map(numbers, text, source_map))

    def _table(self, value: object) -> object:
        return self._runtime.table_from(_lua_value(plain_value(value)), recursive=True)


def _lua_value(value: object) -> object:
    """Field/context values as Lua sees them: lists stay lists (1-based tables), None is nil."""
    if isinstance(value, str):
        return lua_string_value(value)
    if isinstance(value, bool) or value is None:
        return value
    if isinstance(value, (int, float)):
        return number(value)
    if isinstance(value, dict):
        return {str(key): _lua_value(item) for key, item in value.items() if item is not None}
    if isinstance(value, (list, tuple)):
        return [_lua_value(item) for item in value]
    raise TypeError(f"cannot pass a {type(value).__name__} to a Lua template")


def lua_source(chunks: list[Chunk], source_map: SourceMap) -> str:
    """The Lua chunk of a template; body line k is on line k of the result.

    Text goes through ``__wbout(text, line)`` and expressions through ``__wbexpr(line, expr)``
    (which keeps only the first value, like liluat's output function); the line arguments feed
    the output line map.
    """
    pieces: list[str] = []
    for index, chunk in enumerate(chunks):
        line = source_map.line_col(chunk.start)[0]
        if chunk.kind == "code":
            pieces.append(chunk.text)
        elif chunk.kind == "expr":
            value = chunk.text if chunk.text.strip() else "nil"  # `%{= }%` appends nothing
            pieces.append(f"__wbexpr({line}, {value})")
        else:
            text, skipped_break = _trimmed(chunks, index)
            call = f"__wbout({_lua_quote(text)}, {line + skipped_break})" if text else ""
            # The original line breaks follow the call so that later lines keep their numbers.
            pieces.append(call + "\n" * chunk.text.count("\n"))
        pieces.append(" ")
    return "".join(pieces)


def _trimmed(chunks: list[Chunk], index: int) -> tuple[str, int]:
    """Apply liluat's default trimming (``trim_left``/``trim_right`` = "code") to a text chunk.

    Returns:
        The trimmed text, and 1 if its leading line break was dropped (else 0).
    """
    text = chunks[index].text
    previous = chunks[index - 1] if index > 0 else None
    following = chunks[index + 1] if index + 1 < len(chunks) else None

    if previous is not None and previous.trim_right is not None:
        trim_right = previous.trim_right
    else:
        trim_right = previous is not None and previous.kind == "code"
    if following is not None and following.trim_left is not None:
        trim_left = following.trim_left
    else:
        trim_left = following is not None and following.kind == "code"

    if trim_right and trim_left:
        if text.startswith("\n"):
            rest = text[1:]
            if "\n" in rest:
                return _cut_blank_tail(rest) or rest, 1
            if rest.strip(_LUA_SPACE) == "":
                return "", 1
            return rest, 1
        return _cut_blank_tail(text) or text, 0
    if trim_left:
        if index == 0 and text.strip(_LUA_SPACE) == "":
            return "", 0
        return _cut_blank_tail(text) or text, 0
    if trim_right and text.startswith("\n"):
        return text[1:], 1
    return text, 0


def _cut_blank_tail(text: str) -> str | None:
    r"""Cut the blanks after the last line break (Lua's ``^(.*\n)%s-$``).

    Returns:
        The text up to and including its last line break when only blanks follow it, else None.
    """
    last = text.rfind("\n")
    if last < 0 or text[last + 1:].strip(_LUA_SPACE) != "":
        return None
    return text[:last + 1]


def _lua_quote(text: str) -> str:
    # One-line Lua string literal (line breaks escaped) so that the chunk keeps its lines.
    out = ['"']
    for char in text:
        if char == "\\":
            out.append("\\\\")
        elif char == '"':
            out.append('\\"')
        elif char == "\n":
            out.append("\\n")
        elif char == "\r":
            out.append("\\r")
        elif ord(char) < 32 or ord(char) == 127:
            out.append(f"\\{ord(char):03d}")
        else:
            out.append(char)
    out.append('"')
    return "".join(out)


def _error(message: str, line: int | None, source_map: SourceMap, chunks: list[Chunk],
           proto_path: str) -> ProtoError:
    # Compile errors and errors raised in template code carry "wbtemplate:LINE: " in front.
    prefix = "wbtemplate:"
    if message.startswith(prefix):
        number_text, _, rest = message[len(prefix):].partition(":")
        if number_text.isdigit():
            line = line or int(number_text)
            message = rest.strip()
    if line is None:
        return proto_error(message, proto_path, source_map.span(1, 1))
    line = min(line, source_map.line_count)
    column = source_map.first_column(line)
    for chunk in chunks:
        chunk_line, chunk_column = source_map.line_col(chunk.start)
        if chunk.kind != "text" and chunk_line == line:
            column = chunk_column
            break
    return proto_error(message, proto_path, source_map.span(line, column))


_local = threading.local()


def engine() -> LuaEngine:
    """Return the Lua engine of the calling thread, creating it on first use."""
    instance = getattr(_local, "engine", None)
    if instance is None:
        instance = _local.engine = LuaEngine()
    return instance
