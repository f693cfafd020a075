//! The statement layer: `NAME/id, ARG, ARG = v1, v2, …, FUNCTION = expression` with every
//! keyword resolved (abbreviations allowed) and every value located.
//!
//! - A statement keyword is followed by `/`; what follows the `/` is the id (digits, leading
//!   zeros allowed) or, for statements without ids, the first argument (`SIMULATE/DYNAMIC`).
//! - Arguments may come in any order, separated by `,` (or `\` after an expression).
//! - A value list runs over commas and continuation lines while the items are numbers; a word
//!   after a comma is the next keyword.
//! - An expression (`FUNCTION=`, `F1=`…`F8=`, `NORMAL_FUNCTION=`…) runs to the end of the
//!   statement, a `\`, or a comma outside parentheses on the same line. It continues onto a
//!   continuation line (whose leading comma is dropped) unless that line starts with `KEYWORD =`.
//! - Free text (`COMMENT=`/`C=`, `TITLE=`) runs to the end of its line.
//!
//! Errors do not stop the parse: the statement in error is dropped, the problem recorded, and
//! parsing goes on with the next statement.

use super::error::Loc;
use super::keywords::{self, ArgSpec, IdRule, Match, StatementSpec};
use super::lexer::{FileKind, LineProblem, RawStatement, Segment, split_lines};

/// An expression's source text with the location of each character (continuation lines joined
/// by a space, which is located at the next line's start).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ExprText {
    /// The expression.
    pub text: String,
    /// `locs[k]` is where the `k`-th character of `text` came from.
    pub locs: Vec<Loc>,
}

impl ExprText {
    /// Where the character at char index `index` came from (the last one past the end).
    pub fn loc_at(&self, index: usize) -> Loc {
        self.locs
            .get(index)
            .or(self.locs.last())
            .copied()
            .unwrap_or_default()
    }
}

/// A value as written.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ValueKind {
    /// A number, id, word or colon list, as written.
    Atom(String),
    /// A function expression.
    Expr(ExprText),
    /// Free text.
    Text(String),
}

/// One value of an argument, with its location.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Value {
    /// What was written.
    pub kind: ValueKind,
    /// Where its first character is.
    pub loc: Loc,
}

/// One argument of a statement.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Arg {
    /// The keyword it resolved to.
    pub spec: &'static ArgSpec,
    /// The keyword as written (may be abbreviated).
    pub written: String,
    /// Where the keyword is.
    pub loc: Loc,
    /// Its values (empty for a flag).
    pub values: Vec<Value>,
}

/// One statement or command.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Statement {
    /// The keyword it resolved to.
    pub spec: &'static StatementSpec,
    /// Where the statement starts.
    pub loc: Loc,
    /// `NAME/id`: the id and where it is.
    pub id: Option<(u32, Loc)>,
    /// The arguments in the order written (none for statements that are not modelled).
    pub args: Vec<Arg>,
    /// The name a comment `adams_view_name='name'` before it gives (see the lexer).
    pub view_name: Option<String>,
}

impl Statement {
    /// `NAME/id` or `NAME/` for messages.
    pub fn label(&self) -> String {
        match self.id {
            Some((id, _)) => format!("{}/{}", self.spec.name, id),
            None => format!("{}/", self.spec.name),
        }
    }
}

/// A problem found while parsing: where, and what.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ParseProblem {
    /// Where.
    pub loc: Loc,
    /// What.
    pub message: String,
}

/// A parsed dataset or command file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ParsedFile {
    /// Dataset or command file.
    pub kind: FileKind,
    /// The title line (datasets).
    pub title: Option<Segment>,
    /// Leading file-name lines (command files).
    pub file_names: Vec<Segment>,
    /// The statements that parsed.
    pub statements: Vec<Statement>,
    /// Where END / STOP was.
    pub end: Option<Loc>,
    /// The problems found.
    pub problems: Vec<ParseProblem>,
}

