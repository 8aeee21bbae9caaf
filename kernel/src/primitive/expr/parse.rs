//! Formula text → postfix code, by the shunting-yard algorithm (a loop over tokens with an
//! operator stack: no recursion, however deeply the formula nests), folding constants on the way.
//!
//! Grammar: numbers (`2`, `0.5`, `1e-3`), `x`, `y`, `z`, `pi`, `e`; binary `+ - * /` and `^`
//! (power, right-associative, binding tighter than unary minus: `-x^2` is `-(x^2)`); unary `-`
//! and `+`; parentheses; the functions `sin cos exp log sqrt abs` (one argument) and `min max
//! pow` (two). An exponent (`^` or `pow`'s second argument) must be a constant.

use super::code::Op;

/// Longest formula accepted, in bytes.
pub const MAX_LENGTH: usize = 10_000;

/// A formula that does not parse: where (1-based character column) and why.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("column {column}: {message}")]
pub struct ParseError {
    /// 1-based character column of the offending token (0: the whole formula).
    pub column: usize,
    /// What is wrong.
    pub message: String,
}

fn fail<T>(column: usize, message: impl Into<String>) -> Result<T, ParseError> {
    Err(ParseError {
        column,
        message: message.into(),
    })
}

#[derive(Debug, Clone, PartialEq)]
enum Token {
    Num(f64),
    Name(String),
    Sym(char),
}

/// Splits the formula into tokens with their 1-based columns.
fn tokens(text: &str) -> Result<Vec<(Token, usize)>, ParseError> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let column = i + 1;
        if c.is_whitespace() {
            i += 1;
        } else if c.is_ascii_digit() || c == '.' {
            let start = i;
            while i < chars.len() && (chars[i].is_ascii_digit() || chars[i] == '.') {
                i += 1;
            }
            // An exponent: e or E, an optional sign, digits.
            if i < chars.len() && (chars[i] == 'e' || chars[i] == 'E') {
                let mut j = i + 1;
                if j < chars.len() && (chars[j] == '+' || chars[j] == '-') {
                    j += 1;
                }
                if j < chars.len() && chars[j].is_ascii_digit() {
                    while j < chars.len() && chars[j].is_ascii_digit() {
                        j += 1;
                    }
                    i = j;
                }
            }
            let s: String = chars[start..i].iter().collect();
            match s.parse::<f64>() {
                Ok(v) if v.is_finite() => out.push((Token::Num(v), column)),
                _ => return fail(column, format!("'{s}' is not a finite number")),
            }
        } else if c.is_ascii_alphabetic() || c == '_' {
            let start = i;
            while i < chars.len() && (chars[i].is_ascii_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            out.push((Token::Name(chars[start..i].iter().collect()), column));
        } else if "+-*/^(),".contains(c) {
            out.push((Token::Sym(c), column));
            i += 1;
        } else {
            return fail(column, format!("unexpected character {c:?}"));
        }
    }
    Ok(out)
}

/// An entry of the operator stack.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Pending {
    /// A binary operator.
    Binary(char, usize),
    /// Unary minus.
    Neg,
    /// An opening parenthesis; `Some` for a function call (its function, its column).
    Open(Option<(Func, usize)>),
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum Func {
    Unary(Op),
    Min,
    Max,
    Pow,
}

fn function(name: &str) -> Option<Func> {
    Some(match name {
        "sin" => Func::Unary(Op::Sin),
        "cos" => Func::Unary(Op::Cos),
        "exp" => Func::Unary(Op::Exp),
        "log" => Func::Unary(Op::Log),
        "sqrt" => Func::Unary(Op::Sqrt),
        "abs" => Func::Unary(Op::Abs),
        "min" => Func::Min,
        "max" => Func::Max,
        "pow" => Func::Pow,
        _ => return None,
    })
}

fn precedence(op: char) -> u8 {
    match op {
        '+' | '-' => 1,
        '*' | '/' => 2,
        _ => 4, // '^'; unary minus is 3
    }
}

