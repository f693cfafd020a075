//! A statement's arguments: each keyword resolved (abbreviations, repeats) and its values read
//! as its form says (a list of values, a text, an expression), with the problem at its
//! file position.

use super::error::Loc;
use super::keywords::{ArgSpec, Form, Match};
use super::parser::{
    Arg, Cursor, ExprText, ParseProblem, Statement, Value, ValueKind, is_word_char, looks_numeric,
    problem,
};

pub(super) fn parse_arguments(
    cur: &mut Cursor,
    statement: &mut Statement,
) -> Result<(), ParseProblem> {
    loop {
        while cur
            .peek()
            .is_some_and(|c| c.c.is_whitespace() || c.c == ',' || c.c == '\\')
        {
            cur.pos += 1;
        }
        let Some(first) = cur.peek() else {
            return Ok(());
        };
        let (word, loc) = cur.word();
        if word.is_empty() {
            return Err(problem(
                first.loc,
                format!(
                    "{}: unexpected '{}' where an argument keyword was expected",
                    statement.label(),
                    first.c
                ),
            ));
        }
        let arg_spec = argument_spec(statement, &word, loc)?;
        cur.skip_ws();
        let values = argument_values(cur, statement, arg_spec)?;
        if let Some(next) = cur.peek() {
            if !(next.c.is_whitespace() || next.c == ',' || next.c == '\\') {
                return Err(problem(
                    next.loc,
                    format!(
                        "{}: unexpected '{}' after {}",
                        statement.label(),
                        next.c,
                        arg_spec.name
                    ),
                ));
            }
        }
        statement.args.push(Arg {
            spec: arg_spec,
            written: word,
            loc,
            values,
        });
    }
}

/// The argument keyword `word` (written at `loc`, perhaps abbreviated) of `statement`: an
/// error when it is unknown, ambiguous, or given a second time.
fn argument_spec(
    statement: &Statement,
    word: &str,
    loc: Loc,
) -> Result<&'static ArgSpec, ParseProblem> {
    let arg_spec = match statement.spec.argument(word) {
        Match::Found(a) => a,
        Match::Ambiguous(names) => {
            return Err(problem(
                loc,
                format!(
                    "{}: ambiguous abbreviation '{word}': could be {}",
                    statement.label(),
                    names.join(", ")
                ),
            ));
        }
        Match::Unknown => {
            return Err(problem(
                loc,
                format!("{}: unknown argument '{word}'", statement.label()),
            ));
        }
    };
    if let Some(previous) = statement.args.iter().find(|a| a.spec.name == arg_spec.name) {
        return Err(problem(
            loc,
            format!(
                "{}: {} is given twice (first at {})",
                statement.label(),
                arg_spec.name,
                previous.loc
            ),
        ));
    }
    Ok(arg_spec)
}

/// The values of argument `arg_spec` at the cursor (just after its keyword): none for a flag,
/// else after `=` an expression, a text or a list of values, as its form says; an error for a
/// flag given a value, a missing `=` or an empty value.
fn argument_values(
    cur: &mut Cursor,
    statement: &Statement,
    arg_spec: &ArgSpec,
) -> Result<Vec<Value>, ParseProblem> {
    let has_equals = cur.peek().is_some_and(|c| c.c == '=');
    match (arg_spec.form, has_equals) {
        (Form::Flag, false) => Ok(Vec::new()),
        (Form::Flag, true) => Err(problem(
            cur.loc(),
            format!(
                "{}: {} is a flag and takes no value",
                statement.label(),
                arg_spec.name
            ),
        )),
        (_, false) => Err(problem(
            cur.loc(),
            format!(
                "{}: {} needs a value: {} = …",
                statement.label(),
                arg_spec.name,
                arg_spec.name
            ),
        )),
        (form, true) => {
            cur.pos += 1;
            let values = match form {
                Form::Expr => vec![read_expression(cur)],
                Form::Text => vec![read_text(cur)],
                _ => read_values(cur),
            };
            if values.iter().all(|v| match &v.kind {
                ValueKind::Atom(s) | ValueKind::Text(s) => s.is_empty(),
                ValueKind::Expr(e) => e.text.trim().is_empty(),
            }) {
                return Err(problem(
                    cur.loc(),
                    format!(
                        "{}: {} = has no value (truncated statement?)",
                        statement.label(),
                        arg_spec.name
                    ),
                ));
            }
            Ok(values)
        }
    }
}

