//! PNG encoding (8-bit RGB, the `png` crate's fixed default settings, so equal images give equal
//! bytes) and atomic writing.

use super::{Image, RenderError};
use std::path::Path;

/// The PNG bytes of `image`.
pub fn encode(image: &Image) -> Result<Vec<u8>, png::EncodingError> {
    let mut bytes = Vec::new();
    let mut encoder = png::Encoder::new(&mut bytes, image.width, image.height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header()?;
    writer.write_image_data(image.pixels.as_flattened())?;
    writer.finish()?;
    Ok(bytes)
}

/// Writes `image` to `path` as PNG, atomically (a temporary file renamed over `path`).
pub fn write_png(path: &Path, image: &Image) -> Result<(), RenderError> {
    let failed = |message: String| RenderError::Write {
        path: path.to_path_buf(),
        message,
    };
    let bytes = encode(image).map_err(|e| failed(e.to_string()))?;
    Ok(crate::io::write_atomic(path, |out| out.write_all(&bytes))?)
}
