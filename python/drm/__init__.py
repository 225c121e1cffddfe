"""drm: distance-ranked connectivity compression of triangle meshes.

Encode numpy arrays to .drm bytes and back, inspect a file's header, and
read and write mesh files (.drm, PLY, OBJ, OFF and STL) through the readers
and writers of the `drm` command line. docs/library.md has the whole API.

    import drm
    mesh = drm.load("bunny.ply")
    drm.save("bunny.drm", mesh)                # the bytes `drm encode` writes
    vertices, faces = drm.decode(open("bunny.drm", "rb").read())

Arguments are checked, never cast: faces must be integers in 0..2**32-1,
colours integers in 0..255, options of their documented types. A refusal
is a drm.Error that is also the built-in exception Python programs expect:
InvalidTypeError is a TypeError, OutOfRangeError an OverflowError,
InvalidInputError, CorruptError and UnsupportedError ValueErrors, IoError
an OSError, CancelledError and InternalError RuntimeErrors.

Encoding and decoding take progress=callable(fraction, stage) (also
save() to .drm, load() of a .drm file and encode_file()): it is called now
and then with the fraction done (0..1, never falling) and a stage name, and
an answer that is false but not None (False, 0) cancels the call
(CancelledError). Ctrl+C cancels too. Reading and writing PLY, OBJ, OFF and
STL report no progress. The codec runs without the GIL, so threads encode
or decode in parallel.
"""
from __future__ import annotations

import dataclasses
import os
from typing import Any, Callable, Dict, List, Optional, Tuple, Union

import numpy as np

from . import _checks, _drm

__version__: str = _drm.__version__
FORMAT_VERSION: int = _drm.FORMAT_VERSION
MIN_BITS: int = _drm.MIN_BITS
MAX_BITS: int = _drm.MAX_BITS
DEFAULT_BITS: int = _drm.DEFAULT_BITS

Error = _drm.Error
InvalidInputError = _drm.InvalidInputError
CorruptError = _drm.CorruptError
UnsupportedError = _drm.UnsupportedError
CancelledError = _drm.CancelledError
IoError = _drm.IoError
InternalError = _drm.InternalError
InvalidTypeError = _checks.InvalidTypeError
OutOfRangeError = _checks.OutOfRangeError

Progress = Optional[Callable[[float, str], Optional[bool]]]
PathLike = Union[str, os.PathLike]


@dataclasses.dataclass
class Mesh:
    """A triangle mesh as drm reads and writes it.

    vertices: (n, 3) float32. faces: (m, 3) uint32, counter-clockwise.
    attributes: the optional arrays by name (colors (n, 4) uint8, normals
    (n, 3), texcoords (n, 2), quality (n,), corner_texcoords (m, 6),
    corner_normals (m, 9), face_colors (m, 4) uint8, face_quality (m,),
    face_material (m,) uint32, face_texture (m,) uint32) and the name lists
    materials, textures and metadata ((name, text) pairs).
    notes: what the reader changed or could not keep, as sentences.
    stats: for a mesh decoded from .drm, the keys of `drm info --json`.
    """

    vertices: np.ndarray
    faces: np.ndarray
    attributes: Dict[str, Any] = dataclasses.field(default_factory=dict)
    notes: List[str] = dataclasses.field(default_factory=list)
    stats: Optional[Dict[str, Any]] = None
    face_rank: Optional[np.ndarray] = None


def encode(vertices: Any, faces: Any, bits: int = DEFAULT_BITS, *, attributes: Optional[Dict[str, Any]] = None,
           progress: Progress = None, **options: Any) -> bytes:
    """The .drm file of a mesh: vertices (n, 3) numbers, faces (m, 3)
    integers. options: predictor, geometry, connectivity ('auto', 'ranks',
    'topological'), levers, curvature, refine_bits, keep_vertex_order,
    verify, normal_bits, uv_bits, weld ('auto', 'on', 'off'),
    search_starts, threads (never changes the bytes), keep (attribute list,
    as `drm encode --attributes`)."""
    return encode_full(vertices, faces, bits, attributes=attributes, progress=progress, **options)["data"]


def encode_full(vertices: Any, faces: Any, bits: int = DEFAULT_BITS, *, attributes: Optional[Dict[str, Any]] = None,
                progress: Progress = None, **options: Any) -> Dict[str, Any]:
    """Like encode(), returning a dict: data (bytes), vertex_order (the input
    vertex of each decoded vertex), quantized (grid coordinates, input
    order), face_rank (the rank code of each input face), face_order (the
    input face of each decoded face) and face_rotation (the corner of that
    input face the decoded face starts at), stats."""
    v, f, a = _checks.mesh_arrays(vertices, faces, attributes)
    checked = _checks.encode_options(dict(options, bits=bits))
    return _drm.encode(v, f, a, checked, _checks.progress_callback(progress))


