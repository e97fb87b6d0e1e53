// The query kernel this CPU runs (private): the widest instruction set it supports,
// chosen once. TIDEWATER_QUERY_KERNEL=sse2 forces the baseline (tests compare the two).
#pragma once

#include "kernel/kernel_waves.hpp"

namespace tidewater::detail {

struct QueryKernel {
    SolveFn solve;             ///< open water and shores
    RiverSolveFn solve_river;  ///< rivers and their plumes
    const char* name;
};

const QueryKernel& query_kernel();

}  // namespace tidewater::detail
