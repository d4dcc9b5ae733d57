#include <particle_sandbox/validation.hpp>

#include <cmath>

#include "world/validate.hpp"

namespace psb {
namespace {

class Problems {
  public:
    void add(std::string_view setting, std::string message, std::string_view because = {}) {
        out_.push_back({setting, std::move(message), because});
    }
    void positive(std::string_view setting, double v) {
        if (!std::isfinite(v) || !(v > 0.0))
            add(setting, "must be finite and > 0 " + detail::got(v));
    }
    [[nodiscard]] std::vector<SettingProblem> take() { return std::move(out_); }

  private:
    std::vector<SettingProblem> out_;
};

}  // namespace

std::vector<SettingProblem> validate(const WorldDef& def, const SolverSettings& s) {
    Problems p;
    p.positive("width", def.width);
    p.positive("height", def.height);
    if (!std::isfinite(def.gravity.x()) || !std::isfinite(def.gravity.y())) {
        p.add("gravity", "must be finite (got " + detail::pointText(def.gravity) + ")");
    }
    if (!std::isfinite(def.restitution) || def.restitution < 0.0 || def.restitution > 1.0) {
        p.add("restitution", "must be in [0, 1] " + detail::got(def.restitution));
    }
    if (!std::isfinite(def.friction) || def.friction < 0.0) {
        p.add("friction", "must be finite and >= 0 " + detail::got(def.friction));
    }
    if (!std::isfinite(def.tangentialRestitution) || def.tangentialRestitution < -1.0 ||
        def.tangentialRestitution > 1.0) {
        p.add("tangential restitution",
              "must be in [-1, 1] " + detail::got(def.tangentialRestitution));
    }
    if (s.substeps < 1 || s.substeps > kMaxSubsteps) {
        p.add("substeps", "must be in [1, " + std::to_string(kMaxSubsteps) + "] (got " +
                              std::to_string(s.substeps) + ")");
    }
    // An enumerator outside the lists (a cast from an integer) would make step() do nothing.
    if (toString(s.mode) == "?") p.add("mode", "is not a known step mode");
    if (toString(s.broadphase) == "?") p.add("broadphase", "is not a known broadphase");
    return p.take();
}

std::string describe(const SettingProblem& problem) {
    return std::string(problem.setting) + ' ' + problem.message;
}

}  // namespace psb
