"""acbb from Python: run a bearing scene through the engine library.

Standard library only (ctypes + json). It calls the library's FFI entry
point, acbb_run_preset_json_ctl (include/acbb/ffi.h), which runs the scene
as `acbb run PRESET --set ... --json` does and returns the same JSON:

    import acbb
    r = acbb.run("7008C", {"operating.axial_load_N": 300})
    print(r["status"], r["temperature_C"]["outer_ring"], r["losses_W"]["total"])

A preset is a file's path, a preset name looked up as the CLI does (NAME
and NAME.ini in $XDG_CONFIG_HOME/acbb/presets or ~/.config/acbb/presets,
./presets, then the installed presets), or preset text.

The library is found, in this order: the `lib` argument, the environment
variable ACBB_LIB (a path), libacbb.so.0 beside this file, the install
prefix this file was installed into by meson (PREFIX/lib*/), then the
system's search (ldconfig). Calls release the GIL, so runs on several
threads go in parallel. Ctrl-C stops a run called from the main thread
(it runs in a worker thread; the interrupt sets the library's cancel
flag): `Cancelled`, a KeyboardInterrupt, is raised once the library has
returned, with the "cancelled" document in its `result`.
"""

import ctypes
import ctypes.util
import glob
import json
import os
import threading

__all__ = ["run", "load_library", "preset_dirs", "find_preset", "AcbbError", "Cancelled",
           "__version__"]

# The release this module belongs to (`acbb --version`; test_python checks it).
__version__ = "0.1.0"

SONAME = "libacbb.so.0"
# acbb_status values the module tests (include/acbb/status.h).
ACBB_NONFINITE = -9
ACBB_CANCELLED = -11

# Where meson installed things, relative to the prefix, and the module's own
# directory relative to it (meson.build fills these in the installed copy;
# in the source tree they stay as they are and are not used).
_INSTALL = {"pydir": "@ACBB_PY_DIR@", "libdir": "@ACBB_LIB_DIR@",
            "presetdir": "@ACBB_PRESET_DIR@", "prefix": "@ACBB_PREFIX@"}


def _installed(key):
    v = _INSTALL[key]
    return None if v.startswith("@") else v


def _prefix():
    """The prefix this module is installed in: its directory less the site
    directory's part (a DESTDIR or moved prefix included), else the
    configured prefix; None in the source tree. A site directory outside
    the prefix (the interpreter's own, meson.build) is absolute: what
    stands before it is a DESTDIR, before the configured prefix."""
    pydir = _installed("pydir")
    if pydir is None:
        return None
    here = os.path.dirname(os.path.abspath(__file__))
    tail = os.path.normpath(pydir)
    if os.path.isabs(tail):
        stage = here[:-len(tail)] if here.endswith(tail) else ""
        return stage + _installed("prefix")
    if here.endswith(os.sep + tail):
        return here[:-len(tail) - 1]
    return _installed("prefix")


class AcbbError(Exception):
    """The scene did not run: bad input (a preset or setting the engine
    refused, with its message), a scene that could not be set up, or an
    internal error. `status` is the engine's status name ("bad_input",
    "ill_posed", ...), `code` its acbb_status number, `result` the document
    the engine returned (a dict; None when there was none)."""

    def __init__(self, message, status=None, code=None, result=None):
        super().__init__(message)
        self.status, self.code, self.result = status, code, result


def _candidates(lib):
    if lib:
        yield os.fspath(lib)
        return
    if os.environ.get("ACBB_LIB"):
        yield os.environ["ACBB_LIB"]
        return
    here = os.path.dirname(os.path.abspath(__file__))
    yield os.path.join(here, SONAME)
    prefix, libdir = _prefix(), _installed("libdir")
    if prefix and libdir:
        yield os.path.join(prefix, libdir, SONAME)
    found = ctypes.util.find_library("acbb")
    if found:
        yield found


def preset_dirs():
    """The preset search path, as `acbb presets` lists it: the user's
    ($XDG_CONFIG_HOME/acbb/presets, or ~/.config/acbb/presets), ./presets,
    then the installed presets (of this module's prefix, and the configured
    one)."""
    dirs = []
    xdg, home = os.environ.get("XDG_CONFIG_HOME", ""), os.environ.get("HOME", "")
    if xdg.startswith("/"):  # the XDG spec ignores a relative one
        dirs.append(os.path.join(xdg, "acbb", "presets"))
    elif home:
        dirs.append(os.path.join(home, ".config", "acbb", "presets"))
    dirs.append("presets")
    prefix, rel = _prefix(), _installed("presetdir")
    if prefix and rel:
        dirs.append(os.path.join(prefix, rel))
    conf = _installed("prefix")
    if conf and rel and os.path.join(conf, rel) not in dirs:
        dirs.append(os.path.join(conf, rel))
    return dirs


def find_preset(name):
    """The file a preset argument stands for, as the CLI resolves it: an
    existing file or a name with a '/' as it is, else NAME and NAME.ini in
    preset_dirs(), first match; AcbbError (bad_input) when there is none."""
    name = os.fspath(name)
    if "/" in name or os.path.isfile(name) or not name:
        return name
    dirs = preset_dirs()
    ini = name.endswith(".ini")
    for d in dirs:
        for cand in (name,) if ini else (name, name + ".ini"):
            if os.path.isfile(os.path.join(d, cand)):
                return os.path.join(d, cand)
    msg = (f"cannot open preset {name}: no such file, and no {name}{'' if ini else '[.ini]'}"
           f" in {', '.join(dirs)} (see `acbb presets`)")
    raise AcbbError(msg, "bad_input", -1)


