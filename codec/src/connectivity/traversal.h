// The edge traversal shared by encoder and decoder (paper, Tables 1 and 2).
//
// It holds only what the decoder knows: the triangles rebuilt so far, which
// directed edges they use, which edges were coded as boundary, and how many
// open edges each vertex still has. The encoder drives it with the true apex
// of each open edge, the decoder with the apex found from the decoded rank;
// because both run this one class, they visit the same edges in the same
// order and cull the same vertices.
#ifndef DRM_TRAVERSAL_H
#define DRM_TRAVERSAL_H

#include <cstdint>
#include <deque>
#include <utility>
#include <vector>

#include "connectivity/halfedge_map.h"

namespace drm {

class SpatialIndex;

// A directed edge (vi, vj) of a rebuilt triangle (vi, vj, opposite) whose
// other side is still unknown. The triangle to find there is (vj, vi, apex).
struct OpenEdge {
    uint32_t vi = 0, vj = 0, opposite = 0;
};

class Traversal {
public:
    // candidates, if given, loses each vertex as soon as it is culled.
    Traversal(size_t vertexCount, size_t expectedFaces, SpatialIndex* candidates);

    // Inserts a component's start triangle and queues its three edges.
    // Throws Error if a vertex is out of range, repeated, or already used
    // (a kept vertex may be, by an edge it does not share).
    void startComponent(uint32_t a, uint32_t b, uint32_t c);

    // Two connectivity parts (connectivity_parts.h): vertices whose faces
    // in a part may form several fans are never culled there (a vertex is
    // culled once its open edges run out, which would end it after its
    // first fan). Before the first component.
    void keepVertex(uint32_t v);

    // Makes room for vertices up to n - 1 (a decoder that meets its vertices
    // as it goes, topological_coder.h: a header's count is only a claim).
    void growVertices(size_t n) {
        if (n <= openEdges_.size()) return;
        openEdges_.resize(n, 0);
        state_.resize(n, kUntouched);
        if (trackPieces_) pieces_.resize(n);
        if (!kept_.empty()) kept_.resize(n, 0);
    }
    // Right edges to the front too, just behind the left edge: the walk
    // then closes the region it is in before it turns back, as Edgebreaker
    // does, and the front stays one loop far more often (the topological
    // coder's order; the distance ranks keep the paper's). Before the first
    // component.
    void setDepthFirst() { depthFirst_ = true; }
    // Pops edges from the front of the deque until one is open (no triangle
    // and no boundary code on its other side yet). False when none is left.
    bool popOpenEdge(OpenEdge& edge);

    // Records the rank-0 code: nothing lies on the other side of edge.
    void closeAsBoundary(const OpenEdge& edge);

    // Inserts the triangle (vj, vi, apex) across edge; queues its left edge
    // (vi, apex) at the front and its right edge (apex, vj) at the back.
    // Throws Error if the triangle would reuse a directed edge or a culled
    // vertex (only a corrupt stream can ask for that).
    void attachApex(const OpenEdge& edge, uint32_t apex);

    // The third vertex of the rebuilt triangle holding the directed edge
    // (a, b); kNoTriangle if there is none, kBoundary if (b, a) was coded
    // as a boundary edge (so (a, b) is its missing twin).
    static constexpr uint32_t kNoTriangle = HalfEdgeMap::kAbsent;
    static constexpr uint32_t kBoundary = 0xFFFFFFFEu;
    uint32_t thirdVertex(uint32_t a, uint32_t b) const { return halfEdges_.find(a, b); }

