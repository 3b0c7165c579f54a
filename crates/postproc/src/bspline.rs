//! Clamped cubic B-splines evaluated by de Boor's algorithm (seed 003, section 2.3).

use hyplan_core::Point2;
use nalgebra::Vector2;

use crate::PostprocError;
use crate::error::validate_path;
use crate::resample::cumulative_lengths;

/// A clamped B-spline of degree 3 (lower when there are fewer than four control points),
/// evaluated with de Boor's algorithm.
///
/// Two constructions:
///
/// - [`BSpline::from_control_points`]: the path's nodes are the control points, as seed 003
///   (section 2.3) smooths its pruned RRT* path. The curve starts and ends at the end nodes,
///   is tangent to the first and last segments and stays inside the convex hull of every
///   four consecutive nodes, but does not pass through the inner nodes. Knots are uniform,
///   so the parameter runs over `[0, spans]` with one unit per knot span.
/// - [`BSpline::interpolating`]: the curve passes through every node (global interpolation
///   with chord-length parameters and averaged knots, Piegl and Tiller, *The NURBS Book*,
///   section 9.2.1). The parameter is the cumulative chord length of the nodes, so node `k`
///   sits at [`node_params()[k]`](BSpline::node_params).
///
/// Evaluation clamps the parameter to [`domain`](BSpline::domain). At both ends of the
/// domain the end control points are returned bit for bit.
///
/// # Example
///
/// ```
/// use hyplan_core::Point2;
/// use postproc::BSpline;
/// let nodes = [
///     Point2::new(0.0, 0.0),
///     Point2::new(1.0, 2.0),
///     Point2::new(3.0, 2.0),
///     Point2::new(4.0, 0.0),
/// ];
/// let b = BSpline::from_control_points(&nodes)?;
/// let (u0, u1) = b.domain();
/// assert_eq!(b.eval(u0), nodes[0]);
/// assert_eq!(b.eval(u1), nodes[3]);
/// // Clamped: the curve leaves the start along the first control segment.
/// let d = b.derivative(u0);
/// assert!((d.y / d.x - 2.0).abs() < 1e-12);
///
/// let through = BSpline::interpolating(&nodes)?;
/// let s1 = through.node_params().unwrap()[1];
/// assert!((through.eval(s1) - nodes[1]).norm() < 1e-12);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct BSpline {
    curve: Spline,
    first: Spline,
    second: Spline,
    node_params: Option<Vec<f64>>,
}

/// One B-spline as plain data: degree, clamped knot vector and control points.
#[derive(Debug, Clone, PartialEq)]
struct Spline {
    degree: usize,
    knots: Vec<f64>,
    ctrl: Vec<Vector2<f64>>,
}

impl Spline {
    /// The knot span `k` (degree <= k < ctrl.len()) with `knots[k] <= u < knots[k + 1]`,
    /// the last non-empty span for `u` at the end.
    fn span(&self, u: f64) -> usize {
        let p = self.degree;
        let n = self.ctrl.len() - 1;
        let k = self.knots.partition_point(|&x| x <= u).saturating_sub(1);
        k.clamp(p, n)
    }

    /// de Boor's algorithm.
    fn eval(&self, u: f64) -> Vector2<f64> {
        let p = self.degree;
        let k = self.span(u);
        let mut d = [Vector2::zeros(); 4];
        for (j, dj) in d.iter_mut().enumerate().take(p + 1) {
            *dj = self.ctrl[j + k - p];
        }
        for r in 1..=p {
            for j in (r..=p).rev() {
                let left = self.knots[j + k - p];
                let right = self.knots[j + 1 + k - r];
                let alpha = (u - left) / (right - left);
                d[j] = d[j - 1] * (1.0 - alpha) + d[j] * alpha;
            }
        }
        d[p]
    }

    /// The derivative spline (the hodograph), one degree lower; zero for degree 0.
    fn derivative(&self) -> Self {
        let p = self.degree;
        if p == 0 {
            return Self {
                degree: 0,
                knots: vec![self.knots[0], self.knots[self.knots.len() - 1]],
                ctrl: vec![Vector2::zeros()],
            };
        }
        let ctrl = self
            .ctrl
            .windows(2)
            .enumerate()
            .map(|(i, w)| {
                let du = self.knots[i + p + 1] - self.knots[i + 1];
                if du > 0.0 {
                    (w[1] - w[0]) * (p as f64 / du)
                } else {
                    Vector2::zeros()
                }
            })
            .collect();
        Self {
            degree: p - 1,
            knots: self.knots[1..self.knots.len() - 1].to_vec(),
            ctrl,
        }
    }
}