def decode(data: Any, *, attributes: bool = False, threads: int = 0,
           progress: Progress = None) -> Union[Tuple[np.ndarray, np.ndarray], Tuple[np.ndarray, np.ndarray, dict]]:
    """(vertices, faces) of a .drm file given as any bytes-like object;
    with attributes=True, (vertices, faces, attribute dict)."""
    d = decode_full(data, threads=threads, progress=progress)
    if _checks.bool_option(attributes, "attributes"):
        return d["vertices"], d["faces"], d["attributes"]
    return d["vertices"], d["faces"]


def decode_full(data: Any, *, threads: int = 0, progress: Progress = None) -> Dict[str, Any]:
    """A dict: vertices, faces, attributes, quantized (grid coordinates),
    face_rank (the rank code that made each face), grid (origin, step,
    bits), stats."""
    view = _checks.buffer(data)
    return _drm.decode(view, _checks.threads(threads), _checks.progress_callback(progress))


def info(data: Any, *, ranks: bool = False) -> Dict[str, Any]:
    """What the file's header and section table say (the keys of `drm info
    --json`, and format_version), read without decoding; boundary_edges,
    welded_vertices and rank_histogram are None unless ranks=True, which
    decodes the file to count them."""
    view = _checks.buffer(data)
    header = _drm.info(view)
    if not _checks.bool_option(ranks, "ranks"):
        return header
    stats = decode_full(view)["stats"]
    stats["format_version"] = header["format_version"]
    return stats


def max_normal_error(normal_bits: int = 10) -> float:
    """The largest angle, in radians, between a unit normal and its decoded
    value at the given normal bits."""
    return _drm.max_normal_error(_checks.int_option(normal_bits, "normal_bits", _drm.MIN_NORMAL_BITS, _drm.MAX_NORMAL_BITS))


def load(path: PathLike, *, progress: Progress = None) -> Mesh:
    """The mesh of a .drm, PLY, OBJ, OFF or STL file (by extension), read as
    `drm encode` and `drm decode` read it: vertices and faces in file order,
    polygons fanned into triangles, an OBJ's material library only from its
    own folder or below."""
    d = _drm.load(_checks.path(path), _checks.progress_callback(progress))
    return Mesh(d["vertices"], d["faces"], d["attributes"], list(d["notes"]), d["stats"], d.get("face_rank"))


def save(path: PathLike, mesh: Mesh, *, progress: Progress = None, **options: Any) -> List[str]:
    """Writes a mesh to a .drm (encoding options as encode()'s), binary PLY or
    OBJ file (with its .mtl beside it), chosen by the extension. The file
    appears complete or not at all; an existing file is replaced only on
    success. Returns what the format cannot hold, as sentences. Saving a
    loaded mesh to .drm with no options writes the bytes `drm encode`
    writes."""
    if not isinstance(mesh, Mesh):
        raise InvalidTypeError(f"mesh must be a drm.Mesh, not {type(mesh).__name__} (drm.Mesh(vertices, faces))")
    v, f, a = _checks.mesh_arrays(mesh.vertices, mesh.faces, mesh.attributes)
    checked = _checks.encode_options(options)
    result = _drm.save(_checks.path(path), v, f, a, checked, _checks.progress_callback(progress))
    return list(result["notes"])


def encode_file(input: PathLike, output: PathLike, *, progress: Progress = None, **options: Any) -> Dict[str, Any]:
    """What `drm encode INPUT OUTPUT` does, with the same defaults and the same
    bytes: reads a PLY, OBJ, OFF or STL file, encodes it, writes OUTPUT
    atomically, never over INPUT. Returns {"notes": [...], "stats": {...}}."""
    source = _checks.path(input, "input")
    target = _checks.path(output, "output")
    return _drm.encode_file(source, target, _checks.encode_options(options), _checks.progress_callback(progress))


__all__ = [
    "Mesh", "encode", "encode_full", "decode", "decode_full", "info", "load", "save", "encode_file", "max_normal_error",
    "Error", "InvalidInputError", "InvalidTypeError", "OutOfRangeError", "CorruptError", "UnsupportedError",
    "CancelledError", "IoError", "InternalError",
    "FORMAT_VERSION", "MIN_BITS", "MAX_BITS", "DEFAULT_BITS", "__version__",
]
