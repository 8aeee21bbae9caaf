//! A small XML tag scanner for 3MF model parts and package relationships: start, empty and end
//! tags with their attributes and line numbers, in document order.
//!
//! It is not a validating parser: text between tags is skipped, comments, CDATA sections and
//! processing instructions are passed over, and a document type declaration is refused (3MF
//! forbids DTDs, and refusing them rules out entity-expansion bombs). Only the five predefined
//! entities and numeric character references are decoded in attribute values. It never
//! recurses and never panics: every problem is an [`XmlError`] with its 1-based line.

use std::borrow::Cow;

/// A problem and its line.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) struct XmlError {
    /// 1-based line of the problem.
    pub line: usize,
    /// What is wrong.
    pub message: String,
}

/// A tag of the document.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) enum Tag<'a> {
    /// `<name attrs>` or `<name attrs/>` (`empty`).
    Start {
        /// The element name as written (with its prefix, if any).
        name: &'a str,
        /// The text of the attributes; read them with [`attributes`].
        attrs: &'a str,
        /// Whether the tag closes itself.
        empty: bool,
    },
    /// `</name>`.
    End {
        /// The element name as written.
        name: &'a str,
    },
}

/// The tags of a document, each with its line.
pub(super) struct Scanner<'a> {
    text: &'a str,
    pos: usize,
    line: usize,
    counted: usize,
}

impl<'a> Scanner<'a> {
    /// A scanner at the start of `text`.
    pub(super) fn new(text: &'a str) -> Self {
        Self {
            text,
            pos: 0,
            line: 1,
            counted: 0,
        }
    }

    /// The line of byte `at` (at or after the last position asked for).
    fn line_at(&mut self, at: usize) -> usize {
        let at = at.min(self.text.len());
        if at > self.counted {
            self.line += self.text.as_bytes()[self.counted..at]
                .iter()
                .filter(|&&b| b == b'\n')
                .count();
            self.counted = at;
        }
        self.line
    }

    fn error(&mut self, at: usize, message: &str) -> XmlError {
        XmlError {
            line: self.line_at(at),
            message: message.to_string(),
        }
    }

    /// The next tag and its line, `None` at the end of the document.
    pub(super) fn next_tag(&mut self) -> Result<Option<(Tag<'a>, usize)>, XmlError> {
        loop {
            let Some(offset) = self.text[self.pos..].find('<') else {
                self.pos = self.text.len();
                return Ok(None);
            };
            let start = self.pos + offset;
            let rest = &self.text[start..];
            let markup = matches!(rest.as_bytes().get(1), Some(b'!' | b'?'));
            let skip = [("<!--", "-->"), ("<![CDATA[", "]]>"), ("<?", "?>")]
                .into_iter()
                .find(|(open, _)| markup && rest.starts_with(open));
            if let Some((open, close)) = skip {
                let Some(end) = rest[open.len()..].find(close) else {
                    return Err(self.error(start, &format!("unterminated {open}")));
                };
                self.pos = start + open.len() + end + close.len();
                continue;
            }
            if rest.starts_with("<!") {
                return Err(self.error(start, "document type declarations are not allowed"));
            }
            let end = tag_end(rest).ok_or_else(|| self.error(start, "unterminated tag"))?;
            self.pos = start + end + 1;
            let line = self.line_at(start);
            let inner = &rest[1..end];
            let tag = if let Some(name) = inner.strip_prefix('/') {
                Tag::End { name: name.trim() }
            } else {
                let (inner, empty) = match inner.strip_suffix('/') {
                    Some(i) => (i, true),
                    None => (inner, false),
                };
                let split = inner
                    .find(|c: char| c.is_ascii_whitespace())
                    .unwrap_or(inner.len());
                Tag::Start {
                    name: &inner[..split],
                    attrs: &inner[split..],
                    empty,
                }
            };
            return Ok(Some((tag, line)));
        }
    }
}

/// The index of the `>` closing the tag that starts `rest`, outside quoted values.
fn tag_end(rest: &str) -> Option<usize> {
    let mut quote = None;
    for (i, b) in rest.bytes().enumerate().skip(1) {
        match (quote, b) {
            (None, b'>') => return Some(i),
            (None, b'"' | b'\'') => quote = Some(b),
            (Some(q), b) if q == b => quote = None,
            _ => {}
        }
    }
    None
}

