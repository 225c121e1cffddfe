/* drm: distance-ranked connectivity compression of triangle meshes.
 *
 * The C API of the codec library, for C programs and for bindings that
 * cannot catch C++ exceptions (the WebAssembly decoder in web/). It wraps
 * <drmcodec/drmcodec.h>: the same files, the same error messages. No
 * function throws or aborts; each result carries a status and, on failure,
 * the message drm::Error gives.
 *
 *     drmcodec_decoded* d = drmcodec_decode(bytes, size, 0);
 *     if (drmcodec_decoded_status(d) != DRMCODEC_OK) {
 *         fprintf(stderr, "%s\n", drmcodec_decoded_error(d));
 *     } else {
 *         size_t n = 0;
 *         const float* xyz = (const float*)drmcodec_decoded_array(d, DRMCODEC_POSITIONS, &n);
 *         ...
 *     }
 *     drmcodec_decoded_free(d);
 *
 * Every name starts with drmcodec_ or DRMCODEC_, so this header sits beside
 * the Linux kernel's <drm/drm.h> (struct drm_version, DRM_IOCTL_*, ...)
 * without a clash. */
#ifndef DRMCODEC_DRMCODEC_C_H
#define DRMCODEC_DRMCODEC_C_H

#include <stddef.h>
#include <stdint.h>

#if defined(__GNUC__)
#define DRMCODEC_C_API __attribute__((visibility("default")))
#else
#define DRMCODEC_C_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* drm::ErrorKind + 1; DRMCODEC_OUT_OF_MEMORY when an allocation fails. */
enum drmcodec_status {
    DRMCODEC_OK = 0,
    DRMCODEC_INVALID_INPUT = 1,
    DRMCODEC_CORRUPT = 2,
    DRMCODEC_UNSUPPORTED = 3,
    DRMCODEC_CANCELLED = 4,
    DRMCODEC_IO = 5,
    DRMCODEC_INTERNAL = 6,
    DRMCODEC_OUT_OF_MEMORY = 7
};

/* The arrays of a decoded mesh (drm::Decoded), with their element type and
 * the number of values per element. An array the file does not carry has
 * no values. */
enum drmcodec_array {
    DRMCODEC_POSITIONS = 0,         /* float, 3 per vertex */
    DRMCODEC_TRIANGLES = 1,         /* uint32_t, 3 per face, counter-clockwise as encoded */
    DRMCODEC_COLORS = 2,            /* uint8_t, 4 per vertex (RGBA) */
    DRMCODEC_NORMALS = 3,           /* float, 3 per vertex */
    DRMCODEC_TEXCOORDS = 4,         /* float, 2 per vertex */
    DRMCODEC_QUALITY = 5,           /* float, 1 per vertex */
    DRMCODEC_CORNER_TEXCOORDS = 6,  /* float, 6 per face */
    DRMCODEC_CORNER_NORMALS = 7,    /* float, 9 per face */
    DRMCODEC_FACE_COLORS = 8,       /* uint8_t, 4 per face (RGBA) */
    DRMCODEC_FACE_QUALITY = 9,      /* float, 1 per face */
    DRMCODEC_FACE_MATERIAL = 10,    /* uint32_t, 1 per face: index into the material names */
    DRMCODEC_FACE_TEXTURE = 11,     /* uint32_t, 1 per face: index into the texture names */
    DRMCODEC_FACE_RANK = 12,        /* uint32_t, 1 per face: the rank code that made it, 0 if none */
    DRMCODEC_QUANTIZED = 13,        /* int32_t, 3 per vertex: grid coordinates */
    DRMCODEC_ARRAY_COUNT = 14
};

/* The name lists of a decoded mesh. */
enum drmcodec_names {
    DRMCODEC_MATERIAL_NAMES = 0,
    DRMCODEC_TEXTURE_NAMES = 1
};

