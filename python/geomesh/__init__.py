"""geomesh: run Gmsh-compatible .geo scripts and read their meshes as NumPy arrays.

    mesh = geomesh.run("plate.geo", dim=2, numbers={"size": 0.05})
    mesh.nodes                  # (N, 3) float64, a read-only view of the mesh (no copy)
    mesh.elements()["triangle"]  # (M, 3) 0-based node indices
"""

from ._geomesh import Error, Mesh, MeshError, ScriptError, __version__, run

__all__ = ["Error", "Mesh", "MeshError", "ScriptError", "__version__", "run"]
