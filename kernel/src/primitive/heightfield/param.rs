//! The height function's values, derivatives and global bounds in the parameters `(u, v)`: what
//! every height source (Bézier patch, interpolated samples) computes.

/// `h` and its derivatives with respect to the parameters `(u, v)`.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct ParamDerivatives {
    pub h: f64,
    pub hu: f64,
    pub hv: f64,
    pub huu: f64,
    pub huv: f64,
    pub hvv: f64,
}

/// Bounds over the whole parameter square: `lo ≤ h ≤ hi`, `|h_u| ≤ hu`, `|h_v| ≤ hv`, and where `h`
/// is C¹ with bounded second derivatives `(|h_uu|, |h_uv|, |h_vv|)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ParamBounds {
    pub lo: f64,
    pub hi: f64,
    pub hu: f64,
    pub hv: f64,
    pub second: Option<(f64, f64, f64)>,
}
