// checkManifold: counts with vcg::tri::Clean on a VcgMesh copy of the mesh.
#include "drm_vcg/manifold.h"

#include "drm_vcg/vcg_mesh.h"

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <vector>

namespace drm {
namespace vcgio {

namespace {

std::string plural(size_t count, const std::string& singular, const std::string& pluralForm) {
    return std::to_string(count) + " " + (count == 1 ? singular : pluralForm);
}

std::string edgeName(size_t a, size_t b) {
    return "edge (" + std::to_string(a) + ", " + std::to_string(b) + ")";
}

}  // namespace

std::string ManifoldReport::summary() const {
    std::string out;
    auto add = [&out](const std::string& part) { out += (out.empty() ? "" : ", ") + part; };
    if (facesRepeatingVertex) add(plural(facesRepeatingVertex, "face repeating a vertex", "faces repeating a vertex"));
    if (nonManifoldEdges) add(plural(nonManifoldEdges, "non-manifold edge", "non-manifold edges"));
    if (nonManifoldVertices) add(plural(nonManifoldVertices, "non-manifold vertex", "non-manifold vertices"));
    if (misorientedEdges) add(plural(misorientedEdges, "edge with inconsistent orientation", "edges with inconsistent orientation"));
    if (out.empty()) return "manifold and consistently oriented";
    return out + "; first: " + firstProblem;
}

ManifoldReport checkManifold(const drm::Mesh& mesh) {
    ManifoldReport report;
    // Faces repeating a vertex are counted here and kept away from vcglib,
    // whose face-face walks assume three distinct corners.
    drm::Mesh proper;
    proper.positions = mesh.positions;
    std::vector<size_t> originalFace;
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        const uint32_t* t = &mesh.triangles[3 * f];
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) {
            if (report.facesRepeatingVertex++ == 0)
                report.firstProblem = "face " + std::to_string(f) + " (" + std::to_string(t[0]) + ", " +
                                      std::to_string(t[1]) + ", " + std::to_string(t[2]) +
                                      ") uses a vertex twice";
            continue;
        }
        proper.triangles.insert(proper.triangles.end(), t, t + 3);
        originalFace.push_back(f);
    }

    VcgMesh m;
    toVcg(proper, m);
    if (m.face.empty()) return report;
    vcg::tri::UpdateTopology<VcgMesh>::FaceFace(m);
    auto vertexIndex = [&m](const VcgVertex* v) { return size_t(v - &m.vert[0]); };
    auto faceIndex = [&m, &originalFace](const VcgFace* f) { return originalFace[size_t(f - &m.face[0])]; };

    report.nonManifoldEdges = size_t(vcg::tri::Clean<VcgMesh>::CountNonManifoldEdgeFF(m, false));
    if (report.nonManifoldEdges > 0 && report.firstProblem.empty()) {
        for (VcgFace& f : m.face) {
            for (int i = 0; i < 3 && report.firstProblem.empty(); ++i) {
                if (vcg::face::IsManifold(f, i)) continue;
                // Name a few of the faces around the edge, not all of a fan of 20.
                const size_t listed = 6;
                std::string faces;
                size_t count = 0;
                vcg::face::Pos<VcgFace> ring(&f, i);
                do {
                    if (count < listed) faces += (count ? ", " : "") + std::to_string(faceIndex(ring.F()));
                    ++count;
                    ring.NextF();
                } while (ring.F() != &f && count < 100000);
                if (count > listed) faces += " and " + std::to_string(count - listed) + " more";
                report.firstProblem = edgeName(vertexIndex(f.V0(i)), vertexIndex(f.V1(i))) + " is shared by " +
                                      std::to_string(count) + " faces (" + faces + ")";
            }
            if (!report.firstProblem.empty()) break;
        }
    }

    report.nonManifoldVertices = size_t(vcg::tri::Clean<VcgMesh>::CountNonManifoldVertexFF(m, true, true));
    if (report.nonManifoldVertices > 0 && report.firstProblem.empty()) {
        for (size_t v = 0; v < m.vert.size(); ++v) {
            if (!m.vert[v].IsS()) continue;
            report.firstProblem = "vertex " + std::to_string(v) +
                                  " joins faces that do not form a single fan around it";
            break;
        }
    }

    // Orientation is only well defined across edges with exactly two faces.
    if (report.nonManifoldEdges == 0) {
        for (VcgFace& f : m.face) {
            for (int i = 0; i < 3; ++i) {
                if (vcg::face::IsBorder(f, i) || vcg::face::CheckOrientation(f, i)) continue;
                VcgFace* other = f.FFp(i);
                if (&f > other) continue;  // each edge once
                ++report.misorientedEdges;
                if (report.firstProblem.empty())
                    report.firstProblem = "faces " + std::to_string(faceIndex(&f)) + " and " +
                                          std::to_string(faceIndex(other)) + " both run from vertex " +
                                          std::to_string(vertexIndex(f.V0(i))) + " to vertex " +
                                          std::to_string(vertexIndex(f.V1(i)));
            }
        }
    }
    return report;
}

}  // namespace vcgio
}  // namespace drm
