// Reads the one PLY layout tests/data uses (binary little-endian, float x y
// z per vertex, list uchar int vertex_indices per face, triangles only), so
// that codec-only tools can use the real test meshes without vcglib.
#ifndef DRM_TEST_TINY_PLY_H
#define DRM_TEST_TINY_PLY_H

#include <string>
#include <vector>

#include "test_meshes.h"

namespace drm_test {

// Throws std::runtime_error for a file in any other layout.
drm::Mesh readTinyPly(const std::string& path);

// Every *.ply in dir that readTinyPly can read, sorted by file name, named
// by file name without the extension; files it cannot read are skipped.
std::vector<NamedMesh> readPlyDirectory(const std::string& dir);

}  // namespace drm_test

#endif  // DRM_TEST_TINY_PLY_H
