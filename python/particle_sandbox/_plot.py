"""plot(world): a world's state drawn with Matplotlib (the box, obstacles and particles)."""

import numpy as np


def plot(world, ax=None, color="tab:blue", edgecolor="none", box_color="0.3"):
    """Draws the box, the obstacles and the particles at their true radii; returns the Axes.

    y points down in the world (gravity (0, 9.81) pulls down), so the y axis is inverted.
    """
    import matplotlib.pyplot as plt
    from matplotlib.collections import EllipseCollection, LineCollection
    from matplotlib.patches import Circle, Rectangle

    if ax is None:
        _, ax = plt.subplots()
    width, height = world.box
    ax.add_patch(Rectangle((0.0, 0.0), width, height, fill=False, edgecolor=box_color))
    segments = []
    for o in world.obstacles:
        if o.kind == "peg":
            ax.add_patch(Circle(o.a, o.radius, color=box_color))
        else:
            segments.append((o.a, o.b))
    if segments:
        ax.add_collection(LineCollection(segments, colors=box_color))
    positions = world.positions
    diameters = 2.0 * np.asarray(world.radii)
    ax.add_collection(EllipseCollection(diameters, diameters, np.zeros_like(diameters),
                                        units="xy", offsets=positions, offset_transform=ax.transData,
                                        facecolors=color, edgecolors=edgecolor))
    ax.set_xlim(0.0, width)
    ax.set_ylim(height, 0.0)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    return ax
