//! `-D NAME=VALUE` for Rhai scripts: each definition becomes the constant `NAME` in the script's
//! scope before it runs. `VALUE` is a Rhai literal: a number (`10`, `2.5`, `-1e3`), a string in
//! double quotes, `true`/`false`, an array (`[1, 2.5, "a"]`) or an object map (`#{a: 1}`),
//! nested (operators on literals are evaluated); anything else (a variable, a function call) is
//! refused.

use super::Limits;
use super::error::ScriptError;
use ::rhai::{Dynamic, Engine, Scope};

/// The scope holding the constants of `defines` (`NAME=VALUE` each), for the script `file`.
pub(super) fn scope(
    defines: &[String],
    file: &str,
    limits: &Limits,
) -> Result<Scope<'static>, ScriptError> {
    // A bare engine: no functions or operators, so only literals evaluate.
    let mut engine = Engine::new_raw();
    engine.set_max_string_size(limits.max_string_size);
    engine.set_max_array_size(limits.max_array_size);
    engine.set_max_map_size(limits.max_map_size);
    engine.set_max_expr_depths(limits.max_expr_depth, limits.max_expr_depth);
    engine.set_max_operations(limits.max_operations);
    let mut scope = Scope::new();
    for define in defines {
        let (name, value) = parse(define, &engine)
            .map_err(|why| ScriptError::plain(file, format!("-D {define}: {why}")))?;
        scope.push_constant_dynamic(name, value);
    }
    Ok(scope)
}

/// `NAME` and the value of one `NAME=VALUE`, or why not.
fn parse(define: &str, engine: &Engine) -> Result<(String, Dynamic), String> {
    let Some((name, value)) = define.split_once('=') else {
        return Err("expected NAME=VALUE".into());
    };
    let name = name.trim();
    if !is_identifier(name) {
        return Err(format!(
            "'{name}' is not a variable name (a letter or '_', then letters, digits or '_')"
        ));
    }
    let value = value.trim();
    if value.is_empty() {
        return Err("no value after '='".into());
    }
    let parsed = engine.eval_expression::<Dynamic>(value).map_err(|e| {
        format!(
            "the value is not a Rhai literal (a number, a \"string\", true or false, \
             an [array] or a #{{map}}): {e}"
        )
    })?;
    if parsed.is_unit() {
        return Err("the value is not a Rhai literal: () is not a value".into());
    }
    Ok((name.to_string(), parsed))
}

/// A name Rhai reads as a variable: ASCII letter or `_` first, then letters, digits or `_`, and
/// not only underscores.
fn is_identifier(name: &str) -> bool {
    let mut chars = name.chars();
    matches!(chars.next(), Some(c) if c.is_ascii_alphabetic() || c == '_')
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
        && name.chars().any(|c| c != '_')
}

#[cfg(test)]
mod tests {
    use super::*;

    fn one(define: &str) -> Result<Dynamic, String> {
        scope(&[define.to_string()], "t.rhai", &Limits::default())
            .map(|s| {
                s.get_value::<Dynamic>(define.split('=').next().unwrap().trim())
                    .unwrap()
            })
            .map_err(|e| e.to_string())
    }

    #[test]
    fn literals_of_each_kind() {
        assert_eq!(one("n=10").unwrap().as_int(), Ok(10));
        assert_eq!(one("x = -2.5").unwrap().as_float(), Ok(-2.5));
        assert_eq!(
            one("s=\"hi there\"").unwrap().into_string().unwrap(),
            "hi there"
        );
        assert_eq!(one("b=true").unwrap().as_bool(), Ok(true));
        let a = one("a=[1, 2.5, [\"x\"]]").unwrap().into_array().unwrap();
        assert_eq!(a.len(), 3);
        assert_eq!(a[1].as_float(), Ok(2.5));
        let m = one("m=#{w: 3}").unwrap();
        assert!(m.is_map());
    }

    #[test]
    fn names_and_values_are_checked() {
        for (bad, why) in [
            ("size", "expected NAME=VALUE"),
            ("=3", "is not a variable name"),
            ("2x=3", "is not a variable name"),
            ("a-b=3", "is not a variable name"),
            ("x=", "no value"),
            ("x=y", "not a Rhai literal"),
            ("x=sphere(1.0)", "not a Rhai literal"),
            ("x=()", "not a Rhai literal"),
        ] {
            let e = one(bad).unwrap_err();
            assert!(e.starts_with(&format!("t.rhai: -D {bad}: ")), "{e}");
            assert!(e.contains(why), "{bad}: {e}");
        }
    }
}
