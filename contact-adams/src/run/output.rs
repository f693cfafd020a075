//! Run results streamed to a directory as they are computed:
//!
//! - `parts.csv`: per output step and moving part, the CM position, orientation quaternion,
//!   velocity and angular velocity (world frame);
//! - `contacts.csv`: per output step and contact, the points on I and J, the normal (J into I),
//!   penetration and its rate, normal force, friction force and torque, area;
//! - `frames.jsonl`: the same, one JSON object per output step (JSON lines, so a run cut short
//!   leaves every completed line readable);
//! - `requests.csv` and, with OUTPUT/REQSAVE, `<model>.req` when the model has REQUESTs
//!   ([`request_file`](super::request_file));
//! - at the end (also after a failure): `contact_force.svg` and `penetration.svg` against time,
//!   one curve per CONTACT, and `summary.json`.
//!
//! The streams are flushed at most every [`FLUSH_INTERVAL`] of wall time (three write system
//! calls per output step cost more than the dynamics of a small model) and always by
//! [`ResultWriter::finish`], which a run calls whether it succeeded or failed (a writer dropped
//! without it flushes too): what was computed is on disk when the run stops, and a run being
//! watched sees its files grow while it runs. Frames are serialized straight from the states,
//! without building JSON values.

use super::request_file::{RequestOutput, RequestWriter};
use crate::svg_plot::{DecimatedSeries, MAX_SERIES, Plot, Scale, Series};
use contact_solver::mbs::PartId;
use contact_solver::simulate::Frame;
use serde::Serialize;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// The longest wall time a computed output step waits in memory before it is written out.
pub const FLUSH_INTERVAL: Duration = Duration::from_millis(50);

/// One part in a `frames.jsonl` line.
#[derive(Debug, Serialize)]
struct PartLine {
    part: u32,
    position: [f64; 3],
    quaternion: [f64; 4],
    velocity: [f64; 3],
    angular_velocity: [f64; 3],
}

/// One contact in a `frames.jsonl` line.
#[derive(Debug, Serialize)]
struct ContactLine<'a> {
    contact: &'a str,
    index: usize,
    point_i: [f64; 3],
    point_j: [f64; 3],
    normal: [f64; 3],
    penetration: f64,
    penetration_rate: f64,
    normal_force: f64,
    friction_force: [f64; 3],
    friction_torque: f64,
    area: f64,
}

/// One `frames.jsonl` line.
#[derive(Debug, Serialize)]
struct FrameLine<'a> {
    time: f64,
    parts: &'a [PartLine],
    contacts: &'a [ContactLine<'a>],
}

/// Writes a run's frames into a directory.
#[derive(Debug)]
pub struct ResultWriter {
    dir: PathBuf,
    parts_csv: BufWriter<File>,
    contacts_csv: BufWriter<File>,
    frames: BufWriter<File>,
    part_ids: Vec<(PartId, u32)>,
    contact_names: Vec<String>,
    force_series: Vec<DecimatedSeries>,
    depth_series: Vec<DecimatedSeries>,
    parts_line: Vec<PartLine>,
    last_flush: Instant,
    requests: Option<RequestWriter>,
}

impl ResultWriter {
    /// Creates `dir` (and parents) and the streamed files, with their headers.
    pub fn create(
        dir: &Path,
        part_ids: Vec<(PartId, u32)>,
        contact_names: Vec<String>,
        requests: Option<RequestOutput>,
    ) -> std::io::Result<Self> {
        std::fs::create_dir_all(dir).map_err(|e| naming(dir, e))?;
        let open = |name: &str| {
            let path = dir.join(name);
            File::create(&path)
                .map(BufWriter::new)
                .map_err(|e| naming(&path, e))
        };
        let mut parts_csv = open("parts.csv")?;
        writeln!(parts_csv, "time,part,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz")?;
        let mut contacts_csv = open("contacts.csv")?;
        writeln!(
            contacts_csv,
            "time,contact,index,geometry_i,geometry_j,point_i_x,point_i_y,point_i_z,point_j_x,point_j_y,point_j_z,normal_x,normal_y,normal_z,penetration,penetration_rate,normal_force,friction_x,friction_y,friction_z,friction_torque,area"
        )?;
        let n = contact_names.len();
        Ok(Self {
            dir: dir.to_path_buf(),
            parts_csv,
            contacts_csv,
            frames: open("frames.jsonl")?,
            part_ids,
            contact_names,
            force_series: vec![DecimatedSeries::new(); n],
            depth_series: vec![DecimatedSeries::new(); n],
            parts_line: Vec::new(),
            last_flush: Instant::now(),
            requests: requests
                .map(|r| RequestWriter::create(dir, r))
                .transpose()?,
        })
    }

    /// The directory written to.
    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// The elements switched off from the next frame on (the requests reading their forces
    /// read zero while they are off).
    pub fn elements_switched(&mut self, inactive: &crate::run::active::Inactive) {
        if let Some(requests) = &mut self.requests {
            requests.elements_switched(inactive);
        }
    }

