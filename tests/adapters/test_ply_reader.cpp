// The PLY reader takes every value from the file's bytes as its header types
// it: each encoding, each scalar type as property, list entry and list
// count, any header line ending; what it changes it says in a note, what it
// cannot read it refuses with a message naming the place. The files are
// made here, from a header and the values of the body in file order, so
// that each case shows the bytes it is about.
#include <drmcodec/drmcodec.h>
#include <drm_vcg/mesh_io.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "scratch_dir.h"

namespace {

using drm::vcgio::LoadedMesh;

const char* const kEncodings[] = {"ascii", "binary_little_endian", "binary_big_endian"};
const char* const kIntegerTypes[] = {"char", "uchar", "short", "ushort", "int", "uint"};
const char* const kAllTypes[] = {"char", "uchar", "short", "ushort", "int", "uint", "float", "double"};

// The bytes of `value` as `type`, in the file's encoding.
void putValue(std::string& out, const std::string& type, double value, const std::string& encoding) {
    if (encoding == "ascii") {
        char text[64];
        if (type == "float" || type == "float32") std::snprintf(text, sizeof text, "%.9g", double(float(value)));
        else if (type == "double" || type == "float64") std::snprintf(text, sizeof text, "%.17g", value);
        else std::snprintf(text, sizeof text, "%lld", static_cast<long long>(value));
        if (!out.empty() && out.back() != '\n') out += ' ';
        out += text;
        return;
    }
    uint64_t bits = 0;
    size_t size = 0;
    if (type == "char" || type == "int8") bits = uint8_t(int8_t(value)), size = 1;
    else if (type == "uchar" || type == "uint8") bits = uint8_t(value), size = 1;
    else if (type == "short" || type == "int16") bits = uint16_t(int16_t(value)), size = 2;
    else if (type == "ushort" || type == "uint16") bits = uint16_t(value), size = 2;
    else if (type == "int" || type == "int32") bits = uint32_t(int32_t(value)), size = 4;
    else if (type == "uint" || type == "uint32") bits = uint32_t(value), size = 4;
    else if (type == "float" || type == "float32") {
        const float f = float(value);
        uint32_t word;
        std::memcpy(&word, &f, 4);
        bits = word, size = 4;
    } else if (type == "double" || type == "float64") {
        std::memcpy(&bits, &value, 8);
        size = 8;
    } else {
        ADD_FAILURE() << "unknown type " << type;
    }
    for (size_t i = 0; i < size; ++i) {
        const size_t byte = encoding == "binary_big_endian" ? size - 1 - i : i;
        out.push_back(char((bits >> (8 * byte)) & 0xFF));
    }
}

// A PLY file: "ply", the format line, `header` (lines split by '\n', each
// written with `eol`), "end_header", then `values` in the order the body
// holds them (a list's count, then its entries), each as the header types
// it. ASCII items take a line each.
std::string plyFile(const std::string& encoding, const std::string& header, const std::vector<double>& values,
                    const std::string& eol = "\n") {
    struct Property {
        std::string type, countType;
        bool list = false;
    };
    struct Element {
        size_t count = 0;
        std::vector<Property> properties;
    };
    std::vector<Element> elements;
    std::string text = "ply" + eol + "format " + encoding + " 1.0" + eol;
    std::istringstream lines(header);
    std::string line;
    while (std::getline(lines, line)) {
        text += line + eol;
        std::istringstream words(line);
        std::string keyword, a, b, c, d;
        words >> keyword >> a >> b >> c >> d;
        if (keyword == "element") elements.push_back(Element{std::stoul(b), {}});
        else if (keyword == "property" && a == "list") elements.back().properties.push_back(Property{c, b, true});
        else if (keyword == "property") elements.back().properties.push_back(Property{a, "", false});
    }
    text += "end_header" + eol;
    std::string body;
    size_t next = 0;
    const auto take = [&]() {
        if (next == values.size()) {
            ADD_FAILURE() << "too few values for the header";
            return 0.0;
        }
        return values[next++];
    };
    for (const Element& element : elements)
        for (size_t item = 0; item < element.count; ++item) {
            for (const Property& p : element.properties) {
                if (!p.list) {
                    putValue(body, p.type, take(), encoding);
                    continue;
                }
                const double entries = take();
                putValue(body, p.countType, entries, encoding);
                for (int k = 0; k < int(entries); ++k) putValue(body, p.type, take(), encoding);
            }
            if (encoding == "ascii") body += "\n";
        }
    EXPECT_EQ(next, values.size()) << "values left over";
    return text + body;
}

LoadedMesh load(const std::string& bytes) {
    ScratchDir dir;
    writeText(dir.file("m.ply"), bytes);
    return drm::vcgio::loadMesh(dir.file("m.ply"));
}

// The reason loadMesh gives (after "cannot read PATH: "), or "" if it reads.
std::string refusal(const std::string& bytes) {
    ScratchDir dir;
    const std::string path = dir.file("m.ply");
    writeText(path, bytes);
    try {
        drm::vcgio::loadMesh(path);
    } catch (const drm::Error& e) {
        EXPECT_EQ(e.kind(), drm::ErrorKind::InvalidInput) << e.what();
        const std::string prefix = "cannot read " + path + ": ";
        const std::string message = e.what();
        EXPECT_EQ(message.compare(0, prefix.size(), prefix), 0) << message;
        return message.substr(prefix.size());
    }
    return "";
}

// Floats compared bit for bit (NaN and -0 included).
void expectBits(const std::vector<float>& actual, const std::vector<float>& expected) {
    ASSERT_EQ(actual.size(), expected.size());
    for (size_t i = 0; i < actual.size(); ++i)
        EXPECT_EQ(std::memcmp(&actual[i], &expected[i], 4), 0) << "value " << i << ": " << actual[i] << " vs " << expected[i];
}

const std::string kVertexXyz = "property float x\nproperty float y\nproperty float z\n";
const std::vector<float> kSquare = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
const std::vector<double> kSquareValues = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
const std::string kPolygonNote = "polygons were split into triangles: 2 of the 3 triangles come from polygons";

std::vector<double> concat(std::vector<double> a, const std::vector<double>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

TEST(PlyReader, EveryIntegerTypeAsListCountAndEveryTypeAsIndexInEveryEncoding) {
    // A triangle, then a quad fan-split in place.
    const std::vector<double> faces = {3, 0, 1, 2, 4, 0, 2, 3, 1};
    for (const char* encoding : kEncodings)
        for (const char* countType : kIntegerTypes)
            for (const char* indexType : kAllTypes) {
                SCOPED_TRACE(std::string(encoding) + " " + countType + " " + indexType);
                const std::string header = "element vertex 4\n" + kVertexXyz + "element face 2\nproperty list " + countType + " " +
                                           indexType + " vertex_indices";
                const LoadedMesh loaded = load(plyFile(encoding, header, concat(kSquareValues, faces)));
                expectBits(loaded.mesh.positions, kSquare);
                EXPECT_EQ(loaded.mesh.triangles, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 0, 3, 1}));
                EXPECT_EQ(loaded.notes, std::vector<std::string>{kPolygonNote});
            }
}

