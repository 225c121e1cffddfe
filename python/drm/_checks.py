"""Argument checks of the package drm: every value is refused, never cast,
wrapped or truncated, unless it converts exactly to the type the codec holds.

A wrong type raises InvalidTypeError (also a TypeError), a number outside
the range of the codec's type OutOfRangeError (also an OverflowError), a
wrong shape or an unknown name InvalidInputError (also a ValueError).
"""
from __future__ import annotations

import os
from typing import Any, Callable, Dict, Mapping, Optional, Tuple

import numpy as np

from . import _drm

Error = _drm.Error
InvalidInputError = _drm.InvalidInputError


class InvalidTypeError(InvalidInputError, TypeError):
    """An argument of the wrong type: a float where an index is expected, a
    str where bytes are, an int where a name is."""


class OutOfRangeError(InvalidInputError, OverflowError):
    """A number that does not fit the codec's type: an index of 2**32 or
    more, a negative index, a colour channel above 255, a float beyond
    float32's range."""


_FLOAT32_MAX = float(np.finfo(np.float32).max)
_LIMITS = {np.uint8: 255, np.uint32: 2**32 - 1}


def _array(value: Any, name: str, dtype: type, columns: int) -> np.ndarray:
    """value as a C-ordered array of dtype with `columns` values a row (a
    flat array when columns is 1), or the error that says why not."""
    if isinstance(value, (str, bytes, bytearray, memoryview)) or value is None:
        raise InvalidTypeError(f"{name} must be an array of numbers, not {type(value).__name__}")
    try:
        a = np.asarray(value)
    except (ValueError, TypeError) as e:  # ragged nested lists
        raise InvalidInputError(f"{name} must be a regular array of shape (n, {columns}): {e}") from None
    kind = a.dtype.kind
    integral = dtype is not np.float32
    if kind == "O" and a.size and all(isinstance(x, int) and not isinstance(x, bool) for x in a.flat):
        # Python ints beyond 64 bits: numpy keeps them as objects.
        flat = list(a.flat)
        where = max(range(len(flat)), key=lambda i: abs(flat[i]))
        target = "uint32" if dtype is np.uint32 else "uint8" if dtype is np.uint8 else "float32"
        raise OutOfRangeError(f"{name}: row {where // max(columns, 1)} holds {flat[where]}, beyond the range of {target}")
    if integral and kind not in "iu":
        what = "integers" if dtype is np.uint32 else "integers 0..255"
        raise InvalidTypeError(f"{name} must hold {what}, not {a.dtype} values")
    if not integral and kind not in "iuf":
        raise InvalidTypeError(f"{name} must hold numbers, not {a.dtype} values")
    if columns == 1:
        if a.ndim == 2 and a.shape[1] == 1:
            a = a.reshape(-1)
        if a.ndim != 1:
            raise InvalidInputError(f"{name} must be an array of shape (n,), not {a.shape}")
    else:
        if a.ndim == 1 and a.size == 0:
            a = a.reshape(0, columns)
        if a.ndim != 2 or a.shape[1] != columns:
            raise InvalidInputError(f"{name} must be an array of shape (n, {columns}), not {a.shape}")
    if a.size and integral:
        low, high = int(a.min()), int(a.max())
        if low < 0 or high > _LIMITS[dtype]:
            bad = low if low < 0 else high
            where = int(np.argmax(a.reshape(-1) == bad)) // max(columns, 1)
            raise OutOfRangeError(f"{name}: row {where} holds {bad}, outside 0..{_LIMITS[dtype]}")
    if a.size and kind == "f" and a.dtype != np.float32:
        finite = a[np.isfinite(a)]
        if finite.size and float(np.abs(finite).max()) > _FLOAT32_MAX:
            raise OutOfRangeError(f"{name}: {float(np.abs(finite).max())!r} is beyond the range of float32")
    return np.ascontiguousarray(a, dtype=dtype)


# The attribute arrays: (element type, values per element).
ATTRIBUTE_ARRAYS: Dict[str, Tuple[type, int]] = {
    "colors": (np.uint8, 4),
    "normals": (np.float32, 3),
    "texcoords": (np.float32, 2),
    "quality": (np.float32, 1),
    "corner_texcoords": (np.float32, 6),
    "corner_normals": (np.float32, 9),
    "face_colors": (np.uint8, 4),
    "face_quality": (np.float32, 1),
    "face_material": (np.uint32, 1),
    "face_texture": (np.uint32, 1),
}


def _text(value: str, name: str) -> str:
    """value, if it is text a file can hold: UTF-8, no NUL."""
    try:
        value.encode("utf-8")
    except UnicodeEncodeError:
        raise InvalidInputError(f"{name} is not valid Unicode text (it holds a lone surrogate)") from None
    if "\0" in value:
        raise InvalidInputError(f"{name} holds a NUL character")
    return value


def _names(value: Any, name: str) -> list:
    if isinstance(value, (str, bytes)) or not hasattr(value, "__iter__"):
        raise InvalidTypeError(f"{name} must be a list of str, not {type(value).__name__}")
    names = list(value)
    for i, n in enumerate(names):
        if not isinstance(n, str):
            raise InvalidTypeError(f"{name}[{i}] must be a str, not {type(n).__name__}")
        _text(n, f"{name}[{i}]")
    return names


def _metadata(value: Any) -> list:
    if isinstance(value, Mapping):
        value = list(value.items())
    if isinstance(value, (str, bytes)) or not hasattr(value, "__iter__"):
        raise InvalidTypeError(f"metadata must be a list of (name, text) pairs, not {type(value).__name__}")
    pairs = []
    for i, pair in enumerate(value):
        if not isinstance(pair, (tuple, list)) or len(pair) != 2 or not all(isinstance(x, str) for x in pair):
            raise InvalidTypeError(f"metadata[{i}] must be a (name, text) pair of str")
        pairs.append((_text(pair[0], f"metadata[{i}] name"), _text(pair[1], f"metadata[{i}] text")))
    return pairs


