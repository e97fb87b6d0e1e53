#include "shore_upload.hpp"

#include <algorithm>

namespace tidewater::render::detail {

PackedShore pack_shore(const ShoreWaves* shore) {
    PackedShore p;
    if (!shore) return p;
    const std::size_t texels = static_cast<std::size_t>(shore->resolution()) * static_cast<std::size_t>(shore->resolution());
    p.per_wave.assign(std::max<std::size_t>(1, texels * shore->wave_count()), glm::vec4(0.0f));
    for (std::size_t w = 0; w < shore->wave_count(); ++w)
        for (std::size_t k = 0; k < texels; ++k)
            p.per_wave[w * texels + k] = {shore->phase_residual(w)[k], shore->amplitude_factor(w)[k], shore->wavevector_x(w)[k],
                                          shore->wavevector_z(w)[k]};
    p.shared.resize(texels);
    for (std::size_t k = 0; k < texels; ++k)
        p.shared[k] = {shore->depth()[k], shore->breaking()[k], shore->steepness_scale()[k], shore->shore_distance()[k]};
    return p;
}

}  // namespace tidewater::render::detail