fn read_values(cur: &mut Cursor) -> Vec<Value> {
    let mut values = Vec::new();
    loop {
        cur.skip_ws();
        let (atom, loc) = if cur.peek().is_some_and(|c| c.c == '"') {
            cur.quoted()
        } else {
            cur.word()
        };
        values.push(Value {
            kind: ValueKind::Atom(atom),
            loc,
        });
        // Another value follows only if, after the comma, a number or a quoted string comes
        // (a list of names, `CNAMES = "a", "b"`, may go on over continuation lines).
        let after_ws = cur.skip_ws_from(cur.pos);
        if cur.peek_at(after_ws).is_none_or(|c| c.c != ',') {
            return values;
        }
        let next = cur.skip_ws_from(after_ws + 1);
        if cur.peek_at(next).is_some_and(|c| c.c == '"') {
            cur.pos = after_ws + 1;
            continue;
        }
        let mut end = next;
        let mut text = String::new();
        while let Some(ch) = cur.peek_at(end) {
            if !is_word_char(ch.c) {
                break;
            }
            text.push(ch.c);
            end += 1;
        }
        if !looks_numeric(&text) {
            return values;
        }
        cur.pos = after_ws + 1;
    }
}

fn read_text(cur: &mut Cursor) -> Value {
    cur.skip_ws();
    let loc = cur.loc();
    let seg = cur.peek().map(|c| c.seg);
    let mut text = String::new();
    while let Some(ch) = cur.peek() {
        if Some(ch.seg) != seg {
            break;
        }
        text.push(ch.c);
        cur.pos += 1;
    }
    Value {
        kind: ValueKind::Text(text.trim_end().to_string()),
        loc,
    }
}

fn read_expression(cur: &mut Cursor) -> Value {
    cur.skip_ws();
    // `FUNCTION =` at the end of a line: the expression starts on the continuation line.
    if let Some(ch) = cur.peek() {
        if ch.c == ',' && cur.pos > 0 && cur.peek_at(cur.pos - 1).is_some_and(|p| p.seg != ch.seg) {
            cur.pos += 1;
            cur.skip_ws();
        }
    }
    let loc = cur.loc();
    let mut text = String::new();
    let mut locs = Vec::new();
    let mut depth = 0usize;
    while let Some(ch) = cur.peek() {
        let starts_line = cur.pos > 0 && cur.peek_at(cur.pos - 1).is_some_and(|p| p.seg != ch.seg);
        if starts_line && depth == 0 {
            // A continuation line: `, KEYWORD =` starts the next argument; anything else goes on.
            let after_comma = if ch.c == ',' { cur.pos + 1 } else { cur.pos };
            if cur.keyword_assignment_at(after_comma) {
                break;
            }
            text.push(' ');
            locs.push(ch.loc);
            cur.pos = after_comma;
            continue;
        }
        if starts_line && ch.c == ',' {
            text.push(' ');
            locs.push(ch.loc);
            cur.pos += 1;
            continue;
        }
        match ch.c {
            '\\' => break,
            ',' if depth == 0 => break,
            '(' => depth += 1,
            ')' => depth = depth.saturating_sub(1),
            _ => {}
        }
        text.push(ch.c);
        locs.push(ch.loc);
        cur.pos += 1;
    }
    while text.ends_with(char::is_whitespace) {
        text.pop();
        locs.pop();
    }
    Value {
        kind: ValueKind::Expr(ExprText { text, locs }),
        loc,
    }
}
