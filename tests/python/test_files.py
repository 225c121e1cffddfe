"""drm.load and drm.save: the readers and writers of the `drm` command line,
so the files are the tool's, byte for byte, and a mesh's attributes come back
within their stated tolerances. Run over the meshes with attributes beside
the clone (../shared/meshes-attributes, DRM_ATTRIBUTE_MESHES) and tests/data."""
import glob
import math
import os
import subprocess

import numpy as np
import pytest

import drm

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.environ.get("DRM_TEST_DATA", os.path.join(HERE, "..", "data"))
ATTRIBUTE_MESHES = os.environ.get("DRM_ATTRIBUTE_MESHES",
                                  os.path.join(HERE, "..", "..", "..", "shared", "meshes-attributes"))
DRM_TOOL = os.environ.get("DRM_TOOL", "drm")

MESHES = sorted(glob.glob(os.path.join(ATTRIBUTE_MESHES, "*.ply")) + glob.glob(os.path.join(ATTRIBUTE_MESHES, "*.obj")))


def tool(*args):
    subprocess.run([DRM_TOOL, *args], check=True, stdout=subprocess.DEVNULL)


def read(path):
    with open(path, "rb") as f:
        return f.read()


def test_the_attribute_meshes_are_there():
    assert len(MESHES) >= 8, f"no meshes with attributes in {ATTRIBUTE_MESHES}"


@pytest.mark.parametrize("path", MESHES, ids=os.path.basename)
def test_save_to_drm_writes_the_bytes_drm_encode_writes(path, tmp_path):
    mesh = drm.load(path)
    drm.save(tmp_path / "python.drm", mesh)
    tool("encode", path, str(tmp_path / "tool.drm"))
    assert read(tmp_path / "python.drm") == read(tmp_path / "tool.drm")
    assert drm.encode_file(path, str(tmp_path / "file.drm"))["stats"]["total_bytes"] == len(read(tmp_path / "tool.drm"))
    assert read(tmp_path / "file.drm") == read(tmp_path / "tool.drm")


@pytest.mark.parametrize("path", MESHES, ids=os.path.basename)
def test_attributes_come_back_within_their_tolerance(path, tmp_path):
    mesh = drm.load(path)
    assert mesh.attributes, f"{path} loads with no attributes"
    drm.save(tmp_path / "m.drm", mesh)
    back = drm.load(tmp_path / "m.drm")
    # The encoder's correspondence: decoded vertex i is input vertex
    # vertex_order[i]; decoded face j is input face face_order[j], starting
    # at its corner face_rotation[j].
    e = drm.encode_full(mesh.vertices, mesh.faces, attributes=mesh.attributes)
    assert e["data"] == read(tmp_path / "m.drm")
    vo, fo, rot = e["vertex_order"], e["face_order"], e["face_rotation"]
    assert len(back.vertices) == len(vo) and len(back.faces) == len(fo) == len(mesh.faces)
    corner = (np.arange(3)[None, :] + rot[:, None]) % 3  # input corner of each decoded corner
    input_corners = mesh.faces[fo[:, None], corner]
    # The same oriented triangles over the same grid points (a welded mesh's
    # corners may name another input vertex at the same point).
    q = e["quantized"]
    np.testing.assert_array_equal(q[vo[back.faces]], q[input_corners])

    step = drm.decode_full(read(tmp_path / "m.drm"))["grid"]["step"]
    assert np.abs(back.vertices - mesh.vertices[vo]).max() <= 0.5001 * step

    a, b = mesh.attributes, back.attributes
    assert set(b) == set(a), (sorted(a), sorted(b))
    for name in ("colors", "quality"):
        if name in a:
            np.testing.assert_array_equal(b[name], a[name][vo])
    for name in ("face_colors", "face_quality", "face_material", "face_texture"):
        if name in a and name in b:
            np.testing.assert_array_equal(b[name], a[name][fo])
    for name in ("materials", "textures", "metadata"):
        if name in a:
            assert list(b[name]) == list(a[name])
    tolerance = drm.max_normal_error(10)
    if "normals" in a:
        unit = np.linalg.norm(a["normals"][vo], axis=1) > 0.5
        cos = np.sum(b["normals"][unit] * a["normals"][vo][unit], axis=1) / np.linalg.norm(a["normals"][vo][unit], axis=1)
        assert np.arccos(np.clip(cos, -1, 1)).max() <= tolerance + 1e-6
    for name, columns in (("texcoords", 2), ("corner_texcoords", 6)):
        if name in a:
            original = a[name][vo] if name == "texcoords" else \
                a[name].reshape(-1, 3, 2)[fo[:, None], corner].reshape(-1, 6)
            span = max(float(np.ptp(a[name])), 1e-30)
            assert np.abs(b[name] - original).max() <= 0.5001 * span / (2**12 - 1) + 1e-7, name


@pytest.mark.parametrize("path", MESHES, ids=os.path.basename)
def test_save_to_ply_and_obj_writes_what_drm_decode_writes(path, tmp_path):
    tool("encode", path, str(tmp_path / "m.drm"))
    mesh = drm.load(tmp_path / "m.drm")
    (tmp_path / "python").mkdir()
    (tmp_path / "tool").mkdir()
    for extension in (".ply", ".obj"):
        drm.save(tmp_path / "python" / ("m" + extension), mesh)
        tool("decode", str(tmp_path / "m.drm"), str(tmp_path / "tool" / ("m" + extension)))
    written = sorted(os.listdir(tmp_path / "tool"))
    assert sorted(os.listdir(tmp_path / "python")) == written
    for name in written:  # m.ply, m.obj and, for a mesh with materials, m.mtl
        assert read(tmp_path / "python" / name) == read(tmp_path / "tool" / name), name
    again = drm.load(tmp_path / "python" / "m.ply")
    np.testing.assert_array_equal(again.vertices, mesh.vertices)
    np.testing.assert_array_equal(again.faces, mesh.faces)
    for name in ("colors", "quality", "face_colors", "face_quality"):
        if name in mesh.attributes:
            np.testing.assert_array_equal(again.attributes[name], mesh.attributes[name])


