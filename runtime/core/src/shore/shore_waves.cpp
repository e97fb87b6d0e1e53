#include "tidewater/shore_waves.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <thread>

#include "fast_marching.hpp"
#include "gerstner_sums.hpp"
#include "tidewater/constants.hpp"
#include "tidewater/dispersion.hpp"
#include "tidewater/shore_bake.hpp"

namespace tidewater {

namespace {

/// The deep-water boundary: k h >= pi, where tanh(k h) > 0.996.
constexpr double kDeepKh = kPi;
constexpr double kMaxFold = 0.95;

template <typename Work>
void parallel_for(std::size_t count, unsigned threads, const Work& work) {
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
        for (std::size_t k = next++; k < count; k = next++) work(k);
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (auto& th : pool) th.join();
}

}  // namespace

Result<std::shared_ptr<const ShoreWaves>> ShoreWaves::bake(const WaveSet& set, const Terrain& terrain, double water_level,
                                                           const ShoreWaveOptions& options) {
    if (options.resolution < 16 || options.resolution > 4096)
        return Error{ErrorCode::invalid_argument, fmt::format("shore waves: resolution {} is out of range (16 to 4096)", options.resolution)};
    if (!(options.breaking_index > 0.0 && options.breaking_index <= 1.2))
        return Error{ErrorCode::invalid_argument, "shore waves: breaking_index must be in (0, 1.2]"};
    BakeOptions bake;
    bake.resolution = options.resolution;
    bake.threads = options.threads;
    auto field = bake_shore(terrain, water_level, bake);
    if (!field) return field.error();
    const unsigned threads = options.threads == 0 ? std::max(1u, std::thread::hardware_concurrency()) : options.threads;

    auto out = std::make_shared<ShoreWaves>();
    const int n = field->resolution;
    out->n_ = n;
    out->texel_ = field->texel;
    out->corner_ = field->corner;
    const std::size_t count = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
    out->depth_ = field->depth;
    out->distance_ = field->signed_distance;
    const auto waves = set.waves();
    const std::size_t nw = waves.size();
    out->residual_.assign(nw, std::vector<float>(count, 0.0f));
    out->amplitude_.assign(nw, std::vector<float>(count, 0.0f));
    out->kx_.assign(nw, std::vector<float>(count, 0.0f));
    out->kz_.assign(nw, std::vector<float>(count, 0.0f));

    parallel_for(nw, threads, [&](std::size_t w) {
        const Wave& wave = waves[w];
        const double k0 = wave.k;
        const glm::dvec2 dir{wave.dir_x, wave.dir_z};
        std::vector<double> slowness(count, 0.0), phase(count, detail::kUnreached);
        std::vector<unsigned char> deep(count, 0);
        bool any_deep = false;
        for (std::size_t k = 0; k < count; ++k) {
            const double h = static_cast<double>(field->depth[k]);
            if (h <= 0.0) continue;  // land blocks the waves
            slowness[k] = wavenumber_at_depth(wave.omega, h);
            deep[k] = slowness[k] * h >= kDeepKh;
            any_deep = any_deep || deep[k];
        }
        // Sources: deep water, where the open-ocean phase holds. A domain with no deep
        // water takes the wave from the edges it enters through instead (shallow edges
        // would otherwise pin the unrefracted phase along them).
        for (int j = 0; j < n; ++j) {
            for (int i = 0; i < n; ++i) {
                const std::size_t k = field->index(i, j);
                if (slowness[k] <= 0.0) continue;
                const bool entry_edge = (i == 0 && dir.x > 0.05) || (i == n - 1 && dir.x < -0.05) ||
                                        (j == 0 && dir.y > 0.05) || (j == n - 1 && dir.y < -0.05);
                if (any_deep ? deep[k] != 0 : entry_edge) phase[k] = k0 * glm::dot(dir, field->texel_center(i, j));
            }
        }
        // Offset so the marched values start near zero (keeps doubles exact on big domains).
        const double base = k0 * glm::dot(dir, field->corner);
        for (double& v : phase)
            if (std::isfinite(v)) v -= base;
        detail::fast_march(slowness, phase, n, field->texel);
        auto& residual = out->residual_[w];
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const std::size_t k = field->index(i, j);
                if (!std::isfinite(phase[k])) continue;  // unreached: no wave
                residual[k] = static_cast<float>(phase[k] + base - k0 * glm::dot(dir, field->texel_center(i, j)));
            }
        // Local wavevector = k0 D + grad(residual), central differences over reached water.
        auto& kx = out->kx_[w];
        auto& kz = out->kz_[w];
        auto& amp = out->amplitude_[w];
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const std::size_t k = field->index(i, j);
                const double h = field->depth[k];
                if (h <= 0.0 || !std::isfinite(phase[k])) continue;
                auto diff = [&](int a0, int b0, int a1, int b1) {
                    const bool ok0 = a0 >= 0 && b0 >= 0 && a0 < n && b0 < n && std::isfinite(phase[field->index(a0, b0)]);
                    const bool ok1 = a1 >= 0 && b1 >= 0 && a1 < n && b1 < n && std::isfinite(phase[field->index(a1, b1)]);
                    const double v0 = ok0 ? phase[field->index(a0, b0)] : phase[k];
                    const double v1 = ok1 ? phase[field->index(a1, b1)] : phase[k];
                    const double span = (ok0 ? 1.0 : 0.0) + (ok1 ? 1.0 : 0.0);
                    return span > 0.0 ? (v1 - v0) / (span * field->texel) : 0.0;
                };
                glm::dvec2 kvec{diff(i - 1, j, i + 1, j), diff(i, j - 1, i, j + 1)};
                const double kl = slowness[k];  // k(h), solved once above
                const double len = glm::length(kvec);
                kvec = len > 0.0 ? kvec * (kl / len) : dir * kl;  // magnitude exactly k(h)
                kx[k] = static_cast<float>(kvec.x);
                kz[k] = static_cast<float>(kvec.y);
                // Shoaling and refraction (rays against the shore normal).
                // Shoaling from energy flux: sqrt(cg_deep / cg(h)), cg_deep = omega / (2 k0).
                const double ks = std::sqrt(0.5 * wave.omega / k0 / group_velocity(kl, h));
                const glm::dvec2 normal{static_cast<double>(field->gradient_x[k]), static_cast<double>(field->gradient_z[k])};
                double kr = 1.0;
                if (glm::length(normal) > 0.5) {
                    const double cos0 = std::abs(glm::dot(dir, normal));
                    const double cos1 = std::abs(glm::dot(kvec / kl, normal));
                    if (cos0 > 0.05 && cos1 > 0.05) kr = std::sqrt(std::clamp(cos0 / cos1, 0.25, 4.0));
                }
                amp[k] = static_cast<float>(ks * kr);
            }
    });

    // Breaking (all waves together) and steepness, per texel.
    out->breaking_.assign(count, 0.0f);
    out->steepness_.assign(count, 1.0f);
    const double cap_ratio = 0.5 * options.breaking_index;  // amplitude cap = index * h / 2
    for (std::size_t k = 0; k < count; ++k) {
        const double h = static_cast<double>(out->depth_[k]);
        // The local wave height 2 sqrt(sum A^2): exactly 2A for one wave, the rms-based
        // height (about 0.71 Hs) for a spectrum, whose occasional peaks a cap on sum(A) would overstate.
        double energy = 0.0;
        for (std::size_t w = 0; w < nw; ++w) {
            const double a = waves[w].amplitude * static_cast<double>(out->amplitude_[w][k]);
            energy += a * a;
        }
        const double total = std::sqrt(energy);
        if (h <= 0.0) {
            for (std::size_t w = 0; w < nw; ++w) out->amplitude_[w][k] = 0.0f;
            continue;
        }
        const double cap = cap_ratio * h;
        const double ratio = total > 0.0 ? total / cap : 0.0;
        out->breaking_[k] = static_cast<float>(std::clamp((ratio - 0.85) / 0.45, 0.0, 1.0));
        if (ratio > 1.0)
            for (std::size_t w = 0; w < nw; ++w) out->amplitude_[w][k] = static_cast<float>(static_cast<double>(out->amplitude_[w][k]) / ratio);
        double fold = 0.0;
        for (std::size_t w = 0; w < nw; ++w) {
            const double kl = std::hypot(static_cast<double>(out->kx_[w][k]), static_cast<double>(out->kz_[w][k]));
            fold += waves[w].steepness * kl * waves[w].amplitude * static_cast<double>(out->amplitude_[w][k]);
        }
        if (fold > kMaxFold) out->steepness_[k] = static_cast<float>(kMaxFold / fold);
    }
    // Deep everywhere and no shore: the waves are exactly the open-ocean ones.
    bool trivial = field->segment_count == 0;
    for (std::size_t k = 0; k < count && trivial; ++k) {
        trivial = out->depth_[k] > 0.0f && out->steepness_[k] == 1.0f && out->breaking_[k] == 0.0f;
        for (std::size_t w = 0; w < nw && trivial; ++w)
            trivial = out->residual_[w][k] == 0.0f && std::abs(out->amplitude_[w][k] - 1.0f) < 1e-3f;
    }
    out->trivial_ = trivial;
    return std::shared_ptr<const ShoreWaves>(std::move(out));
}

