//! B-spline basis functions and their first two derivatives at one parameter (The NURBS Book,
//! algorithms A2.1 `FindSpan` and A2.3 `DersBasisFuns`), loops only.

/// The span `i` with `knots[i] ≤ t < knots[i + 1]` among the `count` control points' spans
/// (`degree ≤ i < count`), the last span for `t` at the end of the domain.
pub(crate) fn find_span(degree: usize, count: usize, knots: &[f64], t: f64) -> usize {
    let (lo, hi) = (degree, count - 1);
    if t >= knots[hi + 1] {
        // The end of the domain belongs to the last non-empty span.
        let mut i = hi;
        while i > lo && knots[i] >= knots[hi + 1] {
            i -= 1;
        }
        return i;
    }
    if t <= knots[lo] {
        let mut i = lo;
        while i < hi && knots[i + 1] <= knots[lo] {
            i += 1;
        }
        return i;
    }
    let (mut a, mut b) = (lo, hi + 1);
    while b - a > 1 {
        let mid = (a + b) / 2;
        if t < knots[mid] { b = mid } else { a = mid }
    }
    a
}

/// The `degree + 1` non-zero basis functions `N_{span−degree+r}` at `t` and their first and
/// second derivatives: `out[k][r]` is the `k`-th derivative (`k ≤ 2`).
pub(crate) fn basis_derivatives(
    degree: usize,
    span: usize,
    knots: &[f64],
    t: f64,
) -> [Vec<f64>; 3] {
    let p = degree;
    let mut ndu = vec![vec![0.0; p + 1]; p + 1];
    let mut left = vec![0.0; p + 1];
    let mut right = vec![0.0; p + 1];
    ndu[0][0] = 1.0;
    for j in 1..=p {
        left[j] = t - knots[span + 1 - j];
        right[j] = knots[span + j] - t;
        let mut saved = 0.0;
        for r in 0..j {
            // Lower triangle: knot differences; upper: basis values.
            ndu[j][r] = right[r + 1] + left[j - r];
            let temp = if ndu[j][r] == 0.0 {
                0.0
            } else {
                ndu[r][j - 1] / ndu[j][r]
            };
            ndu[r][j] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        ndu[j][j] = saved;
    }
    let mut ders = [vec![0.0; p + 1], vec![0.0; p + 1], vec![0.0; p + 1]];
    for (j, d) in ders[0].iter_mut().enumerate() {
        *d = ndu[j][p];
    }
    let n = 2.min(p);
    let mut a = [vec![0.0; p + 1], vec![0.0; p + 1]];
    for r in 0..=p {
        let (mut s1, mut s2) = (0usize, 1usize);
        a[0][0] = 1.0;
        for k in 1..=n {
            let mut d = 0.0;
            let rk = r as isize - k as isize;
            let pk = p - k;
            if rk >= 0 {
                let rk = rk as usize;
                a[s2][0] = safe_div(a[s1][0], ndu[pk + 1][rk]);
                d = a[s2][0] * ndu[rk][pk];
            }
            let j1 = if rk >= -1 { 1 } else { (-rk) as usize };
            let j2 = if r as isize - 1 <= pk as isize {
                k - 1
            } else {
                p - r
            };
            for j in j1..=j2 {
                let idx = (rk + j as isize) as usize;
                a[s2][j] = safe_div(a[s1][j] - a[s1][j - 1], ndu[pk + 1][idx]);
                d += a[s2][j] * ndu[idx][pk];
            }
            if r <= pk {
                a[s2][k] = safe_div(-a[s1][k - 1], ndu[pk + 1][r]);
                d += a[s2][k] * ndu[r][pk];
            }
            ders[k][r] = d;
            std::mem::swap(&mut s1, &mut s2);
        }
    }
    let mut factor = p as f64;
    for (k, row) in ders.iter_mut().enumerate().take(n + 1).skip(1) {
        for d in row.iter_mut() {
            *d *= factor;
        }
        factor *= (p - k) as f64;
    }
    ders
}

/// `a / b`, 0 where a repeated knot makes `b` zero (the basis function is zero there).
fn safe_div(a: f64, b: f64) -> f64 {
    if b == 0.0 { 0.0 } else { a / b }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bezier_knots_give_bernstein_and_its_derivatives() {
        // Cubic on {0,0,0,0,1,1,1,1}: B_i^3 and derivatives at t = 0.3.
        let knots = [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
        let t: f64 = 0.3;
        let span = find_span(3, 4, &knots, t);
        assert_eq!(span, 3);
        let d = basis_derivatives(3, span, &knots, t);
        let s = 1.0 - t;
        let b = [s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t];
        let db = [
            -3.0 * s * s,
            3.0 * s * s - 6.0 * t * s,
            6.0 * t * s - 3.0 * t * t,
            3.0 * t * t,
        ];
        let ddb = [6.0 * s, -12.0 * s + 6.0 * t, 6.0 * s - 12.0 * t, 6.0 * t];
        for i in 0..4 {
            assert!((d[0][i] - b[i]).abs() < 1e-14);
            assert!((d[1][i] - db[i]).abs() < 1e-13);
            assert!((d[2][i] - ddb[i]).abs() < 1e-12);
        }
        assert_eq!(find_span(3, 4, &knots, 1.0), 3);
    }

    #[test]
    fn uniform_cubic_partition_of_unity_and_end_span() {
        let knots: Vec<f64> = (0..10).map(f64::from).collect();
        for &t in &[3.0, 3.5, 4.2, 5.999, 6.0] {
            let span = find_span(3, 6, &knots, t);
            assert!((3..6).contains(&span), "{t} {span}");
            let d = basis_derivatives(3, span, &knots, t);
            assert!((d[0].iter().sum::<f64>() - 1.0).abs() < 1e-14);
            assert!(d[1].iter().sum::<f64>().abs() < 1e-12);
            assert!(d[2].iter().sum::<f64>().abs() < 1e-12);
        }
        // At t = 3 the first point weighs 1/6 (the notes' (P0 + 4P1 + P2)/6 start).
        let d = basis_derivatives(3, 3, &knots, 3.0);
        assert!((d[0][0] - 1.0 / 6.0).abs() < 1e-15 && (d[0][1] - 4.0 / 6.0).abs() < 1e-15);
    }
}
