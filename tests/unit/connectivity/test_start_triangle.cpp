// Start triangles (start_triangle.h): the cursor they are coded
// from, their gaps, their coding beside the ranks, and the decoder's answer
// to start triangles no encoder writes.
#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <string>
#include <vector>

#include "ranks_only.h"
#include "drmcodec/drmcodec.h"
#include "container/file_format.h"
#include "connectivity/ranked/edge_model.h"
#include "entropy/rank_coder.h"
#include "spatial/spatial_index.h"
#include "connectivity/start_triangle.h"
#include "test_meshes.h"
#include "tiny_ply.h"
#include "connectivity/traversal.h"

using namespace drm;

namespace {

// The cursor by definition: the first untouched vertex at or after `from`,
// cyclically; the vertex count if none.
uint32_t firstUntouchedByScan(const std::vector<bool>& touched, uint32_t from) {
    const uint32_t n = uint32_t(touched.size());
    for (uint32_t k = 0; k < n; ++k) {
        const uint32_t v = (from + k) % n;
        if (!touched[v]) return v;
    }
    return n;
}

}  // namespace

TEST(StartCursor, AgreesWithAScanWhateverOrderVerticesAreTouchedIn) {
    std::mt19937 rng(7);
    for (uint32_t n : {3u, 4u, 10u, 61u, 300u}) {
        SCOPED_TRACE(n);
        std::vector<uint32_t> shuffled(n);
        for (uint32_t v = 0; v < n; ++v) shuffled[v] = v;
        std::shuffle(shuffled.begin(), shuffled.end(), rng);
        Traversal traversal(n, n, nullptr);
        StartCursor cursor(traversal);
        std::vector<bool> touched(n, false);
        // Start triangles over disjoint random vertices (some are never
        // touched, as vertices in no face), asking from random places
        // between them, as a corrupt file may.
        for (size_t k = 0; k + 3 <= n; k += 3) {
            for (int q = 0; q < 5; ++q) {
                const uint32_t from = uint32_t(rng() % n);
                ASSERT_EQ(cursor.at(from), firstUntouchedByScan(touched, from)) << "from " << from;
            }
            if (k + 3 > n - n / 10) break;
            traversal.startComponent(shuffled[k], shuffled[k + 1], shuffled[k + 2]);
            for (size_t i = k; i < k + 3; ++i) touched[shuffled[i]] = true;
        }
        for (uint32_t from = 0; from < n; ++from) EXPECT_EQ(cursor.at(from), firstUntouchedByScan(touched, from));
    }
    // Every vertex touched: the vertex count.
    Traversal full(3, 1, nullptr);
    StartCursor cursor(full);
    EXPECT_EQ(cursor.at(1), 1u);
    full.startComponent(2, 0, 1);
    EXPECT_EQ(cursor.at(0), 3u);
    EXPECT_EQ(cursor.at(2), 3u);
}

// The jump pointers keep the cursor near linear whatever order a file asks
// in: every vertex but the last touched, then asked from each vertex
// downwards (a plain scan would step n^2 / 2 = 4.8e9 times).
TEST(StartCursor, StepsStayLinearWhenAskedBackwards) {
    const uint32_t n = 3 * (1u << 15) + 1;
    Traversal traversal(n, n / 3, nullptr);
    for (uint32_t v = 0; v + 3 < n; v += 3) traversal.startComponent(v, v + 1, v + 2);
    StartCursor cursor(traversal);
    for (uint32_t from = n - 1; from-- > 0;) {
        ASSERT_EQ(cursor.at(from), n - 1) << from;
        ASSERT_LE(cursor.steps(), 4 * uint64_t(n)) << "asked from " << from;
    }
    // Asked forwards, or at random, likewise.
    std::mt19937 rng(3);
    for (int q = 0; q < 100000; ++q) ASSERT_EQ(cursor.at(uint32_t(rng() % n)), n - 1);
    EXPECT_LE(cursor.steps(), 4 * uint64_t(n));
}

