//! The statements, commands and arguments the reader knows, and keyword abbreviation.
//!
//! Adams accepts any keyword shortened to a prefix that is unique among the keywords allowed in
//! that place (reference §7.1): `sim/dyn` is `SIMULATE/DYNAMICS`, `FUNC=` is `FUNCTION=`. An exact
//! match always wins over a longer keyword it prefixes (`I` in `MOTION` is `I`, not `ICDISP`),
//! and a few aliases that Adams documents are listed explicitly (`C=` for `COMMENT` in REQUEST).
//!
//! A statement or argument that Adams has but this product does not model is listed with
//! `modelled: false`: the reader accepts it and the model check reports it as ignored, once.

/// How an argument's value is written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Form {
    /// A bare keyword (`GROUND`, `IMPACT`).
    Flag,
    /// `ARG = v1[, v2 …]`: numbers, ids, words or colon lists.
    Values,
    /// `ARG = expression`, up to the end of the statement, a `\` or an in-line top-level comma.
    Expr,
    /// `ARG = free text` to the end of the line.
    Text,
}

/// One argument keyword.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ArgSpec {
    /// The full keyword, upper case.
    pub name: &'static str,
    /// How its value is written.
    pub form: Form,
    /// False for arguments accepted and reported as ignored.
    pub modelled: bool,
}

/// Whether a statement takes an id after its `/`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum IdRule {
    /// `NAME/id` is required.
    Required,
    /// No id: `NAME/` or `NAME/first_argument`.
    None,
}

/// One statement or command keyword and its arguments.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct StatementSpec {
    /// The full keyword, upper case.
    pub name: &'static str,
    /// Id rule.
    pub id: IdRule,
    /// Its arguments (empty for statements that are not modelled: they are skipped whole).
    pub args: &'static [ArgSpec],
    /// Explicit abbreviations: (alias, full argument name).
    pub aliases: &'static [(&'static str, &'static str)],
    /// False for statements accepted and reported as ignored.
    pub modelled: bool,
}

pub use super::tables::{COMMANDS, DATASET_STATEMENTS};

/// How a word matched a keyword table.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Match<T> {
    /// Exactly one keyword matches (exactly, by an alias, or as a unique prefix).
    Found(T),
    /// The word is a prefix of several keywords (listed, full names).
    Ambiguous(Vec<&'static str>),
    /// No keyword matches.
    Unknown,
}

/// Resolves `word` (any case) against `(name, item)` pairs: exact match, else unique prefix.
pub fn resolve<T: Copy>(word: &str, items: impl Iterator<Item = (&'static str, T)>) -> Match<T> {
    let upper = word.to_ascii_uppercase();
    if upper.is_empty() {
        return Match::Unknown;
    }
    let mut prefixed: Vec<(&'static str, T)> = Vec::new();
    for (name, item) in items {
        if name == upper {
            return Match::Found(item);
        }
        if name.starts_with(&upper) {
            prefixed.push((name, item));
        }
    }
    match prefixed.len() {
        0 => Match::Unknown,
        1 => Match::Found(prefixed[0].1),
        _ => Match::Ambiguous(prefixed.into_iter().map(|(n, _)| n).collect()),
    }
}

impl StatementSpec {
    /// Resolves an argument keyword of this statement (aliases first).
    pub fn argument(&self, word: &str) -> Match<&'static ArgSpec> {
        let upper = word.to_ascii_uppercase();
        for (alias, full) in self.aliases {
            if *alias == upper {
                if let Some(spec) = self.args.iter().find(|a| a.name == *full) {
                    return Match::Found(spec);
                }
            }
        }
        resolve(word, self.args.iter().map(|a| (a.name, a)))
    }
}

/// Resolves a statement (or command) keyword in `table`.
pub fn statement(word: &str, table: &'static [StatementSpec]) -> Match<&'static StatementSpec> {
    resolve(word, table.iter().map(|s| (s.name, s)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn abbreviations_resolve_to_unique_prefixes() {
        let sim = statement("sim", COMMANDS);
        assert!(matches!(sim, Match::Found(s) if s.name == "SIMULATE"));
        let Match::Found(motion) = statement("MOTION", DATASET_STATEMENTS) else {
            panic!("MOTION not found")
        };
        assert!(matches!(motion.argument("func"), Match::Found(a) if a.name == "FUNCTION"));
        assert!(matches!(motion.argument("I"), Match::Found(a) if a.name == "I"));
        assert!(matches!(motion.argument("ROTATION"), Match::Found(a) if a.name == "ROTATIONAL"));
        assert_eq!(
            motion.argument("IC"),
            Match::Ambiguous(vec!["ICDISP", "ICVEL"])
        );
        assert_eq!(motion.argument("BOGUS"), Match::Unknown);
        let Match::Found(request) = statement("REQ", DATASET_STATEMENTS) else {
            panic!("REQUEST not found")
        };
        assert!(matches!(request.argument("c"), Match::Found(a) if a.name == "COMMENT"));
    }

    #[test]
    fn every_table_has_unique_names() {
        for table in [DATASET_STATEMENTS, COMMANDS] {
            for (k, s) in table.iter().enumerate() {
                assert!(
                    table[k + 1..].iter().all(|o| o.name != s.name),
                    "{}",
                    s.name
                );
                for (m, a) in s.args.iter().enumerate() {
                    assert!(
                        s.args[m + 1..].iter().all(|o| o.name != a.name),
                        "{}: {}",
                        s.name,
                        a.name
                    );
                }
            }
        }
    }
}
