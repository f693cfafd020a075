//! The text form of a transmit file: the keyword header (XT Format Reference, physical
//! layout) and a cursor over the node stream's tokens.
//!
//! The stream is written in lines of at most 80 characters that break anywhere, even inside
//! a token, so line ends carry no meaning and are removed before tokens are read. Tokens:
//! integers and reals are followed by a space; a character or logical field is one character
//! with no space after it; a string is its length, a space, then exactly that many characters;
//! an unset real, vector or pointer is `?`.

use crate::error::ErrorKind;

/// The node stream with line ends removed, and where each original line starts in it.
pub struct Stream {
    bytes: Vec<u8>,
    /// Offset in `bytes` of each stream line's first character.
    line_starts: Vec<usize>,
    /// File line number (1-based) of the stream's first line.
    first_line: usize,
}

/// The header's `**END_OF_HEADER` line ends the header; the stream starts on the next line.
const END_OF_HEADER: &[u8] = b"**END_OF_HEADER";

impl Stream {
    /// Splits a file's text into header and stream. A file without the keyword header starts
    /// straight with the stream (`T` + banner).
    pub fn new(text: &[u8]) -> Result<Self, ErrorKind> {
        let (start, first_line) = if text.starts_with(b"**") {
            let at = find(text, END_OF_HEADER).ok_or_else(|| ErrorKind::Truncated {
                what: "the header (no **END_OF_HEADER line)".into(),
            })?;
            let eol = text[at..]
                .iter()
                .position(|&b| b == b'\n')
                .map(|p| at + p + 1)
                .ok_or_else(|| ErrorKind::Truncated {
                    what: "the header (nothing after **END_OF_HEADER)".into(),
                })?;
            let lines = text[..eol].iter().filter(|&&b| b == b'\n').count();
            (eol, lines + 1)
        } else {
            (0, 1)
        };
        let mut bytes = Vec::with_capacity(text.len() - start);
        let mut line_starts = vec![0];
        for &b in &text[start..] {
            match b {
                b'\n' => line_starts.push(bytes.len()),
                b'\r' => {}
                _ => bytes.push(b),
            }
        }
        Ok(Self {
            bytes,
            line_starts,
            first_line,
        })
    }

    /// A cursor at the stream's start.
    pub fn cursor(&self) -> Cursor<'_> {
        Cursor {
            stream: self,
            at: 0,
        }
    }

    /// File line and column (1-based) of stream offset `at`.
    pub fn location(&self, at: usize) -> (usize, usize) {
        let line = self.line_starts.partition_point(|&s| s <= at).max(1) - 1;
        (self.first_line + line, at - self.line_starts[line] + 1)
    }
}

fn find(hay: &[u8], needle: &[u8]) -> Option<usize> {
    hay.windows(needle.len()).position(|w| w == needle)
}

/// A token could not be read: `Eof` when the stream ended, `Bad` with the offset otherwise.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TokenError {
    /// The stream ended.
    Eof,
    /// A malformed token at this offset.
    Bad(usize),
}

/// A read position in a [`Stream`].
pub struct Cursor<'a> {
    stream: &'a Stream,
    at: usize,
}

