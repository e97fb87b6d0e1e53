#include "tidewater/terrain.hpp"

namespace tidewater {

namespace {
template <class... Fs>
struct Overloaded : Fs... {
    using Fs::operator()...;
};
template <class... Fs>
Overloaded(Fs...) -> Overloaded<Fs...>;
}  // namespace

double Terrain::height_at(glm::dvec2 p) const {
    return std::visit(Overloaded{[](const FlatTerrain& f) { return f.height; },
                                 [&](const PlaneTerrain& s) { return s.height + s.slope.x * p.x + s.slope.y * p.y; }},
                      shape_);
}

const char* Terrain::kind_name() const {
    return std::holds_alternative<FlatTerrain>(shape_) ? "flat" : "plane";
}

}  // namespace tidewater
