// Golden files: .drm files written by an earlier build, and the meshes they
// decoded to then. Any change of the bitstream or of the decoder's output
// fails here; an intended one regenerates them (regenerate.sh).
// earlier-versions/ holds a file of each pre-release format version
// (torus-vN.drm, as that version's encoder wrote it): the reader refuses
// each, naming its version.
#include <gtest/gtest.h>

#include <string>

#include "drmcodec/drmcodec.h"
#include "drm_sections.h"
#include "drm_vcg/file_io.h"
#include "drm_vcg/mesh_io.h"

namespace {

void expectDecodesToGolden(const std::string& name) {
    const std::string dir = DRM_GOLDEN_DIR;
    const std::vector<uint8_t> bytes = drm::vcgio::readFileBytes(dir + "/" + name + ".drm");
    const drm::Decoded decoded = drm::decode(bytes);
    const drm::vcgio::LoadedMesh golden = drm::vcgio::loadMesh(dir + "/" + name + ".decoded.ply");
    // Exactly: same positions (bit for bit, as floats), same faces in the same order and rotation.
    EXPECT_EQ(decoded.mesh.positions, golden.mesh.positions) << name;
    EXPECT_EQ(decoded.mesh.triangles, golden.mesh.triangles) << name;
    EXPECT_GT(decoded.mesh.faceCount(), 0u) << name;
    EXPECT_EQ(drm::inspect(bytes).formatVersion, drm::kFileFormatVersion) << name;
}

TEST(Golden, Torus) { expectDecodesToGolden("torus"); }
TEST(Golden, NefertitiWithThePapersMethod) { expectDecodesToGolden("nefertiti"); }
TEST(Golden, ThreeComponentsWithVertexOrderKept) { expectDecodesToGolden("blobby-3cc"); }
TEST(Golden, RawGeometryAtEightBits) { expectDecodesToGolden("star-raw"); }
TEST(Golden, RefineOnNefertiti) { expectDecodesToGolden("nefertiti-refine"); }
// CAD slivers: the front order ranks a good part of the edges.
TEST(Golden, FrontNeighboursOnTrayBottom) { expectDecodesToGolden("tray-bottom"); }
// A scan: most edges from the parent are coded in the local frame, turned
// along the walk, with their tangent signs in their own contexts.
TEST(Golden, TangentSignsOnBunnyLres) { expectDecodesToGolden("bunny-lres"); }
// Refine's coarse tree, coded with the frame along the walk and its tangent
// signs, then two low bits.
TEST(Golden, RefineOnMechHolesShark) { expectDecodesToGolden("shark-refine"); }
// Holes, and the boundary flags as the only lever.
TEST(Golden, BoundaryFlagsAloneOnBlobby) { expectDecodesToGolden("blobby-boundary"); }
// The connectivity in two parts, forced on a small scan.
TEST(Golden, TwoPartsOnBunnyLres) { expectDecodesToGolden("bunny-lres-parts"); }
// The topological coder, which the encoder picks for CAD slivers.
TEST(Golden, TopologicalOnTrayBottom) { expectDecodesToGolden("tray-bottom-topological"); }
// The topological coder over three components with holes, vertex order kept.
TEST(Golden, TopologicalOnBlobbyWithVertexOrderKept) { expectDecodesToGolden("blobby-3cc-topological"); }
// A cut mesh (a fin, two fans at a vertex, the same again on the same
// points): copies named where the walk meets an original's grid point.
TEST(Golden, TopologicalCopiesOnFinsAndBowtie) { expectDecodesToGolden("fins-topological"); }

// Each pre-release version's file is refused as unsupported, by decode and
// inspect alike, with a message that names the file's version.
TEST(EarlierVersions, EachIsRefusedNamingItsVersion) {
    for (int version = 1; version < drm::kFileFormatVersion; ++version) {
        const std::string file = std::string(DRM_GOLDEN_DIR) + "/earlier-versions/torus-v" + std::to_string(version) + ".drm";
        const std::vector<uint8_t> bytes = drm::vcgio::readFileBytes(file);
        ASSERT_GE(bytes.size(), 10u) << file;
        EXPECT_EQ(bytes[8] | (bytes[9] << 8), version) << file << " is not a file of version " << version;
        for (int call = 0; call < 2; ++call) {
            try {
                if (call == 0) drm::decode(bytes);
                else drm::inspect(bytes);
                ADD_FAILURE() << file << " was read";
            } catch (const drm::Error& e) {
                EXPECT_EQ(e.kind(), drm::ErrorKind::Unsupported) << e.what();
                const std::string message = e.what();
                EXPECT_NE(message.find("format version " + std::to_string(version) + ":"), std::string::npos) << message;
                EXPECT_NE(message.find("pre-release"), std::string::npos) << message;
            }
        }
    }
}

}  // namespace
