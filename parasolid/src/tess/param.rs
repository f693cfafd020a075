//! A surface's parameters of a point on it (the inverse of [`Surface::eval`]), the scale that
//! makes parameter space roughly isometric for triangulation, and the parameter steps that
//! keep facets within the chord deviation δ.

use crate::geom::{Surface, golden};
use crate::nurbs::wrap;
use contact_core::Point3;

/// The parameters `(u, v)` of `p` (a point on or near the surface): exact for the analytic
/// surfaces (the foot of the normal through `p`), a grid search refined by Newton steps on the
/// squared distance for the others.
pub fn uv(s: &Surface, p: &Point3) -> (f64, f64) {
    match s {
        Surface::Plane { o, x, y } => ((p - o).dot(x), (p - o).dot(y)),
        Surface::Cone { o, a, x, y, r, tan } => {
            let d = p - o;
            let u = d.dot(y).atan2(d.dot(x));
            // Foot of the normal on the generator line at angle u.
            let h = d.dot(a);
            let rho = (d - a * h).norm();
            let v = if *tan == 0.0 {
                h
            } else {
                // Generator: (r + v tan, v) in (radial, axial); project (rho, h) onto it.
                let k = 1.0 / (1.0 + tan * tan);
                ((rho - r) * tan + h) * k
            };
            (u, v)
        }
        Surface::Sphere { c, a, x, y, .. } => {
            let d = p - c;
            let z = d.dot(a);
            let rho = (d - a * z).norm();
            (d.dot(y).atan2(d.dot(x)), z.atan2(rho))
        }
        Surface::Torus {
            c, a, x, y, big, ..
        } => {
            let d = p - c;
            let z = d.dot(a);
            let rho = (d - a * z).norm();
            (d.dot(y).atan2(d.dot(x)), z.atan2(rho - big))
        }
        Surface::Swept { section, d } => {
            let f = |t: f64| {
                let q = p - section.eval_wrapped(t);
                (q - d * q.dot(d)).norm_squared()
            };
            let range = section.range().unwrap_or((0.0, 1.0));
            let u = search_1d(&f, range, section.closed_range().is_some());
            (u, (p - section.eval_wrapped(u)).dot(d))
        }
        Surface::Spun { profile, b, a } => {
            // The profile point at the same axial height and radius as p.
            let q = p - b;
            let (h, rho) = (q.dot(a), (q - a * q.dot(a)).norm());
            let f = |t: f64| {
                let c = profile.eval_wrapped(t) - b;
                let (ch, cr) = (c.dot(a), (c - a * c.dot(a)).norm());
                (ch - h).powi(2) + (cr - rho).powi(2)
            };
            let range = profile.range().unwrap_or((0.0, 1.0));
            let u = search_1d(&f, range, profile.closed_range().is_some());
            let c = profile.eval_wrapped(u) - b;
            let cr = c - a * c.dot(a);
            let qr = q - a * q.dot(a);
            let v = a.dot(&cr.cross(&qr)).atan2(cr.dot(&qr));
            (u, v)
        }
        Surface::Nurbs(n) => {
            let ((u0, u1), (v0, v1)) = n.range();
            let f = |u: f64, v: f64| (Point3::from(n.eval(u, v)) - p).norm_squared();
            let k = 24;
            let mut best = (f64::INFINITY, u0, v0);
            for i in 0..=k {
                for j in 0..=k {
                    let (u, v) = (
                        u0 + (u1 - u0) * i as f64 / k as f64,
                        v0 + (v1 - v0) * j as f64 / k as f64,
                    );
                    let d = f(u, v);
                    if d < best.0 {
                        best = (d, u, v);
                    }
                }
            }
            // Alternate 1-D minimisations (coordinate descent) in shrinking brackets, which
            // run past the ends of a closed direction (the surface wraps there).
            let (mut u, mut v) = (best.1, best.2);
            let (mut hu, mut hv) = ((u1 - u0) / k as f64, (v1 - v0) / k as f64);
            for _ in 0..12 {
                let (a, b) = bracket(u, hu, (u0, u1), n.u_closed);
                u = golden(&|t| f(t, v), a, b);
                let (a, b) = bracket(v, hv, (v0, v1), n.v_closed);
                v = golden(&|t| f(u, t), a, b);
                hu *= 0.5;
                hv *= 0.5;
            }
            let u = if n.u_closed { wrap(u, (u0, u1)) } else { u };
            let v = if n.v_closed { wrap(v, (v0, v1)) } else { v };
            (u, v)
        }
    }
}

