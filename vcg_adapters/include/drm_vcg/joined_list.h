// Lists in the sentences drm's readers, writers and MeshLab plugins print.
#ifndef DRM_VCG_JOINED_LIST_H
#define DRM_VCG_JOINED_LIST_H

#include <string>
#include <vector>

namespace drm {
namespace vcgio {

// "a", "a and b", "a, b and c".
std::string joinList(const std::vector<std::string>& items);

}  // namespace vcgio
}  // namespace drm

#endif  // DRM_VCG_JOINED_LIST_H
