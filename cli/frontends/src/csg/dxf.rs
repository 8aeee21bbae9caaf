//! A DXF reader for `import("x.dxf")`, as OpenSCAD 2021.01 reads DXF (its `dxfdata.cc`): the
//! entities `LINE`, `ARC`, `CIRCLE`, `LWPOLYLINE` and `POLYLINE`/`VERTEX` of the `ENTITIES`
//! section (those of one layer when a layer is named), and `INSERT`s of `BLOCKS` made of these
//! (position, x/y scale, rotation; inserts inside blocks are not expanded). Arcs and circles are
//! faceted by OpenSCAD's fragment rule. Every entity becomes line segments; segments whose ends
//! meet (within OpenSCAD's `GRID_FINE`) are joined into paths, and the paths are the loops of a
//! region by the even-odd rule (an open path is closed from its end to its start, as OpenSCAD
//! closes it). Points are
//! `(p − origin) · scale`. Other entities are skipped and counted, so the caller can warn.

use super::facets;
use super::facets::Resolution;
use glam::DVec2;
use std::collections::HashMap;

/// OpenSCAD's `GRID_FINE`: segment ends closer than this are the same point.
const GRID_FINE: f64 = 0.000_000_953_674_316_406_25;

/// The most segments a DXF file may produce (a bound on memory for hostile files).
const MAX_SEGMENTS: usize = 1 << 22;

/// What the DXF reader found.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct DxfRegion {
    /// Closed loops; inside by the even-odd rule.
    pub loops: Vec<Vec<DVec2>>,
    /// Names of entity types that were skipped, each once.
    pub skipped: Vec<String>,
    /// Paths that did not close (closed from end to start, as OpenSCAD closes them).
    pub open_paths: usize,
}

/// How the file is read: the layer (`None` for all), origin, scale and arc resolution.
#[derive(Debug, Clone, Copy)]
pub struct DxfOptions<'a> {
    /// Only entities of this layer, or all.
    pub layer: Option<&'a str>,
    /// Subtracted from every point before scaling.
    pub origin: DVec2,
    /// Multiplies every point.
    pub scale: f64,
    /// `$fn/$fa/$fs` for arcs and circles.
    pub res: Resolution,
}

/// One entity's group codes (code, value), in order.
#[derive(Debug, Clone, Default)]
struct Entity {
    kind: String,
    codes: Vec<(i32, String)>,
}

impl Entity {
    fn text(&self, code: i32) -> Option<&str> {
        self.codes
            .iter()
            .find(|(c, _)| *c == code)
            .map(|(_, v)| v.as_str())
    }

    fn num(&self, code: i32, default: f64) -> f64 {
        self.text(code)
            .and_then(|v| v.trim().parse::<f64>().ok())
            .filter(|v| v.is_finite())
            .unwrap_or(default)
    }

    /// Every value of `code`, as numbers.
    fn nums(&self, code: i32) -> Vec<f64> {
        self.codes
            .iter()
            .filter(|(c, _)| *c == code)
            .map(|(_, v)| v.trim().parse::<f64>().unwrap_or(f64::NAN))
            .collect()
    }

    fn layer(&self) -> &str {
        self.text(8).unwrap_or("0").trim()
    }
}

/// Why a DXF file cannot be read.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DxfError {
    /// A group code that is not an integer.
    #[error("line {line}: group code '{text}' is not an integer")]
    Code {
        /// 1-based line of the file.
        line: usize,
        /// The text found.
        text: String,
    },
    /// A number that is not finite where a coordinate was expected.
    #[error("a {kind} entity has a coordinate that is not a finite number")]
    Number {
        /// The entity type.
        kind: String,
    },
    /// Too many segments.
    #[error("more than {MAX_SEGMENTS} segments")]
    TooLarge,
}