/// A clamped knot vector of `n_ctrl` control points and degree `p`, uniform inside,
/// running over `[0, n_ctrl - p]`.
fn uniform_clamped_knots(n_ctrl: usize, p: usize) -> Vec<f64> {
    let spans = n_ctrl - p;
    let mut knots = vec![0.0; p];
    knots.extend((0..=spans).map(|i| i as f64));
    knots.extend(std::iter::repeat_n(spans as f64, p));
    knots
}

impl BSpline {
    fn from_spline(curve: Spline, node_params: Option<Vec<f64>>) -> Self {
        let first = curve.derivative();
        let second = first.derivative();
        Self {
            curve,
            first,
            second,
            node_params,
        }
    }

    /// The clamped B-spline with `control` as control points and uniform knots (seed 003).
    ///
    /// Degree 3 from four control points on, degree `control.len() - 1` below. Repeated
    /// consecutive control points are allowed here (a control point repeated three times
    /// pulls the curve through it; `smooth_checked` uses that to repair), but not
    /// all equal ones.
    ///
    /// # Errors
    ///
    /// [`PostprocError::TooFewNodes`] or [`PostprocError::NonFinite`];
    /// [`PostprocError::RepeatedNode`] when every control point is the same.
    pub fn from_control_points(control: &[Point2]) -> Result<Self, PostprocError> {
        if control.len() < 2 {
            return Err(PostprocError::TooFewNodes {
                nodes: control.len(),
            });
        }
        if let Err(e @ PostprocError::NonFinite { .. }) = validate_path(control) {
            return Err(e);
        }
        if control.iter().all(|&p| p == control[0]) {
            return Err(PostprocError::RepeatedNode {
                index: 0,
                x: control[0].x,
                y: control[0].y,
            });
        }
        let p = (control.len() - 1).min(3);
        let curve = Spline {
            degree: p,
            knots: uniform_clamped_knots(control.len(), p),
            ctrl: control.iter().map(|q| q.coords).collect(),
        };
        Ok(Self::from_spline(curve, None))
    }

    /// The clamped cubic B-spline through every node (global interpolation, chord-length
    /// parameters, averaged knots).
    ///
    /// With two or three nodes the degree drops to 1 or 2 (a straight line, a parabola).
    /// Interpolating splines may overshoot between nodes; `smooth_checked` repairs where
    /// that collides.
    ///
    /// # Errors
    ///
    /// [`PostprocError::TooFewNodes`], [`PostprocError::NonFinite`] or
    /// [`PostprocError::RepeatedNode`].
    pub fn interpolating(nodes: &[Point2]) -> Result<Self, PostprocError> {
        validate_path(nodes)?;
        let n = nodes.len();
        let p = (n - 1).min(3);
        let params = cumulative_lengths(nodes);
        let s = params[n - 1];
        // Averaged knots (NURBS Book eq. 9.8): clamped, one interior knot per inner node
        // beyond the degree.
        let mut knots = vec![0.0; p + 1];
        for j in 1..n - p {
            knots.push(params[j..j + p].iter().sum::<f64>() / p as f64);
        }
        knots.extend(std::iter::repeat_n(s, p + 1));
        let mut curve = Spline {
            degree: p,
            knots,
            ctrl: vec![Vector2::zeros(); n],
        };
        // Collocation system A c = q: row k holds the basis functions at params[k]. The
        // matrix is totally positive and banded, so elimination without pivoting is stable.
        let mut rows: Vec<(usize, [f64; 4])> = Vec::with_capacity(n);
        for &u in &params {
            let k = curve.span(u);
            rows.push((k - p, basis_funs(&curve.knots, p, k, u)));
        }
        let rhs: Vec<Vector2<f64>> = nodes.iter().map(|q| q.coords).collect();
        curve.ctrl = solve_banded(&rows, p, &rhs);
        // Exact ends: the clamped spline interpolates them, so use the nodes themselves.
        curve.ctrl[0] = nodes[0].coords;
        curve.ctrl[n - 1] = nodes[n - 1].coords;
        Ok(Self::from_spline(curve, Some(params)))
    }

