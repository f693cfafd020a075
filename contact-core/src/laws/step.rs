//! Adams' STEP (cubic) and STEP5 (quintic) blending functions.

use crate::error::InvalidArgument;

/// A value with its first derivative.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Smooth {
    /// The function value.
    pub value: f64,
    /// Its derivative with respect to the argument.
    pub slope: f64,
}

/// A validated STEP or STEP5 from `(x0, h0)` to `(x1, h1)`, `x0 < x1`.
///
/// - STEP: `h0 + a·D²·(3 − 2D)`, `a = h1 − h0`, `D = (x − x0)/(x1 − x0)`; `h0` for `x ≤ x0`,
///   `h1` for `x ≥ x1`. Continuous first derivative, second derivative jumps at the ends.
/// - STEP5: `h0 + a·D³·(10 − 15D + 6D²)`: continuous first and second derivatives.
///
/// Adams' worked example: `STEP(x, 3, 0, 4, 1)` at x = 2, 3, 3.5, 4, 5 is 0, 0, 0.5, 1, 1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Step {
    x0: f64,
    h0: f64,
    x1: f64,
    h1: f64,
}

impl Step {
    /// A step from `(x0, h0)` to `(x1, h1)`; all finite and `x0 < x1`.
    pub fn new(x0: f64, h0: f64, x1: f64, h1: f64) -> Result<Self, InvalidArgument> {
        for (argument, v) in [("x0", x0), ("h0", h0), ("x1", x1), ("h1", h1)] {
            crate::error::finite(argument, v)?;
        }
        if x1 <= x0 {
            return Err(InvalidArgument::new("x1", x1, format!("> x0 = {x0:?}")));
        }
        Ok(Self { x0, h0, x1, h1 })
    }

    /// The cubic STEP at `x`.
    pub fn cubic(&self, x: f64) -> Smooth {
        self.eval(x, |d| (d * d * (3.0 - 2.0 * d), 6.0 * d * (1.0 - d)))
    }

    /// The quintic STEP5 at `x`.
    pub fn quintic(&self, x: f64) -> Smooth {
        self.eval(x, |d| {
            let d2 = d * d;
            (
                d2 * d * (10.0 - 15.0 * d + 6.0 * d2),
                30.0 * d2 * (1.0 - d) * (1.0 - d),
            )
        })
    }

    fn eval(&self, x: f64, shape: impl Fn(f64) -> (f64, f64)) -> Smooth {
        if x <= self.x0 {
            return Smooth {
                value: self.h0,
                slope: 0.0,
            };
        }
        if x >= self.x1 {
            return Smooth {
                value: self.h1,
                slope: 0.0,
            };
        }
        let width = self.x1 - self.x0;
        let a = self.h1 - self.h0;
        let (s, ds) = shape((x - self.x0) / width);
        Smooth {
            value: self.h0 + a * s,
            slope: a * ds / width,
        }
    }
}

/// `STEP(x, x0, h0, x1, h1)`: the cubic step with its derivative (see [`Step`]).
pub fn step(x: f64, x0: f64, h0: f64, x1: f64, h1: f64) -> Result<Smooth, InvalidArgument> {
    Ok(Step::new(x0, h0, x1, h1)?.cubic(x))
}

/// `STEP5(x, x0, h0, x1, h1)`: the quintic step with its derivative (see [`Step`]).
pub fn step5(x: f64, x0: f64, h0: f64, x1: f64, h1: f64) -> Result<Smooth, InvalidArgument> {
    Ok(Step::new(x0, h0, x1, h1)?.quintic(x))
}
