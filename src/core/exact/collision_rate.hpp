#pragma once
// How often each particle collides, counted in windows of simulated time, for the exact mode's
// rattle guard (resting.cpp, "Rattling"): a particle that collides more than a limit
// within one window is caught. Windows start at a particle's first collision after the last
// window ended, so the count depends on the trajectory alone, not on how steps chop time.

#include <cstdint>
#include <vector>

namespace psb::exact {

class CollisionRate {
  public:
    /// Sizes the counts for n particles, none counted yet.
    void reset(std::uint32_t n) {
        start_.assign(n, -1e300);
        count_.assign(n, 0);
        quietUntil_.assign(n, -1e300);
    }
    /// Counts a collision of particle i at time `now`; returns whether i has collided more
    /// than `limit` times within `window` seconds (and starts a new window if so).
    bool exceeds(std::uint32_t i, double now, double window, std::uint32_t limit) {
        if (now < quietUntil_[i]) return false;
        if (now - start_[i] > window) {
            start_[i] = now;
            count_[i] = 0;
        }
        if (++count_[i] <= limit) return false;
        start_[i] = -1e300;
        return true;
    }
    /// i is not caught before `until` (seconds): it was set free and is falling.
    void quiet(std::uint32_t i, double until) { quietUntil_[i] = until; }
    [[nodiscard]] bool quietAt(std::uint32_t i, double now) const { return now < quietUntil_[i]; }
    /// Follows a renumbering of the particles: particle i is now to[i].
    void renumber(const std::vector<std::uint32_t>& to) {
        permute(start_, to);
        permute(count_, to);
        permute(quietUntil_, to);
    }
    [[nodiscard]] std::size_t memoryBytes() const {
        return sizeof(double) * (start_.capacity() + quietUntil_.capacity()) +
               sizeof(std::uint32_t) * count_.capacity();
    }

  private:
    template <typename T>
    static void permute(std::vector<T>& v, const std::vector<std::uint32_t>& to) {
        std::vector<T> out(v.size());
        for (std::size_t i = 0; i < v.size(); ++i)
            out[to[i]] = v[i];
        v.swap(out);
    }
    std::vector<double> start_;
    std::vector<std::uint32_t> count_;
    std::vector<double> quietUntil_;
};

}  // namespace psb::exact
