#include "test_meshes.h"

#include <cmath>
#include <map>
#include <utility>

namespace drm_test {
namespace {

// A fixed integer hash (no std:: distributions, whose output differs
// between standard libraries), mapped to [-1, 1).
double hashUnit(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7FEB352Du;
    x ^= x >> 15;
    x *= 0x846CA68Bu;
    x ^= x >> 16;
    return double(x) / 2147483648.0 - 1.0;
}

void addFace(drm::Mesh& mesh, uint32_t a, uint32_t b, uint32_t c) {
    mesh.triangles.insert(mesh.triangles.end(), {a, b, c});
}

}  // namespace

void addVertex(drm::Mesh& mesh, float x, float y, float z) { mesh.positions.insert(mesh.positions.end(), {x, y, z}); }

drm::Mesh fan(uint32_t rim) {
    drm::Mesh disc;
    disc.positions = {0, 0, 0};
    for (uint32_t k = 0; k < rim; ++k) {
        const float u = float(k % (rim / 4)) / float(rim / 4), side = float(k / (rim / 4));
        const float x = side == 0 ? u : side == 1 ? 1 : side == 2 ? 1 - u : 0;
        const float y = side == 0 ? 0 : side == 1 ? u : side == 2 ? 1 : 1 - u;
        disc.positions.insert(disc.positions.end(), {x - 0.5f, y - 0.5f, 0.f});
    }
    for (uint32_t k = 0; k < rim; ++k) disc.triangles.insert(disc.triangles.end(), {0, 1 + k, 1 + (k + 1) % rim});
    return disc;
}

drm::Mesh tetrahedron() {
    drm::Mesh m;
    addVertex(m, 0, 0, 0);
    addVertex(m, 1, 0, 0);
    addVertex(m, 0, 1, 0);
    addVertex(m, 0, 0, 1);
    addFace(m, 0, 2, 1);
    addFace(m, 0, 1, 3);
    addFace(m, 0, 3, 2);
    addFace(m, 1, 2, 3);
    return m;
}

drm::Mesh icosphere(int subdivisions) {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<double> p = {-1, t, 0, 1, t, 0, -1, -t, 0, 1, -t, 0, 0, -1, t, 0, 1, t,
                             0, -1, -t, 0, 1, -t, t, 0, -1, t, 0, 1, -t, 0, -1, -t, 0, 1};
    std::vector<uint32_t> faces = {0, 11, 5, 0, 5, 1,  0, 1,  7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                                   4, 11, 10, 2, 10, 7, 6, 7, 1,  8, 3, 9,  4, 3,  4,  2, 3, 2, 6, 3,
                                   6, 8,  3, 8, 9, 4, 9, 5, 2,  4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
    auto project = [&](size_t v) {
        const double x = p[3 * v], y = p[3 * v + 1], z = p[3 * v + 2];
        const double length = std::sqrt(x * x + y * y + z * z);
        p[3 * v] = x / length;
        p[3 * v + 1] = y / length;
        p[3 * v + 2] = z / length;
    };
    for (size_t v = 0; v < 12; ++v) project(v);
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            const auto key = std::make_pair(std::min(a, b), std::max(a, b));
            const auto found = midpoints.find(key);
            if (found != midpoints.end()) return found->second;
            const uint32_t m = uint32_t(p.size() / 3);
            for (int k = 0; k < 3; ++k) p.push_back((p[3 * size_t(a) + k] + p[3 * size_t(b) + k]) / 2.0);
            project(m);
            midpoints.emplace(key, m);
            return m;
        };
        std::vector<uint32_t> finer;
        for (size_t f = 0; f < faces.size(); f += 3) {
            const uint32_t a = faces[f], b = faces[f + 1], c = faces[f + 2];
            const uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
            finer.insert(finer.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
        }
        faces.swap(finer);
    }
    drm::Mesh m;
    m.positions.assign(p.begin(), p.end());
    m.triangles = faces;
    return m;
}

drm::Mesh gridPatch(int cells, bool withHole, double jitter, uint32_t seed) {
    drm::Mesh m;
    const int side = cells + 1;
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i) {
            const uint32_t id = uint32_t(j * side + i);
            const bool inside = i > 0 && j > 0 && i < cells && j < cells;  // keep the border straight
            const double jx = inside ? jitter * hashUnit(2 * id + seed * 7919u) : 0;
            const double jy = inside ? jitter * hashUnit(2 * id + 1 + seed * 7919u) : 0;
            const double x = (i + jx) / cells, y = (j + jy) / cells;
            const double z = 0.25 - ((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5));
            addVertex(m, float(x), float(y), float(z));
        }
    const int c = cells / 2;
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            if (withHole && (i == c - 1 || i == c) && (j == c - 1 || j == c)) continue;
            const uint32_t v00 = uint32_t(j * side + i), v10 = v00 + 1, v01 = v00 + uint32_t(side), v11 = v01 + 1;
            if ((i + j) % 2 == 0) {
                addFace(m, v00, v10, v11);
                addFace(m, v00, v11, v01);
            } else {
                addFace(m, v00, v10, v01);
                addFace(m, v10, v11, v01);
            }
        }
    return m;
}

