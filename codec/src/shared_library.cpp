// libdrmcodec.so is made of libdrmcodec.a's objects (codec/CMakeLists.txt
// links the archive whole); a shared library target needs one source of
// its own, and this is it.
#include "drmcodec/drmcodec.h"
