"""JavaScript PROTO templates (``%< >%``), evaluated with QuickJS.

How a body becomes JavaScript, after Webots' ``WbTemplateEngine::generateJavascript``:

* plain text is appended as a template literal, ``___out.push(render(`...`));`` -- so, exactly as
  in Webots, ``${...}`` in the VRML text is interpolated and backslash escapes are processed
  (wbtc only escapes backquotes, which would end the literal);
* ``%<= expr >%`` becomes ``___tmp = expr;`` followed by appending ``___tmp``, i.e. the value's
  JavaScript string form (``0.1 + 0.2`` -> ``0.30000000000000004``, ``true`` -> ``true``);
* the pieces are collected in an array and joined once at the end (Webots appends to a string,
  ``___vrml += ...``: the text is the same, but QuickJS copies the whole string at every append,
  which made a template with a few hundred thousand pieces, a 2 km road with crash barriers, run
  for minutes);
* ``%< code >%`` is inserted as is, except ``import`` statements, which are hoisted.

Every append also goes through ``__wbmark``, which records the template line of the piece for
`TemplateOutput.line_map` and returns the piece's string form (so the text is unchanged).

Everything runs inside one strict-mode function, so ``fields``, ``context``, ``console``,
``wbfile`` and the imported modules are visible everywhere. The generated function keeps the
body's line structure (body line *k* is line *k* of the function source), which is how engine
errors map back to PROTO lines.

QuickJS has no module loader in the ``quickjs`` package, so ``import`` statements are rewritten
into constants bound to module objects built from wbtc's own module files (``wbtc/proto/js``).
The engine (one per thread: QuickJS contexts must stay on the thread that made them) is
created once; modules are compiled once; a compiled template is cached by its source.
"""

from __future__ import annotations

import json
import math
import re
import threading
from collections import OrderedDict
from pathlib import Path

import quickjs

from wbtc.errors import ProtoError, Span
from wbtc.proto.template_common import (
    Chunk,
    SourceMap,
    TemplateOutput,
    js_string_value,
    line_map,
    number,
    plain_value,
    proto_error,
)
from wbtc.proto.template_files import note_outside_input

_JS_DIR = Path(__file__).with_name("js")

#: Modules templates may import, by file name.
MODULES = ("wbutility.js", "wbrandom.js", "wbvector2.js", "wbvector3.js", "wbrotation.js",
           "wbgeometry.js")

# The prelude and modules are placed this many lines down in their source so that stack frames
# inside them are never mistaken for template lines (QuickJS names every evaluated source
# "<input>").
_LIBRARY_LINE_OFFSET = 1_000_000

_CACHE_SIZE = 256

_MODULE_IMPORT = re.compile(r"^import \* as (\w+) from '([\w.]+)';", re.MULTILINE)
_MODULE_EXPORT = re.compile(r"^export (?=function|const|let)", re.MULTILINE)
_EXPORTED_NAME = re.compile(r"^export (?:function\*?|const|let)\s+([A-Za-z_$][\w$]*)", re.MULTILINE)

# An import statement inside template code: `import CLAUSE from 'spec'` or `import 'spec'`.
_TEMPLATE_IMPORT = re.compile(
    r"(?<![\w$.])import\s*(?:(?P<clause>[^'\";()]*?)\s*(?<![\w$])from\s*)?"
    r"(?P<quote>['\"])(?P<spec>[^'\"\n]*)(?P=quote)[ \t]*;?"
)
_NAMESPACE_CLAUSE = re.compile(r"^\*\s*as\s+([A-Za-z_$][\w$]*)$")
_NAMED_CLAUSE = re.compile(r"^\{(?P<names>[^{}]*)\}$")
_NAMED_ITEM = re.compile(r"^([A-Za-z_$][\w$]*)(?:\s+as\s+([A-Za-z_$][\w$]*))?$")
_STACK_LINE = re.compile(r"<input>:(\d+)")
_QUICKJS_NOT_DEFINED = re.compile(r"^'(.*)' is not defined$")

#: Time limit of one render, in seconds (unlimited when the template uses `wbfile`, because
#: QuickJS refuses to call back into Python while a limit is set).
TIME_LIMIT = 60.0


