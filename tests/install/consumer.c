/* A C program that includes a kernel-like <drm/drm.h> and drm's C API
 * side by side, encodes a tetrahedron and decodes it again.
 * Exits non-zero on any mismatch. */
#include <drm/drm.h>
#include <drmcodec/drmcodec_c.h>

#include <stdio.h>
#include <string.h>

int main(void) {
    struct drm_version kernel = {1, 2, 3, 0, NULL};
    drm_handle_t handle = DRM_IOCTL_VERSION;
    const float positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    const uint32_t triangles[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    drmcodec_encoded* encoded = drmcodec_encode(positions, 4, triangles, 4, DRMCODEC_DEFAULT_BITS);
    size_t size = 0, count = 0;
    const uint8_t* bytes = drmcodec_encoded_bytes(encoded, &size);
    drmcodec_decoded* decoded;
    int ok;
    if (drmcodec_encoded_status(encoded) != DRMCODEC_OK || size == 0) {
        fprintf(stderr, "encode: %s\n", drmcodec_encoded_error(encoded));
        return 1;
    }
    decoded = drmcodec_decode(bytes, size, 1);
    drmcodec_decoded_array(decoded, DRMCODEC_TRIANGLES, &count);
    ok = drmcodec_decoded_status(decoded) == DRMCODEC_OK && count == 12 &&
         drmcodec_decoded_stat(decoded, DRMCODEC_VERTICES) == 4.0;
    drmcodec_decoded_free(decoded);
    /* A damaged file is refused with a message, never a crash. */
    decoded = drmcodec_decode(bytes, size / 2, 1);
    ok = ok && drmcodec_decoded_status(decoded) == DRMCODEC_CORRUPT && strlen(drmcodec_decoded_error(decoded)) > 0;
    printf("C: drmcodec %s beside %s (handle %u, version %d): %zu bytes, %s\n", drmcodec_version(), DRM_NAME, handle,
           kernel.version_major, size, ok ? "ok" : "MISMATCH");
    drmcodec_decoded_free(decoded);
    drmcodec_encoded_free(encoded);
    return ok ? 0 : 1;
}
