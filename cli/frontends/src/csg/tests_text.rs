//! `text()` through the installed OpenSCAD (skipped where it is not installed): glyphs with their
//! holes, alignment, empty text, arguments written back safely, and the errors.

use super::flat::{Flat, Leaf2, Op2};
use super::parser::parse;
use super::text::{TextError, find_openscad, render, scad_source, text};
use super::{Facets, import_with_warnings};
use solidkit_kernel::primitive::NoMeshResolver;

/// The first statement of `src`.
fn stmt(src: &str) -> super::parser::Stmt {
    let tree = parse(src).expect("parses");
    tree.nodes[tree.roots[0]].clone()
}

/// The loops of each polygon leaf.
fn parts(f: &Flat) -> Vec<usize> {
    f.0.iter()
        .filter_map(|op| match op {
            Op2::Leaf(Leaf2::Polygon(l)) => Some(l.len()),
            _ => None,
        })
        .collect()
}

#[test]
fn arguments_are_written_back_as_openscad_literals() {
    let s = stmt("text(text = \"a\\\"b\\\\c\", size = 10, halign = \"center\", $fn = 0);");
    assert_eq!(
        scad_source(&s).unwrap(),
        "text(text = \"a\\\"b\\\\c\", size = 10.0, halign = \"center\", $fn = 0.0);\n"
    );
    let s = stmt("text(\"x\", size = [1, 2]);");
    assert!(matches!(scad_source(&s), Err(TextError::Argument(n)) if n == "size"));
}

#[test]
fn a_missing_program_is_a_clear_error() {
    let s = stmt("text(\"x\");");
    let e = render(
        std::path::Path::new("/nonexistent/openscad"),
        "text(\"x\");",
        &s,
    )
    .unwrap_err();
    assert!(
        e.to_string()
            .starts_with("openscad failed: /nonexistent/openscad"),
        "{e}"
    );
    assert!(
        TextError::NoOpenScad
            .to_string()
            .contains("'openscad' program")
    );
}

#[test]
fn glyphs_keep_their_holes_and_empty_text_is_empty() {
    if find_openscad().is_none() {
        eprintln!("openscad is not installed: skipped");
        return;
    }
    // "o" and "b" have one hole each, "l" none: three parts, 2 + 2 + 1 loops.
    let mut cache = Default::default();
    let f = text(&stmt("text(text = \"obl\", size = 10);"), &mut cache)
        .unwrap()
        .unwrap();
    let mut p = parts(&f);
    p.sort_unstable();
    assert_eq!(p, [1, 2, 2]);
    assert_eq!(
        text(&stmt("text(text = \"\", size = 10);"), &mut cache).unwrap(),
        None
    );
    // Drawn once per distinct text.
    assert_eq!(cache.len(), 2);
    let again = text(&stmt("text(text = \"obl\", size = 10);"), &mut cache).unwrap();
    assert_eq!(again, Some(f));
}

#[test]
fn extruded_text_is_a_solid_with_openscads_alignment() {
    if find_openscad().is_none() {
        eprintln!("openscad is not installed: skipped");
        return;
    }
    let (s, w) = import_with_warnings(
        "linear_extrude(height = 2) text(text = \"H\", size = 10, halign = \"center\", \
         valign = \"center\");",
        Facets::Exact,
        &NoMeshResolver,
    )
    .unwrap();
    assert!(w.is_empty());
    let b = s.bbox();
    // Centred on the origin by the font's metrics (not exactly the glyph's box; unaligned, the
    // "H" would span x from about 0.8 to 8.4 and y from 0 to 10), 2 high.
    assert!((b.min.x + b.max.x).abs() < 0.5, "{b:?}");
    assert!((b.min.y + b.max.y).abs() < 0.5, "{b:?}");
    assert!(b.max.y > 3.0 && b.max.y < 6.0, "{b:?}");
    assert_eq!((b.min.z, b.max.z), (0.0, 2.0));
}