TEST(PlyReader, TypeAliasesAndVertexIndexSpelling) {
    const std::string header = "element vertex 4\nproperty float32 x\nproperty float32 y\nproperty float32 z\n"
                               "element face 1\nproperty list uint8 int32 vertex_index";
    const LoadedMesh loaded = load(plyFile("binary_big_endian", header, concat(kSquareValues, {3, 3, 2, 1})));
    expectBits(loaded.mesh.positions, kSquare);
    EXPECT_EQ(loaded.mesh.triangles, (std::vector<uint32_t>{3, 2, 1}));
}

TEST(PlyReader, IntegerAndDoublePositionsInBothByteOrders) {
    for (const char* encoding : kEncodings)
        for (const char* type : {"char", "short", "int", "uint", "double"}) {
            SCOPED_TRACE(std::string(encoding) + " " + type);
            const std::string t = type;
            const std::string header = "element vertex 3\nproperty " + t + " x\nproperty " + t + " y\nproperty " + t +
                                       " z\nelement face 1\nproperty list uchar int vertex_indices";
            const LoadedMesh loaded = load(plyFile(encoding, header, {0, 1, 2, 3, 4, 5, 6, 7, 8, 3, 0, 1, 2}));
            expectBits(loaded.mesh.positions, {0, 1, 2, 3, 4, 5, 6, 7, 8});
            EXPECT_TRUE(loaded.notes.empty()) << loaded.notes[0];
        }
}

TEST(PlyReader, PositionsThatFloatCannotHoldAreRoundedWithANote) {
    const std::string header = "element vertex 3\nproperty double x\nproperty int y\nproperty double z\n"
                               "element face 1\nproperty list uchar int vertex_indices";
    for (const char* encoding : kEncodings) {
        SCOPED_TRACE(encoding);
        // 0.1 and 16777217 (2^24 + 1) have no float; 0.5 and 7 do.
        const LoadedMesh loaded = load(plyFile(encoding, header, {0.1, 16777217, 0.5, 1, 7, -2.25, 0, 0, 1, 3, 0, 1, 2}));
        expectBits(loaded.mesh.positions, {0.1f, 16777216.0f, 0.5f, 1, 7, -2.25f, 0, 0, 1});
        EXPECT_EQ(loaded.notes, std::vector<std::string>{
                                    "2 vertex position values were rounded to the nearest float (the file has int and double)"});
    }
    // A double beyond float's range is refused, not made infinite.
    EXPECT_EQ(refusal(plyFile("binary_little_endian", header, {1e300, 0, 0, 1, 0, 0, 0, 1, 0, 3, 0, 1, 2})),
              "vertex 0: its x 1.0000000000000001e+300 is beyond the range of float");
    // NaN and infinity stay what they are (the codec refuses them, naming the vertex).
    const LoadedMesh odd = load(plyFile("binary_big_endian", header,
                                        {std::nan(""), 0, std::numeric_limits<double>::infinity(), 1, 0, 0, 0, 1, 0, 3, 0, 1, 2}));
    EXPECT_TRUE(std::isnan(odd.mesh.positions[0]));
    EXPECT_EQ(odd.mesh.positions[2], std::numeric_limits<float>::infinity());
    EXPECT_TRUE(odd.notes.empty());
}

