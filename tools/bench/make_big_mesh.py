#!/usr/bin/env python3
"""Makes a big triangle mesh by 1-to-4 midpoint subdivision of a PLY mesh.

Usage: tools/bench/make_big_mesh.py IN.ply OUT.ply [--levels 2]

Each level splits every triangle into four at its edge midpoints (one new
vertex per edge, shared by both faces; orientation kept), so the triangle
count grows 4x per level: igea.ply's 268,686 triangles become 1,074,744 after
one level and 4,298,976 after two. The surface is unchanged (midpoints lie on
the flat triangles), so connectivity gets more regular as it grows: this is a
test of time and memory at scale, not of compression rates.

Reads PLY (ASCII or binary, any scalar vertex properties of which x, y, z are
kept, faces as a list of vertex indices; polygons are fanned into
triangles); writes binary little-endian PLY with float x, y, z and uchar/int
faces. Needs numpy (Debian: python3-numpy). Write the output to a temporary
folder: it is large (about 80 MB for 4.3M triangles) and not for the
repository.
"""
import argparse
import sys

import numpy as np

PLY_TYPES = {
    "char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1",
    "short": "i2", "int16": "i2", "ushort": "u2", "uint16": "u2",
    "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
    "float": "f4", "float32": "f4", "double": "f8", "float64": "f8",
}


