"""The package refuses what it cannot take exactly: each refusal is a drm.Error
and the built-in exception a Python program expects (TypeError,
OverflowError, ValueError), and no value is cast, wrapped or truncated.
Also: any bytes-like input, and progress with cancel."""
import array
import os
import threading

import numpy as np
import pytest

import drm

DATA = os.environ.get("DRM_TEST_DATA", os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data"))


@pytest.fixture(scope="module")
def torus():
    return drm.load(os.path.join(DATA, "torus.ply"))


def tetrahedron():
    vertices = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float32)
    faces = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]], dtype=np.uint32)
    return vertices, faces


# One of each attribute kind, for the tetrahedron (4 vertices, 4 faces).
ATTRIBUTE_KINDS = {
    "none": {},
    "colors": {"colors": np.full((4, 4), 200, np.uint8)},
    "normals": {"normals": np.tile(np.array([0, 0, 1], np.float32), (4, 1))},
    "texcoords": {"texcoords": np.full((4, 2), 0.25, np.float32)},
    "quality": {"quality": np.full(4, 1.5, np.float32)},
    "corner_texcoords": {"corner_texcoords": np.full((4, 6), 0.5, np.float32)},
    "corner_normals": {"corner_normals": np.tile(np.array([1, 0, 0] * 3, np.float32), (4, 1))},
    "face_colors": {"face_colors": np.full((4, 4), 9, np.uint8)},
    "face_quality": {"face_quality": np.full(4, 2.0, np.float32)},
    "materials": {"face_material": np.zeros(4, np.uint32), "materials": ["stone"]},
    "textures": {"face_texture": np.zeros(4, np.uint32), "textures": ["stone.png"]},
}


@pytest.mark.parametrize("kind", sorted(ATTRIBUTE_KINDS))
@pytest.mark.parametrize("bad", [4, 10**9, 2**32 - 2, 2**32 - 1])
@pytest.mark.parametrize("weld", ["auto", "on", "off"])
def test_an_index_out_of_range_is_refused_naming_the_face(kind, bad, weld):
    vertices, faces = tetrahedron()
    faces = faces.copy()
    faces[3, 1] = bad
    with pytest.raises(drm.InvalidInputError) as caught:
        drm.encode(vertices, faces, attributes=ATTRIBUTE_KINDS[kind], weld=weld)
    assert isinstance(caught.value, ValueError)
    assert "face 3" in str(caught.value) and f"refers to vertex {bad}" in str(caught.value)


@pytest.mark.parametrize("bad", [2**32, 2**40, -1, 2**64, -2**70])
def test_an_index_beyond_uint32_is_refused_not_wrapped(bad):
    vertices, faces = tetrahedron()
    faces = faces.tolist()  # Python ints: numpy keeps those beyond 64 bits as objects
    faces[1][2] = bad
    with pytest.raises(drm.OutOfRangeError) as caught:
        drm.encode(vertices, faces)
    assert isinstance(caught.value, OverflowError) and isinstance(caught.value, drm.Error)
    assert "row 1" in str(caught.value) and str(bad) in str(caught.value)


def test_python_lists_are_taken_when_exact_and_refused_otherwise():
    vertices, faces = tetrahedron()
    data = drm.encode(vertices.tolist(), faces.tolist())
    assert data == drm.encode(vertices, faces)
    with pytest.raises(drm.InvalidTypeError):
        drm.encode(vertices.tolist(), [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3.0]])
    with pytest.raises(drm.InvalidInputError):
        drm.encode(vertices.tolist(), [[0, 2, 1], [0, 1]])  # ragged


def test_float_faces_are_refused_not_truncated():
    vertices, faces = tetrahedron()
    with pytest.raises(drm.InvalidTypeError) as caught:
        drm.encode(vertices, faces + 0.7)
    assert isinstance(caught.value, TypeError) and "integers" in str(caught.value)


def test_colours_must_be_integers_in_0_255():
    vertices, faces = tetrahedron()
    with pytest.raises(drm.InvalidTypeError):
        drm.encode(vertices, faces, attributes={"colors": np.full((4, 4), 0.5)})
    with pytest.raises(drm.OutOfRangeError) as caught:
        drm.encode(vertices, faces, attributes={"colors": np.full((4, 4), 300)})
    assert "300" in str(caught.value)
    with pytest.raises(drm.OutOfRangeError):
        drm.encode(vertices, faces, attributes={"face_colors": np.full((4, 4), -1)})
    assert drm.encode(vertices, faces, attributes={"colors": np.full((4, 4), 255, np.int64)})


def test_wrong_shapes_and_unknown_names_are_value_errors():
    vertices, faces = tetrahedron()
    for bad in (lambda: drm.encode(vertices[:, :2], faces),
                lambda: drm.encode(vertices, faces, attributes={"colors": np.zeros((4, 3), np.uint8)}),
                lambda: drm.encode(vertices, faces, attributes={"colours": np.zeros((4, 4), np.uint8)}),
                lambda: drm.encode(vertices, faces, attributes={"colors": np.zeros((3, 4), np.uint8)}),
                lambda: drm.encode(vertices, faces, no_such_option=1),
                lambda: drm.encode(vertices, faces, predictor="sideways"),
                lambda: drm.encode(vertices, faces, weld="sometimes"),
                lambda: drm.encode(vertices, faces, bits=drm.MAX_BITS + 1)):
        with pytest.raises(drm.InvalidInputError) as caught:
            bad()
        assert isinstance(caught.value, ValueError)