TEST(PlyReader, BigEndianDoublesReadExactly) {
    const std::string header = "element vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
                               "property double nx\nproperty double ny\nproperty double nz\nproperty double quality\n"
                               "element face 1\nproperty list int int vertex_indices";
    const LoadedMesh loaded = load(plyFile("binary_big_endian", header,
                                           {1.5, -2, 3, 0, 0, 1, 0.25, 4, 5, 6, 0, 1, 0, 8, 7, 8, 9, 1, 0, 0, -1, 3, 2, 1, 0}));
    expectBits(loaded.mesh.positions, {1.5f, -2, 3, 4, 5, 6, 7, 8, 9});
    expectBits(loaded.mesh.normals, {0, 0, 1, 0, 1, 0, 1, 0, 0});
    expectBits(loaded.mesh.quality, {0.25f, 8, -1});
    EXPECT_EQ(loaded.mesh.triangles, (std::vector<uint32_t>{2, 1, 0}));
    EXPECT_TRUE(loaded.notes.empty());
}

TEST(PlyReader, DoubleAndIntegerQualityNotedOnlyWhenInexact) {
    const std::string header = "element vertex 3\n" + kVertexXyz + "property double quality\nelement face 1\n"
                               "property list uchar int vertex_indices\nproperty int quality";
    for (const char* encoding : kEncodings) {
        SCOPED_TRACE(encoding);
        const LoadedMesh exact =
            load(plyFile(encoding, header, {0, 0, 0, 0.5, 1, 0, 0, -3, 0, 1, 0, 1e10, 3, 0, 1, 2, -7}));
        expectBits(exact.mesh.quality, {0.5f, -3, 1e10f});
        expectBits(exact.mesh.faceQuality, {-7});
        EXPECT_TRUE(exact.notes.empty()) << exact.notes[0];
        const LoadedMesh inexact =
            load(plyFile(encoding, header, {0, 0, 0, 0.1, 1, 0, 0, 0.2, 0, 1, 0, 0.5, 3, 0, 1, 2, 16777217}));
        expectBits(inexact.mesh.quality, {0.1f, 0.2f, 0.5f});
        expectBits(inexact.mesh.faceQuality, {16777216.0f});
        EXPECT_EQ(inexact.notes, (std::vector<std::string>{
                                     "2 vertex quality values were rounded to the nearest float (the file has double)",
                                     "1 face quality value was rounded to the nearest float (the file has int)"}));
    }
}

TEST(PlyReader, FloatColoursAreScaledToBytesWithANote) {
    const std::string header = "element vertex 3\n" + kVertexXyz +
                               "property float red\nproperty float green\nproperty float blue\nproperty float alpha\n"
                               "element face 1\nproperty list uchar int vertex_indices\n"
                               "property double red\nproperty double green\nproperty double blue";
    for (const char* encoding : kEncodings) {
        SCOPED_TRACE(encoding);
        const LoadedMesh loaded = load(plyFile(
            encoding, header,
            {0, 0, 0, 1, 0, 0.5, 1, 1, 0, 0, 0.2, 0.4, 0.6, 0.8, 0, 1, 0, 1.5, -1, 0, 0.25, 3, 0, 1, 2, 0.1, 0.9, 0.5}));
        EXPECT_EQ(loaded.mesh.colors, (std::vector<uint8_t>{255, 0, 128, 255, 51, 102, 153, 204, 255, 0, 0, 64}));
        EXPECT_EQ(loaded.mesh.faceColors, (std::vector<uint8_t>{26, 230, 128, 255}));
        EXPECT_EQ(loaded.notes,
                  (std::vector<std::string>{
                      "the file's vertex colours were scaled from float (0..1) to bytes as round(v * 255); values clamped: "
                      "2 outside 0..1",
                      "the file's face colours were scaled from double (0..1) to bytes as round(v * 255)"}));
    }
    // Without alpha, alpha is 255 (and no note for uchar colours).
    const std::string rgb = "element vertex 3\n" + kVertexXyz +
                            "property float red\nproperty float green\nproperty float blue\nelement face 0\n"
                            "property list uchar int vertex_indices";
    const LoadedMesh opaque = load(plyFile("ascii", rgb, {0, 0, 0, 1, 1, 1, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0.5, 0.5, 0.5}));
    EXPECT_EQ(opaque.mesh.colors, (std::vector<uint8_t>{255, 255, 255, 255, 0, 0, 0, 255, 128, 128, 128, 255}));
}

