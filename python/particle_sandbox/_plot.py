"""plot(world): a world's state drawn with Matplotlib (the box, obstacles and particles)."""

import numpy as np


def _add_discs(world, ax, color, edgecolor):
    """The particles as one collection of discs at their radii (in data units).

    A copy of the state, not the world's views: a figure is a snapshot, and a view kept by it
    would keep the world's storage from growing (World: BufferError).
    """
    from matplotlib.collections import EllipseCollection

    positions, radii = _images(world, np.array(world.positions), np.array(world.radii))
    diameters = 2.0 * radii
    return ax.add_collection(EllipseCollection(
        diameters, diameters, np.zeros_like(diameters), units="xy",
        offsets=positions,
        offset_transform=ax.transData, facecolors=color, edgecolors=edgecolor))


def _images(world, positions, radii):
    """In a periodic box, the discs over an edge (or a corner) again at the opposite one, as the
    window draws them; the axes' limits cut each at the box. Elsewhere the discs as they are."""
    if not getattr(world, "periodic", False) or len(radii) == 0:
        return positions, radii
    width, height = world.box
    shifted, sizes = [positions], [radii]
    x, y = positions[:, 0], positions[:, 1]
    for sx in (-width, 0.0, width):
        for sy in (-height, 0.0, height):
            if sx == 0.0 and sy == 0.0:
                continue
            near = np.ones(len(radii), dtype=bool)
            if sx != 0.0:  # over the edge the shift moves it away from
                near &= (x < radii) if sx > 0 else (x > width - radii)
            if sy != 0.0:
                near &= (y < radii) if sy > 0 else (y > height - radii)
            if near.any():
                shifted.append(positions[near] + (sx, sy))
                sizes.append(radii[near])
    return np.concatenate(shifted), np.concatenate(sizes)


def plot(world, ax=None, color="tab:blue", edgecolor="none", box_color="0.3"):
    """Draws the box, the obstacles and the particles at their true radii; returns the Axes.

    y points down in the world (gravity (0, 9.81) pulls down), so the y axis is inverted. A
    periodic box is drawn with dashed edges, and a disc over an edge again at the opposite one.
    """
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection
    from matplotlib.patches import Circle, Rectangle

    if ax is None:
        _, ax = plt.subplots()
    width, height = world.box
    periodic = getattr(world, "periodic", False)
    ax.add_patch(Rectangle((0.0, 0.0), width, height, fill=False, edgecolor=box_color,
                           linestyle="--" if periodic else "-"))
    segments = []
    for o in world.obstacles:
        if o.kind == "peg":
            ax.add_patch(Circle(o.a, o.radius, color=box_color))
        else:
            segments.append((o.a, o.b))
    if segments:
        ax.add_collection(LineCollection(segments, colors=box_color))
    _add_discs(world, ax, color, edgecolor)
    ax.set_xlim(0.0, width)
    ax.set_ylim(height, 0.0)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    return ax


def animate(world, duration, frames=50, ax=None, **plot_kwargs):
    """A Matplotlib animation of `duration` seconds of the world, stepped as it plays.

    Each of the `frames` frames runs duration / frames seconds (World.run, in steps of
    World.dt) and redraws the particles, so the world has advanced by `duration` once the
    animation has been drawn through (as by anim.to_jshtml(), which a notebook shows inline:
    IPython.display.HTML(anim.to_jshtml())). Particles added or removed during the run
    (droppers) appear and go. Returns the matplotlib.animation.FuncAnimation.
    """
    import matplotlib.pyplot as plt
    from matplotlib.animation import FuncAnimation

    if frames < 1:
        raise ValueError(f"animate: frames must be >= 1 (got {frames})")
    ax = plot(world, ax=ax, **plot_kwargs)
    discs = [ax.collections[-1]]
    interval = duration / frames
    color = plot_kwargs.get("color", "tab:blue")
    edgecolor = plot_kwargs.get("edgecolor", "none")

    def frame(k):
        if k > 0:  # frame 0 is the state as it is
            world.run(interval)
        # A new collection each frame: the count of particles may have changed.
        discs[0].remove()
        discs[0] = _add_discs(world, ax, color, edgecolor)
        ax.set_title(f"t = {world.time:.3f} s")
        return (discs[0],)

    animation = FuncAnimation(ax.figure, frame, frames=frames + 1, interval=40, blit=False,
                              repeat=False)
    plt.close(ax.figure)  # shown through the animation, not as a still figure beside it
    return animation
