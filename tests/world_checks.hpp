#pragma once
// What the tests of changes made to a running world check after each step, shared by the core's
// and the session's: every particle finite and, with walls, inside the box. And where the
// scenes they run live: tests/core/scene/scene_corpus/good.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <particle_sandbox/scene.hpp>
#include <particle_sandbox/world.hpp>

namespace psb::test {

/// Every particle's position and velocity finite and, with walls on, its centre inside the box
/// (to 1e-9 m); `when` names the moment in a failure.
inline void expectInsideTheBox(const World& w, const std::string& when) {
    const WorldDef& def = w.def();
    for (const ParticleId id : w.ids()) {
        const Particle p = w.get(id);
        ASSERT_TRUE(std::isfinite(p.position.x()) && std::isfinite(p.position.y()) &&
                    std::isfinite(p.velocity.x()) && std::isfinite(p.velocity.y()))
            << when;
        if (!def.walls) continue;
        EXPECT_GE(p.position.x(), p.radius - 1e-9) << when;
        EXPECT_LE(p.position.x(), def.width - p.radius + 1e-9) << when;
        EXPECT_GE(p.position.y(), p.radius - 1e-9) << when;
        EXPECT_LE(p.position.y(), def.height - p.radius + 1e-9) << when;
    }
}

/// A scene of the loader's good corpus (tests/core/scene/scene_corpus/good) by file name.
inline Scene corpusScene(const std::string& file) {
    return loadScene(std::filesystem::path(PSB_TEST_SOURCE_DIR) / "core" / "scene" /
                     "scene_corpus" / "good" / file);
}

}  // namespace psb::test