@pytest.mark.parametrize("option,value", [("predictor", 3), ("bits", 12.0), ("bits", True), ("curvature", 1),
                                          ("threads", "2"), ("levers", ["all"]), ("keep", None)])
def test_options_of_the_wrong_type_are_type_errors(option, value):
    vertices, faces = tetrahedron()
    kwargs = {option: value}
    with pytest.raises(drm.InvalidTypeError) as caught:
        if option == "bits":
            drm.encode(vertices, faces, value)
        else:
            drm.encode(vertices, faces, **kwargs)
    assert isinstance(caught.value, TypeError) and option in str(caught.value)


def test_numbers_beyond_their_type_are_overflow_errors():
    vertices, faces = tetrahedron()
    with pytest.raises(OverflowError):
        drm.encode(vertices, faces, 2**70)
    with pytest.raises(OverflowError):
        drm.encode(vertices.astype(np.float64) * 1e300, faces)  # beyond float32
    with pytest.raises(OverflowError):
        drm.encode(vertices, faces, threads=-1)


def test_names_must_be_strings():
    vertices, faces = tetrahedron()
    with pytest.raises(drm.InvalidTypeError):
        drm.encode(vertices, faces, attributes={"face_material": np.zeros(4, np.uint32), "materials": [1]})
    with pytest.raises(drm.InvalidTypeError):
        drm.encode(vertices, faces, attributes={"materials": "stone"})


def test_decode_takes_any_bytes_like_object(torus):
    data = drm.encode(torus.vertices, torus.faces)
    expected = drm.decode(data)
    for view in (bytearray(data), memoryview(data), np.frombuffer(data, np.uint8), array.array("B", data),
                 memoryview(b"xx" + data)[2:]):
        vertices, faces = drm.decode(view)
        np.testing.assert_array_equal(vertices, expected[0])
        np.testing.assert_array_equal(faces, expected[1])
    assert drm.info(bytearray(data))["vertices"] == len(torus.vertices)


def test_decode_refuses_what_is_not_bytes():
    for bad in ("not bytes", 12, None, [1, 2, 3]):
        with pytest.raises(drm.InvalidTypeError) as caught:
            drm.decode(bad)
        assert isinstance(caught.value, TypeError)
    with pytest.raises(drm.InvalidInputError):
        drm.decode(np.zeros((4, 4), np.uint8)[:, ::2])  # not contiguous


def test_progress_rises_to_one_and_false_cancels(torus):
    seen = []
    drm.encode(torus.vertices, torus.faces, progress=lambda fraction, stage: seen.append((fraction, stage)))
    fractions = [f for f, _ in seen]
    assert fractions and fractions == sorted(fractions) and fractions[-1] == 1.0
    assert all(isinstance(s, str) and s for _, s in seen)
    with pytest.raises(drm.CancelledError) as caught:
        drm.encode(torus.vertices, torus.faces, progress=lambda fraction, stage: fraction < 0.3)
    assert isinstance(caught.value, RuntimeError)
    data = drm.encode(torus.vertices, torus.faces)
    with pytest.raises(drm.CancelledError):
        drm.decode(data, progress=lambda fraction, stage: False)


def test_an_exception_in_the_progress_callback_comes_back(torus):
    class Stop(Exception):
        pass

    def stop(fraction, stage):
        raise Stop(stage)

    with pytest.raises(Stop):
        drm.encode(torus.vertices, torus.faces, progress=stop)
    with pytest.raises(drm.InvalidTypeError):
        drm.encode(torus.vertices, torus.faces, progress="not callable")


def test_threads_encode_at_once_and_agree(torus):
    expected = drm.encode(torus.vertices, torus.faces)
    results = [None] * 4

    def work(i):
        results[i] = drm.encode(torus.vertices, torus.faces, progress=lambda f, s: True)

    threads = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert results == [expected] * 4


def test_text_that_is_not_unicode_is_refused():
    vertices, faces = tetrahedron()
    with pytest.raises(drm.InvalidInputError) as caught:
        drm.encode(vertices, faces, predictor="\udc80")
    assert isinstance(caught.value, ValueError)
    with pytest.raises(drm.InvalidInputError):
        drm.encode(vertices, faces, attributes={"face_material": np.zeros(4, np.uint32), "materials": ["a\udc80"]})
    with pytest.raises(drm.InvalidInputError):
        drm.encode(vertices, faces, attributes={"metadata": [("obj.mtllib", "x\0y")]})


def test_a_material_the_mesh_does_not_name_is_refused_naming_the_face():
    vertices, faces = tetrahedron()
    with pytest.raises(drm.InvalidInputError) as caught:
        drm.encode(vertices, faces, attributes={"face_material": np.array([0, 0, 0, 7], np.uint32), "materials": ["a"]})
    assert "face 3 uses material 7" in str(caught.value)


def test_the_progress_answer_is_taken_as_python_takes_truth(torus):
    with pytest.raises(drm.CancelledError):
        drm.encode(torus.vertices, torus.faces, progress=lambda f, s: 0)
    assert drm.encode(torus.vertices, torus.faces, progress=lambda f, s: np.bool_(True))

    class Unsure:
        def __bool__(self):
            raise ZeroDivisionError("no answer")

    with pytest.raises(ZeroDivisionError):
        drm.encode(torus.vertices, torus.faces, progress=lambda f, s: Unsure())