def mesh_arrays(vertices: Any, faces: Any, attributes: Optional[Mapping[str, Any]]) -> Tuple[np.ndarray, np.ndarray, dict]:
    """The checked arrays of a mesh, as the extension takes them."""
    v = _array(vertices, "vertices", np.float32, 3)
    f = _array(faces, "faces", np.uint32, 3)
    checked: Dict[str, Any] = {}
    if attributes is None:
        attributes = {}
    if not isinstance(attributes, Mapping):
        raise InvalidTypeError(f"attributes must be a dict of arrays, not {type(attributes).__name__}")
    for key, value in attributes.items():
        if not isinstance(key, str):
            raise InvalidTypeError(f"attribute names are str, not {type(key).__name__}")
        if key in ATTRIBUTE_ARRAYS:
            dtype, columns = ATTRIBUTE_ARRAYS[key]
            checked[key] = _array(value, key, dtype, columns)
        elif key in ("materials", "textures"):
            checked[key] = _names(value, key)
        elif key == "metadata":
            checked[key] = _metadata(value)
        else:
            known = ", ".join(list(ATTRIBUTE_ARRAYS) + ["materials", "textures", "metadata"])
            raise InvalidInputError(f"unknown attribute array '{key}' (known: {known})")
    return v, f, checked


def _int(value: Any, name: str, low: int, high: int) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise InvalidTypeError(f"{name} must be an int, not {type(value).__name__}")
    value = int(value)
    if value < low or value > high:
        raise OutOfRangeError(f"{name} must be between {low} and {high}, not {value}")
    return value


def bool_option(value: Any, name: str) -> bool:
    return _bool(value, name)


def _bool(value: Any, name: str) -> bool:
    if not isinstance(value, (bool, np.bool_)):
        raise InvalidTypeError(f"{name} must be True or False, not {type(value).__name__}")
    return bool(value)


def _str(value: Any, name: str) -> str:
    if not isinstance(value, str):
        raise InvalidTypeError(f"{name} must be a str, not {type(value).__name__}")
    return _text(value, name)


_INT32_MAX = 2**31 - 1
# Each option's check. Ranges that the codec itself knows (bits, refine
# bits, normal and texture coordinate bits) are left to it beyond what an
# int holds, so that its messages, the same as the `drm` tool's, explain them.
OPTION_CHECKS: Dict[str, Callable[[Any, str], Any]] = {
    "bits": lambda v, n: _int(v, n, -_INT32_MAX, _INT32_MAX),
    "predictor": _str,
    "geometry": _str,
    "connectivity": _str,
    "levers": _str,
    "curvature": _bool,
    "refine_bits": lambda v, n: _int(v, n, -_INT32_MAX, _INT32_MAX),
    "keep_vertex_order": _bool,
    "verify": _bool,
    "search_starts": _bool,
    "threads": lambda v, n: _int(v, n, 0, 1024),
    "normal_bits": lambda v, n: _int(v, n, -_INT32_MAX, _INT32_MAX),
    "uv_bits": lambda v, n: _int(v, n, -_INT32_MAX, _INT32_MAX),
    "keep": _str,
    "weld": _str,
}


def encode_options(options: Mapping[str, Any]) -> dict:
    """The checked encoding options, as the extension takes them."""
    checked = {}
    for key, value in options.items():
        if key not in OPTION_CHECKS:
            raise InvalidInputError(f"unknown option '{key}' (known: {', '.join(OPTION_CHECKS)})")
        checked[key] = OPTION_CHECKS[key](value, key)
    return checked


def progress_callback(progress: Any) -> Any:
    if progress is not None and not callable(progress):
        raise InvalidTypeError(f"progress must be callable(fraction, stage) or None, not {type(progress).__name__}")
    return progress


def path(value: Any, name: str = "path") -> bytes:
    """A file name as the extension takes it: the bytes os.fsencode gives,
    so that any name the file system holds works, UTF-8 or not."""
    if isinstance(value, bytes) or not isinstance(value, (str, os.PathLike)):
        raise InvalidTypeError(f"{name} must be a str or os.PathLike, not {type(value).__name__}")
    text = os.fspath(value)
    if not isinstance(text, str):
        raise InvalidTypeError(f"{name} must name the file as str, not {type(text).__name__}")
    if "\0" in text:
        raise InvalidInputError(f"{name} holds a NUL character")
    return os.fsencode(text)


def buffer(data: Any, name: str = "data") -> memoryview:
    """Any bytes-like object (bytes, bytearray, memoryview, a numpy array,
    array.array, mmap) as a contiguous view of its bytes."""
    if isinstance(data, str):
        raise InvalidTypeError(f"{name} must be bytes-like, not str (read the file in binary mode, or use drm.load)")
    try:
        view = memoryview(data)
    except TypeError:
        raise InvalidTypeError(f"{name} must be bytes-like, not {type(data).__name__}") from None
    if not view.c_contiguous:
        raise InvalidInputError(f"{name} must be C-contiguous in memory (bytes(data) makes a copy that is)")
    return view


def int_option(value: Any, name: str, low: int, high: int) -> int:
    return _int(value, name, low, high)


def threads(value: Any) -> int:
    return _int(value, "threads", 0, 1024)


__all__ = ["InvalidTypeError", "OutOfRangeError", "mesh_arrays", "encode_options", "progress_callback", "path",
           "buffer", "threads", "int_option", "bool_option", "ATTRIBUTE_ARRAYS"]
