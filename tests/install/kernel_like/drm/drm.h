/* A stand-in for the Linux kernel's <drm/drm.h> (the Direct Rendering
 * Manager's user-space header, which linux-libc-dev and its kind install
 * as /usr/include/drm/drm.h on most distributions; Debian 12 has none).
 * It declares names of the kind that header declares, so that a program
 * including both it and drm's headers shows any clash: drm's headers live
 * under <drmcodec/...> and use no name of this one. Written for the test,
 * not taken from the kernel. */
#ifndef KERNEL_LIKE_DRM_H
#define KERNEL_LIKE_DRM_H

#include <stddef.h>

#define DRM_NAME "drm"
#define DRM_MIN_ORDER 5
#define DRM_MAX_ORDER 22
#define DRM_IOCTL_BASE 'd'
#define DRM_IO(nr) (((unsigned)DRM_IOCTL_BASE << 8) | (unsigned)(nr))
#define DRM_IOCTL_VERSION DRM_IO(0x00)

typedef unsigned int drm_handle_t;
typedef unsigned int drm_context_t;
typedef unsigned int drm_magic_t;

struct drm_version {
    int version_major;
    int version_minor;
    int version_patchlevel;
    size_t name_len;
    char* name;
};

struct drm_clip_rect {
    unsigned short x1, y1, x2, y2;
};

enum drm_map_type { _DRM_FRAME_BUFFER = 0, _DRM_REGISTERS = 1 };

#endif
