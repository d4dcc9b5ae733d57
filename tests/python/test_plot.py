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


def test_an_animation_runs_the_world_as_it_is_drawn_and_plays_as_html(preset):
    world = ps.World(preset("09-galton-board.json"))
    animation = ps.animate(world, 0.5, frames=5)
    html = animation.to_jshtml()
    assert world.time == pytest.approx(0.5)
    assert html.count("data:image/png;base64") == 6  # the first state and five frames
    with pytest.raises(ValueError, match="frames"):
        ps.animate(world, 1.0, frames=0)
