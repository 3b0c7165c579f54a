//! Any curve of the crate behind one enum, and its resampling at a given spacing.

use hyplan_core::Point2;
use nalgebra::Vector2;

use crate::{BSpline, Pchip, PostprocError};

/// The most samples [`Curve::resample`] and [`smooth_checked`](crate::smooth_checked)
/// produce; a smaller spacing is refused with [`PostprocError::InvalidSpacing`].
pub const MAX_SAMPLES: usize = 10_000_000;

/// A path as one of the crate's curve kinds, so callers can hold any of them.
///
/// | variant | parameter | passes through the nodes |
/// |---|---|---|
/// | [`Curve::Polyline`] | arc length, `[0, L]` | yes, with corners |
/// | [`Curve::Pchip`] | chord length, `[0, L]` | yes, C1 |
/// | [`Curve::BSpline`] | see [`BSpline`] | interpolating: yes, C2; control points: ends only |
///
/// # Example
///
/// ```
/// use hyplan_core::Point2;
/// use postproc::{Curve, Pchip};
/// let nodes = [Point2::new(0.0, 0.0), Point2::new(4.0, 3.0), Point2::new(8.0, 0.0)];
/// let curve = Curve::Pchip(Pchip::new(&nodes)?);
/// let samples = curve.resample(0.25)?;
/// assert_eq!(samples.first(), Some(&nodes[0]));
/// assert_eq!(samples.last(), Some(&nodes[2]));
/// assert!(samples.windows(2).all(|w| nalgebra::distance(&w[0], &w[1]) <= 0.25));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub enum Curve {
    /// The nodes joined by straight segments. Evaluation scans the nodes (linear time).
    Polyline(Vec<Point2>),
    /// A PCHIP curve through the nodes.
    Pchip(Pchip),
    /// A clamped B-spline.
    BSpline(BSpline),
}

impl Curve {
    /// The parameter range `(start, end)`.
    #[must_use]
    pub fn domain(&self) -> (f64, f64) {
        match self {
            Self::Polyline(p) => (0.0, hyplan_core::path_length(p)),
            Self::Pchip(c) => (0.0, c.length_param()),
            Self::BSpline(b) => b.domain(),
        }
    }

    /// The parameters where the curve's pieces meet, both ends included: the nodes for a
    /// polyline, a PCHIP curve or an interpolating B-spline, the distinct knots for a
    /// control-point B-spline.
    #[must_use]
    pub fn breakpoints(&self) -> Vec<f64> {
        match self {
            Self::Polyline(p) => cumulative_lengths(p),
            Self::Pchip(c) => c.knots().to_vec(),
            Self::BSpline(b) => b
                .node_params()
                .map_or_else(|| b.breakpoints(), <[f64]>::to_vec),
        }
    }

    /// The point at parameter `t` (clamped to the domain).
    #[must_use]
    pub fn eval(&self, t: f64) -> Point2 {
        match self {
            Self::Polyline(p) => polyline_locate(p, t).map_or_else(
                || p.first().copied().unwrap_or_else(Point2::origin),
                |(k, f)| p[k] + (p[k + 1] - p[k]) * f,
            ),
            Self::Pchip(c) => c.eval(t),
            Self::BSpline(b) => b.eval(t),
        }
    }

    /// The first derivative with respect to the parameter (a unit vector on a polyline).
    #[must_use]
    pub fn derivative(&self, t: f64) -> Vector2<f64> {
        match self {
            Self::Polyline(p) => polyline_locate(p, t)
                .map_or_else(Vector2::zeros, |(k, _)| (p[k + 1] - p[k]).normalize()),
            Self::Pchip(c) => c.derivative(t),
            Self::BSpline(b) => b.derivative(t),
        }
    }

    /// The second derivative with respect to the parameter (zero on a polyline, whose
    /// corners are not differentiable).
    #[must_use]
    pub fn second_derivative(&self, t: f64) -> Vector2<f64> {
        match self {
            Self::Polyline(_) => Vector2::zeros(),
            Self::Pchip(c) => c.second_derivative(t),
            Self::BSpline(b) => b.second_derivative(t),
        }
    }

