#pragma once
// The cell list of the exact mode: a uniform grid whose cells are at least one largest diameter
// wide, each holding an intrusive doubly linked list of the particles whose centres it owns.
//
// Why it exists. A particle can only touch particles in its own cell and the eight around it,
// so predicting its next collision looks at a handful of particles instead of all N; moving a
// particle between cells is O(1) (unlink, link). Particles change cell at cell-crossing events
// that the stepper schedules like collisions; a particle's cell is the one those events say it
// is in (integer coordinates kx, ky), never recomputed from its rounded position, so a centre a
// few ulps past a face does not make it vanish from its neighbours' searches. The stepper makes
// cells wider than the largest diameter by twice a "skin" and moves a particle only once it is
// a skin past a face (grid.cpp), so two touching discs are always in neighbouring
// cells.
//
// Bounded and unbounded worlds. With walls the grid covers the box exactly (nx·sx = width) and
// the outer faces are never crossed (the walls come first). Without walls particles fly
// anywhere, so cell coordinates are unbounded 64-bit integers folded onto the grid modulo
// (nx, ny): far-apart particles may share a cell, which costs a few extra tests but is never
// wrong, because pair tests use true positions.

#include <cstdint>
#include <vector>

namespace psb::exact {

class CellList {
  public:
    static constexpr std::uint32_t kNone = UINT32_MAX;

    /// Makes an empty grid of nx × ny cells of sx × sy metres with its corner at (ox, oy), for
    /// particles 0..n-1. `wrap` folds out-of-range coordinates back onto the grid (walls off);
    /// otherwise coordinates are clamped to the grid (walls on). nx, ny >= 3 when wrapping.
    void reset(double ox, double oy, double sx, double sy, std::int64_t nx, std::int64_t ny,
               bool wrap, std::uint32_t n);

    [[nodiscard]] std::int64_t coordX(double x) const { return coord(x, ox_, sx_, nx_); }
    [[nodiscard]] std::int64_t coordY(double y) const { return coord(y, oy_, sy_, ny_); }
    /// Lower face of cell column kx / row ky, metres.
    [[nodiscard]] double faceX(std::int64_t kx) const {
        return ox_ + static_cast<double>(kx) * sx_;
    }
    [[nodiscard]] double faceY(std::int64_t ky) const {
        return oy_ + static_cast<double>(ky) * sy_;
    }
    [[nodiscard]] std::int64_t nx() const { return nx_; }
    [[nodiscard]] std::int64_t ny() const { return ny_; }
    [[nodiscard]] bool wraps() const { return wrap_; }

    /// Cell index of coordinates (kx, ky), or kNone if outside a non-wrapping grid.
    [[nodiscard]] std::uint32_t cell(std::int64_t kx, std::int64_t ky) const {
        if (wrap_) {
            kx %= nx_;
            if (kx < 0) kx += nx_;
            ky %= ny_;
            if (ky < 0) ky += ny_;
        } else if (kx < 0 || kx >= nx_ || ky < 0 || ky >= ny_) {
            return kNone;
        }
        return static_cast<std::uint32_t>(ky * nx_ + kx);
    }

    /// Empties every cell, keeping the geometry.
    void clearMembers();
    /// Bytes held (capacities of the cell heads and the membership links).
    [[nodiscard]] std::size_t memoryBytes() const {
        return sizeof(std::uint32_t) * head_.capacity() + sizeof(Link) * link_.capacity();
    }
    void insert(std::uint32_t i, std::uint32_t cell);
    void erase(std::uint32_t i);
    [[nodiscard]] std::uint32_t head(std::uint32_t cell) const { return head_[cell]; }
    [[nodiscard]] std::uint32_t next(std::uint32_t i) const { return link_[i].next; }

  private:
    [[nodiscard]] std::int64_t coord(double v, double o, double s, std::int64_t n) const;

    double ox_ = 0.0, oy_ = 0.0, sx_ = 1.0, sy_ = 1.0;
    std::int64_t nx_ = 1, ny_ = 1;
    bool wrap_ = false;
    std::vector<std::uint32_t> head_;
    struct Link {
        std::uint32_t next, prev, cell;  // neighbours in the cell's list, and the cell
    };
    std::vector<Link> link_;  // one line holds a particle's whole membership
};

}  // namespace psb::exact
