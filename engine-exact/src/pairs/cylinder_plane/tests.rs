//! The cylinder–plane pieces checked against the 12-node rule, the rim series against
//! Gauss–Legendre quadrature, and a grazing, nearly parallel wheel against a 50-digit
//! reference.

use super::*;
use contact_core::UnitQuaternion;

/// The closed-form pieces against the 12-node rule on every piece (exact to round-off on
/// these trigonometric polynomials where the cut is well conditioned), over random tilts
/// and depths from 1e-5 of the radius to full immersion. Shallower cuts, and axes within
/// 1e-6 of parallel, are run too (finite, same contact or none) but not compared: there the
/// node rule's own cut angle asin(u/R) and its lengths (h − a u)/b carry relative errors
/// ε·R/η and ε·a/b, which the end-piece series avoids (see the next two tests).
#[test]
fn closed_form_pieces_agree_with_the_node_rule() {
    let mut seed = 0x2545_F491_4F6C_DD1D_u64;
    let mut rnd = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let cylinder = Cylinder::new(0.7, 2.3).unwrap();
    let (mut closed_used, mut compared, mut series_poses) = (0, 0, 0);
    for k in 0..20000 {
        let near_parallel = k % 4 == 1;
        let tilt = match k % 4 {
            0 => rnd() * std::f64::consts::PI,
            1 => 0.5 * std::f64::consts::PI + (rnd() - 0.5) * 1e-6,
            2 => (rnd() - 0.5) * 1e-3,
            _ => 0.5 * std::f64::consts::PI + (rnd() - 0.5) * 0.2,
        };
        let rotation = UnitQuaternion::from_axis_angle(&Vector3::x_axis(), tilt)
            * UnitQuaternion::from_axis_angle(&Vector3::z_axis(), rnd() * 6.3);
        let pose_c = Isometry3::from_parts(Vector3::zeros().into(), rotation);
        // The cylinder's lowest point along −z, then a depth on a log scale.
        let axis = rotation * Vector3::z();
        let low = (axis.z * 2.3).min(0.0) - 0.7 * (1.0 - axis.z * axis.z).max(0.0).sqrt();
        let depth = 10f64.powf(-9.0 + 9.5 * rnd());
        let pose_plane = Isometry3::translation(0.0, 0.0, low + depth);
        let mut work = WorkCounters::default();
        let closed = contact_by(
            &cylinder,
            &pose_c,
            &pose_plane,
            1.0,
            &mut work,
            Rule::ClosedForm,
        );
        closed_used += usize::from(work.iterations == 0);
        let mut node_work = WorkCounters::default();
        let nodes = contact_by(
            &cylinder,
            &pose_c,
            &pose_plane,
            1.0,
            &mut node_work,
            Rule::Nodes,
        );
        match (closed, nodes) {
            (Some(c), Some(n)) if depth >= 1e-5 && !near_parallel => {
                compared += 1;
                let scale = 2.3;
                let depth_err = (c.depth - n.depth).abs();
                assert!(
                    depth_err <= 1e-12 * n.depth + 1e-14 * scale,
                    "{k}: {c:?} {n:?}"
                );
                assert!(
                    (c.point_a - n.point_a).norm() <= 1e-12 * scale,
                    "{k}: {c:?} {n:?}"
                );
                assert!(
                    (c.point_b - n.point_b).norm() <= 1e-12 * scale,
                    "{k}: {c:?} {n:?}"
                );
                // The node rule's cut angle carries ε·R/η relative (η ≈ the depth).
                let node_error = 8.0 * f64::EPSILON * 0.7 / depth;
                assert!(
                    (c.area - n.area).abs() <= (1e-12 + node_error) * n.area,
                    "{k}: {c:?} {n:?}"
                );
            }
            (Some(c), Some(n)) => {
                series_poses += 1;
                assert!(c.depth.is_finite() && c.area.is_finite(), "{k}: {c:?}");
                assert!((c.depth - n.depth).abs() <= 1e-9 * 2.3, "{k}: {c:?} {n:?}");
            }
            (None, None) => {}
            (c, n) => panic!("{k}: {c:?} vs {n:?}"),
        }
    }
    // Both rules were compared: poses taken wholly in closed form (deep contacts, shallow
    // ones by the end-piece series) and poses with a piece node by node.
    assert!(
        compared > 5000 && closed_used > 5000 && series_poses > 5000,
        "{compared} {closed_used} {series_poses}"
    );
}

