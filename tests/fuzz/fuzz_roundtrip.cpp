// libFuzzer target: encode a mesh built from the input bytes, decode the
// file, and require the decoder to rebuild exactly what the encoder saw.
//
// fuzz_decode.cpp checks that no file breaks the decoder; this checks that
// the decoder reads every file the encoder writes. Encoder and decoder
// replay the same traversal, predictions and adaptive models, so a step
// coded one way and read another (say a multi-bit symbol written, single
// bits read) passes every corrupt-file test and still loses meshes. The
// inputs lean towards the cases that find such drift: coarse quantization
// (many vertices on one grid point), holes, several components, isolated
// vertices, every option.
//
// Coordinates are then often moved to the edges of what a float holds
// (extents past FLT_MAX, FLT_MAX itself, denormals, huge offsets with tiny
// extents, one repeated point) or given a NaN or an infinity. The invariant
// is the encoder's promise: it refuses the mesh with a message naming a
// vertex (only for NaN, infinity or no vertices), or the decoder gives back
// exactly what it coded; a file the decoder refuses is a failure.
//
// The meshes are often not manifold (holes touching at a vertex, stray
// faces over any three indices, faces repeating a vertex, doubled and
// turned-over faces): the encoder must take every one, so an encoder error
// aborts too, as does any outcome that is not a faithful round trip.
#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "drmcodec/drmcodec.h"

