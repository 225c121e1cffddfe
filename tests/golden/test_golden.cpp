// Golden files: .drm files written by an earlier build, and the meshes they
// decoded to then. Any change of the bitstream or of the decoder's output
// fails here; an intended one regenerates them (regenerate.sh).
// earlier-versions/ holds a file of each pre-release format version
// (torus-vN.drm, as that version's encoder wrote it): the reader refuses
// each, naming its version.
#include <gtest/gtest.h>

#include <string>

#include "drm/drm.h"
#include "drm_sections.h"
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

// Format 12's files, as 19bca29 wrote them (format 12's last encoder,
// 0b5407b, wrote them byte for byte the same): the distance ranks alone.
TEST(GoldenFormat12, Torus) { expectDecodesToGolden("torus", "/v12", 12); }
TEST(GoldenFormat12, NefertitiWithThePapersMethod) { expectDecodesToGolden("nefertiti", "/v12", 12); }
TEST(GoldenFormat12, ThreeComponentsWithVertexOrderKept) { expectDecodesToGolden("blobby-3cc", "/v12", 12); }
TEST(GoldenFormat12, RawGeometryAtEightBits) { expectDecodesToGolden("star-raw", "/v12", 12); }
TEST(GoldenFormat12, RefineOnNefertiti) { expectDecodesToGolden("nefertiti-refine", "/v12", 12); }
TEST(GoldenFormat12, FrontNeighboursOnTrayBottom) { expectDecodesToGolden("tray-bottom", "/v12", 12); }
TEST(GoldenFormat12, TangentSignsOnBunnyLres) { expectDecodesToGolden("bunny-lres", "/v12", 12); }
TEST(GoldenFormat12, RefineOnMechHolesShark) { expectDecodesToGolden("shark-refine", "/v12", 12); }
TEST(GoldenFormat12, BoundaryFlagsAloneOnBlobby) { expectDecodesToGolden("blobby-boundary", "/v12", 12); }
TEST(GoldenFormat12, TwoPartsOnBunnyLres) { expectDecodesToGolden("bunny-lres-parts", "/v12", 12); }

// Format 11's files, as its last encoder (98ace33, byte for byte
// a67fd9c's) wrote them: on the seam's side, the size step's wider balls
// searched too.
TEST(GoldenFormat11, Torus) { expectDecodesToGolden("torus", "/v11", 11); }
TEST(GoldenFormat11, NefertitiWithThePapersMethod) { expectDecodesToGolden("nefertiti", "/v11", 11); }
TEST(GoldenFormat11, ThreeComponentsWithVertexOrderKept) { expectDecodesToGolden("blobby-3cc", "/v11", 11); }
TEST(GoldenFormat11, RawGeometryAtEightBits) { expectDecodesToGolden("star-raw", "/v11", 11); }
TEST(GoldenFormat11, RefineOnNefertiti) { expectDecodesToGolden("nefertiti-refine", "/v11", 11); }
TEST(GoldenFormat11, FrontNeighboursOnTrayBottom) { expectDecodesToGolden("tray-bottom", "/v11", 11); }
TEST(GoldenFormat11, TangentSignsOnBunnyLres) { expectDecodesToGolden("bunny-lres", "/v11", 11); }
TEST(GoldenFormat11, RefineOnMechHolesShark) { expectDecodesToGolden("shark-refine", "/v11", 11); }
TEST(GoldenFormat11, BoundaryFlagsAloneOnBlobby) { expectDecodesToGolden("blobby-boundary", "/v11", 11); }
TEST(GoldenFormat11, TwoPartsOnBunnyLres) { expectDecodesToGolden("bunny-lres-parts", "/v11", 11); }

// Format 10's files, as its last encoder (ea1d730) wrote them: the
// connectivity in one part.
TEST(GoldenFormat10, Torus) { expectDecodesToGolden("torus", "/v10", 10); }
TEST(GoldenFormat10, NefertitiWithThePapersMethod) { expectDecodesToGolden("nefertiti", "/v10", 10); }
TEST(GoldenFormat10, ThreeComponentsWithVertexOrderKept) { expectDecodesToGolden("blobby-3cc", "/v10", 10); }
TEST(GoldenFormat10, RawGeometryAtEightBits) { expectDecodesToGolden("star-raw", "/v10", 10); }
TEST(GoldenFormat10, RefineOnNefertiti) { expectDecodesToGolden("nefertiti-refine", "/v10", 10); }
TEST(GoldenFormat10, FrontNeighboursOnTrayBottom) { expectDecodesToGolden("tray-bottom", "/v10", 10); }
TEST(GoldenFormat10, TangentSignsOnBunnyLres) { expectDecodesToGolden("bunny-lres", "/v10", 10); }
TEST(GoldenFormat10, RefineOnMechHolesShark) { expectDecodesToGolden("shark-refine", "/v10", 10); }
TEST(GoldenFormat10, BoundaryFlagsAloneOnBlobby) { expectDecodesToGolden("blobby-boundary", "/v10", 10); }

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