/// The postfix code being built, with constant folding: a constant operand is always exactly
/// one `Const` at the end of the code, so folding pops it.
struct Emitter {
    code: Vec<Op>,
    /// Per operand on the evaluation stack: its constant value, if it is one.
    operands: Vec<Option<f64>>,
}

impl Emitter {
    fn push(&mut self, op: Op) {
        self.operands.push(match op {
            Op::Const(c) => Some(c),
            _ => None,
        });
        self.code.push(op);
    }

    fn unary(&mut self, op: Op, column: usize) -> Result<(), ParseError> {
        let Some(a) = self.operands.pop() else {
            return fail(column, "missing operand");
        };
        if let Some(a) = a {
            self.code.pop();
            self.push(Op::Const(op.apply1(a)));
            return Ok(());
        }
        self.code.push(op);
        self.operands.push(None);
        Ok(())
    }

    fn binary(&mut self, op: Op, column: usize) -> Result<(), ParseError> {
        let (Some(b), Some(a)) = (self.operands.pop(), self.operands.pop()) else {
            return fail(column, "missing operand");
        };
        if matches!(op, Op::Pow) {
            let Some(n) = b else {
                return fail(column, "the exponent must be a constant");
            };
            self.code.pop();
            let pow = if n.fract() == 0.0 && n.abs() <= 64.0 {
                Op::Powi(n as i32)
            } else {
                Op::Powf(n)
            };
            self.operands.push(a);
            return self.unary(pow, column);
        }
        if let (Some(a), Some(b)) = (a, b) {
            self.code.truncate(self.code.len() - 2);
            self.push(Op::Const(op.apply2(a, b)));
            return Ok(());
        }
        self.code.push(op);
        self.operands.push(None);
        Ok(())
    }

    fn pending(&mut self, p: Pending) -> Result<(), ParseError> {
        match p {
            Pending::Binary(c, column) => self.binary(
                match c {
                    '+' => Op::Add,
                    '-' => Op::Sub,
                    '*' => Op::Mul,
                    '/' => Op::Div,
                    _ => Op::Pow,
                },
                column,
            ),
            Pending::Neg => self.unary(Op::Neg, 0),
            Pending::Open(_) => fail(0, "unbalanced parenthesis"),
        }
    }
}

/// Parses `text` into postfix code that leaves one value on the stack.
pub fn parse(text: &str) -> Result<Vec<Op>, ParseError> {
    parse_in(text, ["x", "y", "z"])
}