/// The attributes of a start tag as `(name, value)`, values with their references decoded; an
/// error message for malformed text.
pub(super) fn attributes(attrs: &str) -> Result<Vec<(&str, Cow<'_, str>)>, String> {
    let mut out = Vec::new();
    let mut rest = attrs.trim_start();
    while !rest.is_empty() {
        let eq = rest
            .find('=')
            .ok_or_else(|| format!("attribute without a value near '{}'", short(rest)))?;
        let name = rest[..eq].trim();
        let after = rest[eq + 1..].trim_start();
        let quote = after
            .chars()
            .next()
            .filter(|&c| c == '"' || c == '\'')
            .ok_or_else(|| format!("attribute {name}: value not quoted"))?;
        let close = after[1..]
            .find(quote)
            .ok_or_else(|| format!("attribute {name}: unterminated value"))?;
        let value = decode(&after[1..1 + close]).map_err(|e| format!("attribute {name}: {e}"))?;
        out.push((name, value));
        rest = after[close + 2..].trim_start();
    }
    Ok(out)
}

/// The value of attribute `key` (unprefixed), if present.
pub(super) fn attribute<'a>(attrs: &'a [(&'a str, Cow<'a, str>)], key: &str) -> Option<&'a str> {
    attrs.iter().find(|(k, _)| *k == key).map(|(_, v)| &**v)
}

/// At most 20 characters of `s`, for messages about markup (never about file content at large).
fn short(s: &str) -> String {
    s.chars().take(20).collect()
}

/// `text` with `&amp;`, `&lt;`, `&gt;`, `&quot;`, `&apos;` and `&#N;`/`&#xN;` decoded.
fn decode(text: &str) -> Result<Cow<'_, str>, String> {
    if !text.contains('&') {
        return Ok(Cow::Borrowed(text));
    }
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(amp) = rest.find('&') {
        out.push_str(&rest[..amp]);
        let semi = rest[amp..]
            .find(';')
            .ok_or_else(|| "unterminated character reference".to_string())?;
        let name = &rest[amp + 1..amp + semi];
        let c = match name {
            "amp" => Some('&'),
            "lt" => Some('<'),
            "gt" => Some('>'),
            "quot" => Some('"'),
            "apos" => Some('\''),
            _ => match name.strip_prefix("#x").or_else(|| name.strip_prefix("#X")) {
                Some(hex) => u32::from_str_radix(hex, 16).ok().and_then(char::from_u32),
                None => name
                    .strip_prefix('#')
                    .and_then(|d| d.parse().ok())
                    .and_then(char::from_u32),
            },
        };
        out.push(c.ok_or_else(|| format!("unknown reference &{};", short(name)))?);
        rest = &rest[amp + semi + 1..];
    }
    out.push_str(rest);
    Ok(Cow::Owned(out))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tags(text: &str) -> Result<Vec<(Tag<'_>, usize)>, XmlError> {
        let mut s = Scanner::new(text);
        let mut out = Vec::new();
        while let Some(t) = s.next_tag()? {
            out.push(t);
        }
        Ok(out)
    }

    #[test]
    fn scans_tags_lines_and_attributes() {
        let text = "<?xml version=\"1.0\"?>\n<!-- a > b -->\n<a x='1 > 2'>\n <b y=\"&lt;&#65;&#x42;\"/>\n</a>";
        let t = tags(text).unwrap();
        assert_eq!(t.len(), 3);
        let (Tag::Start { name, attrs, empty }, 3) = &t[0] else {
            panic!("{t:?}")
        };
        assert_eq!((*name, *empty), ("a", false));
        assert_eq!(attributes(attrs).unwrap()[0].1, "1 > 2");
        let (Tag::Start { attrs, empty, .. }, 4) = &t[1] else {
            panic!("{t:?}")
        };
        assert!(*empty);
        let a = attributes(attrs).unwrap();
        assert_eq!(attribute(&a, "y"), Some("<AB"));
        assert_eq!(t[2], (Tag::End { name: "a" }, 5));
    }

    #[test]
    fn malformed_input_is_an_error_with_its_line() {
        assert_eq!(tags("\n\n<a x='1'").unwrap_err().line, 3);
        assert!(tags("<!DOCTYPE x [<!ENTITY a 'b'>]><x/>").is_err());
        assert!(tags("<!-- never closed").is_err());
        assert!(attributes(" x=1").is_err());
        assert!(attributes(" x='&bogus;'").is_err());
        assert!(attributes(" x='1").is_err());
        assert!(attributes(" x").is_err());
    }
}