_loaded = {}


def load_library(lib=None):
    """The engine library as a ctypes.CDLL (see the module text for where
    it is looked for); AcbbError when there is none."""
    tried = []
    for path in _candidates(lib):
        if path in _loaded:
            return _loaded[path]
        if os.sep in path and not os.path.exists(path):
            tried.append(path)
            continue
        try:
            dll = ctypes.CDLL(path)
        except OSError as e:
            tried.append(f"{path} ({e})")
            continue
        dll.acbb_run_preset_json_ctl.restype = ctypes.c_void_p
        dll.acbb_run_preset_json_ctl.argtypes = [
            ctypes.c_char_p, ctypes.c_size_t, ctypes.POINTER(ctypes.c_char_p), ctypes.c_size_t,
            ctypes.POINTER(ctypes.c_int), ctypes.POINTER(ctypes.c_int)]
        dll.acbb_string_free.restype = None
        dll.acbb_string_free.argtypes = [ctypes.c_void_p]
        _loaded[path] = dll
        return dll
    raise AcbbError("cannot find the acbb library (" + SONAME + "); tried: "
                    + (", ".join(tried) or "nothing") + "; pass lib=PATH or set ACBB_LIB")


def _value_text(v):
    if isinstance(v, bool):
        return "on" if v else "off"
    return str(v)


def _settings(settings):
    if settings is None:
        return []
    if isinstance(settings, dict):
        return [f"{k}={_value_text(v)}" for k, v in settings.items()]
    if isinstance(settings, str):
        return [settings]
    return [str(s) for s in settings]


def _preset_text(preset):
    """Preset text (a string with a line break) as it is; a path or a
    preset name (find_preset) is read. Any real preset has several lines
    ([bearing], [operating], ...), so text always has a line break."""
    if isinstance(preset, str) and "\n" in preset:
        return preset
    with open(find_preset(preset), encoding="utf-8") as f:
        return f.read()


class Cancelled(KeyboardInterrupt):
    """Ctrl-C (SIGINT) stopped a run: the library was told to stop and
    returned; `result` is its "cancelled" document (the last good state),
    as `acbb run --json` prints it when interrupted."""

    def __init__(self, result):
        super().__init__("cancelled")
        self.result = result


def _call(dll, text, items):
    """The library call; in the main thread from a worker thread, so that
    Ctrl-C sets the cancel flag instead of waiting for the run's end. The
    flag is a C int the library reads atomically (acbb/cancel_flag.h: an
    aligned int store from here is seen whole)."""
    argv = (ctypes.c_char_p * max(len(items), 1))(*items)
    code, cancel = ctypes.c_int(0), ctypes.c_int(0)
    out, done = {}, threading.Event()

    def work():
        try:
            out["ptr"] = dll.acbb_run_preset_json_ctl(text, len(text), argv, len(items),
                                                      ctypes.byref(cancel), ctypes.byref(code))
        finally:
            done.set()

    interrupted = False
    if threading.current_thread() is not threading.main_thread():
        work()
    else:
        # An Event, not Thread.join: a join cut by KeyboardInterrupt can
        # report the thread finished while it still runs (CPython gh-90882).
        # A second Ctrl-C while the library stops is not caught: it goes up
        # at once, as a second Ctrl-C ends `acbb run` at once.
        worker = threading.Thread(target=work, name="acbb.run", daemon=True)
        try:
            worker.start()
            done.wait()
        except KeyboardInterrupt:
            cancel.value = 1
            interrupted = True
            if worker.ident is not None:
                done.wait()
    return out.get("ptr"), code.value, interrupted


def run(preset, settings=None, lib=None):
    """Run a scene to the end; the dict `acbb run PRESET --json` prints.

    preset: a preset file's path, a preset name ("7008C": looked up as the
    CLI does, find_preset), or its text (a string with line breaks).
    settings: {"section.key": value} or ["section.key=value", ...], in
    preset units, as the CLI's --set takes them.
    A run that started comes back as its dict even when it did not converge
    (look at result["status"]: "converged", "not_converged", "runaway",
    ...). AcbbError when the scene did not run (bad input: the engine's
    message) or a number came out non-finite; Cancelled on Ctrl-C."""
    dll = load_library(lib)
    text = _preset_text(preset).encode("utf-8")
    items = [s.encode("utf-8") for s in _settings(settings)]
    for s in items:
        if b"\0" in s:  # a C string would end there, as argv cannot hold one
            head = s.split(b"\0")[0].decode()
            raise AcbbError(f"{head}: NUL byte in a setting (a setting is plain text)",
                            "bad_input", -1)
    ptr, code, interrupted = _call(dll, text, items)
    if not ptr:
        raise AcbbError("out of memory", "out_of_memory", code)
    try:
        result = json.loads(ctypes.string_at(ptr).decode("utf-8"))
    finally:
        dll.acbb_string_free(ptr)
    if interrupted:
        raise Cancelled(result)
    if "losses_W" not in result:
        raise AcbbError(result["message"], result["status"], code, result)
    # ACBB_NONFINITE with another status: a null in the document (a run
    # that failed as "nonfinite" is a result like any failed run).
    if code == ACBB_NONFINITE and result["status"] != "nonfinite":
        raise AcbbError("internal error: a non-finite number in the results (written as null)",
                        "nonfinite", code, result)
    return result