def read_ply(path):
    """(vertices float64 (n, 3), triangles int64 (m, 3))."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.find(b"end_header")
    if not data.startswith(b"ply") or end < 0:
        raise ValueError(f"{path}: not a PLY file")
    body_start = data.index(b"\n", end) + 1
    header = data[:end].decode("ascii", "replace").splitlines()
    fmt = None
    elements = []  # [name, count, [(prop, type, list_count_type or None)]]
    for line in header:
        words = line.split()
        if not words:
            continue
        if words[0] == "format":
            fmt = words[1]
        elif words[0] == "element":
            elements.append([words[1], int(words[2]), []])
        elif words[0] == "property":
            if words[1] == "list":
                elements[-1][2].append((words[4], PLY_TYPES[words[3]], PLY_TYPES[words[2]]))
            else:
                elements[-1][2].append((words[2], PLY_TYPES[words[1]], None))
    if fmt not in ("ascii", "binary_little_endian", "binary_big_endian"):
        raise ValueError(f"{path}: unknown PLY format {fmt}")
    vertices = faces = None
    if fmt == "ascii":
        tokens = data[body_start:].split()
        pos = 0
        for name, count, props in elements:
            if name == "vertex":
                width = len(props)
                if any(p[2] for p in props):
                    raise ValueError(f"{path}: list properties on vertices are not supported")
                table = np.array(tokens[pos:pos + width * count], dtype=np.float64).reshape(count, width)
                names = [p[0] for p in props]
                vertices = table[:, [names.index("x"), names.index("y"), names.index("z")]]
                pos += width * count
            elif name == "face":
                polys = []
                for _ in range(count):
                    row = []
                    for prop, _type, list_type in props:
                        if list_type:
                            k = int(tokens[pos])
                            values = [int(t) for t in tokens[pos + 1:pos + 1 + k]]
                            pos += 1 + k
                            if prop in ("vertex_indices", "vertex_index"):
                                row = values
                        else:
                            pos += 1
                    polys.append(row)
                faces = polys
            else:
                if any(p[2] for p in props):
                    raise ValueError(f"{path}: list properties on element {name} are not supported")
                pos += len(props) * count
    else:
        order = "<" if fmt == "binary_little_endian" else ">"
        pos = body_start
        for name, count, props in elements:
            if all(p[2] is None for p in props):
                dtype = np.dtype([(p[0], order + p[1]) for p in props])
                table = np.frombuffer(data, dtype=dtype, count=count, offset=pos)
                pos += dtype.itemsize * count
                if name == "vertex":
                    vertices = np.stack([table["x"], table["y"], table["z"]], axis=1).astype(np.float64)
                continue
            if name != "face":
                raise ValueError(f"{path}: list properties on element {name} are not supported")
            # Fast path: one list property, every face a triangle.
            if len(props) == 1:
                _, index_type, count_type = props[0]
                dtype = np.dtype([("n", order + count_type), ("v", order + index_type, (3,))])
                if pos + dtype.itemsize * count <= len(data):
                    table = np.frombuffer(data, dtype=dtype, count=count, offset=pos)
                    if np.all(table["n"] == 3):
                        faces = table["v"].astype(np.int64)
                        pos += dtype.itemsize * count
                        continue
            polys = []
            for _ in range(count):
                row = []
                for prop, ptype, list_type in props:
                    if list_type:
                        ct = np.dtype(order + list_type)
                        k = int(np.frombuffer(data, dtype=ct, count=1, offset=pos)[0])
                        pos += ct.itemsize
                        it = np.dtype(order + ptype)
                        values = np.frombuffer(data, dtype=it, count=k, offset=pos).tolist()
                        pos += it.itemsize * k
                        if prop in ("vertex_indices", "vertex_index"):
                            row = values
                    else:
                        pos += np.dtype(ptype).itemsize
                polys.append(row)
            faces = polys
    if vertices is None or faces is None:
        raise ValueError(f"{path}: needs vertex and face elements")
    if not isinstance(faces, np.ndarray):
        tris = [(p[0], p[i], p[i + 1]) for p in faces for i in range(1, len(p) - 1)]
        faces = np.array(tris, dtype=np.int64).reshape(-1, 3)
    return vertices, faces


def subdivide(vertices, faces):
    """One level of 1-to-4 midpoint subdivision."""
    n = len(vertices)
    a, b, c = faces[:, 0], faces[:, 1], faces[:, 2]
    edges = np.concatenate([np.stack([a, b], 1), np.stack([b, c], 1), np.stack([c, a], 1)])
    keys = np.minimum(edges[:, 0], edges[:, 1]) * n + np.maximum(edges[:, 0], edges[:, 1])
    unique, inverse = np.unique(keys, return_inverse=True)
    lo, hi = unique // n, unique % n
    midpoints = (vertices[lo] + vertices[hi]) / 2
    m = len(faces)
    mid = n + inverse
    ab, bc, ca = mid[:m], mid[m:2 * m], mid[2 * m:]
    new_faces = np.concatenate([
        np.stack([a, ab, ca], 1),
        np.stack([ab, b, bc], 1),
        np.stack([ca, bc, c], 1),
        np.stack([ab, bc, ca], 1),
    ])
    return np.concatenate([vertices, midpoints]), new_faces


def write_ply(path, vertices, faces):
    with open(path, "wb") as f:
        f.write((f"ply\nformat binary_little_endian 1.0\ncomment made by tools/bench/make_big_mesh.py\n"
                 f"element vertex {len(vertices)}\nproperty float x\nproperty float y\nproperty float z\n"
                 f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n").encode())
        f.write(vertices.astype("<f4").tobytes())
        table = np.empty(len(faces), dtype=np.dtype([("n", "u1"), ("v", "<i4", (3,))]))
        table["n"] = 3
        table["v"] = faces
        f.write(table.tobytes())


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("input")
    parser.add_argument("output")
    parser.add_argument("--levels", type=int, default=2, help="subdivision levels (4x triangles each; default 2)")
    args = parser.parse_args()
    vertices, faces = read_ply(args.input)
    for _ in range(args.levels):
        vertices, faces = subdivide(vertices, faces)
    write_ply(args.output, vertices, faces)
    print(f"{args.output}: {len(vertices)} vertices, {len(faces)} triangles "
          f"({args.levels} levels of 1-to-4 subdivision of {args.input})", file=sys.stderr)


if __name__ == "__main__":
    main()
