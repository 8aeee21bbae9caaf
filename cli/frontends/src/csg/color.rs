//! `color()`: OpenSCAD's arguments (`c` a name, `#hex` or a vector, `alpha`) to a colour.
//!
//! As OpenSCAD: `color([r, g, b], alpha)`, `color([r, g, b, a])` (the vector's alpha wins),
//! `color("name", alpha)` with the SVG/CSS names, `color("#rrggbb[aa]")` (its alpha wins over
//! `alpha`), `color(c = …, alpha = …)`; channels are clamped to 0..1. An unknown name or a
//! malformed vector leaves the subtree uncoloured with a warning (OpenSCAD warns too); no
//! argument leaves it uncoloured silently.

use super::args::numbers;
use super::parser::{Stmt, Value};
use solidkit_kernel::Rgba;

/// The colour of a `color()` statement: `Ok(None)` without one, `Err(warning)` when the
/// argument is not a colour.
pub(super) fn color_of(stmt: &Stmt) -> Result<Option<Rgba>, String> {
    let alpha = match stmt.arg("alpha", Some(1)) {
        Some(Value::Num(a)) if a.is_finite() => Some(a.clamp(0.0, 1.0) as f32),
        Some(_) => return Err("alpha: expected a number; the colour is ignored".into()),
        None => None,
    };
    let rgba = match stmt.arg("c", Some(0)) {
        None => return Ok(None),
        Some(Value::Str(s)) => {
            let Some(c) = Rgba::parse(s) else {
                return Err(format!(
                    "unable to parse color {s:?}; the colour is ignored"
                ));
            };
            let hex_alpha = s.trim().starts_with('#') && matches!(s.trim().len(), 5 | 9);
            match alpha {
                Some(a) if !hex_alpha => c.with_alpha(a),
                _ => c,
            }
        }
        Some(v) => match numbers(v).as_deref() {
            Some(&[r, g, b]) => {
                Rgba([r, g, b, 1.0].map(|x| x as f32)).with_alpha(alpha.unwrap_or(1.0))
            }
            Some(&[r, g, b, a]) => Rgba([r, g, b, a].map(|x| x as f32)),
            _ => {
                return Err(
                    "c: expected [r, g, b], [r, g, b, a] or a colour name; the colour is ignored"
                        .into(),
                );
            }
        },
    };
    Ok(Some(Rgba(rgba.0.map(|x| x.clamp(0.0, 1.0)))))
}