TEST(PlyReader, UshortColoursAreScaledAndOtherIntegersClamped) {
    const std::string header = "element vertex 2\n" + kVertexXyz +
                               "property ushort red\nproperty ushort green\nproperty ushort blue\nproperty int alpha\n"
                               "element face 0\nproperty list uchar int vertex_indices";
    for (const char* encoding : kEncodings) {
        SCOPED_TRACE(encoding);
        const LoadedMesh loaded =
            load(plyFile(encoding, header, {0, 0, 0, 65535, 0, 32768, 200, 1, 0, 0, 257, 65534, 128, 300}));
        EXPECT_EQ(loaded.mesh.colors, (std::vector<uint8_t>{255, 0, 128, 200, 1, 255, 0, 255}));
        EXPECT_EQ(loaded.notes,
                  (std::vector<std::string>{"the file's vertex colours were scaled from ushort (0..65535) to bytes as "
                                            "round(v * 255 / 65535); values clamped: 1 outside 0..255",
                                            "the file has no faces"}));
    }
}

TEST(PlyReader, DiffuseColoursAndIntensity) {
    const std::string diffuse = "element vertex 1\n" + kVertexXyz +
                                "property uchar diffuse_red\nproperty uchar diffuse_green\nproperty uchar diffuse_blue\n"
                                "element face 0\nproperty list uchar int vertex_indices";
    EXPECT_EQ(load(plyFile("binary_little_endian", diffuse, {0, 0, 0, 1, 2, 3})).mesh.colors,
              (std::vector<uint8_t>{1, 2, 3, 255}));
    const std::string intensity = "element vertex 2\n" + kVertexXyz + "property float intensity\nelement face 0\n"
                                  "property list uchar int vertex_indices";
    const LoadedMesh grey = load(plyFile("ascii", intensity, {0, 0, 0, 0.5, 1, 0, 0, 1}));
    EXPECT_EQ(grey.mesh.colors, (std::vector<uint8_t>{128, 128, 128, 255, 255, 255, 255, 255}));
    EXPECT_EQ(grey.notes[0], "the file's vertex colours were read from its intensity property, as grey and scaled from float "
                             "(0..1) to bytes as round(v * 255)");
}

TEST(PlyReader, TexCoordsOfEveryNameAndDoubleSt) {
    for (const char* names : {"texture_u texture_v", "s t", "u v"}) {
        SCOPED_TRACE(names);
        std::istringstream pair(names);
        std::string u, v;
        pair >> u >> v;
        const std::string header = "element vertex 3\n" + kVertexXyz + "property double " + u + "\nproperty double " + v +
                                   "\nelement face 1\nproperty list uchar int vertex_indices";
        const LoadedMesh loaded =
            load(plyFile("binary_big_endian", header, {0, 0, 0, 0.25, 0.75, 1, 0, 0, 0.1, 1, 0, 1, 0, 0.5, 0, 3, 0, 1, 2}));
        expectBits(loaded.mesh.texCoords, {0.25f, 0.75f, 0.1f, 1, 0.5f, 0});
        EXPECT_EQ(loaded.notes, std::vector<std::string>{
                                    "1 vertex texture coordinate value was rounded to the nearest float (the file has double)"});
    }
}

TEST(PlyReader, HeaderLineEndingsLfCrlfAndCrOnly) {
    // The first x's bits are 0x3F80000A: little-endian, the body starts with
    // byte 10, which a CR-only header must not take for its line ending.
    float x;
    const uint32_t bits = 0x3F80000Au;
    std::memcpy(&x, &bits, 4);
    const std::string header = "comment made here\nelement vertex 3\n" + kVertexXyz +
                               "element face 1\nproperty list uchar int vertex_indices\ncomment TextureFile a b.png";
    for (const char* eol : {"\n", "\r\n", "\r"})
        for (const char* encoding : kEncodings) {
            SCOPED_TRACE(std::string(encoding) + (eol[0] == '\n' ? " LF" : eol[1] ? " CRLF" : " CR"));
            const LoadedMesh loaded = load(plyFile(encoding, header, {x, 0, 0, 1, 0, 0, 0, 1, 0, 3, 0, 1, 2}, eol));
            expectBits(loaded.mesh.positions, {x, 0, 0, 1, 0, 0, 0, 1, 0});
            EXPECT_EQ(loaded.mesh.triangles, (std::vector<uint32_t>{0, 1, 2}));
            EXPECT_EQ(loaded.mesh.textures, std::vector<std::string>{"a b.png"});
        }
}

