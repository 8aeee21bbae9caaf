//! Warnings the pipeline attaches to a result that may be incomplete or wrong: open mesh
//! operands, a polygonization that is empty or not a closed manifold, and fragments split off by
//! features thinner than a cell.

use crate::TopologyReport;
use solidkit_kernel::primitive::MeshSource;
use solidkit_kernel::{NodeKind, Primitive, Solid};

/// One warning per open mesh operand of `solid` (edges whose two directions are not used equally
/// often): such a solid is where the mesh's winding number is at least ½, which caps each hole.
/// Sorted, without repeats.
pub fn open_operands(solid: &Solid) -> Vec<String> {
    let mut warnings = Vec::new();
    solid.fold(|node, _: &[()]| {
        if let NodeKind::Primitive(Primitive::Mesh(m)) = node.kind()
            && m.open_edges() > 0
        {
            let what = match m.source() {
                MeshSource::File { path } => format!("mesh \"{path}\""),
                other => other.name().to_string(),
            };
            warnings.push(format!(
                "{what} is not closed ({} open edges): its inside is where its winding number is at least 1/2, which caps each hole",
                m.open_edges()
            ));
        }
    });
    warnings.sort();
    warnings.dedup();
    warnings
}

/// The warning for a polygonization `report` that is not a closed manifold. The mesher's output
/// is closed and manifold by construction when the field's samples and interval bounds agree;
/// where they do not (parameters near the limits of floating point) the result may be wrong, and
/// must not be silent.
pub fn not_closed_manifold(report: &TopologyReport) -> Option<String> {
    (report.faces > 0 && !(report.closed && report.manifold)).then(|| {
        format!(
            "the mesh is not a closed manifold ({} boundary edges, {} non-manifold edges, {} non-manifold vertices): the field could not be evaluated faithfully everywhere, so the result may be wrong",
            report.boundary_edges, report.non_manifold_edges, report.non_manifold_vertices
        )
    })
}

/// The warning for an empty polygonization: nothing of the solid was found inside the grid (an
/// empty Boolean result such as a part cut away whole, or parts thinner than the refinement
/// reaches, which are reported on their own too). OpenSCAD refuses such a model ("top level
/// object is empty"); here the empty mesh is written, and said so.
pub fn empty(report: &TopologyReport) -> Option<String> {
    (report.faces == 0).then(|| {
        "the mesh is empty: no part of the solid was found inside the grid (nothing is inside, or every part is thinner than the refinement reaches)".to_string()
    })
}

/// The warning for a solid that reaches beyond its bounding box `bbox` (as the tree computes it)
/// to the edge of the grid padded around it: the mesh is cut there, and closed by a cap half a
/// cell inside the grid's edge.
pub fn beyond_box(bbox: &solidkit_kernel::Aabb) -> String {
    format!(
        "the solid reaches beyond its bounding box [{:e}, {:e}, {:e}]..[{:e}, {:e}, {:e}] to the edge of the grid: the mesh is cut and capped there, so part of the solid may be missing",
        bbox.min.x, bbox.min.y, bbox.min.z, bbox.max.x, bbox.max.y, bbox.max.z
    )
}

/// Shells at most this many cells across (bounding-box diagonal) are fragments.
pub const FRAGMENT_CELLS: f64 = 2.0;

/// The warning for shells at most [`FRAGMENT_CELLS`] cells of `cell` across beside larger ones:
/// pieces the grid split off a solid where a feature thinner than a cell joins them (the tip of a
/// sharp edge that crosses the grid diagonally, a neck, a fin), or parts smaller than the grid
/// can shape. Either way the shell count, and the fragments' shape, are not to be trusted; a
/// finer grid moves or removes them.
pub fn fragments(report: &TopologyReport, cell: f64) -> Option<String> {
    let small = |b: &[glam::DVec3; 2]| (b[1] - b[0]).length() <= FRAGMENT_CELLS * cell;
    let count = report.shell_boxes.iter().filter(|b| small(b)).count();
    let first = report.shell_boxes.iter().find(|b| small(b))?;
    (count < report.shell_boxes.len()).then(|| {
        let c = (first[0] + first[1]) / 2.0;
        format!(
            "{count} of the {} shells are at most {FRAGMENT_CELLS} cells ({:.6}) across (one near {:.6}, {:.6}, {:.6}): fragments split off where a feature thinner than a cell (a sharp edge crossing the grid diagonally, a neck, a fin) joins them to the solid, or parts too small for the grid; the shell count may be wrong; raise --resolution",
            report.shell_boxes.len(),
            FRAGMENT_CELLS * cell,
            c.x,
            c.y,
            c.z
        )
    })
}