    /// The signed curvature at `t`, 1 / world units, positive to the left
    /// (see [`curvature`](crate::curvature)).
    #[must_use]
    pub fn curvature(&self, t: f64) -> f64 {
        crate::curvature(self.derivative(t), self.second_derivative(t))
    }

    /// Samples the curve so that consecutive samples are at most `spacing` apart
    /// (straight-line distance, world units).
    ///
    /// Every breakpoint is a sample, so a polyline keeps its corners and a PCHIP curve its
    /// nodes. The first and last samples are the curve's end points bit for bit.
    ///
    /// # Errors
    ///
    /// [`PostprocError::InvalidSpacing`] when `spacing` is not finite and positive or
    /// would need more than [`MAX_SAMPLES`] samples.
    pub fn resample(&self, spacing: f64) -> Result<Vec<Point2>, PostprocError> {
        let breaks = self.breakpoints();
        let ends: Vec<Point2> = breaks.iter().map(|&t| self.eval(t)).collect();
        check_spacing(spacing, hyplan_core::path_length(&ends))?;
        let mut out = Vec::with_capacity(breaks.len());
        let f = |t: f64| self.eval(t);
        for k in 0..breaks.len().saturating_sub(1) {
            out.push(ends[k]);
            match self {
                Self::Polyline(_) => densify_line(ends[k], ends[k + 1], spacing, &mut out),
                _ => densify_curve(
                    &f,
                    breaks[k],
                    breaks[k + 1],
                    ends[k],
                    ends[k + 1],
                    spacing,
                    &mut out,
                ),
            }
        }
        if let Some(&last) = ends.last() {
            out.push(last);
        }
        Ok(out)
    }
}

/// Checks a spacing for a curve of about `length` world units.
pub(crate) fn check_spacing(spacing: f64, length: f64) -> Result<(), PostprocError> {
    if !(spacing.is_finite() && spacing > 0.0) {
        return Err(PostprocError::InvalidSpacing {
            value: spacing,
            reason: "must be finite and > 0",
        });
    }
    // Curves can be longer than their nodes' polyline; 4x is a generous margin.
    if 4.0 * length / spacing > MAX_SAMPLES as f64 {
        return Err(PostprocError::InvalidSpacing {
            value: spacing,
            reason: "too small for the path's length (more than MAX_SAMPLES samples)",
        });
    }
    Ok(())
}

/// Cumulative lengths of a polyline, starting at 0.
pub(crate) fn cumulative_lengths(p: &[Point2]) -> Vec<f64> {
    let mut s = 0.0;
    let mut out = Vec::with_capacity(p.len());
    if !p.is_empty() {
        out.push(0.0);
    }
    for w in p.windows(2) {
        s += nalgebra::distance(&w[0], &w[1]);
        out.push(s);
    }
    out
}

/// The segment holding arc length `t` and the fraction along it; `None` for fewer than two
/// points or a zero-length polyline.
fn polyline_locate(p: &[Point2], t: f64) -> Option<(usize, f64)> {
    let mut s = 0.0;
    let n = p.len();
    if n < 2 {
        return None;
    }
    let t = t.max(0.0);
    for k in 0..n - 1 {
        let len = nalgebra::distance(&p[k], &p[k + 1]);
        if t <= s + len && len > 0.0 {
            return Some((k, (t - s) / len));
        }
        s += len;
    }
    // Past the end: the end of the last non-degenerate segment.
    (0..n - 1)
        .rev()
        .find(|&k| p[k] != p[k + 1])
        .map(|k| (k, 1.0))
}

/// The polyline `nodes` with every segment split evenly into pieces shorter than
/// `spacing` (the nodes kept): seed 003's densified control polygon, for instance.
///
/// ```
/// use hyplan_core::Point2;
/// let d = postproc::densify(&[Point2::new(0.0, 0.0), Point2::new(1.0, 0.0)], 0.3);
/// assert_eq!(d.len(), 5); // pieces of 0.25
/// ```
#[must_use]
pub fn densify(nodes: &[Point2], spacing: f64) -> Vec<Point2> {
    let mut out = Vec::with_capacity(nodes.len());
    for w in nodes.windows(2) {
        out.push(w[0]);
        densify_line(w[0], w[1], spacing, &mut out);
    }
    out.extend(nodes.last());
    out
}