TEST(PlyReader, CommentsOfAnyLengthAndObjInfo) {
    const std::string header = "comment " + std::string(70000, 'x') + "\nobj_info scanner 7\nelement vertex 3\n" + kVertexXyz +
                               "element face 1\nproperty list uchar int vertex_indices";
    for (const char* encoding : kEncodings) {
        const LoadedMesh loaded = load(plyFile(encoding, header, {0, 0, 0, 1, 0, 0, 0, 1, 0, 3, 0, 1, 2}));
        EXPECT_EQ(loaded.mesh.triangles, (std::vector<uint32_t>{0, 1, 2}));
        EXPECT_TRUE(loaded.notes.empty());
    }
}

TEST(PlyReader, TextureFileNamesAreKeptByteForByte) {
    const std::vector<std::string> names = {"my texture.png", "PROGRA~1/tex{1}.png", "caf\xC3\xA9.png", "  two\tblanks ",
                                            "<this>.png"};
    std::string header;
    for (const std::string& name : names) header += "comment TextureFile " + name + "\n";
    header += "element vertex 3\n" + kVertexXyz + "element face 1\nproperty list uchar int vertex_indices\n"
              "property list uchar float texcoord";
    for (const char* eol : {"\n", "\r\n", "\r"}) {
        const LoadedMesh loaded = load(plyFile("ascii", header, {0, 0, 0, 1, 0, 0, 0, 1, 0, 3, 0, 1, 2, 6, 0, 0, 1, 0, 0, 1}, eol));
        EXPECT_EQ(loaded.mesh.textures, names);
        // Several textures and corner coordinates: every face says which.
        EXPECT_EQ(loaded.mesh.faceTexture, std::vector<uint32_t>{0});
        expectBits(loaded.mesh.cornerTexCoords, {0, 0, 1, 0, 0, 1});
    }
}

TEST(PlyReader, TexNumbersAreKeptWhenTheySaySomething) {
    const std::string faces = "element vertex 3\n" + kVertexXyz +
                              "element face 2\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord\n"
                              "property int texnumber";
    const std::vector<double> positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const auto body = [&](double first, double second) {
        return concat(positions, {3, 0, 1, 2, 6, 0, 0, 1, 0, 0, 1, first, 3, 2, 1, 0, 6, 0, 1, 1, 0, 0, 0, second});
    };
    // One texture, a face naming a third: kept, with a note.
    const LoadedMesh three = load(plyFile("binary_little_endian", "comment TextureFile a.png\n" + faces, body(0, 3)));
    EXPECT_EQ(three.mesh.faceTexture, (std::vector<uint32_t>{0, 3}));
    EXPECT_EQ(three.notes, std::vector<std::string>{
                               "1 face has a texnumber naming none of the file's 1 TextureFile names (face 1: 3): kept as it is"});
    // MeshLab's "no texture" (-1) is kept as the 32-bit value it is.
    const LoadedMesh none =
        load(plyFile("ascii", "comment TextureFile a.png\ncomment TextureFile b.png\n" + faces, body(-1, 1)));
    EXPECT_EQ(none.mesh.faceTexture, (std::vector<uint32_t>{0xFFFFFFFFu, 1}));
    EXPECT_EQ(none.notes, std::vector<std::string>{
                              "1 face has a texnumber naming none of the file's 2 TextureFile names (face 0: -1): kept as it is"});
    // No TextureFile at all.
    const LoadedMesh nameless = load(plyFile("binary_big_endian", faces, body(1, 1)));
    EXPECT_EQ(nameless.mesh.faceTexture, (std::vector<uint32_t>{1, 1}));
    EXPECT_TRUE(nameless.mesh.textures.empty());
    EXPECT_EQ(nameless.notes[0], "2 faces have a texnumber naming none of the file's 0 TextureFile names (face 0: 1): kept as they are");
    // All 0 with one texture says nothing: not kept.
    const LoadedMesh zero = load(plyFile("ascii", "comment TextureFile a.png\n" + faces, body(0, 0)));
    EXPECT_TRUE(zero.mesh.faceTexture.empty());
    EXPECT_EQ(zero.mesh.textures, std::vector<std::string>{"a.png"});
    EXPECT_TRUE(zero.notes.empty());
    // A texnumber that is no whole number is refused.
    std::string fractional = faces;
    fractional.replace(fractional.find("int texnumber"), 3, "float");
    EXPECT_EQ(refusal(plyFile("ascii", fractional, body(0, 1.5))), "face 1: its texnumber 1.5 is not a texture number");
}