/* Figures of a decoded file (drm::Stats). */
enum drmcodec_stat {
    DRMCODEC_VERTICES = 0,
    DRMCODEC_FACES = 1,
    DRMCODEC_COMPONENTS = 2,
    DRMCODEC_BOUNDARY_EDGES = 3,
    DRMCODEC_BITS = 4,                 /* quantization bits */
    DRMCODEC_TOTAL_BYTES = 5,
    DRMCODEC_HEADER_BYTES = 6,
    DRMCODEC_CONNECTIVITY_BYTES = 7,
    DRMCODEC_GEOMETRY_BYTES = 8,
    DRMCODEC_VERTEX_ORDER_BYTES = 9,
    DRMCODEC_ATTRIBUTE_BYTES = 10,
    DRMCODEC_WELDED_VERTICES = 11,
    DRMCODEC_GRID_ORIGIN_X = 12,       /* grid coordinate q of axis k stands for origin[k] + q * step */
    DRMCODEC_GRID_ORIGIN_Y = 13,
    DRMCODEC_GRID_ORIGIN_Z = 14,
    DRMCODEC_GRID_STEP = 15,
    DRMCODEC_MAX_RANK = 16,            /* the largest rank code of any face, 0 if none */
    DRMCODEC_STAT_COUNT = 17
};

typedef struct drmcodec_decoded drmcodec_decoded;
typedef struct drmcodec_encoded drmcodec_encoded;

/* The library's version, e.g. "0.1.0". */
DRMCODEC_C_API const char* drmcodec_version(void);
/* "ok", "invalid input", "corrupt", "unsupported", "cancelled", "i/o",
 * "internal", "out of memory"; "unknown" for any other value. */
DRMCODEC_C_API const char* drmcodec_status_name(int status);

/* Decodes a .drm file held in memory. threads: 0 as the machine allows, 1
 * on the calling thread only (the decoded mesh is the same). Returns NULL
 * only when even the result cannot be allocated; free it with
 * drmcodec_decoded_free. */
DRMCODEC_C_API drmcodec_decoded* drmcodec_decode(const uint8_t* data, size_t size, int threads);
/* DRMCODEC_OK, or why decoding failed. */
DRMCODEC_C_API int drmcodec_decoded_status(const drmcodec_decoded* decoded);
/* "" on success, otherwise the message drm::decode throws. */
DRMCODEC_C_API const char* drmcodec_decoded_error(const drmcodec_decoded* decoded);
/* The values of one array and, in *count, how many values (not elements)
 * it holds; NULL and 0 for an array the file does not carry. Valid until
 * drmcodec_decoded_free. */
DRMCODEC_C_API const void* drmcodec_decoded_array(const drmcodec_decoded* decoded, int array, size_t* count);
/* How many names a list holds, and name i of it (NULL past the end). */
DRMCODEC_C_API size_t drmcodec_decoded_name_count(const drmcodec_decoded* decoded, int names);
DRMCODEC_C_API const char* drmcodec_decoded_name(const drmcodec_decoded* decoded, int names, size_t i);
/* One figure of the file (0 for an unknown stat or a failed decode). */
DRMCODEC_C_API double drmcodec_decoded_stat(const drmcodec_decoded* decoded, int stat);
/* The connectivity coder ("ranks" or "topological") and geometry coder
 * names, as `drm info` prints them; "" for a failed decode. */
DRMCODEC_C_API const char* drmcodec_decoded_connectivity(const drmcodec_decoded* decoded);
DRMCODEC_C_API const char* drmcodec_decoded_geometry(const drmcodec_decoded* decoded);
DRMCODEC_C_API void drmcodec_decoded_free(drmcodec_decoded* decoded);

/* Encodes positions (3 floats per vertex) and triangles (3 indices per
 * face) at the given quantization bits (DRMCODEC_DEFAULT_BITS is the
 * library's default) with every other option at its default. Returns
 * NULL only when the result cannot be allocated. */
#define DRMCODEC_DEFAULT_BITS 12
DRMCODEC_C_API drmcodec_encoded* drmcodec_encode(const float* positions, size_t vertex_count, const uint32_t* triangles,
                                                 size_t face_count, int bits);
DRMCODEC_C_API int drmcodec_encoded_status(const drmcodec_encoded* encoded);
DRMCODEC_C_API const char* drmcodec_encoded_error(const drmcodec_encoded* encoded);
/* The .drm file's bytes and their number; NULL and 0 after a failure. */
DRMCODEC_C_API const uint8_t* drmcodec_encoded_bytes(const drmcodec_encoded* encoded, size_t* size);
DRMCODEC_C_API void drmcodec_encoded_free(drmcodec_encoded* encoded);

#ifdef __cplusplus
}  /* extern "C" */
#endif

#endif /* DRMCODEC_DRMCODEC_C_H */
