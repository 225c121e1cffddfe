#include "connectivity/traversal.h"

#include <algorithm>
#include <string>

#include "drmcodec/drmcodec.h"
#include "spatial/spatial_index.h"

namespace drm {
namespace {
uint64_t packEdge(uint32_t a, uint32_t b) { return (uint64_t(a) << 32) | b; }
}  // namespace

Traversal::Traversal(size_t vertexCount, size_t expectedFaces, SpatialIndex* candidates)
    : halfEdges_(std::min<size_t>(3 * expectedFaces + 16, kFirstHalfEdges), kHalfEdgeSlotsPerEdge),
      fanEnd_(16, kHalfEdgeSlotsPerEdge), fanStart_(16, kHalfEdgeSlotsPerEdge),
      openEdges_(vertexCount, 0), state_(vertexCount, kUntouched), candidates_(candidates) {
    triangles_.reserve(3 * expectedFaces);
}

void Traversal::startComponent(uint32_t a, uint32_t b, uint32_t c) {
    const uint32_t corner[3] = {a, b, c};
    for (uint32_t v : corner) {
        if (v >= vertexCount())
            throw Error(ErrorKind::Corrupt, "start triangle refers to vertex " + std::to_string(v) + ", but there are only " +
                        std::to_string(vertexCount()) + " vertices");
        if (state_[v] != kUntouched && (kept_.empty() || !kept_[v]))
            throw Error(ErrorKind::Corrupt, "start triangle uses vertex " + std::to_string(v) + ", which an earlier component already uses");
    }
    if (a == b || b == c || a == c) throw Error(ErrorKind::Corrupt, "start triangle repeats vertex " + std::to_string(a == b ? a : c));
    // Kept vertices may be shared with earlier components, but an edge
    // never is.
    if (!kept_.empty())
        for (int k = 0; k < 3; ++k) {
            const uint32_t x = corner[k], y = corner[(k + 1) % 3];
            if (halfEdges_.contains(x, y) || halfEdges_.contains(y, x))
                throw Error(ErrorKind::Corrupt, "start triangle reuses the edge " + std::to_string(x) + "-" + std::to_string(y) +
                            " of an earlier component");
        }
    componentStart_ = triangleCount();
    // The paper pushes the three edges in order to the back; (a, b) is popped first.
    addHalfEdge(a, b, c);
    addHalfEdge(b, c, a);
    addHalfEdge(c, a, b);
    if (trackPieces_) {
        linkCorner(a, b, c);
        linkCorner(b, c, a);
        linkCorner(c, a, b);
    }
    triangles_.insert(triangles_.end(), {a, b, c});
    queue_.push_back(packEdge(a, b));
    queue_.push_back(packEdge(b, c));
    queue_.push_back(packEdge(c, a));
}

bool Traversal::popOpenEdge(OpenEdge& edge) {
    while (!queue_.empty()) {
        const uint64_t packed = queue_.front();
        queue_.pop_front();
        const uint32_t vi = uint32_t(packed >> 32), vj = uint32_t(packed);
        // Every edge at a culled vertex is closed (it has no open edge
        // left); the table may have dropped it (insertHalfEdge).
        if (state_[vi] == kCulled || state_[vj] == kCulled) continue;
        if (halfEdges_.contains(vj, vi)) continue;  // closed: a triangle or a boundary code is there
        edge.vi = vi;
        edge.vj = vj;
        edge.opposite = halfEdges_.find(vi, vj);
        return true;
    }
    return false;
}

void Traversal::closeAsBoundary(const OpenEdge& edge) {
    insertHalfEdge(edge.vj, edge.vi, kBoundary);
    --openEdges_[edge.vi];
    --openEdges_[edge.vj];
    releaseIfDone(edge.vi);
    releaseIfDone(edge.vj);
}

void Traversal::attachApex(const OpenEdge& edge, uint32_t apex) {
    if (apex >= vertexCount() || state_[apex] == kCulled || apex == edge.vi || apex == edge.vj)
        throw Error(ErrorKind::Corrupt, "the stream attaches vertex " + std::to_string(apex) + " to edge " + std::to_string(edge.vi) +
                    "-" + std::to_string(edge.vj) + ", where it cannot go");
    if (halfEdges_.contains(edge.vi, apex) || halfEdges_.contains(apex, edge.vj))
        throw Error(ErrorKind::Corrupt, "triangle (" + std::to_string(edge.vj) + ", " + std::to_string(edge.vi) + ", " +
                    std::to_string(apex) + ") would reuse a directed edge");
    addHalfEdge(edge.vj, edge.vi, apex);
    addHalfEdge(edge.vi, apex, edge.vj);
    addHalfEdge(apex, edge.vj, edge.vi);
    if (trackPieces_) {
        linkCorner(edge.vj, edge.vi, apex);
        linkCorner(edge.vi, apex, edge.vj);
        linkCorner(apex, edge.vj, edge.vi);
    }
    triangles_.insert(triangles_.end(), {edge.vj, edge.vi, apex});
    // Left edge to the front keeps the traversal circling the current vertex
    // (paper, Section 3: 5.6% better than breadth first); right edge to the
    // back, or depth first just under the left one (setDepthFirst).
    if (depthFirst_) {
        // The right edge waits just under the left one (topological_coder.h).
        queue_.push_front(packEdge(apex, edge.vj));
        queue_.push_front(packEdge(edge.vi, apex));
    } else {
        queue_.push_front(packEdge(edge.vi, apex));
        queue_.push_back(packEdge(apex, edge.vj));
    }
    releaseIfDone(edge.vi);
    releaseIfDone(edge.vj);
    releaseIfDone(apex);
}

void Traversal::addHalfEdge(uint32_t a, uint32_t b, uint32_t opposite) {
    if (state_[a] == kUntouched) state_[a] = kActive;
    if (state_[b] == kUntouched) state_[b] = kActive;
    if (halfEdges_.contains(b, a)) {
        // The twin was an open edge; this triangle closes it.
        --openEdges_[a];
        --openEdges_[b];
    } else {
        ++openEdges_[a];
        ++openEdges_[b];
    }
    insertHalfEdge(a, b, opposite);
}

void Traversal::insertHalfEdge(uint32_t a, uint32_t b, uint32_t value) {
    // An edge between two culled vertices is never asked for again: every
    // look-up is about an edge at an active vertex (an open edge's ends, the
    // fans around them, a candidate apex), and popOpenEdge skips edges at
    // culled vertices. So when the table fills up, it first drops those:
    // it then holds about the traversal's front, not the whole mesh (a few
    // thousand slots on a mesh of a million triangles, instead of millions).
    if (halfEdges_.full())
        halfEdges_.rebuildKeeping(
            [this](uint32_t x, uint32_t y, uint32_t) { return (state_[x] != kCulled) | (state_[y] != kCulled); });
    halfEdges_.insert(a, b, value);
}

void Traversal::trackFanPieces() {
    if (!triangles_.empty()) throw Error(ErrorKind::Internal, "internal error: fan pieces tracked after the first triangle");
    trackPieces_ = true;
    pieces_.resize(openEdges_.size());
}

void Traversal::linkCorner(uint32_t v, uint32_t p, uint32_t q) {
    // The piece ending at p (its last triangle holds (p, v), the new one
    // (v, p)) and the piece starting at q become one, from the first's start
    // to the second's end; either may be missing (the triangle starts or
    // ends the piece itself).
    Pieces& own = pieces_[v];
    if (own.more == 0) {
        // v has one piece at most (nearly always): its own slot alone.
        if (own.end == p && own.start == q) {
            own.start = own.end = kNoTriangle;  // closed into a ring
        } else if (own.end == p) {
            own.end = q;
        } else if (own.start == q) {
            own.start = p;
        } else if (own.start == kNoTriangle) {
            own.start = p;
            own.end = q;
        } else {
            addPiece(v, p, q);  // a second piece
        }
        return;
    }
    const uint32_t startOfEndingAtP = fanStartTo(p, v), endOfStartingAtQ = fanEndFrom(v, q);
    if (startOfEndingAtP != kNoTriangle && startOfEndingAtP == q) {
        removePiece(v, q, p);  // one piece, closed into a ring around v: no ends left
        return;
    }
    uint32_t start = p, end = q;
    if (startOfEndingAtP != kNoTriangle) {
        start = startOfEndingAtP;
        removePiece(v, start, p);
    }
    if (endOfStartingAtQ != kNoTriangle) {
        end = endOfStartingAtQ;
        removePiece(v, q, end);
    }
    addPiece(v, start, end);
}

void Traversal::addPiece(uint32_t v, uint32_t start, uint32_t end) {
    Pieces& own = pieces_[v];
    if (own.start == kNoTriangle) {
        own.start = start;
        own.end = end;
        return;
    }
    // As insertHalfEdge: a culled vertex's pieces are never asked for again
    // (fanEnd_'s vertex is a key's first, fanStart_'s its second).
    // Erased entries (kAbsent) are dropped too.
    if (fanEnd_.full())
        fanEnd_.rebuildKeeping([this](uint32_t x, uint32_t, uint32_t value) { return value != kNoTriangle && state_[x] != kCulled; });
    if (fanStart_.full())
        fanStart_.rebuildKeeping([this](uint32_t, uint32_t y, uint32_t value) { return value != kNoTriangle && state_[y] != kCulled; });
    fanEnd_.assign(v, start, end);
    fanStart_.assign(end, v, start);
    ++own.more;
}

void Traversal::removePiece(uint32_t v, uint32_t start, uint32_t end) {
    Pieces& own = pieces_[v];
    if (own.start == start) {
        own.start = own.end = kNoTriangle;
        return;
    }
    fanEnd_.erase(v, start);
    fanStart_.erase(end, v);
    --own.more;
}

void Traversal::keepVertex(uint32_t v) {
    if (kept_.empty()) kept_.assign(state_.size(), 0);
    kept_[v] = 1;
}

void Traversal::releaseIfDone(uint32_t v) {
    // In a manifold mesh a touched vertex with no open edge has its whole fan
    // rebuilt (closed, or ending on two coded boundary edges): no later
    // triangle can use it, so it leaves the candidate set (paper, Section 3).
    if (state_[v] == kActive && openEdges_[v] == 0 && (kept_.empty() || !kept_[v])) {
        state_[v] = kCulled;
        if (candidates_) candidates_->remove(v);
    }
}

}  // namespace drm
