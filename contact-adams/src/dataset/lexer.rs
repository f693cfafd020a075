//! The line layer of the Adams language: turns a file into logical statements.
//!
//! Rules (reference §7.1, §7.16):
//! - LF and CRLF line endings; a leading UTF-8 byte-order mark is skipped.
//! - A dataset's (`.adm`) first line is the title, free text.
//! - `!` starts a comment that runs to the end of the line; blank and comment lines are skipped
//!   and do not end a statement. A comment's `adams_view_name='name'` (Adams View writes one
//!   before each element) names the statement that follows.
//! - A line whose first non-blank character is `,` continues the previous statement.
//! - In a command file (`.acf`) a line ending in `&` continues on the next line, and the first
//!   lines without a `/` (before any command) name the dataset and the output files.
//! - `END` (dataset) ends the file; anything after it is ignored. In a command file `STOP` is a
//!   command, and what follows it is ignored too.
//!
//! Each [`Segment`] keeps the location of its first character, so the parser can give every
//! token its own line and column.

use super::error::Loc;

/// Which language a file is in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FileKind {
    /// A model dataset (`.adm`).
    Dataset,
    /// A command file (`.acf`).
    Commands,
}

/// One physical line's share of a statement: its text after leading blanks, comments removed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Segment {
    /// The text (no line ending, no comment, trailing blanks and a continuation `&` removed).
    pub text: String,
    /// The location of the text's first character.
    pub loc: Loc,
}

/// A statement as it spans lines: its first line and any continuation lines.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RawStatement {
    /// The lines, in order; never empty.
    pub segments: Vec<Segment>,
    /// The name Adams View gave the element, from a comment `adams_view_name='name'` on the
    /// lines between the previous statement and this one.
    pub view_name: Option<String>,
}

/// The name in a comment's `adams_view_name='name'`, if it has one.
fn view_name(comment: &str) -> Option<String> {
    let rest = &comment[comment.find("adams_view_name='")? + "adams_view_name='".len()..];
    let name = &rest[..rest.find('\'')?];
    (!name.is_empty()).then(|| name.to_string())
}

impl RawStatement {
    /// The location of the statement's first character.
    pub fn loc(&self) -> Loc {
        self.segments.first().map(|s| s.loc).unwrap_or_default()
    }
}

/// A problem at the line level.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum LineProblem {
    /// A continuation line (`,` first) with no statement before it.
    OrphanContinuation(Loc),
}

/// A file split into statements.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Lines {
    /// The title line of a dataset, with its location.
    pub title: Option<Segment>,
    /// In a command file: the leading file-name lines (dataset, output base name).
    pub file_names: Vec<Segment>,
    /// The statements in order, up to END / STOP (a STOP is included).
    pub statements: Vec<RawStatement>,
    /// Where END was, if present.
    pub end: Option<Loc>,
    /// Line-level problems.
    pub problems: Vec<LineProblem>,
}

