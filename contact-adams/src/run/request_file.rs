//! Request output files: `<model>.req` in Adams' request-file layout, and `requests.csv`.
//!
//! `<model>.req` (written only when the dataset or command file says `OUTPUT/REQSAVE`, as
//! Adams writes its `.req` only then) is fixed-format ASCII, line for line as Adams writes it:
//!
//! 1. ` A.R3    YYYY-MM-DD hh:mm:ss               0         0  3D` (the run's UTC date);
//! 2. the dataset title, padded to 80 columns;
//! 3. `N` (I5), five blanks, the units tag (`M_KGS_N_RACA` for N, kg, m, s), a blank and the
//!    scale factor `1.000000000000000E+00`;
//! 4. per request, in id order: `ID TYPE I J NWORDS` (`1X,I10,4(4X,I10)`), then the COMMENT
//!    padded with blanks to `NWORDS × 4` characters (`NWORDS = ⌈len/4⌉`);
//! 5. per output frame: the time (`1X,1PE13.5`), then one line of six values
//!    (`1X,6(1PE13.5)`) per request in header order.
//!
//! `requests.csv` holds the same values at full precision: `time,id,kind,c1,…,c6`.

use super::requests::{RequestKind, RequestSet};
use contact_core::Units;
use std::fmt::Write as _;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::time::SystemTime;

/// What the request files need besides the requests.
#[derive(Debug, Clone)]
pub struct RequestOutput {
    /// The requests.
    pub set: RequestSet,
    /// The dataset's title line.
    pub title: String,
    /// The units tag of the `.req` header.
    pub units_tag: String,
    /// Whether `<model>.req` is written (OUTPUT/REQSAVE).
    pub reqsave: bool,
    /// The `.req` file's name (`<model>.req`, the dataset's file stem).
    pub file_name: String,
}

/// The request files of one run, open for writing.
#[derive(Debug)]
pub struct RequestWriter {
    output: RequestOutput,
    csv: BufWriter<File>,
    req: Option<BufWriter<File>>,
    line: String,
}

impl RequestWriter {
    /// Creates `requests.csv` (and `<model>.req` when REQSAVE) in `dir`, with their headers.
    pub fn create(dir: &Path, output: RequestOutput) -> std::io::Result<Self> {
        let open = |name: &str| -> std::io::Result<BufWriter<File>> {
            let path: PathBuf = dir.join(name);
            File::create(&path)
                .map(BufWriter::new)
                .map_err(|e| std::io::Error::new(e.kind(), format!("{}: {e}", path.display())))
        };
        let mut csv = open("requests.csv")?;
        writeln!(csv, "time,id,kind,c1,c2,c3,c4,c5,c6")?;
        let req = if output.reqsave {
            let mut req = open(&output.file_name)?;
            req.write_all(header(&output, SystemTime::now()).as_bytes())?;
            Some(req)
        } else {
            None
        };
        Ok(Self {
            output,
            csv,
            req,
            line: String::new(),
        })
    }

    /// The elements switched off from the next frame on.
    pub fn elements_switched(&mut self, inactive: &crate::run::active::Inactive) {
        self.output.set.switch_off(inactive);
    }

    /// Evaluates and writes every request at one output frame.
    pub fn write(&mut self, frame: &contact_solver::simulate::Frame) -> std::io::Result<()> {
        let values = self
            .output
            .set
            .evaluate(frame)
            .map_err(std::io::Error::other)?;
        let t = frame.t;
        for (r, v) in self.output.set.requests.iter().zip(&values) {
            writeln!(
                self.csv,
                "{t:?},{},{},{:?},{:?},{:?},{:?},{:?},{:?}",
                r.id,
                r.kind.name(),
                v[0],
                v[1],
                v[2],
                v[3],
                v[4],
                v[5]
            )?;
        }
        if let Some(req) = &mut self.req {
            self.line.clear();
            let _ = writeln!(self.line, " {:>13}", fortran_e(t));
            for v in &values {
                self.line.push(' ');
                for x in v {
                    let _ = write!(self.line, "{:>13}", fortran_e(*x));
                }
                self.line.push('\n');
            }
            req.write_all(self.line.as_bytes())?;
        }
        Ok(())
    }

    /// Writes out everything so far.
    pub fn flush(&mut self) -> std::io::Result<()> {
        self.csv.flush()?;
        if let Some(req) = &mut self.req {
            req.flush()?;
        }
        Ok(())
    }

    /// Whether `<model>.req` is being written.
    pub fn writes_req(&self) -> bool {
        self.req.is_some()
    }

    /// The `.req` file's name.
    pub fn req_name(&self) -> &str {
        &self.output.file_name
    }
}

