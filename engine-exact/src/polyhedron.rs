//! Exact clipping of a convex polyhedron by half-spaces, on the stack.
//!
//! The intersection of two convex solids bounded by planes (box–box, box–plane) is a convex
//! polyhedron: start from one box and clip it by each bounding plane of the other
//! (Sutherland–Hodgman on every face, then a new face from the points on the clipping plane).
//! Faces made by clipping are marked, so the area-weighted normal of the other solid's surface
//! inside the intersection comes out with the volume and the centroid.
//!
//! ## Robustness
//! - A point where an edge crosses the plane is computed from the edge's endpoints in a fixed
//!   (lexicographic) order, so the two faces sharing the edge produce the same bits and the
//!   new face's vertices are deduplicated by exact equality.
//! - A vertex exactly on the plane is kept (the half-space is closed) and joins the new face.
//! - No new face is made unless some vertex lay strictly outside, so a face lying in the
//!   clipping plane is never doubled.
//!
//! ## Capacity
//! A box has 6 faces and each clipping plane adds at most one, so box–box (6 planes) has at
//! most 12 faces and box–bounded-plane (5 planes) at most 11; a face gains at most one vertex
//! per plane. [`MAX_FACES`] and [`MAX_FACE_VERTICES`] hold those bounds with a margin; the
//! capacities are const parameters so a smaller problem (a box and one plane: 7 faces of at
//! most 6 vertices) uses a smaller, cheaper polyhedron.

use contact_core::{Point3, Vector3};

/// Faces a polyhedron can hold by default (box–box: at most 12).
pub const MAX_FACES: usize = 14;
/// Vertices a face can hold by default. Box–box needs 11: a box face has 4 and gains at most
/// one per clipping plane (10); the face cut by the k-th plane has one vertex per face it
/// crosses (at most 6 + k − 1) and then gains one per later plane (at most 11). 16 leaves a
/// margin for round-off in near-degenerate cuts; 18 cost box–box a third more time
/// (criterion, 1.31 against 1.91 µs in one run), past some size the copies of a face slow.
pub const MAX_FACE_VERTICES: usize = 16;

/// A convex polygon, counter-clockwise seen from outside the polyhedron.
#[derive(Debug, Clone, Copy)]
struct Face<const V: usize> {
    vertices: [Point3; V],
    len: usize,
    from_clip: bool,
}

impl<const V: usize> Face<V> {
    const EMPTY: Self = Self {
        vertices: [Point3::new(0.0, 0.0, 0.0); V],
        len: 0,
        from_clip: false,
    };

    fn push(&mut self, p: Point3) {
        debug_assert!(self.len < V, "face capacity exceeded");
        if self.len < V {
            self.vertices[self.len] = p;
            self.len += 1;
        }
    }

    /// `½ Σ (v_k − v_0) × (v_{k+1} − v_0)`: the area times the outward unit normal.
    fn area_vector(&self) -> Vector3 {
        let v0 = self.vertices[0];
        let mut sum = Vector3::zeros();
        for k in 1..self.len.saturating_sub(1) {
            sum += (self.vertices[k] - v0).cross(&(self.vertices[k + 1] - v0));
        }
        0.5 * sum
    }
}

/// A convex polyhedron as a list of outward-oriented faces: at most `F` faces of at most
/// `V` vertices each.
#[derive(Debug, Clone)]
pub struct ConvexPolyhedron<const F: usize = MAX_FACES, const V: usize = MAX_FACE_VERTICES> {
    faces: [Face<V>; F],
    len: usize,
}

/// Volume, centroid and the clipped faces' area vector of a [`ConvexPolyhedron`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MassProperties {
    /// The enclosed volume (≥ 0 up to round-off).
    pub volume: f64,
    /// The centroid of the volume (the first vertex when the volume is zero).
    pub centroid: Point3,
    /// `Σ area·outward normal` over the faces made by clipping: the clipping solid's surface
    /// inside the polyhedron.
    pub clipped_area_vector: Vector3,
    /// `Σ area` over the same faces: `|clipped_area_vector|` far below it means the clipping
    /// solid's surface inside the polyhedron closes on itself (it is contained, or crosses).
    pub clipped_area: f64,
}

impl<const F: usize, const V: usize> ConvexPolyhedron<F, V> {
    /// The box with centre `center` and half-axes `axes` (three orthogonal vectors, right
    /// handed: `axes[0] × axes[1]` along `axes[2]`, each as long as that half extent).
    pub fn cuboid(center: &Point3, axes: &[Vector3; 3]) -> Self {
        let corner =
            |sx: f64, sy: f64, sz: f64| center + sx * axes[0] + sy * axes[1] + sz * axes[2];
        let quads: [[(f64, f64, f64); 4]; 6] = [
            [(1., -1., -1.), (1., 1., -1.), (1., 1., 1.), (1., -1., 1.)],
            [
                (-1., -1., -1.),
                (-1., -1., 1.),
                (-1., 1., 1.),
                (-1., 1., -1.),
            ],
            [(-1., 1., -1.), (-1., 1., 1.), (1., 1., 1.), (1., 1., -1.)],
            [
                (-1., -1., -1.),
                (1., -1., -1.),
                (1., -1., 1.),
                (-1., -1., 1.),
            ],
            [(-1., -1., 1.), (1., -1., 1.), (1., 1., 1.), (-1., 1., 1.)],
            [
                (-1., -1., -1.),
                (-1., 1., -1.),
                (1., 1., -1.),
                (1., -1., -1.),
            ],
        ];
        let mut poly = Self {
            faces: [Face::EMPTY; F],
            len: 6,
        };
        for (face, quad) in poly.faces.iter_mut().zip(quads.iter()) {
            for &(sx, sy, sz) in quad {
                face.push(corner(sx, sy, sz));
            }
        }
        poly
    }

