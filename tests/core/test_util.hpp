#pragma once
// Small helpers shared by the core tests.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <stdlib.h>  // mkdtemp

#include <particle_sandbox/world.hpp>

namespace psb::test {

/// A world with walls off and the given restitution: pair tests that must not see a wall.
inline World openWorld(double restitution = 1.0, double friction = 0.0) {
    WorldDef def;
    def.width = 1e6;
    def.height = 1e6;
    def.walls = false;
    def.restitution = restitution;
    def.friction = friction;
    return World(def);
}

inline double relErr(double got, double want) {
    const double scale = std::max(std::abs(want), 1e-300);
    return std::abs(got - want) / scale;
}

/// FNV-1a over raw bytes.
inline std::uint64_t fnv1a(std::uint64_t h, const void* data, std::size_t bytes) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < bytes; ++k)
        h = (h ^ b[k]) * 1099511628211ull;
    return h;
}

/// A hash of the bits of every particle's position, velocity and id (in storage order) and of
/// the running counters: equal hashes mean bit-identical states.
inline std::uint64_t stateHash(const World& w) {
    const ParticleArrays& p = w.particles();
    std::uint64_t h = 1469598103934665603ull;
    h = fnv1a(h, p.x.data(), p.size() * sizeof(double));
    h = fnv1a(h, p.y.data(), p.size() * sizeof(double));
    h = fnv1a(h, p.vx.data(), p.size() * sizeof(double));
    h = fnv1a(h, p.vy.data(), p.size() * sizeof(double));
    h = fnv1a(h, p.id.data(), p.size() * sizeof(ParticleId));
    const StepCounters& c = w.counters();
    h = fnv1a(h, &c.collisions, sizeof c.collisions);
    h = fnv1a(h, &c.wallCollisions, sizeof c.wallCollisions);
    h = fnv1a(h, &c.wallImpulse, sizeof c.wallImpulse);
    h = fnv1a(h, &c.maxOverlap, sizeof c.maxOverlap);
    return h;
}

/// A fresh directory under the system's temporary directory, removed with everything in it
/// (after giving the owner back every permission a test took away).
class TempDir {
  public:
    explicit TempDir(const std::string& prefix) {
        std::string pattern =
            (std::filesystem::temp_directory_path() / (prefix + "-XXXXXX")).string();
        if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
        path_ = pattern;
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::permissions(path_, std::filesystem::perms::owner_all,
                                     std::filesystem::perm_options::add, ec);
        std::filesystem::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    [[nodiscard]] const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
};

/// The whole content of a file (empty if it cannot be read).
inline std::string readFile(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace psb::test