/// The parameters of `p` as [`uv`] finds them, searched first near `hint` (the parameters
/// of a point close to `p`): on swept and spun surfaces the section or profile parameter is
/// refined by golden sections within 1/64 of its range either side of the hint, and the
/// whole range is searched only when the minimum lands on that bracket's edge; a B-surface
/// is searched near the hint, and wholly only when that search does not land on it.
/// Analytic surfaces are inverted directly.
pub fn uv_near(s: &Surface, p: &Point3, hint: (f64, f64)) -> (f64, f64) {
    match s {
        Surface::Swept { section, d } => {
            let f = |t: f64| {
                let q = p - section.eval_wrapped(t);
                (q - d * q.dot(d)).norm_squared()
            };
            let range = section.range().unwrap_or((0.0, 1.0));
            match local_1d(&f, hint.0, range, section.closed_range().is_some()) {
                Some(u) => (u, (p - section.eval_wrapped(u)).dot(d)),
                None => uv(s, p),
            }
        }
        Surface::Spun { profile, b, a } => {
            let q = p - b;
            let (h, rho) = (q.dot(a), (q - a * q.dot(a)).norm());
            let f = |t: f64| {
                let c = profile.eval_wrapped(t) - b;
                let (ch, cr) = (c.dot(a), (c - a * c.dot(a)).norm());
                (ch - h).powi(2) + (cr - rho).powi(2)
            };
            let range = profile.range().unwrap_or((0.0, 1.0));
            match local_1d(&f, hint.0, range, profile.closed_range().is_some()) {
                Some(u) => {
                    let c = profile.eval_wrapped(u) - b;
                    let cr = c - a * c.dot(a);
                    let qr = q - a * q.dot(a);
                    (u, a.dot(&cr.cross(&qr)).atan2(cr.dot(&qr)))
                }
                None => uv(s, p),
            }
        }
        Surface::Nurbs(n) => {
            // Coordinate descent from the hint; kept only when it lands on the surface (within
            // a tenth of Parasolid's resolution), as a loop point does.
            let ((u0, u1), (v0, v1)) = n.range();
            let f = |u: f64, v: f64| (Point3::from(n.eval(u, v)) - p).norm_squared();
            let (mut u, mut v) = hint;
            let (mut hu, mut hv) = ((u1 - u0) / 96.0, (v1 - v0) / 96.0);
            for _ in 0..12 {
                let (a, b) = bracket(u, hu, (u0, u1), n.u_closed);
                u = golden(&|t| f(t, v), a, b);
                let (a, b) = bracket(v, hv, (v0, v1), n.v_closed);
                v = golden(&|t| f(u, t), a, b);
                hu *= 0.5;
                hv *= 0.5;
            }
            if f(u, v) <= 1e-18 {
                let u = if n.u_closed { wrap(u, (u0, u1)) } else { u };
                let v = if n.v_closed { wrap(v, (v0, v1)) } else { v };
                (u, v)
            } else {
                uv(s, p)
            }
        }
        _ => uv(s, p),
    }
}

/// The bracket `x ± h`, cut to `[lo, hi]` unless the direction is closed.
fn bracket(x: f64, h: f64, (lo, hi): (f64, f64), closed: bool) -> (f64, f64) {
    if closed {
        (x - h, x + h)
    } else {
        ((x - h).max(lo), (x + h).min(hi))
    }
}

/// The minimum of `f` within 1/64 of `range` either side of `x` (past the range's ends when
/// `closed`, the result then taken back into it); `None` when it lies on the bracket's edge
/// inside the range (the minimum sought may lie beyond).
fn local_1d(f: &dyn Fn(f64) -> f64, x: f64, (lo, hi): (f64, f64), closed: bool) -> Option<f64> {
    let h = (hi - lo) / 64.0;
    let (a, b) = if closed {
        (x - h, x + h)
    } else {
        ((x - h).max(lo), (x + h).min(hi))
    };
    let t = golden(f, a, b);
    let edge = 1e-6 * h;
    let on_edge = (t - a < edge && (closed || a > lo)) || (b - t < edge && (closed || b < hi));
    if on_edge {
        None
    } else if closed {
        Some(wrap(t, (lo, hi)))
    } else {
        Some(t)
    }
}

/// The minimum of `f` over `[lo, hi]`: the best of 201 samples, refined by golden sections in
/// the samples either side (past the ends when `closed`, the result then taken back into
/// the range).
fn search_1d(f: &dyn Fn(f64) -> f64, (lo, hi): (f64, f64), closed: bool) -> f64 {
    let n = 200;
    let step = (hi - lo) / n as f64;
    let mut best = (f64::INFINITY, lo);
    for i in 0..=n {
        let t = lo + step * i as f64;
        let d = f(t);
        if d < best.0 {
            best = (d, t);
        }
    }
    if closed {
        wrap(golden(f, best.1 - step, best.1 + step), (lo, hi))
    } else {
        golden(f, (best.1 - step).max(lo), (best.1 + step).min(hi))
    }
}

/// Lengths per unit of u and v near the face (`scale`), and the largest parameter steps
/// (`None`: the surface is straight that way) keeping facets within δ of the surface.
pub struct Metric {
    /// Metres per unit u, v.
    pub scale: (f64, f64),
    /// Largest steps in u, v.
    pub step: (Option<f64>, Option<f64>),
}

