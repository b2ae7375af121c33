#include "cli/heap_policy.hpp"

#include <malloc.h>

namespace clrt {

void return_large_blocks_when_freed() { mallopt(M_MMAP_THRESHOLD, 1024 * 1024); }

}  // namespace clrt