TEST(StartTriangle, GapsRoundTripAndRefuseWhatNoVertexHas) {
    for (size_t n : {2u, 3u, 17u}) {
        for (uint32_t first = 0; first < n; ++first)
            for (uint32_t v = 0; v < n; ++v) {
                if (v == first) continue;
                const uint32_t gap = startGap(first, v, n);
                EXPECT_LE(gap, n - 2);
                EXPECT_EQ(vertexAtGap(first, gap, n), v);
            }
        try {
            vertexAtGap(0, uint32_t(n - 1), n);  // the first vertex itself
            ADD_FAILURE() << "gap n - 1 accepted";
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::Corrupt);
        }
    }
    EXPECT_EQ(startGap(5, 6, 100), 0u);   // the next vertex costs least
    EXPECT_EQ(startGap(5, 4, 100), 98u);  // one back wraps round
    EXPECT_THROW(vertexAtGap(0, UINT32_MAX, size_t(UINT32_MAX) + 1), Error);
    EXPECT_EQ(vertexAtGap(1, UINT32_MAX - 1, size_t(UINT32_MAX) + 1), 0u);
}

TEST(StartTriangle, GapsCodedBetweenRanksLeaveTheRanksAlone) {
    const uint32_t gaps[] = {0, 1, 2, 3, 7, 8, 1000, 0x7FFFFFFFu, 0xFFFFFFFEu, 0xFFFFFFFFu};
    const uint32_t ranks[] = {1, 2, 1, 1, 0, 3, 30, 1, 2, 2};
    RankEncoder encoder(2);
    RankEncoder ranksOnly(2);
    for (size_t i = 0; i < 10; ++i) {
        encoder.putStartGap(StartField(i % kStartFields), gaps[i]);
        encoder.put(ranks[i], int(i % 2));
        ranksOnly.put(ranks[i], int(i % 2));
    }
    const std::vector<uint8_t> bytes = encoder.finish();
    RankDecoder decoder(bytes.data(), bytes.size(), 2);
    for (size_t i = 0; i < 10; ++i) {
        EXPECT_EQ(decoder.getStartGap(StartField(i % kStartFields)), gaps[i]);
        EXPECT_EQ(decoder.get(int(i % 2)), ranks[i]);
    }
    EXPECT_EQ(decoder.bytesPastEnd(), 0u);
    // A gap of 0 in a model that has seen only zeros costs well under a bit.
    RankEncoder zeros;
    for (int i = 0; i < 100; ++i) zeros.putStartGap(StartField::Skipped, 0);
    EXPECT_LE(zeros.finish().size(), 4u);
}

namespace {

// file with its connectivity section replaced by `connectivity`, written
// as a valid file (header, checksums) of the current format.
std::vector<uint8_t> withConnectivity(const std::vector<uint8_t>& file, const std::vector<uint8_t>& connectivity) {
    const FileParts parts = readFile(file.data(), file.size());
    const std::vector<uint8_t> geometry(parts.geometry, parts.geometry + parts.geometrySize);
    const std::vector<uint8_t> order(parts.vertexOrder, parts.vertexOrder + parts.vertexOrderSize);
    const std::vector<uint8_t> repairs(parts.repairs, parts.repairs + parts.repairsSize);
    return writeFile(parts.header, connectivity, geometry, order, repairs, {}, nullptr);
}

struct StartGaps {
    const char* what;
    uint32_t skipped, second, third;
};

}  // namespace