TEST(PlyReader, PolygonTexCoordsFollowTheirCorners) {
    const std::string header = "element vertex 4\n" + kVertexXyz +
                               "element face 1\nproperty list uchar int vertex_indices\nproperty list uchar double texcoord\n"
                               "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha";
    for (const char* encoding : kEncodings) {
        SCOPED_TRACE(encoding);
        const LoadedMesh loaded = load(
            plyFile(encoding, header, concat(kSquareValues, {4, 3, 2, 1, 0, 8, 0, 1, 1, 1, 1, 0, 0, 0, 10, 20, 30, 40})));
        EXPECT_EQ(loaded.mesh.triangles, (std::vector<uint32_t>{3, 2, 1, 3, 1, 0}));
        expectBits(loaded.mesh.cornerTexCoords, {0, 1, 1, 1, 1, 0, 0, 1, 1, 0, 0, 0});
        EXPECT_EQ(loaded.mesh.faceColors, (std::vector<uint8_t>{10, 20, 30, 40, 10, 20, 30, 40}));
        EXPECT_EQ(loaded.notes, std::vector<std::string>{
                                    "polygons were split into triangles: 2 of the 2 triangles come from polygons"});
    }
}

TEST(PlyReader, TexCoordListsMustHoldTwoValuesPerCorner) {
    const std::string header = "element vertex 3\n" + kVertexXyz +
                               "element face 2\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord";
    for (const char* encoding : kEncodings)
        EXPECT_EQ(refusal(plyFile(encoding, header,
                                  {0, 0, 0, 1, 0, 0, 0, 1, 0, 3, 0, 1, 2, 6, 0, 0, 1, 0, 0, 1, 3, 2, 1, 0, 4, 0, 0, 1, 0})),
                  "face 1 has 4 texcoord values for its 3 corners (two per corner)")
            << encoding;
}

TEST(PlyReader, TristripsAndRangeGrids) {
    const std::string strips = "element vertex 5\n" + kVertexXyz + "element tristrips 1\nproperty list int int vertex_indices";
    const std::vector<double> five = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0};
    const LoadedMesh stripped = load(plyFile("binary_big_endian", strips, concat(five, {7, 0, 1, 2, 3, -1, 4, 3})));
    // Every other triangle of a strip turned; -1 starts a new one (here too short).
    EXPECT_EQ(stripped.mesh.triangles, (std::vector<uint32_t>{0, 1, 2, 2, 1, 3}));
    // A 3 x 2 grid, cell (0, 2) empty: one square whole, one with a hole.
    const std::string grid = "obj_info num_cols 3\nobj_info num_rows 2\nelement vertex 5\n" + kVertexXyz +
                             "element range_grid 6\nproperty list uchar int vertex_indices";
    const LoadedMesh scanned = load(plyFile("ascii", grid, concat(five, {1, 0, 1, 1, 0, 1, 2, 1, 3, 1, 4})));
    EXPECT_EQ(scanned.mesh.triangles, (std::vector<uint32_t>{3, 2, 0, 0, 1, 3, 4, 3, 1}));
    EXPECT_EQ(scanned.notes, std::vector<std::string>{
                                 "polygons were split into triangles: 2 of the 3 triangles come from polygons"});
}

TEST(PlyReader, WhatTheMeshCannotHoldIsNamed) {
    const std::string header =
        "element vertex 3\n" + kVertexXyz +
        "property float curvature\nproperty float radius\nproperty int flags\nproperty list uchar int neighbours\n"
        "element face 1\nproperty list uchar int vertex_indices\nproperty float nx\nproperty float ny\nproperty float nz\n"
        "property list uchar float color\nproperty short label\n"
        "element edge 1\nproperty int vertex1\nproperty int vertex2\n"
        "element material 1\nproperty list uchar uchar name\nelement empty 0\nproperty float nothing";
    for (const char* encoding : kEncodings) {
        SCOPED_TRACE(encoding);
        const LoadedMesh loaded =
            load(plyFile(encoding, header,
                         {0, 0, 0, 0.5, 1, 7, 2, 1, 2, 1, 0, 0, 0.5, 1, 7, 0, 0, 1, 0, 0.5, 1, 7, 0, 3, 0, 1, 2, 0, 0, 1,
                          9, 1, 0, 0, 1, 0, 0, 1, 0, 0, 5, 0, 1, 3, 65, 66, 67}));
        expectBits(loaded.mesh.positions, {0, 0, 0, 1, 0, 0, 0, 1, 0});
        EXPECT_EQ(loaded.mesh.triangles, (std::vector<uint32_t>{0, 1, 2}));
        EXPECT_EQ(loaded.notes,
                  (std::vector<std::string>{
                      "the file's per-face normals, per-corner colours, vertex radii and edges are not kept in .drm files",
                      "the file's PLY properties vertex.curvature, vertex.flags, vertex.neighbours and face.label are not "
                      "kept in .drm files",
                      "the file's PLY elements material are not kept in .drm files"}));
    }
}

