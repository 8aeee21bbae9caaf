//! Script errors as one line: `file:line:column: message (at: offending source line)`.

use super::Limits;
use rhai::{EvalAltResult, ParseError, ParseErrorType, Position};

/// The token `on_progress` returns when the wall-clock deadline has passed.
pub(super) const TIMEOUT: &str = "time limit";

/// A script that cannot be run to a solid, with the place in it where known.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{file}{}: {message}{}", place(*.line, *.column), excerpt(.source_line))]
pub struct ScriptError {
    /// The script's name (its path).
    pub file: String,
    /// 1-based line, when known.
    pub line: Option<usize>,
    /// 1-based column, when known.
    pub column: Option<usize>,
    /// What went wrong.
    pub message: String,
    /// The offending source line (trimmed), when known.
    pub source_line: Option<String>,
}

fn place(line: Option<usize>, column: Option<usize>) -> String {
    match (line, column) {
        (Some(l), Some(c)) => format!(":{l}:{c}"),
        (Some(l), None) => format!(":{l}"),
        _ => String::new(),
    }
}

fn excerpt(source_line: &Option<String>) -> String {
    source_line
        .as_ref()
        .map(|s| format!(" (at: {s})"))
        .unwrap_or_default()
}

impl ScriptError {
    /// An error without a place.
    pub fn plain(file: &str, message: impl Into<String>) -> ScriptError {
        ScriptError {
            file: file.into(),
            line: None,
            column: None,
            message: message.into(),
            source_line: None,
        }
    }

    fn at(source: &str, file: &str, pos: Position, message: String) -> ScriptError {
        let line = pos.line();
        let source_line = line
            .and_then(|l| source.lines().nth(l - 1))
            .map(|s| s.trim().to_string())
            .filter(|s| !s.is_empty());
        ScriptError {
            file: file.into(),
            line,
            column: pos.position(),
            message,
            source_line,
        }
    }
}

/// A syntax error, or a parse-time limit.
pub(super) fn from_parse(source: &str, file: &str, e: &ParseError, limits: &Limits) -> ScriptError {
    let message = match e.err_type() {
        // `curry` is disabled: the lexer refuses the call form, the parser the method form.
        _ if word_at(source, e.position()) == Some("curry") => {
            "'curry' is not available in solidkit scripts".to_string()
        }
        ParseErrorType::ExprTooDeep => format!(
            "expressions nested too deeply (limit {})",
            limits.max_expr_depth
        ),
        ParseErrorType::Reserved(s) if s == "eval" => {
            "'eval' is not available in solidkit scripts".to_string()
        }
        ParseErrorType::Reserved(s) if s == "import" || s == "export" => {
            format!("'{s}' statements (modules) are not available in solidkit scripts")
        }
        other => format!("syntax error: {other}"),
    };
    ScriptError::at(source, file, e.position(), message)
}

/// The identifier starting at `pos` in `source`, if any.
fn word_at(source: &str, pos: Position) -> Option<&str> {
    let line = source.lines().nth(pos.line()?.checked_sub(1)?)?;
    let start = line.char_indices().nth(pos.position()?.checked_sub(1)?)?.0;
    let rest = &line[start..];
    let end = rest
        .find(|c: char| !(c.is_alphanumeric() || c == '_'))
        .unwrap_or(rest.len());
    (end > 0).then(|| &rest[..end])
}

/// A runtime error: the innermost cause, at its place.
pub(super) fn from_eval(
    source: &str,
    file: &str,
    e: &EvalAltResult,
    limits: &Limits,
) -> ScriptError {
    let inner = e.unwrap_inner();
    let pos = if inner.position().is_none() {
        e.position()
    } else {
        inner.position()
    };
    let message = match inner {
        EvalAltResult::ErrorTerminated(..) => format!(
            "the script ran longer than the {} s time limit",
            limits.max_time.as_secs_f64()
        ),
        EvalAltResult::ErrorTooManyOperations(_) => format!(
            "the script took more than {} operations (infinite loop?)",
            limits.max_operations
        ),
        EvalAltResult::ErrorStackOverflow(_) => format!(
            "function calls nested deeper than {} (infinite recursion?)",
            limits.max_call_levels
        ),
        EvalAltResult::ErrorDataTooLarge(what, _) => {
            let limit = match what.as_str() {
                s if s.contains("string") || s.contains("String") => limits.max_string_size,
                s if s.contains("rray") => limits.max_array_size,
                s if s.contains("ap") => limits.max_map_size,
                _ => 0,
            };
            format!("{what} grew beyond the limit ({limit})")
        }
        EvalAltResult::ErrorRuntime(v, _) => v.to_string(),
        other => {
            // Rhai appends ` (line L, position C)`: the place is shown in front instead.
            let text = other.to_string();
            match text.rfind(" (line ") {
                Some(i) => text[..i].to_string(),
                None => text,
            }
        }
    };
    ScriptError::at(source, file, pos, message)
}
