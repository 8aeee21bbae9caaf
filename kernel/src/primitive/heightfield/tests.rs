//! Tests of height fields: conformance for every source, the exact zero set, honest slope bounds,
//! curvature against closed forms, and PNG decoding.

use super::*;
use crate::primitive::conformance::{Rng, check_shape};

fn bezier_bump() -> HeightField {
    let rows = vec![
        vec![0.2, 0.5, 0.4, 0.3],
        vec![0.4, 1.2, 1.0, 0.5],
        vec![0.3, 0.9, 1.4, 0.6],
    ];
    let grid = HeightGrid::from_rows(&rows).unwrap();
    HeightField::new(
        DVec2::new(-1.0, -0.5),
        DVec2::new(1.0, 0.7),
        -0.3,
        HeightSource::Bezier(grid),
    )
    .unwrap()
}

fn sampled(interpolation: Interpolation) -> HeightField {
    let (nx, ny) = (7, 5);
    let values = (0..nx * ny)
        .map(|k| {
            let (i, j) = ((k % nx) as f64, (k / nx) as f64);
            0.5 + 0.3 * (1.3 * i).sin() * (0.9 * j).cos()
        })
        .collect();
    let grid = HeightGrid::new(nx, ny, values).unwrap();
    HeightField::new(
        DVec2::new(-1.2, -1.0),
        DVec2::new(1.0, 0.8),
        0.0,
        HeightSource::Samples {
            grid,
            interpolation,
        },
    )
    .unwrap()
}

/// `h = (x² + y²) / (2R)` over `[−a, a]²` as an exact biquadratic Bézier patch.
fn paraboloid(a: f64, r: f64) -> HeightField {
    let c = [1.0, -1.0, 1.0];
    let rows: Vec<Vec<f64>> = (0..3)
        .map(|j| (0..3).map(|i| a * a * (c[i] + c[j]) / (2.0 * r)).collect())
        .collect();
    HeightField::new(
        DVec2::splat(-a),
        DVec2::splat(a),
        -1.0,
        HeightSource::Bezier(HeightGrid::from_rows(&rows).unwrap()),
    )
    .unwrap()
}

#[test]
fn every_source_conforms() {
    check_shape(&bezier_bump(), 1.6);
    check_shape(&sampled(Interpolation::Bilinear), 1.6);
    check_shape(&sampled(Interpolation::Bicubic), 1.6);
    check_shape(&sampled(Interpolation::Quads), 1.6);
    check_shape(&paraboloid(1.0, 0.8), 1.6);
}

#[test]
fn zero_set_is_the_graph_and_the_base() {
    let mut rng = Rng::new(41);
    for hf in [
        bezier_bump(),
        sampled(Interpolation::Bicubic),
        sampled(Interpolation::Bilinear),
    ] {
        let (lo, hi) = (hf.min(), hf.max());
        for _ in 0..500 {
            let t = (DVec2::new(rng.next(), rng.next()) + 1.0) * 0.5;
            let xy = lo + (hi - lo) * (0.01 + 0.98 * t);
            let h = hf.height(xy.x, xy.y);
            assert!(hf.value(xy.extend(h)).abs() < 1e-12);
            assert!(hf.value(xy.extend(h + 1e-3)) > 0.0);
            assert!(hf.value(xy.extend(h - 1e-3)) < 0.0);
            assert!(hf.value(xy.extend(hf.base() - 1e-3)) > 0.0);
            assert!(hf.value(xy.extend(hf.base())).abs() < 1e-12);
        }
    }
}

#[test]
fn slope_bound_holds_and_is_not_loose_for_bezier() {
    let mut rng = Rng::new(43);
    for hf in [
        bezier_bump(),
        sampled(Interpolation::Bicubic),
        sampled(Interpolation::Bilinear),
    ] {
        let (lo, hi) = (hf.min(), hf.max());
        let mut steepest = 0.0f64;
        for _ in 0..4000 {
            let t = (DVec2::new(rng.next(), rng.next()) + 1.0) * 0.5;
            let xy = lo + (hi - lo) * t;
            let d = hf.derivatives(xy.x, xy.y);
            let slope = DVec2::new(d.hx, d.hy).length();
            assert!(
                slope <= hf.slope_bound() * (1.0 + 1e-12),
                "{slope} > {}",
                hf.slope_bound()
            );
            steepest = steepest.max(slope);
            let (hmin, hmax) = hf.height_range();
            assert!(d.h >= hmin - 1e-12 && d.h <= hmax + 1e-12);
        }
        assert!(
            steepest > 0.25 * hf.slope_bound(),
            "bound {} vs {steepest}",
            hf.slope_bound()
        );
    }
}

