//! A JSON parser that builds a flat arena of values with their byte offsets, without recursion:
//! nesting depth is limited only by memory, and dropping the arena is flat too.
//!
//! Strict where JSON readers differ: a key repeated in one object and a raw control character
//! inside a string are errors at their offset (never "the first (or last) one wins").

use std::collections::HashSet;

/// Objects with more keys than this check a new key against a hash set of the earlier ones
/// instead of scanning them, so duplicate detection stays linear on huge objects.
const SCAN_KEYS: usize = 16;

/// A parsed JSON value; containers refer to other values by arena index.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Value {
    Null,
    Bool(bool),
    Number(f64),
    String(String),
    Array(Vec<u32>),
    Object(Vec<(String, u32)>),
}

impl Value {
    /// Name of the value's JSON type, for error messages.
    pub(crate) fn type_name(&self) -> &'static str {
        match self {
            Value::Null => "null",
            Value::Bool(_) => "a boolean",
            Value::Number(_) => "a number",
            Value::String(_) => "a string",
            Value::Array(_) => "an array",
            Value::Object(_) => "an object",
        }
    }
}

/// A parsed document: `values[0]` is the top-level value.
#[derive(Debug, Default)]
pub(crate) struct Document {
    pub values: Vec<Value>,
    /// Byte offset of each value's first character.
    pub offsets: Vec<usize>,
}

/// A syntax error at a byte offset.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct SyntaxError {
    pub offset: usize,
    pub message: String,
}

enum Expect {
    Value,
    KeyOrEnd,
    Key,
    ValueOrEnd,
    CommaOrEnd,
}

struct Parser<'a> {
    s: &'a [u8],
    i: usize,
    doc: Document,
    /// Open containers (arena indices) and, for objects, the key awaiting its value.
    open: Vec<(u32, Option<String>)>,
    /// The keys of open objects with more than [`SCAN_KEYS`] entries, by arena index.
    key_sets: Vec<(u32, HashSet<String>)>,
}

fn err<T>(offset: usize, message: impl Into<String>) -> Result<T, SyntaxError> {
    Err(SyntaxError {
        offset,
        message: message.into(),
    })
}

/// Parses a complete JSON text.
pub(crate) fn parse(text: &str) -> Result<Document, SyntaxError> {
    let mut p = Parser {
        s: text.as_bytes(),
        i: 0,
        doc: Document::default(),
        open: Vec::new(),
        key_sets: Vec::new(),
    };
    p.run()?;
    Ok(p.doc)
}