LocalShore ShoreWaves::sample(glm::dvec2 p, std::span<LocalWave> waves) const {
    const double u = std::clamp((p.x - corner_.x) / texel_ - 0.5, 0.0, n_ - 1.0);
    const double v = std::clamp((p.y - corner_.y) / texel_ - 0.5, 0.0, n_ - 1.0);
    const int i = std::min(static_cast<int>(u), n_ - 2), j = std::min(static_cast<int>(v), n_ - 2);
    const double fu = u - i, fv = v - j;
    const std::size_t k00 = static_cast<std::size_t>(j) * static_cast<std::size_t>(n_) + static_cast<std::size_t>(i);
    const std::size_t k10 = k00 + 1, k01 = k00 + static_cast<std::size_t>(n_), k11 = k01 + 1;
    const double w00 = (1 - fu) * (1 - fv), w10 = fu * (1 - fv), w01 = (1 - fu) * fv, w11 = fu * fv;
    auto lerp = [&](const std::vector<float>& f) {
        return w00 * static_cast<double>(f[k00]) + w10 * static_cast<double>(f[k10]) + w01 * static_cast<double>(f[k01]) +
               w11 * static_cast<double>(f[k11]);
    };
    LocalShore s;
    s.depth = lerp(depth_);
    s.shore_distance = lerp(distance_);
    s.breaking = lerp(breaking_);
    s.steepness_scale = lerp(steepness_);
    for (std::size_t w = 0; w < waves.size() && w < residual_.size(); ++w) {
        waves[w].phase_residual = lerp(residual_[w]);
        waves[w].amplitude_factor = s.depth > 0.0 ? lerp(amplitude_[w]) : 0.0;
        waves[w].wavevector = {lerp(kx_[w]), lerp(kz_[w])};
    }
    return s;
}

