#pragma once
// The world as Python holds it: the core's World, the frame length its scene gave, and what
// keeps NumPy views of its storage valid.

#include <atomic>
#include <cstddef>

#include <particle_sandbox/world.hpp>

#include "bindings.hpp"

namespace psb::python {

/// Owns a World for Python.
///
/// Views. World.positions and the other arrays are NumPy views of the world's own vectors, each
/// holding a StorageLease (their `base`) that keeps this object alive and counts the views. A
/// vector that grows past its capacity moves, which would leave a view pointing at freed
/// memory, so while any view lives nothing here lets the storage move: adding past the
/// capacity raises BufferError (as NumPy's own resize does with views about), clear() removes
/// particle by particle, and every view reserves room for each ball the droppers still hold,
/// so that steps never move the storage.
///
/// Threads. step(), run() and measure() release the GIL; while one runs, any other call on the
/// same world raises RuntimeError instead of racing it.
class PyWorld {
  public:
    PyWorld(World world, double dt) : world_(std::move(world)), dt_(dt) {}

    /// The world, for a call that does not step it. Throws RuntimeError while it steps.
    World& world();
    /// The world, for a read that needs no exclusive use (views' shapes). Same check.
    const World& view() const;

    [[nodiscard]] double dt() const { return dt_; }
    void setDt(double dt);

    /// Makes sure `extra` more particles fit without the storage moving; while views live,
    /// throws BufferError if they do not.
    void ensureRoom(std::size_t extra, const char* what);
    /// Balls the droppers still hold.
    [[nodiscard]] std::size_t pendingBalls() const;
    /// Lowest capacity among the arrays views read.
    [[nodiscard]] std::size_t capacity() const;

    void leaseOpened();
    void leaseClosed() { --views_; }
    [[nodiscard]] int views() const { return views_; }

    /// Marks the world busy (stepping with the GIL released) for its lifetime.
    class Busy {
      public:
        explicit Busy(PyWorld& w);
        ~Busy() { w_.busy_ = false; }
        Busy(const Busy&) = delete;
        Busy& operator=(const Busy&) = delete;

      private:
        PyWorld& w_;
    };

  private:
    void checkIdle() const;
    World world_;
    double dt_;
    int views_ = 0;
    std::atomic<bool> busy_{false};
};

/// The `base` of every view: keeps the PyWorld alive and counted while the view lives.
class StorageLease {
  public:
    explicit StorageLease(py::object owner);
    ~StorageLease();
    StorageLease(const StorageLease&) = delete;
    StorageLease& operator=(const StorageLease&) = delete;

  private:
    py::object owner_;
};

/// The views World exposes, each documented where it is bound (world.cpp).
enum class Field { Positions, Velocities, Angles, Spins, Masses, Radii, Ids };

/// A read-only NumPy view of `field` over the storage of the PyWorld `owner` (no copy).
py::array particleView(const py::object& owner, Field field);

/// Binds StorageLease (not constructible from Python).
void bindArrays(py::module_& m);

}  // namespace psb::python