/// The group-code pairs of the file, split into entities per section (`(section, entities)`),
/// with `BLOCK`…`ENDBLK` kept as they come.
fn entities(text: &str) -> Result<Vec<(String, Vec<Entity>)>, DxfError> {
    let lines: Vec<&str> = text.lines().collect();
    let mut sections: Vec<(String, Vec<Entity>)> = Vec::new();
    let mut k = 0;
    let mut pending_section = false;
    while k + 1 < lines.len() {
        let code: i32 = lines[k].trim().parse().map_err(|_| DxfError::Code {
            line: k + 1,
            text: lines[k].trim().chars().take(40).collect(),
        })?;
        let value = lines[k + 1].trim_end_matches('\r').to_string();
        k += 2;
        if code == 0 {
            match value.trim() {
                "SECTION" => pending_section = true,
                "ENDSEC" => {}
                "EOF" => break,
                kind => {
                    if let Some((_, list)) = sections.last_mut() {
                        list.push(Entity {
                            kind: kind.to_string(),
                            codes: Vec::new(),
                        });
                    }
                }
            }
            continue;
        }
        if pending_section && code == 2 {
            sections.push((value.trim().to_string(), Vec::new()));
            pending_section = false;
            continue;
        }
        if let Some(e) = sections.last_mut().and_then(|(_, l)| l.last_mut()) {
            e.codes.push((code, value));
        }
    }
    Ok(sections)
}

/// The segments of one drawing entity (in its own coordinates), or `None` when the entity is not
/// a drawing entity this reader knows.
fn segments_of(
    e: &Entity,
    polyline: &mut Option<(bool, Vec<DVec2>)>,
    res: Resolution,
    out: &mut Vec<[DVec2; 2]>,
) -> Result<bool, DxfError> {
    let bad = || DxfError::Number {
        kind: e.kind.clone(),
    };
    let finite = |v: f64| if v.is_finite() { Ok(v) } else { Err(bad()) };
    let pt = |cx: i32, cy: i32| -> Result<DVec2, DxfError> {
        let x = e
            .text(cx)
            .map_or(Ok(0.0), |v| v.trim().parse().map_err(|_| bad()))?;
        let y = e
            .text(cy)
            .map_or(Ok(0.0), |v| v.trim().parse().map_err(|_| bad()))?;
        Ok(DVec2::new(finite(x)?, finite(y)?))
    };
    match e.kind.as_str() {
        "LINE" => out.push([pt(10, 20)?, pt(11, 21)?]),
        "CIRCLE" | "ARC" => {
            let c = pt(10, 20)?;
            let r = finite(e.num(40, f64::NAN))?;
            let (a0, mut a1) = if e.kind == "CIRCLE" {
                (0.0, 360.0)
            } else {
                (finite(e.num(50, 0.0))?, finite(e.num(51, 360.0))?)
            };
            while a1 < a0 {
                a1 += 360.0;
            }
            let full = facets::fragments(r, res);
            let n = ((full as f64 * (a1 - a0) / 360.0).ceil() as usize).max(1);
            let at = |i: usize| {
                let a = (a0 + (a1 - a0) * i as f64 / n as f64).to_radians();
                c + r * DVec2::new(a.cos(), a.sin())
            };
            out.extend((0..n).map(|i| [at(i), at(i + 1)]));
        }
        "LWPOLYLINE" => {
            let xs = e.nums(10);
            let ys = e.nums(20);
            let pts: Vec<DVec2> = xs
                .iter()
                .zip(&ys)
                .map(|(x, y)| DVec2::new(*x, *y))
                .collect();
            if pts.iter().any(|p| !p.is_finite()) {
                return Err(bad());
            }
            let closed = (e.num(70, 0.0) as i64) & 1 == 1;
            chain(&pts, closed, out);
        }
        "POLYLINE" => *polyline = Some(((e.num(70, 0.0) as i64) & 1 == 1, Vec::new())),
        "VERTEX" => {
            if let Some((_, pts)) = polyline.as_mut() {
                pts.push(pt(10, 20)?);
            }
        }
        "SEQEND" => {
            if let Some((closed, pts)) = polyline.take() {
                chain(&pts, closed, out);
            }
        }
        _ => return Ok(false),
    }
    Ok(true)
}

/// The segments between consecutive points (and back to the first when `closed`).
fn chain(pts: &[DVec2], closed: bool, out: &mut Vec<[DVec2; 2]>) {
    out.extend(pts.windows(2).map(|w| [w[0], w[1]]));
    if closed && pts.len() > 2 {
        out.push([pts[pts.len() - 1], pts[0]]);
    }
}

