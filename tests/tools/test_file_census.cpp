// verify's census of what a file describes: counted from the file's bytes
// by a scan of its own, for each format and layout the readers take.
#include "file_census.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

namespace {

using drm::cli::censusMismatch;
using drm::cli::FileCensus;
using drm::cli::takeCensus;

std::vector<uint8_t> bytesOf(const std::string& text) { return std::vector<uint8_t>(text.begin(), text.end()); }

void expectCounts(const FileCensus& census, bool vertexCountKnown, uint64_t vertices, uint64_t triangles) {
    ASSERT_TRUE(census.known);
    EXPECT_EQ(census.vertexCountKnown, vertexCountKnown);
    if (vertexCountKnown) EXPECT_EQ(census.vertices, vertices);
    EXPECT_EQ(census.minTriangles, triangles);
    EXPECT_EQ(census.maxTriangles, triangles);
}

TEST(FileCensus, ObjCountsVerticesAndPolygonTriangles) {
    const std::string obj =
        "# a quad and a triangle\rv 0 0 0 # first\rv 1 0 0\rv 1 1 0\rv 0 1 0\r"
        "f 1 2 3 4 # quad\rf 1 \\\r 2 3\rvt 0 0\rl 1 2\r";
    expectCounts(takeCensus("m.OBJ", bytesOf(obj)), true, 4, 3);
}

TEST(FileCensus, OffCountsFromItsHeaderAndFaces) {
    const std::string off = "OFF\n# comment\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n3 0 1 2 255 0 0\n";
    expectCounts(takeCensus("m.off", bytesOf(off)), true, 4, 3);
    expectCounts(takeCensus("m.off", bytesOf("OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")), true, 3, 1);
    EXPECT_FALSE(takeCensus("m.off", bytesOf("OFF\n3 1 0\n0 0 0\n")).known);
}

TEST(FileCensus, StlCountsFacetsOfEverySolid) {
    const std::string facet = "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n";
    const std::string ascii = "solid a\n" + facet + facet + "endsolid a\nsolid b\n" + facet + "ENDSOLID b\n";
    expectCounts(takeCensus("m.stl", bytesOf(ascii)), false, 0, 3);
    std::vector<uint8_t> binary(84 + 2 * 50, 0);
    binary[80] = 2;
    expectCounts(takeCensus("m.stl", binary), false, 0, 2);
}

// A PLY with a list before the faces' and a list after them, so the walk
// must read every count.
std::string plyHeader(const char* format) {
    return std::string("ply\nformat ") + format + " 1.0\ncomment x\nelement vertex 4\nproperty float x\nproperty float y\n"
           "property float z\nproperty list uchar int neighbours\nelement face 2\nproperty list ushort uint vertex_indices\n"
           "property list uchar float texcoord\nend_header\n";
}

TEST(FileCensus, PlyWalksEveryListAsciiAndBothEndians) {
    const std::string ascii = plyHeader("ascii") + "0 0 0 1 1\n1 0 0 0\n1 1 0 2 0 1\n0 1 0 0\n4 0 1 2 3 0\n3 0 1 2 2 0 0\n";
    expectCounts(takeCensus("m.ply", bytesOf(ascii)), true, 4, 3);
    for (const char* format : {"binary_little_endian", "binary_big_endian"}) {
        const bool big = std::strcmp(format, "binary_big_endian") == 0;
        std::string body;
        const auto put = [&](uint64_t value, int size) {
            for (int i = 0; i < size; ++i) body.push_back(char(value >> (8 * (big ? size - 1 - i : i))));
        };
        const uint64_t neighbours[4] = {1, 0, 2, 0};
        for (uint64_t n : neighbours) {
            put(0, 12);
            put(n, 1);
            put(0, 4 * int(n));
        }
        put(4, 2), put(0, 16), put(0, 1);      // a quad, no texcoords
        put(3, 2), put(0, 12), put(2, 1), put(0, 8);  // a triangle, two texcoords
        expectCounts(takeCensus("m.ply", bytesOf(plyHeader(format) + body)), true, 4, 3);
        EXPECT_FALSE(takeCensus("m.ply", bytesOf(plyHeader(format) + body.substr(0, body.size() - 1))).known) << format;
    }
}

TEST(FileCensus, PlyTriangleStripsLeaveTheTrianglesOpen) {
    const std::string ply = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                            "element tristrips 1\nproperty list int int vertex_indices\nend_header\n"
                            "0 0 0\n1 0 0\n0 1 0\n1 1 0\n4 0 1 2 3\n";
    const FileCensus census = takeCensus("m.ply", bytesOf(ply));
    ASSERT_TRUE(census.known);
    EXPECT_EQ(census.vertices, 4u);
    EXPECT_EQ(census.minTriangles, 0u);
    EXPECT_EQ(censusMismatch(census, 4, 2), "");
}

// Files the readers take whole, which the census must count alike.
TEST(FileCensus, AgreesWithTheReadersOnValidOddities) {
    const std::string quad = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\n";
    expectCounts(takeCensus("m.obj", bytesOf("# from C:\\M\\\n" + quad + "f 2 4 3\n")), true, 4, 2);
    expectCounts(takeCensus("m.obj", bytesOf("\xEF\xBB\xBF" + quad)), true, 4, 1);
    expectCounts(takeCensus("m.obj", bytesOf(quad + "f 2 4 3 \\")), true, 4, 2);
    expectCounts(takeCensus("m.off", bytesOf("OFF\n4 2 0\n0 0 0\n1 0\n0\n0 1 0\n5 1 0\n3 0 1 2\n3 1 3 2\n")), true, 4, 2);
    const std::string facet = "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n";
    expectCounts(takeCensus("m.stl", bytesOf("solid endfacet part\n" + facet + "endsolid endfacet part\n")), false, 0, 1);
    std::string crPly = "ply\rformat binary_little_endian 1.0\relement vertex 1\rproperty float x\rproperty float y\r"
                        "property float z\relement face 0\rproperty list uchar int vertex_indices\rend_header\r";
    crPly += std::string("\x0a\0\0\0\0\0\0\0\0\0\0\0", 12);
    expectCounts(takeCensus("m.ply", bytesOf(crPly)), true, 1, 0);
    const std::string both = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                             "element face 1\nproperty list uchar int vertex_index\nproperty list uchar int vertex_indices\n"
                             "end_header\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2 4 0 1 3 2\n";
    expectCounts(takeCensus("m.ply", bytesOf(both)), true, 4, 2);
}

TEST(FileCensus, MismatchNamesWhatTheReaderLost) {
    FileCensus census;
    census.known = census.vertexCountKnown = true;
    census.vertices = 6;
    census.minTriangles = census.maxTriangles = 2;
    EXPECT_EQ(censusMismatch(census, 6, 2), "");
    EXPECT_EQ(censusMismatch(census, 6, 1), "the reader gave 1 triangles where the file describes 2");
    EXPECT_EQ(censusMismatch(census, 3, 2), "the reader gave 3 vertices where the file lists 6");
    EXPECT_EQ(censusMismatch(FileCensus(), 1, 1), "");
}

}  // namespace
