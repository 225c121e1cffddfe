// The decoder's core (decode/decoder.h), stage by stage through files that
// need each: the ranks and the topological coder, every geometry coder,
// the vertex order kept, a manifold cut undone, two connectivity parts,
// attributes. Each file decodes to the input's oriented triangles over the
// input's grid points (through the encoder's vertex order), with the
// encoder's ranks face by face and its figures; the file's parts are left
// for the caller as readFile finds them; the index and the threads never
// change the answer; and a section replaced by other bytes, checksums
// intact, is refused with an Error, never read out of bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <string>
#include <vector>

#include "container/file_format.h"
#include "decode/decoder.h"
#include "drmcodec/drmcodec.h"
#include "test_meshes.h"
#include "tiny_ply.h"

namespace drm {
namespace {

std::vector<std::array<uint32_t, 3>> orientedFaces(const std::vector<uint32_t>& t) {
    std::vector<std::array<uint32_t, 3>> faces;
    for (size_t f = 0; f + 2 < t.size(); f += 3) {
        std::array<uint32_t, 3> a = {t[f], t[f + 1], t[f + 2]};
        std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
        faces.push_back(a);
    }
    std::sort(faces.begin(), faces.end());
    return faces;
}

struct Case {
    std::string name;
    Mesh mesh;
    EncodeOptions options;
};

std::vector<Case> cases() {
    std::vector<Case> all;
    const Mesh bunny = drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/bunny-lres.ply");
    auto add = [&](const std::string& name, const Mesh& m, void (*set)(EncodeOptions&)) {
        Case c{name, m, EncodeOptions()};
        set(c.options);
        all.push_back(c);
    };
    add("ranks, tree", bunny, [](EncodeOptions& o) {
        o.connectivity = ConnectivityCoder::Ranks;
        o.geometry = GeometryCoder::SpanningTree;
    });
    add("topological", bunny, [](EncodeOptions& o) { o.connectivity = ConnectivityCoder::Topological; });
    add("raw", bunny, [](EncodeOptions& o) {
        o.connectivity = ConnectivityCoder::Ranks;
        o.geometry = GeometryCoder::Raw;
    });
    add("refine", bunny, [](EncodeOptions& o) {
        o.connectivity = ConnectivityCoder::Ranks;
        o.geometry = GeometryCoder::Refine;
        o.refineBits = 2;
    });
    add("sorted", drm_test::mixedMesh(), [](EncodeOptions& o) {
        o.connectivity = ConnectivityCoder::Ranks;
        o.geometry = GeometryCoder::Sorted;
    });
    add("vertex order kept", bunny, [](EncodeOptions& o) { o.keepVertexOrder = true; });
    add("repairs", drm_test::meshNeedingRepairs(), [](EncodeOptions&) {});
    add("two parts", bunny, [](EncodeOptions& o) {
        o.connectivity = ConnectivityCoder::Ranks;
        o.connectivityParts = 2;
    });
    Mesh coloured = drm_test::icosphere(3);
    coloured.colors.assign(4 * coloured.vertexCount(), 0);
    for (size_t i = 0; i < coloured.colors.size(); ++i) coloured.colors[i] = uint8_t(i % 4 == 3 ? 255 : i * 7);
    add("attributes", coloured, [](EncodeOptions&) {});
    return all;
}

TEST(Decoder, EachStageGivesBackTheInput) {
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        const Encoded e = encode(c.mesh, c.options);
        FileParts parts;
        const Decoded d = decodeCore(e.bytes.data(), e.bytes.size(), DecodeOptions(), &parts);
        // The grid points, through the encoder's vertex order.
        ASSERT_EQ(d.quantized.size(), 3 * e.vertexOrder.size());
        for (size_t v = 0; v < e.vertexOrder.size(); ++v)
            for (int k = 0; k < 3; ++k) ASSERT_EQ(d.quantized[3 * v + k], e.quantized[3 * size_t(e.vertexOrder[v]) + k]);
        // The oriented triangles, in input vertex numbers.
        std::vector<uint32_t> faces = d.mesh.triangles;
        for (uint32_t& v : faces) v = e.vertexOrder[v];
        EXPECT_EQ(orientedFaces(faces), orientedFaces(c.mesh.triangles));
        // Ranks face by face, and the figures.
        ASSERT_EQ(d.faceRank.size(), e.faceOrder.size());
        for (size_t f = 0; f < d.faceRank.size(); ++f) ASSERT_EQ(d.faceRank[f], e.faceRank[e.faceOrder[f]]) << f;
        EXPECT_EQ(d.stats.rankHistogram, e.stats.rankHistogram);
        EXPECT_EQ(d.stats.totalBytes, e.bytes.size());
        EXPECT_EQ(d.stats.connectivity, e.stats.connectivity);
        EXPECT_EQ(d.stats.geometry, e.stats.geometry);
        EXPECT_EQ(d.stats.connectivityParts, e.stats.connectivityParts);
        EXPECT_EQ(d.stats.splitVertices, e.stats.splitVertices);
        EXPECT_EQ(d.stats.flippedFaces, e.stats.flippedFaces);
        EXPECT_EQ(d.stats.looseFaces, e.stats.looseFaces);
        EXPECT_EQ(d.mesh.colors.size(), c.mesh.colors.size());
        // The parts, as readFile gives them.
        const FileParts read = readFile(e.bytes.data(), e.bytes.size());
        EXPECT_EQ(parts.formatVersion, read.formatVersion);
        EXPECT_EQ(parts.header.vertexCount, read.header.vertexCount);
        EXPECT_EQ(parts.connectivity, read.connectivity);
        EXPECT_EQ(parts.geometrySize, read.geometrySize);
        EXPECT_EQ(parts.attributes.size(), read.attributes.size());
    }
}

TEST(Decoder, CasesCoverWhatTheyAreNamedFor) {
    // The files above are what their names say, so that each stage runs.
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        const Encoded e = encode(c.mesh, c.options);
        const FileInfo info = inspect(e.bytes);
        if (c.name == "topological") EXPECT_EQ(info.stats.connectivity, ConnectivityCoder::Topological);
        if (c.name == "raw") EXPECT_EQ(info.stats.geometry, GeometryCoder::Raw);
        if (c.name == "vertex order kept") EXPECT_TRUE(info.keepsVertexOrder);
        if (c.name == "repairs") EXPECT_TRUE(info.hasRepairs);
        if (c.name == "two parts") EXPECT_EQ(info.stats.connectivityParts, 2);
        if (c.name == "attributes") EXPECT_FALSE(info.stats.attributeSizes.empty());
    }
}

