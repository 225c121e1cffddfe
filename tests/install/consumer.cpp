// A C++ program that includes a kernel-like <drm/drm.h> and drm's C++ and C
// APIs side by side, encodes a tetrahedron, decodes it, and catches the
// library's error for a damaged file. Exits non-zero on any mismatch.
#include <drm/drm.h>
#include <drmcodec/drmcodec.h>
#include <drmcodec/drmcodec_c.h>

#include <cstdio>
#include <string>

int main() {
    drm_version kernel{};
    kernel.version_major = 1;
    const drm_handle_t handle = DRM_IOCTL_VERSION;
    drm::Mesh mesh;
    mesh.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    mesh.triangles = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    const drm::Encoded encoded = drm::encode(mesh);
    const drm::Decoded decoded = drm::decode(encoded.bytes);
    bool ok = decoded.mesh.faceCount() == 4 && decoded.mesh.vertexCount() == 4;
    try {
        drm::decode(encoded.bytes.data(), encoded.bytes.size() / 2);
        ok = false;
    } catch (const drm::Error& e) {
        ok = ok && e.kind() == drm::ErrorKind::Corrupt;
    }
    std::printf("C++: drmcodec %s beside %s (handle %u, version %d): %zu bytes, %s\n", drm::version(), DRM_NAME,
                handle, kernel.version_major, encoded.bytes.size(), ok ? "ok" : "MISMATCH");
    return ok && std::string(drmcodec_version()) == drm::version() ? 0 : 1;
}