    /// Number of faces.
    #[cfg(test)]
    pub fn face_count(&self) -> usize {
        self.len
    }

    /// Keeps the part with `normal·x ≤ offset`. Returns true when some vertex lay strictly
    /// outside (something was cut away).
    pub fn clip(&mut self, normal: &Vector3, offset: f64) -> bool {
        let mut cap: Face<V> = Face::EMPTY;
        cap.from_clip = true;
        let mut scratch: Face<V> = Face::EMPTY;
        let mut cut = false;
        let mut write = 0;
        for index in 0..self.len {
            let face = &self.faces[index];
            // Each vertex's signed distance, once (the edge loop below reads each twice).
            let mut d = [0.0; V];
            let mut any_out = false;
            for (dk, p) in d.iter_mut().zip(&face.vertices[..face.len]) {
                *dk = normal.dot(&p.coords) - offset;
                any_out |= *dk > 0.0;
            }
            if !any_out {
                // Wholly kept: the face stays as it is (moved down over removed faces); its
                // vertices on the plane still belong to the new face.
                for (p, _) in face
                    .vertices
                    .iter()
                    .zip(&d[..face.len])
                    .filter(|(_, dk)| **dk == 0.0)
                {
                    push_unique(&mut cap, *p);
                }
                if write != index {
                    self.faces[write] = self.faces[index];
                }
                write += 1;
                continue;
            }
            cut = true;
            scratch.len = 0;
            scratch.from_clip = face.from_clip;
            for k in 0..face.len {
                let next = if k + 1 == face.len { 0 } else { k + 1 };
                let (p, q) = (face.vertices[k], face.vertices[next]);
                let (dp, dq) = (d[k], d[next]);
                if dp <= 0.0 {
                    scratch.push(p);
                    if dp == 0.0 {
                        push_unique(&mut cap, p);
                    }
                }
                if (dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0) {
                    let x = crossing(p, dp, q, dq);
                    scratch.push(x);
                    push_unique(&mut cap, x);
                }
            }
            if scratch.len >= 3 {
                let target = &mut self.faces[write];
                target.vertices[..scratch.len].copy_from_slice(&scratch.vertices[..scratch.len]);
                target.len = scratch.len;
                target.from_clip = scratch.from_clip;
                write += 1;
            }
        }
        self.len = write;
        if cut && cap.len >= 3 {
            debug_assert!(self.len < F, "polyhedron capacity exceeded");
            if self.len < F {
                order_counter_clockwise(&mut cap, normal);
                self.faces[self.len] = cap;
                self.len += 1;
            }
        }
        cut
    }

    /// Volume and centroid by the divergence theorem (a fan of tetrahedra from the first
    /// vertex), and the area vector of the clipped faces.
    pub fn mass_properties(&self) -> MassProperties {
        let origin = if self.len > 0 {
            self.faces[0].vertices[0]
        } else {
            Point3::origin()
        };
        let mut six_volume = 0.0;
        let mut moment = Vector3::zeros();
        let mut clipped = Vector3::zeros();
        let mut clipped_area = 0.0;
        for face in &self.faces[..self.len] {
            let a = face.vertices[0] - origin;
            for k in 1..face.len - 1 {
                let b = face.vertices[k] - origin;
                let c = face.vertices[k + 1] - origin;
                let v6 = a.dot(&b.cross(&c));
                six_volume += v6;
                moment += v6 * (a + b + c);
            }
            if face.from_clip {
                let area = face.area_vector();
                clipped += area;
                clipped_area += area.norm();
            }
        }
        let centroid = if six_volume > 0.0 {
            origin + moment / (4.0 * six_volume)
        } else {
            origin
        };
        MassProperties {
            volume: six_volume / 6.0,
            centroid,
            clipped_area_vector: clipped,
            clipped_area,
        }
    }

    /// The total area of the polyhedron's faces.
    pub fn surface_area(&self) -> f64 {
        self.faces[..self.len]
            .iter()
            .map(|f| f.area_vector().norm())
            .sum::<f64>()
    }

    /// The area of the polyhedron's shadow on a plane normal to the unit vector `direction`:
    /// `½ Σ |A_f · direction|` (a convex body's boundary covers its shadow twice).
    #[cfg(test)]
    pub fn projected_area(&self, direction: &Vector3) -> f64 {
        0.5 * self.faces[..self.len]
            .iter()
            .map(|f| f.area_vector().dot(direction).abs())
            .sum::<f64>()
    }
}

