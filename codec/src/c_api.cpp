// The C API (<drmcodec/drmcodec_c.h>): each result object holds the C++
// result or the error that replaced it, so that no exception crosses into C.
#include "drmcodec/drmcodec_c.h"

#include <algorithm>
#include <cstdint>
#include <new>
#include <string>

#include "drmcodec/drmcodec.h"

static_assert(DRMCODEC_DEFAULT_BITS == drm::kDefaultQuantizationBits, "the C API's default bits are the library's");

struct drmcodec_decoded {
    int status = DRMCODEC_OK;
    std::string error;
    drm::Decoded decoded;
    uint32_t maxRank = 0;
};

struct drmcodec_encoded {
    int status = DRMCODEC_OK;
    std::string error;
    drm::Encoded encoded;
};

namespace {

// Runs work(), turning what it throws into the result's status and message.
template <class Result, class Work>
void capture(Result* result, Work work) {
    try {
        work();
    } catch (const drm::Error& e) {
        result->status = int(e.kind()) + 1;
        result->error = e.what();
    } catch (const std::bad_alloc&) {
        result->status = DRMCODEC_OUT_OF_MEMORY;
        result->error = "out of memory";
    } catch (const std::exception& e) {
        result->status = DRMCODEC_INTERNAL;
        result->error = std::string("internal error: ") + e.what();
    }
}

template <class T>
const void* valuesOf(const std::vector<T>& v, size_t* count) {
    if (count) *count = v.size();
    return v.empty() ? nullptr : v.data();
}

const std::vector<std::string>* namesOf(const drmcodec_decoded* d, int names) {
    if (!d || d->status != DRMCODEC_OK) return nullptr;
    if (names == DRMCODEC_MATERIAL_NAMES) return &d->decoded.mesh.materials;
    if (names == DRMCODEC_TEXTURE_NAMES) return &d->decoded.mesh.textures;
    return nullptr;
}

}  // namespace