/// Splits `text` into logical statements; see the module docs for the rules.
pub fn split_lines(text: &str, kind: FileKind) -> Lines {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut out = Lines::default();
    let mut current: Option<RawStatement> = None;
    let mut ampersand_open = false;
    let mut pending_name: Option<String> = None;
    for (index, raw_line) in text.split('\n').enumerate() {
        let line_no = u32::try_from(index + 1).unwrap_or(u32::MAX);
        let line = raw_line.strip_suffix('\r').unwrap_or(raw_line);
        if kind == FileKind::Dataset && index == 0 {
            out.title = Some(Segment {
                text: line.trim_end().to_string(),
                loc: Loc::new(1, 1),
            });
            continue;
        }
        let without_comment = match line.find('!') {
            Some(at) => {
                if let Some(name) = view_name(&line[at..]) {
                    pending_name = Some(name);
                }
                &line[..at]
            }
            None => line,
        };
        let trimmed_end = without_comment.trim_end();
        let leading = trimmed_end.len() - trimmed_end.trim_start().len();
        let body = &trimmed_end[leading..];
        if body.is_empty() {
            continue;
        }
        let col = u32::try_from(trimmed_end[..leading].chars().count() + 1).unwrap_or(u32::MAX);
        let loc = Loc::new(line_no, col);
        let (body, ends_with_ampersand) = match body.strip_suffix('&') {
            Some(b) if kind == FileKind::Commands => (b.trim_end(), true),
            _ => (body, false),
        };
        let segment = Segment {
            text: body.to_string(),
            loc,
        };
        let continues = body.starts_with(',') || ampersand_open;
        ampersand_open = ends_with_ampersand;
        if continues {
            match current.as_mut() {
                Some(statement) => statement.segments.push(segment),
                None => out.problems.push(LineProblem::OrphanContinuation(loc)),
            }
            continue;
        }
        if let Some(done) = current.take() {
            out.statements.push(done);
        }
        let first_word: String = body
            .chars()
            .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
            .collect::<String>()
            .to_ascii_uppercase();
        let rest_after_word = &body[first_word.len()..];
        let bare_word = rest_after_word.trim().is_empty();
        match kind {
            FileKind::Dataset if bare_word && first_word == "END" => {
                out.end = Some(loc);
                return out;
            }
            FileKind::Commands
                if out.statements.is_empty()
                    && out.file_names.len() < 2
                    && !body.contains('/')
                    && !(bare_word && first_word == "STOP") =>
            {
                out.file_names.push(segment);
                continue;
            }
            _ => {}
        }
        let is_stop = kind == FileKind::Commands && bare_word && first_word == "STOP";
        current = Some(RawStatement {
            segments: vec![segment],
            view_name: pending_name.take(),
        });
        if is_stop {
            if let Some(done) = current.take() {
                out.statements.push(done);
            }
            out.end = Some(loc);
            return out;
        }
    }
    if let Some(done) = current.take() {
        out.statements.push(done);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_view_name_comment_names_the_next_statement() {
        let text = "t\nPART/1, GROUND\n!\n!   adams_view_name='fwd_housing'\nPART/9\n, MASS = 1\n! adams_view_name=''\nMARKER/2\n";
        let lines = split_lines(text, FileKind::Dataset);
        let names: Vec<Option<&str>> = lines
            .statements
            .iter()
            .map(|s| s.view_name.as_deref())
            .collect();
        assert_eq!(names, [None, Some("fwd_housing"), None]);
    }

    #[test]
    fn continuation_comments_and_end() {
        let text = "title here\r\n! comment\r\nPART/01, GROUND\r\n\r\n  , QG = 1, 2, 3 ! tail\r\nMARKER/2\r\nEND\r\nPART/9\r\n";
        let lines = split_lines(text, FileKind::Dataset);
        assert_eq!(
            lines.title.as_ref().map(|t| t.text.as_str()),
            Some("title here")
        );
        assert_eq!(lines.statements.len(), 2);
        let part = &lines.statements[0];
        assert_eq!(part.segments.len(), 2);
        assert_eq!(part.segments[1].text, ", QG = 1, 2, 3");
        assert_eq!(part.segments[1].loc, Loc::new(5, 3));
        assert_eq!(lines.end, Some(Loc::new(7, 1)));
    }

    #[test]
    fn command_files_join_ampersand_lines_and_read_file_names() {
        let text = "model.adm\nout\nintegrator/gstiff, &\n\terror = 1e-4\nstop\nsim/dyn\n";
        let lines = split_lines(text, FileKind::Commands);
        assert_eq!(lines.file_names.len(), 2);
        assert_eq!(lines.statements.len(), 2);
        assert_eq!(lines.statements[0].segments[0].text, "integrator/gstiff,");
        assert_eq!(lines.statements[0].segments[1].loc, Loc::new(4, 2));
        assert_eq!(lines.end, Some(Loc::new(5, 1)));
    }

    #[test]
    fn orphan_continuation_is_reported() {
        let lines = split_lines("t\n, MASS = 1\n", FileKind::Dataset);
        assert_eq!(
            lines.problems,
            vec![LineProblem::OrphanContinuation(Loc::new(2, 1))]
        );
    }
}
