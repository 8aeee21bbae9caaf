"""The cross-check harness of solidkit (issue 7): every case of fixtures/crosscheck/cases.json is
built by solidkit (its CLI), by manifold3d, by OpenVDB and by OpenSCAD where expressible, and the
results are compared (volume, area, genus, shells, closed/manifold, Hausdorff distance) within
tolerances derived from the resolution (docs/crosscheck.md).

Modules: paths (where things are), meshio (mesh files), measure (topology and measures of any
triangle mesh, independent of solidkit), tree (the JSON tree: transforms, classification), field
(the tree's field as numpy or scalar Python code), curves, leaves (meshes of single primitives),
build_* (one per system), hausdorff, tolerance, verdict, report, runner (orchestration) and worker
(the subprocess that builds one case in one system); lattice (issue 13's property test: random
lattice trees of boxes and cylinders, solidkit against manifold3d's exact Booleans).
"""