namespace {

[[noreturn]] void fail(const std::string& what) {
    std::fprintf(stderr, "round trip failed: %s\n", what.c_str());
    std::abort();
}

drm::EncodeOptions optionsFrom(FuzzedDataProvider& in) {
    drm::EncodeOptions o;
    o.bits = in.ConsumeIntegralInRange(1, 21);
    o.predictor = in.PickValueInArray({drm::Predictor::Auto, drm::Predictor::Parallelogram, drm::Predictor::Midpoint});
    o.curvature = in.ConsumeBool();
    o.geometry = in.PickValueInArray({drm::GeometryCoder::SpanningTree, drm::GeometryCoder::Raw, drm::GeometryCoder::Refine});
    if (o.geometry == drm::GeometryCoder::Refine) o.refineBits = in.ConsumeIntegralInRange(0, std::min(3, o.bits - 1));
    o.keepVertexOrder = in.ConsumeBool();
    o.levers = {in.ConsumeBool(), in.ConsumeBool(), in.ConsumeBool(), in.ConsumeBool(), in.ConsumeBool(), in.ConsumeBool()};
    o.tryWithoutLevers = in.ConsumeBool();
    o.connectivityParts = in.ConsumeBool() ? 2 : 0;  // two parts, forced on these small meshes
    // The topological coder alone codes its positions (no vertex
    // coder); Auto tries it where no option of the ranks' alone is set.
    o.connectivity = in.PickValueInArray({drm::ConnectivityCoder::Ranks, drm::ConnectivityCoder::Topological, drm::ConnectivityCoder::Auto});
    if (o.connectivity != drm::ConnectivityCoder::Ranks && in.ConsumeBool()) {
        o.geometry = drm::GeometryCoder::Auto;
        o.predictor = drm::Predictor::Auto;
        o.curvature = false;
        o.levers = drm::Levers();
        o.connectivityParts = 0;
    }
    if (o.connectivity == drm::ConnectivityCoder::Topological) o.geometry = drm::GeometryCoder::Auto;
    return o;
}

// A grid patch (cells left out make holes), lifted by small integer
// heights, optionally with tetrahedra and isolated vertices added and the
// vertices shuffled. scale spreads or squeezes it so that quantization
// merges many vertices or none.
drm::Mesh meshFrom(FuzzedDataProvider& in) {
    drm::Mesh m;
    const int w = in.ConsumeIntegralInRange(1, 10), h = in.ConsumeIntegralInRange(1, 10);
    const float scale = float(1 << in.ConsumeIntegralInRange(0, 12)) / 64.0f;
    for (int j = 0; j <= h; ++j)
        for (int i = 0; i <= w; ++i) {
            const float z = float(in.ConsumeIntegralInRange(-3, 3));
            m.positions.insert(m.positions.end(), {float(i) * scale, float(j) * scale, z * scale / 2});
        }
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const uint8_t cell = in.remaining_bytes() > 0 ? in.ConsumeIntegral<uint8_t>() : 1;
            if (cell % 8 == 0) continue;  // a hole
            const uint32_t a = uint32_t(j * (w + 1) + i), b = a + 1, c = a + uint32_t(w + 1), d = c + 1;
            if (cell & 0x80) m.triangles.insert(m.triangles.end(), {a, b, d, a, d, c});
            else m.triangles.insert(m.triangles.end(), {a, b, c, b, d, c});
        }
    const int tetrahedra = in.ConsumeIntegralInRange(0, 3);
    for (int t = 0; t < tetrahedra; ++t) {
        const uint32_t base = uint32_t(m.vertexCount());
        const float x = float(in.ConsumeIntegralInRange(-20, 20)) * scale, y = float(in.ConsumeIntegralInRange(-20, 20)) * scale;
        const float size = float(in.ConsumeIntegralInRange(0, 4)) * scale;  // 0: all four on one point
        m.positions.insert(m.positions.end(), {x, y, 5, x + size, y, 5, x, y + size, 5, x, y, 5 + size});
        for (uint32_t f : {0u, 2u, 1u, 0u, 1u, 3u, 0u, 3u, 2u, 1u, 2u, 3u}) m.triangles.push_back(base + f);
    }
    // Stray faces over any vertices (fins, bowties, faces repeating a
    // vertex), doubled faces, and faces turned over.
    const int stray = in.ConsumeIntegralInRange(0, 4);
    for (int f = 0; f < stray && m.vertexCount() > 0; ++f)
        for (int k = 0; k < 3; ++k)
            m.triangles.push_back(in.ConsumeIntegralInRange<uint32_t>(0, uint32_t(m.vertexCount() - 1)));
    const int doubled = in.ConsumeIntegralInRange(0, 2);
    for (int f = 0; f < doubled && !m.triangles.empty(); ++f) {
        const size_t g = in.ConsumeIntegralInRange<size_t>(0, m.faceCount() - 1);
        const std::array<uint32_t, 3> t = {m.triangles[3 * g], m.triangles[3 * g + 1], m.triangles[3 * g + 2]};
        m.triangles.insert(m.triangles.end(), t.begin(), t.end());
    }
    const int turned = in.ConsumeIntegralInRange(0, 3);
    for (int f = 0; f < turned && !m.triangles.empty(); ++f) {
        const size_t g = in.ConsumeIntegralInRange<size_t>(0, m.faceCount() - 1);
        std::swap(m.triangles[3 * g + 1], m.triangles[3 * g + 2]);
    }
    const int isolated = in.ConsumeIntegralInRange(0, 4);
    for (int v = 0; v < isolated; ++v)
        m.positions.insert(m.positions.end(), {float(in.ConsumeIntegralInRange(-8, 8)) * scale, 0.5f * scale, -1});
    if (in.ConsumeBool()) {
        // Shuffle the vertices: the raw coder and the tree's roots follow input order.
        std::vector<uint32_t> newIndex(m.vertexCount());
        for (uint32_t v = 0; v < newIndex.size(); ++v) newIndex[v] = v;
        for (size_t v = newIndex.size(); v > 1; --v)
            std::swap(newIndex[v - 1], newIndex[in.ConsumeIntegralInRange<size_t>(0, v - 1)]);
        std::vector<float> moved(m.positions.size());
        for (size_t v = 0; v < newIndex.size(); ++v)
            for (int k = 0; k < 3; ++k) moved[3 * size_t(newIndex[v]) + size_t(k)] = m.positions[3 * v + size_t(k)];
        m.positions.swap(moved);
        for (uint32_t& index : m.triangles) index = newIndex[index];
    }
    return m;
}