extern "C" {

const char* drmcodec_version(void) { return drm::version(); }

const char* drmcodec_status_name(int status) {
    if (status == DRMCODEC_OK) return "ok";
    if (status == DRMCODEC_OUT_OF_MEMORY) return "out of memory";
    if (status >= DRMCODEC_INVALID_INPUT && status <= DRMCODEC_INTERNAL) return drm::errorKindName(drm::ErrorKind(status - 1));
    return "unknown";
}

drmcodec_decoded* drmcodec_decode(const uint8_t* data, size_t size, int threads) {
    drmcodec_decoded* result = new (std::nothrow) drmcodec_decoded;
    if (!result) return nullptr;
    capture(result, [&] {
        if (!data && size) throw drm::Error(drm::ErrorKind::InvalidInput, "no data: a null pointer with a size of " + std::to_string(size));
        drm::DecodeOptions options;
        options.threads = threads;
        static const uint8_t kNothing = 0;
        result->decoded = drm::decode(data ? data : &kNothing, size, options);
        for (uint32_t r : result->decoded.faceRank) result->maxRank = std::max(result->maxRank, r);
    });
    if (result->status != DRMCODEC_OK) result->decoded = drm::Decoded();
    return result;
}

int drmcodec_decoded_status(const drmcodec_decoded* d) { return d ? d->status : DRMCODEC_OUT_OF_MEMORY; }

const char* drmcodec_decoded_error(const drmcodec_decoded* d) { return d ? d->error.c_str() : "out of memory"; }

const void* drmcodec_decoded_array(const drmcodec_decoded* d, int array, size_t* count) {
    if (count) *count = 0;
    if (!d || d->status != DRMCODEC_OK) return nullptr;
    const drm::Mesh& m = d->decoded.mesh;
    switch (array) {
        case DRMCODEC_POSITIONS: return valuesOf(m.positions, count);
        case DRMCODEC_TRIANGLES: return valuesOf(m.triangles, count);
        case DRMCODEC_COLORS: return valuesOf(m.colors, count);
        case DRMCODEC_NORMALS: return valuesOf(m.normals, count);
        case DRMCODEC_TEXCOORDS: return valuesOf(m.texCoords, count);
        case DRMCODEC_QUALITY: return valuesOf(m.quality, count);
        case DRMCODEC_CORNER_TEXCOORDS: return valuesOf(m.cornerTexCoords, count);
        case DRMCODEC_CORNER_NORMALS: return valuesOf(m.cornerNormals, count);
        case DRMCODEC_FACE_COLORS: return valuesOf(m.faceColors, count);
        case DRMCODEC_FACE_QUALITY: return valuesOf(m.faceQuality, count);
        case DRMCODEC_FACE_MATERIAL: return valuesOf(m.faceMaterial, count);
        case DRMCODEC_FACE_TEXTURE: return valuesOf(m.faceTexture, count);
        case DRMCODEC_FACE_RANK: return valuesOf(d->decoded.faceRank, count);
        case DRMCODEC_QUANTIZED: return valuesOf(d->decoded.quantized, count);
        default: return nullptr;
    }
}

size_t drmcodec_decoded_name_count(const drmcodec_decoded* d, int names) {
    const std::vector<std::string>* list = namesOf(d, names);
    return list ? list->size() : 0;
}

const char* drmcodec_decoded_name(const drmcodec_decoded* d, int names, size_t i) {
    const std::vector<std::string>* list = namesOf(d, names);
    return list && i < list->size() ? (*list)[i].c_str() : nullptr;
}

double drmcodec_decoded_stat(const drmcodec_decoded* d, int stat) {
    if (!d || d->status != DRMCODEC_OK) return 0;
    const drm::Stats& s = d->decoded.stats;
    const drm::Grid& g = d->decoded.grid;
    switch (stat) {
        case DRMCODEC_VERTICES: return double(s.vertices);
        case DRMCODEC_FACES: return double(s.faces);
        case DRMCODEC_COMPONENTS: return double(s.components);
        case DRMCODEC_BOUNDARY_EDGES: return double(s.boundaryEdges);
        case DRMCODEC_BITS: return double(s.bits);
        case DRMCODEC_TOTAL_BYTES: return double(s.totalBytes);
        case DRMCODEC_HEADER_BYTES: return double(s.headerBytes);
        case DRMCODEC_CONNECTIVITY_BYTES: return double(s.connectivityBytes);
        case DRMCODEC_GEOMETRY_BYTES: return double(s.geometryBytes);
        case DRMCODEC_VERTEX_ORDER_BYTES: return double(s.vertexOrderBytes);
        case DRMCODEC_ATTRIBUTE_BYTES: return double(s.attributeBytes);
        case DRMCODEC_WELDED_VERTICES: return double(s.weldedVertices);
        case DRMCODEC_GRID_ORIGIN_X: return g.origin[0];
        case DRMCODEC_GRID_ORIGIN_Y: return g.origin[1];
        case DRMCODEC_GRID_ORIGIN_Z: return g.origin[2];
        case DRMCODEC_GRID_STEP: return g.step;
        case DRMCODEC_MAX_RANK: return double(d->maxRank);
        default: return 0;
    }
}

const char* drmcodec_decoded_connectivity(const drmcodec_decoded* d) {
    if (!d || d->status != DRMCODEC_OK) return "";
    return drm::connectivityCoderName(d->decoded.stats.connectivity);
}

const char* drmcodec_decoded_geometry(const drmcodec_decoded* d) {
    if (!d || d->status != DRMCODEC_OK) return "";
    // The topological coder walks its own vertex order (drm info prints "walk").
    if (d->decoded.stats.connectivity == drm::ConnectivityCoder::Topological) return "walk";
    return drm::geometryCoderName(d->decoded.stats.geometry);
}

void drmcodec_decoded_free(drmcodec_decoded* d) { delete d; }

drmcodec_encoded* drmcodec_encode(const float* positions, size_t vertexCount, const uint32_t* triangles, size_t faceCount,
                                  int bits) {
    drmcodec_encoded* result = new (std::nothrow) drmcodec_encoded;
    if (!result) return nullptr;
    capture(result, [&] {
        if ((!positions && vertexCount) || (!triangles && faceCount))
            throw drm::Error(drm::ErrorKind::InvalidInput, "no data: a null array with a non-zero count");
        // Beyond 2^32 vertices or faces no index can name them all; the
        // codec's own limits are lower still and give their own message.
        if (vertexCount > UINT32_MAX || faceCount > UINT32_MAX)
            throw drm::Error(drm::ErrorKind::InvalidInput, "the mesh is too large: " + std::to_string(vertexCount) +
                             " vertices and " + std::to_string(faceCount) + " faces (at most 2^32 of each)");
        drm::Mesh mesh;
        mesh.positions.assign(positions, positions + 3 * vertexCount);
        mesh.triangles.assign(triangles, triangles + 3 * faceCount);
        drm::EncodeOptions options;
        options.bits = bits;
        result->encoded = drm::encode(mesh, options);
    });
    if (result->status != DRMCODEC_OK) result->encoded = drm::Encoded();
    return result;
}

int drmcodec_encoded_status(const drmcodec_encoded* e) { return e ? e->status : DRMCODEC_OUT_OF_MEMORY; }

const char* drmcodec_encoded_error(const drmcodec_encoded* e) { return e ? e->error.c_str() : "out of memory"; }

const uint8_t* drmcodec_encoded_bytes(const drmcodec_encoded* e, size_t* size) {
    if (size) *size = 0;
    if (!e || e->status != DRMCODEC_OK) return nullptr;
    if (size) *size = e->encoded.bytes.size();
    return e->encoded.bytes.data();
}

void drmcodec_encoded_free(drmcodec_encoded* e) { delete e; }

}  // extern "C"