TEST(PlyReader, TruncatedBodiesAndCountsBeyondTheFile) {
    const std::string header = "element vertex 3\n" + kVertexXyz + "element face 2\nproperty list uchar int vertex_indices";
    const std::vector<double> values = {0, 0, 0, 1, 0, 0, 0, 1, 0, 3, 0, 1, 2, 3, 2, 1, 0};
    const std::string binary = plyFile("binary_little_endian", header, values);
    const size_t bodyStart = binary.find("end_header\n") + 11;
    EXPECT_EQ(refusal(binary.substr(0, bodyStart + 30)), "the file ends inside vertex 2 (truncated?)");
    EXPECT_EQ(refusal(binary.substr(0, binary.size() - 13)), "the file ends inside face 1 (truncated?)");
    EXPECT_EQ(refusal(binary.substr(0, binary.size() - 2)),
              "face 1 has 3 vertex_indices entries: the file ends inside it (truncated?)");
    const std::string big = plyFile("binary_big_endian", header, values);
    EXPECT_EQ(refusal(big.substr(0, big.size() - 1)), "face 1 has 3 vertex_indices entries: the file ends inside it (truncated?)");
    const std::string ascii = plyFile("ascii", header, values);
    EXPECT_EQ(refusal(ascii.substr(0, ascii.size() - 3)),
              "face 1 has 3 vertex_indices entries: the file ends inside it (truncated?)");
    EXPECT_EQ(refusal(ascii.substr(0, ascii.find("3 2 1 0"))), "the file ends inside face 1 (truncated?)");
    EXPECT_EQ(refusal(ascii.substr(0, ascii.find("3 0 1 2"))), "the header's face count 2 does not fit in the file");

    // Counts no file of this size can hold are refused before anything is allocated.
    std::string huge = binary;
    huge.replace(huge.find("vertex 3"), 8, "vertex 2000000000");
    EXPECT_EQ(refusal(huge), "the header's vertex count 2000000000 does not fit in the file");
    std::string manyFaces = ascii;
    manyFaces.replace(manyFaces.find("face 2"), 6, "face 10");  // 17 bytes left: too few for 10 ASCII faces
    EXPECT_EQ(refusal(manyFaces), "the header's face count 10 does not fit in the file (truncated?)");
    std::string longList = plyFile("binary_little_endian", "element vertex 3\n" + kVertexXyz +
                                   "element face 1\nproperty list uint int vertex_indices",
                                   {0, 0, 0, 1, 0, 0, 0, 1, 0, 3, 0, 1, 2});
    longList[longList.size() - 16] = '\xFF';  // the count's low byte: 255 entries
    EXPECT_EQ(refusal(longList), "face 0 has 255 vertex_indices entries: the file ends inside it (truncated?)");
    EXPECT_EQ(refusal(plyFile("binary_big_endian", "element vertex 3\n" + kVertexXyz +
                              "element face 1\nproperty list short int vertex_indices",
                              {0, 0, 0, 1, 0, 0, 0, 1, 0, -3})),
              "face 0 has -3 vertex_indices entries");
}

TEST(PlyReader, BadFacesAreRefusedNamingTheFace) {
    const std::string header = "element vertex 4\n" + kVertexXyz + "element face 2\nproperty list uchar int vertex_indices";
    for (const char* encoding : kEncodings) {
        SCOPED_TRACE(encoding);
        EXPECT_EQ(refusal(plyFile(encoding, header, concat(kSquareValues, {3, 0, 1, 2, 3, 0, 9, 1}))),
                  "face 1 refers to vertex 9, but the file has 4 vertices");
        EXPECT_EQ(refusal(plyFile(encoding, header, concat(kSquareValues, {3, 0, 1, 2, 4, 0, 1, 2, -1}))),
                  "face 1 refers to vertex -1, but the file has 4 vertices");
        EXPECT_EQ(refusal(plyFile(encoding, header, concat(kSquareValues, {2, 0, 1, 3, 0, 1, 2}))),
                  "face 0 has 2 corners (a face needs at least 3)");
    }
    const std::string floats = "element vertex 4\n" + kVertexXyz + "element face 1\nproperty list uchar float vertex_indices";
    EXPECT_EQ(refusal(plyFile("ascii", floats, concat(kSquareValues, {3, 0, 1.5, 2}))),
              "face 0 refers to vertex 1.5, but the file has 4 vertices");
}