/// The point where the edge `p q` crosses the plane, with `dp`, `dq` the signed distances of
/// opposite signs; computed from the lexicographically smaller endpoint so both faces of the
/// edge give the same bits.
fn crossing(p: Point3, dp: f64, q: Point3, dq: f64) -> Point3 {
    let p_first = (p.x, p.y, p.z) < (q.x, q.y, q.z);
    let (p, dp, q, dq) = if p_first {
        (p, dp, q, dq)
    } else {
        (q, dq, p, dp)
    };
    p + (q - p) * (dp / (dp - dq))
}

fn push_unique<const V: usize>(face: &mut Face<V>, p: Point3) {
    if !face.vertices[..face.len].contains(&p) {
        face.push(p);
    }
}

/// Sorts the (convex, coplanar) vertices counter-clockwise seen from +`normal`.
fn order_counter_clockwise<const V: usize>(face: &mut Face<V>, normal: &Vector3) {
    let n = face.len;
    let mean = face.vertices[..n]
        .iter()
        .fold(Vector3::zeros(), |s, p| s + p.coords)
        / n as f64;
    let helper = if normal.x.abs() < 0.9 {
        Vector3::x()
    } else {
        Vector3::y()
    };
    let u = normal.cross(&helper).normalize();
    let v = normal.cross(&u);
    let mut keys = [0.0; V];
    for (key, p) in keys.iter_mut().zip(&face.vertices[..n]) {
        let d = p.coords - mean;
        *key = pseudo_angle(d.dot(&u), d.dot(&v));
    }
    // Insertion sort: at most V entries.
    for i in 1..n {
        let mut j = i;
        while j > 0 && keys[j - 1] > keys[j] {
            keys.swap(j - 1, j);
            face.vertices.swap(j - 1, j);
            j -= 1;
        }
    }
}

/// A monotone stand-in for `atan2(y, x)` in `[0, 4)` (the "diamond angle"), without
/// trigonometry.
fn pseudo_angle(x: f64, y: f64) -> f64 {
    let l1 = x.abs() + y.abs();
    if l1 == 0.0 {
        return 0.0;
    }
    let (x, y) = (x / l1, y / l1);
    match (x >= 0.0, y >= 0.0) {
        (true, true) => y,
        (false, true) => 1.0 - x,
        (false, false) => 2.0 - y,
        (true, false) => 3.0 + x,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit_cube() -> ConvexPolyhedron {
        ConvexPolyhedron::cuboid(
            &Point3::origin(),
            &[Vector3::x(), Vector3::y(), Vector3::z()],
        )
    }

    #[test]
    fn a_cube_has_its_volume_and_centre() {
        let m = unit_cube().mass_properties();
        assert!((m.volume - 8.0).abs() < 1e-14);
        assert!(m.centroid.coords.norm() < 1e-15);
        assert_eq!(m.clipped_area_vector, Vector3::zeros());
        assert_eq!(m.clipped_area, 0.0);
        assert!((unit_cube().projected_area(&Vector3::z()) - 4.0).abs() < 1e-14);
    }

    #[test]
    fn a_diagonal_cut_leaves_a_corner_tetrahedron() {
        // x + y + z ≥ 2 keeps the corner tetrahedron at (1,1,1) with legs 1: volume 1/6,
        // centroid (1,1,1) − (1/4)(1,1,1).
        let mut p = unit_cube();
        let n = -Vector3::new(1.0, 1.0, 1.0);
        assert!(p.clip(&n, -2.0));
        let m = p.mass_properties();
        assert!((m.volume - 1.0 / 6.0).abs() < 1e-14, "{}", m.volume);
        let expected = Vector3::repeat(0.75);
        assert!((m.centroid.coords - expected).norm() < 1e-14);
        // The cut face: an equilateral triangle of side √2, area √3/2, normal along −(1,1,1).
        let area = 3f64.sqrt() / 2.0;
        assert!((m.clipped_area_vector - area * n.normalize()).norm() < 1e-14);
    }

    #[test]
    fn clipping_through_vertices_and_along_a_face_is_exact() {
        // The plane x = 1 holds a whole face: nothing is cut, no face is added.
        let mut p = unit_cube();
        assert!(!p.clip(&Vector3::x(), 1.0));
        assert_eq!(p.face_count(), 6);
        // x + y ≤ 0 passes through two edges: half the cube.
        assert!(p.clip(&Vector3::new(1.0, 1.0, 0.0), 0.0));
        let m = p.mass_properties();
        assert!((m.volume - 4.0).abs() < 1e-14);
        // Centroid of the prism with triangular base (−1,−1), (1,−1), (−1,1): (−1/3, −1/3).
        assert!((m.centroid.coords - Vector3::new(-1.0 / 3.0, -1.0 / 3.0, 0.0)).norm() < 1e-14);
        assert_eq!(p.face_count(), 5);
    }

    #[test]
    fn clipping_everything_away_leaves_nothing() {
        let mut p = unit_cube();
        p.clip(&Vector3::z(), -2.0);
        assert_eq!(p.face_count(), 0);
        assert_eq!(p.mass_properties().volume, 0.0);
    }
}
