"""The 3-D creatures and their flow as triangles, from a point file alone: the geoms' surfaces from
their recorded type, size and pose (/topology/geom_type, /lagrangian/geom_size_m, geom_position_m,
geom_rotation: MuJoCo's geom_size, geom_xpos and row-major geom_xmat), the flesh's skin when recorded
(/lagrangian/flesh_position_m, /topology/flesh_triangles), and isosurfaces of a stored
cell-centred field (/fields/<name>, (frames, nz, ny, nx)) by marching tetrahedra: each cube of eight
neighbouring cell centres cut into six tetrahedra along its main diagonal (Kuhn's triangulation, so
that neighbouring cubes share their faces' cuts), the surface linear along each tetrahedron's edges.
"""
import numpy as np

# MuJoCo's geom types (mjtGeom).
SPHERE, CAPSULE, ELLIPSOID, CYLINDER, BOX, MESH = 2, 3, 4, 5, 6, 7

# Kuhn's six tetrahedra of a cube whose corner c = i + 2 j + 4 k sits at offset (i, j, k).
_TETS = np.array([[0, 1, 3, 7], [0, 1, 5, 7], [0, 2, 3, 7], [0, 2, 6, 7], [0, 4, 5, 7], [0, 4, 6, 7]])
_CORNERS = [(c & 1, (c >> 1) & 1, (c >> 2) & 1) for c in range(8)]
_OTHERS = np.array([[1, 2, 3], [0, 2, 3], [0, 1, 3], [0, 1, 2]])


def _revolve(profile, slices):
    """Triangles (n, 3, 3) of a surface of revolution about z: profile is a list of (radius, z) from the
    top pole to the bottom one."""
    phi = np.linspace(0.0, 2.0 * np.pi, slices, endpoint=False)
    rings = np.array([[(r * np.cos(p), r * np.sin(p), z) for p in phi] for r, z in profile])
    tris = []
    for a in range(len(profile) - 1):
        for s in range(slices):
            t = (s + 1) % slices
            p00, p01, p10, p11 = rings[a, s], rings[a, t], rings[a + 1, s], rings[a + 1, t]
            tris.append((p00, p10, p11))
            tris.append((p00, p11, p01))
    return np.array(tris)