class _RenderState:
    """What the Python-side `wbfile` functions need to know about the render in progress."""

    def __init__(self) -> None:
        self.temporary_path = ""
        self.proto_dir = ""

    def resolve(self, path: str) -> Path:
        # Webots runs templates with the temporary directory as working directory.
        candidate = Path(path)
        if candidate.is_absolute():
            return candidate
        base = self.temporary_path or self.proto_dir or "."
        return Path(base) / candidate


class JsEngine:
    """A QuickJS context with the prelude and the template modules loaded."""

    def __init__(self) -> None:
        self._context = quickjs.Context()
        self._state = _RenderState()
        self._install_host_functions()
        self._exports: dict[str, frozenset[str]] = {}
        self._context.eval("\n" * _LIBRARY_LINE_OFFSET + self._library_source())
        self._compile = self._context.get("__wbcompile")
        self._run = self._context.get("__wbrun")
        self._compiled: OrderedDict[str, int] = OrderedDict()
        self._time_limit: float | None = None

    # ---- setup ------------------------------------------------------------------------------

    def _library_source(self) -> str:
        parts = [(_JS_DIR / "_prelude.js").read_text(encoding="utf-8")]
        for name in MODULES:
            source = (_JS_DIR / name).read_text(encoding="utf-8")
            self._exports[name] = frozenset(_EXPORTED_NAME.findall(source))
            # Turn the ES module into a factory: imports become calls of the registry passed
            # in, `export` keywords go, and the exported names are returned as an object.
            body = _MODULE_IMPORT.sub(r"const \1 = __wbimport('\2');", source)
            body = _MODULE_EXPORT.sub("", body)
            exported = ", ".join(sorted(self._exports[name]))
            parts.append(f"__wbmodules[{json.dumps(name)}] = function (__wbimport) {{ 'use strict';\n"
                         f"{body}\nreturn {{{exported}}};\n}};")
        return "\n".join(parts)

    def _install_host_functions(self) -> None:
        # Host functions must never raise: an exception escaping into QuickJS is fatal.
        state = self._state

        def file_exists(path: str) -> bool:
            note_outside_input()
            try:
                return state.resolve(str(path)).is_file()
            except Exception:  # noqa: BLE001 - any failure means "no"
                return False

        def read_text_file(path: str) -> str | None:
            note_outside_input()
            try:
                return state.resolve(str(path)).read_text(encoding="utf-8", errors="replace")
            except Exception:  # noqa: BLE001
                return None

        def write_text_file(name: str, content: str) -> bool:
            try:
                if not state.temporary_path:
                    return False
                target = Path(state.temporary_path) / str(name)
                target.write_text(str(content), encoding="utf-8")
                return True
            except Exception:  # noqa: BLE001
                return False

        self._context.add_callable("__wbhost_file_exists", file_exists)
        self._context.add_callable("__wbhost_read_text_file", read_text_file)
        self._context.add_callable("__wbhost_write_text_file", write_text_file)

    # ---- rendering --------------------------------------------------------------------------

    def render(self, chunks: list[Chunk], source_map: SourceMap, fields: dict, context: dict,
               proto_path: str) -> TemplateOutput:
        """Evaluate a split JavaScript template.

        Args:
            chunks: the body split by `split_template`.
            source_map: maps body lines to PROTO file places.
            fields: template fields (``{name: {"value": v, "defaultValue": d}}``).
            context: the template context from `context_values`.
            proto_path: the PROTO file, for messages and `wbfile` paths.

        Returns:
            The generated text and console entries.

        Raises:
            ProtoError: bad import, syntax error or uncaught exception, located in the PROTO.
        """
        source, uses_wbfile = self._function_source(chunks, source_map, proto_path)
        template_id = self._compiled_id(source, source_map, chunks, proto_path)

        self._state.temporary_path = str(context.get("temporary_files_path") or "")
        self._state.proto_dir = str(Path(proto_path).parent) if proto_path else ""
        self._set_time_limit(None if uses_wbfile else TIME_LIMIT)
        try:
            raw = self._run(template_id, _js_literal(plain_value(fields)), json.dumps(plain_value(context)))
        except quickjs.JSException as exc:
            # Only uncatchable conditions get here (the time-limit interrupt): rebuild the
            # error record from the exception text, "Name: message\n    at f (<input>:N)...".
            raise self._error(_exception_record(exc), source_map, chunks, proto_path) from None
        result = json.loads(raw)
        stdout = [str(entry) for entry in result["stdout"]]
        stderr = [str(entry) for entry in result["stderr"]]
        if not result["ok"]:
            raise self._error(result["error"], source_map, chunks, proto_path)
        text = result["vrml"]
        lines = line_map([int(n) for n in result["segments"]], text, source_map)
        return TemplateOutput(text, stdout, stderr, stdout + stderr, lines)

    def _set_time_limit(self, seconds: float | None) -> None:
        if seconds != self._time_limit:
            self._context.set_time_limit(-1 if seconds is None else seconds)
            self._time_limit = seconds

    def _compiled_id(self, source: str, source_map: SourceMap, chunks: list[Chunk],
                     proto_path: str) -> int:
        template_id = self._compiled.get(source)
        if template_id is not None:
            self._compiled.move_to_end(source)
            return template_id
        self._set_time_limit(TIME_LIMIT)
        try:
            result = json.loads(self._compile(source))
        except quickjs.JSException as exc:
            raise self._error(_exception_record(exc), source_map, chunks, proto_path) from None
        if not result["ok"]:
            raise self._error(result["error"], source_map, chunks, proto_path)
        template_id = int(result["id"])
        self._compiled[source] = template_id
        if len(self._compiled) > _CACHE_SIZE:
            _, old_id = self._compiled.popitem(last=False)
            self._context.eval(f"__wbtemplates[{old_id}] = null;")
        return template_id

    def _function_source(self, chunks: list[Chunk], source_map: SourceMap,
                         proto_path: str) -> tuple[str, bool]:
        """The template function; body line k is on line k of the returned source."""
        imports: list[str] = []
        pieces: list[str] = []
        for chunk in chunks:
            line = source_map.line_col(chunk.start)[0]
            # __wbmark(value, line) records where the piece comes from (for the line map) and
            # returns the value's string form, so the appends produce what Webots' produce.
            if chunk.kind == "text":
                pieces.append(f"___out.push(__wbmark(render(`{_escape_backquotes(chunk.text)}`), {line}));")
            elif chunk.kind == "expr":
                # Same shape as Webots' `___tmp = expr; ___vrml += eval("___tmp");` (a comma
                # expression assigns its first operand, as there).
                pieces.append(f"___tmp = {chunk.text}; ___out.push(__wbmark(___tmp, {-line}));")
            else:
                code = self._hoist_imports(chunk, imports, source_map, proto_path)
                pieces.append(code)
        body = "".join(pieces)
        header = ("(function __wbtemplate(__wbfields, __wbcontext, __wbimport, render) {'use strict'; "
                  "const fields = __wbfields; const context = __wbcontext; "
                  "const ___out = []; let ___tmp; " + " ".join(imports) + " ")
        source = header + body + "\nreturn ___out.join('');\n})"
        return source, "wbfile" in body

    def _hoist_imports(self, chunk: Chunk, imports: list[str], source_map: SourceMap,
                       proto_path: str) -> str:
        code = chunk.text
        if "import" not in code:
            return code

        def replace(match: re.Match[str]) -> str:
            offset = chunk.start + 2 + match.start()  # after the opening token
            imports.append(self._binding(match, source_map.span_at(offset), proto_path))
            # Blank the statement but keep its line breaks so that lines do not move.
            return re.sub(r"[^\n]", " ", match.group())

        return _TEMPLATE_IMPORT.sub(replace, code)

    def _binding(self, match: re.Match[str], span: Span, proto_path: str) -> str:
        """The constant declaration that replaces one import statement."""
        spec = match.group("spec")
        name = _module_name(spec)
        if name == "wbfile.js":
            raise proto_error("wbfile is a global object and cannot be imported "
                              "(use wbfile.readTextFile(...) directly)", proto_path, span)
        if name not in self._exports:
            available = ", ".join(MODULES)
            raise proto_error(f"cannot import '{spec}': no such module (available: {available})",
                              proto_path, span)
        clause = (match.group("clause") or "").strip()
        call = f"__wbimport({json.dumps(name)})"
        if not clause:
            return f"{call};"
        namespace = _NAMESPACE_CLAUSE.match(clause)
        if namespace:
            return f"const {namespace.group(1)} = {call};"
        named = _NAMED_CLAUSE.match(clause)
        if named:
            bindings = []
            for item in filter(None, (part.strip() for part in named.group("names").split(","))):
                parsed = _NAMED_ITEM.match(item)
                if not parsed:
                    raise proto_error(f"cannot parse the import of '{item}' from '{spec}'", proto_path, span)
                exported, local = parsed.group(1), parsed.group(2)
                if exported not in self._exports[name]:
                    raise proto_error(f"module '{name}' has no export named '{exported}'", proto_path, span)
                bindings.append(f"{exported}: {local}" if local else exported)
            return f"const {{{', '.join(bindings)}}} = {call};"
        raise proto_error(f"module '{name}' has no default export (use `import * as X from '{spec}'`)",
                          proto_path, span)

    def _error(self, error: dict, source_map: SourceMap, chunks: list[Chunk], proto_path: str) -> ProtoError:
        """The ProtoError for an engine error record (name, message, stack, line)."""
        name = error.get("name") or ""
        message = str(error.get("message") or "")
        # QuickJS quotes the name ("'foo' is not defined"); Webots' engine does not.
        not_defined = _QUICKJS_NOT_DEFINED.match(message)
        if name == "ReferenceError" and not_defined:
            message = f"{not_defined.group(1)} is not defined"
        if message == "interrupted" and name == "InternalError":
            message = f"evaluation took longer than {TIME_LIMIT:g} s (endless loop?)"
            name = ""
        text = f"{name}: {message}" if name else message or "uncaught exception"

        line = error.get("line") if isinstance(error.get("line"), int) else None
        if line is None or line >= _LIBRARY_LINE_OFFSET:
            line = None
            # innermost frame that belongs to template code
            for found in _STACK_LINE.findall(str(error.get("stack") or "")):
                if int(found) < _LIBRARY_LINE_OFFSET:
                    line = int(found)
                    break
        if line is None:
            return proto_error(text, proto_path, source_map.span(1, 1))
        line = min(line, source_map.line_count)
        column = source_map.first_column(line)
        for chunk in chunks:
            chunk_line, chunk_column = source_map.line_col(chunk.start)
            if chunk.kind != "text" and chunk_line == line:
                column = chunk_column
                break
        return proto_error(text, proto_path, source_map.span(line, column))


