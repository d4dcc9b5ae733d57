#pragma once
// The observables window's data, kept in chunks of equal numbers of samples: every sum a value
// is computed from, so that a value is a function of a chunk (the whole window is the sum of its
// chunks) and its error the spread of that function over the chunks (block averaging). When the
// chunks reach 2 × kBlocks, neighbours merge and each chunk spans twice as many samples: memory
// stays bounded however long the window, and the blocks stay equal.

#include <cstdint>
#include <vector>

namespace psb::observables {

struct Chunk {
    std::uint64_t intervals = 0;  ///< sample intervals
    double time = 0.0;            ///< s
    double virial = 0.0;          ///< Σ r_ij·J_ij of pair collisions, kg·m²/s
    double wallImpulse = 0.0;     ///< Σ |J| of wall rebounds, kg·m/s
    std::uint64_t collisions = 0;
    std::uint64_t wallCollisions = 0;  ///< wall rebounds
    std::uint64_t states = 0;          ///< state samples (the particles read)
    double kinetic = 0.0;              ///< Σ over state samples of Σ ½ m |v|², J
    double rotational = 0.0;           ///< Σ over state samples of Σ ½ I ω², J
    double speed = 0.0;                ///< Σ over state samples of the mean speed, m/s
    std::uint64_t snapshots = 0;       ///< g(r) snapshots
    std::vector<double> pairs;         ///< unordered pairs per g(r) bin, summed over snapshots
    std::vector<double> msd, vacf;     ///< Σ over origins and particles, per lag
    std::vector<double> lagCount;      ///< origin-particle terms per lag

    void add(const Chunk& o) {
        intervals += o.intervals;
        time += o.time;
        virial += o.virial;
        wallImpulse += o.wallImpulse;
        collisions += o.collisions;
        wallCollisions += o.wallCollisions;
        states += o.states;
        kinetic += o.kinetic;
        rotational += o.rotational;
        speed += o.speed;
        snapshots += o.snapshots;
        addTo(pairs, o.pairs);
        addTo(msd, o.msd);
        addTo(vacf, o.vacf);
        addTo(lagCount, o.lagCount);
    }

  private:
    static void addTo(std::vector<double>& a, const std::vector<double>& b) {
        if (a.size() < b.size()) a.resize(b.size(), 0.0);
        for (std::size_t k = 0; k < b.size(); ++k)
            a[k] += b[k];
    }
};

/// The chunks of a window, `span` sample intervals each (the last one filling).
class Chunks {
  public:
    explicit Chunks(int blocks) : max_(2 * static_cast<std::size_t>(blocks)) { reset(); }
    void reset() {
        chunks_.assign(1, Chunk{});
        span_ = 1;
    }
    /// The chunk the next interval belongs to (a new one when the last is full).
    Chunk& forNextInterval() {
        if (chunks_.back().intervals >= span_) {
            if (chunks_.size() == max_) merge();
            if (chunks_.back().intervals >= span_) chunks_.emplace_back();
        }
        return chunks_.back();
    }
    /// The chunk being filled.
    Chunk& current() { return chunks_.back(); }
    [[nodiscard]] const std::vector<Chunk>& all() const { return chunks_; }
    [[nodiscard]] std::uint64_t span() const { return span_; }
    /// The sum of every chunk.
    [[nodiscard]] Chunk total() const {
        Chunk t;
        for (const Chunk& c : chunks_)
            t.add(c);
        return t;
    }

  private:
    void merge() {
        std::vector<Chunk> merged;
        for (std::size_t k = 0; k < chunks_.size(); k += 2) {
            Chunk c = chunks_[k];
            if (k + 1 < chunks_.size()) c.add(chunks_[k + 1]);
            merged.push_back(std::move(c));
        }
        chunks_.swap(merged);
        span_ *= 2;
    }
    std::size_t max_;
    std::vector<Chunk> chunks_;
    std::uint64_t span_ = 1;
};

}  // namespace psb::observables
