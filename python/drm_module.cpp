// The Python module `drm`: encode, decode and inspect .drm data with numpy
// arrays (docs/library.md, "Python"). A thin layer over <drm/drm.h>: every
// drm::Error becomes drm.Error's subclass for its kind, with the same
// message.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstring>
#include <string>
#include <vector>

#include "drm/drm.h"

namespace py = pybind11;

namespace {

using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;
using UIntArray = py::array_t<uint32_t, py::array::c_style | py::array::forcecast>;
using ByteArray = py::array_t<uint8_t, py::array::c_style | py::array::forcecast>;

// Python's exception classes, one per drm::ErrorKind, all under drm.Error.
PyObject* gErrorClasses[6] = {};

template <class T>
std::vector<T> flat(const py::array_t<T, py::array::c_style | py::array::forcecast>& a, size_t columns,
                    const char* what) {
    if (a.ndim() == 0 || (a.ndim() > 2) || (a.ndim() == 2 && size_t(a.shape(1)) != columns) ||
        (a.ndim() == 1 && columns != 1 && a.size() % py::ssize_t(columns) != 0))
        throw drm::Error(drm::ErrorKind::InvalidInput, std::string(what) + " must be an array of shape (n, " +
                                                           std::to_string(columns) + ")");
    return std::vector<T>(a.data(), a.data() + a.size());
}

template <class T>
py::array_t<T> shaped(const std::vector<T>& v, size_t columns) {
    const py::ssize_t rows = py::ssize_t(columns ? v.size() / columns : 0);
    py::array_t<T> out = columns == 1 ? py::array_t<T>({rows}) : py::array_t<T>({rows, py::ssize_t(columns)});
    if (!v.empty()) std::memcpy(out.mutable_data(), v.data(), v.size() * sizeof(T));
    return out;
}

py::dict statsDict(const drm::Stats& s, bool decoded) {
    // The keys of `drm info --json` (tools/cmd_info.cpp).
    py::dict d;
    auto perVertex = [&s](uint64_t bytes) { return s.vertices ? 8.0 * double(bytes) / double(s.vertices) : 0.0; };
    d["vertices"] = s.vertices;
    d["faces"] = s.faces;
    d["components"] = s.components;
    d["boundary_edges"] = decoded ? py::object(py::int_(s.boundaryEdges)) : py::object(py::none());
    d["bits"] = s.bits;
    d["predictor"] = drm::predictorName(s.predictor);
    d["curvature"] = s.curvature;
    d["connectivity"] = drm::connectivityCoderName(s.connectivity);
    d["geometry"] = s.connectivity == drm::ConnectivityCoder::Topological ? "walk" : drm::geometryCoderName(s.geometry);
    d["refine_bits"] = s.refineBits;
    d["vertex_numbering"] = s.mortonNumbering ? "morton" : "geometry";
    py::dict levers;
    levers["topological_filter"] = s.levers.topologicalFilter;
    levers["gap_closing"] = s.levers.gapClosing;
    levers["confidence_context"] = s.levers.confidenceContext;
    levers["angle_order"] = s.levers.angleOrder;
    levers["front_neighbours"] = s.levers.frontNeighbours;
    levers["boundary_flag"] = s.levers.boundaryFlag;
    d["levers"] = levers;
    d["header_bytes"] = s.headerBytes;
    d["connectivity_bytes"] = s.connectivityBytes;
    d["geometry_bytes"] = s.geometryBytes;
    d["vertex_order_bytes"] = s.vertexOrderBytes;
    d["attribute_bytes"] = s.attributeBytes;
    d["welded_vertices"] = decoded ? py::object(py::int_(s.weldedVertices)) : py::object(py::none());
    py::list sections;
    for (const drm::Stats::AttributeSize& a : s.attributeSizes) {
        py::dict section;
        section["name"] = a.name;
        section["bytes"] = a.bytes;
        section["bpv"] = perVertex(a.bytes);
        sections.append(section);
    }
    d["attributes"] = sections;
    d["total_bytes"] = s.totalBytes;
    d["connectivity_bpv"] = s.connectivityBitsPerVertex();
    d["geometry_bpv"] = s.geometryBitsPerVertex();
    d["attribute_bpv"] = perVertex(s.attributeBytes);
    d["total_bpv"] = s.totalBitsPerVertex();
    if (decoded) {
        py::dict histogram;
        for (size_t r = 0; r < s.rankHistogram.size(); ++r)
            if (s.rankHistogram[r]) histogram[py::str(std::to_string(r))] = s.rankHistogram[r];
        d["rank_histogram"] = histogram;
    } else {
        d["rank_histogram"] = py::none();
    }
    return d;
}

const uint8_t* bytesOf(const py::bytes& data, size_t* size) {
    char* buffer = nullptr;
    py::ssize_t length = 0;
    if (PyBytes_AsStringAndSize(data.ptr(), &buffer, &length) != 0) throw py::error_already_set();
    *size = size_t(length);
    return reinterpret_cast<const uint8_t*>(buffer);
}

// The mesh's optional arrays by name (docs/library.md lists them).
struct AttributeArray {
    const char* name;
    size_t columns;
    bool perFace;
};
const AttributeArray kAttributeArrays[] = {
    {"colors", 4, false},         {"normals", 3, false},         {"texcoords", 2, false},
    {"quality", 1, false},        {"corner_texcoords", 6, true}, {"corner_normals", 9, true},
    {"face_colors", 4, true},     {"face_quality", 1, true},     {"face_material", 1, true},
    {"face_texture", 1, true},
};

void setAttributes(drm::Mesh& mesh, const py::dict& attributes) {
    for (auto item : attributes) {
        const std::string name = py::str(item.first);
        const py::handle value = item.second;
        if (name == "materials") mesh.materials = value.cast<std::vector<std::string>>();
        else if (name == "textures") mesh.textures = value.cast<std::vector<std::string>>();
        else if (name == "colors") mesh.colors = flat(value.cast<ByteArray>(), 4, "colors");
        else if (name == "face_colors") mesh.faceColors = flat(value.cast<ByteArray>(), 4, "face_colors");
        else if (name == "normals") mesh.normals = flat(value.cast<FloatArray>(), 3, "normals");
        else if (name == "texcoords") mesh.texCoords = flat(value.cast<FloatArray>(), 2, "texcoords");
        else if (name == "quality") mesh.quality = flat(value.cast<FloatArray>(), 1, "quality");
        else if (name == "corner_texcoords") mesh.cornerTexCoords = flat(value.cast<FloatArray>(), 6, "corner_texcoords");
        else if (name == "corner_normals") mesh.cornerNormals = flat(value.cast<FloatArray>(), 9, "corner_normals");
        else if (name == "face_quality") mesh.faceQuality = flat(value.cast<FloatArray>(), 1, "face_quality");
        else if (name == "face_material") mesh.faceMaterial = flat(value.cast<UIntArray>(), 1, "face_material");
        else if (name == "face_texture") mesh.faceTexture = flat(value.cast<UIntArray>(), 1, "face_texture");
        else throw drm::Error(drm::ErrorKind::InvalidInput, "unknown attribute array '" + name + "'");
    }
}

py::dict attributeArrays(const drm::Mesh& m) {
    py::dict d;
    if (!m.colors.empty()) d["colors"] = shaped(m.colors, 4);
    if (!m.normals.empty()) d["normals"] = shaped(m.normals, 3);
    if (!m.texCoords.empty()) d["texcoords"] = shaped(m.texCoords, 2);
    if (!m.quality.empty()) d["quality"] = shaped(m.quality, 1);
    if (!m.cornerTexCoords.empty()) d["corner_texcoords"] = shaped(m.cornerTexCoords, 6);
    if (!m.cornerNormals.empty()) d["corner_normals"] = shaped(m.cornerNormals, 9);
    if (!m.faceColors.empty()) d["face_colors"] = shaped(m.faceColors, 4);
    if (!m.faceQuality.empty()) d["face_quality"] = shaped(m.faceQuality, 1);
    if (!m.faceMaterial.empty()) d["face_material"] = shaped(m.faceMaterial, 1);
    if (!m.faceTexture.empty()) d["face_texture"] = shaped(m.faceTexture, 1);
    if (!m.materials.empty()) d["materials"] = m.materials;
    if (!m.textures.empty()) d["textures"] = m.textures;
    return d;
}

drm::Encoded encodeArrays(const FloatArray& vertices, const UIntArray& faces, int bits, const py::kwargs& options) {
    drm::Mesh mesh;
    mesh.positions = flat(vertices, 3, "vertices");
    mesh.triangles = flat(faces, 3, "faces");
    drm::EncodeOptions o;
    o.bits = bits;
    for (auto item : options) {
        const std::string key = py::str(item.first);
        const py::handle v = item.second;
        if (key == "predictor") o.predictor = drm::parsePredictor(v.cast<std::string>());
        else if (key == "geometry") o.geometry = drm::parseGeometryCoder(v.cast<std::string>());
        else if (key == "connectivity") o.connectivity = drm::parseConnectivityCoder(v.cast<std::string>());
        else if (key == "levers") o.levers = drm::parseLevers(v.cast<std::string>()), o.tryWithoutLevers = false;
        else if (key == "curvature") o.curvature = v.cast<bool>();
        else if (key == "refine_bits") o.refineBits = v.cast<int>();
        else if (key == "keep_vertex_order") o.keepVertexOrder = v.cast<bool>();
        else if (key == "verify") o.verify = v.cast<bool>();
        else if (key == "search_starts") o.searchStarts = v.cast<bool>();
        else if (key == "threads") o.threads = v.cast<int>();
        else if (key == "normal_bits") o.normalBits = v.cast<int>();
        else if (key == "uv_bits") o.uvBits = v.cast<int>();
        else if (key == "keep") o.attributes = drm::parseAttributes(v.cast<std::string>());
        else if (key == "attributes") setAttributes(mesh, v.cast<py::dict>());
        else if (key == "weld") {
            const std::string w = v.cast<std::string>();
            if (w == "auto") o.weld = drm::EncodeOptions::Weld::Auto;
            else if (w == "off") o.weld = drm::EncodeOptions::Weld::Off;
            else if (w == "on") o.weld = drm::EncodeOptions::Weld::On;
            else throw drm::Error(drm::ErrorKind::InvalidInput, "unknown weld '" + w + "' (use auto, on or off)");
        } else {
            throw drm::Error(drm::ErrorKind::InvalidInput, "unknown option '" + key + "'");
        }
    }
    py::gil_scoped_release release;
    return drm::encode(mesh, o);
}

drm::Decoded decodeBytes(const py::bytes& data) {
    size_t size = 0;
    const uint8_t* p = bytesOf(data, &size);
    py::gil_scoped_release release;  // the bytes object stays alive: the caller holds it
    return drm::decode(p, size);
}

}  // namespace

