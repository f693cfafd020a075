//! The 4-slot external Geneva drive of `examples/geneva/`: its dimensions, and the closed
//! triangle meshes of its driver (a crank plate carrying a pin) and its slotted wheel, written as
//! binary STL.
//!
//! Frames: the driver's mesh is in the driver's frame (axis at the origin, +z), the wheel's in
//! the wheel's (axis at the origin, +z); in the assembly the wheel's axis is at
//! `(centre_distance, 0, 0)`. The wheel occupies `0 ≤ z ≤ wheel_thickness`; the pin spans it
//! with a margin on each side and the crank plate runs below it, so only the pin's side touches
//! the wheel. Slot `k` of the wheel points along `45° + k·90°`; the pin starts at crank angle
//! `crank_start_angle` from the line of centres (the +x axis), so that with the driver turning
//! counter-clockwise it enters the slot at 225° when the crank reaches −45°.
//!
//! The generation is deterministic: the same dimensions write the same bytes (a test regenerates
//! the committed meshes and compares).

use nalgebra::Vector3;
use std::f64::consts::FRAC_PI_4;
use std::path::Path;

/// Dimensions of the drive, in the model's length unit (metres in the example).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GenevaDimensions {
    /// Distance `a` between the driver's and the wheel's axes.
    pub centre_distance: f64,
    /// Radius of the pin.
    pub pin_radius: f64,
    /// Slot width minus the pin's diameter.
    pub clearance: f64,
    /// Radius at which the slots end (the pin comes no nearer than `a − r − pin_radius`).
    pub slot_bottom_radius: f64,
    /// Thickness of the wheel.
    pub wheel_thickness: f64,
    /// The crank's angle from the line of centres in the driver's mesh (radians).
    pub crank_start_angle: f64,
    /// Sides of the pin's polygon (its chord deviation is `pin_radius·(1 − cos(π/n))`).
    pub pin_segments: usize,
    /// Segments of each rim arc between two slots.
    pub rim_segments: usize,
}

impl Default for GenevaDimensions {
    /// The example's drive: `a` = 0.1, a 6 mm pin with 1 mm clearance, a 10 mm wheel, the crank
    /// 0.3 rad before engagement.
    fn default() -> Self {
        Self {
            centre_distance: 0.1,
            pin_radius: 0.006,
            clearance: 0.001,
            slot_bottom_radius: 0.0203,
            wheel_thickness: 0.01,
            crank_start_angle: -FRAC_PI_4 - 0.3,
            pin_segments: 96,
            rim_segments: 12,
        }
    }
}

/// One triangle, counter-clockwise seen from outside.
pub type Triangle = [Vector3<f64>; 3];

impl GenevaDimensions {
    /// The crank radius `r = a·sin(π/4)` of a 4-slot drive (the pin enters the slots
    /// tangentially).
    pub fn crank_radius(&self) -> f64 {
        self.centre_distance * FRAC_PI_4.sin()
    }

    /// The wheel's rim radius `a·cos(π/4)`: where the pin enters and leaves a slot.
    pub fn rim_radius(&self) -> f64 {
        self.centre_distance * FRAC_PI_4.cos()
    }

    /// Margin of the pin beyond the wheel's faces, and thickness of the crank plate.
    fn margin(&self) -> f64 {
        0.2 * self.wheel_thickness
    }

    /// The driver: a crank plate below the wheel's plane and the pin standing on it (two closed
    /// shells in one mesh).
    pub fn driver_triangles(&self) -> Vec<Triangle> {
        let (g, h) = (self.margin(), self.wheel_thickness);
        let (c, s) = (self.crank_start_angle.cos(), self.crank_start_angle.sin());
        let r = self.crank_radius();
        let (along, across) = ([c, s], [-s, c]);
        let half_width = 1.5 * self.pin_radius;
        let at = |u: f64, v: f64| [u * along[0] + v * across[0], u * along[1] + v * across[1]];
        let plate = [
            at(-half_width, -half_width),
            at(r + half_width, -half_width),
            at(r + half_width, half_width),
            at(-half_width, half_width),
        ];
        let n = self.pin_segments;
        let pin: Vec<[f64; 2]> = (0..n)
            .map(|k| {
                let phi = 2.0 * std::f64::consts::PI * k as f64 / n as f64;
                let p = at(r, 0.0);
                [
                    p[0] + self.pin_radius * phi.cos(),
                    p[1] + self.pin_radius * phi.sin(),
                ]
            })
            .collect();
        let mut out = extrude(&plate, -3.0 * g, -g);
        out.extend(extrude(&pin, -g, h + g));
        out
    }

    /// The wheel: a disc of the rim radius with four radial slots of width
    /// `2·pin_radius + clearance` down to `slot_bottom_radius`.
    pub fn wheel_triangles(&self) -> Vec<Triangle> {
        let rim = self.rim_radius();
        let half = self.pin_radius + 0.5 * self.clearance;
        let mouth = (rim * rim - half * half).sqrt();
        let opening = (half / rim).asin();
        let mut outline = Vec::new();
        for k in 0..4 {
            let phi = FRAC_PI_4 + k as f64 * std::f64::consts::FRAC_PI_2;
            let (u, v) = ([phi.cos(), phi.sin()], [-phi.sin(), phi.cos()]);
            let at = |a: f64, b: f64| [a * u[0] + b * v[0], a * u[1] + b * v[1]];
            outline.push(at(mouth, -half));
            outline.push(at(self.slot_bottom_radius, -half));
            outline.push(at(self.slot_bottom_radius, half));
            outline.push(at(mouth, half));
            // The rim arc to the next slot, its end points excluded (they are slot corners).
            let (from, to) = (phi + opening, phi + std::f64::consts::FRAC_PI_2 - opening);
            for j in 1..self.rim_segments {
                let angle = from + (to - from) * j as f64 / self.rim_segments as f64;
                outline.push([rim * angle.cos(), rim * angle.sin()]);
            }
        }
        extrude(&outline, 0.0, self.wheel_thickness)
    }