/// The angle step whose chord on radius `r` deviates at most `d`: `θ = 2 acos(1 − d/r)`,
/// at most π/2. The chord bound alone allows steps up to π as `d` nears `r`; on a periodic
/// face a step near π lets one triangle of the parameter domain join a seam point to two
/// points half a turn away, and its copy one period on then joins the same three vertices
/// the other way round (an edge of three or four triangles). A quarter turn keeps every grid
/// triangle within less than half a turn.
pub fn angle_step(r: f64, d: f64) -> f64 {
    if d >= r {
        std::f64::consts::FRAC_PI_2
    } else {
        (2.0 * (1.0 - d / r).acos()).min(std::f64::consts::FRAC_PI_2)
    }
}

/// The metric of `s` over the parameter box `uv_box` (min u, max u, min v, max v).
pub fn metric(s: &Surface, uv_box: (f64, f64, f64, f64), delta: f64) -> Metric {
    let (u0, u1, v0, v1) = uv_box;
    match s {
        Surface::Plane { .. } => Metric {
            scale: (1.0, 1.0),
            step: (None, None),
        },
        Surface::Cone { r, tan, .. } => {
            let rmax = (r + v0 * tan).abs().max((r + v1 * tan).abs()).max(1e-12);
            let rmid = (r + 0.5 * (v0 + v1) * tan).abs().max(1e-12);
            Metric {
                scale: (rmid, (1.0 + tan * tan).sqrt()),
                step: (Some(angle_step(rmax, delta)), None),
            }
        }
        Surface::Sphere { r, .. } => Metric {
            scale: (*r, *r),
            step: (
                Some(angle_step(*r, 0.5 * delta)),
                Some(angle_step(*r, 0.5 * delta)),
            ),
        },
        Surface::Torus { big, small, .. } => Metric {
            scale: ((big + small).max(*small), *small),
            step: (
                Some(angle_step(big + small, 0.5 * delta)),
                Some(angle_step(*small, 0.5 * delta)),
            ),
        },
        _ => numeric_metric(s, (u0, u1, v0, v1), delta),
    }
}

/// Metric of a free-form surface: scales from the mean lengths of grid lines; steps halved
/// until every grid line's chord midpoints lie within δ/2 of the surface (at most 512 cells).
fn numeric_metric(s: &Surface, (u0, u1, v0, v1): (f64, f64, f64, f64), delta: f64) -> Metric {
    let k = 8;
    let du = (u1 - u0).max(1e-12);
    let dv = (v1 - v0).max(1e-12);
    let mut lu = 0.0;
    let mut lv = 0.0;
    for i in 0..=k {
        let f = i as f64 / k as f64;
        for j in 0..k {
            let (a, b) = (j as f64 / k as f64, (j + 1) as f64 / k as f64);
            lu += (s.eval(u0 + du * b, v0 + dv * f) - s.eval(u0 + du * a, v0 + dv * f)).norm();
            lv += (s.eval(u0 + du * f, v0 + dv * b) - s.eval(u0 + du * f, v0 + dv * a)).norm();
        }
    }
    let n = (k + 1) as f64;
    let scale = ((lu / n / du).max(1e-12), (lv / n / dv).max(1e-12));
    let step_along = |along_u: bool| -> Option<f64> {
        let mut cells = 2usize;
        loop {
            let mut worst = 0.0f64;
            for i in 0..=4 {
                let f = i as f64 / 4.0;
                for j in 0..cells {
                    let (a, b) = (j as f64 / cells as f64, (j + 1) as f64 / cells as f64);
                    let at = |t: f64| {
                        if along_u {
                            s.eval(u0 + du * t, v0 + dv * f)
                        } else {
                            s.eval(u0 + du * f, v0 + dv * t)
                        }
                    };
                    let (pa, pb, pm) = (at(a), at(b), at(0.5 * (a + b)));
                    worst = worst.max((pm - (pa + (pb - pa) * 0.5)).norm());
                }
            }
            if worst <= 0.5 * delta || cells >= 512 {
                let span = if along_u { du } else { dv };
                return if cells == 2 && worst < 1e-3 * delta {
                    None
                } else {
                    Some(span / cells as f64)
                };
            }
            cells *= 2;
        }
    };
    Metric {
        scale,
        step: (step_along(true), step_along(false)),
    }
}

#[cfg(test)]
mod tests {
    use super::angle_step;
    use std::f64::consts::FRAC_PI_2;

    /// Oracle: a chord of angle θ on radius r deviates r (1 − cos θ/2) from its arc. Every
    /// step keeps within `d` and within a quarter turn, and a step never grows as `d` falls.
    #[test]
    fn angle_steps_keep_the_chord_bound_and_a_quarter_turn() {
        let r = 0.0025;
        let mut last = 0.0;
        for k in 1..=400 {
            let d = r * k as f64 / 200.0;
            let step = angle_step(r, d);
            assert!(
                step > 0.0 && step <= FRAC_PI_2,
                "d/r {}: step {step}",
                d / r
            );
            assert!(r * (1.0 - (0.5 * step).cos()) <= d * (1.0 + 1e-12));
            assert!(step >= last, "d/r {}: {step} after {last}", d / r);
            last = step;
        }
        // Where the quarter turn does not bind, the step is the chord bound's own.
        let d = 0.01 * r;
        assert_eq!(angle_step(r, d), 2.0 * (1.0 - d / r).acos());
    }
}