/// Reads a DXF file's region.
pub fn read(text: &str, opts: DxfOptions<'_>) -> Result<DxfRegion, DxfError> {
    let sections = entities(text)?;
    let mut region = DxfRegion::default();
    let skip = |kind: &str, region: &mut DxfRegion| {
        if !region.skipped.iter().any(|k| k == kind) {
            region.skipped.push(kind.to_string());
        }
    };
    // Blocks: name → segments in block coordinates.
    let mut blocks: HashMap<String, Vec<[DVec2; 2]>> = HashMap::new();
    for (name, list) in sections.iter().filter(|(n, _)| n == "BLOCKS") {
        let _ = name;
        let mut current: Option<String> = None;
        let mut polyline = None;
        for e in list {
            match e.kind.as_str() {
                "BLOCK" => current = Some(e.text(2).unwrap_or("").trim().to_string()),
                "ENDBLK" => current = None,
                _ => {
                    let Some(b) = current.clone() else { continue };
                    let segs = blocks.entry(b).or_default();
                    if !segments_of(e, &mut polyline, opts.res, segs)? {
                        skip(&e.kind, &mut region);
                    }
                    if segs.len() > MAX_SEGMENTS {
                        return Err(DxfError::TooLarge);
                    }
                }
            }
        }
    }
    let mut segs: Vec<[DVec2; 2]> = Vec::new();
    let wanted = |e: &Entity| opts.layer.is_none_or(|l| l == e.layer());
    for (_, list) in sections.iter().filter(|(n, _)| n == "ENTITIES") {
        let mut polyline: Option<(bool, Vec<DVec2>)> = None;
        let mut polyline_wanted = false;
        for e in list {
            let keep = match e.kind.as_str() {
                "VERTEX" | "SEQEND" => polyline_wanted,
                _ => wanted(e),
            };
            if e.kind == "POLYLINE" {
                polyline_wanted = keep;
            }
            if !keep {
                continue;
            }
            if e.kind == "INSERT" {
                let name = e.text(2).unwrap_or("").trim();
                let Some(block) = blocks.get(name) else {
                    continue;
                };
                let at = DVec2::new(e.num(10, 0.0), e.num(20, 0.0));
                let s = DVec2::new(e.num(41, 1.0), e.num(42, 1.0));
                let a = e.num(50, 0.0).to_radians();
                let rot = DVec2::new(a.cos(), a.sin());
                let map = |p: DVec2| at + rot.rotate(p * s);
                segs.extend(block.iter().map(|[p, q]| [map(*p), map(*q)]));
            } else if !segments_of(e, &mut polyline, opts.res, &mut segs)? {
                skip(&e.kind, &mut region);
            }
            if segs.len() > MAX_SEGMENTS {
                return Err(DxfError::TooLarge);
            }
        }
    }
    for s in &mut segs {
        for p in s.iter_mut() {
            *p = (*p - opts.origin) * opts.scale;
        }
    }
    let (loops, open) = join(&segs);
    region.loops = loops;
    region.open_paths = open;
    Ok(region)
}

