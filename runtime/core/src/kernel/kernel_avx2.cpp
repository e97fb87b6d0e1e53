// AVX2 + FMA build of the query kernel; compiled with -mavx2 -mfma and only
// called after a runtime CPU check (see query.cpp).
#define TIDEWATER_KERNEL_NS kernel_avx2
#include "kernel/eulerian_kernel_impl.hpp"

namespace tidewater::detail::kernel_avx2 {
const char* name() {
    return Arch::name();
}
}  // namespace tidewater::detail::kernel_avx2
