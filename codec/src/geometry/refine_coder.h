// Geometry coder 3, "refine": geometry that uses the connectivity.
//
// The vertex set is coded in two passes around the connectivity:
//  1. the coarse grid (every coordinate >> lowBits) with the spanning-tree
//     coder at bits - lowBits; connectivity is then coded and decoded with
//     ranks computed on these coarse positions (coincident coarse points
//     are ordered by index, as any tie);
//  2. a refinement pass codes the lowBits low bits of every vertex,
//     predicted across the decoded triangles (parallelograms over refined
//     neighbours, else the average of the neighbours) and clamped into the
//     vertex's known coarse cell, with adaptive models whose contexts are
//     the local residual size.
// Everything the decoder computes here is integer arithmetic.
//
#ifndef DRM_REFINE_CODER_H
#define DRM_REFINE_CODER_H

#include <cstddef>
#include <cstdint>
#include <vector>

#include "drmcodec/drmcodec.h"

namespace drm {

// The encoder tries lowBits 1..kMaxTriedRefineBits; a file may hold up to
// kMaxRefineBits (always fewer than the quantization bits): both in drmcodec.h.

// How a vertex's full position is predicted (the encoder tries each and
// records the best in the section):
enum class RefinePredictor : uint8_t {
    Parallelogram = 0,  // mean of the parallelograms over refined triangles across
                        // the vertex's fan; else the neighbour average
    Average = 1,        // mean of the neighbours (full if refined, else cell centre)
    Blend = 2,          // mean of the two above
    Curvature = 3,      // the neighbour average plus the mean offset of the refined
                        // neighbours from their own neighbour averages
};
constexpr int kRefinePredictors = 4;

std::vector<int32_t> coarsenGrid(const std::vector<int32_t>& grid, int lowBits);

struct Refinement {
    RefinePredictor predictor = RefinePredictor::Parallelogram;
    std::vector<uint8_t> bytes;
    bool overBudget = false;  // every predictor passed encodeRefinement's maxBytes
};

struct RefinePayload {
    int lowBits = 0;
    RefinePredictor predictor = RefinePredictor::Parallelogram;
    const uint8_t* tree = nullptr;
    size_t treeSize = 0;
    const uint8_t* refinement = nullptr;
    size_t refinementSize = 0;
};

// The geometry section: u8 lowBits, u8 predictor, varint tree size, the
// tree payload, the refinement payload.
std::vector<uint8_t> writeRefinePayload(int lowBits, const Refinement& refinement, const std::vector<uint8_t>& tree);
// Checks lowBits (1..min(kMaxRefineBits, bits - 1)), the predictor and the
// tree size against the section; throws Error naming the problem.
RefinePayload readRefinePayload(const uint8_t* data, size_t size, int bits);

// fine: the grid coordinates of the vertices (3 per vertex, decoded order).
// triangles: the decoded triangles over those vertices, in the order the
// decoder rebuilds them. Tries every predictor, returns the smallest.
// With maxBytes, a refinement that would take more bytes is not finished:
// then `bytes` is empty and `overBudget` set (an encoder's estimate needs
// no more than that answer).
Refinement encodeRefinement(const std::vector<int32_t>& fine, int lowBits, const std::vector<uint32_t>& triangles,
                            size_t maxBytes = SIZE_MAX);
// coarse: the coarse grid (3 per vertex); returns the full grid. Throws
// Error if the payload ends before the last vertex.
std::vector<int32_t> decodeRefinement(const RefinePayload& payload, const std::vector<int32_t>& coarse,
                                      const std::vector<uint32_t>& triangles);

}  // namespace drm

#endif  // DRM_REFINE_CODER_H
