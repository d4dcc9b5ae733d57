#pragma once
// Mean-squared displacement and velocity autocorrelation against lag, averaged over particles
// and time origins: a new origin every `originEvery` state samples, each kept for `maxLag`
// samples, so a state sample costs O(n × maxLag / originEvery).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "observables/observation_chunk.hpp"

namespace psb::observables {

class TimeCorrelation {
  public:
    void configure(std::size_t particles, std::uint32_t maxLag, std::uint32_t originEvery);
    [[nodiscard]] bool on() const { return maxLag_ > 0; }
    [[nodiscard]] std::uint32_t maxLag() const { return maxLag_; }
    /// State sample number `k` (0 for the first) of positions and velocities in the window's
    /// particle order: adds |r(k) − r(k0)|² and v(k)·v(k0) of every origin k0 within maxLag to
    /// `into`, then starts an origin here if one is due.
    void add(std::uint64_t k, const std::vector<double>& x, const std::vector<double>& y,
             const std::vector<double>& vx, const std::vector<double>& vy, Chunk& into);
    /// Forgets every origin (the particles changed): later samples start afresh.
    void stop() { maxLag_ = 0; }

  private:
    struct Origin {
        std::uint64_t k = 0;
        bool live = false;
        std::vector<double> x, y, vx, vy;
    };
    std::size_t n_ = 0;
    std::uint32_t maxLag_ = 0, originEvery_ = 1;
    std::vector<Origin> origins_;
};

}  // namespace psb::observables
