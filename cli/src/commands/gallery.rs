//! `solidkit gallery`: a Markdown page with a picture and the report line of every example in
//! a folder (solids ray cast from their field, meshes rasterised; solids meshed at a fixed
//! resolution for the report), or, with `--check`, the comparison of a fresh one with the page
//! and pictures already there (exit 1 on drift: what CI runs on docs/gallery.md).

use crate::args::GalleryArgs;
use crate::input;
use crate::output::outln;
use anyhow::{Context, Result, anyhow};
use solidkit_frontends::load::Format;
use solidkit_meshing::io::{MeshFormat, read_mesh};
use solidkit_meshing::pipeline::{MeshOptions, Prepared};
use solidkit_meshing::refine::RefineOptions;
use solidkit_meshing::render::field::trace_field;
use solidkit_meshing::render::png_out::{decode, encode};
use solidkit_meshing::render::raster::{trace_mesh, triangles_box};
use solidkit_meshing::render::{Image, Look, View, picture, shade};
use solidkit_meshing::{ReportOptions, TopologyReport};
use std::path::{Component, Path, PathBuf};

/// A picture may differ from the one on disk in at most this share of its pixels ...
pub const MAX_CHANGED_SHARE: f64 = 0.002;
/// ... where a pixel counts as changed when a channel moved by more than this.
pub const MAX_CHANNEL_STEP: u8 = 2;

/// One example: its file, the picture's file name, the picture and the report line.
struct Entry {
    file: PathBuf,
    png: String,
    image: Image,
    line: String,
}

/// Writes (or checks) the gallery.
pub fn run(a: &GalleryArgs) -> Result<u8> {
    let files = example_files(&a.examples)?;
    if files.is_empty() {
        return Err(anyhow!("{}: no examples found", a.examples.display()));
    }
    let mut entries = Vec::with_capacity(files.len());
    for file in files {
        entries.push(entry(&file, a)?);
    }
    let images = a.output.with_extension("");
    let page = page(a, &entries, &images)?;
    if a.check {
        let drift = drift(a, &entries, &images, &page);
        for d in &drift {
            outln!("drift: {d}")?;
        }
        if drift.is_empty() {
            outln!("gallery up to date: {} examples", entries.len())?;
            return Ok(0);
        }
        outln!(
            "regenerate with: solidkit gallery {} -o {}",
            a.examples.display(),
            a.output.display()
        )?;
        return Ok(1);
    }
    std::fs::create_dir_all(&images).with_context(|| format!("{}", images.display()))?;
    let keep: Vec<&str> = entries.iter().map(|e| e.png.as_str()).collect();
    for old in std::fs::read_dir(&images).with_context(|| format!("{}", images.display()))? {
        let old = old?.path();
        let name = old.file_name().and_then(|n| n.to_str()).unwrap_or_default();
        if name.ends_with(".png") && !keep.contains(&name) {
            std::fs::remove_file(&old).with_context(|| format!("{}", old.display()))?;
        }
    }
    for e in &entries {
        let bytes = encode(&e.image).map_err(|err| anyhow!("{}: {err}", e.png))?;
        let path = images.join(&e.png);
        solidkit_meshing::io::write_atomic(&path, |out| out.write_all(&bytes))?;
    }
    solidkit_meshing::io::write_atomic(&a.output, |out| out.write_all(page.as_bytes()))?;
    outln!("wrote: {} ({} examples)", a.output.display(), entries.len())?;
    Ok(0)
}

/// The examples in `dir`, by name: solids and mesh files (no `.scad`).
fn example_files(dir: &Path) -> Result<Vec<PathBuf>> {
    let mut files = Vec::new();
    for item in std::fs::read_dir(dir).with_context(|| format!("{}", dir.display()))? {
        let path = item?.path();
        if !path.is_file() {
            continue;
        }
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .unwrap_or_default();
        if ext.eq_ignore_ascii_case("scad") {
            continue;
        }
        if is_solid(&path) || MeshFormat::from_path(&path).is_ok() {
            files.push(path);
        }
    }
    files.sort();
    Ok(files)
}

