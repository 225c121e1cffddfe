// The encoder's core (encode/encoder.h): encodeConnectivity's attempt is
// the file encode() writes for a mesh without attributes, its faces are
// the faces decode() gives back, over the grid it was given (a welded
// mesh keeps the grid of the mesh it came from); it refuses options out of
// range, naming each, and stops when the progress callback says so.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "container/file_format.h"
#include "encode/encoder.h"
#include "mesh/quantize.h"
#include "test_meshes.h"
#include "tiny_ply.h"

namespace drm {
namespace {

template <class F>
std::string refusal(F f, ErrorKind kind = ErrorKind::InvalidInput) {
    try {
        f();
    } catch (const Error& e) {
        EXPECT_EQ(e.kind(), kind) << e.what();
        return e.what();
    }
    return "";
}

Attempt attemptFor(const Mesh& m, const EncodeOptions& o, const Grid* grid = nullptr) {
    const Progress none;
    ProgressReporter progress(none);
    return encodeConnectivity(m, o, progress, grid);
}

TEST(Encoder, TheAttemptIsTheFileEncodeWrites) {
    for (const Mesh& m : {drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/bunny-lres.ply"),
                          drm_test::meshNeedingRepairs(), drm_test::mixedMesh()}) {
        EncodeOptions o;
        o.threads = 1;
        const Attempt attempt = attemptFor(m, o);
        const Encoded whole = encode(m, o);
        EXPECT_EQ(attempt.encoded.bytes, whole.bytes);
        // Its sections and header are the file's.
        const std::vector<uint8_t> rewritten = writeFile(attempt.header, attempt.connectivity, attempt.geometry,
                                                         attempt.vertexOrder, attempt.repairs, {}, nullptr);
        EXPECT_EQ(rewritten, whole.bytes);
        const Decoded d = decode(whole.bytes);
        EXPECT_EQ(attempt.decodedTriangles, d.mesh.triangles);
        EXPECT_EQ(attempt.encoded.quantized, quantize(m.positions, makeGrid(m.positions, o.bits)));
        ASSERT_EQ(attempt.encoded.vertexOrder.size(), d.mesh.vertexCount());
        for (size_t v = 0; v < attempt.encoded.vertexOrder.size(); ++v)
            for (int k = 0; k < 3; ++k)
                ASSERT_EQ(d.quantized[3 * v + k], attempt.encoded.quantized[3 * size_t(attempt.encoded.vertexOrder[v]) + k]);
    }
}

TEST(Encoder, TheSameFileWithOneThreadOrTwo) {
    const Mesh m = drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/bunny-lres.ply");
    EncodeOptions one, two;
    one.threads = 1;
    two.threads = 2;
    EXPECT_EQ(attemptFor(m, one).encoded.bytes, attemptFor(m, two).encoded.bytes);
}

TEST(Encoder, AGivenGridIsTheOneUsed) {
    const Mesh m = drm_test::icosphere(2);
    Grid wider = makeGrid(m.positions, 12);
    wider.origin[0] -= 1.0;
    wider.step *= 2;
    const Attempt attempt = attemptFor(m, EncodeOptions(), &wider);
    EXPECT_EQ(attempt.header.grid.origin[0], wider.origin[0]);
    EXPECT_EQ(attempt.header.grid.step, wider.step);
    EXPECT_EQ(attempt.encoded.quantized, quantize(m.positions, wider));
}

TEST(Encoder, OptionsOutOfRangeAreNamed) {
    const Mesh m = drm_test::icosphere(1);
    struct Case {
        void (*set)(EncodeOptions&);
        const char* expected;
    };
    const Case cases[] = {
        {[](EncodeOptions& o) { o.geometry = GeometryCoder(9); }, "unknown geometry coder 9"},
        {[](EncodeOptions& o) { o.predictor = Predictor(7); }, "unknown predictor 7"},
        {[](EncodeOptions& o) {
             o.geometry = GeometryCoder::Refine;
             o.refineBits = 9;
         },
         "refinement bits 9 out of range 0..8 at 12 bits"},
        {[](EncodeOptions& o) {
             o.bits = 4;
             o.geometry = GeometryCoder::Refine;
             o.refineBits = 4;
         },
         "refinement bits 4 out of range 0..3 at 4 bits"},
        {[](EncodeOptions& o) { o.threads = -1; }, "threads -1 is negative (0: as the machine allows)"},
        {[](EncodeOptions& o) { o.connectivity = ConnectivityCoder(5); }, "unknown connectivity coder 5"},
        {[](EncodeOptions& o) {
             o.connectivity = ConnectivityCoder::Topological;
             o.geometry = GeometryCoder::Raw;
         },
         "the topological connectivity coder codes the positions itself; geometry coder raw goes with the distance ranks"},
        {[](EncodeOptions& o) { o.connectivityParts = 3; }, "connectivity parts 3 is not 0 (as the mesh asks), 1 or 2"},
    };
    for (const Case& c : cases) {
        EncodeOptions o;
        c.set(o);
        EXPECT_EQ(refusal([&] { attemptFor(m, o); }), c.expected);
    }
    Mesh badIndex = m;
    badIndex.triangles[7] = 1000;
    EXPECT_NE(refusal([&] { attemptFor(badIndex, EncodeOptions()); }).find("refers to vertex 1000"), std::string::npos);
}

TEST(Encoder, APointPastFloatsRangeIsRefused) {
    const Mesh m = drm_test::icosphere(1);
    // A given grid whose origin is finite as a double but not as a float:
    // every point at or near it decodes past FLT_MAX.
    Grid huge = makeGrid(m.positions, 12);
    huge.origin[0] = 1e39;
    EXPECT_EQ(refusal([&] { attemptFor(m, EncodeOptions(), &huge); }),
              "vertex 0 would decode outside the range of single-precision floats; scale the mesh down");
}

TEST(Encoder, AProgressThatSaysStopCancels) {
    const Mesh m = drm_test::readTinyPly(std::string(DRM_TEST_DATA_DIR) + "/bunny-lres.ply");
    const Progress stop = [](double, const char*) { return false; };
    ProgressReporter progress(stop);
    EXPECT_EQ(refusal([&] { encodeConnectivity(m, EncodeOptions(), progress); }, ErrorKind::Cancelled), "cancelled");
}

}  // namespace
}  // namespace drm
