"""plot(world): the box, the obstacles and every particle drawn at its radius."""

import pytest

import particle_sandbox as ps

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")


def test_every_particle_and_peg_is_drawn_in_the_box(preset):
    import matplotlib.pyplot as plt
    world = ps.World(preset("09-galton-board.json"))
    world.run(1.0)
    ax = ps.plot(world)
    discs = ax.collections[-1]
    assert len(discs.get_offsets()) == len(world) > 0
    pegs = [p for p in ax.patches if type(p).__name__ == "Circle"]
    assert len(pegs) == sum(o.kind == "peg" for o in world.obstacles)
    width, height = world.box
    assert ax.get_xlim() == (0.0, width)
    assert ax.get_ylim() == (height, 0.0)  # y points down
    plt.close(ax.figure)


def test_a_periodic_box_is_dashed_and_a_disc_over_a_corner_is_drawn_in_all_four(preset):
    import matplotlib.pyplot as plt
    scene = ps.Scene()
    scene.world.width, scene.world.height = 10.0, 8.0
    scene.world.walls, scene.world.periodic = False, True
    for x, y in ((0.2, 0.3), (5.0, 4.0), (9.9, 4.0)):  # a corner, the middle, the right edge
        p = ps.ParticleDef()
        p.position, p.radius = (x, y), 0.5
        scene.particles.append(p)
    world = ps.World(scene)
    ax = ps.plot(world)
    box = [p for p in ax.patches if type(p).__name__ == "Rectangle"][0]
    assert box.get_linestyle() == "--"
    drawn = sorted(map(tuple, ax.collections[-1].get_offsets().round(6).tolist()))
    assert drawn == sorted([(0.2, 0.3), (10.2, 0.3), (0.2, 8.3), (10.2, 8.3),  # the corner's
                            (5.0, 4.0), (9.9, 4.0), (-0.1, 4.0)])
    plt.close(ax.figure)


def test_an_animation_runs_the_world_as_it_is_drawn_and_plays_as_html(preset):
    world = ps.World(preset("09-galton-board.json"))
    animation = ps.animate(world, 0.5, frames=5)
    html = animation.to_jshtml()
    assert world.time == pytest.approx(0.5)
    assert html.count("data:image/png;base64") == 6  # the first state and five frames
    with pytest.raises(ValueError, match="frames"):
        ps.animate(world, 1.0, frames=0)