// Moves the coordinates to the edges of float range, or spoils one. Returns
// true if the mesh now holds a NaN or an infinity (the encoder must refuse).
bool moveToFloatEdges(FuzzedDataProvider& in, drm::Mesh& m) {
    if (m.positions.empty()) return false;
    const int how = in.ConsumeIntegralInRange(0, 7);
    const float big = std::numeric_limits<float>::max();
    float lo = 0, hi = 0;
    for (float x : m.positions) {
        lo = std::min(lo, x);
        hi = std::max(hi, x);
    }
    const float span = hi > lo ? hi - lo : 1.0f;
    for (float& x : m.positions) {
        const float t = (x - lo) / span;  // 0 .. 1
        switch (how) {
            case 1: x = float(-double(big) + 2.0 * double(t) * double(big)); break;  // extent 2 * FLT_MAX (in double: 2.0f * big is inf)
            case 2: x = t * big; break;                              // up to FLT_MAX itself
            case 3: x = t * 64.0f * std::numeric_limits<float>::denorm_min(); break;  // denormals, many equal
            case 4: x = 1e30f + t * 1e24f; break;                   // huge offset, tiny extent (many equal floats)
            case 5: x = 4e37f * (t - 0.5f); break;
            case 6: x = 7.0f; break;                                 // one repeated point
            default: break;                                          // 0, 7: as built
        }
    }
    if (in.ConsumeIntegralInRange(0, 15) == 0) {
        const size_t i = in.ConsumeIntegralInRange<size_t>(0, m.positions.size() - 1);
        m.positions[i] = in.ConsumeBool() ? std::numeric_limits<float>::quiet_NaN()
                                          : (in.ConsumeBool() ? 1.0f : -1.0f) * std::numeric_limits<float>::infinity();
        return true;
    }
    return false;
}

// Gives the mesh some of the attributes a file can carry, values drawn from
// the input (often repeated, so that wedges and seams appear), and perhaps a
// vertex per corner (welding). Returns true if it added any.
bool addAttributes(FuzzedDataProvider& in, drm::Mesh& m, drm::EncodeOptions& o) {
    const uint32_t which = in.ConsumeIntegral<uint16_t>() & 0x3FF;
    if (which == 0 || m.positions.empty()) return false;
    const size_t V = m.vertexCount(), F = m.faceCount();
    auto small = [&]() { return float(in.ConsumeIntegralInRange(-4, 4)) * 0.25f; };
    if (which & 1)
        for (size_t i = 0; i < 4 * V; ++i) m.colors.push_back(uint8_t(in.ConsumeIntegralInRange(0, 3) * 85));
    if (which & 2)
        for (size_t i = 0; i < 3 * V; ++i) m.normals.push_back(small());
    if (which & 4)
        for (size_t i = 0; i < 2 * V; ++i) m.texCoords.push_back(small());
    if (which & 8)
        for (size_t i = 0; i < V; ++i) m.quality.push_back(small());
    if (which & 16)
        for (size_t i = 0; i < 6 * F; ++i) m.cornerTexCoords.push_back(small());
    if (which & 32)
        for (size_t i = 0; i < 9 * F; ++i) m.cornerNormals.push_back(small());
    if (which & 64)
        for (size_t i = 0; i < 4 * F; ++i) m.faceColors.push_back(uint8_t(in.ConsumeIntegralInRange(0, 2) * 127));
    if (which & 128)
        for (size_t i = 0; i < F; ++i) m.faceQuality.push_back(small());
    if (which & 256) {
        for (size_t i = 0; i < F; ++i) m.faceMaterial.push_back(in.ConsumeIntegralInRange<uint32_t>(0, 2));
        m.materials = {"a", "b", "c"};
        m.metadata = {{"obj.mtl", "newmtl a\nnewmtl b\n"}};
    }
    if (which & 512) m.textures = {"t.png"};
    o.normalBits = in.ConsumeIntegralInRange(4, 16);
    o.uvBits = in.ConsumeIntegralInRange(1, 24);
    o.weld = in.PickValueInArray({drm::EncodeOptions::Weld::Auto, drm::EncodeOptions::Weld::Off, drm::EncodeOptions::Weld::On});
    o.verify = true;  // the encoder decodes its file and compares every corner
    return true;
}

