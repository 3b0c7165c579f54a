//! Curvature of parametric curves and of sampled polylines.

use hyplan_core::Point2;
use nalgebra::Vector2;

/// The signed curvature of a planar parametric curve from its first and second
/// derivatives: `(x' y'' - y' x'') / |r'|^3`, in 1 / world units, positive when the curve
/// turns left (counter-clockwise). Zero where the first derivative vanishes.
///
/// The result does not depend on how the curve is parametrised.
///
/// # Example
///
/// ```
/// use nalgebra::Vector2;
/// // A circle of radius 2, counter-clockwise: r' = (-2 sin t, 2 cos t), r'' = -r.
/// let t: f64 = 0.7;
/// let d1 = Vector2::new(-2.0 * t.sin(), 2.0 * t.cos());
/// let d2 = Vector2::new(-2.0 * t.cos(), -2.0 * t.sin());
/// assert!((postproc::curvature(d1, d2) - 0.5).abs() < 1e-12);
/// ```
#[must_use]
pub fn curvature(d1: Vector2<f64>, d2: Vector2<f64>) -> f64 {
    let speed = d1.norm();
    if speed == 0.0 || !speed.is_finite() {
        return 0.0;
    }
    d1.perp(&d2) / (speed * speed * speed)
}

/// The signed turning angle at each vertex of a polyline, radians in `(-pi, pi]`, positive
/// to the left; zero at both ends and wherever a neighbouring segment has zero length.
///
/// # Example
///
/// ```
/// use hyplan_core::Point2;
/// let l = [Point2::new(0.0, 0.0), Point2::new(1.0, 0.0), Point2::new(1.0, 1.0)];
/// let a = postproc::turning_angles(&l);
/// assert_eq!(a[0], 0.0);
/// assert!((a[1] - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
/// ```
#[must_use]
pub fn turning_angles(points: &[Point2]) -> Vec<f64> {
    let mut out = vec![0.0; points.len()];
    for i in 1..points.len().saturating_sub(1) {
        let u = points[i] - points[i - 1];
        let v = points[i + 1] - points[i];
        if u != Vector2::zeros() && v != Vector2::zeros() {
            out[i] = u.perp(&v).atan2(u.dot(&v));
        }
    }
    out
}

/// The discrete signed curvature at each vertex of a densely sampled curve: the turning
/// angle divided by the mean length of the two neighbouring segments, 1 / world units.
/// Zero at both ends.
///
/// On a smooth curve sampled a small step `h` apart it converges to the curvature as `h`
/// shrinks; at a corner it stays finite (the corner's angle spread over one step), so a
/// time law capped by `omega_max / |kappa|` slows down there without stopping.
///
/// # Example
///
/// ```
/// use hyplan_core::Point2;
/// // Samples of a circle of radius 4.
/// let pts: Vec<Point2> = (0..50)
///     .map(|i| {
///         let t = f64::from(i) * 0.02;
///         Point2::new(4.0 * t.cos(), 4.0 * t.sin())
///     })
///     .collect();
/// let k = postproc::discrete_curvature(&pts);
/// assert!((k[25] - 0.25).abs() < 1e-4);
/// ```
#[must_use]
pub fn discrete_curvature(points: &[Point2]) -> Vec<f64> {
    let angles = turning_angles(points);
    angles
        .iter()
        .enumerate()
        .map(|(i, &a)| {
            if a == 0.0 {
                return 0.0;
            }
            let l = 0.5
                * (nalgebra::distance(&points[i - 1], &points[i])
                    + nalgebra::distance(&points[i], &points[i + 1]));
            a / l
        })
        .collect()
}
