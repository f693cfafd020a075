//! The broad phase: which force elements can act at a state, so that contacts far apart cost
//! nothing.
//!
//! An element may say that each of its two sides lies inside a ball or box fixed in its part
//! ([`ForceElement::bounds`], a [`Bounds`]); a CONTACT whose geometry lists are all
//! bounded solids does. Such an element's loads are zero whenever its two bounds, placed at
//! the parts' poses as world boxes, are apart ([`Bounds::apart`]): the contact itself makes
//! this test before it asks its engine ([`crate::contact_force::ContactForce`]). At each
//! evaluation the system sweeps and prunes the distinct world boxes along x (sort by the
//! lower bound, compare each with those whose lower bound is below its upper bound) and
//! evaluates only the elements whose boxes overlap, and the elements without bounds; the others are
//! skipped, with loads and partials exactly zero, as they would have been evaluated. So the
//! broad phase changes which elements are evaluated, never a result, and the contact-onset
//! prediction (which reads the contacts' own reports) sees every onset.
//!
//! The test [`Bounds::apart`] keeps a margin of [`MARGIN`] of the two radii: it only
//! ever makes the broad phase evaluate more.

use crate::mbs::{ForceElement, PartId, PartState};
use contact_core::GeometryInstance;
use nalgebra::Vector3;
use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering};

/// The margin of [`Bounds::apart`], relative to the sum of the two half-widths.
pub const MARGIN: f64 = 0.01;

/// A box or a ball fixed in a part that holds one side of a force element.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bounds {
    /// The centre in the part (CM) frame.
    pub centre_p: Vector3<f64>,
    /// The shape about the centre.
    pub shape: BoundsShape,
}

/// The shape of [`Bounds`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum BoundsShape {
    /// A ball of this radius (finite, ≥ 0): its world box is the same at every orientation.
    Ball(f64),
    /// A box with these half-extents (finite, ≥ 0) along the part's axes; its world box is
    /// `|R|·h` for the part's rotation `R`.
    Box(Vector3<f64>),
}

impl Bounds {
    /// The bounds of `instances` (their geometry placed on the part, poses in the part frame):
    /// a ball for one ellipsoid (radius its largest semi-axis), else the part-frame box around
    /// their bounding boxes. `None` when one is unbounded (a plane, a 2-D geometry, whose
    /// material side is a half-plane or a region) or flipped (a cavity), or the list is empty.
    pub fn enclosing(instances: &[GeometryInstance]) -> Option<Self> {
        if let [instance] = instances
            && let contact_core::Geometry::Ellipsoid(e) = &*instance.geometry
            && !instance.flip_normal
        {
            let centre_p = instance.pose_part_geometry.translation.vector;
            return Some(Self {
                centre_p,
                shape: BoundsShape::Ball(e.semi_axes().max()),
            });
        }
        let (mut lo, mut hi) = (
            Vector3::repeat(f64::INFINITY),
            Vector3::repeat(f64::NEG_INFINITY),
        );
        for instance in instances {
            let geometry = &instance.geometry;
            if instance.flip_normal
                || geometry.is_planar()
                || matches!(**geometry, contact_core::Geometry::Plane(_))
            {
                return None;
            }
            let (g_lo, g_hi) = geometry.local_bounding_box();
            let (g_lo, g_hi) = (g_lo.coords, g_hi.coords);
            if !g_lo.iter().chain(g_hi.iter()).all(|v| v.is_finite()) {
                return None;
            }
            let pose = &instance.pose_part_geometry;
            let centre = pose * nalgebra::Point3::from((g_lo + g_hi) * 0.5);
            let half = pose.rotation.to_rotation_matrix().matrix().abs() * ((g_hi - g_lo) * 0.5);
            lo = lo.inf(&(centre.coords - half));
            hi = hi.sup(&(centre.coords + half));
        }
        if instances.is_empty() {
            return None;
        }
        Some(Self {
            centre_p: (lo + hi) * 0.5,
            shape: BoundsShape::Box((hi - lo) * 0.5),
        })
    }

    /// The world box `(centre, half-extents)` for a part at `state`.
    pub fn world_box(&self, state: &PartState) -> (Vector3<f64>, Vector3<f64>) {
        let centre = state.pose_w * nalgebra::Point3::from(self.centre_p);
        let half = match self.shape {
            BoundsShape::Ball(r) => Vector3::repeat(r),
            BoundsShape::Box(h) => state.pose_w.rotation.to_rotation_matrix().matrix().abs() * h,
        };
        (centre.coords, half)
    }

    /// Whether two world boxes `(centre, half-extents)` are apart along some axis:
    /// `|a − b|_k > (h_a + h_b)_k·(1 + MARGIN)`. Apart boxes hold geometry that cannot touch.
    pub fn apart(a: &(Vector3<f64>, Vector3<f64>), b: &(Vector3<f64>, Vector3<f64>)) -> bool {
        (0..3).any(|k| (a.0[k] - b.0[k]).abs() > (a.1[k] + b.1[k]) * (1.0 + MARGIN))
    }
}

