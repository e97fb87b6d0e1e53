#include "kernel/kernel_select.hpp"

#include <cstdlib>
#include <cstring>

namespace tidewater::detail {

namespace {

QueryKernel select_kernel() {
    const char* forced = std::getenv("TIDEWATER_QUERY_KERNEL");
    const bool want_baseline = forced != nullptr && std::strcmp(forced, "sse2") == 0;
#if defined(TIDEWATER_HAVE_AVX2_KERNEL)
    if (!want_baseline && __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) {
        return {&kernel_avx2::solve, &kernel_avx2::solve_river, kernel_avx2::name()};
    }
#else
    (void)want_baseline;
#endif
    return {&kernel_sse2::solve, &kernel_sse2::solve_river, kernel_sse2::name()};
}

}  // namespace

const QueryKernel& query_kernel() {
    static const QueryKernel k = select_kernel();
    return k;
}

}  // namespace tidewater::detail
