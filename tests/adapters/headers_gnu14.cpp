// Compiled as gnu++14 (see CMakeLists.txt): every public vcg_adapters header
// must build in the mode MeshLab 2020.09 plugins use.
#include <drm_vcg/file_io.h>
#include <drm_vcg/mesh_io.h>
#include <drm_vcg/rank_palette.h>
#include <drm_vcg/vcg_attributes.h>
#include <drm_vcg/vcg_mesh.h>

#if __cplusplus > 201402L
#error "this file must be compiled as C++14"
#endif

// Instantiate the templates so their bodies are checked too.
drm::Mesh drmVcgHeadersRoundTrip(const drm::Mesh& mesh) {
    drm::vcgio::VcgMesh vcgMesh;
    drm::vcgio::toVcg(mesh, vcgMesh);
    drm::Mesh out = drm::vcgio::fromVcg(vcgMesh);
    drm::vcgio::attributesToVcg(mesh, vcgMesh);
    drm::vcgio::attributesFromVcg(vcgMesh, drm::vcgio::ioMaskOf(mesh), out);
    return out;
}