    /// Writes one frame to every stream (flushed at most every [`FLUSH_INTERVAL`]).
    pub fn write(&mut self, frame: &Frame) -> std::io::Result<()> {
        let t = frame.t;
        let mut parts_json = std::mem::take(&mut self.parts_line);
        parts_json.clear();
        for &(id, adams) in &self.part_ids {
            let s = &frame.parts[id.0];
            let p = s.pose_w.translation.vector;
            let q = s.pose_w.rotation.quaternion();
            let (v, w) = (s.velocity_w, s.angular_velocity_w);
            writeln!(
                self.parts_csv,
                "{t:?},{adams},{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?}",
                p.x, p.y, p.z, q.w, q.i, q.j, q.k, v.x, v.y, v.z, w.x, w.y, w.z
            )?;
            parts_json.push(PartLine {
                part: adams,
                position: [p.x, p.y, p.z],
                quaternion: [q.w, q.i, q.j, q.k],
                velocity: [v.x, v.y, v.z],
                angular_velocity: [w.x, w.y, w.z],
            });
        }
        let mut contacts_json = Vec::new();
        for (k, reports) in frame.contacts.iter().enumerate() {
            let name = &self.contact_names[k];
            let (mut total, mut deepest) = (0.0, 0.0_f64);
            for (index, r) in reports.iter().enumerate() {
                let c = &r.contact;
                let (pi, pj, n, f) = (c.point_i_w, c.point_j_w, c.normal_w, r.friction_force_w);
                writeln!(
                    self.contacts_csv,
                    "{t:?},{name},{index},{},{},{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?},{:?}",
                    c.geometry_i,
                    c.geometry_j,
                    pi.x,
                    pi.y,
                    pi.z,
                    pj.x,
                    pj.y,
                    pj.z,
                    n.x,
                    n.y,
                    n.z,
                    c.penetration,
                    r.penetration_rate,
                    r.normal_force,
                    f.x,
                    f.y,
                    f.z,
                    r.friction_torque,
                    c.area
                )?;
                contacts_json.push(ContactLine {
                    contact: name,
                    index,
                    point_i: [pi.x, pi.y, pi.z],
                    point_j: [pj.x, pj.y, pj.z],
                    normal: [n.x, n.y, n.z],
                    penetration: c.penetration,
                    penetration_rate: r.penetration_rate,
                    normal_force: r.normal_force,
                    friction_force: [f.x, f.y, f.z],
                    friction_torque: r.friction_torque,
                    area: c.area,
                });
                total += r.normal_force;
                deepest = deepest.max(c.penetration);
            }
            self.force_series[k].push((t, total));
            self.depth_series[k].push((t, deepest));
        }
        serde_json::to_writer(
            &mut self.frames,
            &FrameLine {
                time: t,
                parts: &parts_json,
                contacts: &contacts_json,
            },
        )?;
        self.parts_line = parts_json;
        writeln!(self.frames)?;
        if let Some(requests) = &mut self.requests {
            requests.write(frame)?;
        }
        if self.last_flush.elapsed() >= FLUSH_INTERVAL {
            self.flush()?;
        }
        Ok(())
    }

    /// Writes out everything computed so far.
    pub fn flush(&mut self) -> std::io::Result<()> {
        self.last_flush = Instant::now();
        self.parts_csv.flush()?;
        self.contacts_csv.flush()?;
        if let Some(requests) = &mut self.requests {
            requests.flush()?;
        }
        self.frames.flush()
    }

    /// The request files written, by name (`requests.csv`, and `<model>.req` with REQSAVE).
    pub fn request_files(&self) -> Vec<String> {
        match &self.requests {
            Some(r) if r.writes_req() => vec!["requests.csv".into(), r.req_name().into()],
            Some(_) => vec!["requests.csv".into()],
            None => Vec::new(),
        }
    }

    /// Writes the plots and `summary.json` (call after the run, whether it succeeded or not).
    pub fn finish(&mut self, summary: &serde_json::Value) -> std::io::Result<Vec<PathBuf>> {
        self.flush()?;
        let series = |data: &[DecimatedSeries]| -> Vec<Series> {
            self.contact_names
                .iter()
                .zip(data)
                .map(|(name, points)| Series {
                    name: name.clone(),
                    points: points.points(),
                    line: true,
                })
                .collect()
        };
        let force = Plot {
            title: "Contact normal force".into(),
            x_label: "time".into(),
            y_label: "normal force (sum over the contact's regions)".into(),
            x_scale: Scale::Linear,
            y_scale: Scale::Linear,
            series: series(&self.force_series),
            note: None,
        };
        let depth = Plot {
            title: "Penetration".into(),
            x_label: "time".into(),
            y_label: "largest penetration".into(),
            x_scale: Scale::Linear,
            y_scale: Scale::Linear,
            series: series(&self.depth_series),
            note: None,
        };
        let mut written = Vec::new();
        for (name, mut plot) in [("contact_force.svg", force), ("penetration.svg", depth)] {
            let (left_out, silent) = plot.keep_largest(MAX_SERIES);
            if left_out > 0 {
                plot.note = Some(format!(
                    "+ {left_out} more ({silent} zero throughout): see contacts.csv"
                ));
            }
            let text = plot.to_svg();
            let path = self.dir.join(name);
            std::fs::write(&path, text).map_err(|e| naming(&path, e))?;
            written.push(path);
        }
        // Written to a temporary file and renamed: a reader never sees half a summary.
        let path = self.dir.join("summary.json");
        let partial = self.dir.join("summary.json.partial");
        std::fs::write(
            &partial,
            serde_json::to_string_pretty(summary).map_err(std::io::Error::other)?,
        )
        .map_err(|e| naming(&partial, e))?;
        std::fs::rename(&partial, &path).map_err(|e| naming(&path, e))?;
        written.push(path);
        Ok(written)
    }
}

/// `error` with the path it concerns in its message (the system's message names none).
fn naming(path: &Path, error: std::io::Error) -> std::io::Error {
    std::io::Error::new(error.kind(), format!("{}: {error}", path.display()))
}