// Oriented triangles, each rotated to start at its smallest index, sorted.
std::vector<std::array<uint32_t, 3>> canonicalFaces(const std::vector<uint32_t>& triangles,
                                                    const std::vector<uint32_t>& renumber) {
    std::vector<std::array<uint32_t, 3>> faces;
    for (size_t f = 0; f + 2 < triangles.size(); f += 3) {
        std::array<uint32_t, 3> t = {renumber[triangles[f]], renumber[triangles[f + 1]], renumber[triangles[f + 2]]};
        std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
        faces.push_back(t);
    }
    std::sort(faces.begin(), faces.end());
    return faces;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    FuzzedDataProvider in(data, size);
    drm::EncodeOptions options = optionsFrom(in);
    drm::EncodeOptions withAttributes = options;
    drm::Mesh mesh = meshFrom(in);
    const bool spoiled = moveToFloatEdges(in, mesh);
    if (addAttributes(in, mesh, withAttributes)) {
        // With attributes the encoder checks itself (verify); welding may
        // change the vertex list, so no further comparison here.
        try {
            drm::encode(mesh, withAttributes);
        } catch (const drm::Error& e) {
            // A spoiled mesh must be refused as InvalidInput, naming the
            // non-finite value: the text says which invalid input it was.
            const std::string message = e.what();
            if (spoiled && e.kind() == drm::ErrorKind::InvalidInput && message.find("non-finite") != std::string::npos)
                return 0;
            fail("the encoder refuses a mesh with attributes: " + message);
        }
        if (spoiled) fail("the encoder took a mesh with a NaN or infinite coordinate");
        return 0;
    }
    drm::Encoded encoded;
    try {
        encoded = drm::encode(mesh, options);
    } catch (const drm::Error& e) {
        const std::string message = e.what();
        if (mesh.vertexCount() == 0) return 0;  // the one mesh no file holds
        if (spoiled && e.kind() == drm::ErrorKind::InvalidInput && message.find("vertex ") != std::string::npos &&
            message.find("non-finite") != std::string::npos)
            return 0;  // NaN or infinity, named (the text tells which invalid input)
        fail("the encoder refuses the mesh: " + message);
    }
    if (spoiled) fail("the encoder took a mesh with a NaN or infinite coordinate");
    drm::Decoded decoded;
    try {
        decoded = drm::decode(encoded.bytes);
    } catch (const drm::Error& e) {
        fail(std::string("the decoder refuses the encoder's file: ") + e.what());
    }
    const size_t vertices = mesh.vertexCount();
    if (decoded.mesh.vertexCount() != vertices || decoded.quantized.size() != 3 * vertices)
        fail("vertex count " + std::to_string(decoded.mesh.vertexCount()) + ", input " + std::to_string(vertices));
    if (encoded.vertexOrder.size() != vertices) fail("Encoded::vertexOrder is not a full permutation");
    // Decoded vertex d is input vertex vertexOrder[d] (identity when the file
    // keeps the input order) and must sit on that vertex's grid point.
    std::vector<uint32_t> decodedIndex(vertices);
    for (size_t d = 0; d < vertices; ++d) {
        const uint32_t v = encoded.vertexOrder[d];
        if (v >= vertices) fail("Encoded::vertexOrder holds " + std::to_string(v));
        decodedIndex[v] = uint32_t(d);
        for (int k = 0; k < 3; ++k)
            if (decoded.quantized[3 * d + size_t(k)] != encoded.quantized[3 * size_t(v) + size_t(k)])
                fail("decoded vertex " + std::to_string(d) + " is not on input vertex " + std::to_string(v) +
                     "'s grid point");
    }
    std::vector<uint32_t> identity(vertices);
    for (uint32_t v = 0; v < vertices; ++v) identity[v] = v;
    if (canonicalFaces(mesh.triangles, decodedIndex) != canonicalFaces(decoded.mesh.triangles, identity))
        fail("the decoded faces are not the input's oriented faces");
    return 0;
}