def _exception_record(exc: quickjs.JSException) -> dict:
    """An error record like the prelude's __wberror, from an exception QuickJS did not let JS catch."""
    text = str(exc.args[0] if exc.args else exc)
    head, _, stack = text.partition("\n")
    name, separator, message = head.partition(": ")
    if not separator:
        name, message = "", head
    return {"name": name, "message": message, "stack": stack, "line": None}


def _module_name(spec: str) -> str:
    name = spec.strip()
    if name.startswith("./"):
        name = name[2:]
    name = name.rsplit("/", 1)[-1]
    return name if name.endswith(".js") else name + ".js"


def _escape_backquotes(text: str) -> str:
    # A backquote would end the template literal (and break the template in Webots); escape
    # those not already escaped. Everything else keeps template-literal semantics.
    if "`" not in text:
        return text
    out = []
    backslashes = 0
    for char in text:
        if char == "`" and backslashes % 2 == 0:
            out.append("\\")
        backslashes = backslashes + 1 if char == "\\" else 0
        out.append(char)
    return "".join(out)


def _js_literal(value: object) -> str:
    """JavaScript source for a field value (``undefined`` for None, floats as Webots rounds them)."""
    if value is None:
        return "undefined"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        value = number(value)
        if math.isnan(value):
            return "NaN"
        if math.isinf(value):
            return "Infinity" if value > 0 else "-Infinity"
        return repr(value)
    if isinstance(value, str):
        return json.dumps(js_string_value(value))
    if isinstance(value, dict):
        items = ", ".join(f"{json.dumps(str(key))}: {_js_literal(item)}" for key, item in value.items())
        return "{" + items + "}"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_js_literal(item) for item in value) + "]"
    raise TypeError(f"cannot pass a {type(value).__name__} to a JavaScript template")


_local = threading.local()


def engine() -> JsEngine:
    """Return the JavaScript engine of the calling thread, creating it on first use."""
    instance = getattr(_local, "engine", None)
    if instance is None:
        instance = _local.engine = JsEngine()
    return instance