drm::Mesh boxRing(int cells) {
    // The outer surface of the unit cubes on the border of a cells x cells
    // square: each cube face without a cube behind it is two triangles,
    // corners listed counter-clockwise seen from outside.
    auto filled = [&](int x, int y, int z) {
        return z == 0 && x >= 0 && y >= 0 && x < cells && y < cells && (x == 0 || y == 0 || x == cells - 1 || y == cells - 1);
    };
    drm::Mesh m;
    std::map<int, uint32_t> ids;
    auto vertex = [&](int x, int y, int z) {
        const int key = (x * 64 + y) * 64 + z;
        const auto found = ids.find(key);
        if (found != ids.end()) return found->second;
        const uint32_t id = uint32_t(m.positions.size() / 3);
        addVertex(m, float(x), float(y), float(z));
        ids.emplace(key, id);
        return id;
    };
    struct Side {
        int dx, dy, dz;
        int corner[4][3];
    };
    static const Side sides[6] = {
        {1, 0, 0, {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}},
        {-1, 0, 0, {{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}}},
        {0, 1, 0, {{0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}}},
        {0, -1, 0, {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}},
        {0, 0, 1, {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}},
        {0, 0, -1, {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}},
    };
    for (int y = 0; y < cells; ++y)
        for (int x = 0; x < cells; ++x) {
            if (!filled(x, y, 0)) continue;
            for (const Side& s : sides) {
                if (filled(x + s.dx, y + s.dy, s.dz)) continue;
                uint32_t q[4];
                for (int k = 0; k < 4; ++k) q[k] = vertex(x + s.corner[k][0], y + s.corner[k][1], s.corner[k][2]);
                addFace(m, q[0], q[1], q[2]);
                addFace(m, q[0], q[2], q[3]);
            }
        }
    return m;
}

drm::Mesh append(const drm::Mesh& a, const drm::Mesh& b, float dx, float dy, float dz) {
    drm::Mesh m = a;
    const uint32_t base = uint32_t(a.vertexCount());
    for (size_t v = 0; v < b.vertexCount(); ++v)
        addVertex(m, b.positions[3 * v] + dx, b.positions[3 * v + 1] + dy, b.positions[3 * v + 2] + dz);
    for (uint32_t index : b.triangles) m.triangles.push_back(base + index);
    return m;
}

drm::Mesh meshNeedingRepairs() {
    drm::Mesh m = icosphere(1);
    std::vector<uint32_t>& t = m.triangles;
    std::swap(t[4], t[5]);                    // face 1 turned over
    t.insert(t.end(), {t[6], t[7], t[8]});    // face 2 doubled
    const uint32_t a = t[9], b = t[10];       // a fin on face 3's first edge
    addVertex(m, 0.1f, 0.2f, 2.0f);
    t.insert(t.end(), {a, b, uint32_t(m.vertexCount() - 1)});
    t.insert(t.end(), {t[12], t[12], t[13]}); // a face repeating a vertex
    return m;
}

drm::Mesh mixedMesh() {
    drm::Mesh m = append(gridPatch(10, true), tetrahedron(), 1.5f, 0.25f, 0.0f);
    addVertex(m, -0.5f, 0.5f, 0.75f);
    return m;
}

std::vector<NamedMesh> smallMeshes() {
    std::vector<NamedMesh> meshes;
    drm::Mesh triangle;
    addVertex(triangle, 0, 0, 0);
    addVertex(triangle, 1, 0, 0);
    addVertex(triangle, 0.25f, 1, 0);
    addFace(triangle, 0, 1, 2);
    meshes.push_back({"triangle", triangle});
    meshes.push_back({"tetrahedron", tetrahedron()});
    meshes.push_back({"two-tetrahedra", append(tetrahedron(), tetrahedron(), 2.0f, 0.5f, 0.0f)});
    drm::Mesh isolated = tetrahedron();
    addVertex(isolated, 2, 2, 2);
    addVertex(isolated, -1, 0.5f, 0);
    addVertex(isolated, 0.25f, 0.25f, 0.25f);  // inside the tetrahedron
    meshes.push_back({"isolated-vertices", isolated});
    meshes.push_back({"grid-hole", gridPatch(6, true)});
    meshes.push_back({"grid-jittered", gridPatch(6, false, 0.2, 1)});
    meshes.push_back({"icosphere", icosphere(1)});
    meshes.push_back({"box-ring", boxRing(3)});
    meshes.push_back({"mixed", mixedMesh()});
    meshes.push_back({"needs-repairs", meshNeedingRepairs()});
    return meshes;
}

}  // namespace drm_test