/// Parses a whole file; never panics, whatever the input.
pub fn parse(text: &str, kind: FileKind) -> ParsedFile {
    let lines = split_lines(text, kind);
    let mut problems: Vec<ParseProblem> = lines
        .problems
        .iter()
        .map(|p| match p {
            LineProblem::OrphanContinuation(loc) => ParseProblem {
                loc: *loc,
                message: "a continuation line (starting with ',') has no statement to continue"
                    .to_string(),
            },
        })
        .collect();
    let table = match kind {
        FileKind::Dataset => keywords::DATASET_STATEMENTS,
        FileKind::Commands => keywords::COMMANDS,
    };
    let mut statements = Vec::new();
    for raw in &lines.statements {
        match parse_statement(raw, table) {
            Ok(s) => statements.push(s),
            Err(p) => problems.push(p),
        }
    }
    ParsedFile {
        kind,
        title: lines.title,
        file_names: lines.file_names,
        statements,
        end: lines.end,
        problems,
    }
}

#[derive(Debug, Clone, Copy)]
pub(super) struct Ch {
    pub(super) c: char,
    pub(super) loc: Loc,
    pub(super) seg: usize,
}

pub(super) struct Cursor {
    pub(super) chars: Vec<Ch>,
    pub(super) pos: usize,
    pub(super) end_loc: Loc,
}

pub(super) fn problem(loc: Loc, message: impl Into<String>) -> ParseProblem {
    ParseProblem {
        loc,
        message: message.into(),
    }
}

pub(super) fn is_word_char(c: char) -> bool {
    !(c.is_whitespace() || matches!(c, ',' | '=' | '\\' | '(' | ')' | '!'))
}

impl Cursor {
    fn new(raw: &RawStatement) -> Self {
        let mut chars = Vec::new();
        for (seg, s) in raw.segments.iter().enumerate() {
            for (k, c) in s.text.chars().enumerate() {
                let col = s
                    .loc
                    .col
                    .saturating_add(u32::try_from(k).unwrap_or(u32::MAX));
                chars.push(Ch {
                    c,
                    loc: Loc::new(s.loc.line, col),
                    seg,
                });
            }
        }
        let end_loc = chars
            .last()
            .map(|ch| Loc::new(ch.loc.line, ch.loc.col.saturating_add(1)))
            .unwrap_or_else(|| raw.loc());
        Self {
            chars,
            pos: 0,
            end_loc,
        }
    }

    pub(super) fn peek(&self) -> Option<Ch> {
        self.chars.get(self.pos).copied()
    }

    pub(super) fn peek_at(&self, pos: usize) -> Option<Ch> {
        self.chars.get(pos).copied()
    }

    pub(super) fn loc(&self) -> Loc {
        self.peek().map(|c| c.loc).unwrap_or(self.end_loc)
    }

    pub(super) fn skip_ws(&mut self) {
        while self.peek().is_some_and(|c| c.c.is_whitespace()) {
            self.pos += 1;
        }
    }

    /// Skips blanks from `pos` on; returns the first position that is not blank.
    pub(super) fn skip_ws_from(&self, mut pos: usize) -> usize {
        while self.peek_at(pos).is_some_and(|c| c.c.is_whitespace()) {
            pos += 1;
        }
        pos
    }

    pub(super) fn word(&mut self) -> (String, Loc) {
        let loc = self.loc();
        let mut s = String::new();
        while let Some(ch) = self.peek() {
            if !is_word_char(ch.c) {
                break;
            }
            s.push(ch.c);
            self.pos += 1;
        }
        (s, loc)
    }

    /// A quoted string from the `"` at the cursor to its closing `"` on the same line, both
    /// quotes kept (to the line's end when it is not closed).
    pub(super) fn quoted(&mut self) -> (String, Loc) {
        let loc = self.loc();
        let Some(open) = self.peek() else {
            return (String::new(), loc);
        };
        let seg = open.seg;
        let mut s = String::from('"');
        self.pos += 1;
        while let Some(ch) = self.peek() {
            if ch.seg != seg {
                break;
            }
            s.push(ch.c);
            self.pos += 1;
            if ch.c == '"' {
                break;
            }
        }
        (s, loc)
    }

