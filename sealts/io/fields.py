"""Fields on the seal's mesh: the final state (``write_fields``, fields.xdmf) and fields
over time as one XDMF + HDF5 time series (ParaView: open the .xdmf, play the time steps,
"Warp By Vector" with the displacement to see the deformed seal).

The mesh is stored once; each ``add`` appends one time step's arrays to the HDF5 file,
flushes it, and rewrites the small XDMF file (to a temporary name, then renamed), so an
interrupted run leaves a readable series of the steps written so far. Only rank 0 writes.
"""
import os
from pathlib import Path

import numpy as np


class FieldSeries:
    def __init__(self, path, X, conn, root=True, frames=None):
        """``frames``: a resumed run's frames so far, ``steps`` of the series it continues
        (its HDF5 file is kept up to them, later frames dropped)."""
        self.root = root
        if not root:
            return
        import h5py
        self.xdmf = Path(path).with_suffix(".xdmf")
        self.h5name = self.xdmf.with_suffix(".h5").name
        self.nn, self.nc = X.shape[0], conn.shape[0]
        self.steps = []            # (t, [(name, center, shape)])
        if frames is not None:
            self.h5 = h5py.File(self.xdmf.with_suffix(".h5"), "r+")
            for name in list(self.h5):
                if name.startswith("step") and int(name[4:]) >= len(frames):
                    del self.h5[name]
            self.steps = [(float(t), [(n, c, tuple(s)) for n, c, s in items])
                          for t, items in frames]
            self._write_xdmf()
            return
        self.h5 = h5py.File(self.xdmf.with_suffix(".h5"), "w")
        points = np.zeros((X.shape[0], 3))
        points[:, :2] = X
        self.h5["mesh/geometry"] = points
        self.h5["mesh/topology"] = np.asarray(conn, np.int64)

    def add(self, t, point_data, cell_data=None):
        """Point arrays (n_nodes or n_nodes x k) and cell arrays (n_cells) at time t."""
        if not self.root:
            return
        k = len(self.steps)
        items = []
        for center, data in (("Node", point_data), ("Cell", cell_data or {})):
            for name, v in data.items():
                v = np.asarray(v, float)
                self.h5[f"step{k}/{name}"] = v
                items.append((name, center, v.shape))
        self.h5.flush()
        self.steps.append((float(t), items))
        self._write_xdmf()

    def _write_xdmf(self):
        h5 = self.h5name
        grids = []
        for k, (t, items) in enumerate(self.steps):
            attrs = []
            for name, center, shape in items:
                kind = "Scalar" if len(shape) == 1 else "Vector"
                dims = " ".join(str(d) for d in shape)
                attrs.append(
                    f'<Attribute Name="{name}" AttributeType="{kind}" Center="{center}">'
                    f'<DataItem Dimensions="{dims}" Format="HDF">{h5}:/step{k}/{name}'
                    "</DataItem></Attribute>")
            grids.append(
                f'<Grid Name="seal" GridType="Uniform"><Time Value="{t:.12g}"/>'
                f'<Topology TopologyType="Quadrilateral" NumberOfElements="{self.nc}">'
                f'<DataItem Dimensions="{self.nc} 4" NumberType="Int" Format="HDF">'
                f"{h5}:/mesh/topology</DataItem></Topology>"
                '<Geometry GeometryType="XYZ">'
                f'<DataItem Dimensions="{self.nn} 3" Format="HDF">{h5}:/mesh/geometry'
                "</DataItem></Geometry>" + "".join(attrs) + "</Grid>")
        text = ('<?xml version="1.0"?>\n<Xdmf Version="3.0"><Domain>'
                '<Grid Name="series" GridType="Collection" CollectionType="Temporal">\n'
                + "\n".join(grids) + "\n</Grid></Domain></Xdmf>\n")
        tmp = self.xdmf.with_suffix(".xdmf.tmp")
        tmp.write_text(text)
        os.replace(tmp, self.xdmf)

    def close(self):
        if self.root:
            self.h5.close()


def write_fields(path, model, u):
    """Deformed-state fields as XDMF + HDF5 (ParaView): displacement on nodes, stresses on
    cells, on the reference mesh (apply ParaView's 'Warp By Vector' to see the deformation)."""
    import meshio

    from ..solid.stresses import stress_cells
    cells = stress_cells(model.full_solid(), u)
    disp = np.zeros((model.mesh.X.shape[0], 3))
    disp[:, :2] = u[model.udofs]
    points = np.zeros((model.mesh.X.shape[0], 3))
    points[:, :2] = model.mesh.X
    meshio.write(path, meshio.Mesh(
        points, [("quad", model.mesh.conn)], point_data={"displacement": disp},
        cell_data={k: [v] for k, v in cells.items()}))