    /// The parameter range `(start, end)`.
    #[must_use]
    pub fn domain(&self) -> (f64, f64) {
        let k = &self.curve.knots;
        (k[0], k[k.len() - 1])
    }

    /// The degree (3 unless there are fewer than four control points).
    #[must_use]
    pub fn degree(&self) -> usize {
        self.curve.degree
    }

    /// The clamped knot vector.
    #[must_use]
    pub fn knots(&self) -> &[f64] {
        &self.curve.knots
    }

    /// The distinct knots, that is the parameters where one polynomial piece meets the next
    /// (including both ends of the domain).
    #[must_use]
    pub fn breakpoints(&self) -> Vec<f64> {
        let mut b: Vec<f64> = self.curve.knots.clone();
        b.dedup();
        b
    }

    /// The control points.
    #[must_use]
    pub fn control_points(&self) -> Vec<Point2> {
        self.curve.ctrl.iter().map(|&c| Point2::from(c)).collect()
    }

    /// For an [`interpolating`](BSpline::interpolating) spline, the parameter of each node
    /// (cumulative chord length); `None` for a control-point spline.
    #[must_use]
    pub fn node_params(&self) -> Option<&[f64]> {
        self.node_params.as_deref()
    }

    /// The point at parameter `u` (clamped to the domain).
    #[must_use]
    pub fn eval(&self, u: f64) -> Point2 {
        let (a, b) = self.domain();
        let n = self.curve.ctrl.len();
        if u <= a {
            return Point2::from(self.curve.ctrl[0]);
        }
        if u >= b {
            return Point2::from(self.curve.ctrl[n - 1]);
        }
        Point2::from(self.curve.eval(u))
    }

    /// The first derivative with respect to the parameter at `u` (clamped to the domain).
    #[must_use]
    pub fn derivative(&self, u: f64) -> Vector2<f64> {
        let (a, b) = self.domain();
        self.first.eval(u.clamp(a, b))
    }

    /// The second derivative with respect to the parameter at `u` (clamped to the domain).
    #[must_use]
    pub fn second_derivative(&self, u: f64) -> Vector2<f64> {
        let (a, b) = self.domain();
        self.second.eval(u.clamp(a, b))
    }
}