    // The rebuilt triangles around a vertex v form pieces of its fan:
    // chains of triangles (v, x0, x1), (v, x1, x2) .. (v, x[k-1], x[k]),
    // each joined to the next by an edge at v, ending where the edge has no
    // triangle on its other side yet. Each piece's two ends are kept as
    // triangles are inserted (a few table updates per triangle), so that a
    // piece's far end is one look-up, not a walk around the fan: a walk
    // around a vertex of valence d is O(d), which makes the rebuild O(d^2)
    // (a disc of 40,000 triangles fanned around its centre takes seconds).
    //
    // Only a traversal told to (trackFanPieces, before the first
    // component) keeps them; the topological coder, which asks at every
    // edge, does. The distance ranks walk (fanEnds), as their searches
    // around a vertex of high valence cost as much again, and the pieces
    // (12 bytes a vertex) would raise their decoder's peak memory by about
    // 7 %.
    void trackFanPieces();
    bool tracksFanPieces() const { return trackPieces_; }
    // fanEndFrom(v, x0): x[k] of v's piece whose first triangle is
    // (v, x0, x1), or kNoTriangle if (v, x0) starts no piece.
    // fanStartTo(xk, v): x0 of v's piece whose last triangle is
    // (v, x[k-1], xk), or kNoTriangle if (xk, v) ends none.
    uint32_t fanEndFrom(uint32_t v, uint32_t x0) const {
        const Pieces& p = pieces_[v];
        if (p.start == x0) return p.end;
        return p.more == 0 ? kNoTriangle : fanEnd_.find(v, x0);
    }
    uint32_t fanStartTo(uint32_t xk, uint32_t v) const {
        const Pieces& p = pieces_[v];
        if (p.end == xk) return p.start;
        return p.more == 0 ? kNoTriangle : fanStart_.find(xk, v);
    }

    // Triangles of the component being rebuilt (the start triangle counts).
    size_t componentTriangleCount() const { return triangleCount() - componentStart_; }

    bool isCulled(uint32_t v) const { return state_[v] == kCulled; }
    bool isTouched(uint32_t v) const { return state_[v] != kUntouched; }
    size_t vertexCount() const { return openEdges_.size(); }

    // Rebuilt triangles, in the order they were inserted.
    const std::vector<uint32_t>& triangles() const { return triangles_; }
    // Hands them over at the end, trimmed to their size (the decoder's
    // table grew by doubling from a bounded guess); the traversal is done
    // with then.
    std::vector<uint32_t> takeTriangles() {
        triangles_.shrink_to_fit();
        return std::move(triangles_);
    }
    size_t triangleCount() const { return triangles_.size() / 3; }

private:
    enum : uint8_t { kUntouched = 0, kActive = 1, kCulled = 2 };

    void addHalfEdge(uint32_t a, uint32_t b, uint32_t opposite);
    // Triangle (v, p, q) joins v's fan pieces ending at p and starting at q.
    void linkCorner(uint32_t v, uint32_t p, uint32_t q);
    void addPiece(uint32_t v, uint32_t start, uint32_t end);
    void removePiece(uint32_t v, uint32_t start, uint32_t end);
    void insertHalfEdge(uint32_t a, uint32_t b, uint32_t value);
    // The half-edge table's first capacity: it grows with the front.
    static constexpr size_t kFirstHalfEdges = 4096;
    // The table holds only the front (rebuildKeeping), so it is small, and
    // it is searched several times per triangle: kept at most a quarter
    // full, its probe runs are short and their branches well predicted
    // (docs/tuning.md).
    static constexpr size_t kHalfEdgeSlotsPerEdge = 4;
    void releaseIfDone(uint32_t v);

    // Directed edge (a, b) -> the third vertex of its triangle, or kBoundary
    // for the missing twin of an edge that was coded as boundary.
    HalfEdgeMap halfEdges_;
    // The fan pieces' ends (fanEndFrom, fanStartTo). Nearly every active
    // vertex has one piece: a piece of a vertex whose own slot is free goes
    // there (kNoTriangle: none), any other into the tables as (v, x0) -> xk
    // and (xk, v) -> x0 (`more`: how many of v's are there; the own slot may
    // be free meanwhile). Like halfEdges_, the tables drop culled vertices'
    // entries when they fill up. One struct a vertex, so that a corner's
    // update mostly reads one cache line.
    struct Pieces {
        uint32_t start = kNoTriangle, end = kNoTriangle, more = 0;
    };
    std::vector<Pieces> pieces_;
    HalfEdgeMap fanEnd_, fanStart_;
    bool trackPieces_ = false;
    std::vector<uint32_t> openEdges_;  // per vertex: open edges it lies on
    std::vector<uint8_t> state_;
    std::vector<uint8_t> kept_;        // per vertex, 1 if never culled; empty if none is
    std::deque<uint64_t> queue_;       // packed directed edges (vi, vj)
    std::vector<uint32_t> triangles_;
    size_t componentStart_ = 0;  // triangle count when the current component began
    SpatialIndex* candidates_;
    bool depthFirst_ = false;
};

}  // namespace drm

#endif  // DRM_TRAVERSAL_H
