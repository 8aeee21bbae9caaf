//! Parser of `.csg` statements into an arena tree, with explicit stacks: module nesting of any
//! depth is parsed (and later dropped) without recursion; vector literals nest at most
//! [`MAX_VECTOR_DEPTH`] deep.

use super::error::{CsgError, Pos};
use super::lexer::{Tok, Token, tokenize};

/// Deepest nesting of vector literals accepted.
pub const MAX_VECTOR_DEPTH: usize = 64;

/// An argument value.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// `undef`.
    Undef,
    /// `true` / `false`.
    Bool(bool),
    /// A number.
    Num(f64),
    /// A string.
    Str(String),
    /// A vector `[a, b, …]`.
    Vector(Vec<Value>),
}

/// One argument of a module instantiation.
#[derive(Debug, Clone, PartialEq)]
pub struct Arg {
    /// The name for `name = value`, `None` when positional.
    pub name: Option<String>,
    /// The value.
    pub value: Value,
    /// Where the argument starts.
    pub pos: Pos,
}

/// The modifier characters OpenSCAD writes before a statement (`%cube(1);`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Modifiers {
    /// `%`: background, drawn transparently, not part of the geometry.
    pub background: bool,
    /// `#`: highlighted, still part of the geometry.
    pub highlight: bool,
    /// `!`: root; only this subtree is the model.
    pub root: bool,
    /// `*`: disabled, not part of the geometry.
    pub disable: bool,
}

impl Modifiers {
    /// Whether the statement is left out of the geometry (`%` or `*`).
    pub fn dropped(&self) -> bool {
        self.background || self.disable
    }
}

/// A module instantiation `name(args) { children }` (or `name(args);`).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Stmt {
    /// The module's name.
    pub name: String,
    /// Where the name starts.
    pub pos: Pos,
    /// The arguments in order.
    pub args: Vec<Arg>,
    /// Indices of the children in [`Tree::nodes`].
    pub children: Vec<usize>,
    /// The modifiers written before the name.
    pub modifiers: Modifiers,
}

/// The statements of a file: an arena and the top-level statements.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Tree {
    /// Every statement; children follow their parent.
    pub nodes: Vec<Stmt>,
    /// The top-level statements.
    pub roots: Vec<usize>,
}

/// An open block: the statement whose children are being read, and whether it has braces
/// (otherwise it takes exactly one child statement).
struct Frame {
    parent: Option<usize>,
    braced: bool,
    pos: Pos,
}

/// Parses `.csg` text.
pub fn parse(text: &str) -> Result<Tree, CsgError> {
    let tokens = tokenize(text)?;
    Parser {
        tokens,
        at: 0,
        end: end_pos(text),
    }
    .statements()
}

/// The position just after the text (for errors at the end of the file).
fn end_pos(text: &str) -> Pos {
    let line = text.lines().count().max(1) as u32 + u32::from(text.ends_with('\n'));
    let col = if text.ends_with('\n') {
        1
    } else {
        text.lines().last().map_or(0, |l| l.chars().count()) as u32 + 1
    };
    Pos { line, col }
}

struct Parser {
    tokens: Vec<Token>,
    at: usize,
    end: Pos,
}

impl Parser {
    fn peek(&self) -> Option<&Token> {
        self.tokens.get(self.at)
    }

    fn pos(&self) -> Pos {
        self.peek().map_or(self.end, |t| t.pos)
    }

    fn next(&mut self) -> Result<Token, CsgError> {
        let t = self
            .tokens
            .get(self.at)
            .cloned()
            .ok_or_else(|| CsgError::syntax(self.end, "unexpected end of file"))?;
        self.at += 1;
        Ok(t)
    }

    fn is_punct(&self, c: char) -> bool {
        matches!(self.peek(), Some(Token { tok: Tok::Punct(p), .. }) if *p == c)
    }

    fn expect(&mut self, c: char) -> Result<(), CsgError> {
        let t = self.next()?;
        if t.tok == Tok::Punct(c) {
            Ok(())
        } else {
            Err(CsgError::syntax(
                t.pos,
                format!("expected '{c}', found {}", describe(&t.tok)),
            ))
        }
    }

    fn statements(mut self) -> Result<Tree, CsgError> {
        let mut tree = Tree::default();
        let mut modifiers = Modifiers::default();
        let mut frames = vec![Frame {
            parent: None,
            braced: true,
            pos: Pos { line: 1, col: 1 },
        }];
        loop {
            let Some(token) = self.peek().cloned() else {
                let top = frames.last().expect("root frame");
                if top.parent.is_some() {
                    return Err(CsgError::syntax(
                        self.end,
                        format!(
                            "unexpected end of file: the block opened at {} is not closed",
                            top.pos
                        ),
                    ));
                }
                return Ok(tree);
            };
            let completed = match token.tok {
                Tok::Punct('}') => {
                    let top = frames.last().expect("root frame");
                    if top.parent.is_none() || !top.braced {
                        return Err(CsgError::syntax(token.pos, "unexpected '}'"));
                    }
                    self.at += 1;
                    frames.pop();
                    true
                }
                Tok::Punct(m @ ('%' | '#' | '!' | '*')) => {
                    self.at += 1;
                    let flag = match m {
                        '%' => &mut modifiers.background,
                        '#' => &mut modifiers.highlight,
                        '!' => &mut modifiers.root,
                        _ => &mut modifiers.disable,
                    };
                    *flag = true;
                    if !matches!(
                        self.peek(),
                        Some(Token {
                            tok: Tok::Ident(_),
                            ..
                        }) | Some(Token {
                            tok: Tok::Punct('%' | '#' | '!' | '*'),
                            ..
                        })
                    ) {
                        return Err(CsgError::syntax(
                            token.pos,
                            format!("expected a module name after the modifier '{m}'"),
                        ));
                    }
                    false
                }
                Tok::Punct(';') if frames.last().is_some_and(|f| f.braced) => {
                    self.at += 1;
                    false
                }
                Tok::Ident(name) => {
                    self.at += 1;
                    let args = self.arguments()?;
                    let index = tree.nodes.len();
                    tree.nodes.push(Stmt {
                        name,
                        pos: token.pos,
                        args,
                        children: Vec::new(),
                        modifiers: std::mem::take(&mut modifiers),
                    });
                    match frames.last().expect("root frame").parent {
                        Some(p) => tree.nodes[p].children.push(index),
                        None => tree.roots.push(index),
                    }
                    if self.is_punct(';') {
                        self.at += 1;
                        true
                    } else {
                        let braced = self.is_punct('{');
                        if braced {
                            self.at += 1;
                        }
                        frames.push(Frame {
                            parent: Some(index),
                            braced,
                            pos: token.pos,
                        });
                        false
                    }
                }
                other => {
                    return Err(CsgError::syntax(
                        token.pos,
                        format!("expected a module name, found {}", describe(&other)),
                    ));
                }
            };
            if completed {
                while frames.last().is_some_and(|f| !f.braced) {
                    frames.pop();
                }
            }
        }
    }