/// The end-piece series against Gauss–Legendre after `x = η t²`, which leaves a smooth
/// integrand `4η^{3/2} t² √(2R − η t²) (η(1 − t²))ᵖ` on `[0, 1]` (8 pieces of 12 nodes).
#[test]
fn the_end_moments_series_matches_quadrature_in_the_root_of_the_rim_distance() {
    let r = 0.7;
    for e in 0..=24 {
        let eta = 0.5 * r * 10f64.powf(-0.5 * e as f64);
        let mut reference = [0.0; 3];
        for piece in 0..8 {
            let (t0, t1) = (piece as f64 / 8.0, (piece + 1) as f64 / 8.0);
            quadrature::for_each_node(t0, t1, |t, w| {
                let x = eta * t * t;
                let f = 4.0 * eta * eta.sqrt() * t * t * (2.0 * r - x).sqrt();
                let d = eta * (1.0 - t) * (1.0 + t);
                reference[0] += w * f;
                reference[1] += w * f * d;
                reference[2] += w * f * d * d;
            });
        }
        let series = end_moments(r, eta);
        for p in 0..3 {
            let rel = (series[p] - reference[p]).abs() / reference[p];
            assert!(rel <= 1e-14, "η = {eta:e}, p = {p}: {rel:e}");
        }
    }
}

/// The moments of a piece off the rim, by all of its branches (the difference of series
/// for wide pieces, the 8-, 4- and 2-node rules in `d` for narrower ones), against Gauss–Legendre in
/// `s = 1 − t`, `x = η t²`, over `s ∈ [0, 1 − t₀]` (8 pieces of 12 nodes; smooth there,
/// and `d = η s (2 − s)` keeps its digits). `η` a power of two and `t₀` of few bits, so
/// `η_rim = η t₀²` is exact and both integrate the same range.
#[test]
fn rim_moments_off_the_rim_match_quadrature_in_the_root_of_the_rim_distance() {
    let r = 0.7;
    for k in 2..=40 {
        let eta = 2f64.powi(-k);
        for t_start in [
            0.0,
            0.5,
            0.75,
            0.875,
            0.9375,
            1.0 - 2f64.powi(-4),
            1.0 - 2f64.powi(-7),
            1.0 - 2f64.powi(-10),
            1.0 - 2f64.powi(-14),
            1.0 - 2f64.powi(-20),
            1.0 - 2f64.powi(-17),
            1.0 - 2f64.powi(-26),
        ] {
            let eta_rim = eta * t_start * t_start;
            let span = 1.0 - t_start;
            let mut reference = [0.0; 3];
            for piece in 0..8 {
                let (s0, s1) = (span * piece as f64 / 8.0, span * (piece + 1) as f64 / 8.0);
                quadrature::for_each_node(s0, s1, |s, w| {
                    let t = 1.0 - s;
                    let x = eta * t * t;
                    let f = 4.0 * eta * eta.sqrt() * t * t * (2.0 * r - x).sqrt();
                    let d = eta * s * (2.0 - s);
                    reference[0] += w * f;
                    reference[1] += w * f * d;
                    reference[2] += w * f * d * d;
                });
            }
            let got = rim_moments(r, eta, eta_rim).unwrap();
            for p in 0..3 {
                let rel = (got[p] - reference[p]).abs() / reference[p];
                assert!(
                    rel <= 1e-13,
                    "η = {eta:e}, t₀ = {t_start}, p = {p}: {rel:e}"
                );
            }
        }
    }
}

/// A wheel within 1.1e-7 rad of parallel to the plane, cut 3e-9 deep along 0.027 of its
/// length: the moments against a 50-digit quadrature of the same integrals (mpmath, the
/// plane's `a, b, h` as the doubles below). The series answers to 2e-14; the node rule,
/// whose lengths `(h − a u)/b` carry ε·a/b, was off by 4e-10 in volume and 3e-9 in the
/// axial centroid.
#[test]
fn a_grazing_nearly_parallel_cut_keeps_its_digits() {
    let (a, b, h) = (
        9.999_999_999_999_933e-1,
        1.140_422_833_945_109_5e-7,
        -6.999_999_969_701_55e-1,
    );
    let mut work = WorkCounters::default();
    let (v, mu, mz, _) = slice_moments(a, b, h, 0.7, 2.3, Rule::ClosedForm, &mut work);
    let close = |got: f64, want: f64| ((got - want) / want).abs() <= 2e-14;
    assert!(close(v, 2.796_057_989_195_627_4e-15), "{v:e}");
    assert!(close(mu / v, -6.999_999_987_014_97e-1), "{:e}", mu / v);
    assert!(close(mz / v, 7.590_769_162_087_196e-3), "{:e}", mz / v);
}
