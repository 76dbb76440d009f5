#include "core/host_memory.hpp"

#include <cstdlib>  // defines __GLIBC__ on glibc systems

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace t2imu {

void keep_freed_memory_for_reuse() {
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);              // glibc's ceiling on 64-bit systems
    mallopt(M_TRIM_THRESHOLD, static_cast<int>(0x7fffffff));  // ~2 GiB: int is what mallopt takes
    mallopt(M_TOP_PAD, 1024 * 1024 * 1024);
#endif
}

}  // namespace t2imu
