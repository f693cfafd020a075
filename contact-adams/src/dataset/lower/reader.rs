//! Typed access to a statement's arguments, with located errors.

use crate::dataset::error::Loc;
use crate::dataset::parser::{Arg, ExprText, Statement, Value, ValueKind};

/// A problem found while lowering: where, and what.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Problem {
    /// Where.
    pub loc: Loc,
    /// What.
    pub message: String,
}

impl Problem {
    /// A problem at `loc`.
    pub fn new(loc: Loc, message: impl Into<String>) -> Self {
        Self {
            loc,
            message: message.into(),
        }
    }
}

/// Reads a Fortran-style real; a trailing `D` means degrees (the value is returned in radians).
/// NaN and infinities are not numbers here.
pub fn parse_number(text: &str) -> Option<f64> {
    let (body, degrees) = match text.strip_suffix(['D', 'd']) {
        Some(b) => (b, true),
        None => (text, false),
    };
    let plain = !body.is_empty()
        && body.chars().any(|c| c.is_ascii_digit())
        && body
            .chars()
            .all(|c| c.is_ascii_digit() || matches!(c, '.' | '+' | '-' | 'e' | 'E'));
    if !plain {
        return None;
    }
    let v: f64 = body.parse().ok()?;
    if !v.is_finite() {
        return None;
    }
    Some(if degrees { v.to_radians() } else { v })
}

/// Typed argument access for one statement.
pub struct Reader<'s> {
    /// The statement.
    pub st: &'s Statement,
}

impl<'s> Reader<'s> {
    /// A reader for `st`.
    pub fn new(st: &'s Statement) -> Self {
        Self { st }
    }

    /// The statement's label, `NAME/id`.
    pub fn label(&self) -> String {
        self.st.label()
    }

