//! Tokenizer and Pratt parser for Adams function expressions.
//!
//! Grammar (case-insensitive): numbers in Fortran style (`1.0E+005`, `.5`) with an optional `D`
//! suffix meaning degrees (`30.0d` = 30·π/180); the names `TIME`, `PI`, `DTOR` (π/180) and `RTOD`
//! (180/π); `+ - * /`, `**` or `^` for powers (right-associative, tighter than unary minus);
//! parentheses; calls of the functions in [`FUNCTIONS`](super::ast::FUNCTIONS). A name that is
//! not a known function is an error naming it.

use super::ast::{BinOp, Callee, Expr, FUNCTIONS, MathFn};
use thiserror::Error;

/// The deepest expression tree accepted (parentheses, calls and operator chains each add a
/// level). Evaluation recurses over the tree, so this bounds its stack use.
pub const MAX_DEPTH: usize = 500;

/// Why an expression does not parse; `offset` is the character index in the source text.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("{kind}")]
pub struct ExprError {
    /// Character index of the problem in the expression text.
    pub offset: usize,
    /// What is wrong.
    pub kind: ExprErrorKind,
}

/// What is wrong with an expression.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ExprErrorKind {
    /// A character that cannot start a token.
    #[error("unexpected character '{0}' in expression")]
    UnexpectedChar(char),
    /// The expression ends where more was expected.
    #[error("expression ends early: expected {0}")]
    UnexpectedEnd(&'static str),
    /// A token where another was expected.
    #[error("expected {expected}, found '{found}'")]
    Expected {
        /// What was expected.
        expected: &'static str,
        /// What was found.
        found: String,
    },
    /// A number that does not read.
    #[error("bad number '{0}'")]
    BadNumber(String),
    /// A call of a function the product does not support.
    #[error("unsupported function {0}")]
    UnknownFunction(String),
    /// A name that is neither a constant nor a function call.
    #[error("unknown name {0} (known: TIME, PI, DTOR, RTOD)")]
    UnknownName(String),
    /// A call with the wrong number of arguments.
    #[error("{function} takes {min}..={max} arguments, {given} given")]
    Arity {
        /// The function.
        function: &'static str,
        /// Fewest arguments.
        min: usize,
        /// Most arguments.
        max: usize,
        /// Arguments given.
        given: usize,
    },
    /// An argument that must be an integer id (marker, variable, element) is not one.
    #[error("argument {position} of {function} must be an integer id, found {found}")]
    NotAnId {
        /// The function.
        function: &'static str,
        /// 1-based argument position.
        position: usize,
        /// What was there.
        found: String,
    },
    /// The tree would be deeper than [`MAX_DEPTH`] (nesting plus operator chains).
    #[error("expression nested or chained deeper than {MAX_DEPTH} levels")]
    TooDeep,
    /// USER(…) takes numbers only.
    #[error("USER(…) takes numeric constants only")]
    UserNotConstant,
}

#[derive(Debug, Clone, PartialEq)]
enum Tok {
    Num(f64),
    Name(String),
    Op(char),
    Pow,
    LParen,
    RParen,
    Comma,
    /// `:`, after an arithmetic IF's condition.
    Colon,
}

fn describe(t: &Tok) -> String {
    match t {
        Tok::Num(v) => format!("{v}"),
        Tok::Name(n) => n.clone(),
        Tok::Op(c) => c.to_string(),
        Tok::Pow => "**".into(),
        Tok::LParen => "(".into(),
        Tok::RParen => ")".into(),
        Tok::Comma => ",".into(),
        Tok::Colon => ":".into(),
    }
}

fn err(offset: usize, kind: ExprErrorKind) -> ExprError {
    ExprError { offset, kind }
}

