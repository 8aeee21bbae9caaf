//! `WxH` image sizes, refused when hostile before any pixel is allocated.

use super::RenderError;

/// The most pixels an image may have (64 Mi: 192 MiB of RGB plus the depth buffer).
pub const MAX_PIXELS: u64 = 64 * 1024 * 1024;

/// The longest side accepted.
pub const MAX_SIDE: u64 = 65_536;

/// A checked image size: both sides at least 1, at most [`MAX_SIDE`], at most [`MAX_PIXELS`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ImageSize {
    /// Columns.
    pub width: u32,
    /// Rows.
    pub height: u32,
}

impl ImageSize {
    /// A checked size.
    pub fn new(width: u64, height: u64) -> Result<Self, RenderError> {
        if width == 0 || height == 0 {
            return Err(RenderError::Parse(format!(
                "{width}x{height}: both sides must be at least 1 pixel"
            )));
        }
        if width > MAX_SIDE || height > MAX_SIDE || width.saturating_mul(height) > MAX_PIXELS {
            return Err(RenderError::TooLarge { width, height });
        }
        Ok(Self {
            width: width as u32,
            height: height as u32,
        })
    }

    /// Parses `WxH` (or a single number for a square).
    pub fn parse(s: &str) -> Result<Self, RenderError> {
        let bad = || RenderError::Parse(format!("'{s}' is not a size WxH (e.g. 1024x768)"));
        let number = |t: &str| t.trim().parse::<u64>().map_err(|_| bad());
        match s.split_once(['x', 'X']) {
            Some((w, h)) => Self::new(number(w)?, number(h)?),
            None => {
                let n = number(s)?;
                Self::new(n, n)
            }
        }
    }

    /// `width × height`.
    pub fn pixel_count(self) -> usize {
        self.width as usize * self.height as usize
    }
}

#[cfg(test)]
mod tests {
    use super::ImageSize;

    #[test]
    fn hostile_sizes_are_refused() {
        assert!(ImageSize::parse("100000x100000").is_err());
        assert!(ImageSize::parse("18446744073709551615x2").is_err());
        assert!(ImageSize::parse("0x5").is_err());
        assert!(ImageSize::parse("8192x8192").is_ok());
        assert_eq!(ImageSize::parse("512").unwrap().height, 512);
        assert!(ImageSize::parse("12y4").is_err());
    }
}