/// The `p + 1` non-zero basis functions of degree `p` at `u` in span `k`
/// (NURBS Book algorithm A2.2).
fn basis_funs(knots: &[f64], p: usize, k: usize, u: f64) -> [f64; 4] {
    let mut n = [0.0; 4];
    let mut left = [0.0; 4];
    let mut right = [0.0; 4];
    n[0] = 1.0;
    for j in 1..=p {
        left[j] = u - knots[k + 1 - j];
        right[j] = knots[k + j] - u;
        let mut saved = 0.0;
        for r in 0..j {
            let denom = right[r + 1] + left[j - r];
            let temp = if denom == 0.0 { 0.0 } else { n[r] / denom };
            n[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        n[j] = saved;
    }
    n
}

/// Solves the square collocation system whose row `i` has the entries `vals` from column
/// `start`, by Gaussian elimination without pivoting on a band of half-width `p`.
fn solve_banded(rows: &[(usize, [f64; 4])], p: usize, rhs: &[Vector2<f64>]) -> Vec<Vector2<f64>> {
    let n = rows.len();
    // Band storage: entry (i, j) at band[i][j + w - i] for |i - j| <= w.
    let w = p + 1;
    let width = 2 * w + 1;
    let mut band = vec![0.0; n * width];
    let mut b = rhs.to_vec();
    for (i, (start, vals)) in rows.iter().enumerate() {
        for (c, &v) in vals.iter().enumerate().take(p + 1) {
            let j = start + c;
            if v != 0.0 && j + w >= i && j <= i + w && j < n {
                band[i * width + j + w - i] = v;
            }
        }
    }
    let at = |i: usize, j: usize| i * width + j + w - i;
    for k in 0..n {
        let pivot = band[at(k, k)];
        if pivot == 0.0 {
            continue;
        }
        for i in k + 1..n.min(k + w + 1) {
            let f = band[at(i, k)] / pivot;
            if f == 0.0 {
                continue;
            }
            for j in k..n.min(k + w + 1) {
                if j + w >= i && j <= i + w {
                    band[at(i, j)] -= f * band[at(k, j)];
                }
            }
            b[i] = b[i] - b[k] * f;
        }
    }
    let mut x = vec![Vector2::zeros(); n];
    for i in (0..n).rev() {
        let mut acc = b[i];
        for j in i + 1..n.min(i + w + 1) {
            acc -= x[j] * band[at(i, j)];
        }
        let d = band[at(i, i)];
        x[i] = if d == 0.0 { acc } else { acc / d };
    }
    x
}

#[cfg(test)]
mod tests {
    use nalgebra::point;

    use super::*;

    #[test]
    fn knots_clamped_uniform() {
        assert_eq!(
            uniform_clamped_knots(5, 3),
            vec![0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0, 2.0]
        );
    }

    #[test]
    fn basis_partition_of_unity() {
        let knots = uniform_clamped_knots(7, 3);
        for i in 0..=40 {
            let u = 4.0 * f64::from(i) / 40.0;
            let s = Spline {
                degree: 3,
                knots: knots.clone(),
                ctrl: vec![Vector2::zeros(); 7],
            };
            let k = s.span(u);
            let sum: f64 = basis_funs(&knots, 3, k, u).iter().sum();
            assert!((sum - 1.0).abs() < 1e-14);
        }
    }

    #[test]
    fn de_boor_matches_bezier_for_four_points() {
        // One span: the clamped cubic B-spline is the Bezier curve.
        let c = [[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]].map(Point2::from);
        let b = BSpline::from_control_points(&c).unwrap();
        let t: f64 = 0.3;
        let mt = 1.0 - t;
        let bez = c[0].coords * mt.powi(3)
            + c[1].coords * (3.0 * mt * mt * t)
            + c[2].coords * (3.0 * mt * t * t)
            + c[3].coords * t.powi(3);
        assert!((b.eval(t).coords - bez).norm() < 1e-14);
    }

    #[test]
    fn derivatives_match_finite_differences() {
        let nodes = [[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 0.0], [6.0, 1.0]].map(Point2::from);
        for b in [
            BSpline::from_control_points(&nodes).unwrap(),
            BSpline::interpolating(&nodes).unwrap(),
        ] {
            let (a, e) = b.domain();
            let eps = 1e-6;
            for i in 1..40 {
                let u = a + (e - a) * f64::from(i) / 40.0 + 1e-3;
                let fd = (b.eval(u + eps) - b.eval(u - eps)) / (2.0 * eps);
                assert!((fd - b.derivative(u)).norm() < 1e-5, "at {u}");
                let fd2 = (b.derivative(u + eps) - b.derivative(u - eps)) / (2.0 * eps);
                assert!((fd2 - b.second_derivative(u)).norm() < 1e-3, "at {u}");
            }
        }
    }

    #[test]
    fn interpolation_through_nodes() {
        let nodes: Vec<Point2> = (0..30)
            .map(|i| {
                let t = f64::from(i) * 0.37;
                point![t * 3.0 + t.sin(), (2.0 * t).cos() * 2.0]
            })
            .collect();
        let b = BSpline::interpolating(&nodes).unwrap();
        for (q, &u) in nodes.iter().zip(b.node_params().unwrap()) {
            assert!((b.eval(u) - q).norm() < 1e-9, "node {q} at {u}");
        }
        for k in 2..4 {
            let short = BSpline::interpolating(&nodes[..k]).unwrap();
            for (q, &u) in nodes[..k].iter().zip(short.node_params().unwrap()) {
                assert!((short.eval(u) - q).norm() < 1e-12);
            }
        }
    }

    #[test]
    fn triple_control_point_is_on_polyline() {
        let a = point![0.0, 0.0];
        let b = point![2.0, 2.0];
        let c = point![4.0, 0.0];
        let s = BSpline::from_control_points(&[a, b, b, b, c]).unwrap();
        // Parameter 1 is the knot where the curve reaches b.
        assert!((s.eval(1.0) - b).norm() < 1e-14);
        // Before it, the curve lies on segment a-b (y == x).
        let q = s.eval(0.5);
        assert!((q.x - q.y).abs() < 1e-14);
    }
}
