//! Writing a curve's polyline: OBJ (`v` lines and one `l` line), SVG (a path of the xy
//! projection, y up) or JSON (`{"params", "points", "certified"}`), by the file's extension,
//! atomically.

use anyhow::{Result, bail};
use solidkit_kernel::curve::Polyline;
use solidkit_meshing::io::write_atomic;
use std::io::Write;
use std::path::Path;

/// Writes `line` to `path` in the format of its extension.
pub fn write(path: &Path, line: &Polyline) -> Result<()> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase)
        .unwrap_or_default();
    let text = match ext.as_str() {
        "obj" => obj(line),
        "svg" => svg(line),
        "json" => json(line)?,
        _ => bail!(
            "{}: unknown polyline format (expected .obj, .svg or .json)",
            path.display()
        ),
    };
    write_atomic(path, |out: &mut dyn Write| out.write_all(text.as_bytes()))?;
    Ok(())
}

fn obj(line: &Polyline) -> String {
    let mut s = String::from("# solidkit curve polyline\n");
    for p in &line.points {
        s.push_str(&format!("v {} {} {}\n", p.x, p.y, p.z));
    }
    s.push('l');
    for i in 1..=line.points.len() {
        s.push_str(&format!(" {i}"));
    }
    s.push('\n');
    s
}

fn svg(line: &Polyline) -> String {
    let (mut lo, mut hi) = (
        glam::DVec2::splat(f64::INFINITY),
        glam::DVec2::splat(-f64::INFINITY),
    );
    for p in &line.points {
        lo = lo.min(p.truncate());
        hi = hi.max(p.truncate());
    }
    let size = (hi - lo).max_element().max(1e-9);
    let margin = 0.05 * size;
    let (x0, y0) = (lo.x - margin, -hi.y - margin);
    let (w, h) = (hi.x - lo.x + 2.0 * margin, hi.y - lo.y + 2.0 * margin);
    let mut d = String::new();
    for (i, p) in line.points.iter().enumerate() {
        d.push_str(if i == 0 { "M" } else { " L" });
        d.push_str(&format!("{} {}", p.x, -p.y));
    }
    format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"{x0} {y0} {w} {h}\">\n\
         <path d=\"{d}\" fill=\"none\" stroke=\"black\" stroke-width=\"{}\"/>\n</svg>\n",
        size / 300.0
    )
}

fn json(line: &Polyline) -> Result<String> {
    let points: Vec<[f64; 3]> = line.points.iter().map(|p| p.to_array()).collect();
    Ok(serde_json::to_string(&serde_json::json!({
        "params": line.params,
        "points": points,
        "certified": line.certified,
    }))? + "\n")
}
