// The visitor of several lambdas for std::visit, one overload per alternative.
#pragma once

namespace tidewater::detail {

template <typename... F>
struct Overloaded : F... {
    using F::operator()...;
};
template <typename... F>
Overloaded(F...) -> Overloaded<F...>;

}  // namespace tidewater::detail
