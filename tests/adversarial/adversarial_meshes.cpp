#include "adversarial_meshes.h"

#include <cmath>

#include "test_meshes.h"

namespace adversarial {
namespace {

using drm_test::addVertex;

void addFace(drm::Mesh& m, uint32_t a, uint32_t b, uint32_t c) { m.triangles.insert(m.triangles.end(), {a, b, c}); }

// A fixed integer hash mapped to [0, 1), so every build makes the same meshes.
double hashUnit(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7FEB352Du;
    x ^= x >> 15;
    x *= 0x846CA68Bu;
    x ^= x >> 16;
    return double(x) / 4294967296.0;
}

void flipFace(drm::Mesh& m, size_t f) { std::swap(m.triangles[3 * f + 1], m.triangles[3 * f + 2]); }

// Two triangles sharing only vertex 0.
drm::Mesh bowtie() {
    drm::Mesh m;
    addVertex(m, 0, 0, 0);
    addVertex(m, 1, 0.5f, 0);
    addVertex(m, 1, -0.5f, 0);
    addVertex(m, -1, -0.5f, 0);
    addVertex(m, -1, 0.5f, 0);
    addFace(m, 0, 2, 1);
    addFace(m, 0, 4, 3);
    return m;
}

// Three faces on the edge 0-1.
drm::Mesh fin() {
    drm::Mesh m;
    addVertex(m, 0, 0, 0);
    addVertex(m, 1, 0, 0);
    addVertex(m, 0.5f, 1, 0);
    addVertex(m, 0.5f, -1, 0);
    addVertex(m, 0.5f, 0, 1);
    addFace(m, 0, 1, 2);
    addFace(m, 1, 0, 3);
    addFace(m, 1, 0, 4);
    return m;
}

// `pages` faces on the spine 0-1, all running 0 -> 1.
drm::Mesh book(int pages) {
    drm::Mesh m;
    addVertex(m, 0, 0, 0);
    addVertex(m, 0, 0, 1);
    for (int p = 0; p < pages; ++p) {
        const double angle = 5.0 * p / pages;  // spread over ~290 degrees
        addVertex(m, float(std::cos(angle)), float(std::sin(angle)), 0.5f);
        addFace(m, 0, 1, uint32_t(2 + p));
    }
    return m;
}

// A closed tetrahedron and its mirror image through vertex 0 (the origin).
drm::Mesh tetrahedraSharingAVertex() {
    drm::Mesh m = drm_test::tetrahedron();
    const size_t faces = m.faceCount();
    for (uint32_t v = 1; v < 4; ++v) addVertex(m, -m.positions[3 * v], -m.positions[3 * v + 1], -m.positions[3 * v + 2]);
    auto mirror = [](uint32_t v) { return v == 0 ? 0u : v + 3; };
    for (size_t f = 0; f < faces; ++f)  // mirrored, so turned over to face outwards
        addFace(m, mirror(m.triangles[3 * f]), mirror(m.triangles[3 * f + 2]), mirror(m.triangles[3 * f + 1]));
    return m;
}

// A strip of `quads` quads (two triangles each) closed with a half twist.
drm::Mesh mobiusStrip(int quads) {
    const double pi = 3.14159265358979323846;
    drm::Mesh m;
    for (int i = 0; i < quads; ++i) {
        const double theta = 2 * pi * i / quads, phi = theta / 2;
        const double cx = 2 * std::cos(theta), cy = 2 * std::sin(theta);
        const double dx = 0.5 * std::cos(phi) * std::cos(theta), dy = 0.5 * std::cos(phi) * std::sin(theta),
                     dz = 0.5 * std::sin(phi);
        addVertex(m, float(cx + dx), float(cy + dy), float(dz));  // 2i: top
        addVertex(m, float(cx - dx), float(cy - dy), float(-dz));  // 2i + 1: bottom
    }
    for (int i = 0; i < quads; ++i) {
        const uint32_t top = uint32_t(2 * i), bottom = top + 1;
        const bool last = i == quads - 1;  // after the half twist top and bottom swap
        const uint32_t nextTop = last ? 1u : top + 2, nextBottom = last ? 0u : top + 3;
        addFace(m, top, bottom, nextBottom);
        addFace(m, top, nextBottom, nextTop);
    }
    return m;
}

drm::Mesh closedWithOneFaceFlipped() {
    drm::Mesh m = drm_test::icosphere(1);
    flipFace(m, 17);
    return m;
}

drm::Mesh closedWithHalfTheFacesFlipped() {
    drm::Mesh m = drm_test::icosphere(1);
    for (size_t f = 0; f < m.faceCount(); ++f)
        if (hashUnit(uint32_t(f) + 1000) < 0.5) flipFace(m, f);
    return m;
}

// A closed mesh with one face listed twice, the copy turned over or not.
drm::Mesh closedWithADoubledFace(bool turnedOver) {
    drm::Mesh m = drm_test::icosphere(1);
    const uint32_t* t = &m.triangles[3 * 5];
    const uint32_t a = t[0], b = t[1], c = t[2];
    if (turnedOver)
        addFace(m, a, c, b);
    else
        addFace(m, a, b, c);
    return m;
}

// Two faces over the same three vertices, the second turned over: a closed
// surface, manifold and consistently oriented, though a duplicated face.
drm::Mesh pillow() {
    drm::Mesh m;
    addVertex(m, 0, 0, 0);
    addVertex(m, 1, 0, 0);
    addVertex(m, 0, 1, 0);
    addFace(m, 0, 1, 2);
    addFace(m, 0, 2, 1);
    return m;
}

// The same face twice, same orientation, nothing else.
drm::Mesh twinFaces() {
    drm::Mesh m = pillow();
    flipFace(m, 1);
    return m;
}

// A grid cut in two along a column: the cut's vertices are listed twice,
// each copy at the same position as its original (a texture seam).
drm::Mesh gridWithASeam() {
    const int cells = 6, side = cells + 1, seam = 3;
    drm::Mesh m = drm_test::gridPatch(cells, false);
    std::vector<uint32_t> copyOf(size_t(side * side), 0);
    for (int j = 0; j < side; ++j) {
        const uint32_t v = uint32_t(j * side + seam);
        copyOf[v] = uint32_t(m.vertexCount());
        addVertex(m, m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]);
    }
    for (size_t f = 0; f < m.faceCount(); ++f) {
        uint32_t* t = &m.triangles[3 * f];
        const bool rightOfSeam = int(t[0] % side) > seam || int(t[1] % side) > seam || int(t[2] % side) > seam;
        if (!rightOfSeam) continue;
        for (int k = 0; k < 3; ++k)
            if (int(t[k] % side) == seam) t[k] = copyOf[t[k]];
    }
    return m;
}

// `count` small triangles at random places in the unit cube, no vertex shared.
drm::Mesh triangleSoup(int count) {
    drm::Mesh m;
    for (int f = 0; f < count; ++f) {
        const uint32_t seed = uint32_t(f) * 16;
        const double cx = hashUnit(seed), cy = hashUnit(seed + 1), cz = hashUnit(seed + 2);
        for (uint32_t k = 0; k < 3; ++k)
            addVertex(m, float(cx + 0.1 * hashUnit(seed + 3 + 3 * k)), float(cy + 0.1 * hashUnit(seed + 4 + 3 * k)),
                      float(cz + 0.1 * hashUnit(seed + 5 + 3 * k)));
        addFace(m, uint32_t(3 * f), uint32_t(3 * f + 1), uint32_t(3 * f + 2));
    }
    return m;
}

// A closed mesh with faces (a, a, b), (b, a, a), (a, b, a) and (a, a, a)
// mixed in among its faces, one of them twice.
drm::Mesh closedWithFacesRepeatingAVertex() {
    drm::Mesh m = drm_test::icosphere(1);
    std::vector<uint32_t> triangles;
    const uint32_t extra[][3] = {{0, 0, 5}, {7, 3, 3}, {9, 9, 9}, {4, 2, 4}, {0, 0, 5}};
    for (size_t f = 0; f < m.faceCount(); ++f) {
        triangles.insert(triangles.end(), &m.triangles[3 * f], &m.triangles[3 * f] + 3);
        if (f % 16 == 3) triangles.insert(triangles.end(), extra[f / 16], extra[f / 16] + 3);
    }
    m.triangles = triangles;
    return m;
}

// Faces that keep three distinct indices but lose their area on the grid:
// a flattened tetrahedron whose fourth vertex is within a 12-bit step of
// the first (two faces become segments), a face shrunk to a point, and a
// face whose corners are collinear even in float.
drm::Mesh facesCollapsingOnTheGrid() {
    drm::Mesh m;
    addVertex(m, 0, 0, 0);  // a large face, to set the bounding box
    addVertex(m, 1, 0, 0);
    addVertex(m, 0, 1, 1);
    addFace(m, 0, 1, 2);
    const uint32_t a = 3, b = 4, c = 5, d = 6;
    addVertex(m, 0.25f, 0.25f, 0.5f);
    addVertex(m, 0.75f, 0.25f, 0.5f);
    addVertex(m, 0.5f, 0.75f, 0.5f);
    addVertex(m, 0.25f + 2e-5f, 0.25f + 1e-5f, 0.5f + 1e-5f);
    addFace(m, a, c, b);
    addFace(m, a, b, d);
    addFace(m, a, d, c);
    addFace(m, b, c, d);
    addVertex(m, 0.8f, 0.8f, 0.8f);  // 7, 8, 9: a point
    addVertex(m, 0.8f + 1e-6f, 0.8f, 0.8f);
    addVertex(m, 0.8f, 0.8f + 1e-6f, 0.8f);
    addFace(m, 7, 8, 9);
    addVertex(m, 0, 0.5f, 0.25f);  // 10, 11, 12: a segment
    addVertex(m, 0.5f, 0.5f, 0.25f);
    addVertex(m, 1, 0.5f, 0.25f);
    addFace(m, 10, 11, 12);
    return m;
}

// A tetrahedron among unreferenced vertices: one listed first, one on a
// vertex of the tetrahedron, two at one place, one inside, one far away.
drm::Mesh isolatedVertices() {
    drm::Mesh m;
    addVertex(m, -1, 2, 0.5f);
    m = drm_test::append(m, drm_test::tetrahedron(), 0, 0, 0);
    addVertex(m, 0, 0, 0);
    addVertex(m, -1, -1, -1);
    addVertex(m, -1, -1, -1);
    addVertex(m, 0.2f, 0.2f, 0.2f);
    addVertex(m, 40, 3, -7);
    return m;
}

// Vertices and no faces at all.
drm::Mesh pointsOnly() {
    drm::Mesh m;
    for (uint32_t v = 0; v < 6; ++v) addVertex(m, float(hashUnit(3 * v)), float(hashUnit(3 * v + 1)), float(hashUnit(3 * v + 2)));
    return m;
}

// Every face repeats a vertex; one is listed twice, once from another corner.
drm::Mesh onlyDegenerateFaces() {
    drm::Mesh m;
    addVertex(m, 0, 0, 0);
    addVertex(m, 1, 0, 0);
    addVertex(m, 0, 1, 0);
    addVertex(m, 0, 0, 1);
    addFace(m, 0, 0, 1);
    addFace(m, 2, 2, 2);
    addFace(m, 3, 1, 3);
    addFace(m, 1, 1, 1);
    addFace(m, 1, 0, 0);  // (0, 0, 1) from its third corner
    addFace(m, 2, 3, 3);
    return m;
}

// One vertex and the face (0, 0, 0): a bounding box of size zero too.
drm::Mesh singlePointFace() {
    drm::Mesh m;
    addVertex(m, 3, -2, 1);
    addFace(m, 0, 0, 0);
    return m;
}

// Several of the above in one mesh, side by side.
drm::Mesh everythingAtOnce() {
    drm::Mesh m = bowtie();
    m = drm_test::append(m, fin(), 3, 0, 0);
    m = drm_test::append(m, mobiusStrip(10), 0, 6, 0);
    m = drm_test::append(m, closedWithHalfTheFacesFlipped(), 6, 0, 0);
    m = drm_test::append(m, closedWithADoubledFace(true), 6, 3, 0);
    m = drm_test::append(m, closedWithFacesRepeatingAVertex(), 9, 0, 0);
    m = drm_test::append(m, facesCollapsingOnTheGrid(), 9, 3, 0);
    m = drm_test::append(m, book(5), 0, 0, 3);
    m = drm_test::append(m, isolatedVertices(), 3, 3, 3);
    return m;
}

}  // namespace

