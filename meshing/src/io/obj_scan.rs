//! A line scanner for OBJ text that finds the first offending line, because `tobj` reports its
//! errors without line numbers.
//!
//! It checks what `tobj` checks, the way `tobj` parses (same keywords, same number type, same
//! relative-index rules), plus our own rules (finite coordinates, faces of at least three
//! corners, indices in range). Running it before `tobj` also guarantees that `tobj` never sees
//! an index it could overflow on. It records which line each face came from, so that later
//! problems (a face that cannot be triangulated) can be located too.

use std::ops::Div;
use std::str::{FromStr, SplitWhitespace};

use super::text::{lines, show};
use super::{Location, MeshIoError};

/// A line that produces a face in `tobj`'s output, in file order.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct FaceLine {
    /// 1-based line number.
    pub line: usize,
    /// An `l` polyline of three or more points, which `tobj` returns as a face: to be dropped.
    pub polyline: bool,
}

/// How positive face indices are bounded.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Bound {
    /// By the number of elements in the whole file (what a valid file needs).
    WholeFile,
    /// By the number of elements before the face line (finds forward references, which `tobj`
    /// rejects when they cross an object boundary).
    SoFar,
}

/// Checks OBJ text and lists the lines whose faces `tobj` will return.
pub(super) fn scan(bytes: &[u8], name: &str, bound: Bound) -> Result<Vec<FaceLine>, MeshIoError> {
    let totals = count_elements(bytes);
    let mut scanner = Scanner {
        totals,
        so_far: Counts::default(),
        bound,
        faces: Vec::new(),
    };
    for (number, line) in lines(bytes) {
        let kind = scanner
            .line(line)
            .map_err(|message| MeshIoError::parse(name, Location::Line(number), message))?;
        scanner.record(number, kind);
    }
    Ok(scanner.faces)
}

/// Element counts: vertices, texture coordinates, normals and vertex color values.
#[derive(Debug, Clone, Copy, Default)]
struct Counts {
    v: usize,
    vt: usize,
    vn: usize,
    color_values: usize,
}

/// What a line contributes to `tobj`'s face list.
enum FaceKind {
    None,
    Face,
    Polyline,
}

struct Scanner {
    totals: Counts,
    so_far: Counts,
    bound: Bound,
    faces: Vec<FaceLine>,
}

/// The first pass: how many of each element the file declares (no validation).
fn count_elements(bytes: &[u8]) -> Counts {
    let mut counts = Counts::default();
    for (_, line) in lines(bytes) {
        let Ok(line) = std::str::from_utf8(line) else {
            continue;
        };
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => {
                counts.v += 1;
                counts.color_values += color_values(words.skip(3));
            }
            Some("vt") => counts.vt += 1,
            Some("vn") => counts.vn += 1,
            _ => {}
        }
    }
    counts
}

impl Scanner {
    fn record(&mut self, line: usize, kind: FaceKind) {
        let polyline = match kind {
            FaceKind::None => return,
            FaceKind::Face => false,
            FaceKind::Polyline => true,
        };
        self.faces.push(FaceLine { line, polyline });
    }

