//! PCHIP: piecewise cubic Hermite interpolation with Fritsch-Carlson monotone slopes
//! (seed 000, section 4.6), parametrised by cumulative chord length.

use hyplan_core::Point2;
use nalgebra::Vector2;

use crate::PostprocError;
use crate::error::validate_path;
use crate::resample::cumulative_lengths;

/// A PCHIP curve through a path's nodes: x(s) and y(s) are each a monotone piecewise cubic
/// Hermite interpolant over the cumulative chord length s (seed 000, section 4.6).
///
/// The slopes are those of scipy's `PchipInterpolator` (Fritsch-Carlson with the
/// Fritsch-Butland weighted harmonic mean inside, the three-point shape-preserving formula
/// at both ends, and a straight line for two nodes). Where a coordinate is monotone between
/// nodes, the curve does not overshoot it; at a local extremum of a coordinate the slope is
/// zero.
///
/// The parameter runs over `[0, L]` with `L` the polyline length of the nodes; node `k` sits
/// at [`knots()[k]`](Pchip::knots), and the curve passes through it bit for bit. Evaluation
/// outside `[0, L]` clamps the parameter.
///
/// # Example
///
/// ```
/// use hyplan_core::Point2;
/// use postproc::Pchip;
/// let nodes = [Point2::new(0.0, 0.0), Point2::new(3.0, 4.0), Point2::new(6.0, 0.0)];
/// let curve = Pchip::new(&nodes)?;
/// assert_eq!(curve.length_param(), 10.0);
/// assert_eq!(curve.eval(5.0), nodes[1]);
/// // y has a maximum at the middle node, so its slope there is zero.
/// assert_eq!(curve.derivative(5.0).y, 0.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Pchip {
    nodes: Vec<Point2>,
    knots: Vec<f64>,
    slopes: Vec<Vector2<f64>>,
}

impl Pchip {
    /// The PCHIP curve through `nodes`.
    ///
    /// # Errors
    ///
    /// [`PostprocError::TooFewNodes`], [`PostprocError::NonFinite`] or
    /// [`PostprocError::RepeatedNode`] (a zero chord would make the parameter stall).
    pub fn new(nodes: &[Point2]) -> Result<Self, PostprocError> {
        validate_path(nodes)?;
        let knots = cumulative_lengths(nodes);
        let xs: Vec<f64> = nodes.iter().map(|p| p.x).collect();
        let ys: Vec<f64> = nodes.iter().map(|p| p.y).collect();
        let dx = pchip_slopes(&knots, &xs);
        let dy = pchip_slopes(&knots, &ys);
        let slopes = dx
            .into_iter()
            .zip(dy)
            .map(|(a, b)| Vector2::new(a, b))
            .collect();
        Ok(Self {
            nodes: nodes.to_vec(),
            knots,
            slopes,
        })
    }

    /// The nodes the curve passes through.
    #[must_use]
    pub fn nodes(&self) -> &[Point2] {
        &self.nodes
    }

    /// The parameter of each node: cumulative chord length, world units, starting at 0.
    #[must_use]
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }

    /// The slopes (dx/ds, dy/ds) at each node.
    #[must_use]
    pub fn slopes(&self) -> &[Vector2<f64>] {
        &self.slopes
    }

    /// The end of the parameter range: the polyline length of the nodes, world units.
    #[must_use]
    pub fn length_param(&self) -> f64 {
        self.knots[self.knots.len() - 1]
    }

    /// The piece holding `s` and the local coordinates `(h, t)`, with `s` clamped.
    fn locate(&self, s: f64) -> (usize, f64, f64) {
        let last = self.knots.len() - 2;
        let s = s.clamp(0.0, self.length_param());
        // First knot strictly above s, minus one, kept inside [0, last].
        let k = self
            .knots
            .partition_point(|&x| x <= s)
            .saturating_sub(1)
            .min(last);
        let h = self.knots[k + 1] - self.knots[k];
        (k, h, (s - self.knots[k]) / h)
    }

    /// The point at parameter `s` (clamped to `[0, L]`).
    #[must_use]
    pub fn eval(&self, s: f64) -> Point2 {
        let (k, h, t) = self.locate(s);
        if t == 0.0 {
            return self.nodes[k];
        }
        if t == 1.0 {
            return self.nodes[k + 1];
        }
        let (p0, p1) = (self.nodes[k].coords, self.nodes[k + 1].coords);
        let (d0, d1) = (self.slopes[k] * h, self.slopes[k + 1] * h);
        let t2 = t * t;
        let t3 = t2 * t;
        let h00 = 2.0 * t3 - 3.0 * t2 + 1.0;
        let h10 = t3 - 2.0 * t2 + t;
        let h01 = -2.0 * t3 + 3.0 * t2;
        let h11 = t3 - t2;
        Point2::from(p0 * h00 + d0 * h10 + p1 * h01 + d1 * h11)
    }

    /// The first derivative (dx/ds, dy/ds) at `s` (clamped to `[0, L]`).
    #[must_use]
    pub fn derivative(&self, s: f64) -> Vector2<f64> {
        let (k, h, t) = self.locate(s);
        let (p0, p1) = (self.nodes[k].coords, self.nodes[k + 1].coords);
        let (d0, d1) = (self.slopes[k], self.slopes[k + 1]);
        let t2 = t * t;
        // d/ds = (1/h) d/dt of the Hermite basis.
        (p1 - p0) * ((6.0 * t - 6.0 * t2) / h)
            + d0 * (3.0 * t2 - 4.0 * t + 1.0)
            + d1 * (3.0 * t2 - 2.0 * t)
    }

    /// The second derivative (d2x/ds2, d2y/ds2) at `s` (clamped to `[0, L]`).
    ///
    /// It is piecewise linear and may jump at the nodes; at a node the value of the piece to
    /// its right is returned (of the last piece at the end).
    #[must_use]
    pub fn second_derivative(&self, s: f64) -> Vector2<f64> {
        let (k, h, t) = self.locate(s);
        let (p0, p1) = (self.nodes[k].coords, self.nodes[k + 1].coords);
        let (d0, d1) = (self.slopes[k], self.slopes[k + 1]);
        (p1 - p0) * ((6.0 - 12.0 * t) / (h * h))
            + d0 * ((6.0 * t - 4.0) / h)
            + d1 * ((6.0 * t - 2.0) / h)
    }
}

