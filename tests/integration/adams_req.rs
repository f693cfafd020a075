//! A strict reader of Adams request files (`.req`), the layout `tests/data/PROVENANCE.md`
//! describes (and `contact run` writes with OUTPUT/REQSAVE): three header lines, two lines per
//! request (`ID TYPE I J NWORDS`, then the COMMENT padded to `NWORDS × 4` characters), then per
//! output time a time line and one line of six values per request. LF or CRLF line endings.
//!
//! Strict: a comment of the wrong length, a line without six values, a frame cut short or a
//! time that goes back is an error naming the line.

/// One request's header.
#[derive(Debug, Clone, PartialEq)]
pub struct ReqHeader {
    /// REQUEST id.
    pub id: u32,
    /// 1 displacement, 2 velocity, 3 acceleration, 4 force, 5 expressions.
    pub kind: u32,
    /// I marker (0 for expressions).
    pub i: u32,
    /// J marker (0 for expressions).
    pub j: u32,
    /// The COMMENT, trailing blanks removed.
    pub comment: String,
}

/// A whole request file.
#[derive(Debug, Clone, PartialEq)]
pub struct ReqFile {
    /// The title line, trailing blanks removed.
    pub title: String,
    /// The units tag (`M_KGS_N_RACA`).
    pub units: String,
    /// The requests, in file order.
    pub requests: Vec<ReqHeader>,
    /// The output times.
    pub times: Vec<f64>,
    /// `values[frame][request]`: the six columns.
    pub values: Vec<Vec<[f64; 6]>>,
}

/// Parses `text`; the error names the 1-based line.
pub fn parse(text: &str) -> Result<ReqFile, String> {
    let lines: Vec<&str> = text
        .split('\n')
        .map(|l| l.strip_suffix('\r').unwrap_or(l))
        .collect();
    let line = |k: usize| -> Result<&str, String> {
        lines
            .get(k)
            .copied()
            .ok_or_else(|| format!("line {}: the file ends here", k + 1))
    };
    if !line(0)?.starts_with(" A.R3 ") {
        return Err("line 1: not an Adams request file (no ' A.R3' tag)".into());
    }
    let title = line(1)?.trim_end().to_owned();
    let third: Vec<&str> = line(2)?.split_whitespace().collect();
    let [count, units, _scale] = third[..] else {
        return Err(format!(
            "line 3: expected 'N UNITS SCALE', found {:?}",
            line(2)?
        ));
    };
    let count: usize = count
        .parse()
        .map_err(|_| format!("line 3: request count {count:?}"))?;
    let mut requests = Vec::new();
    for k in 0..count {
        let at = 3 + 2 * k;
        let fields: Vec<u32> = line(at)?
            .split_whitespace()
            .map(|f| {
                f.parse()
                    .map_err(|_| format!("line {}: {f:?} is not an integer", at + 1))
            })
            .collect::<Result<_, _>>()?;
        let [id, kind, i, j, words] = fields[..] else {
            return Err(format!("line {}: expected five integers", at + 1));
        };
        let comment = line(at + 1)?;
        if comment.chars().count() != 4 * words as usize {
            return Err(format!(
                "line {}: the comment has {} characters, NWORDS = {words} says {}",
                at + 2,
                comment.chars().count(),
                4 * words
            ));
        }
        requests.push(ReqHeader {
            id,
            kind,
            i,
            j,
            comment: comment.trim_end().to_owned(),
        });
    }
    let (mut times, mut values) = (Vec::new(), Vec::new());
    let mut at = 3 + 2 * count;
    while at < lines.len() && !lines[at].trim().is_empty() {
        let t: f64 = lines[at]
            .trim()
            .parse()
            .map_err(|_| format!("line {}: {:?} is not a time", at + 1, lines[at]))?;
        if times.last().is_some_and(|&last| t < last) {
            return Err(format!("line {}: time {t} goes back", at + 1));
        }
        let mut frame = Vec::new();
        let number = |f: &str, n: usize| {
            fortran_number(f).ok_or_else(|| format!("line {}: {f:?} is not a number", n + 1))
        };
        for k in 0..count {
            let n = at + 1 + k;
            let row: Vec<f64> = line(n)?
                .split_whitespace()
                .map(|f| number(f, n))
                .collect::<Result<_, _>>()?;
            let row: [f64; 6] = row
                .try_into()
                .map_err(|r: Vec<f64>| format!("line {}: {} values, not 6", n + 1, r.len()))?;
            frame.push(row);
        }
        times.push(t);
        values.push(frame);
        at += count + 1;
    }
    if lines[at..].iter().any(|l| !l.trim().is_empty()) {
        return Err(format!("line {}: text after the last frame", at + 1));
    }
    Ok(ReqFile {
        title,
        units: units.to_owned(),
        requests,
        times,
        values,
    })
}

/// A Fortran E-format number: `1.5E+02`, or `1.5+102` (an exponent of three digits, written
/// without the E).
fn fortran_number(text: &str) -> Option<f64> {
    if let Ok(v) = text.parse() {
        return Some(v);
    }
    let split = text.rfind(['+', '-']).filter(|&k| k > 0)?;
    let (mantissa, exponent) = text.split_at(split);
    mantissa.parse::<f64>().ok()?;
    exponent.parse::<i32>().ok()?;
    format!("{mantissa}e{exponent}").parse().ok()
}

/// Reads and parses the file at `path`.
pub fn read(path: &std::path::Path) -> ReqFile {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    parse(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

#[test]
fn every_adams_request_file_parses_whole() {
    let dir = crate::data_dir().join("adams-tests");
    let mut read_files = 0;
    for case in std::fs::read_dir(&dir).unwrap() {
        let case = case.unwrap().path();
        for file in std::fs::read_dir(&case).unwrap() {
            let path = file.unwrap().path();
            if path.extension().is_some_and(|e| e == "req") {
                let req = read(&path);
                let n = req.requests.len();
                assert!(n == 5 || n == 11, "{}: {n} requests", path.display());
                assert_eq!(req.times.len(), 501, "{}", path.display());
                assert_eq!(req.times[500], 5.0);
                assert_eq!(req.units, "M_KGS_N_RACA");
                let lines = std::fs::read_to_string(&path).unwrap().lines().count();
                assert_eq!(lines, 3 + 2 * n + 501 * (n + 1), "{}", path.display());
                read_files += 1;
            }
        }
    }
    assert_eq!(read_files, 6);
}

#[test]
fn the_reader_refuses_damaged_files() {
    let good = " A.R3    2014-11-18 09:13:47               0         0  3D\r\ntitle\r\n    1     M_KGS_N_RACA 1.000000000000000E+00\r\n          1             1           201           101             1\r\nDISP\r\n   0.00000E+00\r\n   1.00000E+00  2.00000E+00  3.00000E+00  0.00000E+00  0.00000E+00  0.00000E+00\r\n";
    let req = parse(good).unwrap();
    assert_eq!(req.values[0][0][2], 3.0);
    assert_eq!(req.requests[0].comment, "DISP");
    let short_comment = good.replace("DISP\r", "DIS\r");
    assert!(parse(&short_comment).unwrap_err().starts_with("line 5:"));
    let five_values = good.replace("  0.00000E+00  0.00000E+00\r\n", "  0.00000E+00\r\n");
    assert!(parse(&five_values).unwrap_err().contains("5 values"));
    let tiny = good.replace("  3.00000E+00", " -8.69930-105");
    assert_eq!(parse(&tiny).unwrap().values[0][0][2], -8.6993e-105);
    let cut = &good[..good.len() - 90];
    assert!(parse(cut).is_err());
}