impl Cursor<'_> {
    /// The current offset.
    pub fn offset(&self) -> usize {
        self.at
    }

    /// The stream being read.
    pub fn stream(&self) -> &Stream {
        self.stream
    }

    fn skip_spaces(&mut self) -> Result<u8, TokenError> {
        let b = &self.stream.bytes;
        while self.at < b.len() && b[self.at] == b' ' {
            self.at += 1;
        }
        b.get(self.at).copied().ok_or(TokenError::Eof)
    }

    /// Whether the next token is an unset value `?` (consumed if so).
    pub fn unset(&mut self) -> Result<bool, TokenError> {
        if self.skip_spaces()? == b'?' {
            self.at += 1;
            return Ok(true);
        }
        Ok(false)
    }

    /// The next non-space character, without consuming it.
    pub fn peek(&mut self) -> Result<u8, TokenError> {
        self.skip_spaces()
    }

    /// An integer (optionally signed); `None` for `?`.
    pub fn int(&mut self) -> Result<Option<i64>, TokenError> {
        if self.unset()? {
            return Ok(None);
        }
        let b = &self.stream.bytes;
        let start = self.at;
        let mut end = start;
        if matches!(b.get(end), Some(b'-' | b'+')) {
            end += 1;
        }
        while end < b.len() && b[end].is_ascii_digit() {
            end += 1;
        }
        if end == b.len() {
            return Err(TokenError::Eof);
        }
        let text = std::str::from_utf8(&b[start..end]).map_err(|_| TokenError::Bad(start))?;
        let v = text.parse().map_err(|_| TokenError::Bad(start))?;
        self.at = end;
        Ok(Some(v))
    }

    /// A real; `None` for `?`.
    pub fn real(&mut self) -> Result<Option<f64>, TokenError> {
        if self.unset()? {
            return Ok(None);
        }
        let b = &self.stream.bytes;
        let start = self.at;
        let mut end = start;
        while end < b.len() && matches!(b[end], b'0'..=b'9' | b'+' | b'-' | b'.' | b'e' | b'E') {
            end += 1;
        }
        if end == b.len() {
            return Err(TokenError::Eof);
        }
        let text = std::str::from_utf8(&b[start..end]).map_err(|_| TokenError::Bad(start))?;
        let v: f64 = text.parse().map_err(|_| TokenError::Bad(start))?;
        if !v.is_finite() {
            return Err(TokenError::Bad(start));
        }
        self.at = end;
        Ok(Some(v))
    }

    /// One character (a character or logical field): the next non-space byte.
    pub fn char(&mut self) -> Result<u8, TokenError> {
        let c = self.skip_spaces()?;
        self.at += 1;
        Ok(c)
    }

    /// `n` raw characters after one separating space (variable character fields).
    pub fn raw(&mut self, n: usize) -> Result<String, TokenError> {
        let b = &self.stream.bytes;
        if b.get(self.at) == Some(&b' ') {
            self.at += 1;
        }
        let end = self.at.checked_add(n).ok_or(TokenError::Bad(self.at))?;
        if end > b.len() {
            return Err(TokenError::Eof);
        }
        let s = String::from_utf8_lossy(&b[self.at..end]).into_owned();
        self.at = end;
        Ok(s)
    }

    /// A string: its length, a space, the characters.
    pub fn string(&mut self) -> Result<String, TokenError> {
        let start = self.at;
        let n = self.int()?.ok_or(TokenError::Bad(start))?;
        let n = usize::try_from(n).map_err(|_| TokenError::Bad(start))?;
        if self.stream.bytes.get(self.at) != Some(&b' ') {
            return Err(TokenError::Bad(self.at));
        }
        self.raw(n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tokens_run_together_as_the_format_writes_them() {
        let s = Stream::new(b"T5 hello12 -3 +-.5 1e-3 ?F7 x").unwrap();
        let mut c = s.cursor();
        assert_eq!(c.char(), Ok(b'T'));
        assert_eq!(c.string().unwrap(), "hello");
        assert_eq!(c.int(), Ok(Some(12)));
        assert_eq!(c.int(), Ok(Some(-3)));
        assert_eq!(c.char(), Ok(b'+'));
        assert_eq!(c.real(), Ok(Some(-0.5)));
        assert_eq!(c.real(), Ok(Some(1e-3)));
        assert_eq!(c.real(), Ok(None));
        assert_eq!(c.char(), Ok(b'F'));
        assert_eq!(c.int(), Ok(Some(7)));
        assert_eq!(c.char(), Ok(b'x'));
        assert_eq!(c.char(), Err(TokenError::Eof));
    }

    #[test]
    fn line_ends_inside_tokens_are_removed_and_locations_map_back() {
        let s = Stream::new(b"**H\n**END_OF_HEADER***\n12\n34 5 ").unwrap();
        let mut c = s.cursor();
        assert_eq!(c.int(), Ok(Some(1234)));
        assert_eq!(s.location(c.offset()), (4, 3));
    }

    #[test]
    fn a_header_without_its_end_is_truncated() {
        assert!(matches!(
            Stream::new(b"**PART1;\n"),
            Err(ErrorKind::Truncated { .. })
        ));
    }
}