    /// Writes `geneva_driver.stl` and `geneva_wheel.stl` (binary) into `dir`.
    pub fn write_meshes(&self, dir: &Path) -> std::io::Result<()> {
        write_binary_stl(&dir.join("geneva_driver.stl"), &self.driver_triangles())?;
        write_binary_stl(&dir.join("geneva_wheel.stl"), &self.wheel_triangles())
    }
}

/// Writes triangles as binary STL (single precision, as the format stores them).
pub fn write_binary_stl(path: &Path, triangles: &[Triangle]) -> std::io::Result<()> {
    let to_f32 = |v: &Vector3<f64>| [v.x as f32, v.y as f32, v.z as f32];
    let mesh: Vec<stl_io::Triangle> = triangles
        .iter()
        .map(|t| {
            let n = (t[1] - t[0])
                .cross(&(t[2] - t[0]))
                .try_normalize(0.0)
                .unwrap_or_else(Vector3::z);
            stl_io::Triangle {
                normal: stl_io::Normal::new(to_f32(&n)),
                vertices: t.map(|v| stl_io::Vertex::new(to_f32(&v))),
            }
        })
        .collect();
    let mut file = std::io::BufWriter::new(std::fs::File::create(path)?);
    stl_io::write_stl(&mut file, mesh.iter())?;
    std::io::Write::flush(&mut file)
}

/// The closed prism over a simple counter-clockwise outline between heights `z0 < z1`: the
/// outline ear-clipped for the two caps, one quad of two triangles per side.
fn extrude(outline: &[[f64; 2]], z0: f64, z1: f64) -> Vec<Triangle> {
    let at = |p: [f64; 2], z: f64| Vector3::new(p[0], p[1], z);
    let mut out = Vec::new();
    for [a, b, c] in ear_clip(outline) {
        let (a, b, c) = (outline[a], outline[b], outline[c]);
        out.push([at(a, z1), at(b, z1), at(c, z1)]);
        out.push([at(a, z0), at(c, z0), at(b, z0)]);
    }
    for i in 0..outline.len() {
        let (a, b) = (outline[i], outline[(i + 1) % outline.len()]);
        out.push([at(a, z0), at(b, z0), at(b, z1)]);
        out.push([at(a, z0), at(b, z1), at(a, z1)]);
    }
    out
}

/// Ear clipping of a simple counter-clockwise polygon: `n − 2` triangles of indices.
fn ear_clip(outline: &[[f64; 2]]) -> Vec<[usize; 3]> {
    let cross = |o: [f64; 2], a: [f64; 2], b: [f64; 2]| {
        (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    };
    let mut left: Vec<usize> = (0..outline.len()).collect();
    let mut out = Vec::with_capacity(outline.len().saturating_sub(2));
    while left.len() > 3 {
        let n = left.len();
        let ear = (0..n).find(|&i| {
            let (a, b, c) = (left[(i + n - 1) % n], left[i], left[(i + 1) % n]);
            let (pa, pb, pc) = (outline[a], outline[b], outline[c]);
            cross(pa, pb, pc) > 0.0
                && left.iter().all(|&j| {
                    j == a
                        || j == b
                        || j == c
                        || cross(pa, pb, outline[j]) < 0.0
                        || cross(pb, pc, outline[j]) < 0.0
                        || cross(pc, pa, outline[j]) < 0.0
                })
        });
        // A simple polygon always has an ear; a degenerate one ends the clipping.
        let Some(i) = ear else { break };
        out.push([left[(i + n - 1) % n], left[i], left[(i + 1) % n]]);
        left.remove(i);
    }
    if left.len() == 3 {
        out.push([left[0], left[1], left[2]]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Volume by the divergence theorem: positive and equal to area × height for a closed,
    /// outward-oriented prism.
    fn volume(triangles: &[Triangle]) -> f64 {
        triangles
            .iter()
            .map(|[a, b, c]| a.dot(&b.cross(c)) / 6.0)
            .sum()
    }

    #[test]
    fn the_wheel_is_a_closed_prism_of_the_slotted_discs_area() {
        let d = GenevaDimensions::default();
        let rim = d.rim_radius();
        let half = d.pin_radius + 0.5 * d.clearance;
        // The disc less the slots (rectangles from the bottom to the mouth's chord); the rim
        // polygon's chords lose under 1% of the area.
        let slot = 2.0 * half * ((rim * rim - half * half).sqrt() - d.slot_bottom_radius);
        let got = volume(&d.wheel_triangles()) / d.wheel_thickness;
        let true_area = std::f64::consts::PI * rim * rim - 4.0 * slot;
        assert!(
            got > 0.0 && (got - true_area).abs() < 0.01 * true_area,
            "{got} vs {true_area}"
        );
    }

    #[test]
    fn the_driver_is_its_plate_and_pin() {
        let d = GenevaDimensions::default();
        let g = d.margin();
        let r = d.crank_radius();
        let plate = (r + 3.0 * d.pin_radius) * 3.0 * d.pin_radius * 2.0 * g;
        let n = d.pin_segments as f64;
        let pin = 0.5
            * n
            * d.pin_radius.powi(2)
            * (2.0 * std::f64::consts::PI / n).sin()
            * (d.wheel_thickness + 2.0 * g);
        let got = volume(&d.driver_triangles());
        assert!(
            (got - plate - pin).abs() < 1e-12,
            "{got} vs {}",
            plate + pin
        );
    }
}
