// libdrm_codec.so is made of libdrm_codec.a's objects (codec/CMakeLists.txt
// links the archive whole); a shared library target needs one source of
// its own, and this is it.
#include "drm/drm.h"