fn tokenize(chars: &[char]) -> Result<Vec<(Tok, usize)>, ExprError> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let start = i;
        if c.is_whitespace() {
            i += 1;
            continue;
        }
        if c.is_ascii_digit() || (c == '.' && chars.get(i + 1).is_some_and(char::is_ascii_digit)) {
            while i < chars.len() && (chars[i].is_ascii_digit() || chars[i] == '.') {
                i += 1;
            }
            if i < chars.len() && matches!(chars[i], 'e' | 'E') {
                let mut j = i + 1;
                if j < chars.len() && matches!(chars[j], '+' | '-') {
                    j += 1;
                }
                if j < chars.len() && chars[j].is_ascii_digit() {
                    while j < chars.len() && chars[j].is_ascii_digit() {
                        j += 1;
                    }
                    i = j;
                }
            }
            let text: String = chars[start..i].iter().collect();
            let mut value: f64 = text
                .parse()
                .map_err(|_| err(start, ExprErrorKind::BadNumber(text.clone())))?;
            if i < chars.len() && matches!(chars[i], 'd' | 'D') {
                let next = chars.get(i + 1);
                if next.is_some_and(|n| n.is_ascii_alphanumeric() || *n == '_') {
                    let bad: String = chars[start..=i + 1].iter().collect();
                    return Err(err(start, ExprErrorKind::BadNumber(bad)));
                }
                value = value.to_radians();
                i += 1;
            } else if i < chars.len() && (chars[i].is_ascii_alphabetic() || chars[i] == '_') {
                let bad: String = chars[start..=i].iter().collect();
                return Err(err(start, ExprErrorKind::BadNumber(bad)));
            }
            out.push((Tok::Num(value), start));
            continue;
        }
        if c.is_ascii_alphabetic() || c == '_' {
            while i < chars.len() && (chars[i].is_ascii_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            let name: String = chars[start..i].iter().collect();
            out.push((Tok::Name(name.to_ascii_uppercase()), start));
            continue;
        }
        let tok = match c {
            '*' if chars.get(i + 1) == Some(&'*') => {
                i += 1;
                Tok::Pow
            }
            '^' => Tok::Pow,
            '+' | '-' | '*' | '/' => Tok::Op(c),
            '(' => Tok::LParen,
            ')' => Tok::RParen,
            ',' => Tok::Comma,
            ':' => Tok::Colon,
            _ => return Err(err(start, ExprErrorKind::UnexpectedChar(c))),
        };
        i += 1;
        out.push((tok, start));
    }
    Ok(out)
}

struct Parser {
    toks: Vec<(Tok, usize)>,
    pos: usize,
    end: usize,
}

impl Parser {
    fn peek(&self) -> Option<&Tok> {
        self.toks.get(self.pos).map(|(t, _)| t)
    }

    fn offset(&self) -> usize {
        self.toks.get(self.pos).map(|(_, o)| *o).unwrap_or(self.end)
    }

    fn next(&mut self, expected: &'static str) -> Result<(Tok, usize), ExprError> {
        let t = self
            .toks
            .get(self.pos)
            .cloned()
            .ok_or_else(|| err(self.end, ExprErrorKind::UnexpectedEnd(expected)))?;
        self.pos += 1;
        Ok(t)
    }

    fn expr(&mut self, min_bp: u8, mut depth: usize) -> Result<Expr, ExprError> {
        if depth > MAX_DEPTH {
            return Err(err(self.offset(), ExprErrorKind::TooDeep));
        }
        let (tok, at) = self.next("a number, name or '('")?;
        let mut lhs = match tok {
            Tok::Num(v) => Expr::Number(v),
            Tok::Op('-') => Expr::Neg(Box::new(self.expr(5, depth + 1)?)),
            Tok::Op('+') => self.expr(5, depth + 1)?,
            Tok::LParen => {
                let inner = self.expr(0, depth + 1)?;
                self.expect_rparen()?;
                inner
            }
            Tok::Name(name) => self.name(name, at, depth)?,
            other => {
                return Err(err(
                    at,
                    ExprErrorKind::Expected {
                        expected: "a number, name or '('",
                        found: describe(&other),
                    },
                ));
            }
        };
        loop {
            let (op, lbp, rbp) = match self.peek() {
                Some(Tok::Op('+')) => (BinOp::Add, 1, 2),
                Some(Tok::Op('-')) => (BinOp::Sub, 1, 2),
                Some(Tok::Op('*')) => (BinOp::Mul, 3, 4),
                Some(Tok::Op('/')) => (BinOp::Div, 3, 4),
                Some(Tok::Pow) => (BinOp::Pow, 8, 7),
                _ => break,
            };
            if lbp < min_bp {
                break;
            }
            self.pos += 1;
            // A chain `a + b + c …` deepens the tree on the left: count it like nesting, so
            // evaluation (which recurses) stays within the stack.
            depth += 1;
            if depth > MAX_DEPTH {
                return Err(err(self.offset(), ExprErrorKind::TooDeep));
            }
            let rhs = self.expr(rbp, depth + 1)?;
            lhs = Expr::Binary(op, Box::new(lhs), Box::new(rhs));
        }
        Ok(lhs)
    }

    fn expect_rparen(&mut self) -> Result<(), ExprError> {
        let (t, at) = self.next("')'")?;
        if t == Tok::RParen {
            Ok(())
        } else {
            Err(err(
                at,
                ExprErrorKind::Expected {
                    expected: "')'",
                    found: describe(&t),
                },
            ))
        }
    }