    /// Checks one line like `tobj::load_obj_buf` parses it.
    fn line(&mut self, line: &[u8]) -> Result<FaceKind, String> {
        let line = std::str::from_utf8(line).map_err(|_| "line is not valid UTF-8".to_owned())?;
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => {
                self.so_far.color_values += vertex(like_tobj, words)?;
                self.so_far.v += 1;
            }
            Some("vt") => {
                floats(words, 2, "texture coordinates")?;
                self.so_far.vt += 1;
            }
            Some("vn") => {
                floats(words, 3, "normal components")?;
                self.so_far.vn += 1;
            }
            Some("f") => return self.face(words, false),
            Some("l") => return self.face(words, true),
            Some("usemtl") if material_name(line).is_empty() => {
                return Err("'usemtl' without a material name".into());
            }
            _ => {}
        }
        Ok(FaceKind::None)
    }

    /// An `f` (or `l`) line: every corner must parse, and the corners of a face must be in range.
    fn face(&self, words: SplitWhitespace, polyline: bool) -> Result<FaceKind, String> {
        let corners = words.map(corner).collect::<Result<Vec<_>, _>>()?;
        if !polyline && corners.len() < 3 {
            return Err(format!(
                "face has {} vertices (at least 3 needed)",
                corners.len()
            ));
        }
        // `tobj` drops polylines of one or two points but returns the others as faces.
        if corners.len() == 1 || corners.len() == 2 {
            return Ok(FaceKind::None);
        }
        for corner in &corners {
            self.check_corner(corner)?;
        }
        Ok(if polyline {
            FaceKind::Polyline
        } else {
            FaceKind::Face
        })
    }

    fn check_corner(&self, corner: &Corner) -> Result<(), String> {
        let Some(v) = corner.indices[0] else {
            return Err(format!(
                "face vertex '{}' has no position index",
                show(corner.text.as_bytes())
            ));
        };
        let v = self.resolve(v, self.so_far.v, self.totals.v, "face index", "vertices")?;
        let colors = self.totals.color_values;
        if colors > 0 && v.saturating_mul(3).saturating_add(2) >= colors {
            return Err(format!(
                "vertex {} has no color but other vertices have colors",
                v + 1
            ));
        }
        if let Some(vt) = corner.indices[1].filter(|_| self.totals.vt > 0) {
            let (so_far, total) = (self.so_far.vt, self.totals.vt);
            self.resolve(vt, so_far, total, "texture index", "texture coordinates")?;
        }
        if let Some(vn) = corner.indices[2].filter(|_| self.totals.vn > 0) {
            let (so_far, total) = (self.so_far.vn, self.totals.vn);
            self.resolve(vn, so_far, total, "normal index", "normals")?;
        }
        Ok(())
    }

    /// The 0-based index of a 1-based (or negative, relative) OBJ index, checked.
    fn resolve(
        &self,
        index: isize,
        so_far: usize,
        total: usize,
        what: &str,
        elements: &str,
    ) -> Result<usize, String> {
        if index < 0 {
            let back = index.unsigned_abs();
            return so_far.checked_sub(back).ok_or_else(|| {
                format!("relative {what} {index} out of range (only {so_far} {elements} precede this line)")
            });
        }
        let zero_based = index
            .unsigned_abs()
            .checked_sub(1)
            .ok_or_else(|| format!("{what} 0 is invalid (OBJ indices start at 1)"))?;
        let limit = match self.bound {
            Bound::WholeFile => total,
            Bound::SoFar => so_far,
        };
        if zero_based < limit {
            Ok(zero_based)
        } else if zero_based < total {
            Err(format!(
                "{what} {index} refers to a later line (only {so_far} {elements} precede this line)"
            ))
        } else {
            Err(format!(
                "{what} {index} out of range (the file has {total} {elements})"
            ))
        }
    }
}

/// One face corner `v`, `v/vt`, `v//vn` or `v/vt/vn`.
struct Corner<'a> {
    text: &'a str,
    indices: [Option<isize>; 3],
}

/// Parses a corner exactly like `tobj` (empty parts are skipped, at most three parts used).
fn corner(text: &str) -> Result<Corner<'_>, String> {
    let mut indices = [None; 3];
    for (i, part) in text.split('/').enumerate() {
        if part.is_empty() {
            continue;
        }
        let slot = indices.get_mut(i).ok_or_else(|| {
            format!(
                "face vertex '{}' has more than 3 indices",
                show(text.as_bytes())
            )
        })?;
        let index = part
            .parse::<isize>()
            .map_err(|_| format!("face index '{}' is not an integer", show(part.as_bytes())))?;
        *slot = Some(index);
    }
    Ok(Corner { text, indices })
}

/// What `tobj` does with `usemtl NAME`: the text after the first space, trimmed.
fn material_name(line: &str) -> &str {
    line.split_once(' ').map_or("", |(_, rest)| rest.trim())
}

/// `tobj`'s number type is private (`f32`, or `f64` with its `use_f64` feature): this never
/// called function lets type inference find it, so that we parse numbers exactly like `tobj`.
fn like_tobj() -> Vec<impl TobjFloat> {
    tobj::Mesh::default().positions
}

/// What the scanner needs of `tobj`'s number type.
trait TobjFloat: FromStr + Copy + Into<f64> + Div<Output = Self> {}
impl<T: FromStr + Copy + Into<f64> + Div<Output = T>> TobjFloat for T {}

/// `n` numbers (more are ignored, like `tobj` does).
fn floats(mut words: SplitWhitespace, n: usize, what: &str) -> Result<(), String> {
    for _ in 0..n {
        let word = words.next().ok_or_else(|| format!("expected {n} {what}"))?;
        parse_like(like_tobj, word)?;
    }
    Ok(())
}

fn parse_like<T: TobjFloat>(_like: fn() -> Vec<T>, word: &str) -> Result<T, String> {
    word.parse()
        .map_err(|_| format!("expected a number, found '{}'", show(word.as_bytes())))
}