TEST(StartTriangle, DecoderRefusesStartTrianglesNoEncoderWrites) {
    const Mesh mesh = drm_test::icosphere(1);  // 42 vertices
    const std::vector<uint8_t> file = encode(mesh, drm_test::ranksOnly()).bytes;
    const uint32_t n = uint32_t(readFile(file.data(), file.size()).header.vertexCount);
    ASSERT_EQ(n, 42u);
    const StartGaps cases[] = {
        {"a first vertex past the last", n, 0, 1},
        {"a first vertex 2^32 - 1 on", UINT32_MAX, 0, 1},
        {"a second vertex at the first", 0, n - 1, 1},
        {"a third vertex at the first", 0, 0, n - 1},
        {"a third vertex far past the last", 0, 0, UINT32_MAX},
        {"the second vertex twice", 0, 5, 5},
    };
    for (const StartGaps& c : cases) {
        SCOPED_TRACE(c.what);
        RankEncoder stream;
        stream.putStartGap(StartField::Skipped, c.skipped);
        stream.putStartGap(StartField::Second, c.second);
        stream.putStartGap(StartField::Third, c.third);
        for (int i = 0; i < 200; ++i) stream.put(1);
        const std::vector<uint8_t> damaged = withConnectivity(file, stream.finish());
        try {
            decode(damaged);
            ADD_FAILURE() << "decoded";
        } catch (const Error& e) {
            EXPECT_EQ(e.kind(), ErrorKind::Corrupt);
            EXPECT_NE(std::string(e.what()).find("component 0"), std::string::npos) << e.what();
        }
    }
    // A stream that ends where a start triangle should be.
    try {
        decode(withConnectivity(file, {}));
        ADD_FAILURE() << "decoded an empty connectivity section";
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), ErrorKind::Corrupt);
    }
}

namespace {

// The connectivity section of a ranks file (tree geometry, no vertex
// order kept, no repairs), decoded and coded again symbol by symbol, with
// component `target`'s start gaps replaced by `replacement` if given. With
// none replaced it must be the section as written, byte for byte.
std::vector<uint8_t> recodeConnectivity(const std::vector<uint8_t>& file, size_t target, const StartGaps* replacement) {
    const FileParts parts = readFile(file.data(), file.size());
    const FileHeader& header = parts.header;
    const Decoded decoded = decode(file);  // the grid in decoded order
    const std::vector<int32_t>& grid = decoded.quantized;
    const size_t n = grid.size() / 3;
    const std::unique_ptr<SpatialIndex> candidates = makeSpatialIndex(grid, NeighbourIndex::Auto, IndexRole::Traversal);
    Traversal traversal(n, size_t(header.faceCount), candidates.get());
    EdgeModel model(grid, header.grid.bits, header.predictor, header.curvature, header.levers, header.faceCount,
                    *candidates, traversal);
    RankDecoder in(parts.connectivity, parts.connectivitySize, model.contextCount(), model.boundaryFlags());
    RankEncoder out(model.contextCount(), model.boundaryFlags());
    StartCursor cursor(traversal);
    uint32_t lastStart = 0;
    for (size_t c = 0; c < header.componentCount; ++c) {
        const uint32_t from = cursor.at(lastStart);
        StartGaps gaps{"", 0, 0, 0};
        gaps.skipped = in.getStartGap(StartField::Skipped);
        gaps.second = in.getStartGap(StartField::Second);
        gaps.third = in.getStartGap(StartField::Third);
        const uint32_t a = uint32_t((from + uint64_t(gaps.skipped)) % n);
        traversal.startComponent(a, vertexAtGap(a, gaps.second, n), vertexAtGap(a, gaps.third, n));
        lastStart = a;
        const StartGaps& written = c == target && replacement ? *replacement : gaps;
        out.putStartGap(StartField::Skipped, written.skipped);
        out.putStartGap(StartField::Second, written.second);
        out.putStartGap(StartField::Third, written.third);
        OpenEdge edge;
        while (traversal.popOpenEdge(edge)) {
            const EdgeForecast& forecast = model.forecast(edge);
            const uint32_t rank = in.get(forecast.context, forecast.boundaryClass);
            out.put(rank, forecast.context, forecast.boundaryClass);
            if (rank == 0) {
                traversal.closeAsBoundary(edge);
                continue;
            }
            const uint32_t apex = model.vertexOfRank(rank, edge);
            model.resolved(apex);
            traversal.attachApex(edge, apex);
        }
    }
    return out.finish();
}

}  // namespace

