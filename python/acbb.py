"""acbb from Python: run a bearing scene through the engine library.

Standard library only (ctypes + json). It calls the library's FFI entry
point, acbb_run_preset_json (include/acbb/ffi.h), which runs the scene as
`acbb run PRESET --set ... --json` does and returns the same JSON:

    import acbb
    r = acbb.run("presets/7008C.ini", {"operating.axial_load_N": 300})
    print(r["status"], r["temperature_C"]["outer_ring"], r["losses_W"]["total"])

The library is found, in this order: the `lib` argument, the environment
variable ACBB_LIB (a path), libacbb.so.0 beside this file, the install
prefix this file sits in (PREFIX/share/acbb/python/acbb.py, the library in
PREFIX/lib*/), then the system's search (ldconfig). Calls release the GIL,
so runs on several threads go in parallel.
"""

import ctypes
import ctypes.util
import glob
import json
import os

__all__ = ["run", "load_library", "AcbbError"]

SONAME = "libacbb.so.0"
# acbb_status values the module tests (include/acbb/status.h).
ACBB_NONFINITE = -9


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
    prefix = os.path.normpath(os.path.join(here, "..", "..", ".."))
    for pattern in ("lib/*/" + SONAME, "lib64/" + SONAME, "lib/" + SONAME):
        yield from sorted(glob.glob(os.path.join(prefix, pattern)))
    found = ctypes.util.find_library("acbb")
    if found:
        yield found


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
        dll.acbb_run_preset_json.restype = ctypes.c_void_p
        dll.acbb_run_preset_json.argtypes = [ctypes.c_char_p, ctypes.POINTER(ctypes.c_char_p),
                                             ctypes.c_size_t, ctypes.POINTER(ctypes.c_int)]
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
    """A path (PathLike, or a string without a line break) is read; other
    strings are preset text. So a preset given as text needs a line break:
    any real preset has several lines ([bearing], [operating], ...)."""
    if isinstance(preset, os.PathLike) or "\n" not in preset:
        with open(preset, encoding="utf-8") as f:
            return f.read()
    return preset


def run(preset, settings=None, lib=None):
    """Run a scene to the end; the dict `acbb run PRESET --json` prints.

    preset: a preset file's path, or its text (a string with line breaks).
    settings: {"section.key": value} or ["section.key=value", ...], in
    preset units, as the CLI's --set takes them.
    A run that started comes back as its dict even when it did not converge
    (look at result["status"]: "converged", "not_converged", "runaway",
    ...). AcbbError when the scene did not run (bad input: the engine's
    message) or a number came out non-finite."""
    dll = load_library(lib)
    text = _preset_text(preset).encode("utf-8")
    items = [s.encode("utf-8") for s in _settings(settings)]
    argv = (ctypes.c_char_p * max(len(items), 1))(*items)
    code = ctypes.c_int(0)
    ptr = dll.acbb_run_preset_json(text, argv, len(items), ctypes.byref(code))
    if not ptr:
        raise AcbbError("out of memory", "out_of_memory", code.value)
    try:
        result = json.loads(ctypes.string_at(ptr).decode("utf-8"))
    finally:
        dll.acbb_string_free(ptr)
    if "losses_W" not in result:
        raise AcbbError(result["message"], result["status"], code.value, result)
    # ACBB_NONFINITE with another status: a null in the document (a run
    # that failed as "nonfinite" is a result like any failed run).
    if code.value == ACBB_NONFINITE and result["status"] != "nonfinite":
        raise AcbbError("internal error: a non-finite number in the results (written as null)",
                        "nonfinite", code.value, result)
    return result