/// Joins segments whose ends meet into paths, as loops of points (open paths closed from end to
/// start, as OpenSCAD does), and the number of paths that were open.
fn join(segs: &[[DVec2; 2]]) -> (Vec<Vec<DVec2>>, usize) {
    // Merge ends within GRID_FINE: each point snaps to the first one seen in its cell or the
    // neighbouring cells.
    let mut cells: HashMap<(i64, i64), Vec<usize>> = HashMap::new();
    let mut points: Vec<DVec2> = Vec::new();
    let mut id = |p: DVec2| -> usize {
        let c = (
            (p.x / GRID_FINE).floor() as i64,
            (p.y / GRID_FINE).floor() as i64,
        );
        for dx in -1..=1 {
            for dy in -1..=1 {
                if let Some(ids) = cells.get(&(c.0 + dx, c.1 + dy))
                    && let Some(&i) = ids.iter().find(|&&i| points[i].distance(p) <= GRID_FINE)
                {
                    return i;
                }
            }
        }
        points.push(p);
        cells.entry(c).or_default().push(points.len() - 1);
        points.len() - 1
    };
    let edges: Vec<[usize; 2]> = segs
        .iter()
        .map(|[p, q]| [id(*p), id(*q)])
        .filter(|[a, b]| a != b)
        .collect();
    let mut at: Vec<Vec<usize>> = vec![Vec::new(); points.len()];
    for (k, [a, b]) in edges.iter().enumerate() {
        at[*a].push(k);
        at[*b].push(k);
    }
    let mut used = vec![false; edges.len()];
    let mut loops = Vec::new();
    let mut open = 0;
    for first in 0..edges.len() {
        if used[first] {
            continue;
        }
        used[first] = true;
        let [start, mut end] = edges[first];
        let mut path = vec![start, end];
        // Extend forward from `end`; if the path does not close, extend backward from `start`.
        let mut extend = |path: &mut Vec<usize>, end: &mut usize, stop: usize| {
            while *end != stop {
                let Some(&k) = at[*end].iter().find(|&&k| !used[k]) else {
                    return false;
                };
                used[k] = true;
                let [a, b] = edges[k];
                *end = if a == *end { b } else { a };
                path.push(*end);
            }
            true
        };
        if extend(&mut path, &mut end, start) {
            path.pop();
            loops.push(path.iter().map(|&i| points[i]).collect());
            continue;
        }
        let mut back = vec![start];
        let mut s = start;
        extend(&mut back, &mut s, usize::MAX);
        open += 1;
        // OpenSCAD closes open paths (from the far end back to the start).
        back.reverse();
        back.extend(&path[1..]);
        if back.len() >= 3 {
            loops.push(back.iter().map(|&i| points[i]).collect());
        }
    }
    (loops, open)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dxf(entities: &str) -> String {
        format!("0\nSECTION\n2\nENTITIES\n{entities}0\nENDSEC\n0\nEOF\n")
    }

    fn line(layer: &str, a: (f64, f64), b: (f64, f64)) -> String {
        format!(
            "0\nLINE\n8\n{layer}\n10\n{}\n20\n{}\n11\n{}\n21\n{}\n",
            a.0, a.1, b.0, b.1
        )
    }

    const RES: Resolution = Resolution {
        fn_: 0.0,
        fa: 12.0,
        fs: 2.0,
    };

    fn opts(layer: Option<&str>) -> DxfOptions<'_> {
        DxfOptions {
            layer,
            origin: DVec2::ZERO,
            scale: 1.0,
            res: RES,
        }
    }

    fn area(l: &[DVec2]) -> f64 {
        (0..l.len())
            .map(|i| l[i].perp_dot(l[(i + 1) % l.len()]))
            .sum::<f64>()
            .abs()
            / 2.0
    }

    #[test]
    fn lines_in_any_order_join_into_a_square_of_the_layer() {
        let text = dxf(&[
            line("a", (1.0, 0.0), (1.0, 1.0)),
            line("a", (0.0, 0.0), (1.0, 0.0)),
            line("b", (5.0, 5.0), (6.0, 6.0)),
            line("a", (0.0, 1.0), (0.0, 0.0)),
            line("a", (0.0, 1.0), (1.0, 1.0)),
        ]
        .concat());
        let r = read(&text, opts(Some("a"))).unwrap();
        assert_eq!(r.loops.len(), 1);
        assert_eq!(r.loops[0].len(), 4);
        assert!((area(&r.loops[0]) - 1.0).abs() < 1e-12);
        let all = read(&text, opts(None)).unwrap();
        // The stray line of layer b is an open path of two points: no loop.
        assert_eq!((all.loops.len(), all.open_paths), (1, 1));
        let open = dxf(&[
            line("0", (0.0, 0.0), (1.0, 0.0)),
            line("0", (1.0, 1.0), (0.0, 1.0)),
            line("0", (1.0, 0.0), (1.0, 1.0)),
        ]
        .concat());
        let r = read(&open, opts(None)).unwrap();
        assert_eq!((r.loops.len(), r.open_paths), (1, 1));
        assert!((area(&r.loops[0]) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn circle_is_faceted_and_origin_scale_apply() {
        let text = dxf("0\nCIRCLE\n8\n0\n10\n10\n20\n0\n40\n5\n");
        let o = DxfOptions {
            origin: DVec2::new(10.0, 0.0),
            scale: 2.0,
            ..opts(None)
        };
        let r = read(&text, o).unwrap();
        assert_eq!(r.loops.len(), 1);
        let n = facets::fragments(5.0, RES);
        assert_eq!(r.loops[0].len(), n);
        assert!(r.loops[0].iter().all(|p| (p.length() - 10.0).abs() < 1e-9));
    }

    #[test]
    fn unknown_entities_are_reported_and_bad_codes_fail() {
        let r = read(&dxf("0\nSPLINE\n8\n0\n"), opts(None)).unwrap();
        assert_eq!(r.skipped, vec!["SPLINE".to_string()]);
        assert!(matches!(
            read("0\nSECTION\nx\ny\n", opts(None)),
            Err(DxfError::Code { line: 3, .. })
        ));
        assert!(read(&dxf("0\nLINE\n10\nnan\n"), opts(None)).is_err());
    }
}