// Format 4's files, as its last encoder (aa9522b) wrote them.
TEST(GoldenFormat4, Torus) { expectDecodesToGolden("torus", "/v4", 4); }
TEST(GoldenFormat4, NefertitiWithThePapersMethod) { expectDecodesToGolden("nefertiti", "/v4", 4); }
TEST(GoldenFormat4, ThreeComponentsWithVertexOrderKept) { expectDecodesToGolden("blobby-3cc", "/v4", 4); }
TEST(GoldenFormat4, RawGeometryAtEightBits) { expectDecodesToGolden("star-raw", "/v4", 4); }
TEST(GoldenFormat4, RefineOnNefertiti) { expectDecodesToGolden("nefertiti-refine", "/v4", 4); }

// Format 5's files, as its last encoder (adec404) wrote them: one sign model
// per axis, where format 6 has nine.
TEST(GoldenFormat5, Torus) { expectDecodesToGolden("torus", "/v5", 5); }
TEST(GoldenFormat5, NefertitiWithThePapersMethod) { expectDecodesToGolden("nefertiti", "/v5", 5); }
TEST(GoldenFormat5, ThreeComponentsWithVertexOrderKept) { expectDecodesToGolden("blobby-3cc", "/v5", 5); }
TEST(GoldenFormat5, RawGeometryAtEightBits) { expectDecodesToGolden("star-raw", "/v5", 5); }
TEST(GoldenFormat5, RefineOnNefertiti) { expectDecodesToGolden("nefertiti-refine", "/v5", 5); }
TEST(GoldenFormat5, FrontNeighboursOnTrayBottom) { expectDecodesToGolden("tray-bottom", "/v5", 5); }
// Format 9's files, as its last encoder (6f50905) wrote them: boundary
// edges coded as rank 0 among the ranks.
TEST(GoldenFormat9, Torus) { expectDecodesToGolden("torus", "/v9", 9); }
TEST(GoldenFormat9, NefertitiWithThePapersMethod) { expectDecodesToGolden("nefertiti", "/v9", 9); }
TEST(GoldenFormat9, ThreeComponentsWithVertexOrderKept) { expectDecodesToGolden("blobby-3cc", "/v9", 9); }
TEST(GoldenFormat9, RawGeometryAtEightBits) { expectDecodesToGolden("star-raw", "/v9", 9); }
TEST(GoldenFormat9, RefineOnNefertiti) { expectDecodesToGolden("nefertiti-refine", "/v9", 9); }
TEST(GoldenFormat9, FrontNeighboursOnTrayBottom) { expectDecodesToGolden("tray-bottom", "/v9", 9); }
TEST(GoldenFormat9, TangentSignsOnBunnyLres) { expectDecodesToGolden("bunny-lres", "/v9", 9); }
TEST(GoldenFormat9, RefineOnMechHolesShark) { expectDecodesToGolden("shark-refine", "/v9", 9); }

// Format 8's files, as its last encoder (ba39120) wrote them: the
// connectivity numbers the vertices in the vertex section's order.
TEST(GoldenFormat8, Torus) { expectDecodesToGolden("torus", "/v8", 8); }
TEST(GoldenFormat8, NefertitiWithThePapersMethod) { expectDecodesToGolden("nefertiti", "/v8", 8); }
TEST(GoldenFormat8, ThreeComponentsWithVertexOrderKept) { expectDecodesToGolden("blobby-3cc", "/v8", 8); }
TEST(GoldenFormat8, RawGeometryAtEightBits) { expectDecodesToGolden("star-raw", "/v8", 8); }
TEST(GoldenFormat8, RefineOnNefertiti) { expectDecodesToGolden("nefertiti-refine", "/v8", 8); }
TEST(GoldenFormat8, FrontNeighboursOnTrayBottom) { expectDecodesToGolden("tray-bottom", "/v8", 8); }
TEST(GoldenFormat8, TangentSignsOnBunnyLres) { expectDecodesToGolden("bunny-lres", "/v8", 8); }
TEST(GoldenFormat8, RefineOnMechHolesShark) { expectDecodesToGolden("shark-refine", "/v8", 8); }

// Format 7's files, as its last encoder (c1bfbba) wrote them: the start
// triangles in the header, three varints each.
TEST(GoldenFormat7, Torus) { expectDecodesToGolden("torus", "/v7", 7); }
TEST(GoldenFormat7, NefertitiWithThePapersMethod) { expectDecodesToGolden("nefertiti", "/v7", 7); }
TEST(GoldenFormat7, ThreeComponentsWithVertexOrderKept) { expectDecodesToGolden("blobby-3cc", "/v7", 7); }
TEST(GoldenFormat7, RawGeometryAtEightBits) { expectDecodesToGolden("star-raw", "/v7", 7); }
TEST(GoldenFormat7, RefineOnNefertiti) { expectDecodesToGolden("nefertiti-refine", "/v7", 7); }
TEST(GoldenFormat7, FrontNeighboursOnTrayBottom) { expectDecodesToGolden("tray-bottom", "/v7", 7); }
TEST(GoldenFormat7, TangentSignsOnBunnyLres) { expectDecodesToGolden("bunny-lres", "/v7", 7); }
TEST(GoldenFormat7, RefineOnMechHolesShark) { expectDecodesToGolden("shark-refine", "/v7", 7); }