#[test]
fn derivatives_match_finite_differences() {
    for hf in [bezier_bump(), sampled(Interpolation::Bicubic)] {
        let e = 1e-5;
        for &(x, y) in &[(0.13, 0.21), (-0.7, -0.2), (0.5, 0.5)] {
            let d = hf.derivatives(x, y);
            let fx = (hf.height(x + e, y) - hf.height(x - e, y)) / (2.0 * e);
            let fy = (hf.height(x, y + e) - hf.height(x, y - e)) / (2.0 * e);
            assert!((fx - d.hx).abs() < 1e-6 && (fy - d.hy).abs() < 1e-6);
            let dx = hf.derivatives(x + e, y);
            let dy = hf.derivatives(x, y + e);
            let dxm = hf.derivatives(x - e, y);
            let dym = hf.derivatives(x, y - e);
            assert!(((dx.hx - dxm.hx) / (2.0 * e) - d.hxx).abs() < 1e-5);
            assert!(((dy.hy - dym.hy) / (2.0 * e) - d.hyy).abs() < 1e-5);
            assert!(((dy.hx - dym.hx) / (2.0 * e) - d.hxy).abs() < 1e-5);
        }
    }
}

#[test]
fn paraboloid_curvature_matches_closed_form() {
    let (a, r) = (1.5, 0.8);
    let hf = paraboloid(a, r);
    for &(x, y) in &[(0.0, 0.0), (0.3, -0.4), (1.2, 0.9), (-1.5, 1.5)] {
        assert!((hf.height(x, y) - (x * x + y * y) / (2.0 * r)).abs() < 1e-12);
        let c = hf.curvature(x, y);
        let q = (x * x + y * y) / (r * r);
        let k = 1.0 / (r * r * (1.0 + q) * (1.0 + q));
        let h = (2.0 + q) / (2.0 * r * (1.0 + q).powf(1.5));
        assert!((c.gaussian - k).abs() < 1e-12, "{c:?} vs K {k}");
        assert!((c.mean - h).abs() < 1e-12, "{c:?} vs H {h}");
    }
    // Hessian bound: h_xx = h_yy = 1/R, h_xy = 0, so the spectral norm 1/R is within √2.
    let m = hf.hessian_bound().unwrap();
    assert!(m >= 1.0 / r - 1e-12 && m <= 2f64.sqrt() / r + 1e-12, "{m}");
}

#[test]
fn bicubic_sphere_cap_has_curvature_near_closed_form() {
    // A cap of the sphere of radius 2 sampled on a 41 × 41 grid over [−0.8, 0.8]².
    let (r, n, a) = (2.0, 41usize, 0.8);
    let values = (0..n * n)
        .map(|k| {
            let x = -a + 2.0 * a * (k % n) as f64 / (n - 1) as f64;
            let y = -a + 2.0 * a * (k / n) as f64 / (n - 1) as f64;
            (r * r - x * x - y * y).sqrt()
        })
        .collect();
    let grid = HeightGrid::new(n, n, values).unwrap();
    let hf = HeightField::new(
        DVec2::splat(-a),
        DVec2::splat(a),
        0.0,
        HeightSource::Samples {
            grid,
            interpolation: Interpolation::Bicubic,
        },
    )
    .unwrap();
    for &(x, y) in &[(0.0, 0.0), (0.3, 0.2), (-0.4, 0.5)] {
        let c = hf.curvature(x, y);
        assert!((c.gaussian - 1.0 / (r * r)).abs() < 0.02 / (r * r), "{c:?}");
        assert!((c.mean + 1.0 / r).abs() < 0.02 / r, "{c:?}");
    }
}