/// A distinct bound of some elements: on which part, where.
#[derive(Debug, Clone, Copy)]
struct Proxy {
    part: PartId,
    bounds: Bounds,
}

/// The broad phase of a system's force elements (see the module docs).
#[derive(Debug, Default)]
pub struct BroadPhase {
    proxies: Vec<Proxy>,
    /// The elements between two proxies (`a < b`).
    pairs: HashMap<(u32, u32), Vec<u32>>,
    /// The elements without bounds: always evaluated.
    unbounded: Vec<u32>,
    elements: usize,
    /// Element evaluations made and skipped, over every sweep.
    evaluated: AtomicU64,
    skipped: AtomicU64,
}

impl BroadPhase {
    /// The broad phase of `elements` (their [`ForceElement::bounds`]).
    pub fn new(elements: &[Box<dyn ForceElement>]) -> Self {
        Self::of_elements(elements.iter().map(|e| (e.parts(), e.bounds())))
    }

    /// The broad phase of elements given as `(parts, bounds)`, in index order.
    pub fn of_elements<'a>(
        elements: impl IntoIterator<Item = (&'a [PartId], Option<[Bounds; 2]>)>,
    ) -> Self {
        let mut index: HashMap<(usize, bool, [u64; 6]), u32> = HashMap::new();
        let mut broad = Self::default();
        for (k, (parts, bounds)) in elements.into_iter().enumerate() {
            broad.elements += 1;
            let (Some(bounds), [part_a, part_b]) = (bounds, parts) else {
                broad.unbounded.push(k as u32);
                continue;
            };
            let mut proxy = |part: PartId, bounds: Bounds| {
                let (c, h, ball) = match bounds.shape {
                    BoundsShape::Ball(r) => (bounds.centre_p, Vector3::repeat(r), true),
                    BoundsShape::Box(h) => (bounds.centre_p, h, false),
                };
                let key = (
                    part.0,
                    ball,
                    [c.x, c.y, c.z, h.x, h.y, h.z].map(f64::to_bits),
                );
                *index.entry(key).or_insert_with(|| {
                    broad.proxies.push(Proxy { part, bounds });
                    (broad.proxies.len() - 1) as u32
                })
            };
            let (a, b) = (proxy(*part_a, bounds[0]), proxy(*part_b, bounds[1]));
            broad
                .pairs
                .entry((a.min(b), a.max(b)))
                .or_default()
                .push(k as u32);
        }
        broad
    }

    /// The indices of the elements that can act at `states` (indexed by part id), ascending.
    pub fn candidates(&self, states: &[PartState]) -> Vec<usize> {
        let mut active: Vec<usize> = self.unbounded.iter().map(|&k| k as usize).collect();
        if !self.pairs.is_empty() {
            let boxes: Vec<(Vector3<f64>, Vector3<f64>)> = self
                .proxies
                .iter()
                .map(|p| p.bounds.world_box(&states[p.part.0]))
                .collect();
            // Sweep along x: the same margin as `Bounds::apart`, so the sweep misses no pair
            // that test keeps.
            let low = |i: u32| {
                let (c, h) = &boxes[i as usize];
                c.x - h.x * (1.0 + MARGIN)
            };
            let mut order: Vec<u32> = (0..self.proxies.len() as u32).collect();
            order.sort_unstable_by(|&a, &b| low(a).total_cmp(&low(b)).then(a.cmp(&b)));
            for (n, &a) in order.iter().enumerate() {
                let (ca, ha) = &boxes[a as usize];
                for &b in &order[n + 1..] {
                    // Past this, every b is apart from a along x (to round-off in a gap that
                    // the margin keeps wider than the geometry's).
                    if low(b) > ca.x + ha.x * (1.0 + MARGIN) {
                        break;
                    }
                    if self.proxies[a as usize].part == self.proxies[b as usize].part
                        || Bounds::apart(&boxes[a as usize], &boxes[b as usize])
                    {
                        continue;
                    }
                    if let Some(list) = self.pairs.get(&(a.min(b), a.max(b))) {
                        active.extend(list.iter().map(|&k| k as usize));
                    }
                }
            }
            active.sort_unstable();
        }
        self.evaluated
            .fetch_add(active.len() as u64, Ordering::Relaxed);
        self.skipped
            .fetch_add((self.elements - active.len()) as u64, Ordering::Relaxed);
        active
    }

    /// The number of elements it was built for.
    pub fn len(&self) -> usize {
        self.elements
    }

    /// Whether it was built for no element.
    pub fn is_empty(&self) -> bool {
        self.elements == 0
    }

    /// `(evaluated, skipped)`: element evaluations made and skipped so far.
    pub fn counts(&self) -> (u64, u64) {
        (
            self.evaluated.load(Ordering::Relaxed),
            self.skipped.load(Ordering::Relaxed),
        )
    }
}

#[cfg(test)]
mod tests;