/// Parses `text` with the three variable slots named `names` (e.g. `["u", "v", "w"]` for a formula
/// curve or surface: `u` is then read from the first coordinate). An empty name is no variable.
pub fn parse_in(text: &str, names: [&str; 3]) -> Result<Vec<Op>, ParseError> {
    if text.len() > MAX_LENGTH {
        return fail(0, format!("longer than {MAX_LENGTH} bytes"));
    }
    let mut out = Emitter {
        code: Vec::new(),
        operands: Vec::new(),
    };
    let mut stack: Vec<Pending> = Vec::new();
    // Arguments seen so far by each open function call.
    let mut args: Vec<usize> = Vec::new();
    let mut expect_operand = true;
    let toks = tokens(text)?;
    let mut k = 0;
    while k < toks.len() {
        let (tok, column) = (&toks[k].0, toks[k].1);
        match tok {
            Token::Num(v) if expect_operand => {
                out.push(Op::Const(*v));
                expect_operand = false;
            }
            Token::Name(name) if expect_operand => {
                let slot = names.iter().position(|v| !v.is_empty() && v == name);
                let op = match (slot, name.as_str()) {
                    (Some(0), _) => Some(Op::X),
                    (Some(1), _) => Some(Op::Y),
                    (Some(_), _) => Some(Op::Z),
                    (None, "pi") => Some(Op::Const(std::f64::consts::PI)),
                    (None, "e") => Some(Op::Const(std::f64::consts::E)),
                    _ => None,
                };
                if let Some(op) = op {
                    out.push(op);
                    expect_operand = false;
                } else if let Some(f) = function(name) {
                    if toks.get(k + 1).map(|t| &t.0) != Some(&Token::Sym('(')) {
                        return fail(column, format!("'{name}' must be followed by '('"));
                    }
                    stack.push(Pending::Open(Some((f, column))));
                    args.push(1);
                    k += 1; // the '('
                } else {
                    let vars: Vec<&str> = names.into_iter().filter(|v| !v.is_empty()).collect();
                    return fail(
                        column,
                        format!(
                            "unknown name '{name}' (variables {}; constants pi, e; \
                             functions sin, cos, exp, log, sqrt, abs, min, max, pow)",
                            vars.join(", ")
                        ),
                    );
                }
            }
            Token::Sym('(') if expect_operand => stack.push(Pending::Open(None)),
            Token::Sym('-') if expect_operand => stack.push(Pending::Neg),
            Token::Sym('+') if expect_operand => {}
            Token::Sym(c @ ('+' | '-' | '*' | '/' | '^')) if !expect_operand => {
                let p = precedence(*c);
                while let Some(&top) = stack.last() {
                    let pops = match top {
                        Pending::Binary(t, _) => {
                            let q = precedence(t);
                            q > p || (q == p && *c != '^')
                        }
                        Pending::Neg => p < 3,
                        Pending::Open(_) => false,
                    };
                    if !pops {
                        break;
                    }
                    stack.pop();
                    out.pending(top)?;
                }
                stack.push(Pending::Binary(*c, column));
                expect_operand = true;
            }
            Token::Sym(c @ (')' | ',')) if !expect_operand => {
                let open = loop {
                    match stack.pop() {
                        Some(Pending::Open(f)) => break f,
                        Some(p) => out.pending(p)?,
                        None => return fail(column, format!("'{c}' without a matching '('")),
                    }
                };
                if *c == ',' {
                    let Some((f, at)) = open else {
                        return fail(column, "',' outside a function call");
                    };
                    if let Some(n) = args.last_mut() {
                        *n += 1;
                    }
                    stack.push(Pending::Open(Some((f, at))));
                    expect_operand = true;
                } else if let Some((f, at)) = open {
                    let n = args.pop().unwrap_or(0);
                    let wanted = if matches!(f, Func::Unary(_)) { 1 } else { 2 };
                    if n != wanted {
                        return fail(at, format!("expected {wanted} argument(s), found {n}"));
                    }
                    match f {
                        Func::Unary(op) => out.unary(op, at)?,
                        Func::Min => out.binary(Op::Min, at)?,
                        Func::Max => out.binary(Op::Max, at)?,
                        Func::Pow => out.binary(Op::Pow, at)?,
                    }
                }
            }
            Token::Sym(')')
                if expect_operand && matches!(stack.last(), Some(Pending::Open(Some(_)))) =>
            {
                return fail(column, "a function call needs its arguments");
            }
            _ => {
                let what = match tok {
                    Token::Num(v) => format!("number {v}"),
                    Token::Name(n) => format!("'{n}'"),
                    Token::Sym(c) => format!("'{c}'"),
                };
                let wanted = if expect_operand {
                    "an operand"
                } else {
                    "an operator"
                };
                return fail(column, format!("expected {wanted}, found {what}"));
            }
        }
        k += 1;
    }
    if expect_operand {
        return fail(
            text.chars().count() + 1,
            "the formula ends where an operand is expected",
        );
    }
    while let Some(p) = stack.pop() {
        if let Pending::Open(_) = p {
            return fail(0, "unclosed '('");
        }
        out.pending(p)?;
    }
    if out.operands.len() != 1 {
        return fail(0, "not a single expression");
    }
    Ok(out.code)
}
