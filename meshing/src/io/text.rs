//! Helpers shared by the text formats (ASCII STL, ASCII PLY, OFF): lines and
//! whitespace-separated tokens with their 1-based line numbers and number parsing for the
//! readers, the polygon row for the writers.
//!
//! Everything works on bytes, so a file that is not valid UTF-8 (a Latin-1 solid name, say)
//! is only rejected where a token that matters is not a number.

/// The lines of `bytes` with their 1-based numbers; `\n` and a trailing `\r` are removed.
pub(super) fn lines(bytes: &[u8]) -> impl Iterator<Item = (usize, &[u8])> {
    let body = bytes.strip_suffix(b"\n").unwrap_or(bytes);
    let no_lines = bytes.is_empty();
    body.split(|&b| b == b'\n')
        .filter(move |_| !no_lines)
        .enumerate()
        .map(|(i, line)| (i + 1, line.strip_suffix(b"\r").unwrap_or(line)))
}

/// The ASCII-whitespace-separated words of one line.
pub(super) fn words(line: &[u8]) -> impl Iterator<Item = &[u8]> {
    line.split(u8::is_ascii_whitespace)
        .filter(|w| !w.is_empty())
}

/// A token stream over text that ignores line structure but knows the line of every token.
pub(super) struct Tokens<'a> {
    bytes: &'a [u8],
    pos: usize,
    line: usize,
}

impl<'a> Tokens<'a> {
    /// Tokens of `bytes`, whose first line has number `first_line`.
    pub(super) fn new(bytes: &'a [u8], first_line: usize) -> Self {
        Self {
            bytes,
            pos: 0,
            line: first_line,
        }
    }

    /// The next token and its line, or `None` at the end of the text.
    pub(super) fn next_token(&mut self) -> Option<(usize, &'a [u8])> {
        self.skip_whitespace();
        let rest = self.bytes.get(self.pos..)?;
        if rest.is_empty() {
            return None;
        }
        let len = rest
            .iter()
            .position(u8::is_ascii_whitespace)
            .unwrap_or(rest.len());
        self.pos += len;
        Some((self.line, &rest[..len]))
    }

    /// Skips the rest of the current line (after the last token returned).
    pub(super) fn skip_line(&mut self) {
        let rest = self.bytes.get(self.pos..).unwrap_or_default();
        match rest.iter().position(|&b| b == b'\n') {
            Some(newline) => {
                self.pos += newline + 1;
                self.line += 1;
            }
            None => self.pos = self.bytes.len(),
        }
    }

    /// The line the stream is at: that of the last token, or later after whitespace.
    pub(super) fn line(&self) -> usize {
        self.line
    }

    fn skip_whitespace(&mut self) {
        while let Some(&b) = self.bytes.get(self.pos) {
            if !b.is_ascii_whitespace() {
                break;
            }
            if b == b'\n' {
                self.line += 1;
            }
            self.pos += 1;
        }
    }
}

/// A token for messages: lossy UTF-8, control characters escaped (`\u{1b}`), shortened to 40
/// characters.
pub(super) fn show(token: &[u8]) -> String {
    let text = String::from_utf8_lossy(token);
    let mut out = String::new();
    for (count, c) in text.chars().enumerate() {
        if count == 37 && text.chars().count() > 40 {
            out.push_str("...");
            break;
        }
        if c.is_control() {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    out
}

/// Parses a decimal floating-point number (`inf` and `nan` included: callers check finiteness).
pub(super) fn parse_f64(token: &[u8]) -> Option<f64> {
    std::str::from_utf8(token).ok()?.parse().ok()
}

/// Parses a decimal integer with an optional sign.
pub(super) fn parse_i64(token: &[u8]) -> Option<i64> {
    std::str::from_utf8(token).ok()?.parse().ok()
}

/// Parses a finite coordinate, or explains why the token is not one.
pub(super) fn parse_coordinate(token: &[u8]) -> Result<f64, String> {
    match parse_f64(token) {
        Some(value) if value.is_finite() => Ok(value),
        Some(_) => Err(format!(
            "coordinate '{}' is not a finite number",
            show(token)
        )),
        None => Err(format!("expected a number, found '{}'", show(token))),
    }
}

/// A capacity for `count` items of which each needs at least `min_bytes` of the remaining
/// `available` bytes: never trust a count read from a header for an allocation.
pub(super) fn capped_capacity(count: u64, available: usize, min_bytes: usize) -> usize {
    let fit = available / min_bytes.max(1);
    usize::try_from(count).map_or(fit, |count| count.min(fit))
}

/// Writes one polygon row of the text formats (OFF, ASCII PLY): the corner count, then the
/// indices, then the end of the line.
pub(super) fn write_face_row(out: &mut dyn std::io::Write, face: &[u32]) -> std::io::Result<()> {
    write!(out, "{}", face.len())?;
    for i in face {
        write!(out, " {i}")?;
    }
    writeln!(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_are_numbered_from_one_without_line_ends() {
        let got: Vec<_> = lines(b"a\r\nb\n\nc").collect();
        assert_eq!(got, [(1, &b"a"[..]), (2, b"b"), (3, b""), (4, b"c")]);
        assert_eq!(lines(b"x\n").count(), 1);
        assert_eq!(lines(b"").count(), 0);
    }

    #[test]
    fn tokens_know_their_lines() {
        let mut t = Tokens::new(b"solid name here\n  facet\r\n\n 1.5 x", 1);
        assert_eq!(t.next_token(), Some((1, &b"solid"[..])));
        t.skip_line();
        assert_eq!(t.next_token(), Some((2, &b"facet"[..])));
        assert_eq!(t.next_token(), Some((4, &b"1.5"[..])));
        assert_eq!(t.next_token(), Some((4, &b"x"[..])));
        assert_eq!(t.next_token(), None);
        assert_eq!(t.next_token(), None);
    }

    #[test]
    fn coordinates_must_be_finite_numbers() {
        assert_eq!(parse_coordinate(b"-2.5e1"), Ok(-25.0));
        assert!(
            parse_coordinate(b"nan")
                .unwrap_err()
                .contains("not a finite")
        );
        assert!(
            parse_coordinate(b"inf")
                .unwrap_err()
                .contains("not a finite")
        );
        assert!(
            parse_coordinate(b"1,5")
                .unwrap_err()
                .contains("expected a number")
        );
        assert!(parse_coordinate(&[0xff, 0xfe]).is_err());
    }

    #[test]
    fn capacity_is_capped_by_the_bytes_available() {
        assert_eq!(capped_capacity(u64::MAX, 1000, 10), 100);
        assert_eq!(capped_capacity(5, 1000, 10), 5);
        assert_eq!(capped_capacity(5, 1000, 0), 5);
    }
}
