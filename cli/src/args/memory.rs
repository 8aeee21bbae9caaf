//! `--max-memory`: sizes with units (the default budget is
//! `solidkit_meshing::pipeline::limits::default_max_memory`).

/// Parses a size in bytes: a whole number, or a decimal number with K, M, G or T (powers of
/// 1024; a trailing `B` or `iB` is allowed), from 1 MiB to 1 PiB.
pub fn parse_memory(s: &str) -> Result<u64, String> {
    let t = s.trim();
    let upper = t.to_ascii_uppercase();
    let body = upper
        .strip_suffix("IB")
        .or_else(|| upper.strip_suffix('B'))
        .unwrap_or(&upper);
    let (number, shift) = match body.chars().last() {
        Some('K') => (&body[..body.len() - 1], 10),
        Some('M') => (&body[..body.len() - 1], 20),
        Some('G') => (&body[..body.len() - 1], 30),
        Some('T') => (&body[..body.len() - 1], 40),
        _ => (body, 0),
    };
    let bytes = number
        .trim()
        .parse::<f64>()
        .ok()
        .filter(|v| v.is_finite())
        .map(|v| v * (1u64 << shift) as f64);
    match bytes {
        Some(b) if (1048576.0..=1125899906842624.0).contains(&b) => Ok(b as u64),
        _ => Err(format!(
            "'{s}' is not a size from 1M to 1024T (bytes, or a number with K, M, G or T)"
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::parse_memory;

    #[test]
    fn sizes_parse_with_units_and_ranges_are_checked() {
        assert_eq!(parse_memory("8G"), Ok(8 << 30));
        assert_eq!(parse_memory("1.5g"), Ok(3 << 29));
        assert_eq!(parse_memory("512MiB"), Ok(512 << 20));
        assert_eq!(parse_memory("2097152"), Ok(2 << 20));
        for bad in ["", "G", "1K", "-1G", "nanG", "infT", "2000T", "12Q"] {
            assert!(parse_memory(bad).is_err(), "{bad}");
        }
    }
}