const std::vector<AdversarialMesh>& adversarialMeshes() {
    static const std::vector<AdversarialMesh> all = {
        // Clean controls.
        {"tetrahedron", drm_test::tetrahedron(), Repair::None},
        {"icosphere", drm_test::icosphere(2), Repair::None},
        {"grid_with_hole", drm_test::gridPatch(8, true), Repair::None},
        // Topologically clean but geometrically hostile.
        {"coincident_vertices_seam", gridWithASeam(), Repair::None},
        {"soup_of_100_triangles", triangleSoup(100), Repair::None},
        {"faces_collapsing_on_grid", facesCollapsingOnTheGrid(), Repair::None},
        {"isolated_vertices", isolatedVertices(), Repair::None},
        {"points_only", pointsOnly(), Repair::None},
        {"pillow", pillow(), Repair::None},
        // Non-manifold.
        {"bowtie", bowtie(), Repair::SplitVertices},
        {"fin", fin(), Repair::SplitVertices},
        {"book_of_5_pages", book(5), Repair::SplitVertices},
        {"tetrahedra_sharing_a_vertex", tetrahedraSharingAVertex(), Repair::SplitVertices},
        // Orientation.
        {"mobius_strip", mobiusStrip(10), Repair::Some},
        {"closed_one_face_flipped", closedWithOneFaceFlipped(), Repair::FlipFaces},
        {"closed_half_faces_flipped", closedWithHalfTheFacesFlipped(), Repair::FlipFaces},
        // Duplicated faces.
        {"closed_doubled_face", closedWithADoubledFace(false), Repair::RepeatedFaces},
        {"closed_doubled_face_turned_over", closedWithADoubledFace(true), Repair::RepeatedFaces},
        {"twin_faces", twinFaces(), Repair::RepeatedFaces},
        // Faces repeating a vertex.
        {"closed_with_faces_repeating_a_vertex", closedWithFacesRepeatingAVertex(), Repair::LooseFaces},
        {"only_degenerate_faces", onlyDegenerateFaces(), Repair::LooseFaces},
        {"single_point_face", singlePointFace(), Repair::LooseFaces},
        {"everything_at_once", everythingAtOnce(), Repair::Some},
    };
    return all;
}

}  // namespace adversarial