/// The PCHIP slopes of data `(x, y)`, exactly as scipy's `PchipInterpolator` computes them.
///
/// `x` must be strictly increasing and have the length of `y`, with at least two entries
/// (the callers in this crate guarantee it).
pub(crate) fn pchip_slopes(x: &[f64], y: &[f64]) -> Vec<f64> {
    let n = x.len();
    let h: Vec<f64> = x.windows(2).map(|w| w[1] - w[0]).collect();
    let m: Vec<f64> = y
        .windows(2)
        .zip(&h)
        .map(|(w, &hk)| (w[1] - w[0]) / hk)
        .collect();
    if n == 2 {
        // Two points: a straight line.
        return vec![m[0], m[0]];
    }
    let mut d = vec![0.0; n];
    for k in 1..n - 1 {
        let (m0, m1) = (m[k - 1], m[k]);
        if m0 == 0.0 || m1 == 0.0 || sign(m0) != sign(m1) {
            // A local extremum (or a flat piece): zero slope keeps the data's shape.
            d[k] = 0.0;
        } else {
            // Fritsch-Butland weighted harmonic mean of the two secants.
            let w1 = 2.0 * h[k] + h[k - 1];
            let w2 = h[k] + 2.0 * h[k - 1];
            let whmean = (w1 / m0 + w2 / m1) / (w1 + w2);
            d[k] = 1.0 / whmean;
        }
    }
    d[0] = edge_slope(h[0], h[1], m[0], m[1]);
    d[n - 1] = edge_slope(h[n - 2], h[n - 3], m[n - 2], m[n - 3]);
    d
}

/// The three-point, shape-preserving end slope (scipy's `PchipInterpolator._edge_case`).
fn edge_slope(h0: f64, h1: f64, m0: f64, m1: f64) -> f64 {
    let d = ((2.0 * h0 + h1) * m0 - h0 * m1) / (h0 + h1);
    if sign(d) != sign(m0) {
        0.0
    } else if sign(m0) != sign(m1) && d.abs() > 3.0 * m0.abs() {
        3.0 * m0
    } else {
        d
    }
}

/// numpy's `sign`: -1, 0 or 1.
fn sign(v: f64) -> i8 {
    if v > 0.0 {
        1
    } else if v < 0.0 {
        -1
    } else {
        0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slopes_two_points_linear() {
        assert_eq!(pchip_slopes(&[0.0, 2.0], &[1.0, 5.0]), vec![2.0, 2.0]);
    }

    #[test]
    fn slopes_zero_at_extremum() {
        let d = pchip_slopes(&[0.0, 1.0, 2.0], &[0.0, 1.0, 0.0]);
        assert_eq!(d[1], 0.0);
        // Edge: d = ((2+1)*1 - 1*(-1))/2 = 2, sign differs from m1 and |2| <= 3: kept.
        assert_eq!(d[0], 2.0);
        assert_eq!(d[2], -2.0);
    }

    #[test]
    fn slopes_harmonic_mean_on_equal_spacing() {
        // h equal: 1/d = (1/m0 + 1/m1)/2.
        let d = pchip_slopes(&[0.0, 1.0, 2.0, 3.0], &[0.0, 1.0, 4.0, 5.0]);
        assert!((d[1] - 2.0 / (1.0 + 1.0 / 3.0)).abs() < 1e-15);
    }

    #[test]
    fn derivatives_match_finite_differences() {
        let nodes = [[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 0.0]].map(Point2::from);
        let c = Pchip::new(&nodes).unwrap();
        let eps = 1e-6;
        for i in 1..40 {
            let s = c.length_param() * f64::from(i) / 40.0 + 1e-3;
            let fd = (c.eval(s + eps) - c.eval(s - eps)) / (2.0 * eps);
            assert!((fd - c.derivative(s)).norm() < 1e-6, "at {s}");
            let fd2 = (c.derivative(s + eps) - c.derivative(s - eps)) / (2.0 * eps);
            assert!((fd2 - c.second_derivative(s)).norm() < 1e-4, "at {s}");
        }
    }
}