    fn name(&mut self, name: String, at: usize, depth: usize) -> Result<Expr, ExprError> {
        if self.peek() != Some(&Tok::LParen) {
            return match name.as_str() {
                "TIME" => Ok(Expr::Time),
                "PI" => Ok(Expr::Number(std::f64::consts::PI)),
                "DTOR" => Ok(Expr::Number(std::f64::consts::PI / 180.0)),
                "RTOD" => Ok(Expr::Number(180.0 / std::f64::consts::PI)),
                _ => Err(err(at, ExprErrorKind::UnknownName(name))),
            };
        }
        let Some(&(fname, callee, min, max)) = FUNCTIONS.iter().find(|f| f.0 == name) else {
            return Err(err(at, ExprErrorKind::UnknownFunction(name)));
        };
        self.pos += 1;
        let mut args = Vec::new();
        let mut offsets = Vec::new();
        if self.peek() == Some(&Tok::RParen) {
            self.pos += 1;
        } else {
            // An arithmetic IF separates its condition from the branches by ':'.
            let arithmetic_if = callee == Callee::Math(MathFn::If);
            loop {
                offsets.push(self.offset());
                args.push(self.expr(0, depth + 1)?);
                let colon_next = arithmetic_if && args.len() == 1;
                let expected = if colon_next { "':'" } else { "',' or ')'" };
                let (t, at2) = self.next(expected)?;
                match t {
                    Tok::Colon if colon_next => {}
                    Tok::Comma if !colon_next => {}
                    Tok::RParen if !colon_next => break,
                    other => {
                        return Err(err(
                            at2,
                            ExprErrorKind::Expected {
                                expected,
                                found: describe(&other),
                            },
                        ));
                    }
                }
            }
        }
        if args.len() < min || args.len() > max {
            return Err(err(
                at,
                ExprErrorKind::Arity {
                    function: fname,
                    min,
                    max,
                    given: args.len(),
                },
            ));
        }
        let ids = |args: &[Expr]| -> Result<Vec<u32>, ExprError> {
            args.iter()
                .enumerate()
                .map(|(k, a)| match a {
                    // Whole, non-negative and within u32: the cast is exact.
                    Expr::Number(v)
                        if v.fract() == 0.0 && *v >= 0.0 && *v <= f64::from(u32::MAX) =>
                    {
                        Ok(*v as u32)
                    }
                    other => Err(err(
                        offsets[k],
                        ExprErrorKind::NotAnId {
                            function: fname,
                            position: k + 1,
                            found: format!("{other:?}"),
                        },
                    )),
                })
                .collect()
        };
        Ok(match callee {
            Callee::Math(f) => Expr::Math(f, args),
            Callee::Measure(m) => Expr::Measure(m, ids(&args)?),
            Callee::ForceMeasure(m) => Expr::ForceMeasure(m, ids(&args)?),
            Callee::VarVal => Expr::VarVal(ids(&args)?[0]),
            Callee::Element(kind) => {
                let v = ids(&args)?;
                Expr::Element(kind, [v[0], v[1], v[2], v[3]])
            }
            Callee::Orient => {
                let v = ids(&args)?;
                Expr::Orient([v[0], v[1], v[2], v[3]])
            }
            Callee::User => {
                let mut constants = Vec::new();
                for a in &args {
                    match constant(a) {
                        Some(v) => constants.push(v),
                        None => return Err(err(at, ExprErrorKind::UserNotConstant)),
                    }
                }
                Expr::User(constants)
            }
        })
    }
}

/// The value of a constant expression (a number, possibly negated).
fn constant(e: &Expr) -> Option<f64> {
    match e {
        Expr::Number(v) => Some(*v),
        Expr::Neg(inner) => constant(inner).map(|v| -v),
        _ => None,
    }
}

/// Parses an expression. Offsets in errors are character indices into `text`.
pub fn parse_expr(text: &str) -> Result<Expr, ExprError> {
    let chars: Vec<char> = text.chars().collect();
    let toks = tokenize(&chars)?;
    let mut p = Parser {
        toks,
        pos: 0,
        end: chars.len(),
    };
    let e = p.expr(0, 0)?;
    if let Some((t, at)) = p.toks.get(p.pos) {
        return Err(err(
            *at,
            ExprErrorKind::Expected {
                expected: "an operator or the end",
                found: describe(t),
            },
        ));
    }
    Ok(e)
}
