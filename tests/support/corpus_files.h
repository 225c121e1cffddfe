// The shared corpus (../shared/meshes beside the project) as the parameters
// of a test suite, one ctest test per mesh: the same list and test names for
// every suite that walks it.
#ifndef DRM_TEST_CORPUS_FILES_H
#define DRM_TEST_CORPUS_FILES_H

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace drm_test {

// The .ply files in dir, by name, in name order; none if dir is missing.
inline std::vector<std::string> plyFilesIn(const std::string& dir) {
    std::vector<std::string> names;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(dir, error))
        if (entry.is_regular_file() && entry.path().extension() == ".ply") names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// A test's name from its mesh file: the stem, with every character but
// letters and digits turned into '_'.
inline std::string testNameOfMeshFile(const ::testing::TestParamInfo<std::string>& info) {
    std::string name = std::filesystem::path(info.param).stem().string();
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

}  // namespace drm_test

#endif  // DRM_TEST_CORPUS_FILES_H