TEST(PlyReader, HeaderAndTokenErrorsNameTheLine) {
    const std::string faces = "element face 0\nproperty list uchar int vertex_indices";
    EXPECT_EQ(refusal("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty foo y\n"),
              "header line 5: unknown type 'foo'");
    EXPECT_EQ(refusal("ply\nformat ascii 1.0\nelement vertex 1\nproperty list float int x\nend_header\n"),
              "header line 4: a list's count must have an integer type, not 'float'");
    EXPECT_EQ(refusal("ply\r\nformat ascii 1.0\r\nvertices 3\r\nend_header\r\n"), "header line 3: unknown keyword 'vertices'");
    EXPECT_EQ(refusal("ply\nformat ascii 1.0\nelement vertex 1\n"), "the header has no end_header line");
    EXPECT_EQ(refusal("ply\nformat ascii 1.0\nelement vertex 1\n" + kVertexXyz + "property float x\nend_header\n"),
              "header line 7: element 'vertex' has a second property 'x'");
    EXPECT_EQ(refusal("ply\nformat binary_middle_endian 1.0\nend_header\n"), "header line 2: unknown format 'binary_middle_endian'");
    EXPECT_EQ(refusal("ply\nelement vertex 1\n" + kVertexXyz + "end_header\n"), "the header names no format");
    EXPECT_EQ(refusal("PLY\nformat ascii 1.0\nend_header\n"), "not a PLY file: it does not start with \"ply\"");
    EXPECT_EQ(refusal("ply\nformat ascii 1.0\nelement vertex -1\nend_header\n"), "header line 3: bad element count '-1'");
    EXPECT_EQ(refusal("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n"),
              "the vertex element has no z property");
    EXPECT_EQ(refusal(plyFile("ascii", "element vertex 1\n" + kVertexXyz + faces, {0, 0, 0}) + "junk"),
              "");  // what follows the last element is not read
    std::string word = plyFile("ascii", "element vertex 2\n" + kVertexXyz + faces, {0, 0, 0, 1, 1, 1});
    word.replace(word.rfind("1 1 1"), 1, "one");
    EXPECT_EQ(refusal(word), "vertex 1: its x 'one' is not a number");
    std::string wide = plyFile("ascii", "element vertex 1\n" + kVertexXyz + "property uchar red\nproperty uchar green\n"
                               "property uchar blue\n" + faces, {0, 0, 0, 1, 2, 3});
    wide.replace(wide.rfind(" 3"), 2, " 256");
    EXPECT_EQ(refusal(wide), "vertex 0: its blue '256' is outside the range of uchar");
}

TEST(PlyReader, UnknownElementsBetweenKnownOnesAreReadPast) {
    // An element of lists before the faces, in every encoding: the faces
    // after it read right only if its bytes were walked exactly.
    const std::string header = "element vertex 3\n" + kVertexXyz +
                               "element note 2\nproperty list ushort double values\nproperty char tag\n"
                               "element face 1\nproperty list uchar uint vertex_indices";
    for (const char* encoding : kEncodings) {
        SCOPED_TRACE(encoding);
        const LoadedMesh loaded =
            load(plyFile(encoding, header, {0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 0.5, 1.5, -4, 0, 9, 3, 2, 0, 1}));
        EXPECT_EQ(loaded.mesh.triangles, (std::vector<uint32_t>{2, 0, 1}));
        EXPECT_EQ(loaded.notes, std::vector<std::string>{"the file's PLY elements note are not kept in .drm files"});
    }
}

TEST(PlyReader, HeadersOfManyNamesReadInLinearTime) {
    // 60,000 properties and 60,000 empty elements: a check per pair of names
    // would take minutes.
    std::string header = "element vertex 1\n" + kVertexXyz;
    std::vector<double> values = {0, 0, 0};
    for (int i = 0; i < 60000; ++i) {
        header += "property uchar p" + std::to_string(i) + "\n";
        values.push_back(i % 200);
    }
    for (int i = 0; i < 60000; ++i) header += "element e" + std::to_string(i) + " 0\nproperty float f\n";
    header += "element face 0\nproperty list uchar int vertex_indices";
    const LoadedMesh loaded = load(plyFile("binary_little_endian", header, values));
    ASSERT_EQ(loaded.notes.size(), 2u);
    EXPECT_EQ(loaded.notes[0], "the file's PLY properties vertex.p0, vertex.p1, vertex.p2, vertex.p3, vertex.p4 and 59995 more "
                               "are not kept in .drm files");
}

TEST(PlyReader, PlainCorpusLayoutMatchesTheGeneralPath) {
    // The corpus's layout (float x, y, z; uchar int lists) has a loop of its
    // own; the same mesh with a property more goes the general way.
    const std::string plain = "element vertex 4\n" + kVertexXyz + "element face 3\nproperty list uchar int vertex_indices";
    const std::string general = plain + "\nproperty uchar flags";
    const std::vector<double> faces = {3, 0, 1, 2, 5, 0, 1, 2, 3, 1, 3, 3, 2, 1};
    std::vector<double> generalFaces = {3, 0, 1, 2, 0, 5, 0, 1, 2, 3, 1, 0, 3, 3, 2, 1, 0};
    for (const char* encoding : {"binary_little_endian", "binary_big_endian"}) {
        const LoadedMesh a = load(plyFile(encoding, plain, concat(kSquareValues, faces)));
        const LoadedMesh b = load(plyFile(encoding, general, concat(kSquareValues, generalFaces)));
        EXPECT_EQ(a.mesh.triangles, (std::vector<uint32_t>{0, 1, 2, 0, 1, 2, 0, 2, 3, 0, 3, 1, 3, 2, 1}));
        EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
        EXPECT_EQ(a.notes, std::vector<std::string>{"polygons were split into triangles: 3 of the 5 triangles come from polygons"});
    }
}

}  // namespace