/// A `v x y z [w | r g b]` line; returns how many vertex color values `tobj` records for it.
fn vertex<T: TobjFloat>(like: fn() -> Vec<T>, mut words: SplitWhitespace) -> Result<usize, String> {
    let mut xyz = Vec::with_capacity(3);
    for _ in 0..3 {
        let word = words.next().ok_or("expected 3 coordinates after 'v'")?;
        xyz.push((word, parse_like(like, word)?));
    }
    let extra: Vec<&str> = words.collect();
    let (w, colors) = match extra.as_slice() {
        [] => (None, 0),
        [w] => (Some(weight(like, w)?), 0),
        [_, _, _] => (None, color_values(extra.iter().copied())),
        _ => {
            return Err(format!(
                "expected 0, 1 (w) or 3 (r g b) values after the coordinates, found {}",
                extra.len()
            ));
        }
    };
    for (word, value) in xyz {
        let value = w.map_or(value, |w| value / w);
        if !value.into().is_finite() {
            return Err(format!(
                "coordinate '{}' is not a finite number",
                show(word.as_bytes())
            ));
        }
    }
    Ok(colors)
}

fn weight<T: TobjFloat>(like: fn() -> Vec<T>, word: &str) -> Result<T, String> {
    let w = parse_like(like, word)?;
    if w.into() == 0.0 {
        return Err("vertex weight w is zero".into());
    }
    Ok(w)
}

/// How many color values `tobj` keeps from the words after `v x y z`: with exactly three extra
/// words, the leading ones that parse as numbers.
fn color_values<'a>(words: impl Iterator<Item = &'a str>) -> usize {
    let extra: Vec<&str> = words.collect();
    if extra.len() != 3 {
        return 0;
    }
    extra
        .iter()
        .take_while(|word| parse_like(like_tobj, word).is_ok())
        .count()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scan_text(text: &str) -> Result<Vec<FaceLine>, String> {
        scan(text.as_bytes(), "t.obj", Bound::WholeFile).map_err(|e| e.to_string())
    }

    #[test]
    fn records_face_lines_and_polylines() {
        let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nl 1 2\nl 1 2 3\n# c\nf -3 -2 -1\n";
        let faces = scan_text(text).expect("valid");
        let lines: Vec<_> = faces.iter().map(|f| (f.line, f.polyline)).collect();
        assert_eq!(lines, [(4, false), (6, true), (8, false)]);
    }

    #[test]
    fn reports_the_first_offending_line() {
        let v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
        let err = |body: &str| scan_text(&format!("{v}{body}")).expect_err("invalid");
        assert_eq!(
            err("f 1 2 3\nf 1 2 9\n"),
            "t.obj:5: face index 9 out of range (the file has 3 vertices)"
        );
        assert!(err("f 1 2 -4\n").starts_with("t.obj:4: relative face index -4 out of range"));
        assert!(err("f 1 0 2\n").contains("face index 0 is invalid"));
        assert!(err("f 1 2\n").contains("face has 2 vertices"));
        assert!(err("f 1 2 x\n").contains("'x' is not an integer"));
        assert!(err("f 1 2 3/1/1/1\n").contains("more than 3 indices"));
        assert!(err("f 1 2 /1\n").contains("no position index"));
        assert!(err("v 1 nan 2\n").starts_with("t.obj:4: coordinate 'nan' is not a finite"));
        assert!(err("v 1 2\n").contains("expected 3 coordinates"));
        assert!(err("v 1 2 3 0\n").contains("w is zero"));
        assert!(err("v 1 2 3 4 5\n").contains("found 2"));
        assert!(err("vt 1 2\nf 1/5 2/1 3/1\n").contains("texture index 5 out of range"));
        assert!(err("usemtl\n").contains("usemtl"));
        let bad_utf8 = [v.as_bytes(), b"f 1 2 \xff\n"].concat();
        let e = scan(&bad_utf8, "t.obj", Bound::WholeFile).expect_err("utf8");
        assert_eq!(e.location(), Some(Location::Line(4)));
    }

    #[test]
    fn forward_references_are_found_only_when_asked() {
        let text = "v 0 0 0\nf 1 2 3\nv 1 0 0\nv 0 1 0\n";
        assert!(scan_text(text).is_ok());
        let e = scan(text.as_bytes(), "t.obj", Bound::SoFar).expect_err("forward");
        assert!(
            e.to_string()
                .starts_with("t.obj:2: face index 2 refers to a later line")
        );
    }

    #[test]
    fn texture_indices_are_ignored_without_texture_coordinates() {
        assert!(scan_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/7 2/-9 3/99999999999\n").is_ok());
    }
}
