// drm._drm, the compiled half of the Python package `drm` (python/drm/):
// encode, decode and inspect .drm data, and read and write mesh files
// through the readers and writers the `drm` tool uses (drm_vcg/mesh_io.h).
//
// The package's Python half checks every argument and hands this module
// arrays of exactly the types the codec holds (float32, uint32, uint8,
// C order); this module takes nothing else, so no value is ever cast,
// wrapped or truncated on the way in. Every drm::Error becomes the
// package's exception class for its kind, with the same message.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <drm_vcg/file_io.h>
#include <drm_vcg/mesh_io.h>
#include <drmcodec/drmcodec.h>

#include <cctype>
#include <cstring>
#include <exception>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace py = pybind11;

namespace {

// The package's exception classes, one per drm::ErrorKind (python/drm/__init__.py
// documents them).
PyObject* gErrorBase = nullptr;
PyObject* gErrorClasses[6] = {};

// ---- arrays in and out -------------------------------------------------

template <class T>
std::vector<T> valuesOf(const py::handle& value, size_t columns, const char* name) {
    const auto a = py::reinterpret_borrow<py::array>(value);
    if (!py::isinstance<py::array_t<T>>(value) || !(a.flags() & py::array::c_style))
        throw drm::Error(drm::ErrorKind::Internal, std::string("internal error: ") + name + " reached the extension unchecked");
    if (a.ndim() != (columns == 1 ? 1 : 2) || (columns != 1 && size_t(a.shape(1)) != columns))
        throw drm::Error(drm::ErrorKind::Internal, std::string("internal error: ") + name + " has the wrong shape");
    const T* data = static_cast<const T*>(a.data());
    return std::vector<T>(data, data + a.size());
}

template <class T>
py::array_t<T> arrayOf(const std::vector<T>& v, size_t columns) {
    const py::ssize_t rows = py::ssize_t(columns ? v.size() / columns : 0);
    py::array_t<T> out = columns == 1 ? py::array_t<T>({rows}) : py::array_t<T>({rows, py::ssize_t(columns)});
    if (!v.empty()) std::memcpy(out.mutable_data(), v.data(), v.size() * sizeof(T));
    return out;
}

// The attribute arrays by name, as docs/library.md lists them.
void setAttributes(drm::Mesh& mesh, const py::dict& attributes) {
    for (auto item : attributes) {
        const std::string name = py::str(item.first);
        const py::handle v = item.second;
        if (name == "colors") mesh.colors = valuesOf<uint8_t>(v, 4, "colors");
        else if (name == "normals") mesh.normals = valuesOf<float>(v, 3, "normals");
        else if (name == "texcoords") mesh.texCoords = valuesOf<float>(v, 2, "texcoords");
        else if (name == "quality") mesh.quality = valuesOf<float>(v, 1, "quality");
        else if (name == "corner_texcoords") mesh.cornerTexCoords = valuesOf<float>(v, 6, "corner_texcoords");
        else if (name == "corner_normals") mesh.cornerNormals = valuesOf<float>(v, 9, "corner_normals");
        else if (name == "face_colors") mesh.faceColors = valuesOf<uint8_t>(v, 4, "face_colors");
        else if (name == "face_quality") mesh.faceQuality = valuesOf<float>(v, 1, "face_quality");
        else if (name == "face_material") mesh.faceMaterial = valuesOf<uint32_t>(v, 1, "face_material");
        else if (name == "face_texture") mesh.faceTexture = valuesOf<uint32_t>(v, 1, "face_texture");
        else if (name == "materials") mesh.materials = v.cast<std::vector<std::string>>();
        else if (name == "textures") mesh.textures = v.cast<std::vector<std::string>>();
        else if (name == "metadata") mesh.metadata = v.cast<std::vector<std::pair<std::string, std::string>>>();
        else throw drm::Error(drm::ErrorKind::InvalidInput, "unknown attribute array '" + name + "'");
    }
}

py::dict attributeArrays(const drm::Mesh& m) {
    py::dict d;
    if (!m.colors.empty()) d["colors"] = arrayOf(m.colors, 4);
    if (!m.normals.empty()) d["normals"] = arrayOf(m.normals, 3);
    if (!m.texCoords.empty()) d["texcoords"] = arrayOf(m.texCoords, 2);
    if (!m.quality.empty()) d["quality"] = arrayOf(m.quality, 1);
    if (!m.cornerTexCoords.empty()) d["corner_texcoords"] = arrayOf(m.cornerTexCoords, 6);
    if (!m.cornerNormals.empty()) d["corner_normals"] = arrayOf(m.cornerNormals, 9);
    if (!m.faceColors.empty()) d["face_colors"] = arrayOf(m.faceColors, 4);
    if (!m.faceQuality.empty()) d["face_quality"] = arrayOf(m.faceQuality, 1);
    if (!m.faceMaterial.empty()) d["face_material"] = arrayOf(m.faceMaterial, 1);
    if (!m.faceTexture.empty()) d["face_texture"] = arrayOf(m.faceTexture, 1);
    if (!m.materials.empty()) d["materials"] = m.materials;
    if (!m.textures.empty()) d["textures"] = m.textures;
    if (!m.metadata.empty()) d["metadata"] = m.metadata;
    return d;
}

drm::Mesh meshOf(const py::handle& vertices, const py::handle& faces, const py::dict& attributes) {
    drm::Mesh mesh;
    mesh.positions = valuesOf<float>(vertices, 3, "vertices");
    mesh.triangles = valuesOf<uint32_t>(faces, 3, "faces");
    setAttributes(mesh, attributes);
    return mesh;
}

py::dict meshDict(const drm::Mesh& m) {
    py::dict d;
    d["vertices"] = arrayOf(m.positions, 3);
    d["faces"] = arrayOf(m.triangles, 3);
    d["attributes"] = attributeArrays(m);
    return d;
}

// ---- statistics --------------------------------------------------------

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

// ---- options and progress ----------------------------------------------

drm::EncodeOptions encodeOptionsOf(const py::dict& options) {
    // Keys and value types are checked by the package (drm/_checks.py).
    drm::EncodeOptions o;
    for (auto item : options) {
        const std::string key = py::str(item.first);
        const py::handle v = item.second;
        if (key == "bits") o.bits = v.cast<int>();
        else if (key == "predictor") o.predictor = drm::parsePredictor(v.cast<std::string>());
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
    return o;
}

// A Python progress callback, called from the codec's threads with the GIL
// taken. It returns False to cancel; an exception it raises, or Ctrl+C,
// also cancels, and the exception is raised again once the codec returns.
class ProgressBridge {
public:
    explicit ProgressBridge(py::object callback) : callback_(std::move(callback)) {}

    drm::Progress progress() {
        return [this](double fraction, const char* stage) {
            py::gil_scoped_acquire gil;
            if (pending_) return false;
            try {
                if (PyErr_CheckSignals() != 0) throw py::error_already_set();
                if (callback_.is_none()) return true;
                const py::object answer = callback_(fraction, stage);
                if (answer.is_none()) return true;
                const int go = PyObject_IsTrue(answer.ptr());  // Python's truth, as `if answer:` takes it
                if (go < 0) throw py::error_already_set();
                return go == 1;
            } catch (py::error_already_set& e) {
                pending_ = std::make_unique<py::error_already_set>(std::move(e));
                return false;
            }
        };
    }

    // Runs the codec's work without the GIL; re-raises what the callback raised.
    template <class Work>
    auto run(Work work) -> decltype(work()) {
        try {
            py::gil_scoped_release release;
            return work();
        } catch (const drm::Error&) {
            if (pending_) throw std::move(*pending_);
            throw;
        }
    }

private:
    py::object callback_;
    std::unique_ptr<py::error_already_set> pending_;
};

// ---- bytes-like input --------------------------------------------------

// Any object with a C-contiguous buffer (bytes, bytearray, memoryview, a
// numpy array, array.array, mmap), read as its raw bytes.
struct BytesView {
    explicit BytesView(const py::handle& data) {
        if (PyObject_GetBuffer(data.ptr(), &view, PyBUF_C_CONTIGUOUS) != 0) throw py::error_already_set();
    }
    ~BytesView() { PyBuffer_Release(&view); }
    BytesView(const BytesView&) = delete;
    BytesView& operator=(const BytesView&) = delete;
    const uint8_t* data() const { return static_cast<const uint8_t*>(view.buf); }
    size_t size() const { return size_t(view.len); }
    Py_buffer view{};
};

py::dict decodedDict(const drm::Decoded& d) {
    py::dict out = meshDict(d.mesh);
    out["quantized"] = arrayOf(d.quantized, 3);
    out["face_rank"] = arrayOf(d.faceRank, 1);
    out["stats"] = statsDict(d.stats, true);
    py::dict grid;
    grid["origin"] = py::make_tuple(d.grid.origin[0], d.grid.origin[1], d.grid.origin[2]);
    grid["step"] = d.grid.step;
    grid["bits"] = d.grid.bits;
    out["grid"] = grid;
    return out;
}

py::dict encodedDict(const drm::Encoded& e) {
    py::dict d;
    d["data"] = py::bytes(reinterpret_cast<const char*>(e.bytes.data()), e.bytes.size());
    d["vertex_order"] = arrayOf(e.vertexOrder, 1);
    d["quantized"] = arrayOf(e.quantized, 3);
    d["face_rank"] = arrayOf(e.faceRank, 1);
    d["face_order"] = arrayOf(e.faceOrder, 1);
    d["face_rotation"] = arrayOf(e.faceRotation, 1);
    d["stats"] = statsDict(e.stats, true);
    return d;
}

bool endsWithDrm(const std::string& path) {
    if (path.size() < 4) return false;
    std::string tail = path.substr(path.size() - 4);
    for (char& c : tail) c = char(std::tolower(static_cast<unsigned char>(c)));
    return tail == ".drm";
}

// vcglib's OFF and STL readers keep shared state: one file is read at a
// time, whichever thread asks.
std::mutex gReading;

drm::vcgio::LoadedMesh loadMeshFile(const std::string& path) {
    std::lock_guard<std::mutex> lock(gReading);
    return drm::vcgio::loadMesh(path);
}

}  // namespace

PYBIND11_MODULE(_drm, m) {
    m.doc() = "The compiled half of the package drm (docs/library.md): use the package, not this module.";
    m.attr("__version__") = drm::version();
    m.attr("FORMAT_VERSION") = drm::kFileFormatVersion;
    m.attr("MIN_BITS") = drm::kMinQuantizationBits;
    m.attr("MAX_BITS") = drm::kMaxQuantizationBits;
    m.attr("DEFAULT_BITS") = drm::kDefaultQuantizationBits;
    m.attr("MIN_NORMAL_BITS") = drm::kMinNormalBits;
    m.attr("MAX_NORMAL_BITS") = drm::kMaxNormalBits;
    m.attr("MIN_UV_BITS") = drm::kMinUvBits;
    m.attr("MAX_UV_BITS") = drm::kMaxUvBits;

    // drm.Error, and per kind a class that is also the built-in exception a
    // Python program expects for it.
    gErrorBase = PyErr_NewExceptionWithDoc("drm.Error", "Any error drm reports; .kind names which.", nullptr, nullptr);
    PyObject_SetAttrString(gErrorBase, "kind", Py_None);
    m.attr("Error") = py::handle(gErrorBase);
    const struct {
        drm::ErrorKind kind;
        const char* name;
        PyObject* builtin;
        const char* doc;
    } kinds[] = {
        {drm::ErrorKind::InvalidInput, "InvalidInputError", PyExc_ValueError, "The mesh, options or names cannot be coded as given."},
        {drm::ErrorKind::Corrupt, "CorruptError", PyExc_ValueError, "The data is not a well-formed .drm file."},
        {drm::ErrorKind::Unsupported, "UnsupportedError", PyExc_ValueError, "A .drm file of a version or coder this library does not read."},
        {drm::ErrorKind::Cancelled, "CancelledError", PyExc_RuntimeError, "The progress callback asked to stop."},
        {drm::ErrorKind::Io, "IoError", PyExc_OSError, "A file could not be read or written."},
        {drm::ErrorKind::Internal, "InternalError", PyExc_RuntimeError, "A bug: the codec's own check failed."},
    };
    for (const auto& k : kinds) {
        py::tuple bases = py::make_tuple(py::handle(gErrorBase), py::handle(k.builtin));
        PyObject* cls = PyErr_NewExceptionWithDoc(("drm." + std::string(k.name)).c_str(), k.doc, bases.ptr(), nullptr);
        PyObject_SetAttrString(cls, "kind", py::str(drm::errorKindName(k.kind)).ptr());
        gErrorClasses[int(k.kind)] = cls;
        m.attr(k.name) = py::handle(cls);
    }
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const drm::Error& e) {
            // A message may quote a file name that is not UTF-8: its bytes
            // come back as Python's os.fsdecode would give them.
            const std::string message = e.what();
            PyObject* text = PyUnicode_DecodeUTF8(message.data(), py::ssize_t(message.size()), "surrogateescape");
            if (!text) return;
            PyErr_SetObject(gErrorClasses[int(e.kind())], text);
            Py_DECREF(text);
        }
    });

    m.def("max_normal_error", &drm::maxNormalError, py::arg("normal_bits"));
    m.def(
        "encode",
        [](const py::handle& vertices, const py::handle& faces, const py::dict& attributes, const py::dict& options,
           const py::object& progress) {
            const drm::Mesh mesh = meshOf(vertices, faces, attributes);
            drm::EncodeOptions o = encodeOptionsOf(options);
            ProgressBridge bridge(progress);
            o.progress = bridge.progress();
            return encodedDict(bridge.run([&] { return drm::encode(mesh, o); }));
        },
        py::arg("vertices"), py::arg("faces"), py::arg("attributes"), py::arg("options"), py::arg("progress"));
    m.def(
        "decode",
        [](const py::handle& data, int threads, const py::object& progress) {
            const BytesView bytes(data);
            drm::DecodeOptions o;
            o.threads = threads;
            ProgressBridge bridge(progress);
            o.progress = bridge.progress();
            return decodedDict(bridge.run([&] { return drm::decode(bytes.data(), bytes.size(), o); }));
        },
        py::arg("data"), py::arg("threads"), py::arg("progress"));
    m.def(
        "info",
        [](const py::handle& data) {
            const BytesView bytes(data);
            const drm::FileInfo info = drm::inspect(bytes.data(), bytes.size());
            py::dict d = statsDict(info.stats, false);
            d["format_version"] = info.formatVersion;
            return d;
        },
        py::arg("data"));
    m.def(
        "load",
        [](const py::bytes& pathBytes, const py::object& progress) {
            const std::string path = pathBytes;
            py::dict out;
            if (endsWithDrm(path)) {
                std::vector<uint8_t> bytes;
                {
                    py::gil_scoped_release release;
                    bytes = drm::vcgio::readFileBytes(path);
                }
                drm::DecodeOptions o;
                ProgressBridge bridge(progress);
                o.progress = bridge.progress();
                try {
                    out = decodedDict(bridge.run([&] { return drm::decode(bytes, o.progress); }));
                } catch (const drm::Error& e) {
                    throw drm::Error(e.kind(), "cannot decode " + path + ": " + e.what());
                }
                out["notes"] = py::list();
                return out;
            }
            drm::vcgio::LoadedMesh loaded;
            {
                py::gil_scoped_release release;
                loaded = loadMeshFile(path);
            }
            out = meshDict(loaded.mesh);
            out["notes"] = loaded.notes;
            out["stats"] = py::none();
            return out;
        },
        py::arg("path"), py::arg("progress"));
    m.def(
        "save",
        [](const py::bytes& pathBytes, const py::handle& vertices, const py::handle& faces, const py::dict& attributes,
           const py::dict& options, const py::object& progress) {
            const std::string path = pathBytes;
            const drm::Mesh mesh = meshOf(vertices, faces, attributes);
            py::dict out;
            if (endsWithDrm(path)) {
                drm::EncodeOptions o = encodeOptionsOf(options);
                ProgressBridge bridge(progress);
                o.progress = bridge.progress();
                drm::Encoded encoded;
                try {
                    encoded = bridge.run([&] { return drm::encode(mesh, o); });
                } catch (const drm::Error& e) {
                    throw drm::Error(e.kind(), "cannot encode " + path + ": " + e.what());
                }
                {
                    py::gil_scoped_release release;
                    drm::vcgio::writeFileAtomically(path, encoded.bytes);
                }
                out["notes"] = py::list();
                out["stats"] = statsDict(encoded.stats, true);
                return out;
            }
            if (options.size() != 0)
                throw drm::Error(drm::ErrorKind::InvalidInput, "encoding options apply to .drm files only, not to " + path);
            std::vector<std::string> notes;
            {
                py::gil_scoped_release release;
                notes = drm::vcgio::saveMesh(path, mesh);
            }
            out["notes"] = notes;
            out["stats"] = py::none();
            return out;
        },
        py::arg("path"), py::arg("vertices"), py::arg("faces"), py::arg("attributes"), py::arg("options"),
        py::arg("progress"));
    m.def(
        "encode_file",
        [](const py::bytes& inputBytes, const py::bytes& outputBytes, const py::dict& options, const py::object& progress) {
            const std::string input = inputBytes, output = outputBytes;
            // What `drm encode INPUT OUTPUT` does (tools/cmd_encode.cpp),
            // with the same defaults: the same file, byte for byte.
            drm::EncodeOptions o = encodeOptionsOf(options);
            ProgressBridge bridge(progress);
            o.progress = bridge.progress();
            drm::vcgio::LoadedMesh loaded;
            {
                py::gil_scoped_release release;
                drm::vcgio::refuseOverwritingInput(input, output);
                loaded = loadMeshFile(input);
                for (const std::string& read : loaded.otherFilesRead) drm::vcgio::refuseOverwritingInput(read, output);
            }
            drm::Encoded encoded;
            try {
                encoded = bridge.run([&] { return drm::encode(loaded.mesh, o); });
            } catch (const drm::Error& e) {
                throw drm::Error(e.kind(), "cannot encode " + input + ": " + e.what());
            }
            {
                py::gil_scoped_release release;
                drm::vcgio::writeFileAtomically(output, encoded.bytes);
            }
            py::dict out;
            out["notes"] = loaded.notes;
            out["stats"] = statsDict(encoded.stats, true);
            return out;
        },
        py::arg("input"), py::arg("output"), py::arg("options"), py::arg("progress"));
}
