/*
 * _prelude.js -- global scaffolding of wbtc's JavaScript template engine (evaluated once per
 * engine, before the modules). Not a template module: it cannot be imported.
 *
 * Globals seen by templates, as in Webots: `console`, `stdout`, `stderr` and `wbfile`.
 * Internal names start with `__wb`.
 */

var stdout = [];
var stderr = [];

// One console entry per call: arguments are concatenated without separator, objects as
// one-space-indented JSON.
var console = (function () {
  function digest(args) {
    let entry = '';
    for (let i = 0; i < args.length; ++i)
      entry += (typeof args[i] === 'object') ? JSON.stringify(args[i], null, 1) : args[i];
    return entry;
  }
  return {
    log: function () { stdout.push(digest(arguments)); },
    info: function () { stdout.push(digest(arguments)); },
    warn: function () { stdout.push(digest(arguments)); },
    debug: function () { stdout.push(digest(arguments)); },
    error: function () { stderr.push(digest(arguments)); }
  };
})();

// File access for templates; the host functions are installed by Python (__wbhost_*) and never
// throw: failures come back as null.
var wbfile = {
  fileExists: function (path) {
    return __wbhost_file_exists(String(path)) === true;
  },
  readTextFile: function (path) {
    const content = __wbhost_read_text_file(String(path));
    if (content === null) {
      stderr.push('could not open file: ' + path + '.');
      return '';
    }
    return content;
  },
  writeTextFile: function (name, content) {
    if (__wbhost_write_text_file(String(name), String(content)) !== true) {
      stderr.push("could not write file '" + name + "' to the temporary path.");
      return false;
    }
    return true;
  }
};

// Module factories by file name, filled by the module bundle.
var __wbmodules = Object.create(null);

// Compiled template functions, referenced by index from Python.
var __wbtemplates = [];

// A fresh module registry per render: module state (e.g. the wbrandom seed) never leaks from one
// render to the next, like Webots which builds a new engine for every evaluation.
function __wbmakeimporter() {
  const instances = Object.create(null);
  function importModule(name) {
    if (!(name in instances)) {
      const factory = __wbmodules[name];
      if (factory === undefined)
        throw new Error("cannot import '" + name + "'");
      instances[name] = Object.freeze(factory(importModule));
    }
    return instances[name];
  }
  return importModule;
}

function __wbrender(text) {
  return text;
}

// Output bookkeeping for wbtc's line map: per appended piece, five numbers (line breaks already
// in the output, line breaks in the piece, template line -- negative for an expression value --,
// piece ends with a line break, piece is non-empty). Returns the piece as a string: appending
// that string gives the same result as appending the value itself.
var __wbsegments = [];
var __wbnewlines = 0;

function __wbmark(value, line) {
  const text = '' + value;
  let count = 0;
  for (let i = text.indexOf('\n'); i >= 0; i = text.indexOf('\n', i + 1))
    ++count;
  __wbsegments.push(__wbnewlines, count, line,
                    text.length > 0 && text.charCodeAt(text.length - 1) === 10 ? 1 : 0,
                    text.length > 0 ? 1 : 0);
  __wbnewlines += count;
  return text;
}

function __wberror(e) {
  if (e instanceof Error)
    return {name: e.name, message: e.message, stack: String(e.stack || ''),
            line: (typeof e.lineNumber === 'number') ? e.lineNumber : null};
  let message;
  try {
    message = String(e);
  } catch (ignored) {
    message = 'uncaught exception';
  }
  return {name: '', message: message, stack: '', line: null};
}

function __wbcompile(source) {
  try {
    __wbtemplates.push((0, eval)(source));
    return JSON.stringify({ok: true, id: __wbtemplates.length - 1});
  } catch (e) {
    return JSON.stringify({ok: false, error: __wberror(e)});
  }
}

function __wbrun(id, fieldsSource, contextJson) {
  stdout = [];
  stderr = [];
  __wbsegments = [];
  __wbnewlines = 0;
  let result;
  try {
    const fields = (0, eval)('(' + fieldsSource + ')');
    const context = JSON.parse(contextJson);
    const vrml = __wbtemplates[id](fields, context, __wbmakeimporter(), __wbrender);
    result = {ok: true, vrml: String(vrml)};
  } catch (e) {
    result = {ok: false, error: __wberror(e)};
  }
  result.stdout = stdout.map((entry) => String(entry));
  result.stderr = stderr.map((entry) => String(entry));
  result.segments = __wbsegments;
  return JSON.stringify(result);
}
