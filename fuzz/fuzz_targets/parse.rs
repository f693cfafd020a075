//! Fuzz target: arbitrary bytes through the lexer and parser (as a dataset and as a command
//! file) and the whole lowering. Any panic is a bug: bad input must become a diagnostic.
#![no_main]

use contact::dataset::{FileKind, parse_only, read_str};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let _ = parse_only(&text, FileKind::Dataset);
    let _ = parse_only(&text, FileKind::Commands);
    let _ = read_str(&text, "fuzz.adm", None);
});
