#pragma once
// The bins the bin chart's tests share, for its words (view/bin_histogram_test.cpp) and its
// drawing (render/bin_chart_test.cpp): eight rows of pegs and counts close to the binomial.

#include <cstddef>
#include <vector>

#include <particle_sandbox/bins.hpp>
#include <particle_sandbox/particle_arrays.hpp>

namespace psb::app::test {

/// Bins of width 1 from x = 0 to 9 below y = 5: Binomial(8, 1/2).
inline Bins eightRows() {
    Bins b;
    for (int k = 0; k <= 9; ++k)
        b.edges.push_back(k);
    b.top = 5.0;
    b.binomial = BinomialExpectation{8, 0.5};
    return b;
}

/// `n[k]` particles in bin k (centre k + 1/2, below the top), and `falling` above it.
inline ParticleArrays landed(const std::vector<int>& n, int falling = 0) {
    ParticleArrays p;
    for (std::size_t k = 0; k < n.size(); ++k) {
        for (int i = 0; i < n[k]; ++i) {
            p.x.push_back(static_cast<double>(k) + 0.5);
            p.y.push_back(6.0);
        }
    }
    for (int i = 0; i < falling; ++i) {
        p.x.push_back(4.5);
        p.y.push_back(1.0);
    }
    return p;
}

/// Counts close to 1000 × Binomial(8, 1/2).
inline const std::vector<int> kBell = {4, 31, 109, 219, 273, 219, 109, 31, 5};

}  // namespace psb::app::test
