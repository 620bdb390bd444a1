"""The stored fields of a fluid3d point as planes: the kind stores either the plane through the box's
centre normal to slice_normal, (frames, rows, columns), or the whole box, (frames, nz, ny, nx)
(stored_fields = "volume"); from a volume this takes the same plane (layer n // 2 along the normal,
columns and rows the other two axes in x, y, z order), so a figure draws either.
"""
from figures import runs


def plane(point, name, frame=-1):
    """Frame `frame` of /fields/<name> on the centre plane normal to the point's slice_normal."""
    data = point["fields/" + name]
    if data.ndim == 3:
        return data[frame]
    volume = data[frame]  # (nz, ny, nx)
    normal = runs.text(point.attrs.get("slice_normal", "y"))
    if normal == "x":
        return volume[:, :, volume.shape[2] // 2]
    if normal == "y":
        return volume[:, volume.shape[1] // 2, :]
    return volume[volume.shape[0] // 2]