/// The `.req` header: tag line, title, request count and units, two lines per request.
pub fn header(output: &RequestOutput, now: SystemTime) -> String {
    let mut s = String::new();
    let _ = writeln!(s, " A.R3    {}{:>16}{:>10}  3D", utc_date_time(now), 0, 0);
    let _ = writeln!(s, "{:<80}", output.title);
    let _ = writeln!(
        s,
        "{:>5}     {} 1.000000000000000E+00",
        output.set.requests.len(),
        output.units_tag
    );
    for r in &output.set.requests {
        let words = r.comment.chars().count().div_ceil(4);
        let _ = writeln!(
            s,
            " {:>10}    {:>10}    {:>10}    {:>10}    {:>10}",
            r.id,
            r.kind.type_number(),
            if r.kind == RequestKind::Expressions {
                0
            } else {
                r.markers[0]
            },
            if r.kind == RequestKind::Expressions {
                0
            } else {
                r.markers[1]
            },
            words
        );
        let _ = writeln!(s, "{:<width$}", r.comment, width = 4 * words);
    }
    s
}

/// `x` as Fortran `1PE13.5` writes it, without the padding: `-9.23880E-01`, `0.00000E+00`;
/// an exponent beyond ±99 is written without the E, as Fortran does (`1.00000-100`), so the
/// field stays 13 wide and blank-separated.
pub fn fortran_e(x: f64) -> String {
    if x == 0.0 {
        return "0.00000E+00".into();
    }
    if !x.is_finite() {
        return format!("{x}");
    }
    let text = format!("{x:.5e}");
    let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
    let exponent: i32 = exponent.parse().unwrap_or(0);
    let sign = if exponent < 0 { '-' } else { '+' };
    if exponent.abs() > 99 {
        // Fortran drops the E to keep the field 13 wide: `-8.69930-105`.
        return format!("{mantissa}{sign}{:03}", exponent.abs());
    }
    format!("{mantissa}E{sign}{:02}", exponent.abs())
}

/// The units tag of a `.req` header: length, mass and time, force, then `RACA` (radians):
/// `M_KGS_N_RACA` for N, kg, m, s (the tag Adams wrote in every request file seen), the other
/// units by their Adams names; a unit without one is `USER`.
pub fn units_tag(units: &Units) -> String {
    let name = |value: f64, table: &[(f64, &'static str)]| {
        table
            .iter()
            .find(|(v, _)| (value / v - 1.0).abs() < 1e-9)
            .map_or("USER", |(_, n)| n)
    };
    let length = name(
        units.length_metre,
        &[
            (1.0, "M"),
            (1e-3, "MM"),
            (1e-2, "CM"),
            (1e3, "KM"),
            (0.0254, "IN"),
            (0.3048, "FT"),
        ],
    );
    let mass = name(
        units.mass_kg,
        &[
            (1.0, "KG"),
            (1e-3, "G"),
            (1e3, "MG"),
            (0.45359237, "LBM"),
            (14.593902937206364, "SLUG"),
        ],
    );
    let time = name(
        units.time_second,
        &[(1.0, "S"), (1e-3, "MS"), (60.0, "MIN"), (3600.0, "H")],
    );
    let force = name(
        units.force_newton,
        &[
            (1.0, "N"),
            (1e3, "KN"),
            (1e-3, "MN"),
            (1e-5, "DYNE"),
            (4.4482216152605, "LBF"),
            (9.80665, "KGF"),
        ],
    );
    format!("{length}_{mass}{time}_{force}_RACA")
}

/// `YYYY-MM-DD hh:mm:ss` (UTC) of `t`.
fn utc_date_time(t: SystemTime) -> String {
    let secs = t
        .duration_since(SystemTime::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    let (days, rest) = (secs / 86_400, secs % 86_400);
    // Howard Hinnant's civil-from-days.
    let z = days as i64 + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    format!(
        "{year:04}-{month:02}-{day:02} {:02}:{:02}:{:02}",
        rest / 3600,
        rest % 3600 / 60,
        rest % 60
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Duration;

    #[test]
    fn fortran_e_matches_adams_columns() {
        assert_eq!(fortran_e(3.0), "3.00000E+00");
        assert_eq!(fortran_e(-0.923880), "-9.23880E-01");
        assert_eq!(fortran_e(2.929187e-16), "2.92919E-16");
        assert_eq!(fortran_e(0.0), "0.00000E+00");
        assert_eq!(fortran_e(-0.0), "0.00000E+00");
        assert_eq!(fortran_e(1e-100), "1.00000-100");
        assert_eq!(fortran_e(-8.6993e-105), "-8.69930-105");
        assert_eq!(fortran_e(2.5e120), "2.50000+120");
        assert_eq!(format!(" {:>13}", fortran_e(0.01)), "   1.00000E-02");
    }

    #[test]
    fn dates_and_units() {
        // 2014-11-18 09:13:47 UTC, the date of Revolute_Case02's request file.
        let t = SystemTime::UNIX_EPOCH + Duration::from_secs(1_416_302_027);
        assert_eq!(utc_date_time(t), "2014-11-18 09:13:47");
        assert_eq!(units_tag(&Units::MKS), "M_KGS_N_RACA");
        assert_eq!(units_tag(&Units::MMKS), "MM_KGS_N_RACA");
    }
}
