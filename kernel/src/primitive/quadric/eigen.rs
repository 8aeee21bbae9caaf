//! Eigen-decomposition of a symmetric 3×3 matrix by the cyclic Jacobi method: a fixed number of
//! sweeps of plane rotations, each zeroing one off-diagonal entry. Accurate to a few ulps of the
//! matrix norm for every symmetric input, including repeated and zero eigenvalues.

use glam::{DMat3, DVec3};

/// Eigenvalues (ascending) and the matching orthonormal eigenvectors (columns) of a symmetric
/// matrix (only its symmetric part is used).
pub fn symmetric_eigen(m: DMat3) -> (DVec3, DMat3) {
    let s = (m + m.transpose()) * 0.5;
    let mut a = s.to_cols_array_2d();
    let mut v = DMat3::IDENTITY.to_cols_array_2d();
    let norm2: f64 = a.iter().flatten().map(|x| x * x).sum();
    for _sweep in 0..64 {
        let off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        if off <= norm2 * 1e-34 || off == 0.0 {
            break;
        }
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            rotate(&mut a, &mut v, p, q);
        }
    }
    let mut order = [0usize, 1, 2];
    order.sort_by(|&i, &j| a[i][i].total_cmp(&a[j][j]));
    let values = DVec3::new(
        a[order[0]][order[0]],
        a[order[1]][order[1]],
        a[order[2]][order[2]],
    );
    let vectors = DMat3::from_cols(
        DVec3::from_array(v[order[0]]),
        DVec3::from_array(v[order[1]]),
        DVec3::from_array(v[order[2]]),
    );
    (values, vectors)
}

/// One Jacobi rotation in the (p, q) plane: `a ← JᵀaJ` with `J` chosen so that `a[p][q]` becomes 0;
/// the eigenvector columns `v` accumulate `J`. (Arrays are column-major, `a` is symmetric.)
fn rotate(a: &mut [[f64; 3]; 3], v: &mut [[f64; 3]; 3], p: usize, q: usize) {
    let apq = a[q][p];
    if apq == 0.0 {
        return;
    }
    let theta = (a[q][q] - a[p][p]) / (2.0 * apq);
    let t = if theta.abs() > 1e150 {
        0.5 / theta
    } else {
        theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt())
    };
    let c = 1.0 / (t * t + 1.0).sqrt();
    let s = t * c;
    // a ← a J (columns p and q).
    rotate_columns(a, p, q, c, s);
    // a ← Jᵀ a (rows p and q).
    for col in a.iter_mut() {
        let (apk, aqk) = (col[p], col[q]);
        col[p] = c * apk - s * aqk;
        col[q] = s * apk + c * aqk;
    }
    a[q][p] = 0.0;
    a[p][q] = 0.0;
    rotate_columns(v, p, q, c, s);
}

/// Columns `p` and `q` of `m` (column-major) replaced by `c·m_p − s·m_q` and `s·m_p + c·m_q`.
fn rotate_columns(m: &mut [[f64; 3]; 3], p: usize, q: usize, c: f64, s: f64) {
    let (mp, mq) = (m[p], m[q]);
    for (row, (xp, xq)) in mp.iter().zip(mq).enumerate() {
        m[p][row] = c * xp - s * xq;
        m[q][row] = s * xp + c * xq;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::primitive::conformance::Rng;

    #[test]
    fn decomposition_reconstructs_random_symmetric_matrices() {
        let mut rng = Rng::new(11);
        for k in 0..500 {
            let mut m = DMat3::from_cols(rng.vec(3.0), rng.vec(3.0), rng.vec(3.0));
            m = m + m.transpose();
            if k % 5 == 0 {
                // Rank-deficient and repeated eigenvalues.
                let u = rng.vec(1.0).normalize();
                m = DMat3::from_cols(u * u.x, u * u.y, u * u.z) * 2.0;
            }
            let (w, v) = symmetric_eigen(m);
            assert!(w.x <= w.y && w.y <= w.z);
            let back = v * DMat3::from_diagonal(w) * v.transpose();
            let err = (back - m)
                .to_cols_array()
                .iter()
                .map(|x| x.abs())
                .fold(0.0, f64::max);
            assert!(err < 1e-12 * (1.0 + m.to_cols_array().iter().map(|x| x.abs()).sum::<f64>()));
            let ortho = v.transpose() * v - DMat3::IDENTITY;
            assert!(ortho.to_cols_array().iter().all(|x| x.abs() < 1e-12));
        }
    }

    #[test]
    fn diagonal_matrix_keeps_its_values() {
        let (w, _) = symmetric_eigen(DMat3::from_diagonal(DVec3::new(3.0, -1.0, 0.0)));
        assert_eq!(w, DVec3::new(-1.0, 0.0, 3.0));
    }
}
