//! Ground truth of a generated solid and how it was obtained.

use serde::Serialize;

/// How a true value was obtained.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum TruthMethod {
    /// Counted on an exact polyhedron (V, E, F, shells, genus of the polyhedral mesh).
    ExactPolyhedron,
    /// A closed-form expression evaluated in double precision.
    ClosedForm,
    /// Numerical quadrature with a stated error bound.
    Quadrature,
    /// Sampling of the exact field with a stated standard error.
    Sampling,
    /// Known from how the solid or mesh was built (e.g. separate shells, defects put in).
    Construction,
}

/// A true value with its method and uncertainty.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Quantity {
    /// The value.
    pub value: f64,
    /// How it was obtained.
    pub method: TruthMethod,
    /// Standard error of a sampled value.
    pub standard_error: Option<f64>,
    /// Bound of the error of a quadrature (or of rounding in a closed form).
    pub error_bound: Option<f64>,
}

impl Quantity {
    /// A closed-form value.
    pub fn closed_form(value: f64) -> Quantity {
        Quantity {
            value,
            method: TruthMethod::ClosedForm,
            standard_error: None,
            error_bound: None,
        }
    }

    /// A quadrature value with its error bound.
    pub fn quadrature(value: f64, error_bound: f64) -> Quantity {
        Quantity {
            value,
            method: TruthMethod::Quadrature,
            standard_error: None,
            error_bound: Some(error_bound),
        }
    }

    /// A sampled value with its standard error.
    pub fn sampled(value: f64, standard_error: f64) -> Quantity {
        Quantity {
            value,
            method: TruthMethod::Sampling,
            standard_error: Some(standard_error),
            error_bound: None,
        }
    }
}

/// What is known exactly about a generated solid (`None`: not known).
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct Truth {
    /// Volume.
    pub volume: Option<Quantity>,
    /// Surface area.
    pub area: Option<Quantity>,
    /// Total genus over the shells.
    pub genus: Option<i64>,
    /// Connected surface components.
    pub shells: Option<usize>,
    /// `V − E + F` of the surface (of the mesh for counted meshes, of the exact surface
    /// otherwise; they agree for closed manifolds).
    pub euler_characteristic: Option<i64>,
    /// Vertices of the mesh as built (exact polyhedra and parametric grids).
    pub vertices: Option<u64>,
    /// Edges of the mesh as built.
    pub edges: Option<u64>,
    /// Triangles of the mesh as built.
    pub faces: Option<u64>,
    /// Bounding box `[min, max]` of the exact solid.
    pub bbox: Option<[[f64; 3]; 2]>,
    /// How genus, shells and χ are known.
    pub topology_method: Option<TruthMethod>,
    /// Remarks (e.g. what is unknown and why).
    pub note: Option<String>,
}

impl Truth {
    /// Genus `genus` summed over `shells` closed shells: χ = 2·shells − 2·genus.
    pub fn with_topology(mut self, shells: usize, genus: i64, method: TruthMethod) -> Truth {
        self.shells = Some(shells);
        self.genus = Some(genus);
        self.euler_characteristic = Some(2 * shells as i64 - 2 * genus);
        self.topology_method = Some(method);
        self
    }

    /// Mesh counts `(V, E, F)`.
    pub fn with_counts(mut self, (v, e, f): (u64, u64, u64)) -> Truth {
        self.vertices = Some(v);
        self.edges = Some(e);
        self.faces = Some(f);
        self
    }

    /// Counts of a closed triangle mesh of Euler characteristic `chi` with `faces` triangles:
    /// `E = 3F/2`, `V = χ + E − F`.
    pub fn with_closed_counts(self, faces: u64) -> Truth {
        let chi = self.euler_characteristic.unwrap_or(2);
        let edges = 3 * faces / 2;
        let vertices = (chi + edges as i64 - faces as i64) as u64;
        self.with_counts((vertices, edges, faces))
    }

    /// The bounding box from its two corners.
    pub fn with_bbox(mut self, min: [f64; 3], max: [f64; 3]) -> Truth {
        self.bbox = Some([min, max]);
        self
    }

    /// A remark.
    pub fn with_note(mut self, note: impl Into<String>) -> Truth {
        self.note = Some(note.into());
        self
    }
}