@pytest.mark.parametrize("name", ["torus.ply", "fandisk.ply", "genus3.ply"])
def test_off_and_stl_inputs_load_as_the_tool_reads_them(name, tmp_path):
    mesh = drm.load(os.path.join(DATA, name))
    drm.save(tmp_path / "m.drm", mesh)
    tool("decode", str(tmp_path / "m.drm"), str(tmp_path / "m.ply"))
    decoded = drm.load(tmp_path / "m.drm")
    for extension in (".off", ".stl"):
        other = tmp_path / ("m" + extension)
        write_other(other, decoded.vertices, decoded.faces)
        loaded = drm.load(other)
        assert len(loaded.faces) == len(decoded.faces)
        if extension == ".off":
            np.testing.assert_array_equal(loaded.vertices, decoded.vertices)
            np.testing.assert_array_equal(loaded.faces, decoded.faces)
        drm.save(tmp_path / ("from" + extension + ".drm"), loaded)
        tool("encode", str(other), str(tmp_path / ("tool" + extension + ".drm")))
        assert read(tmp_path / ("from" + extension + ".drm")) == read(tmp_path / ("tool" + extension + ".drm"))


def write_other(path, vertices, faces):
    if str(path).endswith(".off"):
        with open(path, "w") as f:
            f.write(f"OFF\n{len(vertices)} {len(faces)} 0\n")
            for v in vertices:
                f.write(" ".join(repr(float(x)) for x in v) + "\n")
            for t in faces:
                f.write("3 " + " ".join(str(int(i)) for i in t) + "\n")
    else:
        with open(path, "w") as f:
            f.write("solid m\n")
            for t in faces:
                f.write(" facet normal 0 0 0\n  outer loop\n")
                for i in t:
                    f.write("   vertex " + " ".join(repr(float(x)) for x in vertices[i]) + "\n")
                f.write("  endloop\n endfacet\n")
            f.write("endsolid m\n")


def test_save_refuses_what_it_cannot_write(tmp_path):
    mesh = drm.load(os.path.join(DATA, "torus.ply"))
    with pytest.raises(drm.InvalidInputError):
        drm.save(tmp_path / "m.xyz", mesh)
    with pytest.raises(drm.InvalidInputError):
        drm.save(tmp_path / "m.ply", mesh, bits=10)  # options are for .drm
    with pytest.raises(drm.InvalidTypeError):
        drm.save(tmp_path / "m.drm", (mesh.vertices, mesh.faces))
    with pytest.raises(drm.IoError) as caught:
        drm.save(tmp_path / "no-such-folder" / "m.drm", mesh)
    assert isinstance(caught.value, OSError)
    assert not (tmp_path / "no-such-folder").exists()


def test_a_failed_save_leaves_the_existing_file(tmp_path):
    mesh = drm.load(os.path.join(DATA, "torus.ply"))
    target = tmp_path / "m.drm"
    target.write_bytes(b"precious")
    bad = drm.Mesh(mesh.vertices, mesh.faces + 10**6)
    with pytest.raises(drm.InvalidInputError):
        drm.save(target, bad)
    assert target.read_bytes() == b"precious"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["m.drm"]


def test_load_refuses_missing_damaged_and_unknown_files(tmp_path):
    with pytest.raises(drm.IoError):
        drm.load(tmp_path / "missing.ply")
    (tmp_path / "bad.drm").write_bytes(b"DRM\0garbage")
    with pytest.raises(drm.CorruptError) as caught:
        drm.load(tmp_path / "bad.drm")
    assert "bad.drm" in str(caught.value)
    (tmp_path / "m.xyz").write_text("1 2 3\n")
    with pytest.raises(drm.InvalidInputError):
        drm.load(tmp_path / "m.xyz")
    with pytest.raises(drm.InvalidTypeError):
        drm.load(b"/tmp/m.ply")


def test_encode_file_never_writes_over_its_input(tmp_path):
    source = tmp_path / "m.ply"
    source.write_bytes(read(os.path.join(DATA, "torus.ply")))
    link = tmp_path / "m.drm"
    os.link(source, link)
    with pytest.raises(drm.Error):
        drm.encode_file(source, link)
    assert read(source) == read(os.path.join(DATA, "torus.ply"))
    assert math.isfinite(drm.encode_file(source, tmp_path / "out.drm")["stats"]["total_bpv"])


def test_file_names_that_are_not_utf8_work(tmp_path):
    name = os.fsdecode(b"m\xff")
    source = tmp_path / (name + ".ply")
    source.write_bytes(read(os.path.join(DATA, "torus.ply")))
    mesh = drm.load(source)
    drm.save(tmp_path / (name + ".drm"), mesh)
    assert len(drm.load(tmp_path / (name + ".drm")).faces) == len(mesh.faces)
    with pytest.raises(drm.IoError) as caught:
        drm.load(tmp_path / (name + "-missing.ply"))
    assert name in str(caught.value)  # the name comes back as os.fsdecode gives it
