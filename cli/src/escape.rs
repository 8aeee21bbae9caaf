//! The one place text from inputs is made safe for a terminal: every message the CLI prints on
//! standard error about an input (errors, Rhai `print`/`debug`) goes through [`one_line`], so a
//! hostile file name, JSON string or script cannot send escape sequences, carriage returns or
//! NUL bytes to the user's terminal, nor split a message over several lines.

/// `text` on one line: newlines become spaces, other control characters (ESC, CR, NUL, ...) and
/// the Unicode bidirectional overrides are written as Rust escapes (`\u{1b}`, `\r`, `\0`).
pub fn one_line(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '\n' => out.push(' '),
            '\0' => out.push_str("\\0"),
            c if c.is_control()
                || matches!(c, '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}') =>
            {
                out.extend(c.escape_default())
            }
            c => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::one_line;

    #[test]
    fn control_characters_are_escaped() {
        assert_eq!(
            one_line("a\u{1b}[2Jb\rc\0d\ne\u{202e}f é"),
            "a\\u{1b}[2Jb\\rc\\0d e\\u{202e}f é"
        );
        assert!(!one_line("\u{7}\u{9b}\t").chars().any(char::is_control));
    }
}
