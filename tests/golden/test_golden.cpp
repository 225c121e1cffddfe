// Golden files: .drm files written by an earlier build, and the meshes they
// decoded to then. Any change of the bitstream or of the decoder's output
// fails here; an intended one regenerates them (regenerate.sh). The files
// of each older format version the library still reads stay, frozen, in a
// folder of their own (v1/: written before the vertex coder's format 2;
// v2/: before format 3's local frame; v3/: before format 4's nearest
// candidates from the predictor's ball), so the decoder keeps reading what
// users already have.
#include <gtest/gtest.h>

#include <string>

#include "drm/drm.h"
#include "drm_vcg/file_io.h"
#include "drm_vcg/mesh_io.h"

namespace {

void expectDecodesToGolden(const std::string& name, const std::string& folder = "", int formatVersion = drm::kFileFormatVersion) {
    const std::string dir = std::string(DRM_GOLDEN_DIR) + folder;
    const std::vector<uint8_t> bytes = drm::vcgio::readFileBytes(dir + "/" + name + ".drm");
    const drm::Decoded decoded = drm::decode(bytes);
    const drm::vcgio::LoadedMesh golden = drm::vcgio::loadMesh(dir + "/" + name + ".decoded.ply");
    // Exactly: same positions (bit for bit, as floats), same faces in the same order and rotation.
    EXPECT_EQ(decoded.mesh.positions, golden.mesh.positions) << name;
    EXPECT_EQ(decoded.mesh.triangles, golden.mesh.triangles) << name;
    EXPECT_GT(decoded.mesh.faceCount(), 0u) << name;
    EXPECT_EQ(drm::inspect(bytes).formatVersion, formatVersion) << name;
}

TEST(Golden, Torus) { expectDecodesToGolden("torus"); }
TEST(Golden, NefertitiWithThePapersMethod) { expectDecodesToGolden("nefertiti"); }
TEST(Golden, ThreeComponentsWithVertexOrderKept) { expectDecodesToGolden("blobby-3cc"); }
TEST(Golden, RawGeometryAtEightBits) { expectDecodesToGolden("star-raw"); }
TEST(Golden, RefineOnNefertiti) { expectDecodesToGolden("nefertiti-refine"); }

TEST(GoldenFormat1, Torus) { expectDecodesToGolden("torus", "/v1", 1); }
TEST(GoldenFormat1, NefertitiWithThePapersMethod) { expectDecodesToGolden("nefertiti", "/v1", 1); }
TEST(GoldenFormat1, ThreeComponentsWithVertexOrderKept) { expectDecodesToGolden("blobby-3cc", "/v1", 1); }
TEST(GoldenFormat1, RawGeometryAtEightBits) { expectDecodesToGolden("star-raw", "/v1", 1); }
// Written by the format 1 encoder (5b602d2) for this folder: refine's coarse
// tree in format 1's syntax.
TEST(GoldenFormat1, RefineOnNefertiti) { expectDecodesToGolden("nefertiti-refine", "/v1", 1); }

// Format 2's files, as its last encoder (82a4d0c) wrote them.
TEST(GoldenFormat2, Torus) { expectDecodesToGolden("torus", "/v2", 2); }
TEST(GoldenFormat2, NefertitiWithThePapersMethod) { expectDecodesToGolden("nefertiti", "/v2", 2); }
TEST(GoldenFormat2, ThreeComponentsWithVertexOrderKept) { expectDecodesToGolden("blobby-3cc", "/v2", 2); }
TEST(GoldenFormat2, RawGeometryAtEightBits) { expectDecodesToGolden("star-raw", "/v2", 2); }
TEST(GoldenFormat2, RefineOnNefertiti) { expectDecodesToGolden("nefertiti-refine", "/v2", 2); }

// Format 3's files, as its last encoder (36ac087) wrote them.
TEST(GoldenFormat3, Torus) { expectDecodesToGolden("torus", "/v3", 3); }
TEST(GoldenFormat3, NefertitiWithThePapersMethod) { expectDecodesToGolden("nefertiti", "/v3", 3); }
TEST(GoldenFormat3, ThreeComponentsWithVertexOrderKept) { expectDecodesToGolden("blobby-3cc", "/v3", 3); }
TEST(GoldenFormat3, RawGeometryAtEightBits) { expectDecodesToGolden("star-raw", "/v3", 3); }
TEST(GoldenFormat3, RefineOnNefertiti) { expectDecodesToGolden("nefertiti-refine", "/v3", 3); }

}  // namespace