impl Parser<'_> {
    fn skip_ws(&mut self) {
        while let Some(c) = self.s.get(self.i) {
            if matches!(c, b' ' | b'\t' | b'\n' | b'\r') {
                self.i += 1;
            } else {
                break;
            }
        }
    }

    fn peek(&self) -> Option<u8> {
        self.s.get(self.i).copied()
    }

    fn push(&mut self, v: Value, offset: usize) -> u32 {
        self.doc.values.push(v);
        self.doc.offsets.push(offset);
        (self.doc.values.len() - 1) as u32
    }

    /// Links a finished value to the innermost open container.
    fn attach(&mut self, idx: u32) {
        if let Some((parent, key)) = self.open.last_mut() {
            match &mut self.doc.values[*parent as usize] {
                Value::Array(items) => items.push(idx),
                Value::Object(entries) => {
                    entries.push((key.take().expect("key before value"), idx));
                }
                _ => unreachable!("only containers are open"),
            }
        }
    }

    fn run(&mut self) -> Result<(), SyntaxError> {
        let mut expect = Expect::Value;
        loop {
            self.skip_ws();
            let at = self.i;
            let Some(c) = self.peek() else {
                return if self.open.is_empty() && !self.doc.values.is_empty() {
                    Ok(())
                } else {
                    err(at, "unexpected end of input")
                };
            };
            if self.open.is_empty() && !self.doc.values.is_empty() {
                return err(at, "unexpected text after the JSON value");
            }
            expect = match expect {
                Expect::Value => self.value(c, at)?,
                Expect::ValueOrEnd if c == b']' => self.close(at)?,
                Expect::ValueOrEnd => self.value(c, at)?,
                Expect::KeyOrEnd if c == b'}' => self.close(at)?,
                Expect::KeyOrEnd | Expect::Key => self.key(c, at)?,
                Expect::CommaOrEnd => self.comma_or_end(c, at)?,
            };
        }
    }

    fn value(&mut self, c: u8, at: usize) -> Result<Expect, SyntaxError> {
        match c {
            b'{' | b'[' => {
                self.i += 1;
                let v = if c == b'{' {
                    Value::Object(Vec::new())
                } else {
                    Value::Array(Vec::new())
                };
                let idx = self.push(v, at);
                self.attach_open(idx);
                Ok(if c == b'{' {
                    Expect::KeyOrEnd
                } else {
                    Expect::ValueOrEnd
                })
            }
            _ => {
                let v = self.scalar(c, at)?;
                let idx = self.push(v, at);
                self.attach(idx);
                Ok(Expect::CommaOrEnd)
            }
        }
    }

    fn attach_open(&mut self, idx: u32) {
        self.attach(idx);
        self.open.push((idx, None));
    }

    fn close(&mut self, _at: usize) -> Result<Expect, SyntaxError> {
        self.i += 1;
        if let Some((idx, _)) = self.open.pop()
            && self.key_sets.last().is_some_and(|(o, _)| *o == idx)
        {
            self.key_sets.pop();
        }
        Ok(Expect::CommaOrEnd)
    }

    /// Whether the innermost open object already has the key `k`.
    fn is_duplicate(&mut self, k: &str) -> bool {
        let Some(&(idx, _)) = self.open.last() else {
            return false;
        };
        let Value::Object(entries) = &self.doc.values[idx as usize] else {
            return false;
        };
        if entries.len() <= SCAN_KEYS {
            return entries.iter().any(|(e, _)| e == k);
        }
        if self.key_sets.last().is_none_or(|(o, _)| *o != idx) {
            let keys = entries.iter().map(|(e, _)| e.clone()).collect();
            self.key_sets.push((idx, keys));
        }
        let (_, keys) = self.key_sets.last_mut().expect("pushed above");
        !keys.insert(k.to_owned())
    }

    fn key(&mut self, c: u8, at: usize) -> Result<Expect, SyntaxError> {
        if c != b'"' {
            return err(at, "expected a quoted object key");
        }
        let k = self.string()?;
        if self.is_duplicate(&k) {
            return err(at, format!("duplicate key \"{k}\" in object"));
        }
        self.skip_ws();
        if self.peek() != Some(b':') {
            return err(self.i, format!("expected ':' after key \"{k}\""));
        }
        self.i += 1;
        if let Some((_, slot)) = self.open.last_mut() {
            *slot = Some(k);
        }
        Ok(Expect::Value)
    }

    fn comma_or_end(&mut self, c: u8, at: usize) -> Result<Expect, SyntaxError> {
        let in_object = match self.open.last() {
            Some((idx, _)) => matches!(self.doc.values[*idx as usize], Value::Object(_)),
            None => return err(at, "unexpected text after the JSON value"),
        };
        match (c, in_object) {
            (b',', true) => {
                self.i += 1;
                Ok(Expect::Key)
            }
            (b',', false) => {
                self.i += 1;
                Ok(Expect::Value)
            }
            (b'}', true) | (b']', false) => self.close(at),
            (_, true) => err(at, "expected ',' or '}' in object"),
            (_, false) => err(at, "expected ',' or ']' in array"),
        }
    }

    fn scalar(&mut self, c: u8, at: usize) -> Result<Value, SyntaxError> {
        match c {
            b'"' => Ok(Value::String(self.string()?)),
            b't' => self.literal("true", Value::Bool(true)),
            b'f' => self.literal("false", Value::Bool(false)),
            b'n' => self.literal("null", Value::Null),
            b'-' | b'0'..=b'9' => self.number(),
            b'N' | b'I' => err(at, "JSON has no NaN or Infinity: numbers must be finite"),
            b'}' | b']' => err(at, format!("unexpected '{}'", c as char)),
            _ => err(at, format!("unexpected character '{}'", self.char_at(at))),
        }
    }

    fn char_at(&self, at: usize) -> char {
        std::str::from_utf8(&self.s[at..])
            .ok()
            .and_then(|t| t.chars().next())
            .unwrap_or('?')
    }

    fn literal(&mut self, word: &str, v: Value) -> Result<Value, SyntaxError> {
        if self.s[self.i..].starts_with(word.as_bytes()) {
            self.i += word.len();
            Ok(v)
        } else {
            err(self.i, format!("invalid literal (expected '{word}')"))
        }
    }

    fn number(&mut self) -> Result<Value, SyntaxError> {
        let start = self.i;
        let digits = |p: &mut Self| {
            let from = p.i;
            while p.peek().is_some_and(|c| c.is_ascii_digit()) {
                p.i += 1;
            }
            p.i > from
        };
        if self.peek() == Some(b'-') {
            self.i += 1;
        }
        if !digits(self) {
            return err(start, "invalid number");
        }
        if self.peek() == Some(b'.') {
            self.i += 1;
            if !digits(self) {
                return err(start, "invalid number: digits expected after '.'");
            }
        }
        if matches!(self.peek(), Some(b'e' | b'E')) {
            self.i += 1;
            if matches!(self.peek(), Some(b'+' | b'-')) {
                self.i += 1;
            }
            if !digits(self) {
                return err(start, "invalid number: digits expected in the exponent");
            }
        }
        let text = std::str::from_utf8(&self.s[start..self.i]).expect("ASCII");
        match text.parse::<f64>() {
            Ok(x) if x.is_finite() => Ok(Value::Number(x)),
            _ => err(start, format!("number {text} is out of range")),
        }
    }

    fn string(&mut self) -> Result<String, SyntaxError> {
        let start = self.i;
        self.i += 1; // opening quote
        let mut out = String::new();
        loop {
            let Some(c) = self.peek() else {
                return err(start, "unterminated string");
            };
            match c {
                b'"' => {
                    self.i += 1;
                    return Ok(out);
                }
                b'\\' => out.push(self.escape()?),
                0..=0x1f => return err(self.i, "control character in string"),
                _ => {
                    let run = self.i;
                    while self
                        .peek()
                        .is_some_and(|c| c != b'"' && c != b'\\' && c >= 0x20)
                    {
                        self.i += 1;
                    }
                    match std::str::from_utf8(&self.s[run..self.i]) {
                        Ok(t) => out.push_str(t),
                        Err(_) => return err(run, "invalid UTF-8 in string"),
                    }
                }
            }
        }
    }

    fn escape(&mut self) -> Result<char, SyntaxError> {
        let at = self.i;
        self.i += 2;
        let c = match self.s.get(at + 1) {
            Some(b'"') => '"',
            Some(b'\\') => '\\',
            Some(b'/') => '/',
            Some(b'b') => '\u{8}',
            Some(b'f') => '\u{c}',
            Some(b'n') => '\n',
            Some(b'r') => '\r',
            Some(b't') => '\t',
            Some(b'u') => return self.unicode_escape(at),
            _ => return err(at, "invalid escape in string"),
        };
        Ok(c)
    }

    fn hex4(&mut self, at: usize) -> Result<u32, SyntaxError> {
        let h = self
            .s
            .get(self.i..self.i + 4)
            .and_then(|h| std::str::from_utf8(h).ok())
            .and_then(|h| u32::from_str_radix(h, 16).ok());
        self.i += 4;
        h.map_or_else(|| err(at, "invalid \\u escape"), Ok)
    }

    fn unicode_escape(&mut self, at: usize) -> Result<char, SyntaxError> {
        let hi = self.hex4(at)?;
        let code = if (0xD800..0xDC00).contains(&hi) {
            if self.s.get(self.i..self.i + 2) != Some(b"\\u") {
                return err(at, "unpaired surrogate in \\u escape");
            }
            self.i += 2;
            let lo = self.hex4(at)?;
            if !(0xDC00..0xE000).contains(&lo) {
                return err(at, "unpaired surrogate in \\u escape");
            }
            0x10000 + ((hi - 0xD800) << 10) + (lo - 0xDC00)
        } else {
            hi
        };
        char::from_u32(code).map_or_else(|| err(at, "invalid \\u escape"), Ok)
    }
}

