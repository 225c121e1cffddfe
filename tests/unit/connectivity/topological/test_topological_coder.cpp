// The topological connectivity coder: every mesh of tests/data
// and the small built meshes come back as the same oriented triangles over
// the same grid points, renumbered in the order the walk met them; broken
// streams are refused with an Error.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>

#include "drmcodec/drmcodec.h"
#include "mesh/manifold_cut.h"
#include "test_meshes.h"
#include "tiny_ply.h"
#include "connectivity/topological/topological_coder.h"

namespace drm {
namespace {

struct Prepared {
    std::vector<int32_t> grid;
    std::vector<uint32_t> triangles;
    std::vector<uint32_t> copyOf;
    size_t originals = 0;
};

// The mesh at 12 bits, cut as the encoder cuts it (copies of a vertex share
// its grid point).
Prepared prepare(const Mesh& mesh) {
    Prepared out;
    const std::vector<int32_t> grid = quantize(mesh.positions, makeGrid(mesh.positions, 12));
    ManifoldCut cut = cutIntoManifold(mesh.triangles, mesh.vertexCount());
    out.grid = grid;
    for (uint32_t original : cut.copyOf) out.grid.insert(out.grid.end(), grid.begin() + 3 * original, grid.begin() + 3 * original + 3);
    out.triangles = std::move(cut.triangles);
    out.copyOf = std::move(cut.copyOf);
    out.originals = mesh.vertexCount();
    return out;
}

TopologicalMesh decodeStreams(const TopologicalStreams& s, const Prepared& in, size_t faces) {
    return decodeTopological(s.connectivity.data(), s.connectivity.size(), s.geometry.data(), s.geometry.size(), in.originals,
                             in.copyOf.size(), faces, 12);
}

using Face = std::array<uint32_t, 3>;
// Each face turned to begin at its smallest vertex, orientation kept.
std::multiset<Face> orientedFaces(const std::vector<uint32_t>& t, const std::vector<uint32_t>* rename = nullptr) {
    std::multiset<Face> faces;
    for (size_t f = 0; f < t.size() / 3; ++f) {
        Face face{t[3 * f], t[3 * f + 1], t[3 * f + 2]};
        if (rename)
            for (uint32_t& v : face) v = (*rename)[v];
        std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
        faces.insert(face);
    }
    return faces;
}

void expectRoundTrip(const std::string& name, const Mesh& mesh) {
    SCOPED_TRACE(name);
    const Prepared in = prepare(mesh);
    TopologicalLayout layout;
    const TopologicalStreams streams = encodeTopological(in.grid, 12, in.triangles, in.copyOf, &layout);
    const TopologicalMesh out = decodeStreams(streams, in, in.triangles.size() / 3);
    const std::vector<uint32_t>& order = layout.vertexOf;
    ASSERT_EQ(out.grid.size(), in.grid.size());
    EXPECT_EQ(out.triangles, layout.triangles);
    EXPECT_EQ(out.components, layout.components);
    EXPECT_EQ(out.copyOf, layout.copyOf);
    // Originals first, then the copies, in the order of their originals;
    // each copy stands for the same input vertex as its original.
    ASSERT_EQ(layout.copyOf.size(), in.copyOf.size());
    auto inputOf = [&](uint32_t cutVertex) { return cutVertex < in.originals ? cutVertex : in.copyOf[cutVertex - in.originals]; };
    for (size_t k = 0; k < layout.copyOf.size(); ++k) {
        ASSERT_LT(layout.copyOf[k], in.originals);
        if (k > 0) EXPECT_LE(layout.copyOf[k - 1], layout.copyOf[k]);
        EXPECT_EQ(inputOf(order[in.originals + k]), inputOf(order[layout.copyOf[k]])) << "copy " << k;
    }
    // Each decoded face is the input face the layout says, same orientation.
    ASSERT_EQ(layout.faceOf.size(), in.triangles.size() / 3);
    for (size_t f = 0; f < layout.faceOf.size(); ++f) {
        std::vector<uint32_t> one(out.triangles.begin() + 3 * f, out.triangles.begin() + 3 * f + 3);
        std::vector<uint32_t> theirs(in.triangles.begin() + 3 * layout.faceOf[f], in.triangles.begin() + 3 * layout.faceOf[f] + 3);
        ASSERT_EQ(orientedFaces(one, &order), orientedFaces(theirs)) << "face " << f;
    }
    ASSERT_EQ(order.size(), in.grid.size() / 3);
    std::vector<uint8_t> seen(order.size(), 0);
    for (size_t id = 0; id < order.size(); ++id) {
        ASSERT_LT(order[id], order.size());
        EXPECT_EQ(seen[order[id]]++, 0) << "input vertex " << order[id] << " met twice";
        for (int k = 0; k < 3; ++k) ASSERT_EQ(out.grid[3 * id + size_t(k)], in.grid[3 * size_t(order[id]) + size_t(k)]) << "vertex " << id;
    }
    EXPECT_EQ(orientedFaces(out.triangles, &order), orientedFaces(in.triangles));
}

TEST(TopologicalCoder, SmallMeshesComeBackRenumberedInTheOrderMet) {
    for (const drm_test::NamedMesh& m : drm_test::smallMeshes()) expectRoundTrip(m.name, m.mesh);
    expectRoundTrip("mixed", drm_test::mixedMesh());
    expectRoundTrip("needing repairs", drm_test::meshNeedingRepairs());
}

// A cut mesh's copies are named where the walk meets a vertex at the grid
// point of an original: one of a fin's, and, with the same mesh again on
// the same points, one of two originals there (the index bits).
TEST(TopologicalCoder, CopiesComeBackAsTheRepairsSectionListsThem) {
    const Mesh repaired = drm_test::meshNeedingRepairs();
    ASSERT_FALSE(prepare(repaired).copyOf.empty());
    expectRoundTrip("one fin", repaired);
    const Mesh twice = drm_test::append(repaired, repaired, 0, 0, 0);
    expectRoundTrip("two fins on the same points", twice);
}

TEST(TopologicalCoder, TestMeshesComeBackRenumberedInTheOrderMet) {
    const std::vector<drm_test::NamedMesh> meshes = drm_test::readPlyDirectory(DRM_TEST_DATA_DIR);
    ASSERT_GE(meshes.size(), 10u);
    for (const drm_test::NamedMesh& m : meshes) expectRoundTrip(m.name, m.mesh);
}

// A CAD part of long slivers (tray-bottom): the case the coder is for. Its
// new vertices need no rank, so its connectivity takes far fewer bits than
// the distance ranks of drm's file.
TEST(TopologicalCoder, CodesSliversInFewerBitsThanDistanceRanks) {
    const Mesh mesh = drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/tray-bottom.ply");
    const Prepared in = prepare(mesh);
    const TopologicalStreams streams = encodeTopological(in.grid, 12, in.triangles, in.copyOf);
    EncodeOptions ranks;
    ranks.connectivity = ConnectivityCoder::Ranks;
    const uint64_t ranked = encode(mesh, ranks).stats.connectivityBytes;
    EXPECT_LT(2 * streams.connectivity.size(), ranked) << "topological " << streams.connectivity.size() << " bytes, ranked " << ranked;
}

TEST(TopologicalCoder, BrokenStreamsAreRefused) {
    const Prepared in = prepare(drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/fandisk.ply"));
    const size_t faces = in.triangles.size() / 3;
    const TopologicalStreams streams = encodeTopological(in.grid, 12, in.triangles, in.copyOf);
    TopologicalStreams cut = streams;
    cut.connectivity.resize(cut.connectivity.size() / 2);
    EXPECT_THROW(decodeStreams(cut, in, faces), Error);
    cut = streams;
    cut.geometry.resize(cut.geometry.size() / 2);
    EXPECT_THROW(decodeStreams(cut, in, faces), Error);
    // Bytes of either stream flipped in turn: decoding either throws a
    // Corrupt Error or gives some mesh, never crashes or hangs; most are
    // refused.
    size_t refused = 0, tried = 0;
    for (int stream = 0; stream < 2; ++stream)
        for (size_t at = 0; at < (stream == 0 ? streams.connectivity.size() : streams.geometry.size()); at += 7) {
            TopologicalStreams damaged = streams;
            (stream == 0 ? damaged.connectivity : damaged.geometry)[at] ^= 0x5A;
            ++tried;
            try {
                decodeStreams(damaged, in, faces);
            } catch (const Error& e) {
                EXPECT_EQ(e.kind(), ErrorKind::Corrupt) << e.what();
                ++refused;
            }
        }
    EXPECT_GT(2 * refused, tried);
    EXPECT_THROW(decodeStreams(streams, in, faces + 5), Error);
    // A header claiming far more vertices than the bytes can hold, and one
    // just within the bound: refused, the second once the streams run out
    // (its tables grow with the vertices met, not with the claim).
    for (size_t claim : {size_t(1) << 31, 8192 * (streams.geometry.size() + 64)}) {
        try {
            decodeTopological(streams.connectivity.data(), streams.connectivity.size(), streams.geometry.data(),
                              streams.geometry.size(), claim, 0, faces, 12);
            ADD_FAILURE() << "a claim of " << claim << " vertices was decoded";
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::Corrupt) << e.what();
        }
    }
}

// The passes over the front for apexes elsewhere on it are bounded
// (OtherSearchBound): with the bound lowered below what a mesh needs, its
// encoding throws InvalidInput, or gives up where a giveUpAbove is set
// (Auto's attempt, the ranks' file kept), and a file written under the
// format's bound is refused as Corrupt by a decoder held to the lower one.
// With the format's bound both sides pass.
TEST(TopologicalCoder, TheSearchForApexesElsewhereOnTheFrontIsBounded) {
    const Prepared in = prepare(drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/mech-holes-shark.ply"));
    const size_t faces = in.triangles.size() / 3;
    TopologicalStats stats;
    const TopologicalStreams streams = encodeTopological(in.grid, 12, in.triangles, in.copyOf, nullptr, &stats);
    ASSERT_GT(stats.symbols[4], 10u) << "the mesh has apexes elsewhere on the front";
    OtherSearchBound low;
    low.floor = 0;
    low.perFace = 0;  // no search at all
    TopologicalBudget budget;
    budget.search = low;
    try {
        encodeTopological(in.grid, 12, in.triangles, in.copyOf, nullptr, nullptr, budget);
        ADD_FAILURE() << "coded past a search bound of none";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::InvalidInput) << e.what();
        EXPECT_NE(std::string(e.what()).find("--connectivity ranks"), std::string::npos) << e.what();
    }
    budget.giveUpAbove = uint64_t(1) << 40;  // a rival file no attempt projects past
    EXPECT_FALSE(encodeTopological(in.grid, 12, in.triangles, in.copyOf, nullptr, nullptr, budget).complete);
    try {
        decodeTopological(streams.connectivity.data(), streams.connectivity.size(), streams.geometry.data(),
                          streams.geometry.size(), in.originals, in.copyOf.size(), faces, 12, low);
        ADD_FAILURE() << "decoded past a search bound of none";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::Corrupt) << e.what();
        EXPECT_NE(std::string(e.what()).find("front vertices read"), std::string::npos) << e.what();
    }
    EXPECT_EQ(decodeStreams(streams, in, faces).triangles.size(), in.triangles.size());
    // At the bound exactly, both sides pass; one front vertex less, both refuse.
    ASSERT_GT(stats.frontRead, 0u);
    OtherSearchBound exact;
    exact.floor = stats.frontRead;
    exact.perFace = 0;
    budget = TopologicalBudget();
    budget.search = exact;
    EXPECT_EQ(encodeTopological(in.grid, 12, in.triangles, in.copyOf, nullptr, nullptr, budget).connectivity, streams.connectivity);
    EXPECT_EQ(decodeTopological(streams.connectivity.data(), streams.connectivity.size(), streams.geometry.data(),
                                streams.geometry.size(), in.originals, in.copyOf.size(), faces, 12, exact)
                  .triangles.size(),
              in.triangles.size());
    OtherSearchBound under = exact;
    --under.floor;
    budget.search = under;
    EXPECT_THROW(encodeTopological(in.grid, 12, in.triangles, in.copyOf, nullptr, nullptr, budget), Error);
    EXPECT_THROW(decodeTopological(streams.connectivity.data(), streams.connectivity.size(), streams.geometry.data(),
                                   streams.geometry.size(), in.originals, in.copyOf.size(), faces, 12, under),
                 Error);
}

// A topological file's walk reports its progress as it goes, encoding and
// decoding (the MeshLab plugin's bar), and a cancel stops it: Cancelled.
TEST(TopologicalCoder, ReportsProgressAndCanBeCancelled) {
    const Mesh mesh = drm_test::icosphere(5);  // 20,480 faces: a report every 4,096 edges
    EncodeOptions options;
    options.connectivity = ConnectivityCoder::Topological;
    std::vector<double> walked;
    options.progress = [&](double fraction, const char* stage) {
        if (std::string(stage) == "coding topologically") walked.push_back(fraction);
        return true;
    };
    const Encoded encoded = encode(mesh, options);
    ASSERT_GE(walked.size(), 4u);
    EXPECT_TRUE(std::is_sorted(walked.begin(), walked.end()));
    EXPECT_LT(walked.front(), 0.1);
    EXPECT_GT(walked.back(), 0.5);
    walked.clear();
    auto decodingReports = [&](double fraction, const char* stage) {
        if (std::string(stage) == "decoding vertices and connectivity") walked.push_back(fraction);
        return true;
    };
    const Decoded decoded = decode(encoded.bytes.data(), encoded.bytes.size(), decodingReports);
    EXPECT_EQ(decoded.mesh.faceCount(), mesh.faceCount());
    ASSERT_GE(walked.size(), 4u);
    EXPECT_TRUE(std::is_sorted(walked.begin(), walked.end()));
    EXPECT_GT(walked.back(), 0.5);
    size_t reports = 0;
    try {
        decode(encoded.bytes.data(), encoded.bytes.size(), [&](double fraction, const char*) { return ++reports < 3 || fraction < 0.2; });
        ADD_FAILURE() << "a cancelled decode returned";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::Cancelled) << e.what();
    }
    EXPECT_GE(reports, 3u);
}

}  // namespace
}  // namespace drm