LagrangianSample evaluate_lagrangian_shore(const WaveSet& set, const ShoreWaves& shore, glm::dvec2 rest, double time,
                                           LocalShore* local) {
    // At most kMaxWaves waves: no allocation in the query's inner loop.
    std::array<LocalWave, kMaxWaves> storage;
    const std::span<LocalWave> lw(storage.data(), set.size());
    const LocalShore ls = shore.sample(rest, lw);
    if (local) *local = ls;
    detail::GerstnerSums g;
    double &dx = g.dx, &dz = g.dz, &eta = g.eta, &mxx = g.mxx, &mxz = g.mxz, &mzz = g.mzz;
    double &sx = g.sx, &sz = g.sz, &vx = g.vx, &vy = g.vy, &vz = g.vz;
    const auto waves = set.waves();
    for (std::size_t i = 0; i < waves.size(); ++i) {
        const Wave& w = waves[i];
        const glm::dvec2 kv = lw[i].wavevector;
        const double kl = std::sqrt(kv.x * kv.x + kv.y * kv.y);
        const double a = w.amplitude * lw[i].amplitude_factor;
        if (a <= 0.0 || kl <= 0.0) continue;
        const glm::dvec2 d = kv / kl;
        const double travelled = std::fmod(w.omega * time, kTwoPi);
        const double theta = w.k * (w.dir_x * rest.x + w.dir_z * rest.y) + lw[i].phase_residual - travelled + w.phase;
        const double s = std::sin(theta), c = std::cos(theta);
        const double qa = w.steepness * ls.steepness_scale * a;
        dx += qa * d.x * c;
        dz += qa * d.y * c;
        eta += a * s;
        mxx += qa * kl * s * d.x * d.x;
        mxz += qa * kl * s * d.x * d.y;
        mzz += qa * kl * s * d.y * d.y;
        sx += a * c * kv.x;
        sz += a * c * kv.y;
        vx += qa * w.omega * d.x * s;
        vz += qa * w.omega * d.y * s;
        vy -= a * w.omega * c;
    }
    return detail::assemble_sample(g);
}

}  // namespace tidewater
