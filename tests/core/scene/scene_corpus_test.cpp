// The loader's bad-scene corpus: every file under scene_corpus/bad must be refused with
// exactly the message in this table (after "<path>: "), and every file under
// scene_corpus/good must load. The messages are part of the interface: a change here is a
// change users see.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>

#include <particle_sandbox/scene.hpp>

namespace psb {
namespace {

const std::filesystem::path kCorpus = std::filesystem::path(PSB_TEST_DATA_DIR) / "scene_corpus";

// clang-format off
const std::map<std::string, std::string> kExpected = {
    {"allow_overlaps_string.json",
     R"(allow_overlaps: expected true or false, got a string)"},
    {"bins_edge_outside_box.json",
     R"(bins.edges[1]: 1.5 lies outside the box (x from 0 to 1 m))"},
    {"bins_edge_string.json",
     R"(bins.edges[1]: expected a number, got a string)"},
    {"bins_edges_not_increasing.json",
     R"(bins.edges[2]: must be greater than the edge before it (0.3), got 0.2)"},
    {"bins_expected_unknown.json",
     R"(bins.expected.normal: unknown key (expected one of: binomial))"},
    {"bins_in_version_2.json",
     R"(bins: need version 3 or later (the file says version 2))"},
    {"bins_one_edge.json",
     R"(bins.edges: needs 2 to 10001 edges (one more than the bins), got 1)"},
    {"bins_p_above_one.json",
     R"(bins.expected.binomial.p: must be in [0, 1] (got 1.5))"},
    {"bins_top_missing.json",
     R"(bins.top: required key is missing)"},
    {"bins_top_outside_box.json",
     R"(bins.top: 1.5 lies outside the box (y from 0 to 1 m))"},
    {"bins_trials_mismatch.json",
     R"(bins.expected.binomial.trials: 3 trials need 4 bins (0 to 3 successes), the edges make 2)"},
    {"bins_trials_zero.json",
     R"(bins.expected.binomial.trials: must be in [1, 1000000] (got 0))"},
    {"broadphase_unknown.json",
     R"(solver.broadphase: unknown broadphase 'kd-tree' (expected one of: auto, all-pairs, grid, quadtree))"},
    {"color_out_of_range.json",
     R"(particles[0].color[1]: must be in [0, 255] (got 256))"},
    {"color_two_channels.json",
     R"(particles[0].color: expected [r, g, b], got 2 elements)"},
    {"dropper_balls_fraction.json",
     R"(droppers[0].balls: expected an integer, got a number)"},
    {"dropper_balls_negative.json",
     R"(droppers[0].balls: must be in [0, 1000000] (got -3))"},
    {"dropper_in_version_3.json",
     R"(droppers: need version 4 or later (the file says version 3))"},
    {"dropper_inside_obstacle.json",
     R"(droppers[0]: balls would start inside obstacles[0])"},
    {"dropper_interval_negative.json",
     R"(droppers[0].interval: must be > 0 (got -0.5))"},
    {"dropper_interval_zero.json",
     R"(droppers[0].interval: must be > 0 (got 0))"},
    {"dropper_mass_missing.json",
     R"(droppers[0].mass: required key is missing)"},
    {"dropper_nan.json",
     R"(line 4, column 46 (droppers[0].balls): syntax error while parsing value - invalid literal; last read: '"balls": N')"},
    {"dropper_next_after_interval.json",
     R"(droppers[0].next_ball_in: must be at most the interval, 0.1 s (got 0.5))"},
    {"dropper_not_array.json",
     R"(droppers: expected an array, got an object)"},
    {"dropper_outside_box.json",
     R"(droppers[0].x: balls would start outside the 1 x 1 m box (x from 1.5 to 1.5 m, radius 0.01 m))"},
    {"dropper_radius_too_big.json",
     R"(droppers[0].radius: a ball of radius 0.6 m does not fit in the 1 x 1 m box)"},
    {"dropper_radius_zero.json",
     R"(droppers[0].radius: must be > 0 (got 0))"},
    {"dropper_spread_negative.json",
     R"(droppers[0].spread: must be >= 0 (got -0.01))"},
    {"dropper_spread_past_wall.json",
     R"(droppers[0].x: balls would start outside the 1 x 1 m box (x from 0.0050000000000000044 to 0.995 m, radius 0.01 m))"},
    {"dropper_too_many_balls.json",
     R"(droppers[0].balls: must be in [0, 1000000] (got 2000000))"},
    {"dropper_unknown_key.json",
     R"(droppers[0].rate: unknown key (expected one of: x, y, balls, interval, radius, mass, color, vx, vy, spread, seed, released, next_ball_in))"},
    {"dropper_y_outside_box.json",
     R"(droppers[0].y: balls would start outside the 1 x 1 m box (y = -0.2 m, radius 0.01 m))"},
    {"dt_negative.json",
     R"(solver.dt: must be > 0 (got -0.01))"},
    {"duplicate_key.json",
     R"(world.width: duplicate key)"},
    {"friction_negative.json",
     R"(world.friction: must be >= 0 (got -1))"},
    {"generate_count_and_packing.json",
     R"(generate: needs exactly one of 'count' and 'packing')"},
    {"generate_count_negative.json",
     R"(generate.count: must be in [0, 1000000] (got -5))"},
    {"generate_count_too_large.json",
     R"(generate.count: must be in [0, 1000000] (got 2000000))"},
    {"generate_does_not_fit.json",
     R"(generate.count: 100 particles of radius 5 m do not fit in the region (at most 81))"},
    {"generate_missing_radius.json",
     R"(generate.radius: required key is missing)"},
    {"generate_neither_count_nor_packing.json",
     R"(generate: needs exactly one of 'count' and 'packing')"},
    {"generate_not_object.json",
     R"(generate: expected an object or an array of objects, got an integer)"},
    {"generate_overlaps_listed.json",
     R"(particles[0]: overlaps particle 0 of generate[0] (centres 1.885985685141033 m apart, radii sum to 20 m))"},
    {"generate_packing_too_many.json",
     R"(generate.packing: gives 779859221 particles, more than the limit of 1000000)"},
    {"generate_region_inverted.json",
     R"(generate.region: needs x0 < x1 and y0 < y1)"},
    {"generate_region_outside.json",
     R"(generate.region: reaches outside the 700 x 700 m box)"},
    {"generate_seed_negative.json",
     R"(generate.seed: must be in [0, 9223372036854775807] (got -1))"},
    {"generate_temperature_and_speed.json",
     R"(generate: give at most one of 'temperature' and 'speed')"},
    {"generate_temperature_too_hot.json",
     R"(generate.temperature: gives a thermal speed sqrt(kT/m) of 3.162277660168379e+157 m/s, above the limit of 1e+14 m/s)"},
    {"gravity_not_array.json",
     R"(world.gravity: expected an array of 2 numbers, got a number)"},
    {"gravity_three_numbers.json",
     R"(world.gravity: expected an array of 2 numbers, got 3 elements)"},
    {"height_boolean.json",
     R"(world.height: expected a number, got a boolean)"},
    {"huge_value.json",
     R"(world.height: magnitude above 1e+15 (got 1e+300))"},
    {"mode_unknown.json",
     R"(solver.mode: unknown mode 'substeps' (did you mean 'substep'?))"},
    {"name_not_string.json",
     R"(name: expected a string, got an integer)"},
    {"nested_too_deep.json",
     R"(nested deeper than 64 levels)"},
    {"number_overflow.json",
     R"(line 3, column 22 (world.width): number overflow parsing '1e999')"},
    {"obstacle_outside_box.json",
     R"(obstacles[0].to: [12, 3] lies outside the 10 x 10 m box)"},
    {"obstacle_overlaps_particle.json",
     R"(particles[1]: overlaps obstacles[0] (centre 0.5 m from its core line, 0.6 m needed))"},
    {"obstacle_peg_missing_radius.json",
     R"(obstacles[0].radius: required key is missing)"},
    {"obstacle_peg_outside_box.json",
     R"(obstacles[0]: centre [-1, 3] lies outside the 10 x 10 m box)"},
    {"obstacle_peg_wider_than_box.json",
     R"(obstacles[0].radius: must be at most the box's larger side, 6 m (got 148121.6))"},
    {"obstacle_segment_zero_length.json",
     R"(obstacles[1]: has zero length: both ends at [2, 3] (use a peg))"},
    {"obstacle_thicker_than_box.json",
     R"(obstacles[0].thickness: must be at most twice the box's larger side, 20 m (got 30))"},
    {"obstacle_thickness_zero.json",
     R"(obstacles[0].thickness: must be > 0 (got 0))"},
    {"obstacle_unknown_key.json",
     R"(obstacles[0].thickness: unknown key (expected one of: type, x, y, radius))"},
    {"obstacle_unknown_type.json",
     R"(obstacles[0].type: unknown obstacle type 'sgement' (did you mean 'segment'?))"},
    {"obstacles_in_version_1.json",
     R"(obstacles: need version 2 or later (the file says version 1))"},
    {"particle_angle_string.json",
     R"(particles[0].angle: expected a number, got a string)"},
    {"particle_fixed_rotation_number.json",
     R"(particles[0].fixed_rotation: expected true or false, got an integer)"},
    {"particle_inertia_factor_above_one.json",
     R"(particles[0].inertia_factor: must be <= 1 (got 1.5))"},
    {"particle_inertia_factor_denormal.json",
     R"(particles[0].inertia_factor: must be >= 0.001 (got 1e-320))"},
    {"particle_inertia_factor_zero.json",
     R"(particles[0].inertia_factor: must be > 0 (got 0))"},
    {"particle_mass_negative.json",
     R"(particles[3].mass: must be > 0 (got -1))"},
    {"particle_mass_subnormal.json",
     R"(particles[1].mass: must be at least 2.2250738585072014e-308 (got 1e-320))"},
    {"particle_missing_mass.json",
     R"(particles[1].mass: required key is missing)"},
    {"particle_near_key.json",
     R"(particles[0].raduis: unknown key (did you mean 'radius'?))"},
    {"particle_not_object.json",
     R"(particles[1]: expected an object, got an array)"},
    {"particle_outside_box.json",
     R"(particles[1]: not inside the 700 x 700 m box (x = 699.5, y = 10, radius = 1))"},
    {"particle_overlap.json",
     R"(particles[1]: overlaps particles[2] (centres 8 m apart, radii sum to 10 m))"},
    {"particle_radius_zero.json",
     R"(particles[0].radius: must be > 0 (got 0))"},
    {"particle_spin_with_fixed_rotation.json",
     R"(particles[0].angular_velocity: must be 0 for a particle with fixed_rotation (got 2))"},
    {"particle_unknown_key.json",
     R"(particles[0].velocity: unknown key (expected one of: x, y, vx, vy, mass, radius, color, trail, angle, angular_velocity, inertia_factor, fixed_rotation))"},
    {"particle_x_null.json",
     R"(particles[0].x: expected a number, got null)"},
    {"particles_not_array.json",
     R"(particles: expected an array, got an object)"},
    {"restitution_above_one.json",
     R"(world.restitution: must be in [0, 1] (got 1.5))"},
    {"restitution_negative.json",
     R"(world.restitution: must be in [0, 1] (got -0.1))"},
    {"root_not_object.json",
     R"((root): expected an object, got an array)"},
    {"periodic_box_too_small.json",
     R"(world.width: 3 m is too small for a periodic box holding a particle of radius 1 m (particles[0]): a periodic box must be at least two diameters of its largest particle, 4 m)"},
    {"periodic_in_version_5.json",
     R"(world.periodic: need version 6 or later (the file says version 5))"},
    {"periodic_obstacle_near_edge.json",
     R"(obstacles[0]: comes within 0.5 m of an edge of the periodic box: obstacles do not act across the edges, so each must stay the largest particle's diameter (1 m) inside every edge)"},
    {"periodic_with_walls.json",
     R"(world.walls: cannot be true in a periodic world (its edges are joined, so it has no walls): leave 'walls' out or set it false)"},
    {"rotation_in_version_4.json",
     R"(particles[0].angular_velocity: need version 5 or later (the file says version 4))"},
    {"substeps_fraction.json",
     R"(solver.substeps: expected an integer, got a number)"},
    {"substeps_huge.json",
     R"(solver.substeps: must be in [1, 100000] (got 18446744073709551615))"},
    {"substeps_zero.json",
     R"(solver.substeps: must be in [1, 100000] (got 0))"},
    {"syntax_control_character.json",
     R"(line 3, column 15 (name): syntax error while parsing value - invalid string: control character U+0009 (HT) must be escaped to \u0009 or \t; last read: '"tab<U+0009>')"},
    {"syntax_empty_file.json",
     R"(line 1, column 1: syntax error while parsing value - unexpected end of input; expected '[', '{', or a literal)"},
    {"syntax_invalid_utf8.json",
     R"(line 3, column 16 (name): syntax error while parsing value - invalid string: ill-formed UTF-8 byte; last read: '"caf\xe9"')"},
    {"syntax_missing_colon.json",
     R"(line 3, column 12 (name): syntax error while parsing object separator - unexpected string literal; expected ':')"},
    {"syntax_trailing_comma.json",
     R"(line 4, column 1: syntax error while parsing object key - unexpected '}'; expected string literal)"},
    {"syntax_truncated.json",
     R"(line 4, column 20 (particles[0]): syntax error while parsing object - unexpected end of input; expected '}')"},
    {"tangential_restitution_above_one.json",
     R"(world.tangential_restitution: must be in [-1, 1] (got 1.5))"},
    {"tangential_restitution_in_version_4.json",
     R"(world.tangential_restitution: need version 5 or later (the file says version 4))"},
    {"unknown_key_far.json",
     R"(world.colour: unknown key (expected one of: width, height, walls, periodic, gravity, restitution, friction, tangential_restitution))"},
    {"unknown_key_top.json",
     R"(partciles: unknown key (did you mean 'particles'?))"},
    {"unknown_key_world.json",
     R"(world.gravty: unknown key (did you mean 'gravity'?))"},
    {"version_missing.json",
     R"(version: required key is missing)"},
    {"version_string.json",
     R"(version: expected an integer, got a string)"},
    {"version_unsupported.json",
     R"(version: unsupported version 7 (this build reads versions 1 to 6))"},
    {"walls_string.json",
     R"(world.walls: expected true or false, got a string)"},
    {"width_string.json",
     R"(world.width: expected a number, got a string)"},
    {"width_zero.json",
     R"(world.width: must be > 0 (got 0))"},
    {"world_not_object.json",
     R"(world: expected an object, got an array)"},
};
// clang-format on

std::vector<std::filesystem::path> filesIn(const std::filesystem::path& dir) {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

TEST(SceneCorpus, EveryBadSceneIsRefusedWithItsExactMessage) {
    const auto files = filesIn(kCorpus / "bad");
    ASSERT_EQ(files.size(), kExpected.size()) << "every corpus file needs a row in kExpected";
    for (const auto& file : files) {
        SCOPED_TRACE(file.filename().string());
        const auto row = kExpected.find(file.filename().string());
        ASSERT_NE(row, kExpected.end()) << "no expected message for this file";
        try {
            (void)loadScene(file);
            ADD_FAILURE() << "loaded, but must be refused";
        } catch (const SceneError& e) {
            EXPECT_EQ(std::string(e.what()), file.string() + ": " + row->second);
        }
    }
}

TEST(SceneCorpus, EveryGoodSceneLoads) {
    for (const auto& file : filesIn(kCorpus / "good")) {
        SCOPED_TRACE(file.filename().string());
        EXPECT_NO_THROW((void)loadScene(file));
    }
}

TEST(SceneCorpus, TheSameTextGivesTheSameMessageWhateverTheSourceName) {
    // parseScene names the source it is given; loadScene passes the path.
    try {
        (void)parseScene(R"({"version": 1, "world": {"width": -1}})", "<stdin>");
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_STREQ(e.what(), "<stdin>: world.width: must be > 0 (got -1)");
    }
}

}  // namespace
}  // namespace psb
