//! Mutated example datasets through `check` and a short `run`: whatever the mutation, an error
//! value or an answer, never a panic.
//!
//! Each example's `.adm` is mutated by a seeded generator (a number replaced by an extreme one,
//! a line deleted or repeated, the text cut short), read, checked (contact pairs included) and,
//! where it reads without errors, run through the library entry point for 0.02 s of model time.

use contact::cli::check::check_contacts;
use contact::engine_choice::build_engine;
use contact::session::{RunOptions, RunSink, run_model};
use contact::solver::simulate::Frame;
use contact_core::{FacetingTolerance, GeometryLibrary};
use std::path::{Path, PathBuf};

/// A sink that keeps nothing.
struct Discard;

impl RunSink for Discard {
    fn frame(&mut self, _frame: &Frame) -> std::io::Result<()> {
        Ok(())
    }
}

/// A small xorshift generator: the mutations are the same on every machine.
struct Seeded(u64);

impl Seeded {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

/// Numbers a mutation puts in place of one the dataset wrote.
const EXTREMES: [&str; 9] = [
    "0",
    "-1",
    "1E300",
    "1E-300",
    "-1E300",
    "1E308",
    "4294967296",
    "0.5",
    "-0.0",
];

/// One mutation of `text`, chosen by `rng`.
fn mutate(text: &str, rng: &mut Seeded) -> String {
    let lines: Vec<&str> = text.lines().collect();
    match rng.below(4) {
        0 => {
            // A number replaced by an extreme one.
            let spans: Vec<(usize, usize)> = number_spans(text);
            if spans.is_empty() {
                return text.to_string();
            }
            let (a, b) = spans[rng.below(spans.len())];
            let with = EXTREMES[rng.below(EXTREMES.len())];
            format!("{}{with}{}", &text[..a], &text[b..])
        }
        1 => {
            let k = rng.below(lines.len());
            let kept: Vec<&str> = lines
                .iter()
                .enumerate()
                .filter(|(i, _)| *i != k)
                .map(|(_, l)| *l)
                .collect();
            kept.join("\n") + "\n"
        }
        2 => {
            let k = rng.below(lines.len());
            let mut doubled = lines.clone();
            doubled.insert(k, lines[k]);
            doubled.join("\n") + "\n"
        }
        _ => {
            let mut cut = rng.below(text.len());
            while !text.is_char_boundary(cut) {
                cut -= 1;
            }
            text[..cut].to_string()
        }
    }
}

/// Byte ranges of the numbers in `text` (digits with an optional sign, point and exponent),
/// outside comments.
fn number_spans(text: &str) -> Vec<(usize, usize)> {
    let bytes = text.as_bytes();
    let mut spans = Vec::new();
    let mut i = 0;
    let mut in_comment = false;
    while i < bytes.len() {
        let c = bytes[i];
        if c == b'\n' {
            in_comment = false;
        } else if c == b'!' {
            in_comment = true;
        }
        let starts = !in_comment
            && c.is_ascii_digit()
            && (i == 0 || !(bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'.'));
        if starts {
            let start = if i > 0 && bytes[i - 1] == b'-' {
                i - 1
            } else {
                i
            };
            let mut end = i;
            while end < bytes.len()
                && (bytes[end].is_ascii_digit() || matches!(bytes[end], b'.' | b'E' | b'e'))
            {
                end += 1;
            }
            spans.push((start, end));
            i = end;
            continue;
        }
        i += 1;
    }
    spans
}

/// Example directories left out of the mutated corpus: the chain drive's rollers sit 1 µm off
/// their teeth, so most of its mutations start them touching exactly, where the exact engine
/// slices the grazing cylinder pairs at great cost (docs/examples.md, *Many parts*); its statements
/// (REVOLUTE loops, SFORCE, cylinder CONTACTs) are mutated in the other examples.
const NOT_MUTATED: [&str; 1] = ["chain_sprockets"];

fn example_datasets() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
    let mut found: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| {
            let sub = e.ok()?.path();
            if NOT_MUTATED.iter().any(|n| sub.ends_with(n)) {
                return None;
            }
            let adm = std::fs::read_dir(&sub).ok()?.find_map(|f| {
                let p = f.ok()?.path();
                (p.extension()? == "adm").then_some(p)
            })?;
            Some(adm)
        })
        .collect();
    found.sort();
    found
}

#[test]
fn mutated_example_datasets_check_and_run_without_a_panic() {
    let options = RunOptions {
        end: Some(0.02),
        dtout: Some(0.01),
        ..RunOptions::default()
    };
    let (mut checked, mut ran) = (0, 0);
    let mut failed = Vec::new();
    for path in example_datasets() {
        let text = std::fs::read_to_string(&path).unwrap();
        // Each example its own sequence, from its file name: adding an example changes no
        // other example's mutations.
        let name = path.file_name().unwrap().to_string_lossy();
        let seed = name.bytes().fold(0x9E37_79B9_7F4A_7C15_u64, |h, b| {
            (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01B3)
        });
        let mut rng = Seeded(seed);
        for round in 0..40 {
            let mutated = mutate(&text, &mut rng);
            let loaded = contact::dataset::read_str(&mutated, &path, None);
            let library = loaded.model.preferences.geometry_library;
            let engine = build_engine(library, FacetingTolerance::new(300.0028).unwrap());
            let _ = check_contacts(&loaded.model, engine.as_ref());
            checked += 1;
            if loaded.has_errors() || library == GeometryLibrary::Faceted && round % 2 == 1 {
                continue;
            }
            match run_model(&loaded.model, &path, &options, &mut Discard) {
                Ok(_) => ran += 1,
                Err(e) => {
                    ran += 1;
                    failed.push(format!("{}: {e}", path.display()));
                }
            }
        }
    }
    println!(
        "{checked} mutated datasets checked, {ran} run, {} of them stopped by an error",
        failed.len()
    );
    for f in failed.iter().take(5) {
        println!("  {}", f.chars().take(200).collect::<String>());
    }
    assert!(checked >= 400 && ran >= 100, "{checked} checked, {ran} run");
}