#[test]
fn samples_are_interpolated() {
    for interpolation in [Interpolation::Bilinear, Interpolation::Bicubic] {
        let hf = sampled(interpolation);
        let g = hf.source().grid();
        for j in 0..g.ny() {
            for i in 0..g.nx() {
                let u = i as f64 / (g.nx() - 1) as f64;
                let v = j as f64 / (g.ny() - 1) as f64;
                let p = hf.point_at(u, v);
                assert!((p.z - g.get(i, j)).abs() < 1e-12);
            }
        }
    }
}

fn encode(
    width: u32,
    height: u32,
    depth: ::png::BitDepth,
    color: ::png::ColorType,
    data: &[u8],
) -> Vec<u8> {
    let mut out = Vec::new();
    {
        let mut enc = ::png::Encoder::new(&mut out, width, height);
        enc.set_color(color);
        enc.set_depth(depth);
        let mut w = enc.write_header().unwrap();
        w.write_image_data(data).unwrap();
    }
    out
}

#[test]
fn png_height_maps_decode_in_8_and_16_bits() {
    // 3 × 2 image; top row (row 0) maps to the largest y.
    let eight = encode(
        3,
        2,
        ::png::BitDepth::Eight,
        ::png::ColorType::Grayscale,
        &[0, 51, 255, 102, 153, 204],
    );
    let g = decode_png(&eight).unwrap();
    assert_eq!((g.nx(), g.ny()), (3, 2));
    assert_eq!(g.get(0, 1), 0.0);
    assert_eq!(g.get(2, 1), 1.0);
    assert!((g.get(1, 0) - 0.6).abs() < 1e-12);
    let words: Vec<u8> = [0u16, 65535, 32768, 1, 2, 3]
        .iter()
        .flat_map(|w| w.to_be_bytes())
        .collect();
    let sixteen = encode(
        3,
        2,
        ::png::BitDepth::Sixteen,
        ::png::ColorType::Grayscale,
        &words,
    );
    let g = decode_png(&sixteen).unwrap();
    assert_eq!(g.get(1, 1), 1.0);
    assert!((g.get(2, 1) - 32768.0 / 65535.0).abs() < 1e-15);
    assert!((g.get(0, 0) - 1.0 / 65535.0).abs() < 1e-15);
    let rgb = encode(1, 2, ::png::BitDepth::Eight, ::png::ColorType::Rgb, &[0; 6]);
    assert!(matches!(
        decode_png(&rgb),
        Err(HeightFieldError::NotGrayscale { .. })
    ));
    assert!(matches!(
        decode_png(b"not a png"),
        Err(HeightFieldError::Png(_))
    ));
}

#[test]
fn png_luminance_reads_every_colour_type_as_openscad_does() {
    // RGB: the luminance weights; the top row maps to the largest y.
    let rgb = encode(
        2,
        2,
        ::png::BitDepth::Eight,
        ::png::ColorType::Rgb,
        &[255, 0, 0, 0, 255, 0, 0, 0, 255, 10, 20, 30],
    );
    let g = decode_png_luminance(&rgb).unwrap();
    assert!((g.get(0, 1) - 0.2126).abs() < 1e-12);
    assert!((g.get(1, 1) - 0.7152).abs() < 1e-12);
    assert!((g.get(0, 0) - 0.0722).abs() < 1e-12);
    assert!((g.get(1, 0) - 18.596 / 255.0).abs() < 1e-12);
    // 16-bit grey keeps the high byte; grey is its own value.
    let words: Vec<u8> = [0x01ffu16, 0, 0x8007, 0xffff]
        .iter()
        .flat_map(|w| w.to_be_bytes())
        .collect();
    let g = decode_png_luminance(&encode(
        2,
        2,
        ::png::BitDepth::Sixteen,
        ::png::ColorType::Grayscale,
        &words,
    ))
    .unwrap();
    assert_eq!(g.get(0, 1), 1.0 / 255.0);
    assert_eq!(g.get(0, 0), 128.0 / 255.0);
    assert_eq!(g.get(1, 0), 1.0);
    // Alpha is ignored.
    let ga = encode(
        2,
        2,
        ::png::BitDepth::Eight,
        ::png::ColorType::GrayscaleAlpha,
        &[51, 0, 51, 255, 51, 7, 51, 9],
    );
    let g = decode_png_luminance(&ga).unwrap();
    assert!(g.values().iter().all(|&v| v == 0.2));
}

