"""geomesh: run Gmsh-compatible .geo scripts, or build models from Python, and read their
meshes as NumPy arrays.

    mesh = geomesh.run("plate.geo", dim=2, numbers={"size": 0.05})
    mesh.nodes                  # (N, 3) float64, a read-only view of the mesh (no copy)
    mesh.elements()["triangle"]  # (M, 3) 0-based node indices

    geomesh.initialize()
    box = geomesh.model.occ.addBox(0, 0, 0, 1, 1, 1)
    geomesh.model.occ.synchronize()
    geomesh.model.mesh.generate(3)
    tags, xyz, _ = geomesh.model.mesh.getNodes()
    geomesh.finalize()
"""

from ._geomesh import (
    Error,
    Mesh,
    MeshError,
    ScriptError,
    __version__,
    clear,
    current_mesh,
    finalize,
    fltk,
    graphics,
    initialize,
    isInitialized,
    logger,
    merge,
    model,
    onelab,
    option,
    plugin,
    run,
    view,
    write,
)

__all__ = [
    "Error",
    "Mesh",
    "MeshError",
    "ScriptError",
    "__version__",
    "clear",
    "current_mesh",
    "finalize",
    "fltk",
    "graphics",
    "initialize",
    "isInitialized",
    "logger",
    "merge",
    "model",
    "onelab",
    "option",
    "plugin",
    "run",
    "view",
    "write",
]