    /// The argument named `name` (full keyword), if given.
    pub fn get(&self, name: &str) -> Option<&'s Arg> {
        self.st.args.iter().find(|a| a.spec.name == name)
    }

    /// True when the flag (or any argument) `name` is given.
    pub fn flag(&self, name: &str) -> bool {
        self.get(name).is_some()
    }

    /// Which of the exclusive `names` is given (at most one; two is an error).
    pub fn one_of(&self, names: &[&'static str]) -> Result<Option<&'static str>, Problem> {
        let given: Vec<&'s Arg> = names.iter().filter_map(|n| self.get(n)).collect();
        match given.as_slice() {
            [] => Ok(None),
            [one] => Ok(names.iter().copied().find(|n| *n == one.spec.name)),
            [first, second, ..] => Err(Problem::new(
                second.loc,
                format!(
                    "{}: {} and {} cannot both be given",
                    self.label(),
                    first.spec.name,
                    second.spec.name
                ),
            )),
        }
    }

    /// An error for a missing required argument, at the statement.
    pub fn missing(&self, what: &str) -> Problem {
        Problem::new(self.st.loc, format!("{}: {what} is required", self.label()))
    }

    fn atom<'v>(&self, arg: &Arg, v: &'v Value) -> Result<&'v str, Problem> {
        match &v.kind {
            ValueKind::Atom(s) => Ok(s),
            _ => Err(Problem::new(
                v.loc,
                format!("{}: {} needs a plain value", self.label(), arg.spec.name),
            )),
        }
    }

    fn number_of(&self, arg: &Arg, v: &Value) -> Result<f64, Problem> {
        let text = self.atom(arg, v)?;
        parse_number(text).ok_or_else(|| {
            Problem::new(
                v.loc,
                format!(
                    "{}: {} = {text} is not a number",
                    self.label(),
                    arg.spec.name
                ),
            )
        })
    }

    fn count(&self, arg: &Arg, allowed: &[usize]) -> Result<(), Problem> {
        if allowed.contains(&arg.values.len()) {
            return Ok(());
        }
        let want: Vec<String> = allowed.iter().map(ToString::to_string).collect();
        Err(Problem::new(
            arg.loc,
            format!(
                "{}: {} takes {} value(s), {} given",
                self.label(),
                arg.spec.name,
                want.join(" or "),
                arg.values.len()
            ),
        ))
    }

    /// A list of numbers with one of the `allowed` lengths.
    pub fn numbers(&self, name: &str, allowed: &[usize]) -> Result<Option<Vec<f64>>, Problem> {
        let Some(arg) = self.get(name) else {
            return Ok(None);
        };
        self.count(arg, allowed)?;
        arg.values
            .iter()
            .map(|v| self.number_of(arg, v))
            .collect::<Result<Vec<_>, _>>()
            .map(Some)
    }

    /// Any number of numbers (at least one).
    pub fn number_list(&self, name: &str) -> Result<Option<Vec<f64>>, Problem> {
        let Some(arg) = self.get(name) else {
            return Ok(None);
        };
        arg.values
            .iter()
            .map(|v| self.number_of(arg, v))
            .collect::<Result<Vec<_>, _>>()
            .map(Some)
    }

    /// One number.
    pub fn number(&self, name: &str) -> Result<Option<f64>, Problem> {
        Ok(self.numbers(name, &[1])?.map(|v| v[0]))
    }

    /// Three numbers.
    pub fn vector(&self, name: &str) -> Result<Option<[f64; 3]>, Problem> {
        Ok(self.numbers(name, &[3])?.map(|v| [v[0], v[1], v[2]]))
    }

    /// A non-negative whole number (counts, orders).
    pub fn count_value(&self, name: &str) -> Result<Option<u32>, Problem> {
        let Some(arg) = self.get(name) else {
            return Ok(None);
        };
        self.count(arg, &[1])?;
        let text = self.atom(arg, &arg.values[0])?;
        text.parse::<u32>().map(Some).map_err(|_| {
            Problem::new(
                arg.values[0].loc,
                format!(
                    "{}: {} = {text} is not a whole number >= 0",
                    self.label(),
                    arg.spec.name
                ),
            )
        })
    }

    /// A list of ids with their locations.
    pub fn ids(&self, name: &str) -> Result<Option<Vec<(u32, Loc)>>, Problem> {
        let Some(arg) = self.get(name) else {
            return Ok(None);
        };
        arg.values
            .iter()
            .map(|v| {
                let text = self.atom(arg, v)?;
                crate::dataset::parser::parse_id(text)
                    .map(|id| (id, v.loc))
                    .ok_or_else(|| {
                        Problem::new(
                            v.loc,
                            format!(
                                "{}: {} = {text} is not an id (a positive integer)",
                                self.label(),
                                arg.spec.name
                            ),
                        )
                    })
            })
            .collect::<Result<Vec<_>, _>>()
            .map(Some)
    }

    /// One id.
    pub fn id(&self, name: &str) -> Result<Option<(u32, Loc)>, Problem> {
        let Some(arg) = self.get(name) else {
            return Ok(None);
        };
        self.count(arg, &[1])?;
        Ok(self.ids(name)?.map(|v| v[0]))
    }

    /// One word, upper case, with its location.
    pub fn word(&self, name: &str) -> Result<Option<(String, Loc)>, Problem> {
        let Some(arg) = self.get(name) else {
            return Ok(None);
        };
        self.count(arg, &[1])?;
        let v = &arg.values[0];
        Ok(Some((self.atom(arg, v)?.to_string(), v.loc)))
    }

    /// The expression of `name`, with its location.
    pub fn expression(&self, name: &str) -> Option<(&'s ExprText, Loc)> {
        let arg = self.get(name)?;
        arg.values.iter().find_map(|v| match &v.kind {
            ValueKind::Expr(e) => Some((e, v.loc)),
            _ => None,
        })
    }

    /// The free text of `name`.
    pub fn text(&self, name: &str) -> Option<String> {
        let arg = self.get(name)?;
        arg.values.iter().find_map(|v| match &v.kind {
            ValueKind::Text(t) => Some(t.clone()),
            _ => None,
        })
    }

    /// The location of argument `name`'s first value, or of the statement.
    pub fn loc_of(&self, name: &str) -> Loc {
        self.get(name)
            .map(|a| a.values.first().map(|v| v.loc).unwrap_or(a.loc))
            .unwrap_or(self.st.loc)
    }
}

#[cfg(test)]
mod tests {
    use super::parse_number;

    #[test]
    fn fortran_numbers_and_degrees() {
        assert_eq!(parse_number("1.0E+005"), Some(1e5));
        assert_eq!(parse_number("-.4"), Some(-0.4));
        assert_eq!(parse_number("90D"), Some(std::f64::consts::FRAC_PI_2));
        assert_eq!(parse_number("1.2.3"), None);
        assert_eq!(parse_number("inf"), None);
        assert_eq!(parse_number("NaN"), None);
        assert_eq!(parse_number("1e999"), None);
        assert_eq!(parse_number("D"), None);
    }
}