#[test]
fn png_file_makes_a_height_field() {
    let dir = std::env::temp_dir().join(format!("solidkit-hf-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("ramp.png");
    let data: Vec<u8> = (0..16).map(|k| (k % 4) as u8 * 85).collect();
    std::fs::write(
        &path,
        encode(
            4,
            4,
            ::png::BitDepth::Eight,
            ::png::ColorType::Grayscale,
            &data,
        ),
    )
    .unwrap();
    let hf = HeightField::from_png(
        DVec2::ZERO,
        DVec2::new(3.0, 3.0),
        0.0,
        &path,
        [1.0, 2.0],
        Interpolation::Bilinear,
    )
    .unwrap();
    // Heights ramp from 1 at x = 0 to 2 at x = 3, so the slope is exactly 1/3.
    assert!((hf.height(1.5, 2.0) - 1.5).abs() < 1e-12);
    assert!((hf.slope_bound() - 1.0 / 3.0).abs() < 1e-12);
    assert_eq!(hf.png_origin().unwrap().heights, [1.0, 2.0]);
    let missing = HeightField::from_png(
        DVec2::ZERO,
        DVec2::ONE,
        0.0,
        &dir.join("none.png"),
        [0.0, 1.0],
        Interpolation::Bilinear,
    );
    assert!(matches!(missing, Err(HeightFieldError::Io(_))));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn invalid_height_fields_are_rejected() {
    let g = HeightGrid::from_rows(&[vec![1.0, 1.0], vec![1.0, 1.0]]).unwrap();
    let src = HeightSource::Bezier(g);
    let bad_rect = HeightField::new(DVec2::ONE, DVec2::ZERO, 0.0, src.clone());
    assert!(matches!(bad_rect, Err(HeightFieldError::Parameter(e)) if e.parameter == "min"));
    let above = HeightField::new(DVec2::ZERO, DVec2::ONE, 1.0, src);
    assert!(matches!(above, Err(HeightFieldError::Parameter(e)) if e.parameter == "base"));
    assert!(HeightGrid::from_rows(&[vec![1.0, 2.0], vec![1.0]]).is_err());
    assert!(HeightGrid::new(1, 3, vec![0.0; 3]).is_err());
    assert!(HeightGrid::new(2, 2, vec![0.0, f64::NAN, 0.0, 0.0]).is_err());
}

/// The PNG with its IHDR patched to declare `width × height` (CRC recomputed).
fn declaring(png: &[u8], width: u32, height: u32) -> Vec<u8> {
    fn crc32(bytes: &[u8]) -> u32 {
        let mut c = !0u32;
        for &b in bytes {
            c ^= u32::from(b);
            for _ in 0..8 {
                c = if c & 1 == 1 {
                    (c >> 1) ^ 0xEDB8_8320
                } else {
                    c >> 1
                };
            }
        }
        !c
    }
    let mut out = png.to_vec();
    assert_eq!(&out[12..16], b"IHDR");
    out[16..20].copy_from_slice(&width.to_be_bytes());
    out[20..24].copy_from_slice(&height.to_be_bytes());
    let crc = crc32(&out[12..29]);
    out[29..33].copy_from_slice(&crc.to_be_bytes());
    out
}

#[test]
fn huge_declared_images_are_refused_before_allocating() {
    let small = encode(
        2,
        2,
        ::png::BitDepth::Eight,
        ::png::ColorType::Grayscale,
        &[0, 1, 2, 3],
    );
    assert!(decode_png(&declaring(&small, 2, 2)).is_ok());
    for (w, h) in [(30_000, 30_000), (MAX_PNG_SIDE + 1, 2), (4097, 4097)] {
        let start = std::time::Instant::now();
        let e = decode_png(&declaring(&small, w, h)).unwrap_err();
        assert!(
            matches!(e, HeightFieldError::ImageTooLarge { width, height } if (width, height) == (w, h)),
            "{e}"
        );
        assert!(e.to_string().contains(&format!("{w} × {h} pixels")), "{e}");
        assert!(start.elapsed().as_secs_f64() < 0.5);
    }
}

#[test]
fn the_largest_allowed_image_decodes() {
    let side = 4096u32;
    let data = vec![7u8; (side * side * 2) as usize];
    let png = encode(
        side,
        side,
        ::png::BitDepth::Sixteen,
        ::png::ColorType::Grayscale,
        &data,
    );
    let g = decode_png(&png).unwrap();
    assert_eq!((g.nx(), g.ny()), (4096, 4096));
    let wide = encode(
        MAX_PNG_SIDE,
        2,
        ::png::BitDepth::Eight,
        ::png::ColorType::Grayscale,
        &vec![0; 2 * MAX_PNG_SIDE as usize],
    );
    assert!(decode_png(&wide).is_ok());
}

/// A Bézier height field over `[0, 2] × [0, 1]` with an `nx × ny` wavy net.
fn wavy_bezier(nx: usize, ny: usize) -> Result<HeightField, HeightFieldError> {
    let values = (0..nx * ny)
        .map(|k| 0.5 + 0.2 * ((k % nx) as f64 * 0.7).sin() * ((k / nx) as f64 * 0.3).cos())
        .collect();
    let grid = HeightGrid::new(nx, ny, values)?;
    HeightField::new(
        DVec2::ZERO,
        DVec2::new(2.0, 1.0),
        0.0,
        HeightSource::Bezier(grid),
    )
}

#[test]
fn bezier_heights_are_the_tensor_sum_and_batches_their_values() {
    use crate::patch::bernstein::tensor_sum;
    let mut rng = Rng::new(71);
    for (nx, ny) in [(2, 2), (2, 5), (7, 3), (40, 33)] {
        let hf = wavy_bezier(nx, ny).unwrap();
        let g = hf.source().grid();
        for _ in 0..200 {
            let (u, v) = (0.5 + 0.6 * rng.next(), 0.5 + 0.6 * rng.next());
            let (u, v) = (u.clamp(0.0, 1.0), v.clamp(0.0, 1.0));
            let plain = tensor_sum(nx - 1, ny - 1, u, v, |i, j| g.get(i, j));
            assert_eq!(bezier::height(g, u, v).to_bits(), plain.to_bits());
        }
        // Chunks of brick-like points: few columns, many heights, and some scattered points.
        let mut pts = Vec::new();
        for k in 0..300 {
            let (i, j) = (k % 5, (k / 5) % 4);
            pts.push(DVec3::new(
                0.3 + 0.01 * i as f64,
                0.4 + 0.01 * j as f64,
                0.01 * k as f64,
            ));
            pts.push(DVec3::new(1.0, 0.5, 0.0) + rng.vec(1.2));
        }
        let x: Vec<f32> = pts.iter().map(|p| p.x as f32).collect();
        let y: Vec<f32> = pts.iter().map(|p| p.y as f32).collect();
        let z: Vec<f32> = pts.iter().map(|p| p.z as f32).collect();
        let mut out = vec![0f32; pts.len()];
        hf.values_f32(&x, &y, &z, &mut out);
        for i in 0..pts.len() {
            let p = DVec3::new(x[i] as f64, y[i] as f64, z[i] as f64);
            assert_eq!(out[i].to_bits(), (hf.value(p) as f32).to_bits(), "{p}");
        }
    }
}

#[test]
fn bezier_nets_beyond_the_evaluation_budget_are_refused() {
    assert!(wavy_bezier(64, 64).is_ok());
    assert!(wavy_bezier(2, 2048).is_ok());
    let e = wavy_bezier(65, 64).unwrap_err();
    assert!(
        matches!(
            e,
            HeightFieldError::TooManyControlHeights { nx: 65, ny: 64 }
        ),
        "{e}"
    );
    let text = e.to_string();
    assert!(text.contains("65 × 64") && text.contains("4160"), "{text}");
}