/// True for the front ends' formats (drawn from their field).
fn is_solid(path: &Path) -> bool {
    Format::from_path(path).is_ok()
}

/// The picture and report line of one example.
fn entry(file: &Path, a: &GalleryArgs) -> Result<Entry> {
    let name = file
        .file_name()
        .and_then(|n| n.to_str())
        .unwrap_or("example");
    let png = format!("{}.png", name.replace('.', "-"));
    let look = Look {
        view: Some(View::Iso),
        edges: true,
        axes: false,
        base: shade::SOLID,
    };
    let shown = file.display();
    let (image, report) = if is_solid(file) {
        let solid = input::load_solid(file, &[], &[])?;
        let program = solid.compile();
        let image = picture(&solid.bbox(), a.size, &look, |cam| {
            trace_field(&program, cam)
        })
        .map_err(|e| anyhow!("{shown}: {e}"))?;
        let options = MeshOptions::new(a.resolution).refine(RefineOptions {
            max_factor: 1,
            ..RefineOptions::default()
        });
        let meshed = Prepared::new(&solid, &options)
            .and_then(|p| p.mesh())
            .map_err(|e| anyhow!("{shown}: {e}"))?;
        (image, meshed.report(&ReportOptions::default()))
    } else {
        let mesh = read_mesh(file)?;
        let image = picture(&triangles_box(&mesh).0, a.size, &look, |cam| {
            trace_mesh(&mesh, cam)
        })
        .map_err(|e| anyhow!("{shown}: {e}"))?;
        (
            image,
            TopologyReport::with_options(&mesh, &ReportOptions::default()),
        )
    };
    Ok(Entry {
        file: file.to_path_buf(),
        png,
        image,
        line: report_line(&report),
    })
}

/// `verdict; N triangles, S shells, genus G, volume V`.
fn report_line(r: &TopologyReport) -> String {
    let genus = r.genus.map_or("-".to_string(), |g| g.to_string());
    let shells = if r.shells == 1 { "shell" } else { "shells" };
    format!(
        "{}; {} triangles, {} {shells}, genus {genus}, volume {:.4}",
        r.verdict(),
        r.faces,
        r.shells,
        r.volume
    )
}

/// The Markdown page.
fn page(a: &GalleryArgs, entries: &[Entry], images: &Path) -> Result<String> {
    let page_dir = a.output.parent().unwrap_or(Path::new("."));
    let images_rel = relative(page_dir, images)?;
    let mut s = String::new();
    s.push_str("# Gallery\n\n");
    // Paths in the text are relative to the folder above the page's (the repository root for
    // docs/gallery.md), so the page does not depend on where the command ran.
    let page_abs = absolute(page_dir)?;
    let root = page_abs.parent().unwrap_or(&page_abs).to_path_buf();
    let from_root = |p: &Path| relative(&root, p).map(|r| display_slash(&r));
    let examples = from_root(&a.examples)?;
    s.push_str(&format!(
        "Every example of `{examples}`: solids ray cast from their field, meshes rasterised \
         (`solidkit render`, iso view, feature edges, {}x{} pixels), and the report line of the \
         solid meshed at resolution {} without refinement (meshes: as read). Generated from the \
         repository root by\n\n```\nsolidkit gallery {examples} -o {}\n```\n\n",
        a.size.width,
        a.size.height,
        a.resolution,
        from_root(&a.output)?,
    ));
    s.push_str(&format!(
        "CI runs the same with `--check` (tests/cli_render.rs) and fails when the page changed or a \
         picture moved: more than {:.1} % of its pixels by more than {MAX_CHANNEL_STEP} levels in \
         a channel (the bytes are the same on every run and thread count on one machine; the \
         tolerance absorbs last-bit differences of another platform's maths library).\n\n",
        MAX_CHANGED_SHARE * 100.0
    ));
    s.push_str("| picture | example | report |\n| --- | --- | --- |\n");
    for e in entries {
        let name = e
            .file
            .file_name()
            .and_then(|n| n.to_str())
            .unwrap_or_default();
        let link = relative(page_dir, &e.file)?;
        s.push_str(&format!(
            "| ![{name}]({}/{}) | [{name}]({}) | {} |\n",
            display_slash(&images_rel),
            e.png,
            display_slash(&link),
            e.line.replace('|', "\\|")
        ));
    }
    Ok(s)
}