    /// `( [name =] value, … )`.
    fn arguments(&mut self) -> Result<Vec<Arg>, CsgError> {
        self.expect('(')?;
        let mut args = Vec::new();
        loop {
            if self.is_punct(')') {
                self.at += 1;
                return Ok(args);
            }
            let pos = self.pos();
            let named = match (self.peek(), self.tokens.get(self.at + 1)) {
                (
                    Some(Token {
                        tok: Tok::Ident(n), ..
                    }),
                    Some(Token {
                        tok: Tok::Punct('='),
                        ..
                    }),
                ) => Some(n.clone()),
                _ => None,
            };
            if named.is_some() {
                self.at += 2;
            }
            let value = self.value()?;
            args.push(Arg {
                name: named,
                value,
                pos,
            });
            if self.is_punct(',') {
                self.at += 1;
            } else if !self.is_punct(')') {
                let t = self.next()?;
                return Err(CsgError::syntax(
                    t.pos,
                    format!("expected ',' or ')', found {}", describe(&t.tok)),
                ));
            }
        }
    }

    /// A value: number (optionally signed), string, `true`, `false`, `undef`, or a vector, nested
    /// through an explicit stack of open vectors.
    fn value(&mut self) -> Result<Value, CsgError> {
        let mut open: Vec<Vec<Value>> = Vec::new();
        loop {
            let t = self.next()?;
            let mut v = match t.tok {
                Tok::Punct('[') => {
                    if open.len() >= MAX_VECTOR_DEPTH {
                        return Err(CsgError::syntax(
                            t.pos,
                            format!("vectors nested deeper than {MAX_VECTOR_DEPTH}"),
                        ));
                    }
                    if self.is_punct(']') {
                        self.at += 1;
                        Value::Vector(Vec::new())
                    } else {
                        open.push(Vec::new());
                        continue;
                    }
                }
                Tok::Punct(sign @ ('-' | '+')) => match self.next()? {
                    Token {
                        tok: Tok::Num(n), ..
                    } => Value::Num(if sign == '-' { -n } else { n }),
                    Token {
                        tok: Tok::Ident(ref id),
                        ..
                    } if special_number(id).is_some() => {
                        let n = special_number(id).expect("checked");
                        Value::Num(if sign == '-' { -n } else { n })
                    }
                    other => {
                        return Err(CsgError::syntax(
                            other.pos,
                            format!(
                                "expected a number after '{sign}', found {}",
                                describe(&other.tok)
                            ),
                        ));
                    }
                },
                Tok::Num(n) => Value::Num(n),
                Tok::Str(s) => Value::Str(s),
                Tok::Ident(ref id) if id == "true" => Value::Bool(true),
                Tok::Ident(ref id) if id == "false" => Value::Bool(false),
                Tok::Ident(ref id) if id == "undef" => Value::Undef,
                Tok::Ident(ref id) if special_number(id).is_some() => {
                    Value::Num(special_number(id).expect("checked"))
                }
                other => {
                    return Err(CsgError::syntax(
                        t.pos,
                        format!("expected a value, found {}", describe(&other)),
                    ));
                }
            };
            // Close the vectors this value ends.
            loop {
                let Some(top) = open.last_mut() else {
                    return Ok(v);
                };
                top.push(v);
                let t = self.next()?;
                match t.tok {
                    Tok::Punct(',') if !self.is_punct(']') => break,
                    Tok::Punct(',') => {
                        self.at += 1;
                        v = Value::Vector(open.pop().expect("open vector"));
                    }
                    Tok::Punct(']') => v = Value::Vector(open.pop().expect("open vector")),
                    other => {
                        return Err(CsgError::syntax(
                            t.pos,
                            format!(
                                "expected ',' or ']' in a vector, found {}",
                                describe(&other)
                            ),
                        ));
                    }
                }
            }
        }
    }
}

/// The numbers OpenSCAD writes as words: `inf` and `nan` (its exports also write `-inf`, `-nan`).
fn special_number(id: &str) -> Option<f64> {
    match id {
        "inf" => Some(f64::INFINITY),
        "nan" => Some(f64::NAN),
        _ => None,
    }
}

/// A token for messages.
fn describe(tok: &Tok) -> String {
    match tok {
        Tok::Ident(s) => format!("'{s}'"),
        Tok::Num(n) => format!("number {n}"),
        Tok::Str(s) => format!("string {s:?}"),
        Tok::Punct(c) => format!("'{c}'"),
    }
}