/// 1-based line and column (in characters) of a byte offset.
pub(crate) fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let offset = offset.min(text.len());
    let before = &text.as_bytes()[..offset];
    let line = 1 + before.iter().filter(|&&c| c == b'\n').count();
    let line_start = before
        .iter()
        .rposition(|&c| c == b'\n')
        .map_or(0, |p| p + 1);
    let column = 1 + String::from_utf8_lossy(&before[line_start..])
        .chars()
        .count();
    (line, column)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_nested_values_and_escapes() {
        let d = parse(r#" {"a": [1, -2.5e3, true, null], "b": "x\"\u00e9\ud83d\ude00"} "#).unwrap();
        let Value::Object(entries) = &d.values[0] else {
            panic!()
        };
        assert_eq!(entries.len(), 2);
        let Value::Array(items) = &d.values[entries[0].1 as usize] else {
            panic!()
        };
        assert_eq!(d.values[items[1] as usize], Value::Number(-2500.0));
        assert_eq!(
            d.values[entries[1].1 as usize],
            Value::String("x\"é😀".into())
        );
    }

    #[test]
    fn reports_offsets_of_errors() {
        for (text, offset) in [
            ("{\"a\": 1,}", 8),
            ("[1, 2", 5),
            ("{\"a\" 1}", 5),
            ("[01.]", 1),
            ("{\"r\": NaN}", 6),
            ("[1] 2", 4),
            ("", 0),
            ("\"abc", 0),
            ("[1e999]", 1),
        ] {
            let e = parse(text).unwrap_err();
            assert_eq!(e.offset, offset, "{text}: {}", e.message);
        }
    }

    #[test]
    fn duplicate_keys_and_raw_control_characters_are_errors() {
        let e = parse("{\"a\": 1,\n \"b\": {\"a\": 2}, \"a\": 3}").unwrap_err();
        assert_eq!(e.offset, 25, "{}", e.message);
        assert_eq!(e.message, "duplicate key \"a\" in object");
        // Equal after unescaping is equal.
        assert!(parse("{\"ab\": 1, \"a\\u0062\": 2}").is_err());
        // Keys of sibling and nested objects are separate.
        assert!(parse("[{\"a\": 1}, {\"a\": {\"a\": 1}}]").is_ok());
        // A large object (hash-set path): the duplicate is found where it is.
        let mut text = String::from("{");
        for k in 0..1000 {
            text += &format!("\"k{k}\": {{\"k{k}\": 0}}, ");
        }
        assert!(parse(&(text.clone() + "\"z\": 0}")).is_ok());
        let at = text.len();
        let e = parse(&(text + "\"k500\": 0}")).unwrap_err();
        assert_eq!(
            (e.offset, e.message.as_str()),
            (at, "duplicate key \"k500\" in object")
        );
        for raw in ["\u{1b}", "\r", "\0", "\n", "\t"] {
            let e = parse(&format!("{{\"a\": \"x{raw}y\"}}")).unwrap_err();
            assert_eq!(e.offset, 8, "{raw:?}: {}", e.message);
            assert!(e.message.contains("control character"), "{}", e.message);
        }
    }

    #[test]
    fn deep_nesting_does_not_touch_the_call_stack() {
        let n = 200_000;
        let text = "[".repeat(n) + &"]".repeat(n);
        let d = parse(&text).unwrap();
        assert_eq!(d.values.len(), n);
    }

    #[test]
    fn line_and_column_count_characters() {
        assert_eq!(line_column("ab\ncé d", 7), (2, 4));
        assert_eq!(line_column("x", 0), (1, 1));
    }
}
