//! Colours of parts of a tree (issue 14): [`Rgba`] (four channels in `0..=1`), parsed from
//! OpenSCAD's and CSS's spellings — the SVG/CSS colour names (OpenSCAD's table, with
//! `transparent`), `#rgb`, `#rgba`, `#rrggbb`, `#rrggbbaa` — and [`Solid::color_skeleton`], the
//! coloured parts of a tree and the min/max skeleton over them, from which the meshing crate
//! finds the part each triangle's surface comes from.
//!
//! A `color` node never changes geometry: it lowers to its child unchanged.
//!
//! [`Solid::color_skeleton`]: crate::Solid::color_skeleton

mod names;
mod skeleton;

pub use skeleton::{ColorSkeleton, ColoredPart, Operand, SkeletonNode};

/// A colour: red, green, blue and alpha (opacity), each in `0..=1`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rgba(pub [f32; 4]);

impl Rgba {
    /// An opaque colour from red, green and blue in `0..=1`.
    pub fn rgb(r: f32, g: f32, b: f32) -> Rgba {
        Rgba([r, g, b, 1.0])
    }

    /// The colour of a CSS/SVG colour name (case-insensitive, as OpenSCAD) or a hex string
    /// (`#rgb`, `#rgba`, `#rrggbb`, `#rrggbbaa`); `None` for anything else.
    pub fn parse(text: &str) -> Option<Rgba> {
        let t = text.trim();
        if let Some(hex) = t.strip_prefix('#') {
            return parse_hex(hex);
        }
        let lower = t.to_ascii_lowercase();
        names::lookup(&lower).map(|[r, g, b, a]| Rgba([r, g, b, a].map(|c| f32::from(c) / 255.0)))
    }

    /// The colour with its alpha replaced.
    pub fn with_alpha(self, alpha: f32) -> Rgba {
        let [r, g, b, _] = self.0;
        Rgba([r, g, b, alpha])
    }

    /// The channels as bytes (`round(255·c)`, clamped), as files store them.
    pub fn to_u8(self) -> [u8; 4] {
        self.0.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8)
    }

    /// The colour from bytes.
    pub fn from_u8(c: [u8; 4]) -> Rgba {
        Rgba(c.map(|c| f32::from(c) / 255.0))
    }

    /// Why the colour is not valid (a channel outside `0..=1` or not finite), if it is not.
    pub fn problem(&self) -> Option<String> {
        self.0
            .iter()
            .any(|c| !(c.is_finite() && (0.0..=1.0).contains(c)))
            .then(|| "color: expected channels between 0 and 1".to_string())
    }
}

/// `rgb`, `rgba`, `rrggbb` or `rrggbbaa` hex digits.
fn parse_hex(hex: &str) -> Option<Rgba> {
    if !hex.bytes().all(|b| b.is_ascii_hexdigit()) {
        return None;
    }
    let digit = |i: usize| u8::from_str_radix(&hex[i..i + 1], 16).ok();
    let pair = |i: usize| u8::from_str_radix(&hex[i..i + 2], 16).ok();
    let bytes: Vec<u8> = match hex.len() {
        3 | 4 => (0..hex.len())
            .map(|i| digit(i).map(|d| d * 17))
            .collect::<Option<_>>()?,
        6 | 8 => (0..hex.len() / 2)
            .map(|i| pair(2 * i))
            .collect::<Option<_>>()?,
        _ => return None,
    };
    let a = bytes.get(3).copied().unwrap_or(255);
    Some(Rgba::from_u8([bytes[0], bytes[1], bytes[2], a]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_and_hex_strings() {
        assert_eq!(Rgba::parse("Red").unwrap().to_u8(), [255, 0, 0, 255]);
        assert_eq!(
            Rgba::parse("cornflowerblue").unwrap().to_u8(),
            [100, 149, 237, 255]
        );
        assert_eq!(Rgba::parse("grey"), Rgba::parse("gray"));
        assert_eq!(Rgba::parse("transparent").unwrap().to_u8()[3], 0);
        assert_eq!(Rgba::parse("#f00").unwrap().to_u8(), [255, 0, 0, 255]);
        assert_eq!(Rgba::parse("#ff000080").unwrap().to_u8(), [255, 0, 0, 128]);
        assert_eq!(
            Rgba::parse("#12345678").unwrap().to_u8(),
            [0x12, 0x34, 0x56, 0x78]
        );
        assert_eq!(
            Rgba::parse("#1234").unwrap().to_u8(),
            [0x11, 0x22, 0x33, 0x44]
        );
        for bad in ["", "#", "#12", "#12345", "#gg0000", "reddish", "#ff00ff0"] {
            assert!(Rgba::parse(bad).is_none(), "{bad}");
        }
        assert!(Rgba([0.0, 1.5, 0.0, 1.0]).problem().is_some());
        assert!(Rgba([0.0, f32::NAN, 0.0, 1.0]).problem().is_some());
        assert!(Rgba::rgb(0.2, 0.4, 0.6).problem().is_none());
    }

    #[test]
    fn the_table_has_every_css_name_once() {
        assert_eq!(names::NAMES.len(), 148);
        assert!(
            names::NAMES.windows(2).all(|w| w[0].0 < w[1].0),
            "sorted, unique"
        );
    }
}

#[cfg(test)]
mod node_tests;