PYBIND11_MODULE(drm, m) {
    m.doc() = "Distance-ranked connectivity compression of triangle meshes (.drm): docs/library.md";
    m.attr("__version__") = drm::version();
    m.attr("FORMAT_VERSION") = drm::kFileFormatVersion;
    m.attr("MIN_BITS") = drm::kMinQuantizationBits;
    m.attr("MAX_BITS") = drm::kMaxQuantizationBits;
    m.attr("DEFAULT_BITS") = drm::kDefaultQuantizationBits;

    PyObject* base = PyErr_NewExceptionWithDoc("drm.Error", "Any error the codec reports; .kind names which.",
                                               nullptr, nullptr);
    m.attr("Error") = py::handle(base);
    const struct {
        drm::ErrorKind kind;
        const char* name;
    } kinds[] = {{drm::ErrorKind::InvalidInput, "InvalidInputError"}, {drm::ErrorKind::Corrupt, "CorruptError"},
                 {drm::ErrorKind::Unsupported, "UnsupportedError"},   {drm::ErrorKind::Cancelled, "CancelledError"},
                 {drm::ErrorKind::Io, "IoError"},                     {drm::ErrorKind::Internal, "InternalError"}};
    for (const auto& k : kinds) {
        PyObject* cls = PyErr_NewException(("drm." + std::string(k.name)).c_str(), base, nullptr);
        PyObject_SetAttrString(cls, "kind", py::str(drm::errorKindName(k.kind)).ptr());
        gErrorClasses[int(k.kind)] = cls;
        m.attr(k.name) = py::handle(cls);
    }
    PyObject_SetAttrString(base, "kind", Py_None);
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const drm::Error& e) {
            PyErr_SetString(gErrorClasses[int(e.kind())], e.what());
        }
    });

    m.def(
        "encode",
        [](const FloatArray& vertices, const UIntArray& faces, int bits, const py::kwargs& options) {
            const drm::Encoded e = encodeArrays(vertices, faces, bits, options);
            return py::bytes(reinterpret_cast<const char*>(e.bytes.data()), e.bytes.size());
        },
        py::arg("vertices"), py::arg("faces"), py::arg("bits") = drm::kDefaultQuantizationBits,
        "encode(vertices (n, 3) float, faces (m, 3) uint32, bits=12, **options) -> bytes\n"
        "options: predictor, geometry, connectivity ('auto', 'ranks', 'topological'), levers, curvature,\n"
        "refine_bits, keep_vertex_order, verify,\n"
        "normal_bits, uv_bits, weld ('auto', 'on', 'off'), search_starts, threads (0, the default: a second\n"
        "thread where the machine has several cores; 1: one; never changes the bytes), keep (attribute list),\n"
        "attributes (dict of arrays).");
    m.def(
        "encode_full",
        [](const FloatArray& vertices, const UIntArray& faces, int bits, const py::kwargs& options) {
            const drm::Encoded e = encodeArrays(vertices, faces, bits, options);
            py::dict d;
            d["data"] = py::bytes(reinterpret_cast<const char*>(e.bytes.data()), e.bytes.size());
            d["vertex_order"] = shaped(e.vertexOrder, 1);
            d["quantized"] = shaped(e.quantized, 3);
            d["face_rank"] = shaped(e.faceRank, 1);
            d["stats"] = statsDict(e.stats, true);
            return d;
        },
        py::arg("vertices"), py::arg("faces"), py::arg("bits") = drm::kDefaultQuantizationBits,
        "Like encode(), returning a dict: data (bytes), vertex_order (input vertex of each decoded vertex),\n"
        "quantized (grid coordinates, input order), face_rank, stats (the keys of `drm info --json`).");
    m.def(
        "decode",
        [](const py::bytes& data, bool attributes) -> py::object {
            const drm::Decoded d = decodeBytes(data);
            py::tuple mesh = py::make_tuple(shaped(d.mesh.positions, 3), shaped(d.mesh.triangles, 3));
            if (!attributes) return std::move(mesh);
            return py::make_tuple(mesh[0], mesh[1], attributeArrays(d.mesh));
        },
        py::arg("data"), py::kw_only(), py::arg("attributes") = false,
        "decode(data) -> (vertices (n, 3) float32, faces (m, 3) uint32);\n"
        "decode(data, attributes=True) -> (vertices, faces, dict of the attribute arrays the file keeps).");
    m.def(
        "decode_full",
        [](const py::bytes& data) {
            const drm::Decoded d = decodeBytes(data);
            py::dict out;
            out["vertices"] = shaped(d.mesh.positions, 3);
            out["faces"] = shaped(d.mesh.triangles, 3);
            out["quantized"] = shaped(d.quantized, 3);
            out["face_rank"] = shaped(d.faceRank, 1);
            out["attributes"] = attributeArrays(d.mesh);
            out["stats"] = statsDict(d.stats, true);
            return out;
        },
        py::arg("data"), "Decodes, returning a dict: vertices, faces, quantized, face_rank, attributes, stats.");
    m.def(
        "info",
        [](const py::bytes& data, bool ranks) {
            size_t size = 0;
            const uint8_t* p = bytesOf(data, &size);
            const drm::FileInfo info = drm::inspect(p, size);
            py::dict d;
            if (ranks) {
                d = statsDict(decodeBytes(data).stats, true);
            } else {
                d = statsDict(info.stats, false);
            }
            d["format_version"] = info.formatVersion;
            return d;
        },
        py::arg("data"), py::kw_only(), py::arg("ranks") = false,
        "info(data) -> dict with the keys of `drm info --json` (and format_version), read from the header\n"
        "without decoding; boundary_edges, welded_vertices and rank_histogram are None unless ranks=True.");
}