    /// True when, from `pos`, the text reads `WORD =` (not `==`): the start of an argument.
    pub(super) fn keyword_assignment_at(&self, pos: usize) -> bool {
        let mut p = self.skip_ws_from(pos);
        let start = p;
        while self
            .peek_at(p)
            .is_some_and(|c| c.c.is_ascii_alphanumeric() || c.c == '_')
        {
            p += 1;
        }
        if p == start {
            return false;
        }
        let p = self.skip_ws_from(p);
        self.peek_at(p).is_some_and(|c| c.c == '=')
            && self.peek_at(p + 1).is_none_or(|c| c.c != '=')
    }
}

fn parse_statement(
    raw: &RawStatement,
    table: &'static [StatementSpec],
) -> Result<Statement, ParseProblem> {
    let mut cur = Cursor::new(raw);
    cur.skip_ws();
    let name_loc = cur.loc();
    let mut name = String::new();
    while let Some(ch) = cur.peek() {
        if !(ch.c.is_ascii_alphanumeric() || ch.c == '_') {
            break;
        }
        name.push(ch.c);
        cur.pos += 1;
    }
    if name.is_empty() {
        let c = cur.peek().map(|ch| ch.c).unwrap_or(' ');
        return Err(problem(
            name_loc,
            format!("expected a statement keyword, found '{c}'"),
        ));
    }
    let spec = match keywords::statement(&name, table) {
        Match::Found(spec) => spec,
        Match::Ambiguous(names) => {
            return Err(problem(
                name_loc,
                format!(
                    "ambiguous abbreviation '{name}': could be {}",
                    names.join(", ")
                ),
            ));
        }
        Match::Unknown => {
            return Err(problem(name_loc, format!("unknown statement '{name}'")));
        }
    };
    let mut statement = Statement {
        spec,
        loc: name_loc,
        id: None,
        args: Vec::new(),
        view_name: raw.view_name.clone(),
    };
    cur.skip_ws();
    let has_slash = cur.peek().is_some_and(|c| c.c == '/');
    if has_slash {
        cur.pos += 1;
    } else if spec.name != "STOP" && spec.modelled {
        return Err(problem(
            cur.loc(),
            format!("expected '/' after {}", spec.name),
        ));
    }
    if !spec.modelled {
        return Ok(statement);
    }
    if has_slash && spec.id == IdRule::Required {
        cur.skip_ws();
        let (id_text, id_loc) = cur.word();
        if id_text.is_empty() {
            return Err(problem(
                id_loc,
                format!("{} needs an id: {}/id", spec.name, spec.name),
            ));
        }
        let id = parse_id(&id_text).ok_or_else(|| {
            let digits = id_text.chars().all(|c| c.is_ascii_digit());
            let nonzero = id_text.trim_start_matches('0').len();
            if digits && nonzero > 0 {
                problem(
                    id_loc,
                    format!(
                        "{}/{id_text}: the id is too large: the largest allowed is {}",
                        spec.name,
                        u32::MAX
                    ),
                )
            } else {
                problem(
                    id_loc,
                    format!("{}/{id_text}: the id must be a positive integer", spec.name),
                )
            }
        })?;
        statement.id = Some((id, id_loc));
    }
    super::arguments::parse_arguments(&mut cur, &mut statement)?;
    Ok(statement)
}

/// A positive integer id; leading zeros allowed (`0101` is 101).
pub fn parse_id(text: &str) -> Option<u32> {
    if text.is_empty() || !text.chars().all(|c| c.is_ascii_digit()) {
        return None;
    }
    text.parse::<u32>().ok().filter(|id| *id > 0)
}

/// True for text that reads as a number, optionally with a `D` (degrees) suffix.
pub(super) fn looks_numeric(text: &str) -> bool {
    let t = text.strip_suffix(['D', 'd']).unwrap_or(text);
    !t.is_empty()
        && t.chars().any(|c| c.is_ascii_digit())
        && t.chars()
            .all(|c| c.is_ascii_digit() || matches!(c, '.' | '+' | '-' | 'e' | 'E'))
}

#[cfg(test)]
#[path = "parser_tests.rs"]
mod tests;