/// What differs between the fresh gallery and the files there.
fn drift(a: &GalleryArgs, entries: &[Entry], images: &Path, page: &str) -> Vec<String> {
    let mut out = Vec::new();
    match std::fs::read_to_string(&a.output) {
        Ok(old) if old == page => {}
        Ok(_) => out.push(format!("{}: the page changed", a.output.display())),
        Err(e) => out.push(format!("{}: {e}", a.output.display())),
    }
    for e in entries {
        let path = images.join(&e.png);
        let old = std::fs::read(&path).ok().and_then(|b| decode(&b));
        match old {
            None => out.push(format!("{}: missing or unreadable", path.display())),
            Some(old) => {
                if let Some(why) = picture_drift(&old, &e.image) {
                    out.push(format!("{}: {why}", path.display()));
                }
            }
        }
    }
    if let Ok(list) = std::fs::read_dir(images) {
        let mut stale: Vec<String> = list
            .filter_map(|f| f.ok()?.file_name().into_string().ok())
            .filter(|n| n.ends_with(".png") && !entries.iter().any(|e| &e.png == n))
            .collect();
        stale.sort();
        for n in stale {
            out.push(format!("{}: no example draws it", images.join(n).display()));
        }
    }
    out
}

/// Why `new` is not `old` within the tolerance, if it is not.
pub fn picture_drift(old: &Image, new: &Image) -> Option<String> {
    if (old.width, old.height) != (new.width, new.height) {
        return Some(format!(
            "size {}x{} became {}x{}",
            old.width, old.height, new.width, new.height
        ));
    }
    let changed = old
        .pixels
        .iter()
        .zip(&new.pixels)
        .filter(|(p, q)| {
            p.iter()
                .zip(q.iter())
                .any(|(a, b)| a.abs_diff(*b) > MAX_CHANNEL_STEP)
        })
        .count();
    let share = changed as f64 / old.pixels.len().max(1) as f64;
    (share > MAX_CHANGED_SHARE)
        .then(|| format!("{changed} pixels changed ({:.2} %)", share * 100.0))
}

/// `to` relative to the folder `from` (both resolved against the current folder).
fn relative(from: &Path, to: &Path) -> Result<PathBuf> {
    let (from, to) = (absolute(from)?, absolute(to)?);
    let (f, t): (Vec<Component>, Vec<Component>) =
        (from.components().collect(), to.components().collect());
    let common = f.iter().zip(&t).take_while(|(a, b)| a == b).count();
    let mut out = PathBuf::new();
    for _ in common..f.len() {
        out.push("..");
    }
    for c in &t[common..] {
        out.push(c);
    }
    Ok(out)
}

/// `p` resolved against the current folder, normalised.
fn absolute(p: &Path) -> Result<PathBuf> {
    let p = if p.as_os_str().is_empty() {
        Path::new(".")
    } else {
        p
    };
    Ok(normalise(&std::env::current_dir()?.join(p)))
}

/// `p` without `.` and with `..` applied (no file system access).
fn normalise(p: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for c in p.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir => {
                out.pop();
            }
            other => out.push(other),
        }
    }
    out
}

/// A path with `/` separators (Markdown links).
fn display_slash(p: &Path) -> String {
    p.components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect::<Vec<_>>()
        .join("/")
}
