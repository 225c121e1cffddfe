// Small meshes built in code, for tests that must not depend on data files:
// robustness tests, the fuzzer's seed corpus, the cross-build determinism
// check. Every coordinate is computed with +, -, *, / and sqrt only (no
// libm transcendentals, no std:: random distributions), so each compiler
// and optimization level builds bit-identical meshes.
#ifndef DRM_TEST_TEST_MESHES_H
#define DRM_TEST_TEST_MESHES_H

#include <cstdint>
#include <string>
#include <vector>

#include "drmcodec/drmcodec.h"

namespace drm_test {

// Four faces, outward oriented.
drm::Mesh tetrahedron();
// A flat square disc fanned around its centre: one vertex of `rim` faces
// (rim a multiple of 4), the hub the topological coder takes alone.
drm::Mesh fan(uint32_t rim);

// An icosahedron with each face split into four, `subdivisions` times,
// projected onto the unit sphere: closed, 10 * 4^s + 2 vertices.
drm::Mesh icosphere(int subdivisions);

// cells x cells quads over the unit square, two triangles each, diagonals
// alternating, lifted into a gentle bump. With a hole, the 2 x 2 cells around
// the centre are left out, so the centre vertex is isolated (cells must be
// even and >= 4). jitter > 0 moves every vertex by up to jitter cell sizes
// along x and y (a fixed hash of its index, seed picks the hash), which makes
// the mesh irregular without folding it as long as jitter < 0.25.
drm::Mesh gridPatch(int cells, bool withHole, double jitter = 0, uint32_t seed = 0);

// A torus-like closed mesh without trigonometry: the boundary of a
// rows x columns x 1 ring of cubes (genus 1).
drm::Mesh boxRing(int cells);

// b's vertices and faces appended to a's, b moved by (dx, dy, dz).
drm::Mesh append(const drm::Mesh& a, const drm::Mesh& b, float dx, float dy, float dz);
void addVertex(drm::Mesh& mesh, float x, float y, float z);

struct NamedMesh {
    std::string name;
    drm::Mesh mesh;
};

// The robustness tests' mesh: a 10 x 10 grid with a hole, a tetrahedron and
// an isolated vertex (three components plus two isolated vertices).
drm::Mesh mixedMesh();

// A closed icosphere given every defect the repairs section undoes: a face
// turned over, a doubled face, a fin (a third face on an edge) and a face
// repeating a vertex. Its files carry a repairs section.
drm::Mesh meshNeedingRepairs();

// A handful of small meshes covering the decoder's cases: one triangle, a
// tetrahedron, several components, isolated vertices, a hole, a closed
// sphere, genus 1. All under 200 faces.
std::vector<NamedMesh> smallMeshes();

}  // namespace drm_test

#endif  // DRM_TEST_TEST_MESHES_H