def geom_triangles(geom_type, size, slices=16):
    """Triangles (n, 3, 3) of one geom in its own frame (m), or None for a type drawn from a mesh the
    point file does not hold."""
    rings = max(2, slices // 2)
    theta = np.linspace(0.0, np.pi, rings + 1)
    if geom_type in (SPHERE, ELLIPSOID):
        unit = _revolve([(np.sin(t), np.cos(t)) for t in theta], slices)
        scale = np.full(3, size[0]) if geom_type == SPHERE else np.asarray(size[:3])
        return unit * scale
    if geom_type == CAPSULE:
        r, h = size[0], size[1]
        top = [(r * np.sin(t), h + r * np.cos(t)) for t in theta if t <= np.pi / 2]
        bottom = [(r * np.sin(t), -h + r * np.cos(t)) for t in theta if t >= np.pi / 2]
        return _revolve(top + bottom, slices)
    if geom_type == CYLINDER:
        r, h = size[0], size[1]
        return _revolve([(0.0, h), (r, h), (r, -h), (0.0, -h)], slices)
    if geom_type == BOX:
        c = np.array([[(2 * (k & 1) - 1) * size[0], (2 * ((k >> 1) & 1) - 1) * size[1],
                       (2 * ((k >> 2) & 1) - 1) * size[2]] for k in range(8)])
        faces = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
        return np.array([tri for a, b, d, e in faces for tri in ((c[a], c[b], c[d]), (c[a], c[d], c[e]))])
    return None


def half_extents(geom_type, size):
    """Half-extents (3,) of a geom's bounding box in its own frame (m); a mesh geom's from its size."""
    r = size[0]
    if geom_type == SPHERE:
        return np.array([r, r, r])
    if geom_type == CAPSULE:
        return np.array([r, r, size[1] + r])
    if geom_type == CYLINDER:
        return np.array([r, r, size[1]])
    return np.abs(np.asarray(size[:3], dtype=float))


def creature_triangles(point, frame):
    """World triangles (n, 3, 3) of every geom at lagrangian frame `frame`, and the number of geoms
    skipped (mesh geoms: their vertices are not stored)."""
    types = point["topology/geom_type"][()]
    size = point["lagrangian/geom_size_m"][frame]
    pos = point["lagrangian/geom_position_m"][frame]
    rot = point["lagrangian/geom_rotation"][frame].reshape(-1, 3, 3)
    out, skipped = [], 0
    for g, t in enumerate(types):
        local = geom_triangles(int(t), size[g])
        if local is None:
            skipped += 1
            continue
        out.append(local @ rot[g].T + pos[g])
    return (np.concatenate(out) if out else np.zeros((0, 3, 3))), skipped


def flesh_triangles(point, frame):
    """World triangles (n, 3, 3) of the flesh's skin at lagrangian frame `frame`
    (/lagrangian/flesh_position_m, /topology/flesh_triangles), or None when the run has no flesh."""
    if "lagrangian/flesh_position_m" not in point or "topology/flesh_triangles" not in point:
        return None
    x = point["lagrangian/flesh_position_m"][frame]
    return x[point["topology/flesh_triangles"][()].reshape(-1, 3)]


def cell_centres(point):
    """The stored box's cell centres along x, y, z (m, world)."""
    f = point["fields"]
    nz, ny, nx = f["q_per_s2"].shape[1:]
    dx = float(f.attrs["dx_m"])
    return [float(f.attrs[f"origin_{a}_m"]) + (np.arange(n) + 0.5) * dx for a, n in zip("xyz", (nx, ny, nz))]


def isosurface(volume, level, axes, colour_field=None):
    """Triangles (n, 3, 3) where the cell-centred `volume` (nz, ny, nx) crosses `level`, on the grid
    of cell centres `axes` (x, y, z); with `colour_field` (same shape) also its value at each
    triangle's centre (n,), linear along the tetrahedra's edges as the surface is."""
    v = np.transpose(np.asarray(volume, dtype=float), (2, 1, 0))  # (nx, ny, nz)
    c = np.transpose(np.asarray(colour_field, dtype=float), (2, 1, 0)) if colour_field is not None else np.zeros_like(v)
    nx, ny, nz = v.shape
    gx, gy, gz = np.meshgrid(*axes, indexing="ij")
    grid = np.stack([gx, gy, gz], axis=-1)

    def corner(a, k):
        i, j, l = _CORNERS[k]
        return a[i:nx - 1 + i, j:ny - 1 + j, l:nz - 1 + l].reshape((-1,) + a.shape[3:])

    values = np.stack([corner(v, k) for k in range(8)], axis=1)
    colours = np.stack([corner(c, k) for k in range(8)], axis=1)
    points = np.stack([corner(grid, k) for k in range(8)], axis=1)
    tris, tri_colours = [], []
    for tet in _TETS:
        val, col, pts = values[:, tet], colours[:, tet], points[:, tet]
        inside = val > level
        count = inside.sum(axis=1)
        rows = np.arange(len(val))

        def cut(sel, a, b):
            va, vb = val[sel, a], val[sel, b]
            t = ((level - va) / np.where(vb == va, 1.0, vb - va))[:, None]
            r = rows[sel]
            return pts[r, a] + t * (pts[r, b] - pts[r, a]), col[r, a] + t[:, 0] * (col[r, b] - col[r, a])

        single = (count == 1) | (count == 3)
        if single.any():
            iso = np.where(count[single] == 1, np.argmax(inside[single], 1), np.argmin(inside[single], 1))
            others = _OTHERS[iso]
            cuts = [cut(single, iso, others[:, m]) for m in range(3)]
            tris.append(np.stack([p for p, _ in cuts], axis=1))
            tri_colours.append(np.mean([q for _, q in cuts], axis=0))
        double = count == 2
        if double.any():
            order = np.argsort(~inside[double], axis=1, kind="stable")
            a, b, d, e = (order[:, m] for m in range(4))
            ad, ae, be, bd = cut(double, a, d), cut(double, a, e), cut(double, b, e), cut(double, b, d)
            for p, q, s in ((ad, ae, be), (ad, be, bd)):
                tris.append(np.stack([p[0], q[0], s[0]], axis=1))
                tri_colours.append((p[1] + q[1] + s[1]) / 3.0)
    if not tris:
        return np.zeros((0, 3, 3)), np.zeros(0)
    return np.concatenate(tris), np.concatenate(tri_colours)


def shade(triangles, rgba, light=(0.3, -0.5, 0.8)):
    """Lambert-shaded colours (n, 4) of triangles (n, 3, 3) with base colours rgba (n, 4): either side
    lit alike (the isosurface's orientation is not kept)."""
    n = np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0])
    n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-300)
    lamp = np.asarray(light, dtype=float) / np.linalg.norm(light)
    k = 0.35 + 0.65 * np.abs(n @ lamp)
    out = np.array(rgba, dtype=float, copy=True)
    out[:, :3] *= k[:, None]
    return out