// Damage to a later component's start triangle, where the cursor has moved
// on and the jump table is in use: blobby-3cc's three components.
TEST(StartTriangle, DecoderRefusesImpossibleStartsOfLaterComponents) {
    const Mesh mesh = drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/blobby-3cc.ply");
    EncodeOptions options = drm_test::ranksOnly();
    options.geometry = GeometryCoder::SpanningTree;
    const std::vector<uint8_t> file = encode(mesh, options).bytes;
    const FileParts parts = readFile(file.data(), file.size());
    ASSERT_EQ(parts.header.componentCount, 3u);
    ASSERT_FALSE(parts.header.keepsVertexOrder || parts.header.hasRepairs);
    const uint32_t n = uint32_t(parts.header.vertexCount);
    // The re-coder gives the section back as written: it reads it right.
    const std::vector<uint8_t> same = recodeConnectivity(file, 0, nullptr);
    ASSERT_EQ(same, std::vector<uint8_t>(parts.connectivity, parts.connectivity + parts.connectivitySize));
    const StartGaps impossible[] = {
        {"a first vertex past the last", n, 0, 1},
        {"a second vertex at the first", 0, n - 1, 1},
        {"the second vertex twice", 0, 3, 3},
        {"a first vertex one round on, at a vertex taken", n - 1, 0, 1},
    };
    for (size_t target : {size_t(1), size_t(2)})
        for (const StartGaps& c : impossible) {
            SCOPED_TRACE(std::string(c.what) + ", component " + std::to_string(target));
            const std::vector<uint8_t> damaged = withConnectivity(file, recodeConnectivity(file, target, &c));
            try {
                decode(damaged);
                ADD_FAILURE() << "decoded";
            } catch (const Error& e) {
                EXPECT_EQ(e.kind(), ErrorKind::Corrupt);
                EXPECT_NE(std::string(e.what()).find("component " + std::to_string(target)), std::string::npos)
                    << e.what();
            }
        }
}

// The search for a cheaper start keeps the default among what it tries, so
// it never makes a file larger, and whatever it keeps decodes to the mesh
// (verify). It finds a smaller file on some of these.
TEST(StartTriangle, SearchingStartsNeverGrowsAFile) {
    size_t smaller = 0;
    for (const char* name : {"torus.ply", "nefertiti.ply", "blobby-3cc.ply", "tray-bottom.ply", "fandisk.ply",
                             "mech-holes-shark.ply", "star-cgal.ply"}) {
        SCOPED_TRACE(name);
        const Mesh mesh = drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/" + name);
        EncodeOptions search = drm_test::ranksOnly(), smallest = drm_test::ranksOnly();
        search.verify = smallest.verify = true;
        smallest.searchStarts = false;
        const size_t searched = encode(mesh, search).bytes.size(), plain = encode(mesh, smallest).bytes.size();
        EXPECT_LE(searched, plain);
        smaller += searched < plain ? 1 : 0;
    }
    EXPECT_GE(smaller, 3u);
}

// The encoder's start triangles decode to the faces it was given, whatever
// vertices lie in no face, however many components there are, and wherever
// its search for a cheaper start puts the first one (meshes this small try
// several, encode/ranked_attempt.cpp).
TEST(StartTriangle, ComponentsAmongIsolatedVerticesRoundTrip) {
    Mesh mesh = drm_test::append(drm_test::icosphere(1), drm_test::tetrahedron(), 3, 0, 0);
    mesh = drm_test::append(mesh, drm_test::gridPatch(4, true), 0, 3, 0);
    for (int i = 0; i < 5; ++i) drm_test::addVertex(mesh, float(-2 - i), 0.5f * float(i), 1.0f);
    EncodeOptions options = drm_test::ranksOnly();
    options.verify = true;  // decodes the file and compares grid points and oriented faces
    const Encoded encoded = encode(mesh, options);
    EXPECT_EQ(encoded.stats.components, 3u);
    const Decoded decoded = decode(encoded.bytes);
    ASSERT_EQ(decoded.mesh.triangles.size(), mesh.triangles.size());
    EXPECT_EQ(decoded.mesh.vertexCount(), mesh.vertexCount());
}
