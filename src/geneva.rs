//! The 4-slot external Geneva drive of `examples/geneva/`: its dimensions, and the closed
//! triangle meshes of its driver (a crank plate carrying a pin, and a locking disc) and its
//! slotted wheel, written as binary STL.
//!
//! With [`GenevaDimensions::locking_disc`] the drive is locked between engagements, as a real
//! drive is (the example is not: its wheel is held by a detent SFORCE). A disc of radius
//! `R_L` about the driver's axis, in the wheel's plane, turns inside a concave arc cut into each
//! land of the wheel (radius `R_L + lock_clearance`, centred on the driver's axis when the wheel
//! rests), so the wheel cannot turn by more than about `lock_clearance/a` while it dwells. The
//! arc meets the rim `lock_tip_angle` either side of the land's middle, which sets `R_L`. Facing
//! the pin, the disc is cut away by a circle of the wheel's rim radius plus `cutout_margin`,
//! centred at the centre distance along the crank, so the wheel's tips swing through while the
//! pin drives it, and the disc locks again as the pin leaves.
//!
//! Why the example runs without it: with 0.05 mm of lock clearance the wheel rattles in the
//! lock after each index, and the faceted run took 2.1 s of wall time per simulated second
//! against 0.07 s without the disc (the contact persists, and the long thin cap triangles of
//! the disc and the wheel make every query dear). Where the disc touches a locking arc the two
//! faceted surfaces overlap in a thin crescent whose centroid lies outside it; the faceted
//! engine once measured such a region along the line through that centroid, 69 mm for an
//! overlap 0.2 mm thick, and now holds it to the convex bound `3V/|S|` (a test in
//! `tests/integration/geneva.rs`).
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
    /// Whether the drive has its locking disc (and the wheel its concave locking arcs). The
    /// example runs without (a detent SFORCE holds its wheel): the wheel rattling in the lock
    /// makes its faceted run 30 times slower (see the module docs).
    pub locking_disc: bool,
    /// Radial gap between the locking disc and the wheel's concave arcs.
    pub lock_clearance: f64,
    /// Where a land's concave arc meets the rim: this angle (radians) either side of the
    /// land's middle, seen from the wheel's axis.
    pub lock_tip_angle: f64,
    /// The locking disc's cut-out: its radius beyond the wheel's rim radius.
    pub cutout_margin: f64,
    /// Sides of the locking disc's full circle (its arc keeps its share of them).
    pub disc_segments: usize,
    /// Segments of each concave arc of the wheel.
    pub lock_segments: usize,
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
            locking_disc: false,
            lock_clearance: 1e-4,
            lock_tip_angle: 37f64.to_radians(),
            cutout_margin: 1e-3,
            disc_segments: 256,
            lock_segments: 64,
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

    /// The radius of a land's concave arc: the circle about the driver's axis (at the centre
    /// distance from the wheel's) through the rim at `lock_tip_angle` from the land's middle.
    pub fn lock_arc_radius(&self) -> f64 {
        let (a, rim) = (self.centre_distance, self.rim_radius());
        (rim * rim + a * a - 2.0 * a * rim * self.lock_tip_angle.cos()).sqrt()
    }

    /// The locking disc's radius `R_L`: the concave arcs' less the lock clearance.
    pub fn locking_disc_radius(&self) -> f64 {
        self.lock_arc_radius() - self.lock_clearance
    }

    /// The radius of the locking disc's cut-out, centred at the centre distance along the crank.
    pub fn cutout_radius(&self) -> f64 {
        self.rim_radius() + self.cutout_margin
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
        // The locking disc spans the wheel's thickness, clear of the plate below it (its own
        // closed shell: the meshes' shells do not touch).
        if self.locking_disc {
            out.extend(extrude(&self.locking_disc_outline(), -0.5 * g, h + g));
        }
        out
    }

    /// The locking disc's outline in the driver's frame, counter-clockwise: the disc's arc the
    /// long way round from one end of the cut-out to the other, then the cut-out's arc back
    /// past the axis.
    pub fn locking_disc_outline(&self) -> Vec<[f64; 2]> {
        let (a, disc, cut) = (
            self.centre_distance,
            self.locking_disc_radius(),
            self.cutout_radius(),
        );
        let along = self.crank_start_angle;
        // Where the two circles cross: this angle either side of the crank, seen from the axis.
        let half = ((disc * disc + a * a - cut * cut) / (2.0 * a * disc)).acos();
        // ... and seen from the cut-out's centre, the angle from the direction back to the axis.
        let back = (disc * half.sin()).atan2(a - disc * half.cos());
        let span = std::f64::consts::TAU - 2.0 * half;
        let disc_steps =
            ((self.disc_segments as f64) * span / std::f64::consts::TAU).ceil() as usize;
        let mut outline = Vec::new();
        for k in 0..=disc_steps {
            let angle = along + half + span * k as f64 / disc_steps as f64;
            outline.push([disc * angle.cos(), disc * angle.sin()]);
        }
        let centre = [a * along.cos(), a * along.sin()];
        let cut_steps = self.lock_segments;
        // Clockwise round the cut-out's centre, from the end just reached to the start, its end
        // points excluded (they are the disc arc's).
        for k in 1..cut_steps {
            let angle =
                along + std::f64::consts::PI + back - 2.0 * back * k as f64 / cut_steps as f64;
            outline.push([centre[0] + cut * angle.cos(), centre[1] + cut * angle.sin()]);
        }
        outline
    }

    /// The wheel: a disc of the rim radius with four radial slots of width
    /// `2·pin_radius + clearance` down to `slot_bottom_radius`, and with the locking disc a
    /// concave locking arc in each land between them.
    pub fn wheel_triangles(&self) -> Vec<Triangle> {
        extrude(&self.wheel_outline(), 0.0, self.wheel_thickness)
    }

    /// The wheel's outline in its frame, counter-clockwise: per slot its four corners, then the
    /// land to the next slot (the rim arc, or with the locking disc a rim tip, the concave
    /// locking arc and a rim tip), slot corners excluded from the lands.
    pub fn wheel_outline(&self) -> Vec<[f64; 2]> {
        let (a, rim) = (self.centre_distance, self.rim_radius());
        let half = self.pin_radius + 0.5 * self.clearance;
        let mouth = (rim * rim - half * half).sqrt();
        let opening = (half / rim).asin();
        let (tip, arc) = (self.lock_tip_angle, self.lock_arc_radius());
        // The concave arc's half-angle seen from its centre (the driver's axis at rest).
        let spread = (rim * tip.sin()).atan2(a - rim * tip.cos());
        let tip_steps = (self.rim_segments / 4).max(1);
        // Rim points strictly between `from` and `to` in `steps` steps, and `to` when asked.
        let rim_arc =
            |outline: &mut Vec<[f64; 2]>, from: f64, to: f64, steps: usize, last: bool| {
                let end = if last { steps } else { steps - 1 };
                for j in 1..=end {
                    let angle = from + (to - from) * j as f64 / steps as f64;
                    outline.push([rim * angle.cos(), rim * angle.sin()]);
                }
            };
        let mut outline = Vec::new();
        for k in 0..4 {
            let phi = FRAC_PI_4 + k as f64 * std::f64::consts::FRAC_PI_2;
            let (u, v) = ([phi.cos(), phi.sin()], [-phi.sin(), phi.cos()]);
            let at = |a: f64, b: f64| [a * u[0] + b * v[0], a * u[1] + b * v[1]];
            outline.push(at(mouth, -half));
            outline.push(at(self.slot_bottom_radius, -half));
            outline.push(at(self.slot_bottom_radius, half));
            outline.push(at(mouth, half));
            let (from, to) = (phi + opening, phi + std::f64::consts::FRAC_PI_2 - opening);
            if !self.locking_disc {
                rim_arc(&mut outline, from, to, self.rim_segments, false);
                continue;
            }
            let middle = phi + FRAC_PI_4;
            rim_arc(&mut outline, from, middle - tip, tip_steps, true);
            let centre = [a * middle.cos(), a * middle.sin()];
            for j in 1..self.lock_segments {
                let angle = middle + std::f64::consts::PI + spread
                    - 2.0 * spread * j as f64 / self.lock_segments as f64;
                outline.push([centre[0] + arc * angle.cos(), centre[1] + arc * angle.sin()]);
            }
            outline.push([rim * (middle + tip).cos(), rim * (middle + tip).sin()]);
            rim_arc(&mut outline, middle + tip, to, tip_steps, false);
        }
        outline
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

    /// The area common to two discs of radii `r0`, `r1` whose centres are `d` apart.
    fn lens(r0: f64, r1: f64, d: f64) -> f64 {
        let a0 = ((d * d + r0 * r0 - r1 * r1) / (2.0 * d * r0)).acos();
        let a1 = ((d * d + r1 * r1 - r0 * r0) / (2.0 * d * r1)).acos();
        r0 * r0 * (a0 - (2.0 * a0).sin() / 2.0) + r1 * r1 * (a1 - (2.0 * a1).sin() / 2.0)
    }

    /// The area of a simple polygon (positive counter-clockwise).
    fn area(outline: &[[f64; 2]]) -> f64 {
        (0..outline.len())
            .map(|i| {
                let (p, q) = (outline[i], outline[(i + 1) % outline.len()]);
                0.5 * (p[0] * q[1] - q[0] * p[1])
            })
            .sum()
    }

    #[test]
    fn the_wheel_is_a_closed_prism_of_the_slotted_discs_area() {
        for d in [GenevaDimensions::default(), locked()] {
            let rim = d.rim_radius();
            let half = d.pin_radius + 0.5 * d.clearance;
            // The disc less the slots (rectangles from the bottom to the mouth's chord) and less
            // the four lenses the locking arcs cut; the polygon's chords lose under 1% of it.
            let slot = 2.0 * half * ((rim * rim - half * half).sqrt() - d.slot_bottom_radius);
            let locks = if d.locking_disc {
                4.0 * lens(rim, d.lock_arc_radius(), d.centre_distance)
            } else {
                0.0
            };
            let got = volume(&d.wheel_triangles()) / d.wheel_thickness;
            let true_area = std::f64::consts::PI * rim * rim - 4.0 * slot - locks;
            assert!(
                got > 0.0 && (got - true_area).abs() < 0.01 * true_area,
                "{got} vs {true_area}"
            );
            assert!((area(&d.wheel_outline()) - got).abs() < 1e-12 * got);
        }
    }

    /// The drive with its locking disc.
    fn locked() -> GenevaDimensions {
        GenevaDimensions {
            locking_disc: true,
            ..GenevaDimensions::default()
        }
    }

    #[test]
    fn the_driver_is_its_plate_pin_and_locking_disc() {
        let d = locked();
        let g = d.margin();
        let r = d.crank_radius();
        let plate = (r + 3.0 * d.pin_radius) * 3.0 * d.pin_radius * 2.0 * g;
        let n = d.pin_segments as f64;
        let pin = 0.5
            * n
            * d.pin_radius.powi(2)
            * (2.0 * std::f64::consts::PI / n).sin()
            * (d.wheel_thickness + 2.0 * g);
        let outline = d.locking_disc_outline();
        let disc_area = area(&outline);
        // The disc less the cut-out's lens, within the polygon's chords (1e-3 here).
        let (disc, cut) = (d.locking_disc_radius(), d.cutout_radius());
        let true_disc = std::f64::consts::PI * disc * disc - lens(disc, cut, d.centre_distance);
        assert!(
            (disc_area - true_disc).abs() < 1e-3 * true_disc,
            "{disc_area} vs {true_disc}"
        );
        let plain = volume(&GenevaDimensions::default().driver_triangles());
        assert!(
            (plain - plate - pin).abs() < 1e-12,
            "{plain} vs {}",
            plate + pin
        );
        let disc_volume = disc_area * (d.wheel_thickness + 1.5 * g);
        let got = volume(&d.driver_triangles());
        let want = plate + pin + disc_volume;
        assert!((got - want).abs() < 1e-12, "{got} vs {want}");
    }

    /// The distance between two segments (0 when they cross).
    fn segment_distance(a: [[f64; 2]; 2], b: [[f64; 2]; 2]) -> f64 {
        let cross = |o: [f64; 2], p: [f64; 2], q: [f64; 2]| {
            (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0])
        };
        let (d1, d2) = (cross(a[0], a[1], b[0]), cross(a[0], a[1], b[1]));
        let (d3, d4) = (cross(b[0], b[1], a[0]), cross(b[0], b[1], a[1]));
        if d1 * d2 < 0.0 && d3 * d4 < 0.0 {
            return 0.0;
        }
        let to_segment = |p: [f64; 2], s: [[f64; 2]; 2]| {
            let (dx, dy) = (s[1][0] - s[0][0], s[1][1] - s[0][1]);
            let t = (((p[0] - s[0][0]) * dx + (p[1] - s[0][1]) * dy) / (dx * dx + dy * dy))
                .clamp(0.0, 1.0);
            (p[0] - s[0][0] - t * dx).hypot(p[1] - s[0][1] - t * dy)
        };
        to_segment(a[0], b)
            .min(to_segment(a[1], b))
            .min(to_segment(b[0], a))
            .min(to_segment(b[1], a))
    }

    /// Whether `p` lies inside the polygon (ray parity).
    fn inside(p: [f64; 2], outline: &[[f64; 2]]) -> bool {
        let mut odd = false;
        for i in 0..outline.len() {
            let (a, b) = (outline[i], outline[(i + 1) % outline.len()]);
            if (a[1] > p[1]) != (b[1] > p[1])
                && p[0] < a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0])
            {
                odd = !odd;
            }
        }
        odd
    }

    /// Over a whole turn of the crank with the wheel at the ideal drive's angle: the locking
    /// disc never meets the wheel, it comes within the lock clearance (and the facets' sag) of
    /// the locking arcs while the wheel dwells, and a wheel turned by more than the lock's play
    /// in the middle of a dwell meets it.
    #[test]
    fn the_locking_disc_clears_the_swinging_wheel_and_holds_the_dwelling_one() {
        let d = locked();
        let (a, r) = (d.centre_distance, d.crank_radius());
        let wheel = d.wheel_outline();
        let disc = d.locking_disc_outline();
        let posed = |outline: &[[f64; 2]], angle: f64, at: f64| -> Vec<[f64; 2]> {
            let (c, s) = (angle.cos(), angle.sin());
            outline
                .iter()
                .map(|p| [at + c * p[0] - s * p[1], s * p[0] + c * p[1]])
                .collect()
        };
        let gap = |w: &[[f64; 2]], k: &[[f64; 2]]| -> f64 {
            if inside(w[0], k) || inside(k[0], w) {
                return 0.0;
            }
            let mut best = f64::INFINITY;
            for i in 0..w.len() {
                for j in 0..k.len() {
                    let s0 = [w[i], w[(i + 1) % w.len()]];
                    let s1 = [k[j], k[(j + 1) % k.len()]];
                    best = best.min(segment_distance(s0, s1));
                }
            }
            best
        };
        // The ideal wheel angle at crank angle `theta` (world, from the line of centres).
        let ideal = |theta: f64| -> f64 {
            if theta < -FRAC_PI_4 {
                0.0
            } else if theta > FRAC_PI_4 {
                -std::f64::consts::FRAC_PI_2
            } else {
                (r * theta.sin())
                    .atan2(r * theta.cos() - a)
                    .rem_euclid(std::f64::consts::TAU)
                    - 225f64.to_radians()
            }
        };
        // How far the facets sag toward each other: the disc's chords inward, the arcs' toward
        // their centre.
        let rim = d.rim_radius();
        let spread = (rim * d.lock_tip_angle.sin()).atan2(a - rim * d.lock_tip_angle.cos());
        let sag = d.locking_disc_radius()
            * (1.0 - (std::f64::consts::PI / d.disc_segments as f64).cos())
            + d.lock_arc_radius() * (1.0 - (spread / d.lock_segments as f64).cos());
        let mut dwell_gap = f64::INFINITY;
        for step in -180..180 {
            let theta = (step as f64).to_radians();
            let w = posed(&wheel, ideal(theta), a);
            let k = posed(&disc, theta - d.crank_start_angle, 0.0);
            let g = gap(&w, &k);
            assert!(g > 0.5 * d.lock_clearance, "crank {theta}: gap {g}");
            if theta.abs() > 100f64.to_radians() {
                dwell_gap = dwell_gap.min(g);
            }
        }
        assert!(
            dwell_gap <= d.lock_clearance && dwell_gap >= d.lock_clearance - sag,
            "dwelling gap {dwell_gap}"
        );
        // Mid-dwell, turning the wheel by twice the play c/a either way closes the gap.
        let k = posed(&disc, std::f64::consts::PI - d.crank_start_angle, 0.0);
        for sign in [1.0, -1.0] {
            let w = posed(&wheel, sign * 2.0 * d.lock_clearance / a, a);
            assert_eq!(gap(&w, &k), 0.0, "turned {sign}");
        }
    }
}
