// Discs that turn, in the session: the Physics section's Roughness (tangential restitution) and
// Discs turn, and the edits of a particle's angular velocity and inertia factor, each applied,
// refused with a message when bad, and undone.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "session/session.hpp"
#include "session/session_fixture.hpp"
#include "session/test_assets.hpp"

namespace psb::app {
namespace {

class SessionSpin : public SessionFixture {
  protected:
    SessionSpin() : SessionFixture("psb-session-spin", TestWindow{}) {}

    /// A launch at rest into empty space at `x` m along the bottom of the default scene's box,
    /// under its particles: the new particle.
    static Particle launch(Session& s, double t0, double x) {
        const std::vector<ParticleId> before = s.world().ids();
        const Vec2 spot(x, 6.3);
        psb::app::drag(s, spot, spot, t0, 2, 0.2, 0.5);
        for (const ParticleId id : s.world().ids()) {
            if (std::find(before.begin(), before.end(), id) == before.end()) {
                return s.world().get(id);
            }
        }
        ADD_FAILURE() << "no particle launched";
        return {};
    }
};

TEST_F(SessionSpin, RoughnessIsSetUndoneAndRefusedOutsideMinusOneToOne) {
    Session s = session();
    s.apply(cmd::SetTangentialRestitution{0.5});
    EXPECT_DOUBLE_EQ(s.world().def().tangentialRestitution, 0.5);
    EXPECT_TRUE(said(s.takeNotices(), "Tangential restitution 0.50"));
    EXPECT_EQ(s.lastAction(), "set tangential restitution");
    // A drag is one action: its later values continue the first.
    const auto actions = s.userActions();
    s.apply(cmd::SetTangentialRestitution{0.6, true});
    s.apply(cmd::SetTangentialRestitution{-0.4, true});
    EXPECT_EQ(s.userActions(), actions);
    EXPECT_DOUBLE_EQ(s.world().def().tangentialRestitution, -0.4);
    for (const double bad : {-1.5, 1.01, std::numeric_limits<double>::quiet_NaN(),
                             std::numeric_limits<double>::infinity()}) {
        s.apply(cmd::SetTangentialRestitution{bad});
        EXPECT_TRUE(said(s.takeNotices(), "Tangential restitution must be between -1 and 1"))
            << bad;
        EXPECT_DOUBLE_EQ(s.world().def().tangentialRestitution, -0.4);
    }
    s.apply(cmd::Undo{});
    EXPECT_DOUBLE_EQ(s.world().def().tangentialRestitution, 0.0) << "the drag undone at once";
    s.apply(cmd::Redo{});
    EXPECT_DOUBLE_EQ(s.world().def().tangentialRestitution, -0.4);
}

TEST_F(SessionSpin, DiscsTurnDecidesWhetherNewParticlesHaveFixedRotation) {
    Session s = session();
    EXPECT_TRUE(s.spawn().turn) << "the default scene's particles turn, and so do new ones";
    EXPECT_FALSE(launch(s, 1.0, 1.0).fixedRotation);
    s.apply(cmd::SetDiscsTurn{false});
    EXPECT_FALSE(s.spawn().turn);
    EXPECT_TRUE(said(s.takeNotices(), "New particles have fixed rotation"));
    EXPECT_TRUE(launch(s, 3.0, 3.0).fixedRotation);
    EXPECT_TRUE(s.world().rotationInUse()) << "a fixed-rotation particle is rotation state";
    const std::size_t n = s.world().size();
    s.apply(cmd::SpawnRandom{});
    ASSERT_EQ(s.world().size(), n + 1);
    EXPECT_TRUE(s.world().get(s.world().ids().back()).fixedRotation) << "M's particles too";
    // Undo: the spawn, the launch, then the setting.
    s.apply(cmd::Undo{});
    s.apply(cmd::Undo{});
    EXPECT_FALSE(s.spawn().turn);
    s.apply(cmd::Undo{});
    EXPECT_TRUE(s.spawn().turn);
}

TEST_F(SessionSpin, AScenesOfGrainsThatDoNotTurnMakesNewOnesThatDoNotTurn) {
    Session s = session();
    s.apply(cmd::OpenFile{testAsset("scenes/10-funnel.json")});
    ASSERT_GT(s.world().size(), 0u);
    EXPECT_FALSE(s.spawn().turn);
    s.apply(cmd::OpenFile{testAsset("scenes/12-ramp.json")});
    EXPECT_TRUE(s.spawn().turn) << "the ramp's ball and disc turn";
}

TEST_F(SessionSpin, AnEditGivesSpinAndAnInertiaFactorAndUndoTakesThemBack) {
    Session s = session();
    const ParticleId id = s.world().ids().front();
    ASSERT_FALSE(s.world().rotationInUse());
    s.apply(cmd::EditParticle{id, ParticleField::Vx, "1.5"});
    EXPECT_FALSE(s.world().rotationInUse()) << "an edit of the rest keeps a world without spin";
    s.apply(cmd::EditParticle{id, ParticleField::Omega, "6.25"});
    EXPECT_TRUE(s.editRefusal().empty()) << s.editRefusal();
    // Typed with y up (the default): counterclockwise, which the world's y-down axes call -6.25.
    ASSERT_TRUE(s.view().yUp);
    EXPECT_DOUBLE_EQ(s.world().get(id).angularVelocity, -6.25);
    EXPECT_TRUE(s.world().rotationInUse());
    s.apply(cmd::EditParticle{id, ParticleField::Inertia, "0.4"});
    EXPECT_DOUBLE_EQ(s.world().get(id).inertiaFactor, 0.4);
    EXPECT_EQ(s.lastAction(), "edit particle");
    s.apply(cmd::Undo{});
    EXPECT_DOUBLE_EQ(s.world().get(id).inertiaFactor, kDefaultInertiaFactor);
    EXPECT_DOUBLE_EQ(s.world().get(id).angularVelocity, -6.25);
    s.apply(cmd::Undo{});
    EXPECT_DOUBLE_EQ(s.world().get(id).angularVelocity, 0.0);
}

TEST_F(SessionSpin, BadSpinsAndInertiaFactorsAreRefusedWithTheReason) {
    Session s = session();
    const ParticleId id = s.world().ids().front();
    s.apply(cmd::EditParticle{id, ParticleField::Omega, "2"});
    const Particle before = s.world().get(id);
    const auto refused = [&](ParticleField field, const char* text, const char* why) {
        s.apply(cmd::EditParticle{id, field, text});
        EXPECT_NE(s.editRefusal().find(why), std::string::npos) << text << ": " << s.editRefusal();
        const Particle after = s.world().get(id);
        EXPECT_EQ(after.angularVelocity, before.angularVelocity) << text;
        EXPECT_EQ(after.inertiaFactor, before.inertiaFactor) << text;
    };
    refused(ParticleField::Inertia, "0", "k: the inertia factor must be from 0.001 to 1");
    refused(ParticleField::Inertia, "1.5", "k: the inertia factor must be from 0.001 to 1");
    refused(ParticleField::Inertia, "-0.4", "k: the inertia factor must be from 0.001 to 1");
    // A denormal k made every contact NaN (1/k overflowed): the session fuzzer's finding.
    refused(ParticleField::Inertia, "1e-320", "k: the inertia factor must be from 0.001 to 1");
    refused(ParticleField::Inertia, "half", "k: 'half' is not a number");
    refused(ParticleField::Omega, "nan", "omega:");
    refused(ParticleField::Omega, "1e300", "omega: the rim would move at");
    refused(ParticleField::Omega, "", "omega: empty");
    // A particle with fixed rotation keeps omega 0.
    s.apply(cmd::SetDiscsTurn{false});
    const Vec2 spot(3.5, 6.3);
    psb::app::drag(s, spot, spot, 5.0, 2, 0.2, 0.5);
    const ParticleId block = s.world().ids().back();
    ASSERT_TRUE(s.world().get(block).fixedRotation);
    s.apply(cmd::EditParticle{block, ParticleField::Omega, "3"});
    EXPECT_NE(s.editRefusal().find("has fixed rotation (it never turns)"), std::string::npos)
        << s.editRefusal();
    EXPECT_EQ(s.world().get(block).angularVelocity, 0.0);
    s.apply(cmd::EditParticle{block, ParticleField::Omega, "0"});
    EXPECT_TRUE(s.editRefusal().empty()) << "0 is what it has";
}

TEST_F(SessionSpin, ThePromptEditsOmegaAndKWithTheRest) {
    Session s = session();
    const ParticleId id = s.world().ids().front();
    s.apply(cmd::Select{id});
    s.apply(cmd::OpenEdit{});
    ASSERT_TRUE(s.prompt().active());
    EXPECT_EQ(s.prompt().text(EditField::Omega), "0");
    EXPECT_EQ(s.prompt().text(EditField::Inertia), "0.5");
    for (int k = 0; k < 4; ++k)
        s.apply(cmd::EditField{});
    ASSERT_EQ(s.prompt().field(), EditField::Omega);
    s.apply(cmd::EditType{"-3.5"});
    s.apply(cmd::EditField{});
    s.apply(cmd::EditType{"0.4"});
    s.apply(cmd::EditApply{});
    EXPECT_FALSE(s.prompt().active());
    // -3.5 typed with y up is clockwise: +3.5 in the world's axes; the message says what was typed.
    EXPECT_DOUBLE_EQ(s.world().get(id).angularVelocity, 3.5);
    EXPECT_DOUBLE_EQ(s.world().get(id).inertiaFactor, 0.4);
    EXPECT_TRUE(said(s.takeNotices(), "omega -3.5 rad/s, k 0.4"));
    // A bad k: refused, the prompt stays open with the reason.
    s.apply(cmd::OpenEdit{});
    s.apply(cmd::EditField{true});
    ASSERT_EQ(s.prompt().field(), EditField::Inertia);
    s.apply(cmd::EditType{"2"});
    s.apply(cmd::EditApply{});
    EXPECT_TRUE(s.prompt().active());
    EXPECT_NE(s.prompt().error().find("inertia factor must be from 0.001 to 1"), std::string::npos)
        << s.prompt().error();
    EXPECT_DOUBLE_EQ(s.world().get(id).inertiaFactor, 0.4);
}

TEST_F(SessionSpin, TheSpinMarksAreShownUnlessSwitchedOff) {
    Session s = session();
    EXPECT_TRUE(s.view().spin);
    s.apply(cmd::SetShow{ShowOption::Spin, false});
    EXPECT_FALSE(s.view().spin);
    EXPECT_TRUE(said(s.takeNotices(), "Spin marks off"));
}

}  // namespace
}  // namespace psb::app
