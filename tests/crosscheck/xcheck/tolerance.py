"""Tolerances derived from the resolution (the rule is documented in docs/crosscheck.md).

Each system X has a grid step g_X (solidkit's cell, OpenVDB's voxel, manifold3d's level-set
edge length; 0 for exact Booleans of faceted primitives) and a facet error e_X (how far its
polygonal primitives can lie from the exact surface: the sagitta of its circle polygons, taken
at half the case's bbox diagonal, 0 for solidkit). For systems S and R, with A and V the
solid's area and volume:

  Hausdorff  d_H(S, R) ≤ K_HAUSDORFF (g_S + g_R) + e_S + e_R
             (a grid-based surface lies within a cell diagonal, √3 g, of the exact one, away
             from features thinner than a cell, except at acute tips, which a grid truncates
             where they get thinner than a cell; a faceted surface lies within its sagitta)
  volume     |V_S − V_R| / V ≤ (A/V) · (K_VOLUME (g_S + g_R) + e_S + e_R)
  area       |A_S − A_R| / A ≤ (A/V) · (K_AREA (g_S + g_R) + e_S + e_R)
             (a mean surface displacement of K·g per grid, times the area, over the volume;
             A/V turns a length into a relative error)
  genus, shells, closed and manifold: equal.

Comparing with an exact value uses g = e = 0 on the exact side.
"""
# Calibrated on the case list (docs/crosscheck.md has the measured worst ratios): marching
# cubes, OpenVDB's mesher and manifold3d's level set move the surface by a small fraction of a
# cell on average; sharp edges cut at a cell cost more area than volume.
K_VOLUME = 0.05
K_AREA = 0.3
# √3 covers smooth surfaces, edges and right-angled corners; acute tips are truncated further
# (2.4 cells at the tetrahedron tip of fixtures/examples/polyhedra_mix.rhai).
K_HAUSDORFF = 3.0


def volume_tol(av: float, g_s: float, g_r: float, e_s: float, e_r: float) -> float:
    return av * (K_VOLUME * (g_s + g_r) + e_s + e_r)


def area_tol(av: float, g_s: float, g_r: float, e_s: float, e_r: float) -> float:
    return av * (K_AREA * (g_s + g_r) + e_s + e_r)


def hausdorff_tol(g_s: float, g_r: float, e_s: float, e_r: float) -> float:
    return K_HAUSDORFF * (g_s + g_r) + e_s + e_r


# Marching cubes cuts a crease (faces meeting at an angle φ between their normals) by a chamfer
# whose cross-section is at most ½ g² tan(φ/2): the cut joins the crossings on the two cell
# edges next to the crease, each at most a cell from it. Small against K_VOLUME's term on the
# case list's solids; it dominates on bars and discs a few cells thick (the lattice trees of
# docs/crosscheck.md), where the area term misses it.
K_EDGE = 0.5


def chamfer_tol(g: float, sharp_edges: float) -> float:
    """Volume a grid of step g may cut off or add at creases; `sharp_edges` is
    measure.sharp_edges of the exact (or reference) mesh: Σ ℓ tan(φ/2)."""
    return K_EDGE * g * g * sharp_edges