TEST(Decoder, IndexAndThreadsNeverChangeTheAnswer) {
    const Mesh bunny = drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/bunny-lres.ply");
    EncodeOptions o;
    o.connectivity = ConnectivityCoder::Ranks;
    o.connectivityParts = 2;
    const Encoded e = encode(bunny, o);
    FileParts parts;
    const Decoded reference = decodeCore(e.bytes.data(), e.bytes.size(), DecodeOptions(), &parts);
    for (NeighbourIndex index : {NeighbourIndex::Grid, NeighbourIndex::Flann})
        for (int threads : {1, 2}) {
            DecodeOptions options;
            options.index = index;
            options.threads = threads;
            const Decoded d = decodeCore(e.bytes.data(), e.bytes.size(), options, &parts);
            EXPECT_EQ(d.mesh.triangles, reference.mesh.triangles);
            EXPECT_EQ(d.quantized, reference.quantized);
            EXPECT_EQ(d.faceRank, reference.faceRank);
        }
}

TEST(Decoder, OtherBytesInASectionAreRefused) {
    const Mesh bunny = drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/bunny-lres.ply");
    std::mt19937 rng(16);
    for (ConnectivityCoder coder : {ConnectivityCoder::Ranks, ConnectivityCoder::Topological}) {
        EncodeOptions o;
        o.connectivity = coder;
        const Encoded e = encode(bunny, o);
        const FileParts parts = readFile(e.bytes.data(), e.bytes.size());
        const std::vector<uint8_t> connectivity(parts.connectivity, parts.connectivity + parts.connectivitySize);
        const std::vector<uint8_t> geometry(parts.geometry, parts.geometry + parts.geometrySize);
        int refused = 0;
        for (int trial = 0; trial < 40; ++trial) {
            // Checksums intact: only the decoding can tell.
            std::vector<uint8_t> c = connectivity, g = geometry;
            std::vector<uint8_t>& victim = trial % 2 ? c : g;
            const size_t at = rng() % victim.size();
            if (trial % 4 < 2) victim[at] ^= uint8_t(1 + rng() % 255);
            else victim.resize(at);
            const std::vector<uint8_t> file = writeFile(parts.header, c, g, {}, {}, {}, nullptr);
            try {
                FileParts p;
                decodeCore(file.data(), file.size(), DecodeOptions(), &p);
            } catch (const Error& err) {
                ++refused;
                EXPECT_TRUE(err.kind() == ErrorKind::Corrupt || err.kind() == ErrorKind::Unsupported) << err.what();
            }
        }
        EXPECT_GT(refused, 0) << connectivityCoderName(coder);
    }
    // A header that claims more vertices than the geometry holds.
    EncodeOptions raw;
    raw.geometry = GeometryCoder::Raw;
    raw.connectivity = ConnectivityCoder::Ranks;
    const Encoded e = encode(bunny, raw);
    const FileParts parts = readFile(e.bytes.data(), e.bytes.size());
    FileHeader more = parts.header;
    more.vertexCount += 1;
    const std::vector<uint8_t> file =
        writeFile(more, std::vector<uint8_t>(parts.connectivity, parts.connectivity + parts.connectivitySize),
                  std::vector<uint8_t>(parts.geometry, parts.geometry + parts.geometrySize), {}, {}, {}, nullptr);
    FileParts p;
    EXPECT_THROW(decodeCore(file.data(), file.size(), DecodeOptions(), &p), Error);
}

}  // namespace
}  // namespace drm