// Format 6's files, as its last encoder (79422de) wrote them: the frame
// not turned about its normal, every sign in format 6's nine contexts.
TEST(GoldenFormat6, Torus) { expectDecodesToGolden("torus", "/v6", 6); }
TEST(GoldenFormat6, NefertitiWithThePapersMethod) { expectDecodesToGolden("nefertiti", "/v6", 6); }
TEST(GoldenFormat6, ThreeComponentsWithVertexOrderKept) { expectDecodesToGolden("blobby-3cc", "/v6", 6); }
TEST(GoldenFormat6, RawGeometryAtEightBits) { expectDecodesToGolden("star-raw", "/v6", 6); }
TEST(GoldenFormat6, RefineOnNefertiti) { expectDecodesToGolden("nefertiti-refine", "/v6", 6); }
TEST(GoldenFormat6, FrontNeighboursOnTrayBottom) { expectDecodesToGolden("tray-bottom", "/v6", 6); }
TEST(GoldenFormat6, ScanBunnyLres) { expectDecodesToGolden("bunny-lres", "/v6", 6); }

// A golden file of an older format with a header flag its version never
// had (bit 8 + highBit: the u16 flags are little-endian), behind a fresh
// checksum: refused as corrupt, not decoded with a meaning it cannot have.
void expectFlagRefused(const std::string& file, int highBit) {
    const std::vector<uint8_t> bytes = drm::vcgio::readFileBytes(std::string(DRM_GOLDEN_DIR) + file);
    std::vector<drm_test::SectionSpan> sections;
    ASSERT_TRUE(drm_test::parseSections(bytes, &sections));
    std::vector<uint8_t> header = drm_test::payloadsOf(bytes, sections)[0];
    EXPECT_EQ(header[1] & (1 << highBit), 0);
    header[1] |= uint8_t(1 << highBit);
    try {
        drm::decode(drm_test::withPayload(bytes, 0, header));
        ADD_FAILURE() << file << " with flag bit " << 8 + highBit << " decoded";
    } catch (const drm::Error& e) {
        EXPECT_EQ(e.kind(), drm::ErrorKind::Corrupt) << e.what();
        EXPECT_NE(std::string(e.what()).find("unknown header flags"), std::string::npos) << e.what();
    }
    EXPECT_NO_THROW(drm::decode(bytes));  // the file as written
}

// The high flag byte of a golden file's header.
uint8_t highFlags(const std::string& file) {
    const std::vector<uint8_t> bytes = drm::vcgio::readFileBytes(std::string(DRM_GOLDEN_DIR) + file);
    std::vector<drm_test::SectionSpan> sections;
    EXPECT_TRUE(drm_test::parseSections(bytes, &sections));
    return drm_test::payloadsOf(bytes, sections)[0][1];
}

// Header flag bit 8 (front neighbours) exists from format 5 on; format 5's
// files and later ones set it.
TEST(GoldenFormat4, FrontNeighbourFlagIsRefused) {
    expectFlagRefused("/v4/blobby-3cc.drm", 0);
    for (const char* folder : {"/v5", "/v6", "/v7", "/v8", "/v9", "/v10", "/v11", ""})
        EXPECT_EQ(highFlags(std::string(folder) + "/blobby-3cc.drm") & 1, 1) << folder;
}

// Header flag bit 9 (the connectivity in the vertex section's order)
// exists from format 9 on. star-raw (raw bits, which keep the input's
// order) sets it; bunny-lres, numbered in Morton order, does not.
TEST(GoldenFormat8, SectionNumberingFlagIsRefused) {
    expectFlagRefused("/v8/bunny-lres.drm", 1);
    EXPECT_EQ(highFlags("/star-raw.drm") & 2, 2);
    EXPECT_EQ(highFlags("/bunny-lres.drm") & 2, 0);
}

// Header flag bit 10 (boundary flags) exists from format 10 on; files
// written with every lever set it, the paper's method does not.
TEST(GoldenFormat9, BoundaryFlagIsRefused) {
    expectFlagRefused("/v9/blobby-3cc.drm", 2);
    EXPECT_EQ(highFlags("/blobby-3cc.drm") & 4, 4);
    EXPECT_EQ(highFlags("/nefertiti.drm") & 4, 0);
}

// Header flag bit 11 (two connectivity parts) exists from format 11 on;
// small meshes stay in one part unless asked.
TEST(GoldenFormat10, TwoPartsFlagIsRefused) {
    expectFlagRefused("/v10/bunny-lres.drm", 3);
    EXPECT_EQ(highFlags("/bunny-lres-parts.drm") & 8, 8);
    EXPECT_EQ(highFlags("/bunny-lres.drm") & 8, 0);
}

}  // namespace
