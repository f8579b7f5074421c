"""Structured quadrilateral meshes of a (possibly skewed) four-sided region."""
import numpy as np


def quad_patch(corners, nx, ny):
    """Bilinear map of an nx x ny grid onto the quadrilateral with counter-clockwise
    ``corners`` (4, 2). Returns X (nodes, 2), conn (elements, 4) counter-clockwise, and the
    node index grid (ny + 1, nx + 1) for picking edges (row 0 is the first edge)."""
    c = np.asarray(corners, float)
    s, t = np.meshgrid(np.linspace(0, 1, nx + 1), np.linspace(0, 1, ny + 1))
    X = ((1 - s) * (1 - t))[..., None] * c[0] + (s * (1 - t))[..., None] * c[1] \
        + (s * t)[..., None] * c[2] + ((1 - s) * t)[..., None] * c[3]
    grid = np.arange((nx + 1) * (ny + 1)).reshape(ny + 1, nx + 1)
    a = grid[:-1, :-1].ravel()
    conn = np.stack([a, a + 1, a + nx + 2, a + nx + 1], 1)
    return X.reshape(-1, 2), conn, grid


def rectangle(x0, x1, y0, y1, nx, ny):
    return quad_patch([[x0, y0], [x1, y0], [x1, y1], [x0, y1]], nx, ny)
