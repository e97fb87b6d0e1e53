// Baseline x86-64 (SSE2) or the target's default ISA.
#define TIDEWATER_KERNEL_NS kernel_sse2
#include "kernel/eulerian_kernel_impl.hpp"

namespace tidewater::detail::kernel_sse2 {
const char* name() {
    return Arch::name();
}
}  // namespace tidewater::detail::kernel_sse2
