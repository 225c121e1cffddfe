// Golden files: .drm files written by an earlier build, and the meshes they
// decoded to then. Any change of the bitstream or of the decoder's output
// fails here; an intended one regenerates them (regenerate.sh).
#include <gtest/gtest.h>

#include <string>

#include "drm/drm.h"
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
}

TEST(Golden, Torus) { expectDecodesToGolden("torus"); }
TEST(Golden, NefertitiWithThePapersMethod) { expectDecodesToGolden("nefertiti"); }
TEST(Golden, ThreeComponentsWithVertexOrderKept) { expectDecodesToGolden("blobby-3cc"); }
TEST(Golden, RawGeometryAtEightBits) { expectDecodesToGolden("star-raw"); }

}  // namespace