/// Pushes the points strictly between `a` and `b` on the segment, evenly spaced less than
/// `spacing` apart.
pub(crate) fn densify_line(a: Point2, b: Point2, spacing: f64, out: &mut Vec<Point2>) {
    let len = nalgebra::distance(&a, &b);
    // floor + 1 pieces: each strictly shorter than the spacing, with no rounding at the edge.
    let n = (len / spacing).floor() as usize + 1;
    let d = b - a;
    for i in 1..n {
        out.push(a + d * (i as f64 / n as f64));
    }
}

/// Pushes samples of `f` strictly inside `(t0, t1)` so that, with `p0 = f(t0)` and
/// `p1 = f(t1)` around them, consecutive points are at most `spacing` apart.
pub(crate) fn densify_curve(
    f: &impl Fn(f64) -> Point2,
    t0: f64,
    t1: f64,
    p0: Point2,
    p1: Point2,
    spacing: f64,
    out: &mut Vec<Point2>,
) {
    // Estimate the piece's length from eight chords, then split it evenly in the parameter.
    let mut est = 0.0;
    let mut prev = p0;
    for i in 1..=8 {
        let q = if i == 8 {
            p1
        } else {
            f(t0 + (t1 - t0) * f64::from(i) / 8.0)
        };
        est += nalgebra::distance(&prev, &q);
        prev = q;
    }
    let n = (est / spacing).floor() as usize + 1;
    let mut a = t0;
    let mut pa = p0;
    for i in 1..=n {
        let (b, pb) = if i == n {
            (t1, p1)
        } else {
            let b = t0 + (t1 - t0) * (i as f64 / n as f64);
            (b, f(b))
        };
        refine(f, a, pa, b, pb, spacing, out, 0);
        if i < n {
            out.push(pb);
        }
        a = b;
        pa = pb;
    }
}

/// Bisects `[a, b]` until the chords are at most `spacing` long, pushing the inner points.
#[allow(clippy::too_many_arguments)]
fn refine(
    f: &impl Fn(f64) -> Point2,
    a: f64,
    pa: Point2,
    b: f64,
    pb: Point2,
    spacing: f64,
    out: &mut Vec<Point2>,
    depth: u32,
) {
    // The curves are continuous, so halving converges; 60 halvings exhaust f64 precision.
    if nalgebra::distance(&pa, &pb) <= spacing || depth >= 60 {
        return;
    }
    let m = 0.5 * (a + b);
    let pm = f(m);
    refine(f, a, pa, m, pm, spacing, out, depth + 1);
    out.push(pm);
    refine(f, m, pm, b, pb, spacing, out, depth + 1);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_spacing_strict() {
        let mut out = vec![];
        densify_line(Point2::new(0.0, 0.0), Point2::new(1.0, 0.0), 0.25, &mut out);
        // 1 / 0.25 = 4 exactly: five pieces, all shorter than 0.25.
        assert_eq!(out.len(), 4);
    }

    #[test]
    fn polyline_eval_and_derivative() {
        let c = Curve::Polyline(vec![
            Point2::new(0.0, 0.0),
            Point2::new(2.0, 0.0),
            Point2::new(2.0, 2.0),
        ]);
        assert_eq!(c.eval(3.0), Point2::new(2.0, 1.0));
        assert_eq!(c.derivative(3.0), Vector2::new(0.0, 1.0));
        assert_eq!(c.eval(10.0), Point2::new(2.0, 2.0));
        assert_eq!(c.breakpoints(), vec![0.0, 2.0, 4.0]);
        let s = c.resample(0.5).unwrap();
        assert!(s.contains(&Point2::new(2.0, 0.0)));
    }
}
